#include "core/plugin.h"

#include <dlfcn.h>
#include <link.h>
#include <unistd.h>

#include <climits>
#include <cstdlib>

namespace uvtk {

namespace {

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

}  // namespace

std::string pluginPath(const char* variable, const std::string& installed, const std::string& built,
                       const std::string& buildDir) {
  if (const char* chosen = std::getenv(variable); chosen && *chosen) return chosen;
  const std::string folder = ownFolder();
  const std::string installedPath = folder + "/" + installed;
  if (::access(installedPath.c_str(), F_OK) == 0) return installedPath;
  char buildTree[PATH_MAX];
  const bool inBuildTree =
      ::realpath(buildDir.c_str(), buildTree) && (folder + "/").rfind(buildTree + std::string("/"), 0) == 0;
  return inBuildTree ? built : installedPath;
}

void* openPluginEntry(const std::string& path, const char* entry, const std::string& what, std::string& error) {
  // Never closed: a plugin's library may keep threads and caches to the end of the process.
  void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    error = "cannot load the " + what + ": " + ::dlerror();
    return nullptr;
  }
  void* address = ::dlsym(handle, entry);
  if (!address) error = "cannot load the " + what + ": " + path + " has no " + entry;
  return address;
}

OpenedLibrary::OpenedLibrary(const char* soname)
    : soname_(soname), handle_(::dlopen(soname, RTLD_NOW | RTLD_LOCAL)) {
  if (!handle_) error_ = ::dlerror();
}

void* OpenedLibrary::symbol(const char* name) {
  void* address = handle_ ? ::dlsym(handle_, name) : nullptr;
  if (!address && error_.empty()) error_ = soname_ + " has no " + name;
  return address;
}

}  // namespace uvtk
