#include "io/obj_writer.h"

#include <charconv>
#include <ostream>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "core/progress.h"
#include "io/atomic_file.h"
#include "io/split_vertices.h"

namespace uvtk::io {

namespace {

// Text is assembled in one buffer and written at once: iostream formatting of millions of
// numbers is several times slower than std::to_chars.
class TextBuffer {
 public:
  void text(const char* s) { buffer_.append(s); }
  void text(const std::string& s) { buffer_.append(s); }
  void character(char c) { buffer_.push_back(c); }
  // The shortest decimal text that reads back as exactly the same double (or float).
  void number(double value, bool asFloat) {
    char digits[32];
    const std::to_chars_result r = asFloat ? std::to_chars(digits, digits + sizeof digits, static_cast<float>(value))
                                           : std::to_chars(digits, digits + sizeof digits, value);
    UVTK_CHECK(r.ec == std::errc());
    buffer_.append(digits, r.ptr);
  }
  // "KEYWORD x y z\n" in double digits.
  void vectorLine(const char* keyword, const Vec3& p) {
    text(keyword);
    for (int a = 0; a < 3; ++a) {
      if (a > 0) character(' ');
      number(p[a], false);
    }
    character('\n');
  }
  void integer(std::size_t value) {
    char digits[24];
    const std::to_chars_result r = std::to_chars(digits, digits + sizeof digits, value);
    buffer_.append(digits, r.ptr);
  }
  void flushTo(std::ostream& out) {
    out.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }
  std::size_t size() const { return buffer_.size(); }

 private:
  std::string buffer_;
};

constexpr std::size_t kFlushBytes = 1 << 20;

void writeHeader(TextBuffer& out, const std::string& header) {
  std::istringstream lines(header);
  for (std::string line; std::getline(lines, line);) {
    out.text("# ");
    out.text(line);
    out.character('\n');
  }
}

}  // namespace

void writeObj(std::ostream& stream, const Mesh& mesh, const UvMap* uvs, const ObjWriteOptions& options) {
  const std::size_t faceCount = mesh.triangles.size();
  UVTK_CHECK(!uvs || uvs->uv.size() == 3 * faceCount);
  TextBuffer out;
  // Progress over the elements written (each vertex, corner, normal and face), reported per flush.
  Progress progress("writing OBJ", mesh.positions.size() + (uvs ? 3 * faceCount : 0) + mesh.normals.size() + faceCount,
                    "elements");
  std::uint64_t unreported = 0;
  auto flushIfFull = [&] {
    ++unreported;
    if (out.size() < kFlushBytes) return;
    out.flushTo(stream);
    progress.advance(unreported);
    unreported = 0;
  };
  writeHeader(out, options.header);

  for (const Vec3& p : mesh.positions) {
    out.vectorLine("v ", p);
    flushIfFull();
  }

  // One vt per distinct (vertex, uv[, w]), numbered vertex by vertex: the split vertices of the UVs.
  // cornerTexcoord[c] is the 0-based vt index of corner c.
  std::vector<int> cornerTexcoord;
  if (uvs) {
    const bool hasW = options.writeW && !uvs->w.empty();
    SplitVertices split = splitVertices(mesh, {uvs, hasW, false});
    for (const std::size_t c : split.corner) {
      out.text("vt ");
      out.number(uvs->uv[c].x(), options.floatPrecision);
      out.character(' ');
      out.number(uvs->uv[c].y(), options.floatPrecision);
      if (options.writeW) {
        out.character(' ');
        out.number(hasW ? uvs->w[c] : 0.0, options.floatPrecision);
      }
      out.character('\n');
      flushIfFull();
    }
    unreported += 3 * faceCount - split.size();
    cornerTexcoord = std::move(split.ofCorner);
  }

  const bool normals = mesh.hasNormals();
  if (normals)
    for (const Vec3& n : mesh.normals) {
      out.vectorLine("vn ", n);
      flushIfFull();
    }

  if (uvs) {
    std::size_t invalid = 0;
    for (std::size_t f = 0; f < faceCount; ++f) invalid += uvs->faceHas(f, kFaceInvalid) ? 1 : 0;
    if (invalid > 0) {
      out.text("# ");
      out.integer(invalid);
      out.text(" faces have corners without a valid UV (written as vt 0 0); 1-based face numbers:");
      for (std::size_t f = 0; f < faceCount; ++f)
        if (uvs->faceHas(f, kFaceInvalid)) {
          out.character(' ');
          out.integer(f + 1);
        }
      out.character('\n');
    }
  }

  for (std::size_t f = 0; f < faceCount; ++f) {
    const Triangle& t = mesh.triangles[f];
    const bool faceNormals =
        normals && mesh.cornerNormals[f][0] >= 0 && mesh.cornerNormals[f][1] >= 0 && mesh.cornerNormals[f][2] >= 0;
    out.character('f');
    for (int k = 0; k < 3; ++k) {
      out.character(' ');
      out.integer(static_cast<std::size_t>(t[k]) + 1);
      if (uvs || faceNormals) out.character('/');
      if (uvs) out.integer(static_cast<std::size_t>(cornerTexcoord[3 * f + k]) + 1);
      if (faceNormals) {
        out.character('/');
        out.integer(static_cast<std::size_t>(mesh.cornerNormals[f][k]) + 1);
      }
    }
    out.character('\n');
    flushIfFull();
  }
  out.flushTo(stream);
  progress.advance(unreported);
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
