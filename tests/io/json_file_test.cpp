// Strict JSON input: what it accepts, and every rejection with its exact one-line message and position.
#include "io/json_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/error.h"
#include "scratch_dir.h"

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

using JsonFileTest = ScratchDirTest;

// The message of the InputError that parsing `text` as "s.json" throws; a failure if it throws none.
std::string errorOf(const std::string& text) {
  try {
    parseJsonText(text, "s.json");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return "";
}

std::string fileErrorOf(const std::string& path) {
  try {
    readJsonFile(path);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for " << path;
  return "";
}

TEST(JsonText, ParsesADocument) {
  const nlohmann::json j = parseJsonText(R"({"name": "a", "sizes": [1, 2.5], "on": true, "none": null})", "s.json");
  EXPECT_EQ(j.at("name"), "a");
  EXPECT_EQ(j.at("sizes"), nlohmann::json::array({1, 2.5}));
  EXPECT_EQ(j.at("on"), true);
  EXPECT_TRUE(j.at("none").is_null());
}

TEST(JsonText, SkipsAByteOrderMarkWhichIsNoColumn) {
  EXPECT_EQ(parseJsonText("\xEF\xBB\xBF{\"a\": 1}", "s.json").at("a"), 1);
  EXPECT_EQ(errorOf("\xEF\xBB\xBF{\"a\" 1}"), "s.json:1:6: error: expected ':', found '1'");
}

TEST(JsonText, RejectsADuplicateKeyAtItsSecondOccurrence) {
  EXPECT_EQ(errorOf("{\n  \"name\": 1,\n  \"path\": 2,\n  \"name\": 3\n}"),
            "s.json:4:3: error: duplicate key \"name\"");
  // In a nested object, and with an escaped quote inside the key.
  EXPECT_EQ(errorOf(R"({"a": [{"k\"q": 1, "k\"q": 2}]})"), R"(s.json:1:20: error: duplicate key "k\"q")");
}

TEST(JsonText, AllowsTheSameKeyInDifferentObjects) {
  const nlohmann::json j = parseJsonText(R"({"a": {"a": 1}, "b": [{"a": 2}, {"a": 3}], "c": {"a": 4}})", "s.json");
  EXPECT_EQ(j.at("b").at(1).at("a"), 3);
}

TEST(JsonText, RejectsTrailingGarbageAfterTheDocument) {
  EXPECT_EQ(errorOf("{}\n{}"), "s.json:2:1: error: expected end of file, found '{'");
  EXPECT_EQ(errorOf("{} x"), "s.json:1:4: error: expected end of file, found 'x'");
  EXPECT_EQ(errorOf("1 2"), "s.json:1:3: error: expected end of file, found '2'");
  EXPECT_EQ(errorOf("[] \"abc\""), "s.json:1:4: error: expected end of file, found '\"abc\"'");
  EXPECT_NO_THROW(parseJsonText("{}\n\n  \t", "s.json"));
}

TEST(JsonText, RejectsATruncatedDocumentAtTheEndOfTheText) {
  EXPECT_EQ(errorOf("{\"a\": [1, 2"), "s.json:1:12: error: expected ',' or ']', found end of file");
  EXPECT_EQ(errorOf("{\"a\": 1\n"), "s.json:2:1: error: expected ',' or '}', found end of file");
  EXPECT_EQ(errorOf("{\"a\":"), "s.json:1:6: error: expected a value, found end of file");
  EXPECT_EQ(errorOf("\"abc"), "s.json:1:5: error: expected a closing quote, found end of file");
  EXPECT_EQ(errorOf("nul"), "s.json:1:1: error: expected a value, found 'nul'");
}

// nlohmann stops at a NUL byte as at the end of the input; the reader does not.
TEST(JsonText, RejectsANulByteAnywhere) {
  using namespace std::string_literals;
  EXPECT_EQ(errorOf("{}\n\0{}"s), "s.json:2:1: error: expected end of file, found control character U+0000");
  EXPECT_EQ(errorOf("[1,\0]"s), "s.json:1:4: error: expected a value, found control character U+0000");
  EXPECT_EQ(errorOf("[\"a\0\"]"s), "s.json:1:4: error: expected the escape \\u0000, found control character U+0000");
}

TEST(JsonText, RejectsAnEmptyText) {
  EXPECT_EQ(errorOf(""), "s.json:1:1: error: expected a value, found end of file");
  EXPECT_EQ(errorOf(" \n"), "s.json:2:1: error: expected a value, found end of file");
}

