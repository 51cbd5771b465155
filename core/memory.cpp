#include "core/memory.h"

#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

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

// The first line of a file as an unsigned number ("max" and anything else: nothing).
std::optional<std::uint64_t> fileNumber(const std::string& path) {
  std::ifstream in(path);
  std::string word;
  if (!(in >> word) || word.empty() || word.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
  try {
    return std::stoull(word);
  } catch (const std::out_of_range&) {
    return std::nullopt;
  }
}

// The value of `key` in a memory.stat file of "key value" lines.
std::optional<std::uint64_t> statValue(const std::string& file, const std::string& key) {
  std::ifstream in(file);
  std::string word;
  std::uint64_t value = 0;
  while (in >> word >> value)
    if (word == key) return value;
  return std::nullopt;
}

// Where the hierarchy of a control group is mounted, from /proc/self/mountinfo: fields 4 (the
// mount's root within the hierarchy) and 5 (the mount point); after " - ", the type and, for v1,
// the controllers among the super options.
struct CgroupMount {
  std::string root, point;
};

std::optional<CgroupMount> cgroupMount(const std::string& mountinfo, bool v2) {
  std::ifstream in(mountinfo);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string id, parent, device, root, point, word;
    if (!(fields >> id >> parent >> device >> root >> point)) continue;
    while (fields >> word && word != "-") {
    }
    std::string type, source, options;
    if (!(fields >> type >> source >> options)) continue;
    const bool memoryV1 = type == "cgroup" && ("," + options + ",").find(",memory,") != std::string::npos;
    if (v2 ? type == "cgroup2" : memoryV1) return CgroupMount{root, point};
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::uint64_t> cgroupMemoryLeft(const std::string& root) {
  std::ifstream groups(root + "/proc/self/cgroup");
  std::optional<std::uint64_t> left;
  std::string line;
  while (std::getline(groups, line)) {
    // "ID:CONTROLLERS:PATH": v2 is "0::PATH"; v1's memory controller is listed by name.
    const std::size_t first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1), path = line.substr(second + 1);
    const bool v2 = line.compare(0, first, "0") == 0 && controllers.empty();
    if (!v2 && ("," + controllers + ",").find(",memory,") == std::string::npos) continue;
    const std::optional<CgroupMount> mount = cgroupMount(root + "/proc/self/mountinfo", v2);
    if (!mount) continue;
    // The group's folder under the mount point; in a container the mount's root is the group itself.
    std::string relative = path;
    if (mount->root != "/" && relative.compare(0, mount->root.size(), mount->root) == 0)
      relative = relative.substr(mount->root.size());
    const std::string limitFile = v2 ? "memory.max" : "memory.limit_in_bytes";
    const std::string usageFile = v2 ? "memory.current" : "memory.usage_in_bytes";
    // The group and each one above it, up to the mount point: every limit on the way applies.
    for (std::string folder = relative;;) {
      const std::string place = root + mount->point + folder;
      const std::optional<std::uint64_t> limit = fileNumber(place + "/" + limitFile);
      const std::optional<std::uint64_t> usage = fileNumber(place + "/" + usageFile);
      // v1 writes "no limit" as a huge page-aligned number: anything beyond 2^62 is none.
      if (limit && usage && *limit < (std::uint64_t(1) << 62)) {
        // Usage counts the page cache, which the kernel drops before it fails an allocation: as
        // container tools do, the inactive file pages are not counted as used.
        const std::uint64_t inactive =
            statValue(place + "/memory.stat", v2 ? "inactive_file" : "total_inactive_file").value_or(0);
        const std::uint64_t used = *usage > inactive ? *usage - inactive : 0;
        const std::uint64_t room = *limit > used ? *limit - used : 0;
        left = std::min(left.value_or(room), room);
      }
      if (folder.empty() || folder == "/") break;
      const std::size_t slash = folder.find_last_of('/');
      folder = slash == std::string::npos ? "" : folder.substr(0, slash);
    }
  }
  return left;
}

std::optional<std::uint64_t> availableMemory() {
  std::optional<std::uint64_t> available = procKilobytes("/proc/meminfo", "MemAvailable:");
  if (!available) {
    const long pages = ::sysconf(_SC_AVPHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages > 0 && pageSize > 0) available = std::uint64_t(pages) * std::uint64_t(pageSize);
  }
  if (const std::optional<std::uint64_t> group = cgroupMemoryLeft())
    available = std::min(available.value_or(*group), *group);
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    const std::uint64_t used = procKilobytes("/proc/self/status", "VmSize:").value_or(0);
    const std::uint64_t left = limit.rlim_cur > used ? limit.rlim_cur - used : 0;
    available = std::min(available.value_or(left), left);
  }
  return available;
}

void setFreedMemory(FreedMemory policy) {
#ifdef __GLIBC__
  // glibc raises the mapping threshold to the size of each large block freed (up to 32 MiB) unless
  // it is set, after which such blocks come from its arenas and stay resident once freed: 0 to 19
  // MiB of a 4 M-face map's peak, by run. A batch of 400 10 k-face meshes kept for reuse: 107 k
  // page faults to 1.4 k, 0.85 of the time (docs/benchmarks.md).
  const bool kept = policy == FreedMemory::KeptForReuse;
  mallopt(M_MMAP_THRESHOLD, kept ? 16 << 20 : 1 << 20);
  if (kept) mallopt(M_TRIM_THRESHOLD, 64 << 20);
#else
  (void)policy;
#endif
}

FreedMemory freedMemoryForMeshes(std::optional<std::uint64_t> largestBytes) {
  return largestBytes && *largestBytes <= (std::uint64_t(16) << 20) ? FreedMemory::KeptForReuse : FreedMemory::GivenBack;
}

std::optional<std::uint64_t> largestFile(const std::vector<std::string>& paths) {
  std::uint64_t largest = 0;
  for (const std::string& path : paths) {
    std::error_code unreadable;
    const std::uintmax_t size = std::filesystem::file_size(path, unreadable);
    if (unreadable) return std::nullopt;
    largest = std::max<std::uint64_t>(largest, size);
  }
  return largest;
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
