// libFuzzer target: the glTF reader (a GLB when the bytes start with "glTF"; no folder, so no
// external file is read), then mapping and writing what it accepts as OBJ (mesh_fuzzer.h); and
// what it accepts, written as a GLB, must read back with the same triangles.
#include <cstdlib>
#include <iterator>
#include <sstream>

#include "io/gltf_reader.h"
#include "io/gltf_writer.h"
#include "mesh_fuzzer.h"

namespace {

uvtk::io::ReadMeshResult readGltfBytes(std::istream& in, const std::string& name) {
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return uvtk::io::readGltf(bytes, name, "", bytes.rfind("glTF", 0) == 0);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  uvtk::fuzz::readMapAndWrite(&readGltfBytes, data, size);
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  uvtk::io::ReadMeshResult result;
  try {
    result = uvtk::io::readGltf(bytes, "fuzz", "", bytes.rfind("glTF", 0) == 0);
  } catch (const uvtk::InputError&) {
    return 0;
  }
  std::ostringstream glb;
  try {
    uvtk::io::writeGlb(glb, result.mesh, nullptr);
  } catch (const uvtk::OutputError&) {
    return 0;  // the transforms took a position beyond the doubles
  }
  // Any exception here escapes: the writer wrote what its reader refuses.
  const uvtk::io::ReadMeshResult back = uvtk::io::readGltf(glb.str(), "fuzz.glb", "", true);
  if (back.mesh.triangles.size() != result.mesh.triangles.size()) std::abort();
  return 0;
}
