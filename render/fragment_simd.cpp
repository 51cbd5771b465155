// The vectorised fragment shading of render/fragment_simd.h, once per Highway target; compiled with
// -ffp-contract=off, so that every lane rounds as the scalar path does.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/fragment_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cmath>
#include <cstddef>

#include "core/libm_simd-inl.h"
#include "render/fragment_simd.h"

HWY_BEFORE_NAMESPACE();
namespace uvtk::render::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
#if UVTK_LIBM_SIMD
using uvtk::HWY_NAMESPACE::AppendSetLanes;
using uvtk::HWY_NAMESPACE::Hypot;
using uvtk::HWY_NAMESPACE::Log2;
using uvtk::HWY_NAMESPACE::WholeToDouble;
using uvtk::HWY_NAMESPACE::WholeToInt64;
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
    b.undecidedCount += AppendSetLanes(d, hn::AndNot(decided, hn::FirstN(d, b.count - i)), std::int64_t(i),
                                       b.undecided + b.undecidedCount);
  }
#endif
}

// Texture coordinate index i wrapped onto [0, n) (texture.cpp's wrapTexel): REPEAT and
// MIRRORED_REPEAT by the low bits of n, a power of two; CLAMP_TO_EDGE for any n.
template <class DI, class VI = hn::Vec<DI>>
VI WrapTexel(DI di, VI i, VI n, Wrap wrap) {
  const VI one = hn::Set(di, 1);
  if (wrap == Wrap::ClampToEdge) return hn::Min(hn::Max(i, hn::Zero(di)), hn::Sub(n, one));
  if (wrap == Wrap::Repeat) return hn::And(i, hn::Sub(n, one));
  // (n - 1) - mirror((i mod 2n) - n), mirror(a) = a >= 0 ? a : -(1 + a)
  const VI a = hn::Sub(hn::And(i, hn::Sub(hn::Add(n, n), one)), n);
  const VI mirrored = hn::IfThenElse(a < hn::Zero(di), hn::Sub(hn::Zero(di), hn::Add(one, a)), a);
  return hn::Sub(hn::Sub(n, one), mirrored);
}

