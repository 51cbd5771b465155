// Runs the `uvtk` program as a user does, in a scratch folder: exit status and stderr.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "scratch_dir.h"

namespace uvtk {

// Whether this build runs under AddressSanitizer, which reserves terabytes of address space: a
// child under `ulimit -v` cannot start there.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitized = true;
#else
constexpr bool kAddressSanitized = false;
#endif
#else
constexpr bool kAddressSanitized = false;
#endif

// The bundled meshes (meshes/), shared by the CLI tests.
inline const std::string kMeshes = UVTK_MESHES_DIR;
inline const std::string kIcosphere = kMeshes + "/icosphere.obj";

struct CliRun {
  int status;       // the exit status, or -1 when the program did not exit normally
  std::string err;  // what it printed on stderr
};

class CliTest : public ScratchDirTest {
 protected:
  CliRun uvtk(const std::string& arguments) const { return shell(std::string(UVTK_BINARY) + " " + arguments); }

  // Runs a shell command line (in a subshell, so `ulimit` stays inside it) with its stderr captured.
  CliRun shell(const std::string& command) const {
    const std::string errFile = path("stderr.txt");
    const int raw = std::system(("(" + command + ") 2> " + errFile + " > /dev/null").c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, readText(errFile)};
  }

  // The words that start a shell command line whose program runs under a resource limit (ulimit):
  // without LeakSanitizer, whose tracer (clang 14) can crash at such a process's exit ("Tracer caught
  // signal 11") and turn its exit status into 1. The limit is what the test checks, not leaks; the
  // release tree runs the same test with no sanitizer at all. A no-op outside a sanitized build.
  static std::string leakCheckOff() { return "export ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\"; "; }
};

}  // namespace uvtk
