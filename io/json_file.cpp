// Strict JSON input over nlohmann's parser. nlohmann finds the syntax errors; this file words them as the
// project's "FILE:LINE:COLUMN: error: expected ..., found ..." and adds what nlohmann accepts but an input file
// must not have: duplicate keys (nlohmann silently keeps the last), unbounded nesting and bytes after a NUL.
//
// Decisions:
// - LINE and COLUMN are 1-based; COLUMN counts UTF-8 characters, as an editor does (a tab is one column).
// - nlohmann reports the position of the last byte it read, which is the last byte of an unexpected token; the
//   message points at the token's first byte instead, and quotes the token. "found end of file" points just
//   past the last byte.
// - A UTF-8 byte-order mark is removed before parsing, so that it is not a column of line 1. A UTF-16 one is named
//   as such: nlohmann would only see a stray byte 0xFF or 0xFE, which does not tell the user what is wrong.
#include "io/json_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "core/error.h"
#include "io/json_text.h"

namespace uvtk::io {
namespace {

constexpr std::uintmax_t kMaxBytes = std::uintmax_t{64} << 20;
// Copying, printing and comparing a nlohmann value recurse into it: bound the nesting so that a hostile file
// cannot overflow the stack of whoever uses the document.
constexpr std::size_t kMaxDepth = 512;
// Tokens quoted in messages are cut to this many characters, so a megabyte of junk makes a readable error.
constexpr std::size_t kMaxQuoted = 40;
constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
constexpr std::string_view kUtf16ByteOrderMarks[] = {"\xFF\xFE", "\xFE\xFF"};  // little-, big-endian

bool isContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// 'TOKEN', cut at a character boundary.
std::string quote(std::string_view token) {
  std::size_t end = 0;
  for (std::size_t characters = 0; end < token.size() && characters < kMaxQuoted; ++characters) {
    ++end;
    while (end < token.size() && isContinuationByte(token[end])) ++end;
  }
  return "'" + std::string(token.substr(0, end)) + (end < token.size() ? "...'" : "'");
}

InputError fileError(const std::string& path, const std::string& what) { return InputError(path + ": error: " + what); }

// "NAME:LINE:COLUMN: error: WHAT" for the byte at `offset` of `text` (offset == size: the end of the text).
InputError errorAt(const std::string& name, std::string_view text, std::size_t offset, const std::string& what) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      line += 1;
      column = 1;
    } else if (!isContinuationByte(text[i])) {
      column += 1;
    }
  }
  return InputError(name + ":" + std::to_string(line) + ":" + std::to_string(column) + ": error: " + what);
}

// The character at `offset` as a message names it: 'c' (a whole UTF-8 character), a control character, a byte
// that does not start valid UTF-8, or the end of the file.
std::string describeAt(std::string_view text, std::size_t offset) {
  if (offset >= text.size()) return "end of file";
  const auto lead = static_cast<unsigned char>(text[offset]);
  char hex[8];
  if (lead < 0x20 || lead == 0x7F) {
    std::snprintf(hex, sizeof hex, "%04X", lead);
    return std::string("control character U+") + hex;
  }
  const std::size_t length = lead < 0x80                   ? 1
                             : lead >= 0xC2 && lead < 0xE0 ? 2
                             : lead >= 0xE0 && lead < 0xF0 ? 3
                             : lead >= 0xF0 && lead < 0xF5 ? 4
                                                           : 0;
  bool valid = length > 0 && offset + length <= text.size();
  for (std::size_t i = 1; valid && i < length; ++i) valid = isContinuationByte(text[offset + i]);
  if (valid) return quote(text.substr(offset, length));
  std::snprintf(hex, sizeof hex, "%02X", lead);
  return std::string("byte 0x") + hex;
}

// The opening quote of the string whose closing quote is at `closing`: the nearest earlier quote not escaped,
// that is not preceded by an odd number of backslashes.
std::size_t stringStart(std::string_view text, std::size_t closing) {
  for (std::size_t i = closing; i-- > 0;) {
    if (text[i] != '"') continue;
    std::size_t backslashes = 0;
    while (backslashes < i && text[i - 1 - backslashes] == '\\') ++backslashes;
    if (backslashes % 2 == 0) return i;
  }
  return 0;
}

