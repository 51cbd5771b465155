// libFuzzer target: a scene's output paths. The first byte chooses: bit 0 --allow-outside, bit 1
// whether the rest goes to checkOutputPath directly or, as the "json" value of an OBJ output, through
// loadScene. Whatever is accepted without --allow-outside must lie in the output folder (component by
// component, after lexical normalisation) and be a name a file system can hold: no NUL, no component
// longer than 255 bytes. Any exception but InputError is a crash.
#include <climits>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "scene/scene.h"
#include "scratch_file.h"

namespace {

namespace fs = std::filesystem;

const fs::path& outputDir() {
  static const fs::path folder = uvtk::fuzz::scratchFolder() / "out";
  return folder;
}

void require(bool condition) {
  if (!condition) std::abort();
}

// The invariant of an accepted output file.
void checkAccepted(const std::string& file, bool allowOutside) {
  require(file.find('\0') == std::string::npos);
  const fs::path path(file);
  require(path == path.lexically_normal());
  if (allowOutside) return;
  const fs::path relative = path.lexically_relative(outputDir());
  require(!relative.empty() && *relative.begin() != ".." && relative != ".");
  for (const fs::path& component : relative) require(component.native().size() <= NAME_MAX);
  auto [folderEnd, fileAt] = std::mismatch(outputDir().begin(), outputDir().end(), path.begin(), path.end());
  require(folderEnd == outputDir().end() && fileAt != path.end());
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::ofstream(uvtk::fuzz::scratchFolder() / "mesh.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  fs::create_directories(outputDir());
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool allowOutside = data[0] & 1, throughScene = data[0] & 2;
  const std::string value(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    if (!throughScene) {
      checkAccepted(uvtk::scene::checkOutputPath(value, outputDir(), allowOutside), allowOutside);
      return 0;
    }
    const nlohmann::json scene = {
        {"meshes", {{{"name", "m"}, {"path", "mesh.obj"}, {"mappings", {{{"kind", "file"}, {"name", "f"}}}}}}},
        {"outputs", {{{"kind", "obj"}, {"mapping", "f"}, {"path", "m.obj"}, {"json", value}}}}};
    // Invalid UTF-8 is replaced, as a scene file cannot hold it.
    const std::string text = scene.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    const std::string path = uvtk::fuzz::writeInput("scene.json", reinterpret_cast<const std::uint8_t*>(text.data()),
                                                    text.size());
    const uvtk::scene::Scene loaded = uvtk::scene::loadScene(path, outputDir().string(), allowOutside);
    for (const std::string& file : loaded.outputs.at(0).files()) checkAccepted(file, allowOutside);
  } catch (const uvtk::InputError&) {
    // the expected way to refuse a path
  }
  return 0;
}
