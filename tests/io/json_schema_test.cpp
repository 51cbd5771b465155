// The JSON Schema subset: every message with its path, and the refusal of keywords the validator does not know.
#include "io/json_schema.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

using Lines = std::vector<std::string>;

// The errors of the document against the schema (both JSON texts) as "PATH: MESSAGE" lines.
Lines errors(const std::string& document, const std::string& schema) {
  Lines lines;
  for (const SchemaError& e : validateJson(nlohmann::json::parse(document), nlohmann::json::parse(schema)))
    lines.push_back(toString(e));
  return lines;
}

// The message of the logic_error that the schema provokes; a failure if there is none.
std::string schemaFaultOf(const std::string& schema) {
  try {
    validateJson(nlohmann::json::object(), nlohmann::json::parse(schema));
  } catch (const std::logic_error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no logic_error for " << schema;
  return "";
}

TEST(JsonSchema, NamesTheExpectedTypeAndTheValueFound) {
  EXPECT_EQ(errors("3", R"({"type": "string"})"), Lines{"/: expected a string, found 3"});
  EXPECT_EQ(errors(R"("abc")", R"({"type": "number"})"), Lines{R"(/: expected a number, found "abc")"});
  EXPECT_EQ(errors("1.5", R"({"type": "integer"})"), Lines{"/: expected an integer, found 1.5"});
  EXPECT_EQ(errors(R"("yes")", R"({"type": "boolean"})"), Lines{R"(/: expected a boolean, found "yes")"});
  EXPECT_EQ(errors("[1]", R"({"type": "object"})"), Lines{"/: expected an object, found an array"});
  EXPECT_EQ(errors("2", R"({"type": "array"})"), Lines{"/: expected an array, found 2"});
  EXPECT_EQ(errors("{}", R"({"type": "null"})"), Lines{"/: expected null, found an object"});
  EXPECT_EQ(errors("true", R"({"type": ["number", "string"]})"), Lines{"/: expected a number or a string, found true"});
  EXPECT_EQ(errors("null", R"({"type": "string"})"), Lines{"/: expected a string, found null"});
}

TEST(JsonSchema, AcceptsIntegralNumbersAsIntegers) {
  EXPECT_EQ(errors("3", R"({"type": "integer"})"), Lines{});
  EXPECT_EQ(errors("3.0", R"({"type": "integer"})"), Lines{});
  EXPECT_EQ(errors("-2e3", R"({"type": "integer"})"), Lines{});
  EXPECT_EQ(errors("3", R"({"type": "number"})"), Lines{});
}

TEST(JsonSchema, ListsTheEnumValues) {
  EXPECT_EQ(errors(R"("w")", R"({"enum": ["x", "y", "z"]})"), Lines{R"(/: expected one of x, y, z, found "w")"});
  EXPECT_EQ(errors("4", R"({"enum": [1, 2, "auto", null]})"), Lines{"/: expected one of 1, 2, auto, null, found 4"});
  EXPECT_EQ(errors("2.0", R"({"enum": [1, 2]})"), Lines{});
}

TEST(JsonSchema, PrintsTheConstAsJson) {
  EXPECT_EQ(errors(R"("x")", R"({"const": "obj"})"), Lines{R"(/: expected "obj", found "x")"});
  EXPECT_EQ(errors(R"({"a": 1})", R"({"const": 2})"), Lines{"/: expected 2, found an object"});
}

TEST(JsonSchema, NamesTheBoundAndTheValue) {
  EXPECT_EQ(errors("-1", R"({"type": "number", "minimum": 0})"), Lines{"/: expected a number >= 0, found -1"});
  EXPECT_EQ(errors("0", R"({"type": "number", "exclusiveMinimum": 0})"), Lines{"/: expected a number > 0, found 0"});
  EXPECT_EQ(errors("1.5", R"({"type": "number", "maximum": 1})"), Lines{"/: expected a number <= 1, found 1.5"});
  EXPECT_EQ(errors("1", R"({"type": "number", "exclusiveMaximum": 1})"), Lines{"/: expected a number < 1, found 1"});
  EXPECT_EQ(errors("0", R"({"type": "integer", "minimum": 1})"), Lines{"/: expected an integer >= 1, found 0"});
  EXPECT_EQ(errors("0.05", R"({"minimum": 0.1})"), Lines{"/: expected a number >= 0.1, found 0.05"});
  EXPECT_EQ(errors("1e300", R"({"maximum": 1e200})"), Lines{"/: expected a number <= 1e+200, found 1e+300"});
  EXPECT_EQ(errors("0", R"({"minimum": 0, "maximum": 0})"), Lines{});
  EXPECT_EQ(errors(R"("a")", R"({"minimum": 0})"), Lines{});  // bounds concern numbers only
}

TEST(JsonSchema, ReportsAMissingKeyAtTheObject) {
  const std::string schema = R"({"type": "object", "required": ["name", "path"],
                                 "properties": {"inner": {"required": ["path"]}}})";
  EXPECT_EQ(errors(R"({"path": "a"})", schema), Lines{R"(/: missing required key "name")"});
  EXPECT_EQ(errors(R"({"name": 1, "path": 2, "inner": {}})", schema), Lines{R"(/inner: missing required key "path")"});
}

