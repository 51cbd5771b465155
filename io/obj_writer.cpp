// OBJ text is made in blocks of lines on every thread (io/ordered_text.h): each block formats its
// numbers (io/shortest_number.h, std::to_chars) straight into its own buffer, and the blocks are written in order,
// about a megabyte per write. iostream formatting of millions of numbers is several times slower.
#include "io/obj_writer.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <ostream>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "core/progress.h"
#include "io/atomic_file.h"
#include "io/face_lists.h"
#include "io/ordered_text.h"
#include "io/shortest_number.h"
#include "io/split_vertices.h"

namespace uvtk::io {

namespace {

// Lines per block: about half a megabyte of text, so a block is written in one call and the
// threads take turns often enough to finish together.
constexpr std::size_t kLinesPerBlock = std::size_t{1} << 13;
// The longest line a block writes but the header's: `f` with three corners v/vt/vn of ten digits
// each, or `vt` with three numbers of at most 24 characters.
constexpr std::size_t kMaxLineBytes = 128;
constexpr Triangle kNoCorners = {-1, -1, -1};

// The shortest decimal text that reads back as exactly the same double (or float).
char* number(char* out, double value, bool asFloat) {
  if (!asFloat) return writeShortest(out, value);
  const std::to_chars_result r = std::to_chars(out, out + 32, static_cast<float>(value));
  UVTK_CHECK(r.ec == std::errc());
  return r.ptr;
}

char* integer(char* out, std::size_t value) { return std::to_chars(out, out + 24, value).ptr; }
// A 1-based index of a table of int indices: 32-bit arithmetic formats it faster.
char* index(char* out, int zeroBased) { return std::to_chars(out, out + 12, static_cast<std::uint32_t>(zeroBased) + 1).ptr; }

// "KEYWORD x y z\n" in double digits.
char* vectorLine(char* out, const char* keyword, const Vec3& p) {
  while (*keyword) *out++ = *keyword++;
  for (int a = 0; a < 3; ++a) {
    if (a > 0) *out++ = ' ';
    out = writeShortest(out, p[a]);
  }
  *out++ = '\n';
  return out;
}

std::string headerText(const std::string& header) {
  std::string text;
  std::istringstream lines(header);
  for (std::string line; std::getline(lines, line);) text += "# " + line + "\n";
  return text;
}

}  // namespace

void writeObj(std::ostream& stream, const Mesh& mesh, const UvMap* uvs, const ObjWriteOptions& options) {
  const std::size_t faceCount = mesh.triangles.size();
  UVTK_CHECK(!uvs || uvs->uv.size() == 3 * faceCount);
  // Progress over the elements written (each vertex, corner, normal and face), reported per block.
  Progress progress("writing OBJ", mesh.positions.size() + (uvs ? 3 * faceCount : 0) + mesh.normals.size() + faceCount,
                    "elements");
  OrderedText out(stream, options.threads);
  // `count` lines, line i written at p by line(i, p), which returns its end (at most kMaxLineBytes
  // on), in blocks on every thread. A block's room is taken once: the text is written through a
  // char pointer, which may alias anything, so the lambdas read the mesh through local pointers.
  const auto lines = [&](std::size_t count, auto line) {
    out.blocks((count + kLinesPerBlock - 1) / kLinesPerBlock, [&](std::size_t block, TextBlock& text) {
      const std::size_t begin = block * kLinesPerBlock, end = std::min(count, begin + kLinesPerBlock);
      char* p = text.room((end - begin) * kMaxLineBytes);
      for (std::size_t i = begin; i < end; ++i) p = line(i, p);
      text.commit(p);
      progress.advance(end - begin);
    });
  };
  out.text(headerText(options.header));

  const Vec3* positions = mesh.positions.data();
  lines(mesh.positions.size(), [positions](std::size_t v, char* p) { return vectorLine(p, "v ", positions[v]); });

  // One vt per distinct (vertex, uv[, w]), numbered vertex by vertex: the split vertices of the UVs.
  // cornerTexcoord[c] is the 0-based vt index of corner c.
  std::vector<int> cornerTexcoord;
  if (uvs) {
    const bool hasW = options.writeW && !uvs->w.empty();
    SplitVertices split = splitVertices(mesh, {uvs, hasW, false}, options.threads);
    const std::size_t* corners = split.corner.data();
    const UvMap* map = uvs;
    const double* w = hasW ? uvs->w.data() : nullptr;
    const bool asFloat = options.floatPrecision, writeW = options.writeW;
    lines(split.size(), [=](std::size_t i, char* p) {
      const std::size_t c = corners[i];
      const Vec2 uv = map->writtenUv(c);
      *p++ = 'v', *p++ = 't', *p++ = ' ';
      p = number(p, uv.x(), asFloat);
      *p++ = ' ';
      p = number(p, uv.y(), asFloat);
      if (writeW) {
        *p++ = ' ';
        p = number(p, w ? w[c] : 0.0, asFloat);
      }
      *p++ = '\n';
      return p;
    });
    progress.advance(3 * faceCount - split.size());
    cornerTexcoord = std::move(split.ofCorner);
  }

  const bool normals = mesh.hasNormals();
  const Vec3* normalValues = mesh.normals.data();
  if (normals) lines(mesh.normals.size(), [normalValues](std::size_t n, char* p) { return vectorLine(p, "vn ", normalValues[n]); });

  // uvtk's lists of faces (io/face_lists.h): the first block's numbers on the line that counts
  // them, every later block's on a line of its own, so that no line is long.
  static_assert(kLinesPerBlock <= kFacesPerLine);
  for (const FaceList& list : kFaceLists) {
    if (!uvs) break;
    const auto has = [&](std::uint8_t flags) { return (flags & list.flag) != 0; };
    const auto first = std::find_if(uvs->faceFlags.begin(), uvs->faceFlags.end(), has);
    if (first == uvs->faceFlags.end()) continue;
    out.text("# " + std::to_string(std::count_if(first, uvs->faceFlags.end(), has)) + std::string(list.objFirst));
    const std::size_t firstBlock = std::size_t(first - uvs->faceFlags.begin()) / kLinesPerBlock;
    out.blocks((faceCount + kLinesPerBlock - 1) / kLinesPerBlock, [&](std::size_t block, TextBlock& text) {
      bool started = block == firstBlock;
      for (std::size_t f = block * kLinesPerBlock, end = std::min(faceCount, f + kLinesPerBlock); f < end; ++f)
        if (uvs->faceHas(f, list.flag)) {
          char* p = text.room(kMaxLineBytes);
          if (!started) {
            *p++ = '\n';
            p = std::copy(list.objMore.begin(), list.objMore.end(), p);
            started = true;
          }
          *p++ = ' ';
          text.commit(integer(p, f + 1));
        }
    });
    out.text("\n");
  }

  const Triangle* triangles = mesh.triangles.data();
  const Triangle* cornerNormals = normals ? mesh.cornerNormals.data() : nullptr;
  const int* texcoords = uvs ? cornerTexcoord.data() : nullptr;
  lines(faceCount, [=](std::size_t f, char* p) {
    const Triangle t = triangles[f];
    const Triangle n = cornerNormals ? cornerNormals[f] : kNoCorners;
    const bool faceNormals = n[0] >= 0 && n[1] >= 0 && n[2] >= 0;
    *p++ = 'f';
    for (int k = 0; k < 3; ++k) {
      *p++ = ' ';
      p = index(p, t[k]);
      if (texcoords || faceNormals) *p++ = '/';
      if (texcoords) p = index(p, texcoords[3 * f + k]);
      if (faceNormals) {
        *p++ = '/';
        p = index(p, n[k]);
      }
    }
    *p++ = '\n';
    return p;
  });
}

void writeObj(const std::string& path, const Mesh& mesh, const UvMap* uvs, const ObjWriteOptions& options) {
  AtomicFile file(path);
  writeObj(file.stream(), mesh, uvs, options);
  file.commit();
}

void writeObj(OutputSet& outputs, const std::string& path, const Mesh& mesh, const UvMap* uvs,
              const ObjWriteOptions& options) {
  outputs.write(path, [&](std::ostream& out) { writeObj(out, mesh, uvs, options); });
}

}  // namespace uvtk::io
