// glibc's hypot, log2 and atan2 on whole SIMD vectors, with glibc's bits (Google Highway, included
// once per target by a file compiled with -ffp-contract=off, so that the fused multiply-adds are
// the ones written). hypot is glibc 2.35's own algorithm (Borges 2019, "An Improved Algorithm for
// hypot(a,b)", the corrected unfused variant, as glibc's generic __hypot computes it) in its
// common range. log2 and atan2 are evaluated in double-double to about 2^-10 ulp: where that
// decides the correctly rounded value and glibc's error bound for the function leaves glibc no
// other, that is glibc's value. Every other lane (outside the common range, or near a rounding
// boundary: a few lanes in a hundred) is reported undecided for the caller to hand to glibc.
// docs/precision.md, "Math mode"; tests/core/libm_simd_test.cpp checks the bits against glibc.
// Outside a target with fused multiply-adds (UVTK_LIBM_SIMD 0) nothing is defined: callers use glibc.
#if defined(UVTK_CORE_LIBM_SIMD_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef UVTK_CORE_LIBM_SIMD_INL_H_
#undef UVTK_CORE_LIBM_SIMD_INL_H_
#else
#define UVTK_CORE_LIBM_SIMD_INL_H_
#endif

#include <hwy/highway.h>

#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace uvtk::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Fused multiply-adds round once only where the processor has them.
#undef UVTK_LIBM_SIMD
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2
#define UVTK_LIBM_SIMD 1
#else
#define UVTK_LIBM_SIMD 0
#endif

#if UVTK_LIBM_SIMD

// Whole numbers of magnitude below 2^51 between double and int64 lanes, exactly, through the bits of
// 1.5 * 2^52 + n: an addition and a subtraction, where AVX2 has no instruction for either conversion
// (Highway's emulation takes about 30 operations from double, 8 to double).
template <class D, class V = hn::Vec<D>>
hn::Vec<hn::RebindToSigned<D>> WholeToInt64(D d, V whole) {
  const hn::RebindToSigned<D> di;
  const V magic = hn::Set(d, 0x1.8p52);
  return hn::Sub(hn::BitCast(di, whole + magic), hn::BitCast(di, magic));
}
template <class D, class VI>
hn::Vec<D> WholeToDouble(D d, VI whole) {
  const hn::Vec<D> magic = hn::Set(d, 0x1.8p52);
  return hn::BitCast(d, hn::Add(whole, hn::BitCast(hn::RebindToSigned<D>(), magic))) - magic;
}

// Appends first + k for each set lane k of the mask, in order, at out (which has room for a whole
// vector); returns how many. Without a branch per lane: which lanes are set is unpredictable. (Highway's
// CompressStore does the same, but GCC 12 copies its 512-byte table to the stack on every AVX2 call.)
template <class D>
std::size_t AppendSetLanes(D d, hn::Mask<D> mask, std::int64_t first, std::int64_t* out) {
  static_assert(hn::MaxLanes(D()) <= 8);
  std::uint8_t bits[8] = {};
  hn::StoreMaskBits(d, mask, bits);
  std::size_t count = 0;
  for (std::size_t k = 0; k < hn::Lanes(d); ++k) out[count] = first + std::int64_t(k), count += (bits[0] >> k) & 1u;
  return count;
}