TEST(JsonSchema, ReportsAnUnknownKeyAtTheKeyWithTheKnownOnes) {
  // nlohmann::json keeps keys sorted, so the known keys read in that order.
  const std::string schema = R"({"type": "object", "additionalProperties": false,
      "properties": {"name": {}, "path": {}, "model": {"type": "object", "additionalProperties": false}}})";
  EXPECT_EQ(errors(R"({"name": "a", "foo": 1})", schema),
            Lines{R"(/foo: unknown key "foo"; expected one of: model, name, path)"});
  EXPECT_EQ(errors(R"({"model": {"x": 1}})", schema), Lines{R"(/model/x: unknown key "x"; expected no keys)"});
  EXPECT_EQ(errors(R"({"a": "x", "b": 2})", R"({"additionalProperties": {"type": "number"}})"),
            Lines{R"(/a: expected a number, found "x")"});
}

TEST(JsonSchema, CountsItems) {
  EXPECT_EQ(errors("[1]", R"({"minItems": 2})"), Lines{"/: expected at least 2 items, found 1"});
  EXPECT_EQ(errors("[1, 2, 3, 4]", R"({"maxItems": 3})"), Lines{"/: expected at most 3 items, found 4"});
  EXPECT_EQ(errors("[1, 2]", R"({"minItems": 3, "maxItems": 3})"), Lines{"/: expected 3 items, found 2"});
  EXPECT_EQ(errors("[]", R"({"minItems": 1})"), Lines{"/: expected at least 1 item, found 0"});
  EXPECT_EQ(errors("[1, 2, 3]", R"({"minItems": 3, "maxItems": 3})"), Lines{});
}

TEST(JsonSchema, ChecksEveryItem) {
  EXPECT_EQ(errors(R"([1, "a", 2, true])", R"({"items": {"type": "number"}})"),
            (Lines{R"(/1: expected a number, found "a")", "/3: expected a number, found true"}));
}

TEST(JsonSchema, ChecksTheLengthInCharacters) {
  EXPECT_EQ(errors(R"("")", R"({"minLength": 1})"), Lines{"/: expected a non-empty string"});
  EXPECT_EQ(errors(R"("ab")", R"({"minLength": 3})"), Lines{"/: expected at least 3 characters"});
  EXPECT_EQ(errors("\"\xC3\xA9\"", R"({"minLength": 2})"), Lines{"/: expected at least 2 characters"});
  EXPECT_EQ(errors("\"\xC3\xA9\xC3\xA9\"", R"({"minLength": 2})"), Lines{});
}

TEST(JsonSchema, SearchesForThePattern) {
  EXPECT_EQ(errors(R"("Abc")", R"({"pattern": "^[a-z]+$"})"),
            Lines{R"(/: expected a string matching ^[a-z]+$, found "Abc")"});
  EXPECT_EQ(errors(R"("abc")", R"({"pattern": "b"})"), Lines{});  // anywhere in the string, as JSON Schema says
}

