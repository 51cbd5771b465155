#include "io/image_plugin.h"

#include <dlfcn.h>
#include <link.h>
#include <unistd.h>

#include <climits>
#include <cstdlib>

namespace uvtk::io {

namespace {

struct Loaded {
  const backend::Functions* functions = nullptr;
  std::string error;
};

// The folder of the executable or shared object holding this code, symlinks resolved; empty if
// unknown. The main program's link-map name is empty (dladdr would give argv[0]): /proc/self/exe.
std::string ownFolder() {
  Dl_info info{};
  link_map* map = nullptr;
  if (!dladdr1(reinterpret_cast<void*>(&ownFolder), &info, reinterpret_cast<void**>(&map), RTLD_DL_LINKMAP))
    return "";
  const char* file = map && map->l_name && map->l_name[0] != '\0' ? map->l_name : "/proc/self/exe";
  char resolved[PATH_MAX];
  if (!::realpath(file, resolved)) return "";
  const std::string path = resolved;
  return path.substr(0, path.rfind('/'));
}

std::string pluginPath() {
  if (const char* chosen = std::getenv("UVTK_IMAGE_PLUGIN"); chosen && *chosen) return chosen;
  const std::string folder = ownFolder();
  const std::string installed = folder + "/" UVTK_IMAGE_PLUGIN_INSTALLED;
  if (::access(installed.c_str(), F_OK) == 0) return installed;
  // A program of the build tree (without an install beside it) takes the build tree's plugin; any
  // other names the installed path in its error.
  char buildTree[PATH_MAX];
  const bool inBuildTree = ::realpath(UVTK_BUILD_DIR, buildTree) && (folder + "/").rfind(buildTree + std::string("/"), 0) == 0;
  return inBuildTree ? UVTK_IMAGE_PLUGIN_BUILT : installed;
}

Loaded load() {
  const std::string path = pluginPath();
  // Never closed: OpenImageIO keeps threads and caches to the end of the process.
  void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) return {nullptr, std::string("cannot load the image plugin: ") + ::dlerror()};
  using Entry = const backend::Functions* (*)();
  const auto entry = reinterpret_cast<Entry>(::dlsym(handle, UVTK_IMAGE_BACKEND_ENTRY));
  if (!entry) return {nullptr, "cannot load the image plugin: " + path + " has no " UVTK_IMAGE_BACKEND_ENTRY};
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
