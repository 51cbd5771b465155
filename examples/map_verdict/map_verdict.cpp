// map_verdict: map the mesh named by argv[1] (with the options of argv[2], in `uvtk map`'s syntax)
// and print the verdict. Exit 0 pass, 1 warn or fail, 2 bad options, 3 an unreadable mesh.
// cmake: find_package(uvtk 0.1 REQUIRED) + target_link_libraries(map_verdict PRIVATE uvtk::uvtk)
// or:    c++ map_verdict.cpp $(pkg-config --cflags --libs uvtk) -o map_verdict
#include <cstdio>
#include <stdexcept>
#include <uvtk/uvtk.h>

int main(int argc, char** argv) {
  if (argc < 2) return std::fprintf(stderr, "usage: map_verdict MESH [OPTIONS]\n"), 2;
  try {
    const uvtk::api::Mesh mesh = uvtk::api::readMesh(argv[1]);
    uvtk::api::MapOptions options;  // the fields and defaults of `uvtk map`
    options.projector = "sphere";
    options.fit = "bbox";
    if (argc > 2) options = uvtk::api::MapOptions::parse(argv[2]);  // e.g. "--projector cube"
    const uvtk::api::Mapping mapping = uvtk::api::map(mesh, options);
    std::printf("%s: %zu faces, verdict %s\n", argv[1], mapping.mesh.triangles.size(), mapping.verdict.status.c_str());
    for (const uvtk::api::Reason& reason : mapping.verdict.reasons)
      std::printf("  %s: %s\n", reason.severity.c_str(), reason.text.c_str());
    return mapping.verdict.status == "pass" ? 0 : 1;
  } catch (const std::invalid_argument& error) {  // bad options: the command line's message
    return std::fprintf(stderr, "%s\n", error.what()), 2;
  } catch (const uvtk::api::InputError& error) {  // "PATH:LINE: error: ..."
    return std::fprintf(stderr, "%s\n", error.what()), 3;
  }
}
