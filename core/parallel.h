// Work spread over threads: each index in [0, count) is handed out once, in any order; callers
// keep results deterministic by writing to per-index slots.
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "core/cancel.h"

namespace uvtk {

inline int threadCount(int requested) {
  if (requested > 0) return requested;
  // Asked once: glibc reads /sys/devices/system/cpu/online on every call, 26 times in a small map.
  static const int cores = std::max(1, int(std::thread::hardware_concurrency()));
  return cores;
}

// The threads parallelFor(count, threads, ...) runs on.
inline int workerCount(int count, int threads) { return std::max(1, std::min(threadCount(threads), count)); }

// work(index, worker) for every index, worker in [0, workerCount(count, threads)) the thread that
// runs it: one worker never runs two indices at once, so it may own scratch memory.
// Once a cancellation is requested (core/cancel.h) no index is handed out any more and, when the
// threads have joined, Cancelled is thrown. An exception from work likewise stops the handing out
// and is rethrown here (the first, if several threads throw), whichever thread ran it.
template <class F>
void parallelForWorkers(int count, int threads, F&& work) {
  const int n = workerCount(count, threads);
  if (n <= 1) {
    for (int i = 0; i < count; ++i) {
      throwIfCancelled();
      work(i, 0);
    }
    return;
  }
  std::atomic<int> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr failure;
  std::mutex failureLock;
  auto run = [&](int worker) {
    try {
      for (int i = next++; i < count && !failed && !cancelRequested(); i = next++) work(i, worker);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(failureLock);
      if (!failure) failure = std::current_exception();
      failed = true;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < n; ++t) {
    try {
      pool.emplace_back(run, t);
    } catch (const std::system_error&) {
      break;  // the system has no thread to give (memory, limits): those started do the work
    }
  }
  run(0);
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  throwIfCancelled();
}

template <class F>
void parallelFor(int count, int threads, F&& work) {
  parallelForWorkers(count, threads, [&](int i, int) { work(i); });
}

}  // namespace uvtk
