// The exact arctangent's vectors, once per Highway target (param/exact_atan2.h). With fused
// multiply-adds (AVX2, AVX-512): a = min(|x|, |y|), b = max, u = a / b as a double-double, the
// nearest c = i/8, atan(u) = atan(c) + atan(r) with r = (u - c) / (1 + u c) (|r| <= 1/16) by its
// odd series to r^17, then pi/2 - ... and pi - ... for the octant, all in double-double; atan(c)
// from a table of nine read by lane permutations (a gather costs more). Without fused
// multiply-adds every value is glibc's. Compiled with -ffp-contract=off: the fused operations are the ones
// written, so the error analysis holds.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "param/exact_atan2.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cmath>
#include <cstdint>

#include "param/exact_atan2.h"

#ifndef UVTK_EXACT_ATAN2_TABLE
#define UVTK_EXACT_ATAN2_TABLE
namespace uvtk::param {
namespace {
// atan(i / 8) for i = 0..7 as hi + lo, each pair the nearest to the real value (MPFR at 300 bits;
// tests/param/exact_atan2_test.cpp reads them back), and atan(1) = pi/4.
alignas(64) constexpr double kAtanOfEighthsHi[8] = {
    0x0p+0,                 0x1.fd5ba9aac2f6ep-4, 0x1.f5b75f92c80ddp-3, 0x1.6f61941e4def1p-2,
    0x1.dac670561bb4fp-2,   0x1.1e00babdefeb4p-1, 0x1.4978fa3269ee1p-1, 0x1.700a7c5784634p-1};
alignas(64) constexpr double kAtanOfEighthsLo[8] = {
    0x0p+0,                 -0x1.cd37686760c17p-59, 0x1.8ab6e3cf7afbdp-57, -0x1.c63aae6f6e918p-56,
    0x1.a2b7f222f65e2p-56,  -0x1.928df287a668fp-58, 0x1.2419a87f2a458p-56, -0x1.8c34d25aadef6p-56};
constexpr double kQuarterPiHi = 0x1.921fb54442d18p-1, kQuarterPiLo = 0x1.1a62633145c07p-55;
}  // namespace
}  // namespace uvtk::param
#endif

