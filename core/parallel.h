// Work spread over threads: each index in [0, count) is handed out once, in any order; callers
// keep results deterministic by writing to per-index slots. The threads are a process-wide pool,
// started when first needed and kept: starting a thread (its stack, its malloc arena, the pages of
// both) cost 15 to 100 us on this machine, against a few microseconds to wake a kept one.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <limits>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/cancel.h"
#include "core/error.h"

namespace uvtk {

inline int threadCount(int requested) {
  if (requested > 0) return requested;
  // Asked once: glibc reads /sys/devices/system/cpu/online on every call, 26 times in a small map.
  static const int cores = std::max(1, int(std::thread::hardware_concurrency()));
  return cores;
}

// The threads parallelFor(count, threads, ...) runs on.
inline int workerCount(int count, int threads) { return std::max(1, std::min(threadCount(threads), count)); }

namespace detail {

// Work for the pool: run(context, slot) once for each slot in [1, workers) a pool thread takes
// (slot 0 is the poster's own).
struct PoolJob {
  void (*run)(void* context, int worker);
  void* context;
  int workers;
};

// A job as the pool lists it until every slot is taken or its poster withdraws it. Lives with its
// poster (nothing is allocated to post it) until withdraw() returns.
struct PostedJob {
  PoolJob job;
  bool aside = false;  // WorkAside's: its poster goes on with work of its own meanwhile
  int taken = 1;       // the slots handed out: slot 0 is the poster's
  int running = 0;     // pool threads inside job.run
  PostedJob* next = nullptr;
  bool listed = false;
  std::condition_variable finished;
};

// Lists `posted` for the pool's threads, starting threads for the slots no idle thread can take:
// for a loop no more than the cores (or its own workers, when it asks for more), for work aside
// as many as it takes (a thread that cannot be started, for memory or limits, leaves its slots
// untaken).
void post(PostedJob& posted);

// No more slots are handed out; waits for the pool threads that took some. Returns the first slot
// left untaken (job.workers when every slot was).
int withdraw(PostedJob& posted);

// Runs slot 0 of `job` on the calling thread and the others on the pool's free threads; returns
// when every slot that was taken has finished. Slots left untaken are not run: the work must be
// shared out by the slots themselves (an index counter), so that slot 0 alone can finish it.
void runOnPool(const PoolJob& job);

}  // namespace detail

// work(index, worker) for every index, worker in [0, workerCount(count, threads)) the thread that
// runs it: one worker never runs two indices at once, so it may own scratch memory. The calling
// thread is worker 0; the others are the pool's, as many as are free (a nested loop runs on those
// left, or on its caller alone).
// Once a cancellation is requested (core/cancel.h) no index is handed out any more and, when the
// threads have finished, Cancelled is thrown. An exception from work likewise stops the handing out
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
  struct Shared {
    Shared(F& w, int c) : work(w), count(c) {}
    F& work;
    int count;
    std::atomic<int> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr failure;
    std::mutex failureLock;
  } shared(work, count);
  const auto run = [](void* context, int worker) {
    Shared& s = *static_cast<Shared*>(context);
    try {
      for (int i = s.next++; i < s.count && !s.failed && !cancelRequested(); i = s.next++) s.work(i, worker);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(s.failureLock);
      if (!s.failure) s.failure = std::current_exception();
      s.failed = true;
    }
  };
  detail::runOnPool({run, &shared, n});
  if (shared.failure) std::rethrow_exception(shared.failure);
  throwIfCancelled();
}

template <class F>
void parallelFor(int count, int threads, F&& work) {
  parallelForWorkers(count, threads, [&](int i, int) { work(i); });
}

// byte |= bits where threads may set bits of the same byte at once (C++17 has no atomic_ref):
// one atomic read-modify-write, no ordering.
template <class Byte>
void orBitsAtomically(Byte& byte, Byte bits) {
  static_assert(sizeof(Byte) == 1);
  __atomic_fetch_or(&byte, bits, __ATOMIC_RELAXED);
}

