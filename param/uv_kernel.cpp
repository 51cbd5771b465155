#include "param/uv_kernel.h"

#include <algorithm>
#include <cstring>
#include <memory>
#include <type_traits>

#include "core/error.h"
#include "core/parallel.h"
#include "param/batch_atan2.h"
#include "param/sample_evaluator.h"
#include "param/uv_kernel_simd.h"

namespace uvtk::param {

namespace {

template <class T>
constexpr Precision precisionOf() {
  return std::is_same_v<T, float> ? Precision::Float : Precision::Double;
}

// What one vertex gets from the per-vertex templates: SampleEvaluator's steps for a single sample
// already in the local frame (the same resolve, verdict, pole test, arctangent call and S-mapping).
template <class T>
struct LaneUv {
  T u = 0, v = 0, axialX = 0, axialY = 0;
  CornerState state = CornerState::Invalid;
  CornerInvalid reason = kCornerMiss;
};

template <class T, class S, class M>
LaneUv<T> mapLane(const S& surface, const M& mapping, const PoleTest& isPole, MathMode math,
                  const SensibleRangeT<T>& range, const SampleT<T>& sample) {
  LaneUv<T> out;
  const HitT<T> hit = surface.resolve(mapping.probe(sample));
  out.reason = judgeHit(hit, range);
  if (out.reason != kCornerValid) return out;
  const Vec3T<T>& q = hit.q;
  out.axialX = q.x(), out.axialY = q.y();
  out.state = CornerState::Ok;
  if (atSingularPoint<S>(isPole, q)) out.state = CornerState::Pole;
  constexpr std::size_t kAngles = std::max(S::kAngles, 1);
  T y[kAngles] = {}, x[kAngles] = {}, angles[kAngles] = {};
  if constexpr (S::kAngles > 0) {
    const auto arguments = surface.angleArguments(q);
    for (std::size_t a = 0; a < kAngles; ++a) y[a] = arguments[a].y, x[a] = arguments[a].x;
    atan2Block(math, y, x, angles, kAngles);
  }
  const Vec2T<T> uv = surface.uvFromAngles(q, angles);
  out.u = S::kTraits.wraps && out.state == CornerState::Pole ? T(0) : uv.x();
  out.v = uv.y();
  if (!std::isfinite(out.u) || !std::isfinite(out.v))
    out.u = out.v = T(0), out.state = CornerState::Invalid, out.reason = kCornerNotFinite;
  return out;
}

// The vector variant of the options, or nothing where every lane goes through mapLane.
std::optional<SimdVariant> simdVariantOf(const ProjectorOptions& o) {
  const bool foot = o.ray == RayKind::SurfaceNormal, central = o.ray == RayKind::Centroid;
  if (!foot && !central) return std::nullopt;
  switch (o.surface) {
    case SurfaceKind::Sphere:
      return SimdVariant::SphereRadial;
    case SurfaceKind::Cylinder:
      return foot ? SimdVariant::CylinderFoot : SimdVariant::CylinderCentral;
    case SurfaceKind::Plane:
      return foot ? SimdVariant::PlaneFoot : SimdVariant::PlaneCentral;
    case SurfaceKind::TwoPlane:
      return foot ? SimdVariant::TwoPlaneFoot : SimdVariant::TwoPlaneCentral;
    default:  // the cube, camera and triplanar have no per-vertex kernel; the others, no vectors
      break;
  }
  return std::nullopt;
}

template <class T>
SimdParams<T> simdParams(SimdVariant variant, const ProjectorOptions& o, const SurfaceT<T>& surface,
                         const SensibleRangeT<T>& range) {
  SimdParams<T> p;
  p.variant = variant;
  p.gluAzimuth = o.spherePreset == SpherePreset::Glu;
  p.seed004 = o.spherePreset == SpherePreset::Seed004;
  p.slope = static_cast<T>(PoleTest(o.poleEpsilon).slope);
  for (int a = 0; a < 3; ++a) p.centre[a] = range.centre[a];
  p.reach = range.reach;
  if (const auto* twoPlane = std::get_if<TwoPlaneSurfaceT<T>>(&surface)) {
    for (int a = 0; a < 4; ++a) p.planeU[a] = twoPlane->planeU[a], p.planeV[a] = twoPlane->planeV[a];
    for (int a = 0; a < 3; ++a) p.axis[a] = twoPlane->axis[a];
  }
  p.twoPi = T(kTwoPi), p.inverseTwoPi = T(1.0 / kTwoPi), p.pi = T(kPi);
  return p;
}

}  // namespace

template <class T>
UvKernel<T>::UvKernel(const ProjectorOptions& o, const Affine3& localFromObject,
                      const std::optional<Eigen::AlignedBox3d>& sensible)
    : surface_(makeSurface<T>(o)),
      mapping_(makeRayMapping<T>(o, LocalFrameT<T>(localFromObject))),
      options_(o),
      range_(sensible),
      needsNormals_(o.ray == RayKind::ObjectNormal || o.ray == RayKind::Reflection) {
  UVTK_CHECK(o.arithmetic.precision == precisionOf<T>());
  if (o.surface == SurfaceKind::Cube)
    throw UsageError("the cube projector chooses a face per triangle: map a mesh with project()");
}

template <class T>
void UvKernel<T>::run(const KernelSpan<T>& span, std::size_t first, std::vector<UvException>& exceptions) const {
  const std::optional<SimdVariant> variant = simdVariantOf(options_);
  const PoleTest isPole(options_.poleEpsilon);
  const MathMode math = options_.arithmetic.math;
  const bool wraps = traitsOf(options_.surface).wraps;
  std::visit(
      [&](const auto& s, const auto& m) {
        using S = std::decay_t<decltype(s)>;
        using M = std::decay_t<decltype(m)>;
        if constexpr (!std::is_same_v<S, CubeSurfaceT<T>>) {
          // One vertex through the templates, into the outputs; a pole or an invalid one listed.
          const auto perVertex = [&](std::size_t i) {
            SampleT<T> sample{Vec3T<T>(span.x[i], span.y[i], span.z[i]), Vec3T<T>::Zero()};
            if constexpr (M::kNeedsNormal) sample.n = Vec3T<T>(span.nx[i], span.ny[i], span.nz[i]);
            const LaneUv<T> r = mapLane<T>(s, m, isPole, math, range_, sample);
            span.u[i] = r.u, span.v[i] = r.v;
            if (span.axialX) span.axialX[i] = r.axialX, span.axialY[i] = r.axialY;
            if (r.state != CornerState::Ok) exceptions.push_back({std::uint32_t(first + i), r.state, r.reason});
          };
          if (!variant) {
            for (std::size_t i = 0; i < span.count; ++i) perVertex(i);
            return;
          }
          const SimdParams<T> params = simdParams(*variant, options_, surface_, range_);
          thread_local std::unique_ptr<SimdBlock<T>> scratch;
          if (!scratch) scratch = std::make_unique<SimdBlock<T>>();
          SimdBlock<T>& b = *scratch;
          constexpr std::size_t kSize = SimdBlock<T>::kSize;
          for (std::size_t start = 0; start < span.count; start += kSize) {
            const std::size_t n = std::min(kSize, span.count - start);
            const bool whole = n == kSize;  // the vectors read and write the span itself
            if (whole) {
              b.in[0] = span.x + start, b.in[1] = span.y + start, b.in[2] = span.z + start;
              b.out[0] = span.u + start, b.out[1] = span.v + start;
              b.out[2] = span.axialX ? span.axialX + start : b.ax, b.out[3] = span.axialY ? span.axialY + start : b.ay;
            } else {  // whole vectors read zeros past the end
              std::fill(b.x + n, b.x + kSize, T(0)), std::fill(b.y + n, b.y + kSize, T(0));
              std::fill(b.z + n, b.z + kSize, T(0));
              std::memcpy(b.x, span.x + start, n * sizeof(T));
              std::memcpy(b.y, span.y + start, n * sizeof(T));
              std::memcpy(b.z, span.z + start, n * sizeof(T));
              b.in[0] = b.x, b.in[1] = b.y, b.in[2] = b.z;
              b.out[0] = b.u, b.out[1] = b.v, b.out[2] = b.ax, b.out[3] = b.ay;
            }
            bool slow = simdPrepare(params, b, n);
            if (wraps) {
              atan2Block(math, b.y0, b.x0, b.angle0, n);
              if (S::kAngles > 1) atan2Block(math, b.y1, b.x1, b.angle1, n);
              slow |= simdFinish(params, b, n);
            }
            if (!whole) {
              std::memcpy(span.u + start, b.u, n * sizeof(T));
              std::memcpy(span.v + start, b.v, n * sizeof(T));
              if (span.axialX) {
                std::memcpy(span.axialX + start, b.ax, n * sizeof(T));
                std::memcpy(span.axialY + start, b.ay, n * sizeof(T));
              }
            }
            if (slow)
              for (std::size_t i = 0; i < n; ++i)
                if (b.slow[i] != T(0)) perVertex(start + i);
          }
        }
      },
      surface_, mapping_);
}

template <class T>
void toLocal(const Affine3& localFromObject, const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
             LocalPoints<T>& out, int threads) {
  const LocalFrameT<T> frame(localFromObject);
  const std::size_t n = positions.size();
  const bool withNormals = !normals.empty();
  if (withNormals && normals.size() != n) throw UsageError("this O-mapping needs one normal per position");
  out.x.resize(n), out.y.resize(n), out.z.resize(n);
  out.nx.resize(withNormals ? n : 0), out.ny.resize(withNormals ? n : 0), out.nz.resize(withNormals ? n : 0);
  const int chunks = threadCount(threads);
  const std::size_t size = (n + std::size_t(chunks) - 1) / std::size_t(chunks);
  parallelFor(chunks, chunks, [&](int chunk) {
    const std::size_t begin = std::min(n, std::size_t(chunk) * size), end = std::min(n, begin + size);
    for (std::size_t i = begin; i < end; ++i) {
      const Vec3T<T> p = frame.point(positions[i]);
      out.x[i] = p.x(), out.y[i] = p.y(), out.z[i] = p.z();
      if (!withNormals) continue;
      const Vec3T<T> m = frame.normal(normals[i]);
      out.nx[i] = m.x(), out.ny[i] = m.y(), out.nz[i] = m.z();
    }
  });
}

template <class T>
void mapUvs(const ProjectorOptions& o, const Affine3& localFromObject, const LocalPoints<T>& points, UvArrays<T>& out,
            int threads, const std::optional<Eigen::AlignedBox3d>& sensible) {
  const UvKernel<T> kernel(o, localFromObject, sensible);
  const std::size_t n = points.size();
  if (kernel.needsNormals() && points.nx.size() != n) throw UsageError("this O-mapping needs one normal per position");
  out.u.resize(n), out.v.resize(n);
  out.exceptions.clear();
  const int chunks = threadCount(threads);
  const std::size_t size = (n / std::size_t(chunks) + 255) / 256 * 256;
  std::vector<std::vector<UvException>> exceptions(static_cast<std::size_t>(chunks));
  parallelFor(chunks, chunks, [&](int chunk) {
    const std::size_t begin = std::min(n, std::size_t(chunk) * size);
    const std::size_t end = chunk + 1 == chunks ? n : std::min(n, begin + size);
    KernelSpan<T> span;
    span.count = end - begin;
    span.x = points.x.data() + begin, span.y = points.y.data() + begin, span.z = points.z.data() + begin;
    if (kernel.needsNormals())
      span.nx = points.nx.data() + begin, span.ny = points.ny.data() + begin, span.nz = points.nz.data() + begin;
    span.u = out.u.data() + begin, span.v = out.v.data() + begin;
    kernel.run(span, begin, exceptions[std::size_t(chunk)]);
  });
  for (const std::vector<UvException>& e : exceptions) out.exceptions.insert(out.exceptions.end(), e.begin(), e.end());
}

template class UvKernel<float>;
template class UvKernel<double>;
template void toLocal(const Affine3&, const std::vector<Vec3>&, const std::vector<Vec3>&, LocalPoints<float>&, int);
template void toLocal(const Affine3&, const std::vector<Vec3>&, const std::vector<Vec3>&, LocalPoints<double>&, int);
template void mapUvs(const ProjectorOptions&, const Affine3&, const LocalPoints<float>&, UvArrays<float>&, int,
                     const std::optional<Eigen::AlignedBox3d>&);
template void mapUvs(const ProjectorOptions&, const Affine3&, const LocalPoints<double>&, UvArrays<double>&, int,
                     const std::optional<Eigen::AlignedBox3d>&);

}  // namespace uvtk::param
