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
  const backend::Functions* functions =
      openPluginFunctions<backend::Functions>(path, UVTK_IMAGE_BACKEND_ENTRY, "image plugin", backend::kVersion, error);
  return {functions, error};
}

}  // namespace

const backend::Functions* imagePlugin(std::string& error) {
  static const Loaded loaded = load();
  error = loaded.error;
  return loaded.functions;
}

}  // namespace uvtk::io