HWY_BEFORE_NAMESPACE();
namespace uvtk::param {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2
// table[index] for indices 0..7, by lane permutations (one on 8-lane vectors, two on 4-lane ones).
template <class D, class VI>
hn::Vec<D> lookUpEight(D d, const double* table, VI index) {
  if constexpr (hn::MaxLanes(D()) >= 8) {
    return hn::TableLookupLanes(hn::Load(d, table), hn::IndicesFromVec(d, index));
  } else {
    const hn::RebindToSigned<D> di;
    const VI low = hn::And(index, hn::Set(di, 3));
    const auto upper = hn::RebindMask(d, index > hn::Set(di, 3));
    return hn::IfThenElse(upper, hn::TableLookupLanes(hn::Load(d, table + 4), hn::IndicesFromVec(d, low)),
                          hn::TableLookupLanes(hn::Load(d, table), hn::IndicesFromVec(d, low)));
  }
}
#endif

std::size_t ExactAtan2(const double* y, const double* x, double* out, std::size_t n) {
  std::size_t glibcCount = 0;
  std::size_t i = 0;
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2  // MulAdd is one rounding only where FMA exists
  const hn::ScalableTag<double> d;
  const hn::RebindToSigned<decltype(d)> di;
  const hn::RebindToUnsigned<decltype(d)> du;
  using V = hn::Vec<decltype(d)>;
  const std::size_t lanes = hn::Lanes(d);
  const V one = hn::Set(d, 1.0), zero = hn::Zero(d);
  // pi/2 and pi as hi + lo.
  const V halfPiHi = hn::Set(d, 0x1.921fb54442d18p+0), halfPiLo = hn::Set(d, 0x1.1a62633145c07p-54);
  const V piHi = hn::Set(d, 0x1.921fb54442d18p+1), piLo = hn::Set(d, 0x1.1a62633145c07p-53);
  const auto exponentBits = hn::Set(du, 0x7FF0000000000000ull), fractionBits = hn::Set(du, 0x000FFFFFFFFFFFFFull);
  // The undecided lanes' indices, gathered by the vectors and handed to glibc after them (a
  // branch per vector would mispredict often: nearly half the vectors hold one).
  constexpr std::size_t kBatch = 512;
  alignas(64) std::int64_t undecided[kBatch + HWY_MAX_BYTES / 8];
  std::size_t pending = 0;
  const auto flush = [&] {
    for (std::size_t k = 0; k < pending; ++k) {
      const auto j = std::size_t(undecided[k]);
      out[j] = std::atan2(y[j], x[j]);
    }
    glibcCount += pending, pending = 0;
  };
  for (; i + lanes <= n; i += lanes) {
    if (pending > kBatch - lanes) flush();
    const V vy = hn::LoadU(d, y + i), vx = hn::LoadU(d, x + i);
    const V ax = hn::Abs(vx), ay = hn::Abs(vy);
    const auto swapped = ay > ax;  // atan2 = pi/2 - atan(ax / ay)
    const auto negative = vx < zero;  // atan2 = pi - ...
    const V a = hn::Min(ax, ay), b = hn::Max(ax, ay);
    // u + du = a / b to about 2^-106; the exact remainder a - u b by one fused operation.
    const V u = a / b;
    const V du0 = hn::NegMulAdd(u, b, a) / b;
    // Where glibc takes a path of its own (zeros, infinities, NaN, scaled or extreme exponents,
    // u below 2^-50), or the comparisons below fail (NaN), the lane is glibc's.
    const V large = hn::Set(d, 0x1p500);  // each compared: Min and Max may drop a NaN
    auto decided = hn::And(hn::And(hn::And(ax <= large, ay <= large), a >= hn::Set(d, 0x1p-500)), u >= hn::Set(d, 0x1p-50));
    // c = i/8 nearest u; u - c is exact (Sterbenz: u/2 <= c <= 2u for i >= 1).
    const V k = hn::Round(u * hn::Set(d, 8.0));
    const auto index = hn::And(hn::ConvertTo(di, k), hn::Set(di, 7));
    const auto one8 = k == hn::Set(d, 8.0);  // c = 1
    const V atanCHi = hn::IfThenElse(one8, hn::Set(d, kQuarterPiHi), lookUpEight(d, kAtanOfEighthsHi, index));
    const V atanCLo = hn::IfThenElse(one8, hn::Set(d, kQuarterPiLo), lookUpEight(d, kAtanOfEighthsLo, index));
    const V c = k * hn::Set(d, 1.0 / 8);
    // 1 + u c + du c as hi + lo: u c exactly as p + pError, then Fast2Sum(1, p) (p <= 1).
    const V p = u * c, pError = hn::MulSub(u, c, p);
    const V denominatorHi = one + p;
    const V denominatorLo = ((one - denominatorHi) + p) + pError + du0 * c;
    // r = (u - c + du) / denominator as hi + lo, the first quotient's remainder by one fused operation.
    const V numerator = u - c;
    const V rHi = (numerator + du0) / denominatorHi;
    const V rLo = (hn::NegMulAdd(rHi, denominatorHi, numerator) + du0 - rHi * denominatorLo) / denominatorHi;
    // atan(r) = r - r^3/3 + r^5/5 - ... : the terms after r in double (|r| <= 2^-4: the first
    // omitted, r^19/19, is below 2^-80 r).
    const V r2 = rHi * rHi;
    V series = hn::Set(d, 1.0 / 17);
    for (const double coefficient : {-1.0 / 15, 1.0 / 13, -1.0 / 11, 1.0 / 9, -1.0 / 7, 1.0 / 5, -1.0 / 3})
      series = hn::MulAdd(series, r2, hn::Set(d, coefficient));
    const V tail = hn::MulAdd(rHi * r2, series, rLo);
    // atan(u) = atan(c) + atan(r): Fast2Sum of the leading parts (|atan(c)| >= |r| or c = 0).
    const V sumHi = atanCHi + rHi;
    const V sumLo = ((atanCHi - sumHi) + rHi) + atanCLo + tail;
    // The octant: pi/2 - atan(u) where |y| > |x|, then pi - that where x < 0 (Fast2Sums: the
    // constant is the larger).
    const V halfHi = halfPiHi - sumHi;
    const V halfLo = ((halfPiHi - halfHi) - sumHi) + halfPiLo - sumLo;
    V hi = hn::IfThenElse(swapped, halfHi, sumHi), lo = hn::IfThenElse(swapped, halfLo, sumLo);
    const V backHi = piHi - hi;
    const V backLo = ((piHi - backHi) - hi) + piLo - lo;
    hi = hn::IfThenElse(negative, backHi, hi), lo = hn::IfThenElse(negative, backLo, lo);
    // The rounded value and where the double-double lies from it, in ulps of it (its binade's;
    // a power of two, whose ulp below is half, is left to glibc).
    const V rounded = hi + lo;
    const V offset = (hi - rounded) + lo;  // hi - rounded is exact: they are within an ulp
    const auto bits = hn::BitCast(du, rounded);
    const V ulp = hn::BitCast(d, hn::And(bits, exponentBits)) * hn::Set(d, 0x1p-52);
    decided = hn::AndNot(hn::RebindMask(d, hn::And(bits, fractionBits) == hn::Zero(du)), decided);
    // glibc's result lies within B ulp of the true value, B its bound for the branch it takes
    // (x > 0 and |y| < |x|: 0.504 for u < 1/16, else 0.56; every other branch at most 0.503).
    // Where the true value lies less than 1 - B ulp from the rounded value, every other double is
    // more than B away, so glibc returns the rounded value: |offset| < 1 - B, less 0.02 for this
    // evaluation's error (below 2^-12 ulp) and a margin.
    const auto firstOctant = hn::AndNot(negative, hn::Not(swapped));
    const V bound = hn::IfThenElse(
        firstOctant, hn::IfThenElse(u < hn::Set(d, 1.0 / 16), hn::Set(d, 0.504), hn::Set(d, 0.56)), hn::Set(d, 0.503));
    decided = hn::And(decided, hn::Abs(offset) < (hn::Set(d, 0.98) - bound) * ulp);
    hn::StoreU(hn::CopySign(rounded, vy), d, out + i);
    pending += hn::CompressStore(hn::Iota(di, std::int64_t(i)), hn::RebindMask(di, hn::Not(decided)), di,
                                 undecided + pending);
  }
  flush();
#endif
  for (; i < n; ++i) out[i] = std::atan2(y[i], x[i]), ++glibcCount;
  return glibcCount;
}

}  // namespace HWY_NAMESPACE
}  // namespace uvtk::param
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace uvtk::param {

HWY_EXPORT(ExactAtan2);

std::size_t exactAtan2Block(const double* y, const double* x, double* out, std::size_t n) {
  return HWY_DYNAMIC_DISPATCH(ExactAtan2)(y, x, out, n);
}

}  // namespace uvtk::param
#endif
