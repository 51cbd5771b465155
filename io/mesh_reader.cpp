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
//
// A regular OBJ file (or OBJ text in memory) is read in chunks split at line ends, on all threads,
// each thread reading (pread) and parsing its own chunks into their own arrays. A chunk does not
// know how many vertices precede it, so it keeps positive indices as they are and notes the fewest
// vertices before it that they need; a chunk that needs more than precede it, uses negative
// (relative) indices or fails is read again once the counts before it are known, exactly as the
// sequential reader reads it, with its true line numbers: the first error in file order is the one
// reported, word for word. Polygons are triangulated once every position is in place. The stream
// reader (stdin, FIFOs, devices, readObj) is the same code as one chunk that knows its counts from
// the start. Most lines take a fast path (ObjChunkReader::readPlainLine) that hands anything
// unusual to the general one.
#include "io/mesh_reader.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <istream>
#include <memory>
#include <mutex>
#include <optional>
#include <streambuf>
#include <string_view>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "core/huge_pages.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "io/gltf_reader.h"
#include "io/face_lists.h"
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

// The blanks that separate an OBJ or OFF line's tokens.
bool isBlank(char c) { return c == ' ' || c == '\t'; }

// Reads text line by line, from a stream or from memory, and hands out the whitespace-separated
// tokens of the current line. It knows the file name and line number, so the errors about the
// input are raised here. With a Progress it reports the bytes read (the line ending counted as one).
class LineReader {
 public:
  // The lines of a stream, read in blocks.
  LineReader(std::istream& in, const std::string& name, Progress* progress = nullptr)
      : in_(&in), name_(name), progress_(progress) {}
  // The lines of `text`, held in memory, the first numbered `firstLine`; `fileStart` when the text
  // opens the file (where a byte-order mark may be).
  LineReader(std::string_view text, const std::string& name, std::size_t firstLine, bool fileStart,
             Progress* progress = nullptr)
      : name_(name),
        lineNumber_(firstLine - 1),
        fileStart_(fileStart),
        progress_(progress),
        text_(text) {}
  ~LineReader() {
    if (progress_) progress_->advance(unreportedBytes_);
  }

  // Advances to the next line, with its line ending and comment removed. False at end of file.
  bool nextLine() {
    if (!readLine()) return false;
    ++lineNumber_;
    unreportedBytes_ += line_.size() + 1;
    if (progress_ && lineNumber_ % kLinesPerReport == 0) {
      progress_->advance(unreportedBytes_);
      unreportedBytes_ = 0;
    }
    const char* begin = line_.data();
    const char* end = begin + line_.size();
    if (fileStart_) {
      fileStart_ = false;
      const auto byte = [&](std::size_t i) { return i < line_.size() ? static_cast<unsigned char>(begin[i]) : 0u; };
      if ((byte(0) == 0xFF && byte(1) == 0xFE) || (byte(0) == 0xFE && byte(1) == 0xFF))
        fail("ASCII/UTF-8 text", "a UTF-16 byte-order mark");
      if (byte(0) == 0xEF && byte(1) == 0xBB && byte(2) == 0xBF) begin += 3;
    }
    if (end > begin && end[-1] == '\r') --end;
    // One pass both rejects binary data and finds where a comment starts.
    const char* comment = end;
    for (const char* p = begin; p != end; ++p) {
      const unsigned char c = static_cast<unsigned char>(*p);
      if (c <= '#' || c == 0x7F) {  // one test for the rare bytes, then which of them
        if ((c < 0x20 && c != '\t') || c == 0x7F) {
          static constexpr char kHex[] = "0123456789ABCDEF";
          fail("text", std::string("byte 0x") + kHex[c >> 4] + kHex[c & 15]);
        }
        if (c == '#' && comment == end) comment = p;
      }
    }
    position_ = begin;
    end_ = comment;
    comment_ = {comment, static_cast<std::size_t>(end - comment)};
    return true;
  }

