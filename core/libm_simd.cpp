// The array forms of core/libm_simd-inl.h, once per Highway target (compiled with -ffp-contract=off).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "core/libm_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cmath>
#include <cstdint>

#include "core/libm_simd-inl.h"
#include "core/libm_simd.h"

HWY_BEFORE_NAMESPACE();
namespace uvtk::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// out[i] = vector(lanes) over whole vectors, scalar(i) for the undecided lanes (their indices
// gathered by the vectors and handed over in batches: a branch per vector would mispredict
// often) and for the tail. Returns how many values `scalar` computed.
template <class Vector, class Scalar>
std::size_t Blocks(double* out, std::size_t n, const Vector& vector, const Scalar& scalar) {
  std::size_t i = 0, byScalar = 0;
#if UVTK_LIBM_SIMD
  const hn::ScalableTag<double> d;
  const std::size_t lanes = hn::Lanes(d);
  constexpr std::size_t kBatch = 512;
  alignas(64) std::int64_t undecided[kBatch];
  std::size_t pending = 0;
  const auto flush = [&] {
    for (std::size_t k = 0; k < pending; ++k) out[undecided[k]] = scalar(std::size_t(undecided[k]));
    byScalar += pending, pending = 0;
  };
  for (; i + lanes <= n; i += lanes) {
    if (pending > kBatch - lanes) flush();
    auto decided = hn::FirstN(d, lanes);
    hn::StoreU(vector(d, i, decided), d, out + i);
    pending += AppendSetLanes(d, hn::Not(decided), std::int64_t(i), undecided + pending);
  }
  flush();
#else
  static_cast<void>(vector);  // no fused multiply-adds: every value is glibc's
#endif
  for (; i < n; ++i) out[i] = scalar(i), ++byScalar;
  return byScalar;
}

std::size_t HypotBlock(const double* x, const double* y, double* out, std::size_t n) {
  return Blocks(
      out, n,
      [&]([[maybe_unused]] auto d, [[maybe_unused]] std::size_t i, [[maybe_unused]] auto& decided) {
#if UVTK_LIBM_SIMD
        return Hypot(d, hn::LoadU(d, x + i), hn::LoadU(d, y + i), decided);
#endif
      },
      [&](std::size_t i) { return std::hypot(x[i], y[i]); });
}

std::size_t Log2Block(const double* x, double* out, std::size_t n) {
  return Blocks(
      out, n,
      [&]([[maybe_unused]] auto d, [[maybe_unused]] std::size_t i, [[maybe_unused]] auto& decided) {
#if UVTK_LIBM_SIMD
        return Log2(d, hn::LoadU(d, x + i), decided);
#endif
      },
      [&](std::size_t i) { return std::log2(x[i]); });
}

std::size_t Atan2Block(const double* y, const double* x, double* out, std::size_t n) {
  return Blocks(
      out, n,
      [&]([[maybe_unused]] auto d, [[maybe_unused]] std::size_t i, [[maybe_unused]] auto& decided) {
#if UVTK_LIBM_SIMD
        return Atan2(d, hn::LoadU(d, y + i), hn::LoadU(d, x + i), decided);
#endif
      },
      [&](std::size_t i) { return std::atan2(y[i], x[i]); });
}

}  // namespace uvtk::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace uvtk::libm {

HWY_EXPORT(HypotBlock);
HWY_EXPORT(Log2Block);
HWY_EXPORT(Atan2Block);

std::size_t hypot(const double* x, const double* y, double* out, std::size_t n) {
  return HWY_DYNAMIC_DISPATCH(HypotBlock)(x, y, out, n);
}
std::size_t log2(const double* x, double* out, std::size_t n) { return HWY_DYNAMIC_DISPATCH(Log2Block)(x, out, n); }
std::size_t atan2(const double* y, const double* x, double* out, std::size_t n) {
  return HWY_DYNAMIC_DISPATCH(Atan2Block)(y, x, out, n);
}

}  // namespace uvtk::libm
#endif
