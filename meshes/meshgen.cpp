// uvtk_meshgen: writes the bundled sample meshes (meshes/generators.h) into a folder.
// Usage: uvtk_meshgen [FOLDER]   (default: the current folder)
#include <cstdio>
#include <exception>
#include <string>

#include "io/obj_writer.h"
#include "meshes/generators.h"

int main(int argc, char** argv) {
  if (argc > 2) {
    std::fprintf(stderr, "usage: uvtk_meshgen [FOLDER]\n");
    return 2;
  }
  const std::string folder = argc == 2 ? argv[1] : ".";
  try {
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
