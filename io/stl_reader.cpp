// Strict STL reader, ASCII and binary, streamed: neither the file nor a claimed count is held or
// reserved whole.
//
// Decisions where the format leaves room:
// - Binary or ASCII is decided by size: a file of exactly 84 + 50 N bytes, N the uint32 at byte 80,
//   is binary, whatever its header says (many binary headers start with "solid"). Otherwise a file
//   whose first 84 bytes are text and start with `solid` (any case, after a UTF-8 byte-order mark
//   and whitespace) is ASCII; anything else is a binary file of the wrong size, an error naming
//   both sizes. An ASCII file of exactly 84 + 50 N bytes would need N >= 0x20202020 (its bytes 80
//   to 83 are text): 27 GB.
// - Facet normals are ignored, in both forms: they are often zero or wrong, and the mesh's normals
//   come from its geometry. ASCII normals must still be numbers (nan and inf included, which some
//   writers print for degenerate facets).
// - Coordinates are float32, as the format defines them: ASCII text is rounded to the nearest
//   float (a value beyond the float range is an error, one too small for it becomes 0) and stored
//   as the double of that float, exactly. NaN and infinity are errors in both forms.
// - Corners are welded into one vertex when their float positions are equal (-0 and +0 equal: the
//   same point); the vertex keeps the first corner's value. Vertices are numbered in the order of
//   their first corner; MeshWarnings::weldedCorners counts the corners that reused a vertex.
// - Facets whose corners weld together are kept (checkMesh counts them as degenerate).
// - ASCII: one statement a line (`solid [name]`, `facet normal x y z`, `outer loop`,
//   `vertex x y z`, `endloop`, `endfacet`, `endsolid [name]`), keywords in any case, blank lines
//   anywhere, tabs or spaces between tokens, LF or CRLF. Several solids in one file (one per part,
//   as some CAD exporters write) go into one mesh; the names are not kept or compared. After the
//   last `endsolid` only blank lines may follow.
// - The binary attribute byte count (some writers put a colour there) is ignored.
#include "io/stl_reader.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <istream>
#include <streambuf>
#include <string_view>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "io/number_text.h"

namespace uvtk::io {
namespace {

// A count from a header is a claim: reserve at most this many elements for it.
constexpr std::size_t kMaxReserve = std::size_t{1} << 20;
constexpr std::size_t kMaxQuoted = 40;
constexpr std::size_t kHeaderBytes = 84;  // 80 free bytes, then the uint32 triangle count
constexpr std::size_t kTriangleBytes = 50;
constexpr std::size_t kTrianglesPerBlock = 4096;
constexpr std::size_t kMaxLineBytes = std::size_t{64} << 20;
constexpr std::size_t kReadBlock = std::size_t{1} << 16;

std::string quote(std::string_view token) {
  if (token.size() > kMaxQuoted) return "'" + std::string(token.substr(0, kMaxQuoted)) + "...'";
  return "'" + std::string(token) + "'";
}

InputError fileError(const std::string& name, const std::string& what) { return InputError(name + ": error: " + what); }

using Float3 = std::array<float, 3>;

// Welds corners by float position in an open-addressing hash table of vertex indices, keyed on the
// coordinates' bits (with -0 as +0) and compared with == on the stored positions: expected O(1) a
// corner, and no memory beyond an int a slot.
class Welder {
 public:
  explicit Welder(std::size_t expectedVertices) {
    std::size_t capacity = 16;
    while (capacity < 2 * expectedVertices) capacity *= 2;
    slots_.assign(capacity, -1);
  }

  // The vertex at p, appended to `positions` if it is new; `tooMany` is called (and must throw)
  // when a new vertex would not fit an int.
  template <class TooMany>
  int vertex(const Float3& p, std::vector<Vec3>& positions, TooMany tooMany) {
    const Vec3 position(p[0], p[1], p[2]);
    for (std::size_t i = hash(p) & (slots_.size() - 1);; i = (i + 1) & (slots_.size() - 1)) {
      const int v = slots_[i];
      if (v < 0) break;
      if (positions[static_cast<std::size_t>(v)] == position) return v;
    }
    if (positions.size() >= static_cast<std::size_t>(INT_MAX)) tooMany();
    const int v = static_cast<int>(positions.size());
    positions.push_back(position);
    if (2 * positions.size() > slots_.size())
      rehash(positions, 2 * slots_.size());
    else
      insert(p, v);
    return v;
  }

