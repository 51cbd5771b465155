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

// The threads parallelFor(count, threads, ...) runs on.
inline int workerCount(int count, int threads) { return std::max(1, std::min(threadCount(threads), count)); }

// work(index, worker) for every index, worker in [0, workerCount(count, threads)) the thread that
// runs it: one worker never runs two indices at once, so it may own scratch memory.
template <class F>
void parallelForWorkers(int count, int threads, F&& work) {
  const int n = workerCount(count, threads);
  if (n <= 1) {
    for (int i = 0; i < count; ++i) work(i, 0);
    return;
  }
  std::atomic<int> next{0};
  auto run = [&](int worker) {
    for (int i = next++; i < count; i = next++) work(i, worker);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < n; ++t) pool.emplace_back(run, t);
  run(0);
  for (std::thread& t : pool) t.join();
}

template <class F>
void parallelFor(int count, int threads, F&& work) {
  parallelForWorkers(count, threads, [&](int i, int) { work(i); });
}

}  // namespace uvtk
