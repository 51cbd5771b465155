// Strict JSON input: a malformed document, trailing bytes or a duplicate key is an InputError whose one-line
// message reads "FILE:LINE:COLUMN: error: expected ..., found ..." (or "... error: duplicate key "K"").
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace uvtk::io {

// Reads and parses the file. A file that cannot be opened, is a directory or is larger than 64 MiB is an
// InputError too ("FILE: error: ...").
nlohmann::json readJsonFile(const std::string& path);

// Parses `text` as one JSON document; `name` stands for the file in messages. A leading UTF-8 byte-order mark
// is skipped.
nlohmann::json parseJsonText(const std::string& text, const std::string& name);

}  // namespace uvtk::io
