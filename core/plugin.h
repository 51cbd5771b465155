// Plugins: shared modules a program opens on first use, so that a process that never needs what
// they hold (OpenImageIO, assimp) never loads it and never pays its start-up.
#pragma once

#include <string>

namespace uvtk {

// Where a plugin is looked for, in order: $`variable` when set; `installed` (relative to the folder of
// the executable or shared object this code is linked into: an installed prefix's
// ../lib/uvtk/NAME); `built`, the build tree's, for a program of the build tree `buildDir` with no
// install beside it. Any other program gets the installed path, which its error then names.
std::string pluginPath(const char* variable, const std::string& installed, const std::string& built,
                       const std::string& buildDir);

// dlopen of `path` (never closed, symbols local) and the address of its `entry`; null with `error`
// set to one line naming `what`, the path and why it failed.
void* openPluginEntry(const std::string& path, const char* entry, const std::string& what, std::string& error);

// The table of functions a plugin's `entry` returns (a struct whose first member is `int version`),
// when it is of `version`; null with `error` set to one line naming `what` and the path otherwise.
template <class Functions>
const Functions* openPluginFunctions(const std::string& path, const char* entry, const std::string& what, int version,
                                     std::string& error) {
  using Entry = const Functions* (*)();
  const auto open = reinterpret_cast<Entry>(openPluginEntry(path, entry, what, error));
  if (!open) return nullptr;
  const Functions* functions = open();
  if (functions->version == version) return functions;
  error = "cannot load the " + what + ": " + path + " is version " + std::to_string(functions->version) +
          ", this program needs version " + std::to_string(version);
  return nullptr;
}

// A system library opened by its soname when first needed rather than linked (never closed,
// symbols local), and its functions bound one by one: error() stays empty while every one is found,
// else holds the first failure (dlerror's words, or "SONAME has no NAME"); a function not found is null.
class OpenedLibrary {
 public:
  explicit OpenedLibrary(const char* soname);

  template <class Function>
  void bind(Function& function, const char* name) {
    function = reinterpret_cast<Function>(symbol(name));
  }
  const std::string& error() const { return error_; }

 private:
  void* symbol(const char* name);

  std::string soname_;
  void* handle_;
  std::string error_;
};

}  // namespace uvtk