// The rounded value of hi + lo (lo small beside hi, hi + lo within 2^-10 ulp of a function's true
// value), with `decided` cleared where a result of glibc's, within `bound` ulp of the true value,
// could be another double: where the true value lies 1 - bound ulp or more from the rounded one,
// less 0.02 for this evaluation's error and a margin. Zero, a power of two (whose ulp below is
// half) and non-finite values are undecided too.
template <class D, class V = hn::Vec<D>>
V RoundDecided(D d, V hi, V lo, V bound, hn::Mask<D>& decided) {
  const hn::RebindToUnsigned<D> du;
  const V rounded = hi + lo;
  const V offset = (hi - rounded) + lo;  // exact: hi and rounded lie within an ulp
  const auto bits = hn::BitCast(du, rounded);
  const auto exponent = hn::And(bits, hn::Set(du, 0x7FF0000000000000ull));
  const V ulp = hn::BitCast(d, exponent) * hn::Set(d, 0x1p-52);
  const auto powerOfTwo = hn::RebindMask(d, hn::And(bits, hn::Set(du, 0x000FFFFFFFFFFFFFull)) == hn::Zero(du));
  const auto normal = hn::RebindMask(d, hn::And(exponent != hn::Zero(du), exponent != hn::Set(du, 0x7FF0000000000000ull)));
  decided = hn::And(decided, hn::AndNot(powerOfTwo, normal));
  decided = hn::And(decided, hn::Abs(offset) < (hn::Set(d, 0.98) - bound) * ulp);
  return rounded;
}

// glibc's hypot(x, y) where 2^-500 <= min(|x|, |y|), max(|x|, |y|) <= 2^500 and the smaller is
// more than 2^-50 of the larger (else undecided; min = 0 gives the larger, as glibc does).
template <class D, class V = hn::Vec<D>>
V Hypot(D d, V x, V y, hn::Mask<D>& decided) {
  const V a = hn::Abs(x), b = hn::Abs(y);
  const V ax = hn::Max(a, b), ay = hn::Min(a, b);  // NaN lanes are cleared below
  const V two = hn::Set(d, 2.0);
  // Borges 2019, "An Improved Algorithm for hypot(a,b)": h = sqrt(ax^2 + ay^2), corrected by its
  // residual expanded without cancellation, as glibc's __hypot (the variant without FMA).
  V h = hn::Sqrt(ax * ax + ay * ay);
  const auto nearDiagonal = h <= two * ay;
  const V deltaY = h - ay, deltaX = h - ax;
  const V t1 = hn::IfThenElse(nearDiagonal, ax * (two * deltaY - ax), two * deltaX * (ax - two * ay));
  const V t2 = hn::IfThenElse(nearDiagonal, (deltaY - two * (ax - ay)) * deltaY,
                              (hn::Set(d, 4.0) * deltaX - ay) * ay + deltaX * deltaX);
  h = h - (t1 + t2) / (two * h);
  const auto numbers = hn::And(a == a, b == b);  // Max and Min may drop a NaN
  const auto zero = hn::And(numbers, hn::And(ay == hn::Zero(d), ax <= hn::Set(d, 0x1p500)));
  const auto common = hn::And(numbers, hn::And(hn::And(ax <= hn::Set(d, 0x1p500), ay >= hn::Set(d, 0x1p-500)),
                                               ay > ax * hn::Set(d, 0x1p-50)));
  decided = hn::And(decided, hn::Or(common, zero));
  return hn::IfThenElse(zero, ax, h);
}

