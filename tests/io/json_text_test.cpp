// JSON text for names of any bytes: dump()'s exact text where it can write one, \udcXX for each byte
// that is not UTF-8 (Python's json.loads of it is os.fsdecode of the bytes), and read back to the
// same bytes.
#include "io/json_text.h"

#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "io/json_file.h"

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

using Json = nlohmann::json;

TEST(JsonOfAnyBytes, IsDumpsTextForEveryUtf8Document) {
  const Json document = {{"path", "caf\xc3\xa9/\xe2\x82\xac.obj"}, {"n", 1.5}, {"empty", Json::object()},
                         {"list", {1, "two", nullptr, true, Json::array()}}, {"nested", {{"a", {{"b", "\x7f\t"}}}}}};
  for (const int indent : {-1, 0, 2, 4}) EXPECT_EQ(jsonText(document, indent), document.dump(indent)) << indent;
}

TEST(JsonOfAnyBytes, WritesEachStrayByteAsALowSurrogateEscape) {
  // json.loads(r'"in\udcff\udcc3.obj"') == os.fsdecode(b"in\xff\xc3.obj") in Python; a truncated euro sign.
  EXPECT_EQ(jsonText(Json("in\xff\xc3.obj")), R"("in\udcff\udcc3.obj")");
  EXPECT_EQ(jsonText(Json("\xe2\x82")), R"("\udce2\udc82")");
  EXPECT_EQ(jsonText(Json("\xed\xa0\x80")), R"("\udced\udca0\udc80")");  // an encoded surrogate is not UTF-8
  EXPECT_EQ(jsonText(Json("\xc0\xaf")), R"("\udcc0\udcaf")");            // nor an overlong '/'
  EXPECT_EQ(jsonText(Json("ok \xc3\xa9 \"q\" \n\x80")), "\"ok \xc3\xa9 \\\"q\\\" \\n\\udc80\"");
  // Keys too, and the layout of the whole document is dump()'s.
  const Json document = {{"k\xfe", {1, "v\xfd"}}, {"e", Json::object()}};
  EXPECT_EQ(jsonText(document, 2), "{\n  \"e\": {},\n  \"k\\udcfe\": [\n    1,\n    \"v\\udcfd\"\n  ]\n}");
  EXPECT_EQ(jsonText(document), "{\"e\":{},\"k\\udcfe\":[1,\"v\\udcfd\"]}");
}

TEST(JsonOfAnyBytes, ReadsBackToTheSameBytes) {
  const std::string name = "dir\x80/in\xff\xc3\xa9.obj";
  const Json document = {{"path", name}, {"paths", {name, "plain"}}, {name, 3}};
  const Json read = parseJsonText(jsonText(document, 2), "doc.json");
  EXPECT_EQ(read.at("path").get<std::string>(), name);
  EXPECT_EQ(read.at("paths").at(0).get<std::string>(), name);
  EXPECT_EQ(read.at(name).get<int>(), 3);
  // A document with such escapes reads the same through the ordered reader merge-reports uses.
  std::string marked = jsonText(document);
  ASSERT_TRUE(markLoneByteEscapes(marked));
  EXPECT_EQ(restoredDocument(nlohmann::ordered_json::parse(marked)).at("path").get<std::string>(), name);
}

TEST(JsonOfAnyBytes, OnlyLoneEscapesOfBytesAreMarked) {
  std::string pair = R"(["\ud83d\ude00", "\\udcff", "\udc7f"])";  // a pair, an escaped backslash, not a byte
  const std::string before = pair;
  EXPECT_FALSE(markLoneByteEscapes(pair));
  EXPECT_EQ(pair, before);
  std::string lone = R"(["a\uDCFFb", "\udc80"])";
  EXPECT_TRUE(markLoneByteEscapes(lone));
  EXPECT_EQ(lone, R"(["a\uf7FFb", "\uf780"])");
  // A document without them reads as before, U+F780..U+F7FF included; one that is malformed
  // elsewhere keeps its message.
  EXPECT_EQ(parseJsonText("[\"\xef\x9e\x80\"]", "d").at(0).get<std::string>(), "\xef\x9e\x80");
  EXPECT_THROW(parseJsonText(R"(["\udcff", ])", "d"), InputError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
