// core/simd_targets.cpp's processor check against the compiler's own (__builtin_cpu_supports, which
// also asks the operating system whether it saves the registers).
#include <gtest/gtest.h>

#include <hwy/targets.h>

namespace {
namespace UVTK_TEST_FILE {

TEST(SimdTargets, AreTheOnesTheProcessorAndTheSystemSupport) {
  const int64_t targets = hwy::SupportedTargets();
  EXPECT_NE(targets & HWY_EMU128, 0);
  EXPECT_NE(targets & HWY_SCALAR, 0);
#if HWY_ARCH_X86
  __builtin_cpu_init();
  const bool sse4 = __builtin_cpu_supports("ssse3") && __builtin_cpu_supports("sse4.2") &&
                    __builtin_cpu_supports("aes") && __builtin_cpu_supports("pclmul");
  const bool avx2 = sse4 && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
                    __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
  const bool avx3 = avx2 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                    __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw");
  EXPECT_EQ((targets & HWY_SSE4) != 0, sse4);
  EXPECT_EQ((targets & HWY_AVX2) != 0, avx2);
  EXPECT_EQ((targets & HWY_AVX3) != 0, avx3);
  if (targets & HWY_AVX3_DL) {
    EXPECT_TRUE(avx3);
  }
#endif
  // The dispatch picks the best of them that the build compiled.
  hwy::GetChosenTarget().Update(targets);
  EXPECT_TRUE(hwy::GetChosenTarget().IsInitialized());
}

}  // namespace UVTK_TEST_FILE
}  // namespace