namespace libm_detail {
// Per 32nd of [1, 2), i: 1/c for c the interval's middle (a double), k_i in {0, 1} and
// -log2(1/c) - k_i as hi + lo (MPFR at 300 bits; from i = 13 on, log2 x is computed as
// (e + 1) + log2(m / 2), so that log2 stays exact near 1 from below). Intervals 0 and 31 use
// 1/c = 1 and 1/2: their r below is then exact and nothing cancels near x = 1.
alignas(64) inline constexpr double kLog2InverseC[32] = {
    0x1p+0, 0x1.e9131abf0b767p-1, 0x1.dae6076b981dbp-1, 0x1.cd85689039b0bp-1, 0x1.c0e070381c0ep-1,
    0x1.b4e81b4e81b4fp-1, 0x1.a98ef606a63bep-1, 0x1.9ec8e951033d9p-1, 0x1.948b0fcd6e9ep-1, 0x1.8acb90f6bf3aap-1,
    0x1.8181818181818p-1, 0x1.78a4c8178a4c8p-1, 0x1.702e05c0b817p-1, 0x1.6816816816817p-1, 0x1.6058160581606p-1,
    0x1.58ed2308158edp-1, 0x1.51d07eae2f815p-1, 0x1.4afd6a052bf5bp-1, 0x1.446f86562d9fbp-1, 0x1.3e22cbce4a902p-1,
    0x1.3813813813814p-1, 0x1.323e34a2b10bfp-1, 0x1.2c9fb4d812cap-1, 0x1.27350b8812735p-1, 0x1.21fb78121fb78p-1,
    0x1.1cf06ada2811dp-1, 0x1.1811811811812p-1, 0x1.135c81135c811p-1, 0x1.0ecf56be69c9p-1, 0x1.0a6810a6810a7p-1,
    0x1.0624dd2f1a9fcp-1, 0x1p-1};
alignas(64) inline constexpr double kLog2TableHi[32] = {
    0x0p+0, 0x1.0eb389fa29f9dp-4, 0x1.bc84240adabb9p-4, 0x1.32ae9e278ae19p-3, 0x1.84c2bd02f03b6p-3,
    0x1.d49ee4c32596cp-3, 0x1.11307dad30b74p-2, 0x1.37124cea4cdedp-2, 0x1.5c01a39fbd689p-2, 0x1.800a563161c53p-2,
    0x1.a33760a7f6051p-2, 0x1.c592fad295b57p-2, 0x1.e726aa1e754d3p-2, -0x1.f804ae8d0cd04p-2, -0x1.d7e6c0abc357bp-2,
    -0x1.b877c57b1b06fp-2, -0x1.99b072a96c6b2p-2, -0x1.7b89f02cf2aafp-2, -0x1.5dfdcf1eeae0fp-2, -0x1.4106017c3ecap-2,
    -0x1.249cd2b13cd6fp-2, -0x1.08bce0d95fa36p-2, -0x1.dac22d3e441d6p-3, -0x1.a5094b54d2828p-3, -0x1.7046031c79f84p-3,
    -0x1.3c6fb650cde51p-3, -0x1.097e38ce6064ep-3, -0x1.aed391ab6674ap-4, -0x1.4c560fe68af8bp-4, -0x1.d6ebd1f1fec14p-5,
    -0x1.184b8e4c56afcp-5, 0x0p+0};
alignas(64) inline constexpr double kLog2TableLo[32] = {
    0x0p+0, -0x1.4171a24e24942p-58, 0x1.0446f0f41f7cbp-59, -0x1.9855ac57fff35p-60, -0x1.f84eecba83c8ep-59,
    0x1.cb858f16e12d5p-57, 0x1.47523d83ea177p-58, 0x1.05c3d2cf67559p-56, 0x1.0f48164c2367p-58, -0x1.3c83c71cbe6b3p-57,
    -0x1.8ba864ee95507p-60, -0x1.295fe9031806bp-57, -0x1.d821361d7bb7ep-57, 0x1.7f26898edf303p-56, 0x1.4a0f01ebcfde3p-57,
    -0x1.67605cac48719p-56, 0x1.f985970c7a96cp-59, -0x1.9dea463052c2cp-56, 0x1.ac206233f7e96p-56, -0x1.355746781a69ap-56,
    0x1.6b4a82d7fe1a1p-56, 0x1.07bb7f5aae567p-60, 0x1.f119e79f40af4p-59, 0x1.98dc4a74f5539p-58, -0x1.5be41b06e36f6p-61,
    -0x1.0be4fa2f11c07p-57, -0x1.99dad32e3848cp-57, 0x1.90f87244276f2p-59, 0x1.e9a084e2495d3p-61, -0x1.27597bcf45294p-63,
    -0x1.f4850f40e51c9p-59, 0x0p+0};
constexpr double kInverseLn2Hi = 0x1.71547652b82fep+0, kInverseLn2Lo = 0x1.777d0ffda0d24p-56;

// table[index] for indices 0..kEntries-1 (a multiple of the lane count), by lane permutations:
// a gather costs more.
template <std::size_t kEntries, class D, class VI>
hn::Vec<D> LookUp(D d, const double* table, VI index) {
  const hn::RebindToSigned<D> di;
  constexpr std::size_t kLanes = hn::MaxLanes(D());
  static_assert(kEntries % kLanes == 0 && (kLanes == 4 || kLanes == 8));
  const auto lane = hn::IndicesFromVec(d, hn::And(index, hn::Set(di, std::int64_t(kLanes - 1))));
  const VI part = hn::ShiftRight<kLanes == 8 ? 3 : 2>(index);
  hn::Vec<D> out = hn::TableLookupLanes(hn::Load(d, table), lane);
  for (std::size_t k = 1; k < kEntries / kLanes; ++k)
    out = hn::IfThenElse(hn::RebindMask(d, part == hn::Set(di, std::int64_t(k))),
                         hn::TableLookupLanes(hn::Load(d, table + k * kLanes), lane), out);
  return out;
}

// atan(i / 8) for i = 0..7 as hi + lo, each pair the nearest to the real value (MPFR at 300 bits),
// and atan(1) = pi/4; pi/2 and pi.
alignas(64) inline constexpr double kAtanOfEighthsHi[8] = {
    0x0p+0,               0x1.fd5ba9aac2f6ep-4, 0x1.f5b75f92c80ddp-3, 0x1.6f61941e4def1p-2,
    0x1.dac670561bb4fp-2, 0x1.1e00babdefeb4p-1, 0x1.4978fa3269ee1p-1, 0x1.700a7c5784634p-1};
alignas(64) inline constexpr double kAtanOfEighthsLo[8] = {
    0x0p+0,                -0x1.cd37686760c17p-59, 0x1.8ab6e3cf7afbdp-57,  -0x1.c63aae6f6e918p-56,
    0x1.a2b7f222f65e2p-56, -0x1.928df287a668fp-58, 0x1.2419a87f2a458p-56, -0x1.8c34d25aadef6p-56};
constexpr double kQuarterPiHi = 0x1.921fb54442d18p-1, kQuarterPiLo = 0x1.1a62633145c07p-55;
constexpr double kHalfPiHi = 0x1.921fb54442d18p+0, kHalfPiLo = 0x1.1a62633145c07p-54;
constexpr double kPiHi = 0x1.921fb54442d18p+1, kPiLo = 0x1.1a62633145c07p-53;
}  // namespace libm_detail