bool isNumberByte(char c) { return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-'; }

// The first byte of the number token ending at `last`: back over the bytes a number may contain, then forward
// to the first that may start one ("true2" holds the number "2", not "e2").
std::size_t numberStart(std::string_view text, std::size_t last) {
  std::size_t start = last;
  while (start > 0 && isNumberByte(text[start - 1])) --start;
  while (start < last && text[start] != '-' && !(text[start] >= '0' && text[start] <= '9')) ++start;
  return start;
}

// The first byte of the token of type `token` (nlohmann's name for it) whose last byte is at `last`.
std::size_t tokenStart(std::string_view text, const std::string& token, std::size_t last) {
  if (token == "string literal") return stringStart(text, last);
  if (token == "number literal") return numberStart(text, last);
  if (token == "true literal" || token == "null literal") return last - 3;
  if (token == "false literal") return last - 4;
  return last;  // punctuation and the end of input are one position
}

bool isWordByte(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
         c == '+' || c == '.';
}

bool startsWith(const std::string& s, std::string_view prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

bool endsWith(const std::string& s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The text between `open` and `close` in `s`, or "" if `open` is not there.
std::string between(const std::string& s, std::string_view open, std::string_view close) {
  const std::size_t begin = s.find(open);
  if (begin == std::string::npos) return "";
  const std::size_t from = begin + open.size();
  return s.substr(from, s.find(close, from) - from);
}

// What the lexer wanted when a token that started well went wrong, keyed by nlohmann's message for it.
const std::pair<std::string_view, std::string_view> kLexerExpectations[] = {
    {"invalid string: missing closing quote", "a closing quote"},
    {"invalid string: ill-formed UTF-8 byte", "UTF-8 text"},
    {"invalid string: forbidden character after backslash", "one of \" \\ / b f n r t u after a backslash"},
    {"invalid string: '\\u' must be followed by 4 hex digits", "4 hex digits after \\u"},
    {"invalid string: surrogate U+D800..U+DBFF must be followed by U+DC00..U+DFFF",
     "\\uDC00..\\uDFFF after \\uD800..\\uDBFF"},
    {"invalid string: surrogate U+DC00..U+DFFF must follow U+D800..U+DBFF", "\\uD800..\\uDBFF before \\uDC00..\\uDFFF"},
    {"invalid BOM; must be 0xEF 0xBB 0xBF if given", "a UTF-8 byte-order mark (EF BB BF)"},
    {"invalid number; expected digit after '-'", "a digit after '-'"},
    {"invalid number; expected digit after '.'", "a digit after '.'"},
    {"invalid number; expected '+', '-', or digit after exponent", "'+', '-' or a digit after the exponent"},
};

// Hands the text to nlohmann's parser byte by byte and records how far the parser has read: a SAX event comes
// without a position.
class TrackingIterator {
 public:
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  TrackingIterator(const char* position, const char** reached) : position_(position), reached_(reached) {}
  reference operator*() const { return *position_; }
  TrackingIterator& operator++() {
    *reached_ = ++position_;
    return *this;
  }
  TrackingIterator operator++(int) {
    TrackingIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const TrackingIterator& other) const { return position_ == other.position_; }
  bool operator!=(const TrackingIterator& other) const { return position_ != other.position_; }

 private:
  const char* position_;
  const char** reached_;
};

// Builds the document from nlohmann's SAX events, as nlohmann's own DOM parser does, and rejects what that
// parser lets through. (nlohmann's parser callback would see the keys too, but with a callback its parser scans
// the parent container at the end of every object: quadratic time for an array of many objects.)
class StrictParser {
 public:
  using Json = nlohmann::json;

  // `escapedBytes`: the text's lone \udcXX escapes were turned into \uf7XX (see parseJsonText): each
  // U+F780..U+F7FF of a string or key is the byte 0xXX again.
  StrictParser(std::string_view text, const std::string& name, bool escapedBytes = false)
      : text_(text), name_(name), reached_(text.data()), escapedBytes_(escapedBytes) {}

  Json parse() {
    Json::sax_parse(TrackingIterator(text_.data(), &reached_), TrackingIterator(text_.data() + text_.size(), &reached_),
                    this);
    // nlohmann takes a NUL byte for the end of the input, so it accepts anything after one. A NUL inside the
    // document is an error already; one after it is trailing garbage.
    if (const std::size_t nul = text_.find('\0'); nul != std::string_view::npos)
      throw errorAt(name_, text_, nul, "expected end of file, found " + describeAt(text_, nul));
    return std::move(root_);
  }

  // The SAX interface that nlohmann calls. Its parser and lexer have read a key or an opening bracket up to the
  // last byte when they report it, and no further.
  bool null() { return add(nullptr); }
  bool boolean(bool value) { return add(value); }
  bool number_integer(Json::number_integer_t value) { return add(value); }
  bool number_unsigned(Json::number_unsigned_t value) { return add(value); }
  bool number_float(Json::number_float_t value, const std::string& /*text*/) { return add(value); }
  bool string(std::string& value) { return add(restoredBytes(std::move(value))); }
  bool binary(Json::binary_t& value) { return add(Json::binary(std::move(value))); }  // only binary formats
  bool start_object(std::size_t /*unknown size*/) { return open(Json::object()); }
  bool start_array(std::size_t /*unknown size*/) { return open(Json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(std::string& name) {
    const std::string key = restoredBytes(std::move(name));
    Json& object = *open_.back();
    if (object.contains(key))
      throw errorAt(name_, text_, stringStart(text_, readCount() - 1),
                    "duplicate key " + Json(key).dump(-1, ' ', false, Json::error_handler_t::replace));
    member_ = &object[key];
    return true;
  }

  bool parse_error(std::size_t byte, const std::string& /*last token*/, const Json::exception& e) {
    // 406: a number too large for a double, reported just after its last byte.
    if (e.id == 406) {
      const std::size_t last = std::min(byte, text_.size()) - 1;
      const std::size_t start = numberStart(text_, last);
      throw errorAt(
          name_, text_, start,
          "expected a number within the range of a double, found " + quote(text_.substr(start, last + 1 - start)));
    }
    throw syntaxError(byte, e.what());
  }

 private:
  // Bytes the parser has read.
  std::size_t readCount() const { return static_cast<std::size_t>(reached_ - text_.data()); }

  // Puts a value where the document is: the root, the end of the open array, or the member of the last key.
  Json* place(Json value) {
    if (open_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    Json& container = *open_.back();
    if (container.is_array()) {
      container.push_back(std::move(value));
      return &container.back();
    }
    *member_ = std::move(value);
    return member_;
  }

  bool add(Json value) {
    place(std::move(value));
    return true;
  }

  bool open(Json container) {
    if (open_.size() >= kMaxDepth)
      throw errorAt(name_, text_, readCount() - 1,
                    "expected at most " + std::to_string(kMaxDepth) + " nested arrays and objects, found " +
                        std::to_string(open_.size() + 1));
    // The pointer stays valid: nothing is added to a container while one of its members is open.
    open_.push_back(place(std::move(container)));
    return true;
  }

  bool close() {
    open_.pop_back();
    return true;
  }

  // nlohmann's message reads "... syntax error while parsing CONTEXT - DETAIL[; expected TOKEN]", DETAIL being
  // "unexpected TOKEN" or the lexer's complaint about a malformed token and "; last read: '...'".
  InputError syntaxError(std::size_t byte, const std::string& message) const {
    const std::size_t offset = std::min<std::size_t>(byte > 0 ? byte - 1 : 0, text_.size());
    const std::string context = between(message, "while parsing ", " - ");
    const std::string detail = message.substr(std::min(message.find(" - "), message.size()));

    std::size_t start = offset;
    std::string found;
    if (startsWith(detail, " - unexpected ")) {
      const std::string token = between(detail, "unexpected ", ";");
      start = tokenStart(text_, token, offset);
      // The "end of input" may be a NUL byte, which describeAt names.
      found = token == "end of input" ? describeAt(text_, offset) : quote(text_.substr(start, offset + 1 - start));
    } else {
      const std::string lexerMessage = between(detail, " - ", "; last read: ");
      for (const auto& [complaint, expected] : kLexerExpectations) {
        if (lexerMessage != complaint) continue;
        // A misplaced surrogate is noticed at the last hex digit of its escape: quote the whole escape.
        const bool escape = offset >= 5 && text_.substr(offset - 5, 2) == "\\u";
        if (complaint.find("surrogate") != std::string_view::npos && escape)
          return errorAt(name_, text_, offset - 5,
                         "expected " + std::string(expected) + ", found " + quote(text_.substr(offset - 5, 6)));
        return errorAt(name_, text_, offset,
                       "expected " + std::string(expected) + ", found " + describeAt(text_, offset));
      }
      const std::string escapes = between(lexerMessage, " must be escaped to ", ";");
      if (!escapes.empty())
        return errorAt(name_, text_, offset, "expected the escape " + escapes + ", found " + describeAt(text_, offset));
      if (lexerMessage != "invalid literal")
        return errorAt(name_, text_, offset, "expected valid JSON, found " + lexerMessage);
      // A bare word where a value or punctuation belongs: quote the whole word ("tru", not 't').
      while (start > 0 && isWordByte(text_[start - 1])) --start;
      std::size_t end = offset;
      while (end < text_.size() && isWordByte(text_[end])) ++end;
      found = end > start ? quote(text_.substr(start, end - start)) : describeAt(text_, offset);
    }
    return errorAt(name_, text_, start, "expected " + expectedIn(context, message, start) + ", found " + found);
  }

  // What the parser wanted in `context` (nlohmann's name for it) at the token starting at `start`.
  std::string expectedIn(const std::string& context, const std::string& message, std::size_t start) const {
    if (context == "value") return endsWith(message, "; expected end of input") ? "end of file" : "a value";
    if (context == "object separator") return "':'";
    if (context == "array") return "',' or ']'";
    if (context == "object") return "',' or '}'";
    if (context == "object key") {
      // Right after '{' the object may also close; after ',' a key must follow.
      std::size_t previous = start;
      while (previous > 0 && std::string_view(" \t\r\n").find(text_[previous - 1]) != std::string_view::npos)
        --previous;
      return previous > 0 && text_[previous - 1] == '{' ? "a quoted key or '}'" : "a quoted key";
    }
    return "valid JSON";
  }

  std::string restoredBytes(std::string value) const { return escapedBytes_ ? restoreEscapedBytes(std::move(value)) : value; }

  std::string_view text_;
  const std::string& name_;
  const char* reached_;  // one past the last byte the parser has read
  bool escapedBytes_;
  Json root_;
  std::vector<Json*> open_;  // the open arrays and objects, innermost last
  Json* member_ = nullptr;   // where the value of the last key goes
};

}  // namespace

nlohmann::json parseJsonText(const std::string& text, const std::string& name) {
  std::string_view body = text;
  if (body.substr(0, kByteOrderMark.size()) == kByteOrderMark) body.remove_prefix(kByteOrderMark.size());
  for (const std::string_view mark : kUtf16ByteOrderMarks)
    if (body.substr(0, mark.size()) == mark)
      throw errorAt(name, body, 0, "expected UTF-8 text, found a UTF-16 byte-order mark");
  try {
    return StrictParser(body, name).parse();
  } catch (const InputError&) {
    // A byte that is not UTF-8 in a name is written as \udcXX (io/json_text.h); read back, each
    // such lone escape is that byte again. The text is tried as it is first, so a document without
    // one reads exactly as before; the replacement keeps every offset, so messages stay exact.
    std::string escaped(body);
    if (!markLoneByteEscapes(escaped)) throw;
    return StrictParser(escaped, name, true).parse();
  }
}

nlohmann::json readJsonFile(const std::string& path) {
  // A directory opens as a stream on Linux and only fails on reading: name the real reason.
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored))
    throw fileError(path, "cannot open: " + std::generic_category().message(EISDIR));
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int error = errno;
    throw fileError(path, "cannot open: " + (error ? std::generic_category().message(error) : "unknown error"));
  }

  const std::string limit = "expected at most 64 MiB (" + std::to_string(kMaxBytes) + " bytes)";
  std::error_code sizeError;  // only regular files have a size; the reading below bounds the others
  const std::uintmax_t size = std::filesystem::file_size(path, sizeError);
  if (!sizeError && size > kMaxBytes) throw fileError(path, limit + ", found " + std::to_string(size) + " bytes");
  std::string text;
  if (!sizeError) text.reserve(size);
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxBytes) throw fileError(path, limit + ", found more");
  }
  if (in.bad()) throw fileError(path, "cannot read: input/output error");
  return parseJsonText(text, path);
}

}  // namespace uvtk::io
