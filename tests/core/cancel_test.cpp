// Cancellation (core/cancel.h) through parallelFor: no index is handed out once it is requested,
// Cancelled comes out after the threads have joined, and nested loops carry it out too.
#include "core/cancel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/parallel.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

// Every test leaves the process without a request, whatever it asserted.
class Cancel : public ::testing::Test {
 protected:
  void TearDown() override { clearCancel(); }
};

TEST_F(Cancel, NothingIsRequestedUntilSomeoneAsks) {
  EXPECT_FALSE(cancelRequested());
  EXPECT_NO_THROW(throwIfCancelled());
  requestCancel();
  EXPECT_TRUE(cancelRequested());
  EXPECT_THROW(throwIfCancelled(), Cancelled);
  clearCancel();
  EXPECT_FALSE(cancelRequested());
}

TEST_F(Cancel, WithoutARequestEveryIndexRunsOnce) {
  for (int threads : {1, 2, 4}) {
    std::vector<std::atomic<int>> runs(1000);
    parallelFor(1000, threads, [&](int i) { ++runs[std::size_t(i)]; });
    for (const std::atomic<int>& r : runs) EXPECT_EQ(r, 1) << threads;
  }
}

TEST_F(Cancel, OneThreadStopsAtTheNextIndexAndThrows) {
  int ran = 0;
  EXPECT_THROW(parallelFor(1000, 1,
                           [&](int i) {
                             ++ran;
                             if (i == 10) requestCancel();
                           }),
               Cancelled);
  EXPECT_EQ(ran, 11);
}

TEST_F(Cancel, ThreadsStopHandingOutIndicesAndThrowOnceJoined) {
  // Index 0 requests; the others wait for the request, so each thread runs at most the index it
  // held when the request came.
  constexpr int kThreads = 4;
  std::atomic<int> ran{0};
  EXPECT_THROW(parallelFor(100000, kThreads,
                           [&](int i) {
                             ++ran;
                             if (i == 0) requestCancel();
                             while (!cancelRequested()) std::this_thread::yield();
                           }),
               Cancelled);
  EXPECT_GE(ran, 1);
  EXPECT_LE(ran, kThreads);
}

TEST_F(Cancel, ARequestMadeBeforeTheLoopRunsNoIndex) {
  requestCancel();
  for (int threads : {1, 3}) {
    std::atomic<int> ran{0};
    EXPECT_THROW(parallelFor(50, threads, [&](int) { ++ran; }), Cancelled) << threads;
    EXPECT_EQ(ran, 0) << threads;
  }
}

// A loop inside a loop's work runs on the outer loop's threads: its Cancelled must reach the caller
// instead of ending the process from a thread nobody catches on.
TEST_F(Cancel, ANestedLoopCancelledOnAWorkerThreadReachesTheCaller) {
  // Outer index 5 requests from inside its inner loop; later outer indices wait for the request.
  for (int innerThreads : {1, 2}) {
    std::atomic<int> outer{0};
    EXPECT_THROW(parallelFor(64, 2,
                             [&](int i) {
                               ++outer;
                               while (i > 5 && !cancelRequested()) std::this_thread::yield();
                               parallelFor(8, innerThreads, [&](int j) {
                                 if (i == 5 && j == 3) requestCancel();
                               });
                             }),
                 Cancelled)
        << innerThreads;
    EXPECT_LE(outer, 8) << innerThreads;
    clearCancel();
  }
}

TEST_F(Cancel, AnExceptionOnAWorkerThreadIsRethrownByTheCaller) {
  for (int threads : {1, 2, 4}) {
    try {
      parallelFor(10000, threads, [&](int i) {
        if (i == 7) throw std::invalid_argument("index 7");
      });
      ADD_FAILURE() << "no exception, threads " << threads;
    } catch (const std::invalid_argument& e) {
      EXPECT_STREQ(e.what(), "index 7");
    }
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