// glibc's log2(x) for positive normal x (else undecided). glibc 2.36's log2 is the Arm
// optimized-routines algorithm, within 0.547 ulp by its documentation (0.5455 the worst of 2 x 10^7
// arguments measured against MPFR here); 0.55 is taken.
template <class D, class V = hn::Vec<D>>
V Log2(D d, V x, hn::Mask<D>& decided) {
  namespace t = libm_detail;
  const hn::RebindToSigned<D> di;
  const hn::RebindToUnsigned<D> du;
  const auto bits = hn::BitCast(du, x);
  const auto biased = hn::ShiftRight<52>(bits);  // x > 0: no sign bit
  decided = hn::And(decided, hn::And(x >= hn::Set(d, 0x1p-1022), x <= hn::Set(d, 0x1.fffffffffffffp+1023)));
  // x = 2^e m, m in [1, 2); interval i of m by its top five fraction bits.
  const V m = hn::BitCast(d, hn::Or(hn::And(bits, hn::Set(du, 0x000FFFFFFFFFFFFFull)), hn::Set(du, 0x3FF0000000000000ull)));
  const auto index = hn::BitCast(di, hn::And(hn::ShiftRight<47>(bits), hn::Set(du, 31)));
  const V inverseC = t::LookUp<32>(d, t::kLog2InverseC, index);
  const V tableHi = t::LookUp<32>(d, t::kLog2TableHi, index), tableLo = t::LookUp<32>(d, t::kLog2TableLo, index);
  const V e = WholeToDouble(d, hn::BitCast(di, biased)) - hn::Set(d, 1023.0);
  const V k = e + hn::IfThenElseZero(hn::RebindMask(d, index > hn::Set(di, 12)), hn::Set(d, 1.0));
  // r = m / c - 1 as hi + lo: m (1/c) exactly by one fused operation, less 1 (exact: within 2).
  const V p = m * inverseC;
  const V rLo = hn::MulSub(m, inverseC, p);
  const V rHi = p - hn::Set(d, 1.0);
  // ln(1 + r) = r - r^2/2 + r^3 (1/3 - r/4 + ... + r^10/13), |r| <= 2^-5: the first omitted term
  // is below 2^-69 r. r^2 exactly as hi + lo.
  const V r2 = rHi * rHi, r2Lo = hn::MulSub(rHi, rHi, r2);
  V series = hn::Set(d, 1.0 / 13);
  for (const double c : {-1.0 / 12, 1.0 / 11, -1.0 / 10, 1.0 / 9, -1.0 / 8, 1.0 / 7, -1.0 / 6, 1.0 / 5, -1.0 / 4, 1.0 / 3})
    series = hn::MulAdd(series, rHi, hn::Set(d, c));
  const V half = hn::Set(d, 0.5);
  const V lnHi = rHi - half * r2;  // Fast2Sum: |r| >= r^2/2
  const V lnLo = ((rHi - lnHi) - half * r2) + rLo - half * r2Lo - rHi * rLo + (r2 * rHi) * series;
  // log2(1 + r) = ln(1 + r) / ln 2 as hi + lo.
  const V invHi = hn::Set(d, t::kInverseLn2Hi), invLo = hn::Set(d, t::kInverseLn2Lo);
  const V logHi = lnHi * invHi;
  const V logLo = hn::MulSub(lnHi, invHi, logHi) + lnHi * invLo + lnLo * invHi;
  // k + table + log2(1 + r): TwoSum of k and the table's hi, then of that and logHi.
  const V a = k + tableHi, aV = a - k, aLo = (k - (a - aV)) + (tableHi - aV);
  const V s = a + logHi, sV = s - a, sLo = (a - (s - sV)) + (logHi - sV);
  return RoundDecided(d, s, sLo + aLo + tableLo + logLo, hn::Set(d, 0.55), decided);
}

