#include "io/image_plugin.h"

#include "core/plugin.h"

namespace uvtk::io {

namespace {

struct Loaded {
  const backend::Functions* functions = nullptr;
  std::string error;
};

Loaded load() {
  const std::string path =
      pluginPath("UVTK_IMAGE_PLUGIN", UVTK_IMAGE_PLUGIN_INSTALLED, UVTK_IMAGE_PLUGIN_BUILT, UVTK_BUILD_DIR);
  std::string error;
  using Entry = const backend::Functions* (*)();
  const auto entry = reinterpret_cast<Entry>(openPluginEntry(path, UVTK_IMAGE_BACKEND_ENTRY, "image plugin", error));
  if (!entry) return {nullptr, error};
  const backend::Functions* functions = entry();
  if (functions->version != backend::kVersion)
    return {nullptr, "cannot load the image plugin: " + path + " is version " + std::to_string(functions->version) +
                         ", this program needs version " + std::to_string(backend::kVersion)};
  return {functions, ""};
}

}  // namespace

const backend::Functions* imagePlugin(std::string& error) {
  static const Loaded loaded = load();
  error = loaded.error;
  return loaded.functions;
}

}  // namespace uvtk::io
