// JSON documents as text, for any string Linux allows. nlohmann's dump() throws on a string that is
// not UTF-8, and a path may be any bytes but '/' and NUL; jsonText writes each byte that is not part
// of valid UTF-8 as the escape \udcXX (0x80 <= XX <= 0xFF), as Python's os.fsdecode
// (surrogateescape) does: json.loads then os.fsencode gives the bytes back. Every other document is
// exactly dump()'s text.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace uvtk::io {

// dump(indent)'s text; indent < 0 is the compact form.
std::string jsonText(const nlohmann::json& value, int indent = -1);

// Reading such text back, for a parser that refuses lone surrogates (nlohmann's): turns each
// \udcXX (0x80 <= XX <= 0xFF) not after a high-surrogate escape into \uf7XX, a private-use
// character written in as many bytes, so offsets in messages stay exact; returns whether there was
// one. restoreEscapedBytes then turns each U+F780..U+F7FF of a string read from it back into the
// byte 0xXX. Parsers try the text as it is first: only a document that holds such an escape reads
// U+F780..U+F7FF as bytes.
bool markLoneByteEscapes(std::string& text);
std::string restoreEscapedBytes(const std::string& value);

// restoreEscapedBytes on every string and key of a parsed document.
template <class Json>
Json restoredDocument(const Json& value) {
  if (value.is_string()) return restoreEscapedBytes(value.template get<std::string>());
  if (value.is_array()) {
    Json out = Json::array();
    for (const Json& element : value) out.push_back(restoredDocument(element));
    return out;
  }
  if (value.is_object()) {
    Json out = Json::object();
    for (auto it = value.begin(); it != value.end(); ++it) out[restoreEscapedBytes(it.key())] = restoredDocument(it.value());
    return out;
  }
  return value;
}

}  // namespace uvtk::io
