// Highway's two run-time entry points of dynamic dispatch (hwy/targets.h), defined here so that no
// uvtk program loads libhwy.so: Debian's libhwy 1.0.3 calibrates a timer (hwy::platform::
// TimerResolution) in a static initializer of every process that loads it, 3.3 ms of the 15 ms a
// `uvtk --version` took (perf record, 2026-12-02). Everything else of Highway that uvtk uses is
// in its headers. The targets are those Highway 1.0.3's targets.cc finds, from the same CPUID
// bits and the same check that the operating system saves the registers (XCR0).
#include <cpuid.h>

#include <cstdint>

#include <hwy/targets.h>

namespace hwy {

namespace {

#if HWY_ARCH_X86
bool bit(std::uint32_t word, int index) { return (word >> index) & 1u; }

std::int64_t x86Targets() {
  // Four CPUIDs, each about 6 us on a virtual machine (__get_cpuid would ask for the highest leaf
  // before each). Every x86-64 processor has leaf 1 and extended leaf 0x80000001 (its long-mode bit).
  std::uint32_t a = 0, b = 0, c = 0, d = 0;
  __cpuid(0, a, b, c, d);
  const std::uint32_t highestLeaf = a;
  __cpuid(1, a, b, c, d);
  const std::uint32_t c1 = c, d1 = d;
  std::uint32_t b7 = 0, c7 = 0;
  if (highestLeaf >= 7) {
    __cpuid_count(7, 0, a, b, c, d);
    b7 = b, c7 = c;
  }
  __cpuid(0x80000001u, a, b, c, d);
  const std::uint32_t cExtended = c;

  const bool ssse3 = bit(d1, 25) && bit(d1, 26) && bit(c1, 0) && bit(c1, 9);            // SSE, SSE2, SSE3, SSSE3
  const bool sse4 = ssse3 && bit(c1, 19) && bit(c1, 20) && bit(c1, 1) && bit(c1, 25);   // SSE4.1, 4.2, CLMUL, AES
  const bool avx2 = sse4 && bit(c1, 28) && bit(b7, 5) && bit(b7, 3) && bit(b7, 8) &&    // AVX, AVX2, BMI, BMI2
                    bit(c1, 12) && bit(cExtended, 5) && bit(c1, 29);                     // FMA, LZCNT, F16C
  const bool avx3 = avx2 && bit(b7, 16) && bit(b7, 31) && bit(b7, 17) && bit(b7, 30);  // AVX-512 F, VL, DQ, BW
  const bool avx3dl = avx3 && bit(c7, 11) && bit(c7, 10) && bit(c7, 1) && bit(c7, 6) &&  // VNNI, VPCLMULQDQ, VBMI, VBMI2
                      bit(c7, 9) && bit(c7, 14) && bit(c7, 12);                          // VAES, VPOPCNTDQ, BITALG
  std::int64_t targets = (ssse3 ? HWY_SSSE3 : 0) | (sse4 ? HWY_SSE4 : 0) | (avx2 ? HWY_AVX2 : 0) |
                         (avx3 ? HWY_AVX3 : 0) | (avx3dl ? HWY_AVX3_DL : 0);
  // Registers the operating system does not save across a context switch are not usable.
  std::uint32_t xcr0 = 0;
  if (bit(c1, 27)) {  // OSXSAVE
    std::uint32_t high = 0;
    __asm__ volatile("xgetbv" : "=a"(xcr0), "=d"(high) : "c"(0));
  }
  if (!bit(xcr0, 1)) targets &= ~(HWY_SSSE3 | HWY_SSE4);
  if (!bit(xcr0, 2)) targets &= ~(HWY_AVX2 | HWY_AVX3 | HWY_AVX3_DL);
  if (!bit(xcr0, 5) || !bit(xcr0, 6) || !bit(xcr0, 7)) targets &= ~(HWY_AVX3 | HWY_AVX3_DL);
  return targets;
}
#endif

}  // namespace

int64_t SupportedTargets() {
  static const std::int64_t supported = [] {
    std::int64_t targets = HWY_EMU128 | HWY_SCALAR | HWY_STATIC_TARGET;
#if HWY_ARCH_X86
    targets |= x86Targets();
#endif
    return targets;
  }();
  return supported;
}

ChosenTarget& GetChosenTarget() {
  static ChosenTarget chosen;
  return chosen;
}

}  // namespace hwy