TEST(JsonSchema, CutsALongStringFound) {
  EXPECT_EQ(errors('"' + std::string(100, 'a') + '"', R"({"type": "number"})"),
            Lines{"/: expected a number, found \"" + std::string(60, 'a') + "...\""});
}

TEST(JsonSchema, ReportsANestedErrorAtItsPath) {
  const std::string schema = R"({
    "$schema": "https://json-schema.org/draft/2020-12/schema",
    "type": "object",
    "properties": {"meshes": {"type": "array", "items": {"$ref": "#/$defs/mesh"}}},
    "$defs": {
      "mesh": {"type": "object", "required": ["path"],
               "properties": {"path": {"type": "string"}, "mapping": {"$ref": "#/$defs/mapping"}}},
      "mapping": {"type": "object", "properties": {"axis": {"enum": ["x", "y", "z"]}}}
    }
  })";
  const std::string document = R"({"meshes": [
    {"path": "a.obj"},
    {"path": "b.obj", "mapping": {"axis": "y"}},
    {"path": "c.obj", "mapping": {"axis": "w"}}
  ]})";
  EXPECT_EQ(errors(document, schema), Lines{R"(/meshes/2/mapping/axis: expected one of x, y, z, found "w")"});
}

TEST(JsonSchema, ReportsAllErrorsInDocumentOrder) {
  const std::string schema = R"({"type": "object", "required": ["c"], "properties": {
      "a": {"type": "number", "minimum": 0}, "b": {"type": "string"}, "c": {}}})";
  EXPECT_EQ(errors(R"({"b": 1, "a": -1})", schema),
            (Lines{R"(/: missing required key "c")", "/a: expected a number >= 0, found -1",
                   "/b: expected a string, found 1"}));
}

TEST(JsonSchema, DoesNotLookInsideAValueOfTheWrongType) {
  const std::string schema = R"({"type": "object", "required": ["x"], "additionalProperties": false,
                                 "properties": {"x": {}}})";
  EXPECT_EQ(errors(R"([{"y": 1}])", schema), Lines{"/: expected an object, found an array"});
}

TEST(JsonSchema, EscapesKeysInPaths) {
  const std::string schema = R"({"properties": {"a/b": {"properties": {"c~d": {"type": "string"}},
                                                         "additionalProperties": false}}})";
  EXPECT_EQ(
      errors(R"({"a/b": {"c~d": 1, "e/f~": 2}})", schema),
      (Lines{"/a~1b/c~0d: expected a string, found 1", R"(/a~1b/e~1f~0: unknown key "e/f~"; expected one of: c~d)"}));
}

const std::string kShapes = R"({
  "oneOf": [{"$ref": "#/$defs/sphere"}, {"$ref": "#/$defs/cylinder"}],
  "$defs": {
    "sphere": {"type": "object", "required": ["kind", "radius"], "additionalProperties": false,
               "properties": {"kind": {"const": "sphere"}, "radius": {"type": "number", "exclusiveMinimum": 0}}},
    "cylinder": {"type": "object", "required": ["kind"], "additionalProperties": false,
                 "properties": {"kind": {"const": "cylinder"}, "axis": {"enum": ["x", "y", "z"]}}}
  }
})";

TEST(JsonSchema, ChoosesTheBranchOfADiscriminatedUnionByItsKey) {
  EXPECT_EQ(errors(R"({"kind": "sphere", "radius": 1})", kShapes), Lines{});
  EXPECT_EQ(errors(R"({"kind": "cone"})", kShapes), Lines{R"(/: expected kind one of sphere, cylinder, found "cone")"});
  EXPECT_EQ(errors(R"({"radius": 1})", kShapes), Lines{R"(/: missing required key "kind")"});
  EXPECT_EQ(errors("[]", kShapes), Lines{"/: expected an object, found an array"});
  EXPECT_EQ(errors(R"({"kind": "sphere", "radius": "big"})", kShapes),
            Lines{R"(/radius: expected a number, found "big")"});
  EXPECT_EQ(errors(R"({"kind": "cylinder", "axis": "w", "extra": 1})", kShapes),
            (Lines{R"(/axis: expected one of x, y, z, found "w")",
                   R"(/extra: unknown key "extra"; expected one of: axis, kind)"}));
}

