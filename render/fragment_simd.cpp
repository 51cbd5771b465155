// The vectorised fragment shading of render/fragment_simd.h, once per Highway target; compiled with
// -ffp-contract=off, so that every lane rounds as the scalar path does.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/fragment_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cstddef>

#include "core/libm_simd-inl.h"
#include "render/fragment_simd.h"

HWY_BEFORE_NAMESPACE();
namespace uvtk::render::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
#if UVTK_LIBM_SIMD
using uvtk::HWY_NAMESPACE::Hypot;
using uvtk::HWY_NAMESPACE::Log2;
#endif

bool Vectorised() { return UVTK_LIBM_SIMD; }

void ShadeFragments(const FragmentFrame& frame, FragmentBatch& b) {
  b.undecidedCount = 0;
#if !UVTK_LIBM_SIMD
  static_cast<void>(frame), static_cast<void>(b);
#else
  const hn::ScalableTag<double> d;
  const hn::RebindToSigned<decltype(d)> di;
  using V = hn::Vec<decltype(d)>;
  const std::size_t lanes = hn::Lanes(d);
  // The nine numbers of each DrawnFace's kFromWindow (column-major), read from one base.
  const double* coefficients = frame.drawnFaces[0].interpolator.kFromWindow().data();
  static_assert(sizeof(DrawnFace) % sizeof(double) == 0);
  const auto stride = hn::Set(di, std::int64_t(sizeof(DrawnFace) / sizeof(double)));
  const V zero = hn::Zero(d);
  const V width = hn::Set(d, double(frame.textureWidth)), height = hn::Set(d, double(frame.textureHeight));
  for (std::size_t i = 0; i < b.count; i += lanes) {
    const V x = hn::Load(d, b.x + i), y = hn::Load(d, b.y + i);
    const auto record = hn::Mul(hn::Load(di, b.drawn + i), stride);
    const auto m = [&](int row, int column) {
      return hn::GatherIndex(d, coefficients, hn::Add(record, hn::Set(di, std::int64_t(3 * column + row))));
    };
    // TriangleInterpolator::at, in its order: k = M (x, y, 1), s = (k0 + k1) + k2.
    V k[3], dkdx[3], dkdy[3];
    for (int r = 0; r < 3; ++r) dkdx[r] = m(r, 0), dkdy[r] = m(r, 1);
    k[0] = (dkdx[0] * x + dkdy[0] * y) + m(0, 2);
    k[1] = (dkdx[1] * x + dkdy[1] * y) + m(1, 2);
    k[2] = dkdx[2] * x + (dkdy[2] * y + m(2, 2));
    const V s = (k[0] + k[1]) + k[2];
    const V dsdx = (dkdx[0] + dkdx[1]) + dkdx[2], dsdy = (dkdy[0] + dkdy[1]) + dkdy[2];
    const V s2 = s * s;
    // interpolatedTexcoords for a 2D texture: (s, t, q) summed corner by corner from zero.
    const auto corner = hn::Load(di, b.corners + i);
    const auto texcoord = [&](int k, int component) {
      return hn::GatherIndex(d, frame.corners, hn::Add(corner, hn::Set(di, std::int64_t(4 * k + component))));
    };
    V tc[3] = {zero, zero, zero}, tdx[3] = {zero, zero, zero}, tdy[3] = {zero, zero, zero};
    for (int c = 0; c < 3; ++c) {
      const V bary = k[c] / s;
      hn::Store(bary, d, (c == 0 ? b.b0 : c == 1 ? b.b1 : b.b2) + i);
      const V dbdx = (dkdx[c] * s - k[c] * dsdx) / s2;  // the quotient rule on k / s
      const V dbdy = (dkdy[c] * s - k[c] * dsdy) / s2;
      for (int component = 0; component < 3; ++component) {
        const V value = texcoord(c, component == 2 ? 3 : component);  // s, t and q
        tc[component] = tc[component] + bary * value;
        tdx[component] = tdx[component] + dbdx * value;
        tdy[component] = tdy[component] + dbdy * value;
      }
    }
    const V q = tc[2], q2 = q * q;
    const V ss = tc[0] / q, tt = tc[1] / q;
    const V dsdxOut = (tdx[0] * q - tc[0] * tdx[2]) / q2, dtdxOut = (tdx[1] * q - tc[1] * tdx[2]) / q2;
    const V dsdyOut = (tdy[0] * q - tc[0] * tdy[2]) / q2, dtdyOut = (tdy[1] * q - tc[1] * tdy[2]) / q2;
    hn::Store(ss, d, b.s + i), hn::Store(tt, d, b.t + i);
    hn::Store(dsdxOut, d, b.dsdx + i), hn::Store(dtdxOut, d, b.dtdx + i);
    hn::Store(dsdyOut, d, b.dsdy + i), hn::Store(dtdyOut, d, b.dtdy + i);
    // levelOfDetail: rho from the longer footprint where the squared lengths are well apart, else
    // the larger of both hypots; lambda = log2(rho) + bias.
    auto decided = hn::And(hn::And(hn::IsFinite(dsdxOut), hn::IsFinite(dtdxOut)),
                           hn::And(hn::IsFinite(dsdyOut), hn::IsFinite(dtdyOut)));
    const V dudx = dsdxOut * width, dvdx = dtdxOut * height, dudy = dsdyOut * width, dvdy = dtdyOut * height;
    const V sx = dudx * dudx + dvdx * dvdx, sy = dudy * dudy + dvdy * dvdy;
    const V low = hn::Set(d, 1e-290), high = hn::Set(d, 1e290), separated = hn::Set(d, 1.0 + 1e-9);
    const auto inRange = hn::And(hn::And(sx >= low, sx <= high), hn::And(sy >= low, sy <= high));
    const auto xLonger = hn::And(inRange, sx > sy * separated);
    const auto yLonger = hn::AndNot(xLonger, hn::And(inRange, sy > sx * separated));
    auto decidedX = decided, decidedY = decided;
    const V hx = Hypot(d, dudx, dvdx, decidedX), hy = Hypot(d, dudy, dvdy, decidedY);
    // Only the hypot that levelOfDetail takes counts.
    const auto both = hn::And(hn::Not(xLonger), hn::Not(yLonger));
    decided = hn::Or(hn::Or(hn::And(xLonger, decidedX), hn::And(yLonger, decidedY)), hn::And(both, hn::And(decidedX, decidedY)));
    const V rho = hn::IfThenElse(xLonger, hx, hn::IfThenElse(yLonger, hy, hn::Max(hx, hy)));
    const V lambda = Log2(d, rho, decided) + hn::Set(d, frame.lodBias);
    hn::Store(lambda, d, b.lambda + i);
    const auto inBatch = hn::FirstN(d, b.count - i);
    b.undecidedCount += hn::CompressStore(hn::Iota(di, std::int64_t(i)), hn::RebindMask(di, hn::AndNot(decided, inBatch)),
                                          di, b.undecided + b.undecidedCount);
  }
#endif
}

}  // namespace uvtk::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace uvtk::render {

HWY_EXPORT(Vectorised);
HWY_EXPORT(ShadeFragments);

bool fragmentsVectorised() { return HWY_DYNAMIC_DISPATCH(Vectorised)(); }

void shadeFragments(const FragmentFrame& frame, FragmentBatch& batch) { HWY_DYNAMIC_DISPATCH(ShadeFragments)(frame, batch); }

}  // namespace uvtk::render
#endif