 private:
  static std::uint32_t bits(float f) {
    f += 0.0f;  // -0 becomes +0: equal positions must hash alike
    std::uint32_t b = 0;
    std::memcpy(&b, &f, 4);
    return b;
  }

  std::size_t hash(const Float3& p) const {
    std::uint64_t h = (std::uint64_t{bits(p[0])} << 32 | bits(p[1])) * 0x9E3779B97F4A7C15ull;
    h ^= (h >> 32) ^ std::uint64_t{bits(p[2])} * 0xC2B2AE3D27D4EB4Full;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    return static_cast<std::size_t>(h ^ (h >> 32));
  }

  void insert(const Float3& p, int v) {
    std::size_t i = hash(p) & (slots_.size() - 1);
    while (slots_[i] >= 0) i = (i + 1) & (slots_.size() - 1);
    slots_[i] = v;
  }

  void rehash(const std::vector<Vec3>& positions, std::size_t capacity) {
    slots_.assign(capacity, -1);
    for (std::size_t v = 0; v < positions.size(); ++v) {
      const Vec3& q = positions[v];
      insert({static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z())}, static_cast<int>(v));
    }
  }

  std::vector<int> slots_;  // vertex indices, -1 for an empty slot; a power of two long, at most half full
};

ReadMeshResult withWarnings(Mesh mesh) {
  ReadMeshResult result;
  const MeshWarnings checked = checkMesh(mesh);
  result.warnings.degenerateFaces = checked.degenerateFaces;
  result.warnings.unreferencedVertices = checked.unreferencedVertices;
  result.warnings.weldedCorners = 3 * mesh.triangles.size() - mesh.positions.size();
  result.mesh = std::move(mesh);
  return result;
}

std::string nonFiniteText(float f) { return std::isnan(f) ? "nan" : f > 0 ? "inf" : "-inf"; }

// ---------------------------------------------------------------------------------------------
// Binary

float littleEndianFloat(const char* p) {
  std::uint32_t b = 0;
  for (int i = 3; i >= 0; --i) b = b << 8 | static_cast<unsigned char>(p[i]);
  float f = 0.0f;
  std::memcpy(&f, &b, 4);
  return f;
}

ReadMeshResult readBinary(std::istream& in, const std::string& name, std::uint32_t count) {
  if (count == 0) throw fileError(name, "expected at least one triangle, found a binary header count of 0");
  if (count > static_cast<std::uint32_t>(INT_MAX))
    throw fileError(name, "expected at most " + std::to_string(INT_MAX) + " triangles, found a binary header count of " +
                              std::to_string(count));
  Mesh mesh;
  mesh.triangles.reserve(std::min<std::size_t>(count, kMaxReserve));
  // A closed mesh has about half as many vertices as triangles.
  mesh.positions.reserve(std::min<std::size_t>(count / 2 + 3, kMaxReserve));
  Welder welder(std::min<std::size_t>(count / 2 + 3, kMaxReserve));
  const auto tooMany = [&] { throw fileError(name, "expected at most " + std::to_string(INT_MAX) + " distinct vertices, found more"); };
  std::vector<char> block(kTrianglesPerBlock * kTriangleBytes);
  for (std::uint64_t done = 0; done < count;) {
    const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(kTrianglesPerBlock, count - done));
    in.read(block.data(), static_cast<std::streamsize>(n * kTriangleBytes));
    if (in.bad()) throw fileError(name, "cannot read: input/output error");
    const std::uint64_t got = static_cast<std::uint64_t>(in.gcount());
    if (got != n * kTriangleBytes)  // the file shrank after its size was taken
      throw InputError(name + ": byte " + std::to_string(kHeaderBytes + done * kTriangleBytes + got) + ": error: expected " +
                       std::to_string(count) + " triangles of 50 bytes, found end of file");
    for (std::size_t t = 0; t < n; ++t, ++done) {
      const char* triangle = block.data() + t * kTriangleBytes;
      Triangle corners{};
      for (int k = 0; k < 3; ++k) {
        Float3 p{};
        for (int a = 0; a < 3; ++a) {
          const std::size_t offset = 12 + 12 * static_cast<std::size_t>(k) + 4 * static_cast<std::size_t>(a);  // after the normal
          p[static_cast<std::size_t>(a)] = littleEndianFloat(triangle + offset);
          if (!std::isfinite(p[static_cast<std::size_t>(a)]))
            throw InputError(name + ": byte " + std::to_string(kHeaderBytes + done * kTriangleBytes + offset) +
                             ": error: expected a finite number, found " + nonFiniteText(p[static_cast<std::size_t>(a)]));
        }
        corners[static_cast<std::size_t>(k)] = welder.vertex(p, mesh.positions, tooMany);
      }
      mesh.triangles.push_back(corners);
    }
  }
  return withWarnings(std::move(mesh));
}