TEST(JsonSchema, DescribesTheAlternativesOfAFailedOneOf) {
  const std::string size = R"({"oneOf": [{"type": "number", "minimum": 1}, {"const": "auto"}]})";
  EXPECT_EQ(errors("2", size), Lines{});
  EXPECT_EQ(errors(R"("auto")", size), Lines{});
  EXPECT_EQ(errors(R"("x")", size), Lines{R"(/: expected a number or "auto", found "x")"});
  EXPECT_EQ(errors("0", size), Lines{R"(/: expected a number or "auto", found 0)"});
  EXPECT_EQ(errors("true", R"({"oneOf": [{"type": "number", "description": "a size in pixels"}, {"const": "auto"}]})"),
            Lines{R"(/: expected a size in pixels or "auto", found true)"});
  EXPECT_EQ(errors("3", R"({"oneOf": [{"enum": ["a", "b"]}, {"$ref": "#/$defs/s"}, {"minimum": 5}],
                            "$defs": {"s": {"type": ["string", "null"]}}})"),
            Lines{"/: expected one of a, b or a string or null or alternative 3, found 3"});
}

TEST(JsonSchema, RejectsAValueMatchingTwoBranchesOfOneOfButNotOfAnyOf) {
  EXPECT_EQ(errors("3", R"({"oneOf": [{"type": "number"}, {"type": "integer"}]})"),
            Lines{"/: matches more than one alternative"});
  EXPECT_EQ(errors("3", R"({"anyOf": [{"type": "number"}, {"type": "integer"}]})"), Lines{});
  EXPECT_EQ(errors(R"("x")", R"({"anyOf": [{"type": "number"}, {"const": "auto"}]})"),
            Lines{R"(/: expected a number or "auto", found "x")"});
}

TEST(JsonSchema, IgnoresAnnotations) {
  EXPECT_EQ(errors("1", R"({"$schema": "https://json-schema.org/draft/2020-12/schema", "$id": "s", "title": "t",
                            "description": "d", "default": 1, "examples": [1], "$comment": "c", "type": "number"})"),
            Lines{});
}

TEST(JsonSchema, RefusesAKeywordItWouldIgnore) {
  const std::string message = schemaFaultOf(R"({"properties": {"a": {"type": "object", "patternProperties": {}}}})");
  EXPECT_NE(message.find("\"patternProperties\""), std::string::npos) << message;
  EXPECT_NE(message.find("/properties/a"), std::string::npos) << message;
  // Wherever it sits, even in a branch or a definition no document reaches.
  EXPECT_NE(schemaFaultOf(R"({"$defs": {"x": {"format": "uri"}}})").find("\"format\""), std::string::npos);
  EXPECT_NE(schemaFaultOf(R"({"anyOf": [{"maxLength": 3}]})").find("\"maxLength\""), std::string::npos);
}

TEST(JsonSchema, RefusesAMalformedSchema) {
  EXPECT_NE(schemaFaultOf(R"({"type": "float"})").find("unknown type \"float\""), std::string::npos);
  EXPECT_NE(schemaFaultOf(R"({"$ref": "#/$defs/none"})").find("names no schema"), std::string::npos);
  EXPECT_NE(schemaFaultOf(R"({"$ref": "other.json#/x"})").find("#/$defs/NAME"), std::string::npos);
  EXPECT_NE(schemaFaultOf(R"({"$ref": "#/$defs/a", "$defs": {"a": {"$ref": "#/$defs/a"}}})").find("cycle"),
            std::string::npos);
  EXPECT_NE(schemaFaultOf(R"({"pattern": "("})").find("invalid regular expression"), std::string::npos);
  EXPECT_NE(schemaFaultOf(R"({"minItems": -1})").find("non-negative integer"), std::string::npos);
}

TEST(JsonSchema, PrintsTheRootAsSlash) {
  EXPECT_EQ(toString({"", "m"}), "/: m");
  EXPECT_EQ(toString({"/a/0", "m"}), "/a/0: m");
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
