// core/huge_pages.h: the advice changes no value, and the kernel backs advised memory with
// huge pages where it offers them.
#include "core/huge_pages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

TEST(HugePages, ResizeGivesValueInitialisedElements) {
  std::vector<float> v{1.0f, 2.0f};
  resizeOnHugePages(v, std::size_t(3) << 20);  // 12 MiB
  ASSERT_EQ(v.size(), std::size_t(3) << 20);
  EXPECT_EQ(v[0], 1.0f);
  EXPECT_EQ(v[1], 2.0f);
  std::size_t nonZero = 0;
  for (std::size_t i = 2; i < v.size(); ++i) nonZero += v[i] != 0.0f;
  EXPECT_EQ(nonZero, 0u);
  std::vector<int> small;
  resizeOnHugePages(small, 3);  // no whole huge page inside: no advice
  EXPECT_EQ(small, std::vector<int>(3, 0));
}

// Faulted in on threads first (blocks of 32 MiB or more), the elements are the same: the old ones
// kept, the new ones value-initialised; with and without the advice.
TEST(HugePages, ResizeOnThreadsKeepsAndValueInitialises) {
  for (const int threads : {1, 2, 3})
    for (const bool advised : {false, true}) {
      std::vector<double> v{1.0, -2.0, 3.0};
      if (advised)
        resizeOnHugePages(v, std::size_t(5) << 20, threads);  // 40 MiB
      else
        resizeFaultedIn(v, std::size_t(5) << 20, threads);
      ASSERT_EQ(v.size(), std::size_t(5) << 20);
      EXPECT_EQ(v[0], 1.0);
      EXPECT_EQ(v[1], -2.0);
      EXPECT_EQ(v[2], 3.0);
      std::size_t nonZero = 0;
      for (std::size_t i = 3; i < v.size(); ++i) nonZero += v[i] != 0.0;
      EXPECT_EQ(nonZero, 0u) << threads << " threads, advised " << advised;
    }
}

// The AnonHugePages of the mapping that holds `address`, in kB; -1 when not found.
long anonHugePagesKb(const void* address) {
  std::ifstream smaps("/proc/self/smaps");
  const auto a = reinterpret_cast<std::uintptr_t>(address);
  bool inside = false;
  std::string line;
  while (std::getline(smaps, line)) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream header(line);
    if (header >> std::hex >> begin >> dash >> end && dash == '-') {
      inside = begin <= a && a < end;
      continue;
    }
    if (inside && line.rfind("AnonHugePages:", 0) == 0) return std::stol(line.substr(14));
  }
  return -1;
}

TEST(HugePages, AdvisedMemoryIsBackedByHugePagesWhereTheKernelOffersThem) {
  std::ifstream enabled("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string mode;
  std::getline(enabled, mode);
  if (mode.find("[never]") != std::string::npos || mode.empty()) GTEST_SKIP() << "transparent huge pages are off";
  std::vector<float> v;
  resizeOnHugePages(v, std::size_t(4) << 20);  // 16 MiB: at least 7 whole huge pages inside
  // The advice splits the mapping at the first whole huge page: look 2 MiB in, past the split.
  EXPECT_GE(anonHugePagesKb(reinterpret_cast<const char*>(v.data()) + (std::size_t(1) << 21)), 2048);
}

// Faulted in without the advice, a block stays in small pages where huge pages come only on
// request (Debian's "madvise"; under "always" the kernel gives them unasked).
TEST(HugePages, FaultedInMemoryIsNotAdvised) {
  std::ifstream enabled("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string mode;
  std::getline(enabled, mode);
  if (mode.find("[always]") != std::string::npos) GTEST_SKIP() << "transparent huge pages are always on";
  std::vector<float> v;
  resizeFaultedIn(v, std::size_t(4) << 20);  // 16 MiB
  EXPECT_EQ(anonHugePagesKb(reinterpret_cast<const char*>(v.data()) + (std::size_t(1) << 21)), 0);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
