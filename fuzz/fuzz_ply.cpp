// libFuzzer target: the PLY reader, then mapping and writing what it accepts as OBJ (mesh_fuzzer.h);
// and what it accepts, written back by the PLY writer in both formats, must read back the same:
// every corner's position, UV and normal bit for bit.
#include <cstring>

#include "io/ply_reader.h"
#include "io/ply_writer.h"
#include "mesh_fuzzer.h"

namespace {

using uvtk::Mesh;
using uvtk::Vec3;

// The file's texcoords as a UvMap (they are per corner after reading).
uvtk::UvMap fileUvs(const Mesh& mesh) {
  uvtk::UvMap uvs;
  uvs.faceFlags.assign(mesh.triangles.size(), uvtk::kFaceOk);
  uvs.cornerInvalid.assign(3 * mesh.triangles.size(), uvtk::kCornerValid);
  for (std::size_t c = 0; c < 3 * mesh.triangles.size(); ++c) {
    const Vec3& t = mesh.texcoords[std::size_t(mesh.cornerTexcoords[c / 3][c % 3])];
    uvs.uv.emplace_back(t.x(), t.y());
  }
  return uvs;
}

bool sameBits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0; }

// Corner c's attribute from a per-vertex table and its corner table.
const Vec3& cornerValue(const std::vector<Vec3>& table, const std::vector<uvtk::Triangle>& corners, std::size_t c) {
  return table[std::size_t(corners[c / 3][c % 3])];
}

void roundTrip(const uvtk::io::ReadMeshResult& first, bool ascii) {
  const Mesh& mesh = first.mesh;
  const uvtk::UvMap uvs = mesh.hasTexcoords() ? fileUvs(mesh) : uvtk::UvMap();
  uvtk::io::PlyWriteOptions options;
  options.ascii = ascii;
  std::ostringstream out;
  uvtk::io::writePly(out, mesh, mesh.hasTexcoords() ? &uvs : nullptr, options);
  std::istringstream in(out.str());
  const Mesh back = uvtk::io::readPly(in, "written").mesh;  // an InputError here is a bug: it escapes
  if (back.triangles.size() != mesh.triangles.size() || back.hasTexcoords() != mesh.hasTexcoords() ||
      back.hasNormals() != mesh.hasNormals())
    std::abort();
  for (std::size_t c = 0; c < 3 * mesh.triangles.size(); ++c) {
    if (!sameBits(cornerValue(mesh.positions, mesh.triangles, c), cornerValue(back.positions, back.triangles, c)))
      std::abort();
    if (mesh.hasTexcoords()) {
      const Vec3 uv(uvs.uv[c].x(), uvs.uv[c].y(), 0.0);
      if (!sameBits(uv, cornerValue(back.texcoords, back.cornerTexcoords, c))) std::abort();
    }
    if (mesh.hasNormals() &&
        !sameBits(cornerValue(mesh.normals, mesh.cornerNormals, c), cornerValue(back.normals, back.cornerNormals, c)))
      std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  uvtk::fuzz::readMapAndWrite(&uvtk::io::readPly, data, size);
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  uvtk::io::ReadMeshResult result;
  try {
    result = uvtk::io::readPly(in, "fuzz");
  } catch (const uvtk::InputError&) {
    return 0;
  }
  roundTrip(result, false);
  roundTrip(result, true);
  return 0;
}
