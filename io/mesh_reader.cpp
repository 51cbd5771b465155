// Strict OBJ and OFF readers: line by line, tokens found by pointer scanning, numbers parsed with
// std::from_chars (locale-independent, no per-token allocation). Every rejection goes through
// LineReader, which knows the file name and line number, and through inputError(), the one
// place that formats messages.
//
// Decisions where the formats leave room:
// - Errors about a missing line ("found end of file") name the line one past the last line.
// - A UTF-8 byte-order mark is skipped; a UTF-16 one, a NUL, a control byte other than tab, and
//   a carriage return anywhere but at the end of a line are errors. Bytes >= 0x80 are allowed
//   (UTF-8 names and comments).
// - '#' starts a comment anywhere on a line, in both formats.
// - Numbers are decimal (no hex floats); a leading '+' is accepted, as strtod does, in counts and
//   indices too (`f +1 +2 +3` is `f 1 2 3`, as `v +1 0 0` is `v 1 0 0`). A value too small to
//   represent becomes 0; one too large is "not finite", like nan and inf.
// - Counts and indices must fit an int: triangles store int indices.
// - A face of more than three corners is triangulated in its plane (io/polygon_triangulation.h), so
//   a concave polygon does not fold; one that is not simple is counted in the warnings with its line.
// - A line longer than 64 MiB is an error: no writer emits one, and it is never held whole.
// readMesh shows its progress over the file's bytes (core/progress.h), reported every few
// thousand lines so that the count costs nothing per line but an addition.
#include "io/mesh_reader.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>
#include <fstream>
#include <istream>
#include <streambuf>
#include <string_view>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "core/progress.h"
#include "io/gltf_reader.h"
#include "io/mesh_format.h"
#include "io/number_text.h"
#include "io/ply_reader.h"
#include "io/polygon_triangulation.h"
#include "io/stl_reader.h"

namespace uvtk::io {
namespace {

// A count read from a file is a claim, not a fact: reserve at most this many elements for it and
// let the vector grow as data actually arrives, so a lying header cannot exhaust memory.
constexpr std::size_t kMaxReserve = std::size_t{1} << 20;
// Tokens quoted in messages are cut to this length, so a megabyte of junk makes a readable error.
constexpr std::size_t kMaxQuoted = 40;
constexpr Triangle kNoCorners = {-1, -1, -1};
// The longest line accepted: no writer emits more (a face of a million corners takes about 10 MB),
// and a file without line breaks must not be held in memory whole.
constexpr std::size_t kMaxLineBytes = std::size_t{64} << 20;
// Bytes read from the stream at a time, at first and at most.
constexpr std::size_t kFirstReadBlock = std::size_t{1} << 16;
constexpr std::size_t kReadBlock = std::size_t{1} << 20;
// Lines read between two progress reports (a power of two).
constexpr std::size_t kLinesPerReport = 4096;

std::string quote(std::string_view token) {
  if (token.size() > kMaxQuoted) return "'" + std::string(token.substr(0, kMaxQuoted)) + "...'";
  return "'" + std::string(token) + "'";
}

// The one place messages are formatted: "FILE:LINE: error: WHAT", or "FILE: error: WHAT" for
// problems of the file as a whole (line 0).
InputError inputError(const std::string& name, std::size_t line, const std::string& what) {
  const std::string where = line > 0 ? name + ":" + std::to_string(line) : name;
  return InputError(where + ": error: " + what);
}

InputError expectedError(const std::string& name, std::size_t line, const std::string& expected,
                         const std::string& found) {
  return inputError(name, line, "expected " + expected + ", found " + found);
}

// Reads a stream line by line and hands out the whitespace-separated tokens of the current line.
// It knows the file name and line number, so the errors about the input are raised here. With a
// Progress it reports the bytes read (the line ending counted as one).
class LineReader {
 public:
  LineReader(std::istream& in, const std::string& name, Progress* progress = nullptr)
      : in_(in), name_(name), progress_(progress) {}