  // The current line's comment, from its '#' to the end of the line; empty when it has none.
  std::string_view comment() const { return comment_; }

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
    while (position_ != end_ && !isBlank(*position_)) ++position_;
    return {start, static_cast<std::size_t>(position_ - start)};
  }

  // Whether the line's last non-blank character (before any comment) is a backslash.
  bool endsWithBackslash() const {
    const char* p = end_;
    while (p != position_ && isBlank(p[-1])) --p;
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
  const std::string& name() const { return name_; }

  // For a reader of common lines beside this one (ObjChunkReader::readPlainLine): the unread text,
  // empty when reading a stream or when the next line may open the file (its byte-order mark).
  std::string_view unreadText() const { return fileStart_ ? std::string_view() : textInMemory(); }
  // The text not yet read when it is held in memory (a chunk, or text given whole); empty for a stream.
  std::string_view textInMemory() const { return in_ ? std::string_view() : text_.substr(next_); }
  // Passes over the next `length` bytes of unreadText(), one line read by someone else.
  void skipLine(std::size_t length) {
    next_ += length;
    ++lineNumber_;
    unreportedBytes_ += length;
    if (progress_ && lineNumber_ % kLinesPerReport == 0) {
      progress_->advance(unreportedBytes_);
      unreportedBytes_ = 0;
    }
  }

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
  // Points line_ at the next line without its '\n'; a line may end at end of file without one.
  // False at end of file. A line is never longer than kMaxLineBytes, so a file without line breaks
  // cannot exhaust memory.
  bool readLine() {
    if (!in_) {  // in memory: the line is a view of the text
      if (next_ == text_.size()) return false;
      const char* begin = text_.data() + next_;
      const std::size_t available = text_.size() - next_;
      const char* newline = static_cast<const char*>(std::memchr(begin, '\n', available));
      const std::size_t length = newline ? std::size_t(newline - begin) : available;
      if (length > kMaxLineBytes) failLongLine();
      line_ = {begin, length};
      next_ += newline ? length + 1 : length;
      return true;
    }
    // From a stream: the line is assembled in lineText_ from a buffer refilled in large blocks.
    lineText_.clear();
    bool any = false;
    for (;;) {
      if (next_ == filled_ && !refill()) break;
      any = true;
      const char* begin = buffer_.data() + next_;
      const std::size_t available = filled_ - next_;
      const char* newline = static_cast<const char*>(std::memchr(begin, '\n', available));
      const std::size_t length = newline ? std::size_t(newline - begin) : available;
      if (lineText_.size() + length > kMaxLineBytes) failLongLine();
      lineText_.append(begin, length);
      next_ += newline ? length + 1 : length;
      if (newline) break;
    }
    line_ = lineText_;
    return any;
  }

  [[noreturn]] void failLongLine() const {
    throw expectedError(name_, lineNumber_ + 1, "a line of at most " + std::to_string(kMaxLineBytes >> 20) + " MiB",
                        "a longer one");
  }

  // Reads the next block into buffer_; false at end of file.
  bool refill() {
    next_ = filled_ = 0;
    if (!in_->good()) return false;  // the previous block ended at end of file
    // Small inputs take a small buffer: the first block is 64 KiB, each next one twice as large.
    buffer_.resize(buffer_.empty() ? kFirstReadBlock : std::min(kReadBlock, 2 * buffer_.size()));
    in_->read(buffer_.data(), std::streamsize(buffer_.size()));
    if (in_->bad()) throw inputError(name_, 0, "cannot read: input/output error");
    filled_ = std::size_t(in_->gcount());
    return filled_ > 0;
  }

  void skipBlanks() {
    while (position_ != end_ && isBlank(*position_)) ++position_;
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

  std::istream* in_ = nullptr;  // null: the lines of text_
  const std::string& name_;
  std::vector<char> buffer_;
  std::size_t next_ = 0, filled_ = 0;  // the first unread byte of buffer_ (or text_), and how many buffer_ holds
  std::string lineText_;
  std::string_view line_;  // the current line: lineText_, or a part of text_
  std::size_t lineNumber_ = 0;
  bool fileStart_ = true;
  Progress* progress_;
  std::uint64_t unreportedBytes_ = 0;
  std::string_view text_;
  const char* position_ = nullptr;
  const char* end_ = nullptr;
  std::string_view comment_;
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

ReadMeshResult withWarnings(Mesh mesh, const MeshWarnings& readerWarnings, int threads = 1) {
  ReadMeshResult result;
  result.warnings = readerWarnings;
  const MeshWarnings checked = checkMesh(mesh, threads);
  result.warnings.degenerateFaces = checked.degenerateFaces;
  result.warnings.unreferencedVertices = checked.unreferencedVertices;
  result.mesh = std::move(mesh);
  return result;
}

// Three numbers named in messages: a position ("an x coordinate", ...) or a normal.
constexpr const char* kPositionNames[3] = {"an x coordinate", "a y coordinate", "a z coordinate"};
constexpr const char* kNormalNames[3] = {"a normal's x component", "a normal's y component", "a normal's z component"};

Vec3 readVector(LineReader& reader, const char* const (&names)[3]) {
  Vec3 v;
  for (int a = 0; a < 3; ++a) v[a] = reader.number(names[a]);
  return v;
}

// ---------------------------------------------------------------------------------------------
// OBJ

bool isIgnoredObjKeyword(std::string_view keyword) {
  // Grouping, smoothing and material statements, and line and point elements, carry nothing a
  // triangle mesh keeps.
  return keyword == "o" || keyword == "g" || keyword == "s" || keyword == "usemtl" || keyword == "mtllib" ||
         keyword == "l" || keyword == "p";
}


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
// `expected`: the triangles the table will likely hold, its room when it is created.
void appendCorners(std::vector<Triangle>& table, std::size_t triangleIndex, bool faceHasIt, const Triangle& corners,
                   std::size_t expected) {
  if (table.empty() && !faceHasIt) return;
  if (table.empty()) table.reserve(std::max(expected, triangleIndex + 1));
  if (table.size() < triangleIndex) table.resize(triangleIndex, kNoCorners);
  table.push_back(faceHasIt ? corners : kNoCorners);
}

// The element tables OBJ indices refer to.
enum ObjTable : int { kPositionTable, kTexcoordTable, kNormalTable };
using ObjCounts = std::array<std::size_t, 3>;  // elements of each table

// A face of more than three corners, triangulated once every position is known: its n - 2
// triangles hold their places in the arrays meanwhile.
struct ObjPolygon {
  std::size_t firstTriangle;  // in the chunk's triangles
  std::size_t firstCorner;    // in the chunk's polygonCorners
  std::size_t corners;
  int form;
  std::size_t line;  // the chunk's numbering: add lineOffset
};

// What the lines of one chunk of an OBJ define, in their order. The corner tables are the chunk's
// part of the mesh's: they start at the chunk's first face with the attribute (the triangles before
// it have none). Indices are 0-based into the whole mesh's tables.
struct ObjChunk {
  std::vector<Vec3> positions, texcoords, normals;
  std::vector<Triangle> triangles, cornerTexcoords, cornerNormals;
  std::vector<ObjPolygon> polygons;
  std::vector<ObjCorner> polygonCorners;
  std::size_t lines = 0;
  std::size_t lineOffset = 0;  // from the chunk's line numbers to the file's
  std::size_t vertexColours = 0, parameterVertices = 0;
  ListedFaces listedFaces;  // 0-based, from uvtk's comments (io/face_lists.h)
  // Left by a read that did not know the counts before the chunk (provisional):
  std::exception_ptr error;                 // the read stopped here (syntax errors do not depend on the counts)
  bool relative = false;                    // a negative index: it depends on the counts before the chunk
  std::array<long long, 3> needed = {};     // the fewest elements before the chunk its positive indices need

  ObjCounts counts() const { return {positions.size(), texcoords.size(), normals.size()}; }

  // Whether the chunk must be read again with the counts before it known: it stopped, it has
  // relative indices, or some index or table is out of range there (an error, then).
  bool settledBy(const ObjCounts& before) const {
    if (error || relative) return false;
    const ObjCounts own = counts();
    for (int t = 0; t < 3; ++t)
      if (needed[t] > static_cast<long long>(before[t]) || before[t] + own[t] > static_cast<std::size_t>(INT_MAX))
        return false;
    return true;
  }
};

// The lines of `text` that begin (after blanks) with each keyword a chunk's arrays take: v, vt, vn
// and f, each at most the text's bytes over its shortest line ("v 0 0 0\n" is 8 bytes). A chunk's
// arrays are sized by them before it is read: grown by doubling, they touched and copied about
// twice the memory they end with (a 4 M-face map's reader faulted in about 430 MB for 190 MB of
// arrays).
struct ObjLineCounts {
  std::size_t positions = 0, texcoords = 0, normals = 0, faces = 0;
};
ObjLineCounts countObjLines(std::string_view text) {
  ObjLineCounts n;
  const char *p = text.data(), *const end = p + text.size();
  while (p != end) {
    while (p != end && isBlank(*p)) ++p;
    if (end - p >= 2) {
      if (p[0] == 'f' && isBlank(p[1])) ++n.faces;
      else if (p[0] == 'v' && isBlank(p[1])) ++n.positions;
      else if (end - p >= 3 && p[0] == 'v' && isBlank(p[2])) n.texcoords += p[1] == 't', n.normals += p[1] == 'n';
    }
    const void* newline = std::memchr(p, '\n', std::size_t(end - p));
    p = newline ? static_cast<const char*>(newline) + 1 : end;
  }
  const std::size_t bytes = text.size();
  n.positions = std::min(n.positions, bytes / 8), n.texcoords = std::min(n.texcoords, bytes / 5);
  n.normals = std::min(n.normals, bytes / 9), n.faces = std::min(n.faces, bytes / 8);
  return n;
}

// Triangles store int indices, so no table may grow past INT_MAX entries.
template <typename T>
void pushBounded(LineReader& reader, std::vector<T>& table, std::size_t before, const T& value, const char* what) {
  if (before + table.size() >= static_cast<std::size_t>(INT_MAX))
    reader.fail("at most " + std::to_string(INT_MAX) + " " + what, "more");
  table.push_back(value);
}

// Reads the lines of one chunk into `chunk`. With the counts of the elements before the chunk
// (`before`), every index is resolved and checked as the sequential reader does, and errors are
// thrown; without them (null), a positive index is kept as it is with the count it needs noted,
// and a negative one is only noted.
class ObjChunkReader {
 public:
  ObjChunkReader(LineReader& reader, const ObjCounts* before, ObjChunk& chunk)
      : reader_(reader), before_(before), chunk_(chunk) {}

  // OBJ: `v x y z`, `v x y z w` or `v x y z r g b`; `vt u [v [w]]`; `vn x y z`; `vp u [v [w]]`,
  // ignored and counted; `f` with corners v, v/vt, v//vn or v/vt/vn, one form per face. w is the
  // weight of a rational curve's control point, which a polygon mesh has no use for: checked as a
  // number, then ignored, not divided by (as tinyobjloader, which keeps it apart; Assimp divides).
  // r g b are the vertex colours MeshLab and others write: checked as numbers, dropped and counted.
  // A line ending in '\' (a continuation, which few writers emit) is an error rather than joined,
  // so every message names one physical line.
  void read() {
    const std::size_t firstLine = reader_.lineNumber() + 1;
    chunk_.lineOffset = 0;
    if (const std::string_view text = reader_.textInMemory(); !text.empty()) {  // a stream's arrays grow as read
      const ObjLineCounts expected = countObjLines(text);
      chunk_.positions.reserve(expected.positions);
      chunk_.texcoords.reserve(expected.texcoords);
      chunk_.normals.reserve(expected.normals);
      chunk_.triangles.reserve(expected.faces);
      expectedTriangles_ = expected.faces;
    }
    for (;;) {
      if (readPlainLine()) continue;
      if (!reader_.nextLine()) break;
      if (reader_.endsWithBackslash()) reader_.fail("end of line", "a '\\' line continuation");
      const std::string_view keyword = reader_.token();
      if (keyword.empty()) {  // a blank line, or a comment: perhaps a line of uvtk's lists of faces
        if (!reader_.comment().empty()) readFaceListLine(reader_.comment(), false, chunk_.listedFaces);
        continue;
      }
      if (keyword == "v") {
        const Vec3 p = readVector(reader_, kPositionNames);
        int more = 0;  // w, or r g b
        for (double ignored = 0.0; reader_.optionalNumber(ignored);) ++more;
        if (more != 0 && more != 1 && more != 3)
          reader_.fail("x y z, x y z w or x y z r g b", std::to_string(3 + more) + " numbers");
        if (more == 3) ++chunk_.vertexColours;
        pushBounded(reader_, chunk_.positions, before(kPositionTable), p, "vertices");
      } else if (keyword == "f") {
        readFace();
      } else if (keyword == "vt") {
        Vec3 t = Vec3::Zero();
        t.x() = reader_.number("a u coordinate");
        if (reader_.optionalNumber(t.y())) reader_.optionalNumber(t.z());
        reader_.expectEndOfLine();
        pushBounded(reader_, chunk_.texcoords, before(kTexcoordTable), t, "texture coordinates");
      } else if (keyword == "vn") {
        const Vec3 n = readVector(reader_, kNormalNames);
        reader_.expectEndOfLine();
        pushBounded(reader_, chunk_.normals, before(kNormalTable), n, "normals");
      } else if (keyword == "vp") {
        double ignored = 0.0;
        reader_.number("a u parameter");
        if (reader_.optionalNumber(ignored)) reader_.optionalNumber(ignored);
        reader_.expectEndOfLine();
        ++chunk_.parameterVertices;
      } else if (!isIgnoredObjKeyword(keyword)) {
        reader_.failAt("a keyword (v, vt, vn, f, ...)", keyword);
      }
    }
    chunk_.lines = reader_.lineNumber() + 1 - firstLine;
  }

 private:
  std::size_t before(int table) const { return before_ ? (*before_)[table] : 0; }
  // The elements of `table` the chunk has defined so far (one table's size: a corner's index
  // reads only its own).
  std::size_t definedIn(int table) const {
    return table == kPositionTable   ? chunk_.positions.size()
           : table == kTexcoordTable ? chunk_.texcoords.size()
                                     : chunk_.normals.size();
  }

  // The 0-based index of a corner's index text into `table`, whose elements so far are `defined`
  // in the chunk.
  int index(std::string_view text, int table, const char* what) {
    const std::size_t defined = definedIn(table);
    if (before_) return resolveObjIndex(reader_, text, (*before_)[table] + defined, what);
    long long i = 0;
    if (parseInteger(text, i) && i != 0) {
      if (i < 0) {
        chunk_.relative = true;
        return 0;
      }
      chunk_.needed[table] = std::max(chunk_.needed[table], i - static_cast<long long>(defined));
      return i <= INT_MAX ? static_cast<int>(i - 1) : 0;  // one beyond INT_MAX needs more than any table holds
    }
    return resolveObjIndex(reader_, text, defined, what);  // not an index whatever precedes: throws
  }

  void readFace() {
    corners_.clear();
    int faceForm = kVertexOnly;
    for (std::string_view token = reader_.token(); !token.empty(); token = reader_.token()) {
      std::string_view parts[3];
      int form = kVertexOnly;
      if (!splitCorner(token, parts, form)) reader_.fail("a face corner v, v/vt, v//vn or v/vt/vn", quote(token));
      if (corners_.empty()) faceForm = form;
      if (form != faceForm)
        reader_.fail(std::string("a corner of the same form as the first (") + formName(faceForm) + ")", quote(token));
      ObjCorner c;
      c.v = index(parts[0], kPositionTable, "a vertex index");
      if (form & kWithTexcoord) c.vt = index(parts[1], kTexcoordTable, "a texture coordinate index");
      if (form & kWithNormal) c.vn = index(parts[2], kNormalTable, "a normal index");
      corners_.push_back(c);
    }
    if (corners_.size() < 3) reader_.fail("at least 3 vertices in a face", std::to_string(corners_.size()));
    addFace(faceForm, reader_.lineNumber());
  }

  // ---- Common lines, read straight from the text
  //
  // Most lines of most files are `v x y z`, `vt u v`, `vn x y z` and `f` with positive indices in
  // one of the four forms, with single blanks, no comment, no sign and nothing unusual: such a
  // line is read here in one pass, without the tokens and checks of the general reader. Anything
  // else (a sign, a comment, a stray byte, an index out of range, an error) leaves the line
  // untouched for the general reader, which then reads it as it reads every line. A number is
  // what std::from_chars reads up to a blank or the line's end, as the general reader's whole
  // token, so both readers give the same values.

  // Reads the next line if it is a common one; false (nothing read) otherwise.
  bool readPlainLine() {
    const std::string_view rest = reader_.unreadText();
    if (rest.empty()) return false;
    const char* p = rest.data();
    const char* const end = p + rest.size();
    while (p != end && isBlank(*p)) ++p;
    if (end - p < 2) return false;
    if (p[0] == 'v') {
      const char kind = p[1];
      if (isBlank(kind)) {
        Vec3 v;
        p += 1;
        if (!readNumbers(p, end, v, 3) || !lineEnds(p, end)) return false;
        if (before(kPositionTable) + chunk_.positions.size() >= static_cast<std::size_t>(INT_MAX)) return false;
        chunk_.positions.push_back(v);
      } else if ((kind == 't' || kind == 'n') && end - p > 2 && isBlank(p[2])) {
        const int table = kind == 't' ? kTexcoordTable : kNormalTable;
        std::vector<Vec3>& values = kind == 't' ? chunk_.texcoords : chunk_.normals;
        Vec3 v = Vec3::Zero();
        p += 2;
        if (!readNumbers(p, end, v, kind == 't' ? 2 : 3) || !lineEnds(p, end)) return false;
        if (before(table) + values.size() >= static_cast<std::size_t>(INT_MAX)) return false;
        values.push_back(v);
      } else {
        return false;
      }
    } else if (p[0] == 'f' && isBlank(p[1])) {
      ++p;
      corners_.clear();
      int faceForm = -1;
      IndexBounds bounds = indexBounds();
      while (p != end && isBlank(*p)) {
        while (p != end && isBlank(*p)) ++p;
        if (p == end || *p == '\n' || *p == '\r') break;
        // The indices are kept in locals and stored into the corner in place: fields written one
        // by one into a corner then copied whole would stall the copy on every corner.
        int form = kVertexOnly, vt = -1, vn = -1;
        const int v = readIndex(p, end, kPositionTable, bounds);
        if (v < 0) return false;
        if (p != end && *p == '/') {
          ++p;
          if (p != end && *p != '/') {
            if ((vt = readIndex(p, end, kTexcoordTable, bounds)) < 0) return false;
            form |= kWithTexcoord;
          }
          if (p != end && *p == '/') {
            ++p;
            if ((vn = readIndex(p, end, kNormalTable, bounds)) < 0) return false;
            form |= kWithNormal;
          }
          if (form == kVertexOnly) return false;  // "1/": malformed
        }
        if (faceForm < 0) faceForm = form;
        if (form != faceForm) return false;
        ObjCorner& corner = corners_.emplace_back();
        corner.v = v, corner.vt = vt, corner.vn = vn;
      }
      if (corners_.size() < 3 || !lineEnds(p, end)) return false;
      if (!before_) chunk_.needed = bounds.needed;
      addFace(faceForm, reader_.lineNumber() + 1);
    } else {
      return false;
    }
    const std::size_t length = std::size_t(p - rest.data());
    if (length > kMaxLineBytes) return false;  // perhaps too long: the general reader knows
    reader_.skipLine(length);
    return true;
  }

  // `count` numbers, each after blanks, none after a sign '+' (the general reader takes that).
  static bool readNumbers(const char*& p, const char* end, Vec3& v, int count) {
    for (int a = 0; a < count; ++a) {
      if (p == end || !isBlank(*p)) return false;
      do ++p;
      while (p != end && isBlank(*p));
      const std::from_chars_result r = std::from_chars(p, end, v[a], std::chars_format::general);
      if (r.ec != std::errc() || !std::isfinite(v[a])) return false;
      p = r.ptr;
    }
    return true;
  }

  // Past blanks to the line's end, "\n", "\r\n" or the text's end; false if anything else is there.
  static bool lineEnds(const char*& p, const char* end) {
    while (p != end && isBlank(*p)) ++p;
    if (p == end) return true;
    if (*p == '\r') ++p;
    if (p == end) return true;
    if (*p != '\n') return false;
    ++p;
    return true;
  }

  // What a face line's indices are checked against, in locals for the line (a face defines no
  // element): the elements each table has before it (the chunk's own, and those before the chunk
  // when known), and the counts the chunk needs before it (stored when the line is read).
  struct IndexBounds {
    std::array<long long, 3> defined, largest;  // largest: the last valid index, or none (-1) when unknown
    std::array<long long, 3> needed;
  };
  IndexBounds indexBounds() const {
    IndexBounds b{};
    for (int t = 0; t < 3; ++t) {
      b.defined[t] = static_cast<long long>(definedIn(t));
      b.largest[t] = before_ ? static_cast<long long>((*before_)[t]) + b.defined[t] : -1;
    }
    b.needed = chunk_.needed;
    return b;
  }

  // The 0-based index of a positive decimal index of at most 9 digits, in range when the counts
  // before the chunk are known (the counts it needs noted when they are not); -1 for any other text.
  static int readIndex(const char*& text, const char* end, int table, IndexBounds& bounds) {
    const char *start = text, *p = text;  // a local cursor: `text` is stored once, not every digit
    long long value = 0;
    while (p != end && *p >= '0' && *p <= '9' && p - start < 10) value = value * 10 + (*p++ - '0');
    text = p;
    if (p == start || p - start == 10 || value == 0) return -1;
    if (p != end && !isBlank(*p) && *p != '/' && *p != '\n' && *p != '\r') return -1;
    if (bounds.largest[table] >= 0) {
      if (value > bounds.largest[table]) return -1;
    } else {
      bounds.needed[table] = std::max(bounds.needed[table], value - bounds.defined[table]);
    }
    return static_cast<int>(value - 1);
  }

  // Adds the face of corners_ (at least three, of one form), read on `line`: a triangle at once, a
  // polygon as the places of its triangles.
  void addFace(int faceForm, std::size_t line) {
    const bool texcoords = faceForm & kWithTexcoord, normals = faceForm & kWithNormal;
    if (corners_.size() == 3) {
      const ObjCorner &a = corners_[0], &b = corners_[1], &c = corners_[2];
      const std::size_t triangle = chunk_.triangles.size();
      chunk_.triangles.push_back({a.v, b.v, c.v});
      appendCorners(chunk_.cornerTexcoords, triangle, texcoords, {a.vt, b.vt, c.vt}, expectedTriangles_);
      appendCorners(chunk_.cornerNormals, triangle, normals, {a.vn, b.vn, c.vn}, expectedTriangles_);
      return;
    }
    chunk_.polygons.push_back(
        {chunk_.triangles.size(), chunk_.polygonCorners.size(), corners_.size(), faceForm, line});
    chunk_.polygonCorners.insert(chunk_.polygonCorners.end(), corners_.begin(), corners_.end());
    for (std::size_t i = 2; i < corners_.size(); ++i) {  // places, filled by joinObjChunks
      const std::size_t triangle = chunk_.triangles.size();
      chunk_.triangles.push_back(kNoCorners);
      appendCorners(chunk_.cornerTexcoords, triangle, texcoords, kNoCorners, expectedTriangles_);
      appendCorners(chunk_.cornerNormals, triangle, normals, kNoCorners, expectedTriangles_);
    }
  }

  LineReader& reader_;
  const ObjCounts* before_;
  ObjChunk& chunk_;
  std::vector<ObjCorner> corners_;  // reused by every face
  std::size_t expectedTriangles_ = 0;  // the room a corner table is created with
};

// Whether any of the chunks has a corner table: then the mesh has one for every triangle.
bool anyCornerTable(const std::vector<ObjChunk>& chunks, std::vector<Triangle> ObjChunk::*table) {
  return std::any_of(chunks.begin(), chunks.end(), [&](const ObjChunk& c) { return !(c.*table).empty(); });
}

// Copies `part` (or -1 for each of `count` triangles if the chunk has no such table) to `at`.
void placeCornerTable(const std::vector<Triangle>& part, std::size_t count, std::vector<Triangle>::iterator at) {
  if (part.empty())
    std::fill_n(at, count, kNoCorners);
  else
    std::copy(part.begin(), part.end(), at);
}

template <typename T>
void release(std::vector<T>& v) {
  std::vector<T>().swap(v);
}

// The mesh of the chunks, read in file order and each settled (every index resolved and checked),
// with its polygons triangulated; or the error of a file without faces.
ReadMeshResult joinObjChunks(std::vector<ObjChunk>& chunks, const std::string& name, int threads) {
  const int n = static_cast<int>(chunks.size());
  // Where each chunk's elements go.
  std::vector<ObjCounts> before(n + 1, ObjCounts{});
  std::vector<std::size_t> trianglesBefore(n + 1, 0);
  std::size_t lines = 0;
  MeshWarnings warnings;
  for (int i = 0; i < n; ++i) {
    const ObjCounts own = chunks[i].counts();
    for (int t = 0; t < 3; ++t) before[i + 1][t] = before[i][t] + own[t];
    trianglesBefore[i + 1] = trianglesBefore[i] + chunks[i].triangles.size();
    lines += chunks[i].lines;
    warnings.vertexColours += chunks[i].vertexColours;
    warnings.parameterVertices += chunks[i].parameterVertices;
  }
  if (trianglesBefore[n] == 0) throw expectedError(name, lines + 1, "at least one face", "end of file");

  Mesh mesh;
  if (n == 1) {  // a stream, or a small file: the chunk's arrays are the mesh's
    ObjChunk& c = chunks[0];
    mesh.positions = std::move(c.positions);
    mesh.texcoords = std::move(c.texcoords);
    mesh.normals = std::move(c.normals);
    mesh.triangles = std::move(c.triangles);
    mesh.cornerTexcoords = std::move(c.cornerTexcoords);
    mesh.cornerNormals = std::move(c.cornerNormals);
  } else {
    resizeFaultedIn(mesh.positions, before[n][kPositionTable], threads);
    resizeFaultedIn(mesh.texcoords, before[n][kTexcoordTable], threads);
    resizeFaultedIn(mesh.normals, before[n][kNormalTable], threads);
    resizeFaultedIn(mesh.triangles, trianglesBefore[n], threads);
    const bool texcoords = anyCornerTable(chunks, &ObjChunk::cornerTexcoords);
    const bool normals = anyCornerTable(chunks, &ObjChunk::cornerNormals);
    if (texcoords) resizeFaultedIn(mesh.cornerTexcoords, trianglesBefore[n], threads);
    if (normals) resizeFaultedIn(mesh.cornerNormals, trianglesBefore[n], threads);
    // Each chunk's memory is given back as soon as it is copied, so the mesh is never held twice whole.
    parallelFor(n, threads, [&](int i) {
      ObjChunk& c = chunks[i];
      std::copy(c.positions.begin(), c.positions.end(), mesh.positions.begin() + before[i][kPositionTable]);
      std::copy(c.texcoords.begin(), c.texcoords.end(), mesh.texcoords.begin() + before[i][kTexcoordTable]);
      std::copy(c.normals.begin(), c.normals.end(), mesh.normals.begin() + before[i][kNormalTable]);
      std::copy(c.triangles.begin(), c.triangles.end(), mesh.triangles.begin() + trianglesBefore[i]);
      const std::size_t count = c.triangles.size();
      if (texcoords) placeCornerTable(c.cornerTexcoords, count, mesh.cornerTexcoords.begin() + trianglesBefore[i]);
      if (normals) placeCornerTable(c.cornerNormals, count, mesh.cornerNormals.begin() + trianglesBefore[i]);
      release(c.positions), release(c.texcoords), release(c.normals);
      release(c.triangles), release(c.cornerTexcoords), release(c.cornerNormals);
    });
  }

  // Polygons into the places their triangles hold, now that every position is known.
  std::vector<MeshWarnings> nonSimple(n);
  parallelFor(n, threads, [&](int i) {
    ObjChunk& c = chunks[i];
    if (c.polygons.empty()) return;
    PolygonTriangulator triangulator;
    std::vector<int> vertices;
    std::vector<PolygonTriangle> triangles;
    for (const ObjPolygon& p : c.polygons) {
      const ObjCorner* corners = c.polygonCorners.data() + p.firstCorner;
      vertices.clear();
      for (std::size_t k = 0; k < p.corners; ++k) vertices.push_back(corners[k].v);
      if (!triangulator.triangulate(mesh.positions, vertices, triangles) && nonSimple[i].nonSimplePolygons++ == 0)
        nonSimple[i].firstNonSimplePolygonLine = p.line + c.lineOffset;
      std::size_t at = trianglesBefore[i] + p.firstTriangle;
      for (const PolygonTriangle& t : triangles) {
        const ObjCorner &a = corners[t[0]], &b = corners[t[1]], &d = corners[t[2]];
        mesh.triangles[at] = {a.v, b.v, d.v};
        if (p.form & kWithTexcoord) mesh.cornerTexcoords[at] = {a.vt, b.vt, d.vt};
        if (p.form & kWithNormal) mesh.cornerNormals[at] = {a.vn, b.vn, d.vn};
        ++at;
      }
    }
    release(c.polygons), release(c.polygonCorners);
  });
  for (const MeshWarnings& w : nonSimple) {
    if (warnings.nonSimplePolygons == 0) warnings.firstNonSimplePolygonLine = w.firstNonSimplePolygonLine;
    warnings.nonSimplePolygons += w.nonSimplePolygons;
  }
  ListedFaces listed;
  for (ObjChunk& c : chunks)
    for (std::size_t i = 0; i < listed.size(); ++i) {
      listed[i].insert(listed[i].end(), c.listedFaces[i].begin(), c.listedFaces[i].end());
      release(c.listedFaces[i]);
    }
  std::vector<std::size_t> marked;
  applyFaceLists(mesh, 0, mesh.triangles.size(), listed, marked);
  warnings.listedInvalidUvFaces = marked.size();
  ReadMeshResult result = withWarnings(std::move(mesh), warnings, threads);
  result.listedInvalidUvFaces = std::move(marked);
  return result;
}

// An OBJ read sequentially, every index resolved as its line is read.
ReadMeshResult readObjLines(LineReader& reader) {
  std::vector<ObjChunk> chunks(1);
  const ObjCounts none = {};
  ObjChunkReader(reader, &none, chunks[0]).read();
  return joinObjChunks(chunks, reader.name(), 1);
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

// Bytes read from a file: a vector<char> would zero each byte before the read overwrites it.
struct ReadBuffer {
  std::unique_ptr<char[]> data;
  std::size_t size = 0, capacity = 0;

  // Makes room for `count` more bytes after the first `size`.
  char* extend(std::size_t count) {
    if (size + count > capacity) {
      const std::size_t grown = std::max(size + count, 2 * capacity);
      std::unique_ptr<char[]> larger(new char[grown]);  // not value-initialised: read into
      if (size > 0) std::memcpy(larger.get(), data.get(), size);
      data = std::move(larger);
      capacity = grown;  // only once it is there: after a bad_alloc a pooled buffer keeps its true room
    }
    return data.get() + size;
  }
};

// Where the chunks of an OBJ come from: text in memory or a regular file, read piece by piece.
// Chunk i holds the lines that start in [i B, (i + 1) B) (B: the chunk size): it begins at the
// first line start at or after i B (0, or one past a '\n') and ends at the next chunk's beginning,
// so every line is in exactly one chunk, however long. The same chunks whatever the source.
class ObjSource {
 public:
  virtual ~ObjSource() = default;
  virtual std::size_t size() const = 0;
  // The lines that start in [begin, end); `buffer` holds their text when it is not in memory.
  virtual std::string_view lines(std::size_t begin, std::size_t end, ReadBuffer& buffer) const = 0;
};

class TextSource : public ObjSource {
 public:
  explicit TextSource(std::string_view text) : text_(text) {}
  std::size_t size() const override { return text_.size(); }
  std::string_view lines(std::size_t begin, std::size_t end, ReadBuffer&) const override {
    const std::size_t first = lineStart(begin), last = lineStart(end);
    return first < last ? text_.substr(first, last - first) : std::string_view();
  }

 private:
  // The first line start at or after `at`.
  std::size_t lineStart(std::size_t at) const {
    if (at == 0) return 0;
    if (at > text_.size()) return text_.size();
    const void* newline = std::memchr(text_.data() + at - 1, '\n', text_.size() - (at - 1));
    return newline ? std::size_t(static_cast<const char*>(newline) - text_.data()) + 1 : text_.size();
  }

  std::string_view text_;
};

// A regular file, each chunk read with pread() by the thread that parses it: the reading is spread
// over the threads too, and only a chunk's worth of text per thread is ever held.
class FileSource : public ObjSource {
 public:
  // Throws InputError when `path` cannot be opened.
  FileSource(const std::string& path, std::size_t size) : path_(path), size_(size) {
    errno = 0;
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0) throw inputError(path, 0, "cannot open: " + std::generic_category().message(errno));
  }
  ~FileSource() override { ::close(fd_); }
  FileSource(const FileSource&) = delete;
  FileSource& operator=(const FileSource&) = delete;

  std::size_t size() const override { return size_; }

  std::string_view lines(std::size_t begin, std::size_t end, ReadBuffer& buffer) const override {
    // From the byte before `begin` (a '\n' there starts a line at `begin`) to the first '\n' at
    // or after end - 1, which ends the last line; the file may have changed size since: its end
    // ends the last line then.
    const std::size_t from = begin == 0 ? 0 : begin - 1;
    buffer.size = 0;
    bool more = fill(buffer, from, end - from);
    const char* data = buffer.data.get();
    std::size_t first = 0;
    if (begin > 0) {
      const char* newline = static_cast<const char*>(std::memchr(data, '\n', buffer.size));
      if (!newline || from + std::size_t(newline - data) >= end - 1) return {};  // no line starts here
      first = std::size_t(newline - data) + 1;
    }
    std::size_t searched = end - 1 - from;
    for (;;) {
      data = buffer.data.get();
      if (searched < buffer.size) {
        const void* newline = std::memchr(data + searched, '\n', buffer.size - searched);
        if (newline) return {data + first, std::size_t(static_cast<const char*>(newline) - data) + 1 - first};
        searched = buffer.size;
      }
      if (!more) return {data + first, buffer.size - first};
      more = fill(buffer, from + buffer.size, std::max<std::size_t>(buffer.size - first, kFirstReadBlock));
    }
  }

 private:
  // Appends up to `count` bytes read at `offset`; false once the file has ended.
  bool fill(ReadBuffer& buffer, std::size_t offset, std::size_t count) const {
    char* out = buffer.extend(count);
    std::size_t got = 0;
    while (got < count) {
      const ssize_t n = ::pread(fd_, out + got, count - got, off_t(offset + got));
      if (n == 0) break;
      if (n < 0) {
        if (errno == EINTR) continue;
        throw inputError(path_, 0, "cannot read: input/output error");
      }
      got += std::size_t(n);
    }
    buffer.size += got;
    return got == count;
  }

  std::string path_;
  std::size_t size_;
  int fd_ = -1;
};

// Buffers handed to the threads in turn, so that each keeps reusing the memory it already has.
class BufferPool {
 public:
  ReadBuffer take() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (free_.empty()) return {};
    ReadBuffer buffer = std::move(free_.back());
    free_.pop_back();
    return buffer;
  }
  void give(ReadBuffer&& buffer) {
    const std::lock_guard<std::mutex> lock(mutex_);
    free_.push_back(std::move(buffer));
  }

 private:
  std::mutex mutex_;
  std::vector<ReadBuffer> free_;
};

ReadMeshResult readObjChunks(const ObjSource& source, const std::string& name, int threads, std::size_t chunkBytes,
                             Progress* progress) {
  chunkBytes = std::max<std::size_t>(chunkBytes, 1);
  const std::size_t total = source.size();
  const int n = static_cast<int>(std::max<std::size_t>((total + chunkBytes - 1) / chunkBytes, 1));
  const auto range = [&](int i) { return std::pair(i * chunkBytes, i + 1 == n ? total + 1 : (i + 1) * chunkBytes); };
  std::vector<ObjChunk> chunks(n);
  BufferPool buffers;
  parallelFor(n, threads, [&](int i) {
    ReadBuffer buffer = buffers.take();
    try {
      const auto [begin, end] = range(i);
      LineReader reader(source.lines(begin, end, buffer), name, 1, i == 0, progress);
      ObjChunkReader(reader, nullptr, chunks[i]).read();
    } catch (...) {
      chunks[i].error = std::current_exception();
    }
    buffers.give(std::move(buffer));
  });

  // The counts and the line before each chunk, up to the first that stopped; the chunks read again
  // with them: those that stopped, have relative indices or are out of range.
  struct Again {
    int chunk;
    ObjCounts before;
    std::size_t firstLine;
    std::exception_ptr error;
  };
  std::vector<Again> again;
  ObjCounts before = {};
  std::size_t line = 1;
  for (int i = 0; i < n; ++i) {
    if (!chunks[i].settledBy(before)) again.push_back({i, before, line, nullptr});
    if (chunks[i].error) break;
    chunks[i].lineOffset = line - 1;
    const ObjCounts own = chunks[i].counts();
    for (int t = 0; t < 3; ++t) before[t] += own[t];
    line += chunks[i].lines;
  }
  parallelFor(static_cast<int>(again.size()), threads, [&](int j) {
    Again& a = again[j];
    ObjChunk exact;
    ReadBuffer buffer = buffers.take();
    try {
      const auto [begin, end] = range(a.chunk);
      LineReader reader(source.lines(begin, end, buffer), name, a.firstLine, a.chunk == 0);
      ObjChunkReader(reader, &a.before, exact).read();
    } catch (...) {
      a.error = std::current_exception();
    }
    buffers.give(std::move(buffer));
    if (a.error) return;
    if (chunks[a.chunk].error)
      a.error = chunks[a.chunk].error;  // not an error of the text (memory): what stopped a chunk stops it again
    else
      chunks[a.chunk] = std::move(exact);
  });
  for (const Again& a : again)  // the first error in file order
    if (a.error) std::rethrow_exception(a.error);
  return joinObjChunks(chunks, name, threads);
}

}  // namespace

