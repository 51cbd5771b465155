// The per-vertex steps of render/raster_simd.h, once per Highway target; compiled with
// -ffp-contract=off, so that every lane rounds as the scalar statement does.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/raster_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/raster_simd.h"

HWY_BEFORE_NAMESPACE();
namespace uvtk::render::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

std::pair<double, double> TransformToClip(const Mat4& m, const Vec3* positions, Vec4* clip, std::size_t n) {
  const hn::ScalableTag<double> d;
  using V = hn::Vec<decltype(d)>;
  const std::size_t lanes = hn::Lanes(d);
  const double* in = positions->data();
  double* out = clip->data();
  V least = hn::Set(d, HUGE_VAL), greatest = hn::Zero(d);
  const auto row = [&](int i, V x, V y, V z) {
    return ((hn::Set(d, m(i, 0)) * x + hn::Set(d, m(i, 1)) * y) + hn::Set(d, m(i, 2)) * z) + hn::Set(d, m(i, 3));
  };
  const auto extent = [&](V c0, V c1, V c2, V c3) {  // the largest finite |coordinate|, 0 if none
    V e = hn::Zero(d);
    for (const V c : {c0, c1, c2, c3}) e = hn::Max(e, hn::IfThenElseZero(hn::IsFinite(c), hn::Abs(c)));
    const auto some = e > hn::Zero(d);
    least = hn::IfThenElse(some, hn::Min(least, e), least), greatest = hn::Max(greatest, e);
  };
  std::size_t v = 0;
  for (; v + lanes <= n; v += lanes) {
    V x, y, z;
    hn::LoadInterleaved3(d, in + 3 * v, x, y, z);
    const V c0 = row(0, x, y, z), c1 = row(1, x, y, z), c2 = row(2, x, y, z), c3 = row(3, x, y, z);
    hn::StoreInterleaved4(c0, c1, c2, c3, d, out + 4 * v);
    extent(c0, c1, c2, c3);
  }
  double l = hn::GetLane(hn::MinOfLanes(d, least)), g = hn::GetLane(hn::MaxOfLanes(d, greatest));
  for (; v < n; ++v) {  // the tail, as Eigen
    clip[v] = m * positions[v].homogeneous();
    double e = 0.0;
    for (int i = 0; i < 4; ++i)
      if (std::isfinite(clip[v][i])) e = std::max(e, std::fabs(clip[v][i]));
    if (e > 0.0) l = std::min(l, e), g = std::max(g, e);
  }
  return {l, g};
}

// snapToWindow, and with `test` false every point snapped as if inside (snapPoint).
void SnapPoints(const Vec4* clip, std::size_t n, double guard, int width, int height, bool test, std::int64_t* window) {
  const hn::ScalableTag<double> d;
  const hn::RebindToSigned<decltype(d)> di;
  using V = hn::Vec<decltype(d)>;
  using VI = hn::Vec<decltype(di)>;
  const std::size_t lanes = hn::Lanes(d);
  const V g = hn::Set(d, guard), zero = hn::Zero(d), one = hn::Set(d, 1.0), half = hn::Set(d, 0.5);
  const V w = hn::Set(d, double(width)), h = hn::Set(d, double(height)), subpixel = hn::Set(d, 256.0);
  // llround of |v| < 2^62 without the library call: truncation, then the fraction's rounding.
  const auto roundHalfAway = [&](V v) {
    const VI i = hn::ConvertTo(di, v);
    const V fraction = v - hn::ConvertTo(d, i);
    const VI up = hn::IfThenElseZero(hn::RebindMask(di, fraction >= half), hn::Set(di, 1));
    const VI down = hn::IfThenElseZero(hn::RebindMask(di, fraction <= hn::Neg(half)), hn::Set(di, 1));
    return hn::Sub(hn::Add(i, up), down);
  };
  const auto snap = [&](const double* in, std::int64_t* out) {
    V x, y, z, cw;
    hn::LoadInterleaved4(d, in, x, y, z, cw);
    auto inside = hn::FirstN(d, lanes);
    if (test) {
      inside = hn::And(hn::And(hn::IsFinite(x), hn::IsFinite(y)), hn::And(hn::IsFinite(z), hn::IsFinite(cw)));
      inside = hn::And(inside, cw > zero);
      // The clip planes: near, far, and the guard band in x and y.
      const V gw = g * cw;
      inside = hn::And(inside, hn::And(cw + z >= zero, cw - z >= zero));
      inside = hn::And(inside, hn::And(gw - x >= zero, gw + x >= zero));
      inside = hn::And(inside, hn::And(gw - y >= zero, gw + y >= zero));
    }
    // Lanes not inside compute on 0 / 1: no overflow into the conversions.
    const V xs = hn::IfThenElseZero(inside, x), ys = hn::IfThenElseZero(inside, y), ws = hn::IfThenElse(inside, cw, one);
    const VI sx = roundHalfAway((xs / ws + one) * half * w * subpixel);
    const VI sy = roundHalfAway((ys / ws + one) * half * h * subpixel);
    const VI packed = hn::Or(hn::ShiftLeft<32>(sy), hn::And(sx, hn::Set(di, 0xFFFFFFFFll)));
    const VI outside = hn::Set(di, std::int64_t(std::uint32_t(kOutsideWindow)));
    hn::StoreU(hn::IfThenElse(hn::RebindMask(di, inside), packed, outside), di, out);
  };
  std::size_t v = 0;
  for (; v + lanes <= n; v += lanes) snap(clip[v].data(), window + v);
  for (; v < n; ++v) {  // the tail: a whole vector of which lane 0 is the point (zeros elsewhere)
    alignas(64) double padded[4 * HWY_MAX_BYTES / 8] = {};
    for (int i = 0; i < 4; ++i) padded[i] = clip[v][i];
    alignas(64) std::int64_t lane[HWY_MAX_BYTES / 8];
    snap(padded, lane);
    window[v] = lane[0];
  }
}

}  // namespace uvtk::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace uvtk::render {

HWY_EXPORT(TransformToClip);
HWY_EXPORT(SnapPoints);

std::pair<double, double> transformToClip(const Mat4& clipFromObject, const Vec3* positions, Vec4* clip, std::size_t n) {
  return HWY_DYNAMIC_DISPATCH(TransformToClip)(clipFromObject, positions, clip, n);
}

void snapToWindow(const Vec4* clip, std::size_t n, double guard, int width, int height, std::int64_t* window) {
  HWY_DYNAMIC_DISPATCH(SnapPoints)(clip, n, guard, width, height, true, window);
}

std::int64_t snapPoint(const Vec4& clip, int width, int height) {
  std::int64_t window = 0;
  HWY_DYNAMIC_DISPATCH(SnapPoints)(&clip, 1, 0.0, width, height, false, &window);
  return window;
}

}  // namespace uvtk::render
#endif
