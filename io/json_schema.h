// A validator for the subset of JSON Schema (draft 2020-12 keyword names) that the project's schemas use, with
// messages that say what was expected and what was found.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace uvtk::io {

struct SchemaError {
  std::string path;  // JSON Pointer (RFC 6901) to the offending value, "" for the root
  std::string message;
};

// Every error of `document` against `schema` (a schema document; "$ref": "#/$defs/NAME" resolves inside it), in
// document order: a depth-first walk, object keys in nlohmann::json's (sorted) order. A schema keyword outside
// the supported subset, or a malformed schema, throws std::logic_error naming it: the schema is the program's.
std::vector<SchemaError> validateJson(const nlohmann::json& document, const nlohmann::json& schema);

// "PATH: MESSAGE" with PATH "/" for the root.
std::string toString(const SchemaError& e);

}  // namespace uvtk::io
