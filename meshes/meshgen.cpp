// uvtk_meshgen: writes the bundled sample meshes (meshes/generators.h) into a folder.
// Usage: uvtk_meshgen [FOLDER]   (default: the current folder)
//        uvtk_meshgen --sphere SEGMENTS RINGS FILE   a lat-long sphere of any size, for large-mesh
//        measurements (3162 x 1582: 10 M triangles)
//        uvtk_meshgen --like-real FOLDER   a torus knot, a long bone, a bumpy blob and an open scanned patch
//        uvtk_meshgen --help
#include <cstdio>
#include <filesystem>
#include <cstdlib>
#include <exception>
#include <string>

#include <utility>

#include "io/obj_writer.h"
#include "meshes/generators.h"

namespace {

const char* const kUsage =
    "usage: uvtk_meshgen [FOLDER]                        the bundled sample meshes (default: the current folder)\n"
    "       uvtk_meshgen --sphere SEGMENTS RINGS FILE    a lat-long sphere of any size (3162 1582: 10 M triangles)\n"
    "       uvtk_meshgen --like-real FOLDER              a torus knot, a long bone, a bumpy blob, a scanned patch\n"
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
      uvtk::io::writeObj(argv[4], mesh, nullptr);
      std::fprintf(stderr, "%s: %zu vertices, %zu faces\n", argv[4], mesh.vertexCount(), mesh.faceCount());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return 4;
    }
    return 0;
  }
  if (argc == 3 && std::string(argv[1]) == "--like-real") {
    // Meshes like real ones (meshes/generators.h), for trying uvtk where nobody tuned it.
    const std::pair<const char*, uvtk::Mesh> meshes[] = {{"torus_knot.obj", uvtk::meshes::torusKnot(2, 3, 240, 16)},
                                                        {"bone.obj", uvtk::meshes::bone(120, 32)},
                                                        {"bumpy_blob.obj", uvtk::meshes::bumpyBlob(4)},
                                                        {"scanned_patch.obj", uvtk::meshes::scannedPatch(4)}};
    try {
      std::error_code made;  // a folder that does not exist yet is made; writeObj says what else is wrong
      std::filesystem::create_directories(argv[2], made);
      for (const auto& [file, mesh] : meshes) {
        uvtk::io::writeObj(std::string(argv[2]) + "/" + file, mesh, nullptr);
        std::fprintf(stderr, "%s/%s: %zu vertices, %zu faces\n", argv[2], file, mesh.vertexCount(), mesh.faceCount());
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
      uvtk::io::ObjWriteOptions options;
      options.header = m.header();
      uvtk::io::writeObj(folder + "/" + m.file, m.mesh, nullptr, options);
      std::fprintf(stderr, "%s/%s: %zu vertices, %zu faces\n", folder.c_str(), m.file, m.mesh.vertexCount(),
                   m.mesh.faceCount());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 4;
  }
  return 0;
}
