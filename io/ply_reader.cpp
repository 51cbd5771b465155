// Strict PLY reader: the header parsed line by line into element and property descriptions, then
// the data read by one element loop over two sources, ASCII (tokens, std::from_chars) and binary
// (memcpy and a byte swap where the file's order is not the host's). The stream is read in large
// blocks into one buffer; memory follows the data read, never a count the header claims.
//
// Decisions where the format leaves room:
// - Header lines end with \n or \r\n; comment and obj_info lines may appear anywhere after `ply`,
//   blank lines are skipped; control bytes other than tab are errors. A UTF-8 byte-order mark is
//   an error: no PLY reader accepts one.
// - Element and property names may not repeat. Every element needs a property unless its count is 0.
// - Counts are at most INT_MAX (elements and list lengths). A face has at least 3 corners.
// - Every float and double value in the file must be finite, the ignored ones too; ASCII values
//   are parsed at their declared type (a float property as a float, an integer one as an integer
//   of that type's range), so an ASCII file reads exactly as its binary twin.
// - vertex: x y z (any scalar type) required; nx ny nz all or none; texcoords from the first pair
//   present of s t, u v, texture_u texture_v, texture_s texture_t; red green blue counted as
//   vertex colours; anything else read and dropped.
// - face: a list vertex_indices or vertex_index (not both) of an integer type; an optional list
//   `texcoord` of 2 numbers per corner (MeshLab's per-wedge UVs), which wins over vertex texcoords.
// - The vertex element may follow the face element: faces are then kept as read and checked and
//   triangulated at the end, an index past the end named at the face's place.
// - ASCII: one element per line (blank lines between are skipped), nothing but white space after
//   the last; binary: nothing at all after the last element.
// - A binary file's polygons that are not simple are counted with line 0: there are no lines.
#include "io/ply_reader.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <istream>
#include <string_view>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "io/face_lists.h"
#include "io/number_text.h"
#include "io/polygon_triangulation.h"

namespace uvtk::io {
namespace {

// A count read from a file is a claim: reserve at most this many elements for it.
constexpr std::size_t kMaxReserve = std::size_t{1} << 20;
constexpr std::size_t kMaxQuoted = 40;
// The longest line accepted, header or ASCII data (a face of a million corners takes about 10 MB).
constexpr std::size_t kMaxLineBytes = std::size_t{64} << 20;
constexpr std::size_t kFirstReadBlock = std::size_t{1} << 16;
constexpr std::size_t kReadBlock = std::size_t{1} << 20;

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
constexpr bool kHostLittleEndian = false;
#else
constexpr bool kHostLittleEndian = true;
#endif

// A token for a message, cut to kMaxQuoted bytes, its control bytes escaped (core/error.h's
// printable()): binary junk quoted raw could hold a NUL that would cut the message.
std::string quote(std::string_view token) {
  if (token.size() > kMaxQuoted) return "'" + printable(token.substr(0, kMaxQuoted)) + "...'";
  return "'" + printable(token) + "'";
}

// "FILE:LINE: error: WHAT" (text), "FILE: byte N: error: WHAT" (binary data), "FILE: error: WHAT".
[[noreturn]] void failAtLine(const std::string& name, std::size_t line, const std::string& expected,
                             const std::string& found) {
  throw InputError(name + ":" + std::to_string(line) + ": error: expected " + expected + ", found " + found);
}

[[noreturn]] void failAtByte(const std::string& name, std::uint64_t byte, const std::string& expected,
                             const std::string& found) {
  throw InputError(name + ": byte " + std::to_string(byte) + ": error: expected " + expected + ", found " + found);
}

// ---------------------------------------------------------------------------------------------
// Types and the header

enum class Type : std::uint8_t { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

struct TypeInfo {
  const char* name;   // as messages show it
  const char* alias;  // the other spelling the header may use
  int size;
  bool isFloat;
  long long min, max;
};

constexpr TypeInfo kTypes[] = {
    {"char", "int8", 1, false, INT8_MIN, INT8_MAX},        {"uchar", "uint8", 1, false, 0, UINT8_MAX},
    {"short", "int16", 2, false, INT16_MIN, INT16_MAX},    {"ushort", "uint16", 2, false, 0, UINT16_MAX},
    {"int", "int32", 4, false, INT32_MIN, INT32_MAX},      {"uint", "uint32", 4, false, 0, UINT32_MAX},
    {"float", "float32", 4, true, 0, 0},                   {"double", "float64", 8, true, 0, 0},
};

const TypeInfo& info(Type t) { return kTypes[static_cast<int>(t)]; }

bool parseType(std::string_view token, Type& type) {
  for (int i = 0; i < 8; ++i)
    if (token == kTypes[i].name || token == kTypes[i].alias) {
      type = static_cast<Type>(i);
      return true;
    }
  return false;
}

const char* const kTypeList = "char, uchar, short, ushort, int, uint, float, double, or int8 ... float64";

// What a property is to this reader.
enum Role : std::uint8_t { kIgnored, kX, kY, kZ, kNx, kNy, kNz, kU, kV, kIndices, kFaceTexcoords };

struct Property {
  std::string name;
  bool list = false;
  Type countType = Type::uint8;
  Type type = Type::float32;  // of the value, or of each list item
  Role role = kIgnored;
  std::size_t line = 0;
};

struct Element {
  std::string name;
  long long count = 0;
  std::size_t line = 0;
  std::vector<Property> properties;
};

enum class Format { ascii, binaryLittleEndian, binaryBigEndian };

struct Header {
  Format format = Format::ascii;
  std::vector<Element> elements;
  int vertexElement = -1, faceElement = -1;
  bool normals = false, vertexTexcoords = false, faceTexcoords = false, colours = false;
  ListedFaces listedFaces;  // 0-based, from uvtk's comments (io/face_lists.h)
};

// "1 vertex", "6 faces", "2 'edge' elements".
std::string countOf(const Element& e, long long n) {
  const std::string count = std::to_string(n);
  if (e.name == "vertex") return count + (n == 1 ? " vertex" : " vertices");
  if (e.name == "face") return count + (n == 1 ? " face" : " faces");
  return count + " '" + e.name + (n == 1 ? "' element" : "' elements");
}

// ---------------------------------------------------------------------------------------------
// The stream, read in large blocks into one buffer

class ByteStream {
 public:
  ByteStream(std::istream& in, const std::string& name) : in_(in), name_(name) {}

