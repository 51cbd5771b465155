// Inside param: the two-stage mapping of many samples in a chosen precision T and math mode, in
// blocks, so that the arctangents of a block go to batch_atan2 at once. Shared by projector.cpp
// (float and double) and reference.cpp (long double).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <type_traits>
#include <variant>

#include "core/error.h"
#include "core/parallel.h"
#include "param/batch_atan2.h"
#include "param/projector.h"
#include "param/surfaces.h"

namespace uvtk::param {

// Object-space points and normals carried into the projector's frame. The move is computed in
// double (long double for T = long double) and only then rounded to T: the local origin keeps
// float exact for meshes far from the object origin (docs/precision.md).
template <class T>
struct LocalFrameT {
  using Wide = std::conditional_t<(sizeof(T) > sizeof(double)), T, double>;
  Eigen::Matrix<Wide, 3, 3> linear, normalMatrix;  // normalMatrix: inverse transpose of `linear`, times a power of two
  Vec3T<Wide> origin;                              // the object-space point at (about) the local origin
  Vec3T<Wide> residue;                             // its exact local coordinates, the rounding error of `origin`

  explicit LocalFrameT(const Affine3& localFromObject) : linear(localFromObject.linear().cast<Wide>()) {
    const Mat3 inverse = inverseAtAnyScale(localFromObject.linear());
    // Normals only need a direction: the inverse transpose at unit scale cannot overflow in norm().
    normalMatrix = (inverse.transpose() * unitPowerOfTwo(inverse)).cast<Wide>();
    // local = linear (p - origin) + residue: p - origin cancels exactly near the mesh, where
    // linear p + translation would lose the digits of |p| (1e-8 absolute at 1e8 from the origin).
    const Vec3 o = -(inverse * localFromObject.translation());
    origin = (o.allFinite() ? o : Vec3::Zero()).cast<Wide>();
    using Long = long double;
    residue = (localFromObject.linear().cast<Long>() * origin.template cast<Long>() +
               localFromObject.translation().cast<Long>())
                  .template cast<Wide>();
  }

  Vec3T<T> point(const Vec3& p) const { return (linear * (p.cast<Wide>() - origin) + residue).template cast<T>(); }
  Vec3T<T> normal(const Vec3& n) const {
    Vec3T<Wide> m = normalMatrix * n.cast<Wide>();
    Wide length = m.norm();
    if (!(length > Wide(0) && std::isfinite(length))) {  // a normal beyond about 1e+-154 squares out of range
      const Wide largest = m.cwiseAbs().maxCoeff();
      if (largest > Wide(0) && std::isfinite(largest)) m /= largest;
      length = m.norm();
    }
    return length > Wide(0) && std::isfinite(length) ? Vec3T<T>((m / length).template cast<T>()) : Vec3T<T>::Zero();
  }
};

// The surface of `o`, which has a formula of a point (the camera, triplanar and the charts go
// round this: project() and Projector).
template <class T, std::size_t... I>
SurfaceT<T> makeSurface(const ProjectorOptions& o, std::index_sequence<I...>) {
  std::optional<SurfaceT<T>> made;
  const auto makeIf = [&](auto kind) {
    using Of = SurfaceOf<decltype(kind)::value, T>;
    if constexpr (!std::is_void_v<typename Of::type>)
      if (o.surface == decltype(kind)::value) made.emplace(Of::make(o));
  };
  (makeIf(std::integral_constant<SurfaceKind, kSurfaces[I]>()), ...);
  UVTK_CHECK(made.has_value());
  return *std::move(made);
}

template <class T>
SurfaceT<T> makeSurface(const ProjectorOptions& o) {
  return makeSurface<T>(o, std::make_index_sequence<std::size(kSurfaces)>());
}

template <class T>
RayMappingT<T> makeRayMapping(const ProjectorOptions& o, const LocalFrameT<T>& frame) {
  switch (o.ray) {
    case RayKind::SurfaceNormal:
      return SurfaceNormalRayT<T>{};
    case RayKind::Centroid:
      return CentroidRayT<T>{};
    case RayKind::ObjectNormal:
      return ObjectNormalRayT<T>{};
    case RayKind::Reflection:
      if (!o.eye) throw UsageError("the reflection mapping needs an eye position (--eye x,y,z)");
      return ReflectionRayT<T>{frame.point(*o.eye), o.atInfinity};
  }
  return SurfaceNormalRayT<T>{};
}

// Calls f(surface, mapping) with the concrete surface and O-mapping types the options name.
template <class T, class F>
decltype(auto) visitProjector(const ProjectorOptions& o, const LocalFrameT<T>& frame, F&& f) {
  return std::visit(std::forward<F>(f), makeSurface<T>(o), makeRayMapping<T>(o, frame));
}

// The whole two-stage mapping of samples of a non-cube surface: O-mapping, resolve, the hit's
// verdict (judgeHit: miss, behind, not finite, out of range), pole test, S-mapping. Per block: every
// sample to its hit point, the block's arctangents at once, then (u, v). Out is VertexUv, or a
// record with the same members in another precision (ReferenceUv).
template <class T, class S, class M, class Out = VertexUv>
class SampleEvaluator {
 public:
  SampleEvaluator(const S& surface, const M& mapping, const LocalFrameT<T>& frame, PoleTest isPole, MathMode math,
                  const SensibleRangeT<T>& range)
      : surface_(surface), mapping_(mapping), frame_(frame), isPole_(isPole), math_(math), range_(range) {}

