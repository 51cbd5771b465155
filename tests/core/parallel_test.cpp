// The pool under parallelFor and WorkAside (core/parallel.h): every index once, whatever the
// nesting, the callers or the threads free; work set aside runs once, beside or on the asker;
// exceptions come out where the work is asked for; a child of fork() has a pool of its own.
#include "core/parallel.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <vector>

namespace uvtk {
namespace {

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

}  // namespace
}  // namespace uvtk