  // The next n bytes, consumed; null if the stream ends first.
  const char* take(std::size_t n) {
    if (filled_ - next_ < n && !fill(n)) return nullptr;
    const char* p = buffer_.data() + next_;
    next_ += n;
    return p;
  }

  // Up to n bytes from the current position, not consumed.
  std::string_view peek(std::size_t n) {
    if (filled_ - next_ < n) fill(n);
    return {buffer_.data() + next_, std::min(n, filled_ - next_)};
  }

  // The 0-based offset in the file of the next byte.
  std::uint64_t offset() const { return base_ + next_; }

  enum class Line { ok, endOfFile, tooLong };
  // The next line without its '\n' (the last may end at end of file without one). The view lives
  // until the next call.
  Line line(std::string_view& text) {
    std::size_t searched = 0;
    for (;;) {
      const std::size_t available = filled_ - next_;
      const char* begin = buffer_.data() + next_;
      const void* newline = available > searched ? std::memchr(begin + searched, '\n', available - searched) : nullptr;
      if (newline) {
        const std::size_t length = static_cast<std::size_t>(static_cast<const char*>(newline) - begin);
        text = {begin, length};
        next_ += length + 1;
        return Line::ok;
      }
      searched = available;
      if (available > kMaxLineBytes) return Line::tooLong;
      if (!fill(available + 1)) {
        if (available == 0) return Line::endOfFile;
        text = {buffer_.data() + next_, available};
        next_ += available;
        return Line::ok;
      }
    }
  }

  // Consumes the rest of the stream; returns how many bytes it held.
  std::uint64_t drain() {
    std::uint64_t count = filled_ - next_;
    next_ = filled_;
    while (fill(1)) {
      count += filled_;
      next_ = filled_;
    }
    return count;
  }

 private:
  // Makes at least n bytes available from next_, reading whole blocks; false if the stream ends first.
  bool fill(std::size_t n) {
    if (next_ > 0) {
      std::memmove(buffer_.data(), buffer_.data() + next_, filled_ - next_);
      filled_ -= next_;
      base_ += next_;
      next_ = 0;
    }
    // Small inputs take a small buffer: 64 KiB at first, twice as much each time up to 1 MiB; a long
    // line grows it further, doubling so that a line of n bytes costs O(n).
    std::size_t size = buffer_.empty() ? kFirstReadBlock : std::min(kReadBlock, 2 * buffer_.size());
    if (n > size) size = std::max(n, std::min(2 * buffer_.size(), kMaxLineBytes + 1));
    if (size > buffer_.size()) buffer_.resize(size);
    while (filled_ < n && !ended_) {
      in_.read(buffer_.data() + filled_, static_cast<std::streamsize>(buffer_.size() - filled_));
      if (in_.bad()) throw InputError(name_ + ": error: cannot read: input/output error");
      const std::size_t got = static_cast<std::size_t>(in_.gcount());
      filled_ += got;
      ended_ = filled_ < buffer_.size();
    }
    return filled_ >= n;
  }