void SampleTexels(const FragmentTexture& tex, FragmentBatch& b) {
  b.unsampledCount = 0;
#if !UVTK_LIBM_SIMD
  static_cast<void>(tex), static_cast<void>(b);
#else
  const hn::ScalableTag<double> d;
  const hn::RebindToSigned<decltype(d)> di;
  const hn::RebindToUnsigned<decltype(d)> du;
  const hn::Rebind<float, decltype(d)> df;
  using V = hn::Vec<decltype(d)>;
  using VI = hn::Vec<decltype(di)>;
  const std::size_t lanes = hn::Lanes(d);
  const SamplerState& sampler = tex.sampler;
  const Filter min = sampler.minFilter;
  // chooseLevels' constants (texture.cpp): GL 4.6 §8.14.3, §8.15.
  const bool mipmapped = needsMipmaps(min);
  const bool oneLevel = min == Filter::NearestMipmapNearest || min == Filter::LinearMipmapNearest;
  const bool minLinear = min == Filter::Linear || min == Filter::LinearMipmapNearest || min == Filter::LinearMipmapLinear;
  const bool magLinear = sampler.magFilter == Filter::Linear;
  const double crossover = magLinear && (min == Filter::NearestMipmapNearest || min == Filter::NearestMipmapLinear) ? 0.5 : 0.0;
  const V q = hn::Set(d, double(tex.levels - 1));
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0), half = hn::Set(d, 0.5), far = hn::Set(d, 4611686018427387904.0);
  const VI width = hn::Set(di, tex.width), height = hn::Set(di, tex.height), oneI = hn::Set(di, 1);
  // First, per fragment and level, where its texels lie and their weights.
  for (std::size_t i = 0; i < b.count; i += lanes) {
    const V s = hn::Load(d, b.s + i), t = hn::Load(d, b.t + i);
    const auto finite = hn::And(hn::IsFinite(s), hn::IsFinite(t));
    V lambda = hn::Load(d, b.lambda + i);
    lambda = hn::IfThenElse(hn::IsNaN(lambda), hn::Set(d, HUGE_VAL), lambda);  // as +infinity
    // chooseLevels: one level or two, their weights, and LINEAR or NEAREST within them.
    const auto magnified = lambda <= hn::Set(d, crossover);
    const auto linear = magLinear == minLinear ? (magLinear ? hn::FirstN(d, lanes) : hn::FirstN(d, 0))
                                                : (magLinear ? magnified : hn::Not(magnified));
    V levels[2] = {zero, zero}, weights[2] = {one, zero};
    if (mipmapped && oneLevel) {
      levels[0] = hn::IfThenElse(lambda <= half, zero, hn::IfThenElse(lambda > q + half, q, hn::Ceil(lambda + half) - one));
      levels[1] = levels[0];
    } else if (mipmapped) {
      const auto top = lambda >= q;
      const V floor = hn::Floor(lambda);
      const V f = lambda - floor;
      levels[0] = hn::IfThenElse(top, q, floor);
      levels[1] = hn::IfThenElse(top, q, floor + one);
      weights[0] = hn::IfThenElse(top, one, one - f);
      weights[1] = hn::IfThenElseZero(hn::Not(top), f);
    }
    levels[0] = hn::IfThenElseZero(hn::Not(magnified), levels[0]), levels[1] = hn::IfThenElse(magnified, levels[0], levels[1]);
    weights[0] = hn::IfThenElse(magnified, one, weights[0]), weights[1] = hn::IfThenElseZero(hn::Not(magnified), weights[1]);
    // Lanes read where sample() does not (s or t not finite) fetch texel 0 of level 0 instead.
    const V sIn = hn::IfThenElseZero(finite, s), tIn = hn::IfThenElseZero(finite, t);
    for (int l = 0; l < 2; ++l) {
      const VI k = WholeToInt64(d, levels[l]);
      const VI w = hn::Max(width >> k, oneI), h = hn::Max(height >> k, oneI);  // GL: max(1, floor(w / 2^k))
      const VI offset = hn::GatherIndex(di, tex.levelOffset, k);
      const auto tap = [&](V coordinate, VI size, V& fraction) {  // linearTap, or nearestTexel
        V u = coordinate * WholeToDouble(d, size);
        u = hn::IfThenElse(linear, u - half, u);
        u = hn::Min(hn::Max(u, hn::Neg(far)), far);
        const V lower = hn::Floor(u);
        fraction = hn::IfThenElseZero(linear, u - lower);
        return hn::AllTrue(d, hn::Abs(lower) < hn::Set(d, 0x1p51)) ? WholeToInt64(d, lower) : hn::ConvertTo(di, lower);
      };
      V a, c;
      const VI i0 = tap(sIn, w, a), j0 = tap(tIn, h, c);
      const VI wi0 = WrapTexel(di, i0, w, sampler.wrapS), wi1 = WrapTexel(di, hn::Add(i0, oneI), w, sampler.wrapS);
      const VI wj0 = WrapTexel(di, j0, h, sampler.wrapT), wj1 = WrapTexel(di, hn::Add(j0, oneI), h, sampler.wrapT);
      const VI row0 = hn::Add(offset, hn::Mul(wj0, w)), row1 = hn::Add(offset, hn::Mul(wj1, w));
      hn::Store(hn::Add(row0, wi0), di, b.texel[4 * l] + i), hn::Store(hn::Add(row0, wi1), di, b.texel[4 * l + 1] + i);
      hn::Store(hn::Add(row1, wi0), di, b.texel[4 * l + 2] + i), hn::Store(hn::Add(row1, wi1), di, b.texel[4 * l + 3] + i);
      hn::Store(a, d, b.alphaS[l] + i), hn::Store(c, d, b.betaT[l] + i), hn::Store(weights[l], d, b.levelWeight[l] + i);
    }
    b.unsampledCount += AppendSetLanes(d, hn::AndNot(finite, hn::FirstN(d, b.count - i)), std::int64_t(i),
                                       b.unsampled + b.unsampledCount);
  }
  // Then every row of texels asked for, so that it is in cache when blended (the levels a
  // frame minifies to are larger than the core's cache).
  for (std::size_t j = 0; j < b.count; ++j)
    for (int r = 0; r < 8; r += 2) __builtin_prefetch(tex.texels + b.texel[r][j]);
  // Last, GL's blend of each level's texels and of the levels, each channel's byte b read as
  // float(b / 255.0) widened.
  const auto* texels = reinterpret_cast<const std::int64_t*>(tex.texels);  // eight bytes read at a texel
  const int channels = tex.alpha ? 4 : 3;
  for (std::size_t i = 0; i < b.count; i += lanes) {
    V channel[4] = {zero, zero, zero, zero};
    for (int l = 0; l < 2; ++l) {
      const V a = hn::Load(d, b.alphaS[l] + i), c = hn::Load(d, b.betaT[l] + i);
      // GL 4.6 §8.14.2: (1-a)(1-b) t00 + a(1-b) t10 + (1-a) b t01 + a b t11, in this order (NEAREST:
      // the texel of weight 1).
      const V weights[4] = {(one - a) * (one - c), a * (one - c), (one - a) * c, a * c};
      V blended[4] = {zero, zero, zero, zero};
      for (int tx = 0; tx < 4; ++tx) {
        const VI index = hn::Load(di, b.texel[4 * l + tx] + i);
        const auto bytes = hn::And(hn::BitCast(du, hn::GatherOffset(di, texels, hn::ShiftLeft<2>(index))),
                                   hn::Set(du, 0xFFFFFFFFull));
        for (int ch = 0; ch < channels; ++ch) {
          const V byte = WholeToDouble(d, hn::BitCast(di, hn::And(hn::ShiftRightSame(bytes, 8 * ch), hn::Set(du, 255))));
          const V value = hn::PromoteTo(d, hn::DemoteTo(df, byte * hn::Set(d, 1.0 / 255.0)));
          const V term = weights[tx] * value;
          blended[ch] = tx == 0 ? term : blended[ch] + term;
        }
      }
      const V levelWeight = hn::Load(d, b.levelWeight[l] + i);
      for (int ch = 0; ch < channels; ++ch) channel[ch] = channel[ch] + levelWeight * blended[ch];  // sum += weight * level
    }
    hn::Store(channel[0], d, b.red + i), hn::Store(channel[1], d, b.green + i);
    hn::Store(channel[2], d, b.blue + i), hn::Store(channel[3], d, b.alpha + i);
  }
