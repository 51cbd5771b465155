// Work spread over threads: each index in [0, count) is handed out once, in any order; callers
// keep results deterministic by writing to per-index slots.
#pragma once

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace uvtk {

inline int threadCount(int requested) {
  if (requested > 0) return requested;
  return std::max(1, int(std::thread::hardware_concurrency()));
}

template <class F>
void parallelFor(int count, int threads, F&& work) {
  const int n = std::min(threadCount(threads), count);
  if (n <= 1) {
    for (int i = 0; i < count; ++i) work(i);
    return;
  }
  std::atomic<int> next{0};
  auto run = [&] {
    for (int i = next++; i < count; i = next++) work(i);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < n; ++t) pool.emplace_back(run);
  run();
  for (std::thread& t : pool) t.join();
}

}  // namespace uvtk
