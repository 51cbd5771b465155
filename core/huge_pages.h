// Large buffers filled afresh, faulted in before their elements are constructed (a mapping's
// corners, the judgement's faces, a frame's set-up records), and transparent huge pages for the
// renderer's, where the kernel grants them on request (Debian's default "madvise"): faulting the
// ~150 MB of a 1 M-triangle 1920 x 1080 frame in 4 KiB pages took about a fifth of its time at 1
// thread. Mapping and judging ask for no huge pages: with defragmentation on advice (Debian's
// default) a fresh huge page can wait for the kernel to compact memory, and on this project's
// machines faulting in advised blocks cost 0.15 to 2 ms a MB against 0.26 to 0.43 for small pages
// (the 4 M-face map 2.9 to 3.4 s against 2.7 to 2.8).
#pragma once

#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "core/parallel.h"

namespace uvtk {

// Advice for the whole 2 MiB pages within [data, data + bytes), given before the memory is first
// touched; where the kernel declines, the pages stay ordinary ones.
inline void adviseHugePages(const void* data, std::size_t bytes) {
  constexpr std::uintptr_t kHugePage = std::uintptr_t(1) << 21;
  const auto start = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t begin = (start + kHugePage - 1) & ~(kHugePage - 1), end = (start + bytes) & ~(kHugePage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

// The pages of [data, data + bytes) faulted in on `threads` threads (0: one per core), so that the
// kernel's clearing of fresh pages, a fifth of `uvtk map`'s CPU time on a paravirtualised guest, is
// shared by the cores instead of falling on the one thread that constructs the elements. Where the
// kernel lacks MADV_POPULATE_WRITE (before Linux 5.14) the first touch faults them as before.
// A smaller block (from 64 KiB) is faulted in by one call on this thread: 0.46 us a page instead of
// 1 us a fault (a 480 KB block, 122 to 55 us).
inline void prefaultPages(const void* data, std::size_t bytes, int threads) {
  constexpr std::uintptr_t kPage = 4096, kHugePage = std::uintptr_t(1) << 21, kPiece = std::uintptr_t(1) << 24;
  constexpr std::size_t kOneCallBytes = std::size_t(1) << 16;
  const int workers = threadCount(threads);
  const auto start = reinterpret_cast<std::uintptr_t>(data);
  if (workers <= 1 || bytes < 2 * kPiece) {
    const std::uintptr_t begin = (start + kPage - 1) & ~(kPage - 1), end = (start + bytes) & ~(kPage - 1);
    if (bytes >= kOneCallBytes && end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
    return;
  }
  const std::uintptr_t begin = (start + kHugePage - 1) & ~(kHugePage - 1), end = (start + bytes) & ~(kHugePage - 1);
  const int pieces = int((end - begin + kPiece - 1) / kPiece);
  parallelFor(pieces, workers, [&](int i) {
    const std::uintptr_t from = begin + std::uintptr_t(i) * kPiece, to = std::min(end, from + kPiece);
    madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);
  });
}

// A vector of n elements whose storage is faulted in on `threads` threads (0: one per core) before
// its elements are constructed.
template <typename Vector>
void resizeFaultedIn(Vector& v, std::size_t n, int threads = 1) {
  v.reserve(n);
  if (n > v.size()) prefaultPages(v.data() + v.size(), (n - v.size()) * sizeof(*v.data()), threads);
  v.resize(n);
}

// The same with its storage advised as huge pages first (the renderer's buffers).
template <typename Vector>
void resizeOnHugePages(Vector& v, std::size_t n, int threads = 1) {
  v.reserve(n);
  adviseHugePages(v.data(), n * sizeof(*v.data()));
  resizeFaultedIn(v, n, threads);
}

}  // namespace uvtk