  // Samples i < count at object-space position(i) with normal(i) (read only when the O-mapping
  // needs normals) into out[i].
  template <class PositionOf, class NormalOf>
  void operator()(std::size_t count, PositionOf position, NormalOf normal, Out* out) const {
    for (std::size_t start = 0; start < count; start += kBlock)
      block(
          std::min(kBlock, count - start), [&](std::size_t i) -> decltype(auto) { return position(start + i); },
          [&](std::size_t i) -> decltype(auto) { return normal(start + i); }, out + start);
  }

  Out at(const Vec3& position, const Vec3& normal) const {
    Out out;
    block(
        1, [&](std::size_t) -> const Vec3& { return position; }, [&](std::size_t) -> const Vec3& { return normal; },
        &out);
    return out;
  }

 private:
  static constexpr std::size_t kBlock = 256;
  static constexpr std::size_t kAngles = std::max(S::kAngles, 1);
  using OutVec2 = decltype(Out::uv);
  using R = typename OutVec2::Scalar;

// The block's scratch is left uninitialised on purpose (it is written per valid sample and read
// only for those); GCC cannot follow the states and warns.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif
  template <class PositionOf, class NormalOf>
  void block(std::size_t n, PositionOf position, NormalOf normal, Out* out) const {
    std::array<Vec3T<T>, kBlock> q;
    std::array<T, kBlock * kAngles> y, x, angles;
    for (std::size_t i = 0; i < n; ++i) {
      SampleT<T> sample{frame_.point(position(i)), Vec3T<T>::Zero()};
      if constexpr (M::kNeedsNormal) sample.n = frame_.normal(normal(i));
      const HitT<T> hit = surface_.resolve(mapping_.probe(sample));
      out[i] = Out{};
      out[i].reason = judgeHit(hit, range_);
      if (out[i].reason != kCornerValid) {
        for (std::size_t a = 0; a < kAngles; ++a) y[i * kAngles + a] = T(0), x[i * kAngles + a] = T(1);
        continue;
      }
      q[i] = hit.q;
      out[i].axial = OutVec2(R(q[i].x()), R(q[i].y()));
      out[i].state = CornerState::Ok;
      if (atSingularPoint<S>(isPole_, q[i])) out[i].state = CornerState::Pole;
      if constexpr (S::kAngles > 0) {
        const auto arguments = surface_.angleArguments(q[i]);
        for (std::size_t a = 0; a < kAngles; ++a)
          y[i * kAngles + a] = arguments[a].y, x[i * kAngles + a] = arguments[a].x;
      }
    }
    if constexpr (S::kAngles > 0) atan2Block(math_, y.data(), x.data(), angles.data(), n * kAngles);
    for (std::size_t i = 0; i < n; ++i) {
      if (out[i].state == CornerState::Invalid) continue;
      const Vec2T<T> uv = surface_.uvFromAngles(q[i], angles.data() + i * kAngles);
      // u is undefined at a wrapping surface's pole (§5); v is defined there.
      out[i].uv = OutVec2(S::kTraits.wraps && out[i].state == CornerState::Pole ? R(0) : R(uv.x()), R(uv.y()));
      if (!out[i].uv.allFinite())
        out[i].uv = OutVec2::Zero(), out[i].state = CornerState::Invalid, out[i].reason = kCornerNotFinite;
    }
  }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

  S surface_;
  M mapping_;
  LocalFrameT<T> frame_;
  PoleTest isPole_;
  MathMode math_;
  SensibleRangeT<T> range_;
};

// mapVertices in precision T into `out` (positions.size() records): the surface and O-mapping
// the options name, `threads` contiguous ranges of whole blocks, hits judged against the range of
// `sensible` (none: no range check). Throws UsageError for the cube (its face is chosen per
// triangle) and for missing normals.
template <class T, class Out>
void evaluatePositions(const ProjectorOptions& o, const Affine3& localFromObject, const std::vector<Vec3>& positions,
                       const std::vector<Vec3>& normals, Out* out, MathMode math, int threads,
                       const std::optional<Eigen::AlignedBox3d>& sensible = std::nullopt) {
  const LocalFrameT<T> frame(localFromObject);
  visitProjector<T>(o, frame, [&](const auto& s, const auto& m) {
    using S = std::decay_t<decltype(s)>;
    using M = std::decay_t<decltype(m)>;
    if constexpr (std::is_same_v<S, CubeSurfaceT<T>>) {
      throw UsageError("the cube projector chooses a face per triangle: map a mesh with project()");
    } else {
      if (M::kNeedsNormal && normals.size() != positions.size())
        throw UsageError("this O-mapping needs one normal per position");
      const SampleEvaluator<T, S, M, Out> evaluate(s, m, frame, PoleTest(o.poleEpsilon), math,
                                                   SensibleRangeT<T>(sensible));
      const int chunks = threadCount(threads);
      const std::size_t size = (positions.size() / std::size_t(chunks) + 255) / 256 * 256;
      parallelFor(chunks, chunks, [&](int chunk) {
        const std::size_t begin = std::min(positions.size(), std::size_t(chunk) * size);
        const std::size_t end = std::min(positions.size(), begin + size);
        evaluate(
            end - begin, [&](std::size_t i) -> const Vec3& { return positions[begin + i]; },
            [&](std::size_t i) -> const Vec3& { return normals[begin + i]; }, out + begin);
      });
    }
  });
}

}  // namespace uvtk::param