  std::istream& in_;
  const std::string& name_;
  std::vector<char> buffer_;
  std::size_t next_ = 0, filled_ = 0;  // the first unread byte of buffer_, and how many it holds
  std::uint64_t base_ = 0;             // the file offset of buffer_[0]
  bool ended_ = false;
};

bool isBlank(char c) { return c == ' ' || c == '\t'; }

// Splits a line into blank-separated tokens, front to back.
class Tokens {
 public:
  explicit Tokens(std::string_view text) : p_(text.data()), end_(text.data() + text.size()) {}
  std::string_view next() {
    while (p_ != end_ && isBlank(*p_)) ++p_;
    const char* start = p_;
    while (p_ != end_ && !isBlank(*p_)) ++p_;
    return {start, static_cast<std::size_t>(p_ - start)};
  }
  bool atEnd() {
    while (p_ != end_ && isBlank(*p_)) ++p_;
    return p_ == end_;
  }

 private:
  const char* p_;
  const char* end_;
};

// A header line: its text without line ending, checked for control bytes.
class HeaderReader {
 public:
  HeaderReader(ByteStream& bytes, const std::string& name) : bytes_(bytes), name_(name) {}

  // The first line must be `ply`; a file of another kind is refused from its first bytes.
  void expectMagic() {
    const std::string_view start = bytes_.peek(64);
    if (start.size() >= 3 && static_cast<unsigned char>(start[0]) == 0xEF &&
        static_cast<unsigned char>(start[1]) == 0xBB && static_cast<unsigned char>(start[2]) == 0xBF)
      failAtLine(name_, 1, "'ply'", "a UTF-8 byte-order mark");
    std::string_view first = start.substr(0, start.find('\n'));
    const bool whole = first.size() < start.size();
    if (!first.empty() && first.back() == '\r' && whole) first.remove_suffix(1);
    if (first != "ply")
      failAtLine(name_, 1, "'ply' (the first line of a PLY file)", start.empty() ? "end of file" : quote(first));
    next();
  }

  // Advances to the next line; false at end of file.
  bool next() {
    std::string_view text;
    switch (bytes_.line(text)) {
      case ByteStream::Line::endOfFile:
        return false;
      case ByteStream::Line::tooLong:
        failAtLine(name_, line_ + 1, "a line of at most " + std::to_string(kMaxLineBytes >> 20) + " MiB",
                   "a longer one");
      case ByteStream::Line::ok:
        break;
    }
    ++line_;
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    for (const char ch : text) {
      const unsigned char c = static_cast<unsigned char>(ch);
      if ((c < 0x20 && c != '\t') || c == 0x7F) {
        static constexpr char kHex[] = "0123456789ABCDEF";
        fail("text", std::string("byte 0x") + kHex[c >> 4] + kHex[c & 15]);
      }
    }
    text_ = text;
    return true;
  }

  std::string_view text() const { return text_; }
  std::size_t line() const { return line_; }

  [[noreturn]] void fail(const std::string& expected, const std::string& found) const {
    failAtLine(name_, line_, expected, found);
  }
  [[noreturn]] void failAt(const std::string& expected, std::string_view token) const {
    fail(expected, token.empty() ? "end of line" : quote(token));
  }

