#include "io/json_text.h"

#include <cctype>
#include <cstddef>
#include <cstdio>
#include <cstring>

namespace uvtk::io {
namespace {

using Json = nlohmann::json;

// The length of the valid UTF-8 sequence at `at` (RFC 3629: shortest form, no surrogates, at most
// U+10FFFF), or 0 when the byte there does not start one.
std::size_t utf8SequenceLength(const std::string& s, std::size_t at) {
  const auto byte = [&](std::size_t i) { return i < s.size() ? static_cast<unsigned char>(s[i]) : 0u; };
  const unsigned b0 = byte(at);
  const auto continuation = [&](std::size_t i) { return (byte(i) & 0xC0u) == 0x80u; };
  if (b0 < 0x80) return 1;
  if (b0 >= 0xC2 && b0 <= 0xDF) return continuation(at + 1) ? 2 : 0;
  if (b0 >= 0xE0 && b0 <= 0xEF) {
    const unsigned b1 = byte(at + 1);
    const bool second = b0 == 0xE0 ? (b1 >= 0xA0 && b1 <= 0xBF) : b0 == 0xED ? (b1 >= 0x80 && b1 <= 0x9F) : continuation(at + 1);
    return second && continuation(at + 2) ? 3 : 0;
  }
  if (b0 >= 0xF0 && b0 <= 0xF4) {
    const unsigned b1 = byte(at + 1);
    const bool second = b0 == 0xF0 ? (b1 >= 0x90 && b1 <= 0xBF) : b0 == 0xF4 ? (b1 >= 0x80 && b1 <= 0x8F) : continuation(at + 1);
    return second && continuation(at + 2) && continuation(at + 3) ? 4 : 0;
  }
  return 0;
}

// A string as dump() quotes it, each stray byte as \udcXX.
void appendString(std::string& out, const std::string& s) {
  out += '"';
  std::size_t i = 0;
  while (i < s.size()) {
    std::size_t end = i;
    while (end < s.size()) {
      const std::size_t length = utf8SequenceLength(s, end);
      if (length == 0) break;
      end += length;
    }
    if (end > i) {
      const std::string quoted = Json(s.substr(i, end - i)).dump();
      out.append(quoted, 1, quoted.size() - 2);
    }
    if (end < s.size()) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\udc%02x", static_cast<unsigned char>(s[end]));
      out += escape;
      ++end;
    }
    i = end;
  }
  out += '"';
}

// dump()'s layout: "key": value, an object's members and an array's elements one per line at
// `indent` spaces a level (or none, compact), an empty object or array as {} and [].
void append(std::string& out, const Json& value, int indent, int depth) {
  const bool pretty = indent >= 0;
  const auto newline = [&](int level) {
    if (!pretty) return;
    out += '\n';
    out.append(static_cast<std::size_t>(indent * level), ' ');
  };
  if (value.is_string()) {
    appendString(out, value.get_ref<const std::string&>());
  } else if (value.is_object() && !value.empty()) {
    out += '{';
    bool first = true;
    for (auto it = value.begin(); it != value.end(); ++it) {
      if (!first) out += ',';
      first = false;
      newline(depth + 1);
      appendString(out, it.key());
      out += pretty ? ": " : ":";
      append(out, it.value(), indent, depth + 1);
    }
    newline(depth);
    out += '}';
  } else if (value.is_array() && !value.empty()) {
    out += '[';
    bool first = true;
    for (const Json& element : value) {
      if (!first) out += ',';
      first = false;
      newline(depth + 1);
      append(out, element, indent, depth + 1);
    }
    newline(depth);
    out += ']';
  } else {
    out += value.dump();  // numbers, booleans, null, {} and []
  }
}

}  // namespace

bool markLoneByteEscapes(std::string& text) {
  bool marked = false;
  const auto lower = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
  const auto hexIn = [&](char c, const char* digits) { return std::strchr(digits, lower(c)) != nullptr && c != 0; };
  const auto highSurrogateAt = [&](std::size_t at) {  // "\\ud800".."\\udbff"
    return text[at] == '\\' && lower(text[at + 1]) == 'u' && lower(text[at + 2]) == 'd' && hexIn(text[at + 3], "89ab");
  };
  for (std::size_t i = 0; i + 6 <= text.size(); ++i) {
    if (text[i] != '\\') continue;
    const bool lone = lower(text[i + 1]) == 'u' && lower(text[i + 2]) == 'd' && lower(text[i + 3]) == 'c' &&
                      hexIn(text[i + 4], "89abcdef") && hexIn(text[i + 5], "0123456789abcdef") &&
                      !(i >= 6 && highSurrogateAt(i - 6));
    if (lone) {
      text[i + 2] = 'f', text[i + 3] = '7';
      marked = true;
      i += 5;
    } else {
      ++i;  // an escaped character: the next one does not start an escape
    }
  }
  return marked;
}

std::string restoreEscapedBytes(const std::string& value) {
  std::string out;
  out.reserve(value.size());
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(value[k]); };
  for (std::size_t i = 0; i < value.size(); ++i) {
    // U+F780..U+F7FF is EF 9E 80..EF 9F BF: the byte 0x80 + the seven bits it carries.
    if (i + 2 < value.size() && byte(i) == 0xEF && (byte(i + 1) == 0x9E || byte(i + 1) == 0x9F)) {
      out += static_cast<char>(0x80 | ((byte(i + 1) & 1) << 6) | (byte(i + 2) & 0x3F));
      i += 2;
    } else {
      out += value[i];
    }
  }
  return out;
}

std::string jsonText(const Json& value, int indent) {
  try {
    return value.dump(indent);
  } catch (const Json::type_error&) {  // 316: a string that is not UTF-8
    std::string out;
    append(out, value, indent, 0);
    return out;
  }
}

}  // namespace uvtk::io