ReadMeshResult readObjText(std::string_view text, const std::string& name, int threads, std::size_t chunkBytes) {
  return readObjChunks(TextSource(text), name, threads, chunkBytes, nullptr);
}

ReadMeshResult readObjFile(const std::string& path, int threads, std::size_t chunkBytes) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0 || !S_ISREG(status.st_mode)) return readMesh(path, threads);
  const FileSource file(path, std::size_t(status.st_size));
  Progress progress("reading " + path, file.size(), "MB", 1'000'000);
  return readObjChunks(file, path, threads, chunkBytes, &progress);
}

ReadMeshResult readObj(std::istream& in, const std::string& name) {
  LineReader reader(in, name);
  return readObjLines(reader);
}

ReadMeshResult readOff(std::istream& in, const std::string& name) {
  LineReader reader(in, name);
  return readOffLines(reader);
}

ReadMeshResult readMesh(const std::string& path, int threads) {
  const std::optional<MeshFormat> format = meshFormatOf(path);
  if (!format) {
    const std::string extension = std::filesystem::path(path).extension().string();
    throw expectedError(path, 0, kReadableExtensions, extension.empty() ? "none" : quote(extension));
  }
  // A directory opens as a stream on Linux and only fails on reading: name the real reason.
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored))
    throw inputError(path, 0, "cannot open: " + std::generic_category().message(EISDIR));
  // A regular OBJ is read in parallel chunks; anything else as a stream, as it comes.
  struct stat status {};
  if (*format == MeshFormat::obj && ::stat(path.c_str(), &status) == 0 && S_ISREG(status.st_mode))
    return readObjFile(path, threads);
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
