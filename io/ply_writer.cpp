// PLY output: one vertex per distinct (vertex, UV, normal) of the corners (io/split_vertices.h),
// doubles throughout so that positions and UVs read back bit for bit; binary little endian by
// default, whatever the host, or ASCII in the shortest text that round-trips each double.
#include "io/ply_writer.h"

#include <charconv>
#include <cstring>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/progress.h"
#include "io/face_lists.h"
#include "io/shortest_number.h"
#include "io/split_vertices.h"

namespace uvtk::io {
namespace {

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
constexpr bool kHostLittleEndian = false;
#else
constexpr bool kHostLittleEndian = true;
#endif

constexpr std::size_t kFlushBytes = std::size_t{1} << 20;

// The file assembled in one buffer and written a megabyte at a time.
class Buffer {
 public:
  void text(std::string_view s) { buffer_.append(s); }
  void character(char c) { buffer_.push_back(c); }
  // The shortest decimal text that reads back as exactly the same double.
  void number(double value) {
    char digits[kShortestNumberBytes];
    buffer_.append(digits, writeShortest(digits, value));
  }
  void integer(std::size_t value) {
    char digits[24];
    const std::to_chars_result r = std::to_chars(digits, digits + sizeof digits, value);
    buffer_.append(digits, r.ptr);
  }
  // The value's bytes, least significant first.
  template <typename T>
  void binary(T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if (!kHostLittleEndian)
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
    buffer_.append(bytes, sizeof(T));
  }
  // Writes the buffer out once it holds a megabyte; true if it did.
  bool flushIfFull(std::ostream& out) {
    if (buffer_.size() < kFlushBytes) return false;
    flush(out);
    return true;
  }
  void flush(std::ostream& out) {
    out.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

 private:
  std::string buffer_;
};

void writeHeader(Buffer& out, const Mesh& mesh, const UvMap* uvs, const PlyWriteOptions& options, std::size_t vertices) {
  out.text("ply\n");
  out.text(options.ascii ? "format ascii 1.0\n" : "format binary_little_endian 1.0\n");
  std::istringstream lines(options.header);
  for (std::string line; std::getline(lines, line);) {
    out.text("comment ");
    out.text(line);
    out.character('\n');
  }
  const std::size_t faceCount = mesh.triangles.size();
  for (const FaceList& list : kFaceLists) {
    const std::vector<std::size_t> listed = facesWith(uvs, list.flag);
    if (listed.empty()) continue;
    out.text("comment uvtk: ");
    out.integer(listed.size());
    out.text(list.plyFirst);
    // Continued on further lines, so that no header line grows past what a reader holds at once.
    for (std::size_t i = 0; i < listed.size(); ++i) {
      if (i > 0 && i % kFacesPerLine == 0) {
        out.character('\n');
        out.text(list.plyMore);
      }
      out.character(' ');
      out.integer(listed[i]);
    }
    out.character('\n');
  }
  out.text("element vertex ");
  out.integer(vertices);
  out.text("\nproperty double x\nproperty double y\nproperty double z\n");
  if (mesh.hasNormals() || options.vertexNormals) out.text("property double nx\nproperty double ny\nproperty double nz\n");
  if (uvs) out.text("property double s\nproperty double t\n");
  out.text("element face ");
  out.integer(faceCount);
  out.text("\nproperty list uchar int vertex_indices\nend_header\n");
}

}  // namespace

void writePly(std::ostream& stream, const Mesh& mesh, const UvMap* uvs, const PlyWriteOptions& options) {
  const std::size_t faceCount = mesh.triangles.size();
  UVTK_CHECK(!uvs || uvs->uv.size() == 3 * faceCount);
  const SplitVertices split = splitVertices(mesh, {uvs, false, true});
  Buffer out;
  writeHeader(out, mesh, uvs, options, split.size());
  // Progress over the vertices and faces written, reported per flush.
  Progress progress("writing PLY", split.size() + faceCount, "elements");
  std::uint64_t unreported = 0;
  const auto written = [&] {
    ++unreported;
    if (!out.flushIfFull(stream)) return;
    progress.advance(unreported);
    unreported = 0;
  };

  UVTK_CHECK(!options.vertexNormals || options.vertexNormals->size() == mesh.positions.size());
  // A corner without a normal of its own gets the area-weighted vertex normal, as a mapping reads
  // it (core/mesh.h cornerNormals); the others keep theirs as given, bit for bit.
  const std::vector<Vec3> vertexNormals = mesh.hasNormals() ? areaWeightedVertexNormals(mesh) : std::vector<Vec3>();
  const bool normals = mesh.hasNormals() || options.vertexNormals;
  for (std::size_t i = 0; i < split.size(); ++i) {
    const std::size_t c = split.corner[i];
    double values[8];
    int count = 0;
    const Vec3& p = mesh.positions[std::size_t(split.vertex[i])];
    for (int a = 0; a < 3; ++a) values[count++] = p[a];
    if (normals) {
      const std::size_t v = std::size_t(split.vertex[i]);
      const int own = mesh.hasNormals() ? mesh.cornerNormals[c / 3][c % 3] : -1;
      const Vec3& n = own >= 0             ? mesh.normals[std::size_t(own)]
                      : mesh.hasNormals() ? vertexNormals[v]
                                          : (*options.vertexNormals)[v];
      for (int a = 0; a < 3; ++a) values[count++] = n[a];
    }
    if (uvs) {
      const Vec2 uv = uvs->writtenUv(c);
      values[count++] = uv.x();
      values[count++] = uv.y();
    }
    for (int k = 0; k < count; ++k) {
      if (!options.ascii) {
        out.binary(values[k]);
        continue;
      }
      if (k > 0) out.character(' ');
      out.number(values[k]);
    }
    if (options.ascii) out.character('\n');
    written();
  }
  for (std::size_t f = 0; f < faceCount; ++f) {
    const int* corners = &split.ofCorner[3 * f];
    if (options.ascii) {
      out.character('3');
      for (int k = 0; k < 3; ++k) {
        out.character(' ');
        out.integer(static_cast<std::size_t>(corners[k]));
      }
      out.character('\n');
    } else {
      out.binary(std::uint8_t{3});
      for (int k = 0; k < 3; ++k) out.binary(std::int32_t{corners[k]});
    }
    written();
  }
  out.flush(stream);
  progress.advance(unreported);
}

}  // namespace uvtk::io