 private:
  ByteStream& bytes_;
  const std::string& name_;
  std::string_view text_;
  std::size_t line_ = 0;
};


Property* findProperty(Element& e, std::string_view name) {
  for (Property& p : e.properties)
    if (p.name == name) return &p;
  return nullptr;
}

void parseFormat(HeaderReader& reader, Tokens& tokens, Format& format) {
  const std::string_view kind = tokens.next();
  if (kind == "ascii")
    format = Format::ascii;
  else if (kind == "binary_little_endian")
    format = Format::binaryLittleEndian;
  else if (kind == "binary_big_endian")
    format = Format::binaryBigEndian;
  else
    reader.failAt("a format ascii, binary_little_endian or binary_big_endian", kind);
  const std::string_view version = tokens.next();
  if (version != "1.0") reader.failAt("format version 1.0", version);
}

Element parseElement(HeaderReader& reader, Tokens& tokens, const std::vector<Element>& elements) {
  Element e;
  e.line = reader.line();
  const std::string_view name = tokens.next();
  if (name.empty()) reader.failAt("an element name", name);
  for (const Element& other : elements)
    if (other.name == name) reader.failAt("an element name not used before", name);
  e.name = std::string(name);
  const std::string_view count = tokens.next();
  if (!parseInteger(count, e.count) || e.count < 0) reader.failAt("an element count (a non-negative integer)", count);
  if (e.count > INT_MAX) reader.failAt("an element count of at most " + std::to_string(INT_MAX), count);
  return e;
}

Property parseProperty(HeaderReader& reader, Tokens& tokens, Element& element) {
  Property p;
  p.line = reader.line();
  std::string_view type = tokens.next();
  if (type == "list") {
    p.list = true;
    const std::string_view countType = tokens.next();
    if (!parseType(countType, p.countType) || info(p.countType).isFloat)
      reader.failAt("an integer type for a list count (char, uchar, short, ushort, int, uint, or int8 ... uint32)",
                    countType);
    type = tokens.next();
  }
  if (!parseType(type, p.type)) reader.failAt(std::string("a property type (") + kTypeList + ")", type);
  const std::string_view name = tokens.next();
  if (name.empty()) reader.failAt("a property name", name);
  if (findProperty(element, name))
    reader.failAt("a property name not used before in element '" + element.name + "'", name);
  p.name = std::string(name);
  return p;
}

// An element of a positive count needs something to read.
void checkHasProperties(const HeaderReader& reader, const std::vector<Element>& elements, std::string_view keyword) {
  if (elements.empty()) return;
  const Element& e = elements.back();
  if (e.count > 0 && e.properties.empty())
    reader.fail("a property of element '" + e.name + "' (its count is " + std::to_string(e.count) + ")",
                quote(keyword));
}

// Gives the vertex and face properties their roles, or says what is missing.
void assignRoles(Header& header, const std::string& name, std::size_t endLine) {
  for (std::size_t i = 0; i < header.elements.size(); ++i) {
    if (header.elements[i].name == "vertex") header.vertexElement = static_cast<int>(i);
    if (header.elements[i].name == "face") header.faceElement = static_cast<int>(i);
  }
  if (header.vertexElement < 0) failAtLine(name, endLine, "an element 'vertex'", "'end_header'");
  if (header.faceElement < 0) {
    for (const Element& e : header.elements)  // old range scans store triangle strips instead
      if (e.name == "tristrips")
        failAtLine(name, e.line, "an element 'face'",
                   "'element tristrips' (triangle strips are not read: save the mesh with faces, e.g. from MeshLab)");
    failAtLine(name, endLine, "an element 'face' (a point cloud is not a mesh)", "'end_header'");
  }
  Element& vertex = header.elements[std::size_t(header.vertexElement)];
  Element& face = header.elements[std::size_t(header.faceElement)];
  if (vertex.count == 0) failAtLine(name, vertex.line, "at least one vertex", "'element vertex 0'");
  if (face.count == 0) failAtLine(name, face.line, "at least one face", "'element face 0'");

  const auto scalar = [&](const char* property) {
    Property* p = findProperty(vertex, property);
    if (p && p->list) failAtLine(name, p->line, std::string("a scalar property '") + property + "'", "a list");
    return p;
  };
  const char* const kPosition[3] = {"x", "y", "z"};
  const char* const kNormal[3] = {"nx", "ny", "nz"};
  for (int a = 0; a < 3; ++a) {
    Property* p = scalar(kPosition[a]);
    if (!p) failAtLine(name, vertex.line, "properties x, y and z in element 'vertex'", std::string("no '") + kPosition[a] + "'");
    p->role = static_cast<Role>(kX + a);
  }
  int normals = 0;
  for (int a = 0; a < 3; ++a) normals += scalar(kNormal[a]) ? 1 : 0;
  if (normals > 0) {
    for (int a = 0; a < 3; ++a) {
      Property* p = scalar(kNormal[a]);
      if (!p) failAtLine(name, vertex.line, "all or none of nx, ny and nz in element 'vertex'", std::string("no '") + kNormal[a] + "'");
      p->role = static_cast<Role>(kNx + a);
    }
    header.normals = true;
  }
  static const char* const kTexcoordPairs[4][2] = {{"s", "t"}, {"u", "v"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};
  for (const auto& pair : kTexcoordPairs) {
    Property* u = scalar(pair[0]);
    Property* v = scalar(pair[1]);
    if (!u || !v) continue;
    u->role = kU;
    v->role = kV;
    header.vertexTexcoords = true;
    break;
  }
  header.colours = findProperty(vertex, "red") && findProperty(vertex, "green") && findProperty(vertex, "blue");

  Property* indices = findProperty(face, "vertex_indices");
  if (Property* other = findProperty(face, "vertex_index")) {
    if (indices) failAtLine(name, other->line, "one of vertex_indices and vertex_index in element 'face'", "both");
    indices = other;
  }
  if (!indices) failAtLine(name, face.line, "a list vertex_indices (or vertex_index) in element 'face'", "none");
  if (!indices->list) failAtLine(name, indices->line, "a list '" + indices->name + "'", "a scalar property");
  if (info(indices->type).isFloat)
    failAtLine(name, indices->line, "a list of an integer type for '" + indices->name + "'",
               std::string("a list of ") + info(indices->type).name);
  indices->role = kIndices;
  if (Property* texcoord = findProperty(face, "texcoord")) {
    if (!texcoord->list) failAtLine(name, texcoord->line, "a list 'texcoord' (2 numbers per corner)", "a scalar property");
    texcoord->role = kFaceTexcoords;
    header.faceTexcoords = true;
  }
}

Header parseHeader(HeaderReader& reader, const std::string& name) {
  reader.expectMagic();
  Header header;
  bool haveFormat = false;
  for (;;) {
    if (!reader.next()) failAtLine(name, reader.line() + 1, "'end_header'", "end of file");
    Tokens tokens(reader.text());
    const std::string_view keyword = tokens.next();
    if (keyword == "comment") readFaceListLine(reader.text(), true, header.listedFaces);
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "format") {
      if (haveFormat) reader.fail("one format line", "a second");
      parseFormat(reader, tokens, header.format);
      haveFormat = true;
    } else if (!haveFormat) {
      reader.failAt("a format line (format ascii 1.0, ...)", keyword);
    } else if (keyword == "element") {
      checkHasProperties(reader, header.elements, keyword);
      header.elements.push_back(parseElement(reader, tokens, header.elements));
    } else if (keyword == "property") {
      if (header.elements.empty()) reader.fail("an element line before the first property", "'property'");
      header.elements.back().properties.push_back(parseProperty(reader, tokens, header.elements.back()));
    } else if (keyword == "end_header") {
      checkHasProperties(reader, header.elements, keyword);
      if (!tokens.atEnd()) reader.failAt("end of line", tokens.next());
      assignRoles(header, name, reader.line());
      return header;
    } else {
      reader.failAt("a header keyword (comment, obj_info, format, element, property or end_header)", keyword);
    }
    if (!tokens.atEnd()) reader.failAt("end of line", tokens.next());
  }
}

// ---------------------------------------------------------------------------------------------
// The data: two sources of values with one interface, read by one element loop

// What a value is, for messages: "a float for property 'z'", "an int in list 'vertex_indices'".
std::string describe(Type t, const Property& p, bool item, bool finite = false) {
  const std::string type = info(t).name;
  const std::string article = finite ? "a finite " : (type == "int" ? "an " : "a ");
  return article + type + (item ? " in list '" : " for property '") + p.name + "'";
}

std::string rangeOf(Type t) {
  return " (" + std::to_string(info(t).min) + ".." + std::to_string(info(t).max) + ")";
}

// Where the element loop is, for the message about a file that ends early.
struct Position {
  const Element* element = nullptr;
  long long index = 0;  // the element being read, 0-based: as many were read whole
};

// ASCII data: one element per line, values separated by blanks.
class AsciiSource {
 public:
  static constexpr bool kText = true;

