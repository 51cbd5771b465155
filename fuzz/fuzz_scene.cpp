// libFuzzer target: the scene parser (JSON syntax, schema, names and references, input files and
// every option group), on a scene file beside a small valid mesh "mesh.obj" and texture "tex.png".
#include <fstream>

#include "core/error.h"
#include "io/image_io.h"
#include "scene/scene.h"
#include "scratch_file.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const auto& folder = uvtk::fuzz::scratchFolder();
  std::ofstream(folder / "mesh.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";
  uvtk::io::writeImage((folder / "tex.png").string(), uvtk::Image(2, 2, 3, 0.5f), uvtk::io::PixelType::UInt8);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = uvtk::fuzz::writeInput("scene.json", data, size);
  try {
    uvtk::scene::loadScene(path, (uvtk::fuzz::scratchFolder() / "out").string());
  } catch (const uvtk::InputError&) {
    // the expected way to refuse a scene
  }
  return 0;
}