  // Advances to the next line, with its line ending and comment removed. False at end of file.
  bool nextLine() {
    if (!readLine()) return false;
    ++lineNumber_;
    unreportedBytes_ += line_.size() + 1;
    if (progress_ && lineNumber_ % kLinesPerReport == 0) {
      progress_->advance(unreportedBytes_);
      unreportedBytes_ = 0;
    }
    std::size_t begin = 0;
    std::size_t end = line_.size();
    if (lineNumber_ == 1) {
      const auto byte = [&](std::size_t i) { return i < end ? static_cast<unsigned char>(line_[i]) : 0u; };
      if ((byte(0) == 0xFF && byte(1) == 0xFE) || (byte(0) == 0xFE && byte(1) == 0xFF))
        fail("ASCII/UTF-8 text", "a UTF-16 byte-order mark");
      if (byte(0) == 0xEF && byte(1) == 0xBB && byte(2) == 0xBF) begin = 3;
    }
    if (end > begin && line_[end - 1] == '\r') --end;
    // One pass both rejects binary data and finds where a comment starts.
    std::size_t comment = end;
    for (std::size_t i = begin; i < end; ++i) {
      const unsigned char c = static_cast<unsigned char>(line_[i]);
      if ((c < 0x20 && c != '\t') || c == 0x7F) {
        static constexpr char kHex[] = "0123456789ABCDEF";
        fail("text", std::string("byte 0x") + kHex[c >> 4] + kHex[c & 15]);
      }
      if (c == '#' && comment == end) comment = i;
    }
    position_ = line_.data() + begin;
    end_ = line_.data() + comment;
    return true;
  }

  // Advances to the next line that has a token, skipping blank and comment lines. False at end of file.
  bool nextContentLine() {
    while (nextLine())
      if (!atEndOfLine()) return true;
    return false;
  }

  bool atEndOfLine() {
    skipBlanks();
    return position_ == end_;
  }

  // The next token of the current line; empty at its end.
  std::string_view token() {
    skipBlanks();
    const char* start = position_;
    while (position_ != end_ && *position_ != ' ' && *position_ != '\t') ++position_;
    return {start, static_cast<std::size_t>(position_ - start)};
  }

  // Whether the line's last non-blank character (before any comment) is a backslash.
  bool endsWithBackslash() const {
    const char* p = end_;
    while (p != position_ && (p[-1] == ' ' || p[-1] == '\t')) --p;
    return p != position_ && p[-1] == '\\';
  }

  // A finite number; `what` names the expected value when the line ends early ("a y coordinate").
  double number(const char* what) {
    const std::string_view t = token();
    if (t.empty()) failAt(what, t);
    return toNumber(t);
  }

  // A finite number if the line has another token; false at end of line.
  bool optionalNumber(double& value) {
    const std::string_view t = token();
    if (t.empty()) return false;
    value = toNumber(t);
    return true;
  }

  void expectEndOfLine() {
    const std::string_view t = token();
    if (!t.empty()) failAt("end of line", t);
  }

  std::size_t lineNumber() const { return lineNumber_; }

  [[noreturn]] void fail(const std::string& expected, const std::string& found) const {
    throw expectedError(name_, lineNumber_, expected, found);
  }

  // "found 'TOKEN'", or "found end of line" for an empty token.
  [[noreturn]] void failAt(const std::string& expected, std::string_view text) const {
    fail(expected, text.empty() ? "end of line" : quote(text));
  }

  // Something is missing at the end: the message names the line after the last one.
  [[noreturn]] void failAtEndOfFile(const std::string& expected) const {
    throw expectedError(name_, lineNumber_ + 1, expected, "end of file");
  }

 private:
  // Reads the next line into line_ without its '\n', from a buffer refilled in large blocks; a line
  // may end at end of file without one. False at end of file. A line is never held longer than
  // kMaxLineBytes, so a file without line breaks cannot exhaust memory.
  bool readLine() {
    line_.clear();
    bool any = false;
    for (;;) {
      if (next_ == filled_ && !refill()) return any;
      any = true;
      const char* begin = buffer_.data() + next_;
      const std::size_t available = filled_ - next_;
      const char* newline = static_cast<const char*>(std::memchr(begin, '\n', available));
      const std::size_t length = newline ? std::size_t(newline - begin) : available;
      if (line_.size() + length > kMaxLineBytes)
        throw expectedError(name_, lineNumber_ + 1, "a line of at most " + std::to_string(kMaxLineBytes >> 20) + " MiB",
                            "a longer one");
      line_.append(begin, length);
      next_ += newline ? length + 1 : length;
      if (newline) return true;
    }
  }