// ---------------------------------------------------------------------------------------------
// ASCII

bool equalsIgnoringCase(std::string_view token, std::string_view keyword) {
  if (token.size() != keyword.size()) return false;
  for (std::size_t i = 0; i < token.size(); ++i) {
    const char c = token[i] >= 'A' && token[i] <= 'Z' ? static_cast<char>(token[i] - 'A' + 'a') : token[i];
    if (c != keyword[i]) return false;
  }
  return true;
}

// Lines of text from the bytes already read (the start of the file) and then the stream, split
// into tokens; it knows the line number, so the errors about the text are raised here.
class LineReader {
 public:
  LineReader(std::string start, std::istream& in, const std::string& name)
      : in_(in), name_(name), buffer_(start.begin(), start.end()), filled_(buffer_.size()) {}

  // Advances to the next line that has a token. False at end of file.
  bool nextContentLine() {
    while (nextLine())
      if (!atEndOfLine()) return true;
    return false;
  }

  bool atEndOfLine() {
    while (position_ != end_ && (*position_ == ' ' || *position_ == '\t')) ++position_;
    return position_ == end_;
  }

  // The next token of the current line; empty at its end.
  std::string_view token() {
    atEndOfLine();
    const char* start = position_;
    while (position_ != end_ && *position_ != ' ' && *position_ != '\t') ++position_;
    return {start, static_cast<std::size_t>(position_ - start)};
  }

  // The next token, which must be `keyword` in any case; `expected` names it in the message.
  void keyword(std::string_view keyword, const std::string& expected) {
    const std::string_view t = token();
    if (!equalsIgnoringCase(t, keyword)) failAt(expected, t);
  }

  // A coordinate: a finite number within the float range, rounded to float.
  float coordinate(const char* what) {
    const std::string_view t = token();
    if (t.empty()) failAt(what, t);
    float value = 0.0f;
    switch (parseReal(t, value)) {
      case NumberSyntax::ok:
        return value;
      case NumberSyntax::malformed:
        failAt("a number", t);
      case NumberSyntax::notFinite:
        failAt("a finite number", t);
      case NumberSyntax::tooLarge:
        failAt("a number within the float32 range (magnitude at most 3.40282347e+38)", t);
    }
    UVTK_CHECK(false);
    return value;
  }

  // A normal's component: any number, nan and inf included; the value is not kept.
  void anyNumber(const char* what) {
    const std::string_view t = token();
    if (t.empty()) failAt(what, t);
    float ignored = 0.0f;
    if (parseReal(t, ignored) == NumberSyntax::malformed) failAt("a number", t);
  }

  void expectEndOfLine() {
    const std::string_view t = token();
    if (!t.empty()) failAt("end of line", t);
  }

  [[noreturn]] void fail(const std::string& expected, const std::string& found) const {
    throw InputError(name_ + ":" + std::to_string(lineNumber_) + ": error: expected " + expected + ", found " + found);
  }

  [[noreturn]] void failAt(const std::string& expected, std::string_view text) const {
    fail(expected, text.empty() ? "end of line" : quote(text));
  }

  // Something is missing at the end: the message names the line after the last one.
  [[noreturn]] void failAtEndOfFile(const std::string& expected) const {
    throw InputError(name_ + ":" + std::to_string(lineNumber_ + 1) + ": error: expected " + expected + ", found end of file");
  }

 private:
  // Advances to the next line, its line ending removed, checked to be text. False at end of file.
  bool nextLine() {
    if (!readLine()) return false;
    ++lineNumber_;
    std::size_t begin = 0;
    std::size_t end = line_.size();
    if (lineNumber_ == 1 && line_.compare(0, 3, "\xEF\xBB\xBF") == 0) begin = 3;
    if (end > begin && line_[end - 1] == '\r') --end;
    for (std::size_t i = begin; i < end; ++i) {
      const unsigned char c = static_cast<unsigned char>(line_[i]);
      if ((c < 0x20 && c != '\t') || c == 0x7F) {
        static constexpr char kHex[] = "0123456789ABCDEF";
        fail("text", std::string("byte 0x") + kHex[c >> 4] + kHex[c & 15]);
      }
    }
    position_ = line_.data() + begin;
    end_ = line_.data() + end;
    return true;
  }