// work(begin, end) for the ranges [k chunk, (k + 1) chunk) of [0, count), on threads. The ranges
// do not depend on the threads: results kept per range and combined in range order are the same
// on any number of them.
template <class F>
void parallelForRanges(std::size_t count, std::size_t chunk, int threads, F&& work) {
  const std::size_t ranges = (count + chunk - 1) / chunk;
  UVTK_CHECK(ranges <= std::size_t(std::numeric_limits<int>::max()));
  parallelFor(int(ranges), threads, [&](int r) {
    const std::size_t begin = std::size_t(r) * chunk;
    work(begin, std::min(count, begin + chunk));
  });
}

// A reduction over [0, count): each range's value, from `init`, made by work(value, begin, end),
// then the values combined in range order by combine(total, value), the total from `init`. A range
// works on a local value, stored when it is done: a value in the shared vector, reached through a
// reference the compiler must assume may alias the data read (a char count aliases everything, a
// box of doubles the doubles), was loaded and stored on every item (a UV box over 12 M corners
// took 12 ns a corner).
template <class T, class F, class Combine>
T reduceRanges(std::size_t count, std::size_t chunk, int threads, const T& init, F&& work, Combine&& combine) {
  std::vector<T> values((count + chunk - 1) / chunk, init);
  parallelForRanges(count, chunk, threads, [&](std::size_t begin, std::size_t end) {
    T value = init;
    work(value, begin, end);
    values[begin / chunk] = std::move(value);
  });
  T total = init;
  for (const T& value : values) combine(total, value);
  return total;
}

// The bounding box (an Eigen::AlignedBox, or Bounds2 of core/math.h) that extend(box, i) builds for
// i in [0, count), in ranges on threads: a box is a minimum and a maximum, so the ranges' boxes
// joined in order give the bits one loop gives (the first of equal minima kept).
template <class Box, class Extend>
Box boundsInRanges(std::size_t count, int threads, Extend&& extend) {
  return reduceRanges(
      count, std::size_t(1) << 16, threads, Box(),
      [&](Box& box, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) extend(box, i);
      },
      [](Box& total, const Box& box) { total.extend(box); });
}

// `work()` set going beside the caller: on a pool thread (one is started when none is free), or,
// when `aside` is false or no thread has taken it by the time it is asked for, by the thread that
// asks (get()). Set aside, it always runs, as std::async's work does: the destructor waits for it
// (or runs it) and drops what it threw; not set aside, it runs only when asked, as std::launch::
// deferred's does.
template <class F>
class WorkAside {
 public:
  using Result = std::invoke_result_t<F&>;

  WorkAside(F work, bool aside) : work_(std::move(work)), aside_(aside) {
    posted_.job = {[](void* self, int) { static_cast<WorkAside*>(self)->run(); }, this, 2};
    posted_.aside = true;
    if (aside_) detail::post(posted_);
  }
  WorkAside(const WorkAside&) = delete;
  WorkAside& operator=(const WorkAside&) = delete;
  ~WorkAside() {
    if (aside_) finish();
  }

  // The work's result; rethrows what it threw.
  Result get() {
    finish();
    if (failure_) std::rethrow_exception(failure_);
    if constexpr (!std::is_void_v<Result>) return std::move(*result_);
  }

 private:
  void run() noexcept {
    try {
      if constexpr (std::is_void_v<Result>) work_();
      else result_.emplace(work_());
    } catch (...) {
      failure_ = std::current_exception();
    }
  }
  void finish() {
    if (finished_) return;
    finished_ = true;
    if (!aside_ || detail::withdraw(posted_) == 1) run();  // not posted, or not taken
  }

  F work_;
  std::optional<std::conditional_t<std::is_void_v<Result>, char, Result>> result_;
  std::exception_ptr failure_;
  bool aside_;
  detail::PostedJob posted_;
  bool finished_ = false;
};

}  // namespace uvtk