  // Reads the next block into buffer_; false at end of file.
  bool refill() {
    next_ = filled_ = 0;
    if (!in_.good()) return false;  // the previous block ended at end of file
    // Small inputs take a small buffer: the first block is 64 KiB, each next one twice as large.
    buffer_.resize(buffer_.empty() ? kFirstReadBlock : std::min(kReadBlock, 2 * buffer_.size()));
    in_.read(buffer_.data(), std::streamsize(buffer_.size()));
    if (in_.bad()) throw inputError(name_, 0, "cannot read: input/output error");
    filled_ = std::size_t(in_.gcount());
    return filled_ > 0;
  }

  void skipBlanks() {
    while (position_ != end_ && (*position_ == ' ' || *position_ == '\t')) ++position_;
  }

  double toNumber(std::string_view t) const {
    double value = 0.0;
    switch (parseReal(t, value)) {
      case NumberSyntax::ok:
        return value;
      case NumberSyntax::malformed:
        failAt("a number", t);
      case NumberSyntax::notFinite:
      case NumberSyntax::tooLarge:
        failAt("a finite number", t);
    }
    UVTK_CHECK(false);
    return value;
  }

  std::istream& in_;
  const std::string& name_;
  std::vector<char> buffer_;
  std::size_t next_ = 0, filled_ = 0;  // the first unread byte of buffer_, and how many it holds
  std::string line_;
  std::size_t lineNumber_ = 0;
  Progress* progress_;
  std::uint64_t unreportedBytes_ = 0;
  const char* position_ = nullptr;
  const char* end_ = nullptr;
};

// What a reader keeps across lines: the triangulator and its scratch space, and what the reader
// itself warns about (checkMesh adds the rest).
struct ReaderState {
  PolygonTriangulator triangulator;
  std::vector<int> vertices;  // the face's vertex indices
  std::vector<PolygonTriangle> triangles;
  MeshWarnings warnings;