  // Reads the next line into line_ without its '\n'. False at end of file. A line is never held
  // longer than kMaxLineBytes, so a file without line breaks cannot exhaust memory.
  bool readLine() {
    line_.clear();
    bool any = false;
    for (;;) {
      if (next_ == filled_ && !refill()) return any;
      any = true;
      const char* begin = buffer_.data() + next_;
      const std::size_t available = filled_ - next_;
      const char* newline = static_cast<const char*>(std::memchr(begin, '\n', available));
      const std::size_t length = newline ? static_cast<std::size_t>(newline - begin) : available;
      if (line_.size() + length > kMaxLineBytes)
        throw InputError(name_ + ":" + std::to_string(lineNumber_ + 1) + ": error: expected a line of at most " +
                         std::to_string(kMaxLineBytes >> 20) + " MiB, found a longer one");
      line_.append(begin, length);
      next_ += newline ? length + 1 : length;
      if (newline) return true;
    }
  }

  bool refill() {
    next_ = filled_ = 0;
    if (!in_.good()) return false;
    buffer_.resize(kReadBlock);
    in_.read(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    if (in_.bad()) throw fileError(name_, "cannot read: input/output error");
    filled_ = static_cast<std::size_t>(in_.gcount());
    return filled_ > 0;
  }

  std::istream& in_;
  const std::string& name_;
  std::vector<char> buffer_;
  std::size_t next_ = 0, filled_ = 0;  // the first unread byte of buffer_, and how many it holds
  std::string line_;
  std::size_t lineNumber_ = 0;
  const char* position_ = nullptr;
  const char* end_ = nullptr;
};

constexpr const char* kCoordinateNames[3] = {"an x coordinate", "a y coordinate", "a z coordinate"};
constexpr const char* kNormalNames[3] = {"a normal's x component", "a normal's y component", "a normal's z component"};

// The next line, which must start with `keyword` (any case).
void keywordLine(LineReader& reader, std::string_view keyword, const std::string& expected) {
  if (!reader.nextContentLine()) reader.failAtEndOfFile(expected);
  reader.keyword(keyword, expected);
}

// After `facet`: the rest of the facet, up to and with its `endfacet`.
Triangle readFacet(LineReader& reader, Mesh& mesh, Welder& welder) {
  reader.keyword("normal", "'normal'");
  for (const char* what : kNormalNames) reader.anyNumber(what);
  reader.expectEndOfLine();
  keywordLine(reader, "outer", "'outer loop'");
  reader.keyword("loop", "'loop'");
  reader.expectEndOfLine();
  Triangle corners{};
  for (int k = 0; k < 3; ++k) {
    keywordLine(reader, "vertex", "'vertex'");
    Float3 p{};
    for (int a = 0; a < 3; ++a) p[static_cast<std::size_t>(a)] = reader.coordinate(kCoordinateNames[a]);
    reader.expectEndOfLine();
    corners[static_cast<std::size_t>(k)] = welder.vertex(
        p, mesh.positions, [&] { reader.fail("at most " + std::to_string(INT_MAX) + " distinct vertices", "more"); });
  }
  keywordLine(reader, "endloop", "'endloop' (a facet has 3 vertices)");
  reader.expectEndOfLine();
  keywordLine(reader, "endfacet", "'endfacet'");
  reader.expectEndOfLine();
  return corners;
}

ReadMeshResult readAscii(LineReader& reader) {
  Mesh mesh;
  Welder welder(0);
  reader.nextContentLine();  // the caller saw `solid` on the first content line
  for (bool first = true;; first = false) {
    reader.keyword("solid", first ? "'solid'" : "'solid' or end of file");
    // The rest of the line is the solid's name, which the mesh does not keep.
    for (;;) {
      if (!reader.nextContentLine()) reader.failAtEndOfFile("'facet' or 'endsolid'");
      const std::string_view keyword = reader.token();
      if (equalsIgnoringCase(keyword, "endsolid")) break;  // then the name, not compared with the solid's
      if (!equalsIgnoringCase(keyword, "facet")) reader.failAt("'facet' or 'endsolid'", keyword);
      if (mesh.triangles.size() >= static_cast<std::size_t>(INT_MAX))
        reader.fail("at most " + std::to_string(INT_MAX) + " facets", "more");
      mesh.triangles.push_back(readFacet(reader, mesh, welder));
    }
    if (!reader.nextContentLine()) break;
  }
  if (mesh.triangles.empty()) reader.failAtEndOfFile("at least one facet");
  return withWarnings(std::move(mesh));
}

// ---------------------------------------------------------------------------------------------
// Which form

// Whether the file's first bytes are text starting with the keyword `solid`.
bool looksLikeAscii(std::string_view start) {
  for (const char c : start) {
    const unsigned char b = static_cast<unsigned char>(c);
    if ((b < 0x20 && c != '\t' && c != '\n' && c != '\r') || b == 0x7F) return false;
  }
  if (start.substr(0, 3) == "\xEF\xBB\xBF") start.remove_prefix(3);
  const std::size_t first = start.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return false;
  start.remove_prefix(first);
  if (start.size() < 5 || !equalsIgnoringCase(start.substr(0, 5), "solid")) return false;
  return start.size() == 5 || start[5] == ' ' || start[5] == '\t' || start[5] == '\r' || start[5] == '\n';
}

// A read-only view of bytes as a stream buffer: the rest of a stream that cannot seek, read whole.
class BytesBuffer : public std::streambuf {
 public:
  explicit BytesBuffer(std::string& bytes) { setg(bytes.data(), bytes.data(), bytes.data() + bytes.size()); }
};

ReadMeshResult readStlForm(const std::string& start, std::uint64_t size, std::istream& rest, const std::string& name) {
  std::uint32_t count = 0;
  if (start.size() == kHeaderBytes)
    for (int i = 3; i >= 0; --i) count = count << 8 | static_cast<unsigned char>(start[80 + static_cast<std::size_t>(i)]);
  const std::uint64_t binarySize = kHeaderBytes + kTriangleBytes * std::uint64_t{count};
  if (start.size() == kHeaderBytes && size == binarySize) return readBinary(rest, name, count);
  if (looksLikeAscii(start)) {
    LineReader reader(start, rest, name);
    return readAscii(reader);
  }
  if (size == 0) throw fileError(name, "expected an STL file, found an empty file");
  if (size < kHeaderBytes)
    throw fileError(name, "expected an STL file (ASCII, starting with 'solid', or binary, of at least 84 bytes), found " +
                              std::to_string(size) + " bytes of neither");
  throw fileError(name, "expected " + std::to_string(binarySize) + " bytes (84 + 50 a triangle) for the " +
                            std::to_string(count) + " triangles the binary header claims, found " + std::to_string(size) +
                            " bytes");
}

}  // namespace

