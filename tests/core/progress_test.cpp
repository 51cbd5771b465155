// The progress lines as text, and the silence of short or disabled work in logs.
#include "core/progress.h"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

TEST(ProgressBarLine, ShowsLabelBarCountsAndTime) {
  EXPECT_EQ(progressBarLine("mapping", 1234, 5000, "vertices", 2.34, 80),
            "mapping [#######.......................] 1234/5000 vertices  2.3 s");
  EXPECT_EQ(progressBarLine("m", 0, 10, "tiles", 0.0, 80), "m [..............................] 0/10 tiles  0.0 s");
  EXPECT_EQ(progressBarLine("m", 10, 10, "tiles", 1.0, 80), "m [##############################] 10/10 tiles  1.0 s");
}

TEST(ProgressBarLine, ShowsCountsInDisplayedUnits) {
  EXPECT_EQ(progressBarLine("reading a.obj", 12'345'678, 50'000'000, "MB", 1.0, 80, 1'000'000),
            "reading a.obj [#######.......................] 12.3/50.0 MB  1.0 s");
}

TEST(ProgressBarLine, FitsANarrowTerminalByShorteningTheBarThenTheLabelFromTheLeft) {
  const std::string narrow = progressBarLine("mapping", 5, 10, "meshes", 1.0, 50);
  EXPECT_EQ(narrow, "mapping [##########..........] 5/10 meshes  1.0 s");
  const std::string path = progressBarLine("reading /a/very/long/folder/name/mesh.obj", 5, 10, "MB", 1.0, 50);
  EXPECT_EQ(path, "...lder/name/mesh.obj [#####.....] 5/10 MB  1.0 s");
  for (int width : {1, 10, 30, 50, 200})
    EXPECT_LE(progressBarLine("reading /a/very/long/path.obj", 5, 10, "MB", 1.0, width).size(),
              std::size_t(std::max(width - 1, 0)))
        << width;
}

TEST(ProgressBarLine, ANothingToDoIsFullAndMoreThanTheTotalIsNotMore) {
  EXPECT_EQ(progressBarLine("x", 0, 0, "u", 0.0, 80), "x [##############################] 0/0 u  0.0 s");
  EXPECT_EQ(progressBarLine("x", 12, 10, "u", 0.0, 80), "x [##############################] 12/10 u  0.0 s");
}

TEST(ProgressPlainLine, ReadsAsALogLine) {
  EXPECT_EQ(progressPlainLine("mapping", 1234, 5000, "meshes", 5.04), "mapping: 1234/5000 meshes, 5.0 s");
  EXPECT_EQ(progressPlainLine("reading a.off", 2'500'000, 10'000'000, "MB", 5.0, 1'000'000),
            "reading a.off: 2.5/10.0 MB, 5.0 s");
}

// Under the test, stderr is captured to a file: not a terminal.
TEST(Progress, ShortWorkPrintsNothingInALogAndDisabledPrintsNothingAtAll) {
  for (bool enabled : {false, true}) {
    setProgressEnabled(enabled);
    testing::internal::CaptureStderr();
    {
      Progress progress("mapping", 4000, "vertices");
      std::vector<std::thread> threads;
      for (int t = 0; t < 4; ++t)
        threads.emplace_back([&] {
          for (int i = 0; i < 1000; ++i) progress.advance();
        });
      for (std::thread& t : threads) t.join();
    }
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << enabled;
  }
  setProgressEnabled(false);
}

TEST(Progress, MessagesAreWholeLines) {
  setProgressEnabled(true);
  testing::internal::CaptureStderr();
  {
    Progress progress("mapping", 2, "meshes");
    progress.advance();
    printProgressMessage("a.obj:3: error: expected a number, found 'x'");
    progress.advance();
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "a.obj:3: error: expected a number, found 'x'\n");
  setProgressEnabled(false);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
