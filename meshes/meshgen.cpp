// uvtk_meshgen: writes the bundled sample meshes (meshes/generators.h) into a folder.
// Usage: uvtk_meshgen [FOLDER]   (default: the current folder)
//        uvtk_meshgen --sphere SEGMENTS RINGS FILE   a lat-long sphere of any size, for large-mesh
//        measurements (3162 x 1582: 10 M triangles)
//        uvtk_meshgen --like-real FOLDER [EXT]   a torus knot, a long bone, a bumpy blob and an open
//        scanned patch, as .obj or as EXT (ply, stl, glb, gltf)
// A FILE's extension chooses its format: .obj, .ply, .stl, .glb or .gltf (io/mesh_format.h).
//        uvtk_meshgen --help
#include <cstdio>
#include <filesystem>
#include <cstdlib>
#include <exception>
#include <string>

#include <utility>

#include "io/mesh_format.h"
#include "io/mesh_writer.h"
#include "meshes/generators.h"

namespace {

// Writes `mesh` by the extension of `path`, with `header` as its comment where the format has one.
void writeGenerated(const std::string& path, const uvtk::Mesh& mesh, const std::string& header = "") {
  uvtk::io::MeshWriteOptions options;
  options.header = header;
  uvtk::io::writeMesh(path, mesh, nullptr, options);
}

const char* const kUsage =
    "usage: uvtk_meshgen [FOLDER]                        the bundled sample meshes (default: the current folder)\n"
    "       uvtk_meshgen --sphere SEGMENTS RINGS FILE    a lat-long sphere of any size (3162 1582: 10 M triangles)\n"
    "       uvtk_meshgen --like-real FOLDER [EXT]        a torus knot, a long bone, a bumpy blob, a scanned patch\n"
    "                                                    (.obj, or EXT: ply, stl, glb, gltf)\n"
    "A FILE's extension chooses its format: .obj, .ply, .stl, .glb, .gltf\n"
    "       uvtk_meshgen --help                          this text\n";

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    std::fputs(kUsage, stdout);
    return 0;
  }
  if (argc == 5 && std::string(argv[1]) == "--sphere") {
    const int segments = std::atoi(argv[2]), rings = std::atoi(argv[3]);
    if (segments < 3 || rings < 2) {
      std::fprintf(stderr, "uvtk_meshgen: --sphere: expected SEGMENTS >= 3 and RINGS >= 2\n");
      return 2;
    }
    try {
      const uvtk::Mesh mesh = uvtk::meshes::latLongSphere(segments, rings);
      writeGenerated(argv[4], mesh);
      std::fprintf(stderr, "%s: %zu vertices, %zu faces\n", argv[4], mesh.vertexCount(), mesh.faceCount());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return 4;
    }
    return 0;
  }
  if ((argc == 3 || argc == 4) && std::string(argv[1]) == "--like-real") {
    const std::string extension = argc == 4 ? std::string(".") + argv[3] : ".obj";
    if (!uvtk::io::meshFormatOf("x" + extension) || extension == ".off") {
      std::fprintf(stderr, "uvtk_meshgen: --like-real: expected EXT obj, ply, stl, glb or gltf, found '%s'\n", argv[3]);
      return 2;
    }
    // Meshes like real ones (meshes/generators.h), for trying uvtk where nobody tuned it.
    const std::pair<const char*, uvtk::Mesh> meshes[] = {{"torus_knot", uvtk::meshes::torusKnot(2, 3, 240, 16)},
                                                        {"bone", uvtk::meshes::bone(120, 32)},
                                                        {"bumpy_blob", uvtk::meshes::bumpyBlob(4)},
                                                        {"scanned_patch", uvtk::meshes::scannedPatch(4)}};
    try {
      std::error_code made;  // a folder that does not exist yet is made; the writer says what else is wrong
      std::filesystem::create_directories(argv[2], made);
      for (const auto& [stem, mesh] : meshes) {
        const std::string file = std::string(argv[2]) + "/" + stem + extension;
        writeGenerated(file, mesh);
        std::fprintf(stderr, "%s: %zu vertices, %zu faces\n", file.c_str(), mesh.vertexCount(), mesh.faceCount());
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return 4;
    }
    return 0;
  }
  // A folder named like an option is a mistyped option (a folder "-x" is still "./-x").
  const std::string first = argc > 1 ? argv[1] : "";
  if (argc > 1 && first[0] == '-' && first != "--sphere" && first != "--like-real") {
    std::fprintf(stderr, "uvtk_meshgen: error: unknown option '%s' (uvtk_meshgen --help lists them)\n", argv[1]);
    return 2;
  }
  if (argc > 2 || first[0] == '-') {
    std::fputs("uvtk_meshgen: error: expected [FOLDER] | --sphere SEGMENTS RINGS FILE | --like-real FOLDER\n", stderr);
    return 2;
  }
  const std::string folder = argc == 2 ? argv[1] : ".";
  try {
    std::error_code made;
    std::filesystem::create_directories(folder, made);
    for (const uvtk::meshes::BundledMesh& m : uvtk::meshes::bundledMeshes()) {
      writeGenerated(folder + "/" + m.file, m.mesh, m.header());
      std::fprintf(stderr, "%s/%s: %zu vertices, %zu faces\n", folder.c_str(), m.file, m.mesh.vertexCount(),
                   m.mesh.faceCount());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 4;
  }
  return 0;
}
