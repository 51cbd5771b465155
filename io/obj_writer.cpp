#include "io/obj_writer.h"

#include <charconv>
#include <cstring>
#include <ostream>
#include <sstream>
#include <unordered_map>

#include "core/error.h"
#include "io/atomic_file.h"

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

// A `vt` entry is shared by the corners of one vertex that have the same UV; bitwise equality,
// so that -0 and +0 or two NaN payloads never merge silently.
struct TexcoordKey {
  int vertex;
  std::uint64_t u, v, w;
  bool operator==(const TexcoordKey& o) const { return vertex == o.vertex && u == o.u && v == o.v && w == o.w; }
};

struct TexcoordKeyHash {
  std::size_t operator()(const TexcoordKey& k) const {
    std::uint64_t h = static_cast<std::uint64_t>(k.vertex) * 0x9E3779B97F4A7C15ull;
    for (std::uint64_t x : {k.u, k.v, k.w}) h = (h ^ x) * 0xBF58476D1CE4E5B9ull + (h >> 29);
    return static_cast<std::size_t>(h);
  }
};

std::uint64_t bitsOf(double value) {
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

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
  auto flushIfFull = [&] {
    if (out.size() >= kFlushBytes) out.flushTo(stream);
  };
  writeHeader(out, options.header);

  for (const Vec3& p : mesh.positions) {
    out.text("v ");
    out.number(p.x(), false);
    out.character(' ');
    out.number(p.y(), false);
    out.character(' ');
    out.number(p.z(), false);
    out.character('\n');
    flushIfFull();
  }

  // One vt per distinct (vertex, uv); cornerTexcoord[c] is its 1-based index.
  std::vector<std::size_t> cornerTexcoord;
  if (uvs) {
    const bool hasW = !uvs->w.empty();
    cornerTexcoord.resize(3 * faceCount);
    std::unordered_map<TexcoordKey, std::size_t, TexcoordKeyHash> index;
    index.reserve(mesh.positions.size() + mesh.positions.size() / 8);
    for (std::size_t c = 0; c < 3 * faceCount; ++c) {
      const Vec2& uv = uvs->uv[c];
      const double w = options.writeW && hasW ? uvs->w[c] : 0.0;
      const TexcoordKey key{mesh.triangles[c / 3][c % 3], bitsOf(uv.x()), bitsOf(uv.y()), bitsOf(w)};
      const auto [it, inserted] = index.emplace(key, index.size() + 1);
      cornerTexcoord[c] = it->second;
      if (!inserted) continue;
      out.text("vt ");
      out.number(uv.x(), options.floatPrecision);
      out.character(' ');
      out.number(uv.y(), options.floatPrecision);
      if (options.writeW) {
        out.character(' ');
        out.number(w, options.floatPrecision);
      }
      out.character('\n');
      flushIfFull();
    }
  }

  const bool normals = options.writeNormals && mesh.hasNormals();
  if (normals)
    for (const Vec3& n : mesh.normals) {
      out.text("vn ");
      out.number(n.x(), false);
      out.character(' ');
      out.number(n.y(), false);
      out.character(' ');
      out.number(n.z(), false);
      out.character('\n');
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
      if (uvs) out.integer(cornerTexcoord[3 * f + k]);
      if (faceNormals) {
        out.character('/');
        out.integer(static_cast<std::size_t>(mesh.cornerNormals[f][k]) + 1);
      }
    }
    out.character('\n');
    flushIfFull();
  }
  out.flushTo(stream);
}

void writeObj(const std::string& path, const Mesh& mesh, const UvMap* uvs, const ObjWriteOptions& options) {
  AtomicFile file(path);
  writeObj(file.stream(), mesh, uvs, options);
  file.commit();
}

}  // namespace uvtk::io
