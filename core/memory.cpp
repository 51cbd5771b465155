#include "core/memory.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace uvtk {
namespace {

// The value of `key` ("MemAvailable:") in a /proc file of "Key: N kB" lines, in bytes.
std::optional<std::uint64_t> procKilobytes(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string word;
  while (in >> word) {
    if (word != key) continue;
    std::uint64_t kilobytes = 0;
    if (in >> kilobytes) return kilobytes * 1024;
    return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::uint64_t> availableMemory() {
  std::optional<std::uint64_t> available = procKilobytes("/proc/meminfo", "MemAvailable:");
  if (!available) {
    const long pages = ::sysconf(_SC_AVPHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages > 0 && pageSize > 0) available = std::uint64_t(pages) * std::uint64_t(pageSize);
  }
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    const std::uint64_t used = procKilobytes("/proc/self/status", "VmSize:").value_or(0);
    const std::uint64_t left = limit.rlim_cur > used ? limit.rlim_cur - used : 0;
    available = std::min(available.value_or(left), left);
  }
  return available;
}

std::string formatBytes(std::uint64_t bytes) {
  char text[32];
  if (bytes >= (std::uint64_t(1) << 30))
    std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(std::uint64_t(1) << 30));
  else if (bytes >= (std::uint64_t(1) << 20))
    std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(std::uint64_t(1) << 20));
  else if (bytes >= (std::uint64_t(1) << 10))
    std::snprintf(text, sizeof text, "%.1f KiB", double(bytes) / double(std::uint64_t(1) << 10));
  else
    std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
  return text;
}

}  // namespace uvtk
