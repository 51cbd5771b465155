// The pool under parallelFor and WorkAside (core/parallel.h): every index once, whatever the
// nesting, the callers or the threads free; work set aside runs once, beside or on the asker;
// exceptions come out where the work is asked for; a child of fork() has a pool of its own.
#include "core/parallel.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

TEST(Parallel, NestedLoopsRunEveryIndexOnce) {
  std::vector<std::atomic<int>> runs(64 * 50);
  parallelFor(64, 4, [&](int i) { parallelFor(50, 3, [&](int j) { ++runs[std::size_t(i * 50 + j)]; }); });
  for (const std::atomic<int>& r : runs) EXPECT_EQ(r, 1);
}

TEST(Parallel, ManyCallersAtOnceEachGetEveryIndex) {
  constexpr int kCallers = 8, kCount = 2000;
  std::vector<std::vector<int>> runs(kCallers, std::vector<int>(kCount, 0));
  std::vector<std::thread> callers;
  for (int c = 0; c < kCallers; ++c)
    callers.emplace_back([&, c] {
      for (int round = 0; round < 20; ++round) parallelFor(kCount, 3, [&](int i) { ++runs[std::size_t(c)][std::size_t(i)]; });
    });
  for (std::thread& t : callers) t.join();
  for (const std::vector<int>& r : runs)
    for (int n : r) EXPECT_EQ(n, 20);
}

TEST(Parallel, AWorkerNeverRunsTwoIndicesAtOnce) {
  // Each worker owns a slot; a second index entering a busy slot would see it taken.
  constexpr int kThreads = 4;
  std::vector<std::atomic<int>> busy(kThreads);
  std::atomic<int> clashes{0}, ran{0};
  parallelForWorkers(5000, kThreads, [&](int, int worker) {
    if (busy[std::size_t(worker)].exchange(1) != 0) ++clashes;
    ++ran;
    busy[std::size_t(worker)] = 0;
  });
  EXPECT_EQ(clashes, 0);
  EXPECT_EQ(ran, 5000);
}

TEST(Parallel, TheFirstExceptionComesOutAfterTheLoop) {
  std::atomic<int> ran{0};
  EXPECT_THROW(parallelFor(10000, 4,
                           [&](int i) {
                             ++ran;
                             if (i == 100) throw std::runtime_error("index 100");
                             // Later items take a while: with instant ones the other workers could
                             // finish the loop while the throwing thread waits for a core (a
                             // loaded machine), before it can stop the handing out.
                             if (i > 100) std::this_thread::sleep_for(std::chrono::milliseconds(1));
                           }),
               std::runtime_error);
  EXPECT_LT(ran, 10000);  // the handing out stopped
  // The pool is whole afterwards.
  std::atomic<int> after{0};
  parallelFor(1000, 4, [&](int) { ++after; });
  EXPECT_EQ(after, 1000);
}

TEST(Parallel, WorkAsideGivesItsResultBesideTheCallerOrOnIt) {
  for (bool aside : {true, false}) {
    std::atomic<int> runs{0};
    WorkAside sum([&] {
      ++runs;
      std::vector<int> v(1000);
      std::iota(v.begin(), v.end(), 1);
      return std::accumulate(v.begin(), v.end(), 0);
    }, aside);
    std::atomic<int> alongside{0};
    parallelFor(100, 2, [&](int) { ++alongside; });  // the caller's own loop meanwhile
    EXPECT_EQ(sum.get(), 500500) << aside;
    EXPECT_EQ(runs, 1) << aside;
    EXPECT_EQ(alongside, 100);
  }
}

TEST(Parallel, WorkAsideRethrowsWhenAskedAndItsDestructorWaits) {
  WorkAside failing([]() -> int { throw std::runtime_error("aside"); }, true);
  EXPECT_THROW(failing.get(), std::runtime_error);
  std::atomic<bool> done{false};
  {
    WorkAside slow([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      done = true;
    }, true);
  }  // not asked: the destructor waits
  EXPECT_TRUE(done);
}

TEST(Parallel, RangesCoverEveryIndexOnceInFixedPieces) {
  for (const std::size_t count : {std::size_t(0), std::size_t(1), std::size_t(999), std::size_t(1000), std::size_t(1001)})
    for (const int threads : {1, 2, 5}) {
      std::vector<std::atomic<int>> runs(count);
      std::vector<std::pair<std::size_t, std::size_t>> pieces((count + 99) / 100);
      parallelForRanges(count, 100, threads, [&](std::size_t begin, std::size_t end) {
        pieces[begin / 100] = {begin, end};
        for (std::size_t i = begin; i < end; ++i) ++runs[i];
      });
      for (const std::atomic<int>& r : runs) EXPECT_EQ(r, 1);
      for (std::size_t k = 0; k < pieces.size(); ++k)  // [100 k, min(count, 100 k + 100)) whatever the threads
        EXPECT_EQ(pieces[k], std::make_pair(100 * k, std::min(count, 100 * k + 100))) << count << " " << threads;
    }
}

TEST(Parallel, AReductionCombinesTheRangesInOrder) {
  // Joining each range's indices in range order gives 0, 1, ..., n - 1 on any number of threads;
  // a floating sum taken that way is the same bits on any number too.
  std::vector<double> values(100000);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = 1.0 / double(i + 1) * (i % 3 == 0 ? -1e-3 : 1.0);
  std::vector<double> sums;
  for (const int threads : {1, 2, 3, 8}) {
    const std::vector<std::size_t> order = reduceRanges(
        values.size(), 4096, threads, std::vector<std::size_t>{},
        [](std::vector<std::size_t>& part, std::size_t begin, std::size_t end) {
          for (std::size_t i = begin; i < end; ++i) part.push_back(i);
        },
        [](std::vector<std::size_t>& total, const std::vector<std::size_t>& part) {
          total.insert(total.end(), part.begin(), part.end());
        });
    std::vector<std::size_t> expected(values.size());
    std::iota(expected.begin(), expected.end(), std::size_t(0));
    EXPECT_EQ(order, expected) << threads;
    sums.push_back(reduceRanges(
        values.size(), 4096, threads, 0.0,
        [&](double& sum, std::size_t begin, std::size_t end) {
          for (std::size_t i = begin; i < end; ++i) sum += values[i];
        },
        [](double& total, double sum) { total += sum; }));
  }
  for (const double sum : sums) EXPECT_EQ(sum, sums.front());
}

TEST(Parallel, BitsSetAtOnceByManyThreadsAreAllKept) {
  std::vector<std::uint8_t> bytes(1000, 0);
  parallelFor(8, 8, [&](int bit) {
    for (std::uint8_t& b : bytes) orBitsAtomically(b, std::uint8_t(1u << bit));
  });
  for (const std::uint8_t b : bytes) EXPECT_EQ(b, 0xff);
}

TEST(Parallel, AChildOfForkHasAPoolOfItsOwn) {
  parallelFor(100, 4, [](int) {});  // the parent's pool has threads
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::atomic<int> ran{0};
    parallelFor(1000, 4, [&](int) { ++ran; });
    WorkAside aside([] { return 7; }, true);
    ::_exit(ran == 1000 && aside.get() == 7 ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
