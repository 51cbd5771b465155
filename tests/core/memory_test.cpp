// The memory a process may still take, as control groups limit it: cgroupMemoryLeft on trees laid
// out as /proc and /sys show them (cgroup v2, v1, a container's view), and availableMemory in a
// real group the test creates where the machine lets it.
#include "core/memory.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

constexpr std::uint64_t kMiB = std::uint64_t(1) << 20;

class CgroupTree : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("uvtk-cgroup-" + std::to_string(::getpid()));
    fs::remove_all(root_);
  }
  void TearDown() override { fs::remove_all(root_); }
  void write(const std::string& path, const std::string& text) {
    const fs::path file = root_ / path.substr(1);
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
  }
  std::optional<std::uint64_t> left() const { return cgroupMemoryLeft(root_.string()); }
  fs::path root_;
};

const char* const kV2Mounts = "22 1 0:21 / /proc rw - proc proc rw\n"
                              "30 23 0:26 / /sys/fs/cgroup rw,nosuid - cgroup2 cgroup2 rw,nsdelegate\n";

TEST_F(CgroupTree, V2LimitLessWhatTheGroupUsesWithoutInactiveFilePages) {
  write("/proc/self/cgroup", "0::/jobs/job7\n");
  write("/proc/self/mountinfo", kV2Mounts);
  write("/sys/fs/cgroup/jobs/job7/memory.max", "1073741824\n");
  write("/sys/fs/cgroup/jobs/job7/memory.current", std::to_string(300 * kMiB) + "\n");
  write("/sys/fs/cgroup/jobs/job7/memory.stat", "anon 1000\nfile 5000\ninactive_file " + std::to_string(100 * kMiB) + "\n");
  // 1024 MiB - (300 - 100) MiB
  EXPECT_EQ(left(), std::optional<std::uint64_t>(824 * kMiB));
}

TEST_F(CgroupTree, V2TheTightestGroupOnTheWayUpAndMaxIsNoLimit) {
  write("/proc/self/cgroup", "0::/jobs/job7\n");
  write("/proc/self/mountinfo", kV2Mounts);
  write("/sys/fs/cgroup/jobs/job7/memory.max", "max\n");
  write("/sys/fs/cgroup/jobs/job7/memory.current", std::to_string(10 * kMiB));
  write("/sys/fs/cgroup/jobs/memory.max", std::to_string(512 * kMiB));
  write("/sys/fs/cgroup/jobs/memory.current", std::to_string(500 * kMiB));
  EXPECT_EQ(left(), std::optional<std::uint64_t>(12 * kMiB));
  write("/sys/fs/cgroup/jobs/memory.max", "max\n");
  EXPECT_EQ(left(), std::nullopt);
}

TEST_F(CgroupTree, V2UsageAboveTheLimitLeavesNothing) {
  write("/proc/self/cgroup", "0::/j\n");
  write("/proc/self/mountinfo", kV2Mounts);
  write("/sys/fs/cgroup/j/memory.max", std::to_string(64 * kMiB));
  write("/sys/fs/cgroup/j/memory.current", std::to_string(65 * kMiB));
  EXPECT_EQ(left(), std::optional<std::uint64_t>(0));
}

TEST_F(CgroupTree, V1MemoryControllerAmongOthersAndItsHugeNoLimit) {
  write("/proc/self/cgroup", "5:devices:/\n4:memory,hugetlb:/batch/task\n0::/\n");
  write("/proc/self/mountinfo",
        "35 31 0:32 / /sys/fs/cgroup/memory rw,relatime - cgroup cgroup rw,memory,hugetlb\n"
        "36 31 0:33 / /sys/fs/cgroup/devices rw,relatime - cgroup cgroup rw,devices\n");
  write("/sys/fs/cgroup/memory/batch/task/memory.limit_in_bytes", std::to_string(256 * kMiB));
  write("/sys/fs/cgroup/memory/batch/task/memory.usage_in_bytes", std::to_string(56 * kMiB));
  write("/sys/fs/cgroup/memory/batch/task/memory.stat", "cache 1\ntotal_inactive_file " + std::to_string(6 * kMiB) + "\n");
  write("/sys/fs/cgroup/memory/batch/memory.limit_in_bytes", "9223372036854771712");
  write("/sys/fs/cgroup/memory/batch/memory.usage_in_bytes", std::to_string(56 * kMiB));
  EXPECT_EQ(left(), std::optional<std::uint64_t>(206 * kMiB));
}