  AsciiSource(ByteStream& bytes, const std::string& name, std::size_t line) : bytes_(bytes), name_(name), line_(line) {}

  Position at;

  void beginRecord() {
    while (nextLine())
      if (!tokens_.atEnd()) return;
    failAtLine(name_, line_ + 1, countOf(*at.element, at.element->count), std::to_string(at.index) + " and end of file");
  }

  void endRecord() {
    if (!tokens_.atEnd()) failAtLine(name_, line_, "end of line", quote(tokens_.next()));
  }

  // After the last element, only blank lines.
  void expectEnd() {
    while (nextLine())
      if (!tokens_.atEnd()) failAtLine(name_, line_, "end of file", quote(tokens_.next()));
  }

  long long count(const Property& p) {
    token_ = tokens_.next();
    if (token_.empty()) failAtLine(name_, line_, "a list count for '" + p.name + "'", "end of line");
    const long long n = integerOf(p.countType, p, kCount);
    if (n < 0 || n > INT_MAX)
      failAtLine(name_, line_, "a list count in 0.." + std::to_string(INT_MAX) + " for '" + p.name + "'", quote(token_));
    return n;
  }

  // The value of a scalar property (listCount < 0) or item `item` of a list of listCount.
  long long integer(const Property& p, long long listCount = -1, long long item = 0) {
    next(p, listCount, item);
    return integerOf(p.type, p, listCount >= 0 ? kItem : kScalar);
  }

  double real(const Property& p, long long listCount = -1, long long item = 0) {
    next(p, listCount, item);
    const TypeInfo& t = info(p.type);
    if (!t.isFloat) return static_cast<double>(integerOf(p.type, p, listCount >= 0 ? kItem : kScalar));
    if (p.type == Type::float32) {
      float value = 0;
      checkReal(parseReal(token_, value), p, listCount >= 0);
      return value;
    }
    double value = 0;
    checkReal(parseReal(token_, value), p, listCount >= 0);
    return value;
  }

  void skip(const Property& p) {
    if (!p.list) {
      real(p);
      return;
    }
    const long long n = count(p);
    for (long long k = 0; k < n; ++k) real(p, n, k);
  }

  // The place of the value last read (its line), and of item k of a list whose first item was at `first`.
  std::uint64_t place() const { return line_; }
  std::uint64_t itemPlace(std::uint64_t first, const Property&, long long) const { return first; }
  std::size_t line() const { return line_; }

  [[noreturn]] void fail(std::uint64_t place, const std::string& expected, const std::string& found) const {
    failAtLine(name_, static_cast<std::size_t>(place), expected, found);
  }
  std::string shown(long long value) const { return quote(std::to_string(value)); }

