// Transparent huge pages for large buffers filled afresh (a frame's clip positions, window
// vertices, set-up records and images; a mapping's corners; the judgement's faces), where the kernel grants them on
// request (Debian's default "madvise"): faulting the ~150 MB of a 1 M-triangle 1920 x 1080 frame
// in 4 KiB pages took about a fifth of its time at 1 thread.
#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>

namespace uvtk {

// Advice for the whole 2 MiB pages within [data, data + bytes), given before the memory is first
// touched; where the kernel declines, the pages stay ordinary ones.
inline void adviseHugePages(const void* data, std::size_t bytes) {
  constexpr std::uintptr_t kHugePage = std::uintptr_t(1) << 21;
  const auto start = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t begin = (start + kHugePage - 1) & ~(kHugePage - 1), end = (start + bytes) & ~(kHugePage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

// A vector of n elements whose storage is advised before its elements are constructed.
template <typename Vector>
void resizeOnHugePages(Vector& v, std::size_t n) {
  v.reserve(n);
  adviseHugePages(v.data(), n * sizeof(*v.data()));
  v.resize(n);
}

}  // namespace uvtk