ReadMeshResult readStl(std::istream& in, const std::string& name) {
  std::string start(kHeaderBytes, '\0');
  in.read(start.data(), static_cast<std::streamsize>(kHeaderBytes));
  if (in.bad()) throw fileError(name, "cannot read: input/output error");
  start.resize(static_cast<std::size_t>(in.gcount()));
  if (start.size() < kHeaderBytes) return readStlForm(start, start.size(), in, name);

  // The size decides the form: taken by seeking when the stream can, else by reading the rest.
  const std::istream::pos_type here = in.tellg();
  if (here != std::istream::pos_type(-1)) {
    in.seekg(0, std::ios::end);
    const std::istream::pos_type end = in.tellg();
    in.seekg(here);
    if (end == std::istream::pos_type(-1) || !in) throw fileError(name, "cannot read: the input tells its position but cannot seek");
    return readStlForm(start, kHeaderBytes + static_cast<std::uint64_t>(end - here), in, name);
  }
  in.clear();  // a failed position query may have set failbit
  std::string rest;
  std::vector<char> block(kReadBlock);
  while (in.read(block.data(), static_cast<std::streamsize>(block.size())) || in.gcount() > 0)
    rest.append(block.data(), static_cast<std::size_t>(in.gcount()));
  if (in.bad()) throw fileError(name, "cannot read: input/output error");
  BytesBuffer buffer(rest);
  std::istream restStream(&buffer);
  return readStlForm(start, kHeaderBytes + rest.size(), restStream, name);
}

}  // namespace uvtk::io