 private:
  bool nextLine() {
    std::string_view text;
    switch (bytes_.line(text)) {
      case ByteStream::Line::endOfFile:
        return false;
      case ByteStream::Line::tooLong:
        failAtLine(name_, line_ + 1, "a line of at most " + std::to_string(kMaxLineBytes >> 20) + " MiB", "a longer one");
      case ByteStream::Line::ok:
        break;
    }
    ++line_;
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    tokens_ = Tokens(text);
    return true;
  }

  void next(const Property& p, long long listCount, long long item) {
    token_ = tokens_.next();
    if (!token_.empty()) return;
    if (listCount < 0) failAtLine(name_, line_, describe(p.type, p, false), "end of line");
    failAtLine(name_, line_, std::to_string(listCount) + " items in list '" + p.name + "'", std::to_string(item));
  }

  enum IntegerKind { kScalar, kItem, kCount };

  // The message is made only on failure: this runs for every value.
  long long integerOf(Type t, const Property& p, IntegerKind kind) const {
    long long value = 0;
    if (!parseInteger(token_, value) || value < info(t).min || value > info(t).max) {
      const std::string what = kind == kCount ? std::string("a ") + info(t).name + " list count for '" + p.name + "'"
                                              : describe(t, p, kind == kItem);
      failAtLine(name_, line_, what + rangeOf(t), quote(token_));
    }
    return value;
  }

  void checkReal(NumberSyntax syntax, const Property& p, bool item) const {
    if (syntax == NumberSyntax::malformed) failAtLine(name_, line_, describe(p.type, p, item), quote(token_));
    if (syntax == NumberSyntax::notFinite || syntax == NumberSyntax::tooLarge) failAtLine(name_, line_, describe(p.type, p, item, true), quote(token_));
  }

  ByteStream& bytes_;
  const std::string& name_;
  std::size_t line_;
  Tokens tokens_{std::string_view()};
  std::string_view token_;
};

template <typename T>
T load(const char* p, bool swap) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, p, sizeof(T));
  if (swap) std::reverse(bytes, bytes + sizeof(T));
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

// Binary data: values back to back in the file's byte order.
class BinarySource {
 public:
  static constexpr bool kText = false;

  BinarySource(ByteStream& bytes, const std::string& name, bool swap) : bytes_(bytes), name_(name), swap_(swap) {}

  Position at;

  void beginRecord() {}
  void endRecord() {}

  // After the last element, nothing.
  void expectEnd() {
    const std::uint64_t offset = bytes_.offset();
    if (const std::uint64_t more = bytes_.drain())
      failAtByte(name_, offset, "end of file after the last element", std::to_string(more) + " more bytes");
  }

  long long count(const Property& p) {
    const long long n = integerAt(p.countType);
    if (n < 0 || n > INT_MAX)
      failAtByte(name_, place_, "a list count in 0.." + std::to_string(INT_MAX) + " for '" + p.name + "'", std::to_string(n));
    return n;
  }

  long long integer(const Property& p, long long = -1, long long = 0) { return integerAt(p.type); }

  double real(const Property& p, long long listCount = -1, long long = 0) {
    if (!info(p.type).isFloat) return static_cast<double>(integerAt(p.type));
    const double value = p.type == Type::float32 ? load<float>(take(4), swap_) : load<double>(take(8), swap_);
    if (!std::isfinite(value))
      failAtByte(name_, place_, describe(p.type, p, listCount >= 0, true),
                 std::isnan(value) ? "nan" : value > 0 ? "inf" : "-inf");
    return value;
  }

  void skip(const Property& p) {
    if (!p.list) {
      real(p);
      return;
    }
    const long long n = count(p);
    for (long long k = 0; k < n; ++k) real(p, n, k);
  }

  std::uint64_t place() const { return place_; }
  std::uint64_t itemPlace(std::uint64_t first, const Property& p, long long k) const {
    return first + static_cast<std::uint64_t>(k) * static_cast<std::uint64_t>(info(p.type).size);
  }
  std::size_t line() const { return 0; }

  [[noreturn]] void fail(std::uint64_t place, const std::string& expected, const std::string& found) const {
    failAtByte(name_, place, expected, found);
  }
  std::string shown(long long value) const { return std::to_string(value); }

 private:
  const char* take(std::size_t size) {
    place_ = bytes_.offset();
    const char* p = bytes_.take(size);
    if (!p)
      failAtByte(name_, place_, countOf(*at.element, at.element->count), std::to_string(at.index) + " and end of file");
    return p;
  }

  long long integerAt(Type t) {
    switch (t) {
      case Type::int8: return load<std::int8_t>(take(1), false);
      case Type::uint8: return load<std::uint8_t>(take(1), false);
      case Type::int16: return load<std::int16_t>(take(2), swap_);
      case Type::uint16: return load<std::uint16_t>(take(2), swap_);
      case Type::int32: return load<std::int32_t>(take(4), swap_);
      case Type::uint32: return load<std::uint32_t>(take(4), swap_);
      case Type::float32:
      case Type::float64: break;
    }
    UVTK_CHECK(false);
    return 0;
  }

