// The vector stages of the narrow kernel, once per Highway target. Each operation is the one the
// per-vertex templates (param/surfaces.h, param/formulas.h) perform, in the same order and
// precision, so a lane gets the same bits: separate multiplies and adds (this file is compiled
// with -ffp-contract=off, and no MulAdd), IEEE division and square root. What the vectors would do
// differently (hypot's range, misses, poles, values out of range or not finite) marks the lane
// slow instead.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "param/uv_kernel_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "param/uv_kernel_simd.h"

HWY_BEFORE_NAMESPACE();
namespace uvtk::param {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// radialDistance's square root, and where it would take std::hypot instead (magnitudes outside
// (kLow, 1/kLow)) or the input is not finite: there the lane is slow.
template <class D, class V, class M>
V radial(D d, V x, V y, M& fine) {
  using T = hn::TFromD<D>;
  constexpr T kLow = sizeof(T) == 4 ? T(1e-15f) : T(1e-150);
  const V m = hn::Max(hn::Abs(x), hn::Abs(y));
  fine = hn::And(fine, hn::And(m > hn::Set(d, kLow), m < hn::Set(d, T(1) / kLow)));
  return hn::Sqrt(x * x + y * y);
}

template <class D, class V>
auto inRange(D d, const SimdParams<hn::TFromD<D>>& p, V qx, V qy, V qz) {
  const V reach = hn::Set(d, p.reach);
  return hn::And(hn::And(hn::Abs(qx - hn::Set(d, p.centre[0])) <= reach, hn::Abs(qy - hn::Set(d, p.centre[1])) <= reach),
                 hn::Abs(qz - hn::Set(d, p.centre[2])) <= reach);
}

template <class D, class V>
auto finite3(V a, V b, V c) {
  return hn::And(hn::And(hn::IsFinite(a), hn::IsFinite(b)), hn::IsFinite(c));
}

// Eigen's order for a 3-vector dot product: (a0 b0 + a1 b1) + a2 b2 in double (a packet of two,
// then the last), a0 b0 + (a1 b1 + a2 b2) in float (tests/param/uv_kernel_test.cpp checks both).
template <class D, class V>
V dot3(D d, const hn::TFromD<D>* a, V x, V y, V z) {
  const V x0 = hn::Set(d, a[0]) * x, y1 = hn::Set(d, a[1]) * y, z2 = hn::Set(d, a[2]) * z;
  if constexpr (sizeof(hn::TFromD<D>) == 4) return x0 + (y1 + z2);
  return (x0 + y1) + z2;
}

template <class T>
bool Prepare(const SimdParams<T>& p, SimdBlock<T>& b, std::size_t n) {
  const hn::ScalableTag<T> d;
  using V = hn::Vec<decltype(d)>;
  const std::size_t lanes = hn::Lanes(d);
  const V zero = hn::Zero(d), one = hn::Set(d, T(1));
  auto anySlow = hn::Zero(d) != zero;  // all false
  for (std::size_t i = 0; i < n; i += lanes) {
    const V x = hn::LoadU(d, b.in[0] + i), y = hn::LoadU(d, b.in[1] + i), z = hn::LoadU(d, b.in[2] + i);
    auto fine = finite3<decltype(d)>(x, y, z);
    switch (p.variant) {
      case SimdVariant::SphereRadial:
      case SimdVariant::CylinderFoot: {
        const V rho = radial(d, x, y, fine);
        fine = hn::AndNot(rho <= hn::Set(d, p.slope) * hn::Abs(z), fine);  // a pole is slow
        const bool glu = p.variant == SimdVariant::SphereRadial && p.gluAzimuth;
        hn::Store(glu ? x : y, d, b.y0 + i);
        hn::Store(glu ? y : x, d, b.x0 + i);
        hn::Store(rho, d, b.y1 + i);
        hn::Store(hn::Abs(z), d, b.x1 + i);
        hn::Store(z, d, b.qz + i);
        hn::StoreU(x, d, b.out[2] + i);
        hn::StoreU(y, d, b.out[3] + i);
        break;
      }
      case SimdVariant::CylinderCentral: {
        const V rho = radial(d, x, y, fine);  // in hypot's range: rho > 0
        const V qx = x / rho, qy = y / rho, qz = z / rho;
        fine = hn::And(fine, hn::And(finite3<decltype(d)>(qx, qy, qz), inRange(d, p, qx, qy, qz)));
        const V rq = radial(d, qx, qy, fine);
        fine = hn::AndNot(rq <= hn::Set(d, p.slope) * hn::Abs(qz), fine);
        hn::Store(qy, d, b.y0 + i);
        hn::Store(qx, d, b.x0 + i);
        hn::Store(qz, d, b.qz + i);
        hn::StoreU(qx, d, b.out[2] + i);
        hn::StoreU(qy, d, b.out[3] + i);
        break;
      }
      case SimdVariant::PlaneFoot:
        fine = hn::And(fine, inRange(d, p, x, y, zero));
        hn::StoreU(x, d, b.out[0] + i);
        hn::StoreU(y, d, b.out[1] + i);
        hn::StoreU(x, d, b.out[2] + i);
        hn::StoreU(y, d, b.out[3] + i);
        break;
      case SimdVariant::PlaneCentral: {
        fine = hn::And(fine, z > zero);
        const V qx = x / z, qy = y / z;
        fine = hn::And(fine, hn::And(finite3<decltype(d)>(qx, qy, one), inRange(d, p, qx, qy, one)));
        hn::StoreU(qx, d, b.out[0] + i);
        hn::StoreU(qy, d, b.out[1] + i);
        hn::StoreU(qx, d, b.out[2] + i);
        hn::StoreU(qy, d, b.out[3] + i);
        break;
      }
      case SimdVariant::TwoPlaneFoot:
      case SimdVariant::TwoPlaneCentral: {
        V qx = x, qy = y, qz = z;
        if (p.variant == SimdVariant::TwoPlaneCentral) {
          const V along = dot3(d, p.axis, x, y, z);
          fine = hn::And(fine, along > zero);
          qx = x / along, qy = y / along, qz = z / along;
          fine = hn::And(fine, finite3<decltype(d)>(qx, qy, qz));
        }
        fine = hn::And(fine, inRange(d, p, qx, qy, qz));
        const V u = dot3(d, p.planeU, qx, qy, qz) + hn::Set(d, p.planeU[3]);
        const V v = dot3(d, p.planeV, qx, qy, qz) + hn::Set(d, p.planeV[3]);
        fine = hn::And(fine, hn::And(hn::IsFinite(u), hn::IsFinite(v)));
        hn::StoreU(u, d, b.out[0] + i);
        hn::StoreU(v, d, b.out[1] + i);
        hn::StoreU(qx, d, b.out[2] + i);
        hn::StoreU(qy, d, b.out[3] + i);
        break;
      }
    }
    const auto slow = hn::Not(fine);
    hn::Store(hn::IfThenElseZero(slow, one), d, b.slow + i);
    anySlow = hn::Or(anySlow, slow);
  }
  return !hn::AllFalse(d, anySlow);
}

// turnFromAngle: (theta + [theta < 0] 2 pi) / 2 pi + 0, times [u < 1].
template <class D, class V>
V turn(D d, const SimdParams<hn::TFromD<D>>& p, V theta) {
  const V zero = hn::Zero(d), one = hn::Set(d, hn::TFromD<D>(1));
  const V u = (theta + hn::IfThenElseZero(theta < zero, one) * hn::Set(d, p.twoPi)) * hn::Set(d, p.inverseTwoPi) + zero;
  return u * hn::IfThenElseZero(u < one, one);
}

template <class T>
bool Finish(const SimdParams<T>& p, SimdBlock<T>& b, std::size_t n) {
  const hn::ScalableTag<T> d;
  using V = hn::Vec<decltype(d)>;
  const hn::RebindToSigned<decltype(d)> di;
  const std::size_t lanes = hn::Lanes(d);
  const V zero = hn::Zero(d), one = hn::Set(d, T(1));
  const bool sphere = p.variant == SimdVariant::SphereRadial;
  auto anySlow = hn::Zero(d) != zero;
  for (std::size_t i = 0; i < n; i += lanes) {
    const V a0 = hn::Load(d, b.angle0 + i), qz = hn::Load(d, b.qz + i);
    V u, v;
    if (sphere) {
      u = p.seed004 ? a0 / hn::Set(d, p.twoPi) + zero : turn(d, p, a0);
      const V fraction = hn::Load(d, b.angle1 + i) / hn::Set(d, p.pi);
      auto southern = hn::RebindMask(d, hn::BitCast(di, qz) < hn::Zero(di));  // the sign bit, -0 included
      const auto fromZero = p.seed004 ? hn::Not(southern) : southern;
      v = hn::IfThenElse(fromZero, fraction, one - fraction);
    } else {
      u = turn(d, p, a0);
      v = qz;
    }
    hn::StoreU(u, d, b.out[0] + i);
    hn::StoreU(v, d, b.out[1] + i);
    const auto slow = hn::Not(hn::And(hn::IsFinite(u), hn::IsFinite(v)));
    const V old = hn::Load(d, b.slow + i);
    hn::Store(hn::IfThenElse(slow, one, old), d, b.slow + i);
    anySlow = hn::Or(anySlow, slow);
  }
  return !hn::AllFalse(d, anySlow);
}

bool PrepareF(const SimdParams<float>& p, SimdBlock<float>& b, std::size_t n) { return Prepare(p, b, n); }
bool PrepareD(const SimdParams<double>& p, SimdBlock<double>& b, std::size_t n) { return Prepare(p, b, n); }
bool FinishF(const SimdParams<float>& p, SimdBlock<float>& b, std::size_t n) { return Finish(p, b, n); }
bool FinishD(const SimdParams<double>& p, SimdBlock<double>& b, std::size_t n) { return Finish(p, b, n); }

}  // namespace HWY_NAMESPACE
}  // namespace uvtk::param
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace uvtk::param {

HWY_EXPORT(PrepareF);
HWY_EXPORT(PrepareD);
HWY_EXPORT(FinishF);
HWY_EXPORT(FinishD);

bool simdPrepare(const SimdParams<float>& p, SimdBlock<float>& b, std::size_t n) {
  return HWY_DYNAMIC_DISPATCH(PrepareF)(p, b, n);
}
bool simdPrepare(const SimdParams<double>& p, SimdBlock<double>& b, std::size_t n) {
  return HWY_DYNAMIC_DISPATCH(PrepareD)(p, b, n);
}
bool simdFinish(const SimdParams<float>& p, SimdBlock<float>& b, std::size_t n) {
  return HWY_DYNAMIC_DISPATCH(FinishF)(p, b, n);
}
bool simdFinish(const SimdParams<double>& p, SimdBlock<double>& b, std::size_t n) {
  return HWY_DYNAMIC_DISPATCH(FinishD)(p, b, n);
}

}  // namespace uvtk::param
#endif
