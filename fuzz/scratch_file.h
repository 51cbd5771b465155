// The scene and image targets read files, as users' runs do: each input is written to one file in a
// private folder made once per process.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace uvtk::fuzz {

// The process's folder under the system's temporary folder, created on first use and removed when
// the fuzzer exits normally (after a crash it stays, beside the crashing input).
inline const std::filesystem::path& scratchFolder() {
  static const std::filesystem::path folder = [] {
    const auto f = std::filesystem::temp_directory_path() / ("uvtk_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(f);
    return f;
  }();
  // Registered after `folder` is built, so it runs before `folder` is destroyed.
  static const int removal = std::atexit([] {
    std::error_code ignored;
    std::filesystem::remove_all(folder, ignored);
  });
  (void)removal;
  return folder;
}

// Writes the input to `name` in the scratch folder and returns its path.
inline std::string writeInput(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const std::string path = (scratchFolder() / name).string();
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

}  // namespace uvtk::fuzz