// glibc's atan2(y, x) where neither is zero, infinite or NaN, both lie within 2^-500 .. 2^500 and
// the smaller of |x|, |y| is at least 2^-50 of the larger (else undecided). a = min(|x|, |y|),
// b = max, u = a / b as hi + lo, c = i/8 nearest u, atan(u) = atan(c) + atan(r) with
// r = (u - c) / (1 + u c), |r| <= 1/16, by its odd series to r^17; then pi/2 - ... and pi - ...
// for the octant, all in double-double. glibc 2.36's bound (the "Max ULP" of each branch of its
// e_atan2.c): 0.504 for x > 0, |y| < |x| and u < 1/16, 0.56 for x > 0, |y| < |x| and u >= 1/16,
// at most 0.503 in every other branch.
template <class D, class V = hn::Vec<D>>
V Atan2(D d, V y, V x, hn::Mask<D>& decided) {
  namespace t = libm_detail;
  const hn::RebindToSigned<D> di;
  const V one = hn::Set(d, 1.0);
  const V ax = hn::Abs(x), ay = hn::Abs(y);
  const auto swapped = ay > ax;       // atan2 = pi/2 - atan(ax / ay)
  const auto negative = x < hn::Zero(d);  // atan2 = pi - ...
  const V a = hn::Min(ax, ay), b = hn::Max(ax, ay);
  // u + du = a / b to about 2^-106; the exact remainder a - u b by one fused operation.
  const V u = a / b;
  const V du = hn::NegMulAdd(u, b, a) / b;
  const V large = hn::Set(d, 0x1p500);  // each compared: Min and Max may drop a NaN
  decided = hn::And(decided, hn::And(hn::And(hn::And(ax <= large, ay <= large), a >= hn::Set(d, 0x1p-500)),
                                     u >= hn::Set(d, 0x1p-50)));
  // c = i/8 nearest u; u - c is exact (Sterbenz: u/2 <= c <= 2u for i >= 1).
  const V k = hn::Round(u * hn::Set(d, 8.0));
  const auto index = hn::And(WholeToInt64(d, k), hn::Set(di, 7));
  const auto whole = k == hn::Set(d, 8.0);  // c = 1
  const V atanCHi = hn::IfThenElse(whole, hn::Set(d, t::kQuarterPiHi), t::LookUp<8>(d, t::kAtanOfEighthsHi, index));
  const V atanCLo = hn::IfThenElse(whole, hn::Set(d, t::kQuarterPiLo), t::LookUp<8>(d, t::kAtanOfEighthsLo, index));
  const V c = k * hn::Set(d, 1.0 / 8);
  // 1 + u c + du c as hi + lo: u c exactly as p + pError, then Fast2Sum(1, p) (p <= 1).
  const V p = u * c, pError = hn::MulSub(u, c, p);
  const V denominatorHi = one + p;
  const V denominatorLo = ((one - denominatorHi) + p) + pError + du * c;
  // r = (u - c + du) / denominator as hi + lo, the first quotient's remainder by one fused operation.
  const V numerator = u - c;
  const V rHi = (numerator + du) / denominatorHi;
  const V rLo = (hn::NegMulAdd(rHi, denominatorHi, numerator) + du - rHi * denominatorLo) / denominatorHi;
  // atan(r) = r - r^3/3 + r^5/5 - ...: the terms after r in double (|r| <= 2^-4: the first
  // omitted, r^19/19, is below 2^-80 r).
  const V r2 = rHi * rHi;
  V series = hn::Set(d, 1.0 / 17);
  for (const double coefficient : {-1.0 / 15, 1.0 / 13, -1.0 / 11, 1.0 / 9, -1.0 / 7, 1.0 / 5, -1.0 / 3})
    series = hn::MulAdd(series, r2, hn::Set(d, coefficient));
  const V tail = hn::MulAdd(rHi * r2, series, rLo);
  // atan(u) = atan(c) + atan(r): Fast2Sum of the leading parts (|atan(c)| >= |r| or c = 0).
  const V sumHi = atanCHi + rHi;
  const V sumLo = ((atanCHi - sumHi) + rHi) + atanCLo + tail;
  // The octant (Fast2Sums: the constant is the larger).
  const V halfPiHi = hn::Set(d, t::kHalfPiHi), piHi = hn::Set(d, t::kPiHi);
  const V halfHi = halfPiHi - sumHi;
  const V halfLo = ((halfPiHi - halfHi) - sumHi) + hn::Set(d, t::kHalfPiLo) - sumLo;
  V hi = hn::IfThenElse(swapped, halfHi, sumHi), lo = hn::IfThenElse(swapped, halfLo, sumLo);
  const V backHi = piHi - hi;
  const V backLo = ((piHi - backHi) - hi) + hn::Set(d, t::kPiLo) - lo;
  hi = hn::IfThenElse(negative, backHi, hi), lo = hn::IfThenElse(negative, backLo, lo);
  const auto firstOctant = hn::AndNot(negative, hn::Not(swapped));
  const V bound = hn::IfThenElse(
      firstOctant, hn::IfThenElse(u < hn::Set(d, 1.0 / 16), hn::Set(d, 0.504), hn::Set(d, 0.56)), hn::Set(d, 0.503));
  return hn::CopySign(RoundDecided(d, hi, lo, bound, decided), y);
}

#endif  // UVTK_LIBM_SIMD

}  // namespace uvtk::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // include guard