#endif
}

}  // namespace uvtk::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace uvtk::render {

HWY_EXPORT(Vectorised);
HWY_EXPORT(ShadeFragments);
HWY_EXPORT(SampleTexels);

bool fragmentsVectorised() { return HWY_DYNAMIC_DISPATCH(Vectorised)(); }

void shadeFragments(const FragmentFrame& frame, FragmentBatch& batch) { HWY_DYNAMIC_DISPATCH(ShadeFragments)(frame, batch); }

void sampleTexels(const FragmentTexture& texture, FragmentBatch& batch) {
  HWY_DYNAMIC_DISPATCH(SampleTexels)(texture, batch);
}

std::optional<FragmentTexture> vectorisedTexture(const Texture& texture, const SamplerState& sampler, bool alpha) {
  const auto powerOfTwo = [](int n) { return (n & (n - 1)) == 0; };
  if (!texture.packed() || !texture.standardBytes() || texture.levelCount() > 32) return std::nullopt;
  if ((sampler.wrapS != Wrap::ClampToEdge && !powerOfTwo(texture.width())) ||
      (sampler.wrapT != Wrap::ClampToEdge && !powerOfTwo(texture.height())))
    return std::nullopt;
  FragmentTexture out;
  out.texels = texture.packedTexels(0);
  for (int k = 0; k < texture.levelCount(); ++k) out.levelOffset[k] = std::int64_t(texture.packedOffset(k));
  out.levels = texture.levelCount(), out.width = texture.width(), out.height = texture.height();
  out.sampler = sampler;
  out.alpha = alpha;
  return out;
}

}  // namespace uvtk::render
#endif