TEST(JsonText, NamesWhatWasExpectedAndTheTokenFoundAtItsFirstCharacter) {
  EXPECT_EQ(errorOf(R"({"a" 1})"), "s.json:1:6: error: expected ':', found '1'");
  EXPECT_EQ(errorOf(R"({"a": 1 "b": 2})"), "s.json:1:9: error: expected ',' or '}', found '\"b\"'");
  EXPECT_EQ(errorOf("[1 2]"), "s.json:1:4: error: expected ',' or ']', found '2'");
  EXPECT_EQ(errorOf("[true 25.5e3]"), "s.json:1:7: error: expected ',' or ']', found '25.5e3'");
  EXPECT_EQ(errorOf("[1 false]"), "s.json:1:4: error: expected ',' or ']', found 'false'");
  EXPECT_EQ(errorOf("[true2]"), "s.json:1:6: error: expected ',' or ']', found '2'");
  EXPECT_EQ(errorOf("[1,]"), "s.json:1:4: error: expected a value, found ']'");
  EXPECT_EQ(errorOf(R"({"a": 1,})"), "s.json:1:9: error: expected a quoted key, found '}'");
  EXPECT_EQ(errorOf("{a: 1}"), "s.json:1:2: error: expected a quoted key or '}', found 'a'");
  EXPECT_EQ(errorOf("{ 3: 1}"), "s.json:1:3: error: expected a quoted key or '}', found '3'");
  EXPECT_EQ(errorOf(R"({"a": tru})"), "s.json:1:7: error: expected a value, found 'tru'");
  EXPECT_EQ(errorOf(R"({"a": yes})"), "s.json:1:7: error: expected a value, found 'yes'");
  EXPECT_EQ(errorOf(R"({"a": @})"), "s.json:1:7: error: expected a value, found '@'");
  EXPECT_EQ(errorOf(R"({"a": 'x'})"), "s.json:1:7: error: expected a value, found '''");
}

TEST(JsonText, NamesWhatIsWrongInsideAToken) {
  EXPECT_EQ(errorOf("[1, -x]"), "s.json:1:6: error: expected a digit after '-', found 'x'");
  EXPECT_EQ(errorOf("[1.]"), "s.json:1:4: error: expected a digit after '.', found ']'");
  EXPECT_EQ(errorOf("[1e]"), "s.json:1:4: error: expected '+', '-' or a digit after the exponent, found ']'");
  EXPECT_EQ(errorOf("\"a\nb\""),
            "s.json:1:3: error: expected the escape \\u000A or \\n, found control character U+000A");
  EXPECT_EQ(errorOf(R"("\x")"), R"(s.json:1:3: error: expected one of " \ / b f n r t u after a backslash, found 'x')");
  EXPECT_EQ(errorOf(R"("\u12g")"), R"(s.json:1:6: error: expected 4 hex digits after \u, found 'g')");
  EXPECT_EQ(errorOf("\"\xFF\""), "s.json:1:2: error: expected UTF-8 text, found byte 0xFF");
  EXPECT_EQ(errorOf(R"(["\uD800x"])"), R"(s.json:1:9: error: expected \uDC00..\uDFFF after \uD800..\uDBFF, found 'x')");
  EXPECT_EQ(errorOf(R"(["\uDC00"])"),
            R"(s.json:1:3: error: expected \uD800..\uDBFF before \uDC00..\uDFFF, found '\uDC00')");
  EXPECT_EQ(errorOf("[1e999, 2]"), "s.json:1:2: error: expected a number within the range of a double, found '1e999'");
  EXPECT_EQ(errorOf("-1e999"), "s.json:1:1: error: expected a number within the range of a double, found '-1e999'");
}

TEST(JsonText, CountsColumnsInCharactersAndLinesFromOne) {
  EXPECT_EQ(errorOf("{\n  \"\xC3\xA9\": 1 2}"), "s.json:2:10: error: expected ',' or '}', found '2'");
  EXPECT_EQ(errorOf("[\r\n1\r\n2]"), "s.json:3:1: error: expected ',' or ']', found '2'");
  EXPECT_EQ(errorOf("[1, \xC3\xA9]"), "s.json:1:5: error: expected a value, found '\xC3\xA9'");
}

TEST(JsonText, CutsALongTokenInTheMessage) {
  const std::string message = errorOf("[1 \"" + std::string(50, 'a') + "\"]");
  EXPECT_EQ(message, "s.json:1:4: error: expected ',' or ']', found '\"" + std::string(39, 'a') + "...'");
}

TEST(JsonText, BoundsTheNesting) {
  EXPECT_NO_THROW(parseJsonText(std::string(512, '[') + std::string(512, ']'), "s.json"));
  EXPECT_EQ(errorOf(std::string(100000, '[')),
            "s.json:1:513: error: expected at most 512 nested arrays and objects, found 513");
}

TEST_F(JsonFileTest, ReadsAFile) { EXPECT_EQ(readJsonFile(writeText("a.json", "{\"a\": [1]}\n")).at("a").at(0), 1); }

TEST_F(JsonFileTest, NamesTheFileInMessages) {
  const std::string file = writeText("dup.json", "{\"a\": 1, \"a\": 2}");
  EXPECT_EQ(fileErrorOf(file), file + ":1:10: error: duplicate key \"a\"");
}

TEST_F(JsonFileTest, RejectsAnEmptyFile) {
  const std::string file = writeText("empty.json", "");
  EXPECT_EQ(fileErrorOf(file), file + ":1:1: error: expected a value, found end of file");
}

TEST_F(JsonFileTest, RejectsADirectoryAndAMissingFile) {
  EXPECT_EQ(fileErrorOf(dir_.string()), dir_.string() + ": error: cannot open: Is a directory");
  EXPECT_EQ(fileErrorOf(path("none.json")), path("none.json") + ": error: cannot open: No such file or directory");
}

TEST_F(JsonFileTest, RejectsAFileLargerThan64MiB) {
  const std::string file = writeText("big.json", "");
  std::filesystem::resize_file(file, (std::uintmax_t{64} << 20) + 1);  // sparse: nothing is written
  EXPECT_EQ(fileErrorOf(file), file + ": error: expected at most 64 MiB (67108864 bytes), found 67108865 bytes");
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