  // Triangulates `vertices` into `triangles` (corner numbers), counting a polygon that is not simple.
  void triangulate(const Mesh& mesh, const LineReader& reader) {
    if (triangulator.triangulate(mesh.positions, vertices, triangles)) return;
    if (warnings.nonSimplePolygons++ == 0) warnings.firstNonSimplePolygonLine = reader.lineNumber();
  }
};

ReadMeshResult withWarnings(Mesh mesh, const MeshWarnings& readerWarnings) {
  ReadMeshResult result;
  result.warnings = readerWarnings;
  const MeshWarnings checked = checkMesh(mesh);
  result.warnings.degenerateFaces = checked.degenerateFaces;
  result.warnings.unreferencedVertices = checked.unreferencedVertices;
  result.mesh = std::move(mesh);
  return result;
}

// Triangles store int indices, so no table may grow past INT_MAX entries.
template <typename T>
void pushBounded(LineReader& reader, std::vector<T>& table, const T& value, const char* what) {
  if (table.size() >= static_cast<std::size_t>(INT_MAX))
    reader.fail("at most " + std::to_string(INT_MAX) + " " + what, "more");
  table.push_back(value);
}

// ---------------------------------------------------------------------------------------------
// OBJ

// Which of vt and vn the corners of a face carry, as bits.
enum CornerForm : int { kVertexOnly = 0, kWithTexcoord = 1, kWithNormal = 2 };

const char* formName(int form) {
  static const char* const kNames[] = {"v", "v/vt", "v//vn", "v/vt/vn"};
  return kNames[form];
}

// Splits a face corner "v", "v/vt", "v//vn" or "v/vt/vn" into its index texts; false for any other shape.
bool splitCorner(std::string_view corner, std::string_view parts[3], int& form) {
  const std::size_t slash1 = corner.find('/');
  parts[0] = corner.substr(0, slash1);
  if (parts[0].empty()) return false;
  if (slash1 == std::string_view::npos) {
    form = kVertexOnly;
    return true;
  }
  const std::string_view rest = corner.substr(slash1 + 1);
  const std::size_t slash2 = rest.find('/');
  parts[1] = rest.substr(0, slash2);
  if (slash2 == std::string_view::npos) {
    form = kWithTexcoord;
    return !parts[1].empty();
  }
  parts[2] = rest.substr(slash2 + 1);
  form = (parts[1].empty() ? kVertexOnly : kWithTexcoord) | kWithNormal;
  return !parts[2].empty() && parts[2].find('/') == std::string_view::npos;
}

// An OBJ index: 1-based, or negative counting back from the last of the `count` elements defined
// so far (OBJ resolves indices against what precedes the face). Returns the 0-based index.
int resolveObjIndex(const LineReader& reader, std::string_view text, std::size_t count, const char* what) {
  long long index = 0;
  const bool integer = parseInteger(text, index);
  const long long n = static_cast<long long>(count);
  if (integer && index > 0 && index <= n) return static_cast<int>(index - 1);
  if (integer && index < 0 && index >= -n) return static_cast<int>(n + index);
  if (n == 0) reader.fail(std::string(what) + " (none is defined before this line)", quote(text));
  // A negative integer, even one beyond long long, was meant as a relative index: show that range.
  const bool negative = text.size() > 1 && text[0] == '-' &&
                        std::all_of(text.begin() + 1, text.end(), [](char c) { return c >= '0' && c <= '9'; });
  const std::string range = negative ? "-" + std::to_string(n) + "..-1" : "1.." + std::to_string(n);
  reader.fail(std::string(what) + " in " + range, quote(text));
}

struct ObjCorner {
  int v = -1, vt = -1, vn = -1;
};

// Appends one triangle's corner attributes. The table is created (with -1 for every earlier
// triangle) by the first face that has the attribute, so it stays empty while no face has one.
void appendCorners(std::vector<Triangle>& table, std::size_t triangleIndex, bool faceHasIt, const Triangle& corners) {
  if (table.empty() && !faceHasIt) return;
  if (table.size() < triangleIndex) table.resize(triangleIndex, kNoCorners);
  table.push_back(faceHasIt ? corners : kNoCorners);
}

void readObjFace(LineReader& reader, Mesh& mesh, std::vector<ObjCorner>& corners, ReaderState& state) {
  corners.clear();
  int faceForm = kVertexOnly;
  for (std::string_view token = reader.token(); !token.empty(); token = reader.token()) {
    std::string_view parts[3];
    int form = kVertexOnly;
    if (!splitCorner(token, parts, form)) reader.fail("a face corner v, v/vt, v//vn or v/vt/vn", quote(token));
    if (corners.empty()) faceForm = form;
    if (form != faceForm)
      reader.fail(std::string("a corner of the same form as the first (") + formName(faceForm) + ")", quote(token));
    ObjCorner c;
    c.v = resolveObjIndex(reader, parts[0], mesh.positions.size(), "a vertex index");
    if (form & kWithTexcoord)
      c.vt = resolveObjIndex(reader, parts[1], mesh.texcoords.size(), "a texture coordinate index");
    if (form & kWithNormal) c.vn = resolveObjIndex(reader, parts[2], mesh.normals.size(), "a normal index");
    corners.push_back(c);
  }
  if (corners.size() < 3) reader.fail("at least 3 vertices in a face", std::to_string(corners.size()));
  state.vertices.clear();
  for (const ObjCorner& c : corners) state.vertices.push_back(c.v);
  state.triangulate(mesh, reader);
  for (const PolygonTriangle& t : state.triangles) {
    const ObjCorner &a = corners[t[0]], &b = corners[t[1]], &c = corners[t[2]];
    const std::size_t triangle = mesh.triangles.size();
    mesh.triangles.push_back({a.v, b.v, c.v});
    appendCorners(mesh.cornerTexcoords, triangle, faceForm & kWithTexcoord, {a.vt, b.vt, c.vt});
    appendCorners(mesh.cornerNormals, triangle, faceForm & kWithNormal, {a.vn, b.vn, c.vn});
  }
}

bool isIgnoredObjKeyword(std::string_view keyword) {
  // Grouping, smoothing and material statements, and line and point elements, carry nothing a
  // triangle mesh keeps.
  return keyword == "o" || keyword == "g" || keyword == "s" || keyword == "usemtl" || keyword == "mtllib" ||
         keyword == "l" || keyword == "p";
}

// ---------------------------------------------------------------------------------------------
// OFF

struct OffLayout {
  bool normals = false;  // each vertex line carries nx ny nz after x y z
  bool colours = false;  // ... then r g b [a], read and dropped
};

bool parseOffHeader(std::string_view header, OffLayout& layout) {
  const bool both = header == "CNOFF" || header == "NCOFF";
  layout.normals = both || header == "NOFF";
  layout.colours = both || header == "COFF";
  return layout.normals || layout.colours || header == "OFF";
}

// A count from the OFF counts line: an integer in 0..INT_MAX.
int readOffCount(LineReader& reader, const char* what) {
  const std::string_view t = reader.token();
  long long count = 0;
  if (!parseInteger(t, count) || count < 0) reader.failAt(std::string(what) + " (a non-negative integer)", t);
  if (count > INT_MAX) reader.failAt(std::string(what) + " of at most " + std::to_string(INT_MAX), t);
  return static_cast<int>(count);
}

// Up to `maximum` trailing colour values (integers or floats), read and dropped.
void skipColour(LineReader& reader, int maximum) {
  double ignored = 0.0;
  for (int i = 0; i < maximum; ++i)
    if (!reader.optionalNumber(ignored)) return;
}

// "1 face", "6 faces".
std::string countOf(int n, const char* singular, const char* plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

// Three numbers named in messages: a position ("an x coordinate", ...) or a normal.
constexpr const char* kPositionNames[3] = {"an x coordinate", "a y coordinate", "a z coordinate"};
constexpr const char* kNormalNames[3] = {"a normal's x component", "a normal's y component", "a normal's z component"};

Vec3 readVector(LineReader& reader, const char* const (&names)[3]) {
  Vec3 v;
  for (int a = 0; a < 3; ++a) v[a] = reader.number(names[a]);
  return v;
}

void readOffVertex(LineReader& reader, const OffLayout& layout, Mesh& mesh) {
  mesh.positions.push_back(readVector(reader, kPositionNames));
  if (layout.normals) mesh.normals.push_back(readVector(reader, kNormalNames));
  if (layout.colours) {
    reader.number("a red component");
    reader.number("a green component");
    reader.number("a blue component");
    skipColour(reader, 1);  // alpha
  }
  reader.expectEndOfLine();
}

void readOffFace(LineReader& reader, ReaderState& state, Mesh& mesh) {
  std::vector<int>& corners = state.vertices;
  const std::string_view countToken = reader.token();
  long long n = 0;
  if (!parseInteger(countToken, n) || n < 3) reader.failAt("a face vertex count of at least 3", countToken);
  const std::size_t vertexCount = mesh.positions.size();
  corners.clear();
  // n comes from the file: the loop ends at the line's end, so a huge n allocates nothing.
  for (long long i = 0; i < n; ++i) {
    const std::string_view t = reader.token();
    if (t.empty()) reader.fail(std::to_string(n) + " vertex indices", std::to_string(i));
    long long index = 0;
    if (!parseInteger(t, index) || index < 0 || index >= static_cast<long long>(vertexCount))
      reader.failAt("a vertex index in 0.." + std::to_string(vertexCount - 1), t);
    corners.push_back(static_cast<int>(index));
  }
  skipColour(reader, 4);  // a colour-map index or r g b [a]
  reader.expectEndOfLine();
  state.triangulate(mesh, reader);
  for (const PolygonTriangle& t : state.triangles) mesh.triangles.push_back({corners[t[0]], corners[t[1]], corners[t[2]]});
}

// OBJ: `v x y z`, `v x y z w` or `v x y z r g b`; `vt u [v [w]]`; `vn x y z`; `vp u [v [w]]`,
// ignored and counted; `f` with corners v, v/vt, v//vn or v/vt/vn, one form per face. w is the
// weight of a rational curve's control point, which a polygon mesh has no use for: checked as a
// number, then ignored, not divided by (as tinyobjloader, which keeps it apart; Assimp divides).
// r g b are the vertex colours MeshLab and others write: checked as numbers, dropped and counted.
// A line ending in '\' (a continuation, which few writers emit) is an error rather than joined, so
// every message names one physical line.
ReadMeshResult readObjLines(LineReader& reader) {
  Mesh mesh;
  std::vector<ObjCorner> corners;  // reused by every face
  ReaderState state;
  while (reader.nextLine()) {
    if (reader.endsWithBackslash()) reader.fail("end of line", "a '\\' line continuation");
    const std::string_view keyword = reader.token();
    if (keyword.empty()) continue;
    if (keyword == "v") {
      const Vec3 p = readVector(reader, kPositionNames);
      int more = 0;  // w, or r g b
      for (double ignored = 0.0; reader.optionalNumber(ignored);) ++more;
      if (more != 0 && more != 1 && more != 3)
        reader.fail("x y z, x y z w or x y z r g b", std::to_string(3 + more) + " numbers");
      if (more == 3) ++state.warnings.vertexColours;
      pushBounded(reader, mesh.positions, p, "vertices");
    } else if (keyword == "f") {
      readObjFace(reader, mesh, corners, state);
    } else if (keyword == "vt") {
      Vec3 t = Vec3::Zero();
      t.x() = reader.number("a u coordinate");
      if (reader.optionalNumber(t.y())) reader.optionalNumber(t.z());
      reader.expectEndOfLine();
      pushBounded(reader, mesh.texcoords, t, "texture coordinates");
    } else if (keyword == "vn") {
      const Vec3 n = readVector(reader, kNormalNames);
      reader.expectEndOfLine();
      pushBounded(reader, mesh.normals, n, "normals");
    } else if (keyword == "vp") {
      double ignored = 0.0;
      reader.number("a u parameter");
      if (reader.optionalNumber(ignored)) reader.optionalNumber(ignored);
      reader.expectEndOfLine();
      ++state.warnings.parameterVertices;
    } else if (!isIgnoredObjKeyword(keyword)) {
      reader.failAt("a keyword (v, vt, vn, f, ...)", keyword);
    }
  }
  if (mesh.triangles.empty()) reader.failAtEndOfFile("at least one face");
  return withWarnings(std::move(mesh), state.warnings);
}

// OFF: a header (OFF, NOFF, COFF, CNOFF or NCOFF), optionally followed on its line by the counts
// `nv nf ne`, else the counts on the next line; nv vertex lines; nf face lines
// `n i0 .. i(n-1) [colour]` with 0-based indices and up to four colour values; then only blank
// and comment lines. Blank and comment lines may appear anywhere.
ReadMeshResult readOffLines(LineReader& reader) {
  const std::string kHeaders = "an OFF header (OFF, NOFF, COFF, CNOFF or NCOFF)";
  if (!reader.nextContentLine()) reader.failAtEndOfFile(kHeaders);
  OffLayout layout;
  const std::string_view header = reader.token();
  if (!parseOffHeader(header, layout)) reader.failAt(kHeaders, header);
  if (reader.atEndOfLine() && !reader.nextContentLine()) reader.failAtEndOfFile("a vertex count");
  const int vertexCount = readOffCount(reader, "a vertex count");
  const int faceCount = readOffCount(reader, "a face count");
  readOffCount(reader, "an edge count");  // unused, but part of the format
  reader.expectEndOfLine();
  if (vertexCount == 0) reader.fail("at least one vertex", "a vertex count of 0");
  if (faceCount == 0) reader.fail("at least one face", "a face count of 0");

  Mesh mesh;
  mesh.positions.reserve(std::min<std::size_t>(vertexCount, kMaxReserve));
  if (layout.normals) mesh.normals.reserve(std::min<std::size_t>(vertexCount, kMaxReserve));
  for (int i = 0; i < vertexCount; ++i) {
    if (!reader.nextContentLine()) reader.failAtEndOfFile(countOf(vertexCount, "vertex", "vertices"));
    readOffVertex(reader, layout, mesh);
  }
  mesh.triangles.reserve(std::min<std::size_t>(faceCount, kMaxReserve));
  ReaderState state;  // reused by every face
  for (int i = 0; i < faceCount; ++i) {
    if (!reader.nextContentLine()) reader.failAtEndOfFile(countOf(faceCount, "face", "faces"));
    readOffFace(reader, state, mesh);
  }
  if (reader.nextContentLine()) reader.failAt("end of file", reader.token());
  // OFF normals are per vertex: every corner uses the normal of its own vertex.
  if (layout.normals) mesh.cornerNormals = mesh.triangles;
  return withWarnings(std::move(mesh), state.warnings);
}

// The bytes a reader takes from `source`, counted into a Progress: PLY and STL show their reading
// as OBJ and OFF do (theirs is counted per line). Seeking is passed through, as the STL reader
// asks for the file's size.
class ProgressBuffer : public std::streambuf {
 public:
  ProgressBuffer(std::streambuf& source, Progress& progress) : source_(source), progress_(progress) {}

 protected:
  int_type underflow() override {
    const std::streamsize got = source_.sgetn(buffer_.data(), std::streamsize(buffer_.size()));
    if (got <= 0) return traits_type::eof();
    progress_.advance(std::uint64_t(got));
    setg(buffer_.data(), buffer_.data(), buffer_.data() + got);
    return traits_type::to_int_type(buffer_[0]);
  }
  // Large reads go straight from the source, past the buffer.
  std::streamsize xsgetn(char* out, std::streamsize n) override {
    std::streamsize done = std::min<std::streamsize>(n, egptr() - gptr());
    if (done > 0) {  // before the first read there is no buffer at all (gptr() is null)
      std::memcpy(out, gptr(), std::size_t(done));
      gbump(int(done));
    }
    if (done < n) {
      const std::streamsize got = source_.sgetn(out + done, n - done);
      if (got > 0) progress_.advance(std::uint64_t(got)), done += got;
    }
    return done;
  }
  pos_type seekoff(off_type offset, std::ios_base::seekdir from, std::ios_base::openmode which) override {
    if (from == std::ios_base::cur) offset -= egptr() - gptr();  // the source is ahead by what is unread here
    setg(buffer_.data(), buffer_.data(), buffer_.data());
    return source_.pubseekoff(offset, from, which);
  }
  pos_type seekpos(pos_type position, std::ios_base::openmode which) override {
    setg(buffer_.data(), buffer_.data(), buffer_.data());
    return source_.pubseekpos(position, which);
  }

 private:
  std::streambuf& source_;
  Progress& progress_;
  std::array<char, std::size_t{1} << 16> buffer_;
};

}  // namespace

ReadMeshResult readObj(std::istream& in, const std::string& name) {
  LineReader reader(in, name);
  return readObjLines(reader);
}

ReadMeshResult readOff(std::istream& in, const std::string& name) {
  LineReader reader(in, name);
  return readOffLines(reader);
}

ReadMeshResult readMesh(const std::string& path) {
  const std::optional<MeshFormat> format = meshFormatOf(path);
  if (!format) {
    const std::string extension = std::filesystem::path(path).extension().string();
    throw expectedError(path, 0, kReadableExtensions, extension.empty() ? "none" : quote(extension));
  }
  // A directory opens as a stream on Linux and only fails on reading: name the real reason.
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored))
    throw inputError(path, 0, "cannot open: " + std::generic_category().message(EISDIR));
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int error = errno;
    throw inputError(path, 0, "cannot open: " + (error ? std::generic_category().message(error) : "unknown error"));
  }
  const std::uintmax_t size = std::filesystem::file_size(path, ignored);
  Progress progress("reading " + path, size == std::uintmax_t(-1) ? 0 : size, "MB", 1'000'000);
  if (*format != MeshFormat::obj && *format != MeshFormat::off) {
    ProgressBuffer counted(*in.rdbuf(), progress);
    std::istream countedIn(&counted);
    if (*format == MeshFormat::ply) return readPly(countedIn, path);
    if (*format == MeshFormat::stl) return readStl(countedIn, path);
    return readGltf(countedIn, path);
  }
  LineReader reader(in, path, &progress);
  return *format == MeshFormat::obj ? readObjLines(reader) : readOffLines(reader);
}

}  // namespace uvtk::io