TEST_F(CgroupTree, AContainerSeesItsOwnGroupAsTheMountsRoot) {
  // Docker's view: /proc/self/cgroup names the host's path, the mount's root is that same group.
  write("/proc/self/cgroup", "0::/system.slice/docker-abc.scope\n");
  write("/proc/self/mountinfo", "30 23 0:26 /system.slice/docker-abc.scope /sys/fs/cgroup ro - cgroup2 cgroup2 rw\n");
  write("/sys/fs/cgroup/memory.max", std::to_string(2048 * kMiB));
  write("/sys/fs/cgroup/memory.current", std::to_string(48 * kMiB));
  EXPECT_EQ(left(), std::optional<std::uint64_t>(2000 * kMiB));
}

TEST_F(CgroupTree, NoGroupFilesNoLimit) {
  write("/proc/self/cgroup", "0::/\n");
  write("/proc/self/mountinfo", kV2Mounts);
  EXPECT_EQ(left(), std::nullopt);
  EXPECT_EQ(cgroupMemoryLeft((root_ / "absent").string()), std::nullopt);
}

// A real group of 64 MiB where this process may make one (root, a writable v1 memory hierarchy or
// a v2 one with the memory controller): a child moved into it sees at most 64 MiB available.
TEST(AvailableMemory, AChildInAGroupOf64MiBSeesAtMostThat) {
  const fs::path v2 = "/sys/fs/cgroup", v1 = "/sys/fs/cgroup/memory";
  const bool useV1 = fs::exists(v1 / "memory.limit_in_bytes");
  const fs::path group = (useV1 ? v1 : v2) / ("uvtk-test-" + std::to_string(::getpid()));
  std::error_code error;
  if (!fs::create_directory(group, error) || !fs::exists(group / (useV1 ? "memory.limit_in_bytes" : "memory.max"))) {
    fs::remove(group, error);
    GTEST_SKIP() << "cannot create a memory control group here (not root, or no writable memory hierarchy)";
  }
  std::ofstream(group / (useV1 ? "memory.limit_in_bytes" : "memory.max")) << 64 * kMiB;
  int channel[2];
  ASSERT_EQ(::pipe(channel), 0);
  const pid_t child = ::fork();
  if (child == 0) {
    std::ofstream(group / "cgroup.procs") << ::getpid() << std::flush;
    const std::optional<std::uint64_t> available = availableMemory();
    const std::uint64_t value = available ? *available : ~std::uint64_t(0);
    (void)!::write(channel[1], &value, sizeof value);
    ::_exit(0);
  }
  ::close(channel[1]);
  std::uint64_t seen = 0;
  const bool read = ::read(channel[0], &seen, sizeof seen) == sizeof seen;
  ::close(channel[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  fs::remove(group, error);
  ASSERT_TRUE(read);
  EXPECT_LE(seen, 64 * kMiB);
  EXPECT_GT(seen, 0u);
}

TEST(FreedMemory, KeptForReuseUpTo16MiBAndGivenBackBeyondOrWhenUnknown) {
  EXPECT_EQ(freedMemoryForMeshes(std::uint64_t(0)), FreedMemory::KeptForReuse);
  EXPECT_EQ(freedMemoryForMeshes(16 * kMiB), FreedMemory::KeptForReuse);
  EXPECT_EQ(freedMemoryForMeshes(16 * kMiB + 1), FreedMemory::GivenBack);
  EXPECT_EQ(freedMemoryForMeshes(std::nullopt), FreedMemory::GivenBack);
}

TEST(FreedMemory, TheLargestFileOrNothingWhenOneCannotBeRead) {
  const fs::path folder = fs::temp_directory_path() / ("uvtk-largest-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  std::ofstream(folder / "a.obj") << "v 0 0 0\n";            // 8 bytes
  std::ofstream(folder / "b.obj") << std::string(300, 'x');  // 300 bytes
  const std::string a = (folder / "a.obj").string(), b = (folder / "b.obj").string();
  EXPECT_EQ(largestFile({}), std::optional<std::uint64_t>(0));
  EXPECT_EQ(largestFile({a, b}), std::optional<std::uint64_t>(300));
  EXPECT_EQ(largestFile({a}), std::optional<std::uint64_t>(8));
  EXPECT_EQ(largestFile({a, (folder / "missing.obj").string()}), std::nullopt);
  EXPECT_EQ(largestFile({folder.string()}), std::nullopt);  // a folder has no size of its own
  std::error_code ignored;
  fs::remove_all(folder, ignored);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