  ByteStream& bytes_;
  const std::string& name_;
  bool swap_;
  std::uint64_t place_ = 0;  // the offset of the value last read
};

// The mesh as it is built, and the scratch space reused by every face.
struct Builder {
  Mesh mesh;
  std::vector<Vec3> vertexTexcoords;
  MeshWarnings warnings;
  PolygonTriangulator triangulator;
  std::vector<int> corners;  // the face's vertex indices, as read
  std::vector<double> uv;    // the face's texcoord list
  std::vector<int> polygon;  // the triangulator's copy of a face's corners
  std::vector<PolygonTriangle> triangles;
  // Faces read before the vertex element: their corners, where each face's corners end, the place
  // of each face's first index, and their texcoord lists, all as read.
  std::vector<int> pendingCorners;
  std::vector<std::size_t> pendingEnds;
  std::vector<std::uint64_t> pendingPlaces;
  std::vector<double> pendingUv;
};

// Triangulates one face into the mesh; `uv` holds 2 numbers per corner, or is null.
void addFace(Builder& b, const std::string& name, const int* corners, std::size_t n, const double* uv, std::size_t line) {
  b.polygon.assign(corners, corners + n);
  if (!b.triangulator.triangulate(b.mesh.positions, b.polygon, b.triangles))
    if (b.warnings.nonSimplePolygons++ == 0) b.warnings.firstNonSimplePolygonLine = line;
  Mesh& m = b.mesh;
  if (m.triangles.size() + b.triangles.size() > static_cast<std::size_t>(INT_MAX) ||
      (uv && m.texcoords.size() + n > static_cast<std::size_t>(INT_MAX)))
    throw InputError(name + ": error: more than " + std::to_string(INT_MAX) + " triangles or texture coordinates");
  const int base = static_cast<int>(m.texcoords.size());
  if (uv)
    for (std::size_t k = 0; k < n; ++k) m.texcoords.emplace_back(uv[2 * k], uv[2 * k + 1], 0.0);
  for (const PolygonTriangle& t : b.triangles) {
    m.triangles.push_back({corners[t[0]], corners[t[1]], corners[t[2]]});
    if (uv) m.cornerTexcoords.push_back({base + t[0], base + t[1], base + t[2]});
  }
}

template <class Source>
void readVertex(Source& s, const Element& e, Builder& b, const Header& h) {
  Vec3 p = Vec3::Zero(), n = Vec3::Zero(), uv = Vec3::Zero();
  s.beginRecord();
  for (const Property& prop : e.properties) {
    switch (prop.role) {
      case kX: case kY: case kZ: p[prop.role - kX] = s.real(prop); break;
      case kNx: case kNy: case kNz: n[prop.role - kNx] = s.real(prop); break;
      case kU: case kV: uv[prop.role - kU] = s.real(prop); break;
      default: s.skip(prop);
    }
  }
  s.endRecord();
  b.mesh.positions.push_back(p);
  if (h.normals) b.mesh.normals.push_back(n);
  if (h.vertexTexcoords) b.vertexTexcoords.push_back(uv);
}

std::string indexRange(bool known, std::size_t vertexCount) {
  return "a vertex index in 0.." + (known ? std::to_string(vertexCount - 1) : std::string("the vertex count - 1"));
}

template <class Source>
void readFace(Source& s, const Element& e, Builder& b, const Header& h, bool verticesKnown, const std::string& name) {
  std::vector<int>& corners = b.corners;
  corners.clear();
  b.uv.clear();
  const std::size_t vertexCount = b.mesh.positions.size();
  std::uint64_t firstPlace = 0, texcoordPlace = 0;
  long long texcoordCount = 0;
  s.beginRecord();
  for (const Property& prop : e.properties) {
    if (prop.role == kIndices) {
      const long long n = s.count(prop);
      if (n < 3) {
        const char* what = n == 1 ? " (a point, not a face)" : n == 2 ? " (a line, not a face)" : "";
        s.fail(s.place(), "a face of at least 3 corners", "a face of " + std::to_string(n) + what);
      }
      for (long long k = 0; k < n; ++k) {
        const long long v = s.integer(prop, n, k);
        if (k == 0) firstPlace = s.place();
        if (v < 0 || v >= (verticesKnown ? static_cast<long long>(vertexCount) : INT_MAX))
          s.fail(s.place(), indexRange(verticesKnown, vertexCount), s.shown(v));
        corners.push_back(static_cast<int>(v));
      }
    } else if (prop.role == kFaceTexcoords) {
      texcoordCount = s.count(prop);
      texcoordPlace = s.place();
      for (long long k = 0; k < texcoordCount; ++k) b.uv.push_back(s.real(prop, texcoordCount, k));
    } else {
      s.skip(prop);
    }
  }
  s.endRecord();
  if (h.faceTexcoords && static_cast<std::size_t>(texcoordCount) != 2 * corners.size())
    s.fail(texcoordPlace,
           "a texcoord list of 2 numbers per corner (" + std::to_string(2 * corners.size()) + " for " +
               std::to_string(corners.size()) + " corners)",
           std::to_string(texcoordCount));
  const double* uv = h.faceTexcoords ? b.uv.data() : nullptr;
  if (verticesKnown) {
    addFace(b, name, corners.data(), corners.size(), uv, s.line());
    return;
  }
  b.pendingCorners.insert(b.pendingCorners.end(), corners.begin(), corners.end());
  b.pendingEnds.push_back(b.pendingCorners.size());
  b.pendingPlaces.push_back(Source::kText ? s.line() : firstPlace);
  if (uv) b.pendingUv.insert(b.pendingUv.end(), b.uv.begin(), b.uv.end());
}

// Faces that came before the vertex element, checked and triangulated now.
template <class Source>
void addPendingFaces(Source& s, const Element& face, Builder& b, const std::string& name) {
  const Property* indices = nullptr;
  for (const Property& p : face.properties)
    if (p.role == kIndices) indices = &p;
  const long long vertexCount = static_cast<long long>(b.mesh.positions.size());
  std::vector<int> corners = std::move(b.pendingCorners);
  const bool uv = !b.pendingUv.empty();
  std::size_t begin = 0;
  for (std::size_t f = 0; f < b.pendingEnds.size(); ++f) {
    const std::size_t end = b.pendingEnds[f];
    for (std::size_t c = begin; c < end; ++c)
      if (corners[c] >= vertexCount)
        s.fail(s.itemPlace(b.pendingPlaces[f], *indices, static_cast<long long>(c - begin)),
               indexRange(true, static_cast<std::size_t>(vertexCount)), s.shown(corners[c]));
    addFace(b, name, corners.data() + begin, end - begin, uv ? b.pendingUv.data() + 2 * begin : nullptr,
            Source::kText ? static_cast<std::size_t>(b.pendingPlaces[f]) : 0);
    begin = end;
  }
}

template <class Source>
void readData(Source& s, const Header& h, Builder& b, const std::string& name) {
  for (std::size_t i = 0; i < h.elements.size(); ++i) {
    const Element& e = h.elements[i];
    s.at.element = &e;
    const std::size_t reserve = std::min(static_cast<std::size_t>(e.count), kMaxReserve);
    if (static_cast<int>(i) == h.vertexElement) {
      b.mesh.positions.reserve(reserve);
      if (h.normals) b.mesh.normals.reserve(reserve);
      if (h.vertexTexcoords) b.vertexTexcoords.reserve(reserve);
      for (s.at.index = 0; s.at.index < e.count; ++s.at.index) readVertex(s, e, b, h);
    } else if (static_cast<int>(i) == h.faceElement) {
      b.mesh.triangles.reserve(reserve);
      const bool verticesKnown = h.vertexElement < h.faceElement;
      for (s.at.index = 0; s.at.index < e.count; ++s.at.index) readFace(s, e, b, h, verticesKnown, name);
    } else {
      for (s.at.index = 0; s.at.index < e.count; ++s.at.index) {
        s.beginRecord();
        for (const Property& prop : e.properties) s.skip(prop);
        s.endRecord();
      }
    }
  }
  s.expectEnd();
  if (h.faceElement < h.vertexElement) addPendingFaces(s, h.elements[std::size_t(h.faceElement)], b, name);
}

}  // namespace

ReadMeshResult readPly(std::istream& in, const std::string& name) {
  ByteStream bytes(in, name);
  HeaderReader reader(bytes, name);
  const Header header = parseHeader(reader, name);
  Builder b;
  if (header.format == Format::ascii) {
    AsciiSource source(bytes, name, reader.line());
    readData(source, header, b, name);
  } else {
    const bool little = header.format == Format::binaryLittleEndian;
    BinarySource source(bytes, name, little != kHostLittleEndian);
    readData(source, header, b, name);
  }
  Mesh& mesh = b.mesh;
  // Per-vertex attributes: every corner uses its own vertex's. A face texcoord list wins.
  if (header.normals) mesh.cornerNormals = mesh.triangles;
  if (header.vertexTexcoords && !header.faceTexcoords) {
    mesh.texcoords = std::move(b.vertexTexcoords);
    mesh.cornerTexcoords = mesh.triangles;
  }
  ReadMeshResult result;
  result.warnings = b.warnings;
  applyFaceLists(mesh, 0, mesh.triangles.size(), header.listedFaces, result.listedInvalidUvFaces);
  result.warnings.listedInvalidUvFaces = result.listedInvalidUvFaces.size();
  if (header.colours) result.warnings.vertexColours = mesh.positions.size();
  const MeshWarnings checked = checkMesh(mesh);
  result.warnings.degenerateFaces = checked.degenerateFaces;
  result.warnings.unreferencedVertices = checked.unreferencedVertices;
  result.mesh = std::move(mesh);
  return result;
}

}  // namespace uvtk::io
