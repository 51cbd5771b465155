// The two stages of Bier & Sloan (1986) as types. A RayMapping (O-mapping) turns a vertex into
// a Probe; a Surface (intermediate surface) resolves the probe to a hit point q and gives the
// (u, v) of q (S-mapping). Every surface composes with every ray mapping (docs/conventions.md §4).
// Each type is a template on the scalar T the mapping runs in (float, double, or long double for
// the references that measure the others); the names without a suffix are the double ones.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <variant>

#include "core/math.h"
#include "core/uv_map.h"
#include "param/formulas.h"
#include "param/surface_traits.h"

namespace uvtk::param {

// What an O-mapping sends to the surface, in the surface's local frame.
template <class T>
struct ProbeT {
  enum class Kind {
    Foot,     // the point itself; the surface takes the foot of its own normal through it
    Central,  // the ray from the local origin through `point` (a direction when at infinity)
    Ray,      // the ray point + t direction, first hit t >= 0
  };
  Kind kind = Kind::Foot;
  Vec3T<T> point = Vec3T<T>::Zero();
  Vec3T<T> direction = Vec3T<T>::Zero();
};

// A vertex as the O-mappings see it: local position, unit local normal (zero when unused).
template <class T>
struct SampleT {
  Vec3T<T> p;
  Vec3T<T> n;
};

// ---- O-mappings ----

template <class T>
struct SurfaceNormalRayT {  // `isn`: along the intermediate surface's own normal
  static constexpr bool kNeedsNormal = false;
  ProbeT<T> probe(const SampleT<T>& s) const { return {ProbeT<T>::Kind::Foot, s.p, Vec3T<T>::Zero()}; }
};

template <class T>
struct CentroidRayT {  // `centroid`: from the local origin through the point
  static constexpr bool kNeedsNormal = false;
  ProbeT<T> probe(const SampleT<T>& s) const { return {ProbeT<T>::Kind::Central, s.p, Vec3T<T>::Zero()}; }
};

template <class T>
struct ObjectNormalRayT {  // `normal`: from the point along its normal
  static constexpr bool kNeedsNormal = true;
  ProbeT<T> probe(const SampleT<T>& s) const { return {ProbeT<T>::Kind::Ray, s.p, s.n}; }
};

template <class T>
struct ReflectionRayT {  // `reflection`: the view ray from the eye, mirrored about the normal
  static constexpr bool kNeedsNormal = true;
  Vec3T<T> eye;             // local frame
  bool atInfinity = false;  // look up by direction only, as from the surface's centre
  ProbeT<T> probe(const SampleT<T>& s) const {
    const Vec3T<T> view = (s.p - eye).normalized();
    // Without a normal there is no mirror: a zero direction, which every surface misses.
    const Vec3T<T> r = s.n == Vec3T<T>::Zero() ? s.n : Vec3T<T>(view - T(2) * s.n.dot(view) * s.n);  // V - 2 (N.V) N
    return atInfinity ? ProbeT<T>{ProbeT<T>::Kind::Central, r, Vec3T<T>::Zero()}
                      : ProbeT<T>{ProbeT<T>::Kind::Ray, s.p, r};
  }
};

template <class T>
using RayMappingT = std::variant<SurfaceNormalRayT<T>, CentroidRayT<T>, ObjectNormalRayT<T>, ReflectionRayT<T>>;

// ---- Hit points and their verdict (docs/conventions.md §4) ----

// What a surface makes of a probe: the hit point q in the local frame, or why there is none
// (kCornerMiss, kCornerBehind). Reads like an optional: `if (hit)`, `*hit`, `hit->x()`.
template <class T>
struct HitT {
  Vec3T<T> q = Vec3T<T>::Zero();
  CornerInvalid reason = kCornerMiss;
  // false where q only shares the hit's (u, v) (the radial surfaces' isn and the sphere's central
  // probe return the point itself): then q says nothing about how far the hit lies, and the range
  // rule does not apply.
  bool onSurface = true;
  explicit operator bool() const { return reason == kCornerValid; }
  const Vec3T<T>& operator*() const { return q; }
  const Vec3T<T>* operator->() const { return &q; }
};

template <class T>
HitT<T> hitAt(const Vec3T<T>& q) {
  return {q, kCornerValid, true};
}

template <class T>
HitT<T> sameUvAs(const Vec3T<T>& q) {  // a point with the hit's (u, v), not the hit itself
  return {q, kCornerValid, false};
}

template <class T>
HitT<T> noHit(CornerInvalid reason) {
  return {Vec3T<T>::Zero(), reason, true};
}

// The range rule (§4): a hit lies out of range when some coordinate of q - centre(B) exceeds
// kSensibleRange times the largest half-extent of the sensible box B (param::sensibleBox: the
// mesh's local box united with the surface's unit shape). Far hits come from nearly parallel rays.
constexpr double kSensibleRange = 2.0;

template <class T>
struct SensibleRangeT {
  Vec3T<T> centre = Vec3T<T>::Zero();
  T reach = std::numeric_limits<T>::infinity();  // without a box every finite hit is in range

  SensibleRangeT() = default;
  explicit SensibleRangeT(const std::optional<Eigen::AlignedBox3d>& box) {
    if (!box || box->isEmpty()) return;
    centre = box->center().cast<T>();
    reach = static_cast<T>(kSensibleRange * (0.5 * box->sizes()).maxCoeff());
  }
  bool contains(const Vec3T<T>& q) const { return (q - centre).cwiseAbs().maxCoeff() <= reach; }
};

// Why a hit gives no (u, v), or kCornerValid: the surface's verdict (miss, behind), then a value
// that is not finite, then the range rule. A few compares: it runs once per sample.
template <class T>
CornerInvalid judgeHit(const HitT<T>& hit, const SensibleRangeT<T>& range) {
  if (hit.reason != kCornerValid) return hit.reason;
  if (!hit.q.allFinite()) return kCornerNotFinite;
  if (hit.onSurface && !range.contains(hit.q)) return kCornerOutOfRange;
  return kCornerValid;
}

// ---- Intermediate surfaces ----
// resolve() returns the hit of the probe (HitT: the point q in the local frame, or why there is
// none); radial surfaces may return a point with the hit's (u, v) instead (HitT::onSurface false),
// since their (u, v) and pole tests are scale-invariant.
//
// The S-mapping of a surface runs in two steps, so that the arctangents of a whole block of points
// can be taken at once by a vectorised library (--math fast): angleArguments(q) gives the (y, x)
// pairs whose atan2 the surface needs (kAngles of them), uvFromAngles(q, angles) the (u, v).
// uvAt(q) composes the two with libm's atan2.

// An arctangent's arguments: the angle is atan2(y, x).
template <class T>
struct AtanArguments {
  T y, x;
};

// The smallest t >= 0 with a t^2 + b t + c = 0, computed without cancellation. c is the
// implicit function at the ray's origin; where |c| <= 64 eps cScale the origin counts as on the
// surface and t = 0, so that a vertex of a mesh fitted to the surface hits itself whichever way
// rounding went.
template <class T>
std::optional<T> firstNonNegativeRoot(T a, T b, T c, T cScale);

// Where a surface's (u, v) is not defined: nowhere, on its axis (the poles of the wrapping
// surfaces, §5: u is undefined there, v exact), or at -z alone (the shrink wrap's one point).
enum class Singular { None, Axis, BelowOnly };

// Whether the hit q is at the surface's singular point(s), under the pole test (--pole-eps).
template <class S, class T>
bool atSingularPoint(const PoleTest& isPole, const Vec3T<T>& q) {
  if constexpr (S::kSingular == Singular::None) return false;
  const bool onAxis = isPole(radialDistance(q.x(), q.y()), q.z());
  if constexpr (S::kSingular == Singular::BelowOnly) return onAxis && q.z() < T(0);
  return onAxis;
}

template <class T>
struct PlaneSurfaceT {  // z = 0, (u, v) = (x, y)
  static constexpr SurfaceTraits kTraits{"plane", false, false, true, true, false, false, false, UnitShape::Plane};
  static constexpr Singular kSingular = Singular::None;
  static constexpr int kAngles = 0;
  HitT<T> resolve(const ProbeT<T>& probe) const;
  std::array<AtanArguments<T>, 0> angleArguments(const Vec3T<T>&) const { return {}; }
  Vec2T<T> uvFromAngles(const Vec3T<T>& q, const T*) const { return {q.x(), q.y()}; }
  Vec2T<T> uvAt(const Vec3T<T>& q) const { return uvFromAngles(q, nullptr); }
};

// Two planes E1, E2 in object space: u, v are true signed distances to them. Rays meet the
// plane a.x = 0 (Central: a.x = 1) with a = n1 x n2 / |n1 x n2|, so that the planes
// x = 0 and y = 0 reproduce PlaneSurface.
template <class T>
struct TwoPlaneSurfaceT {
  static constexpr SurfaceTraits kTraits{"two-plane", false, false, false, false, false, false, false, UnitShape::None};
  static constexpr Singular kSingular = Singular::None;
  static constexpr int kAngles = 0;
  Vec4T<T> planeU;  // normalised so that (a, b, c) has unit length
  Vec4T<T> planeV;
  Vec3T<T> axis;  // a
  // Normalises in double, then rounds to T. Throws UsageError for a zero normal or parallel planes.
  TwoPlaneSurfaceT(const Vec4& e1, const Vec4& e2);
  HitT<T> resolve(const ProbeT<T>& probe) const;
  std::array<AtanArguments<T>, 0> angleArguments(const Vec3T<T>&) const { return {}; }
  Vec2T<T> uvFromAngles(const Vec3T<T>& q, const T*) const {
    return {planeU.template head<3>().dot(q) + planeU[3], planeV.template head<3>().dot(q) + planeV[3]};
  }
  Vec2T<T> uvAt(const Vec3T<T>& q) const { return uvFromAngles(q, nullptr); }
};

template <class T>
struct CylinderSurfaceT {  // radius 1 about the z axis
  static constexpr SurfaceTraits kTraits{"cylinder", true, false, true, false, false, false, false, UnitShape::Cylinder};
  static constexpr Singular kSingular = Singular::Axis;
  static constexpr int kAngles = 1;
  HitT<T> resolve(const ProbeT<T>& probe) const;
  std::array<AtanArguments<T>, 1> angleArguments(const Vec3T<T>& q) const { return {{{q.y(), q.x()}}}; }
  // (u, v) = (turn fraction, z) (§3)
  Vec2T<T> uvFromAngles(const Vec3T<T>& q, const T* angles) const { return {turnFromAngle(angles[0]), q.z()}; }
  Vec2T<T> uvAt(const Vec3T<T>& q) const { return cylinderUv(q); }
  double uStart() const { return 0.0; }
  double uPerTurn() const { return 1.0; }  // u grows counter-clockwise seen from +z
};

template <class T>
struct SphereSurfaceT {  // radius 1 about the origin
  static constexpr SurfaceTraits kTraits{"sphere", true, false, true, false, false, false, false, UnitShape::Ball};
  static constexpr Singular kSingular = Singular::Axis;
  static constexpr int kAngles = 2;
  SpherePreset preset = SpherePreset::Default;
  HitT<T> resolve(const ProbeT<T>& probe) const;
  // The azimuth's arguments for the preset, then those of the angle from the nearer pole (§3).
  std::array<AtanArguments<T>, 2> angleArguments(const Vec3T<T>& q) const {
    const auto [y, x] = sphereAzimuthArguments(q, preset);
    return {{{y, x}, {radialDistance(q.x(), q.y()), std::fabs(q.z())}}};
  }
  Vec2T<T> uvFromAngles(const Vec3T<T>& q, const T* angles) const {
    return {sphereUFromAngle(angles[0], preset), sphereVFromPoleAngle(angles[1], std::signbit(q.z()), preset)};
  }
  Vec2T<T> uvAt(const Vec3T<T>& q) const { return sphereUv(q, preset); }
  double uStart() const { return uPeriodStart(preset); }
  double uPerTurn() const { return preset == SpherePreset::Glu ? -1.0 : 1.0; }  // gluSphere's s runs clockwise
};

// The octahedral map of the direction of q (Cigolle, Donow, Evangelakos, Mara, McGuire, Meyer, "A
// Survey of Efficient Representations for Independent Unit Vectors", JCGT 3(2), 2014): p = q / |q|_1;
// where p_z < 0 the lower half folds out over the corners, (p_x, p_y) <- ((1 - |p_y|) sign p_x,
// (1 - |p_x|) sign p_y) with sign(0) = +1; (u, v) = (p_x, p_y)/2 + 1/2. Any positive scale of q.
template <class T>
Vec2T<T> octahedralUv(const Vec3T<T>& q) {
  const T l1 = std::fabs(q.x()) + std::fabs(q.y()) + std::fabs(q.z());
  T px = q.x() / l1, py = q.y() / l1;
  if (q.z() < T(0)) {
    const T sx = px < T(0) ? T(-1) : T(1), sy = py < T(0) ? T(-1) : T(1);  // -0 counts as 0: +1
    const T foldedX = (T(1) - std::fabs(py)) * sx, foldedY = (T(1) - std::fabs(px)) * sy;
    px = foldedX, py = foldedY;
  }
  return {px * T(0.5) + T(0.5), py * T(0.5) + T(0.5)};
}

// The unit sphere's directions on the square (docs/conventions.md §3). No angle.
template <class T>
struct OctahedralSurfaceT {
  static constexpr SurfaceTraits kTraits{"octahedral", false, false, true, false, false, false, false, UnitShape::Ball};
  static constexpr Singular kSingular = Singular::None;
  static constexpr int kAngles = 0;
  HitT<T> resolve(const ProbeT<T>& probe) const { return SphereSurfaceT<T>{}.resolve(probe); }
  std::array<AtanArguments<T>, 0> angleArguments(const Vec3T<T>&) const { return {}; }
  Vec2T<T> uvFromAngles(const Vec3T<T>& q, const T*) const { return octahedralUv(q); }
  Vec2T<T> uvAt(const Vec3T<T>& q) const { return octahedralUv(q); }
};

// 3ds Max's shrink wrap, the azimuthal equidistant projection about the -z pole: theta the angle
// of q from +z (atan2(hypot(x, y), z), in [0, pi]), phi its azimuth from +x; (u, v) = (1/2 + (theta
// / pi) cos phi / 2, 1/2 + (theta / pi) sin phi / 2), with cos phi = x / hypot(x, y), sin phi = y /
// hypot(x, y). +z maps to the centre (1/2, 1/2); -z, the one singular point, to the unit circle
// about it, here at phi = 0: (1, 1/2).
template <class T>
Vec2T<T> shrinkWrapUv(const Vec3T<T>& q, T theta) {
  const T r = radialDistance(q.x(), q.y());
  const T radius = theta / T(kPi) * T(0.5);
  if (!(r > T(0))) return {T(0.5) + radius, T(0.5)};
  return {T(0.5) + radius * (q.x() / r), T(0.5) + radius * (q.y() / r)};
}

// One singular point (-z) instead of two poles (docs/conventions.md §3). One angle: theta from +z.
template <class T>
struct ShrinkWrapSurfaceT {
  static constexpr SurfaceTraits kTraits{"shrink-wrap", false, false, true, false, false, false, false, UnitShape::Ball};
  static constexpr Singular kSingular = Singular::BelowOnly;
  static constexpr int kAngles = 1;
  HitT<T> resolve(const ProbeT<T>& probe) const { return SphereSurfaceT<T>{}.resolve(probe); }
  std::array<AtanArguments<T>, 1> angleArguments(const Vec3T<T>& q) const {
    return {{{radialDistance(q.x(), q.y()), q.z()}}};
  }
  Vec2T<T> uvFromAngles(const Vec3T<T>& q, const T* angles) const { return shrinkWrapUv(q, angles[0]); }
  Vec2T<T> uvAt(const Vec3T<T>& q) const {
    return shrinkWrapUv(q, std::atan2(radialDistance(q.x(), q.y()), q.z()));
  }
};

// The box [-1, 1]^3. Faces are chosen per triangle (chooseFace); each corner is then projected
// onto that face's plane by its own probe (projectOnFace), then to (s, t) (faceSt).
template <class T>
struct CubeSurfaceT {
  static constexpr SurfaceTraits kTraits{"cube", false, true, true, false, false, false, true, UnitShape::Cube};
  static constexpr Singular kSingular = Singular::None;
  CubeConvention convention = CubeConvention::Gl;
  CubeLayout layout = CubeLayout::Faces;
  // `faceNormal` is the triangle's normal, used by Foot probes (box mapping).
  std::optional<CubeFace> chooseFace(const ProbeT<T>& probe, const Vec3T<T>& faceNormal) const;
  // The face a corner alone would choose (Foot probes: the major axis of its position).
  std::optional<CubeFace> cornerFace(const ProbeT<T>& probe) const;
  // The probe's hit on face f's plane (a Ray probe: for t >= 0 only, else kCornerBehind).
  HitT<T> projectOnFace(const ProbeT<T>& probe, CubeFace f) const;
  // Face coordinates (s, t) of a hit on face f's plane, before the layout.
  Vec2T<T> faceSt(const Vec3T<T>& q, CubeFace f) const { return cubeFaceSt(q, f, convention); }
  Vec2T<T> uvAt(const Vec2T<T>& st, CubeFace f) const { return cubeAtlasUv(st, f, convention, layout); }
};

// ---- The surfaces by kind ----
// SurfaceOf<kind, T>::type is the struct of a surface with a formula of a point, made from the
// projector's options by make(); void for the others (placement.h). A new surface is its struct
// above and its SurfaceOf here: SurfaceT, makeSurface and traitsOf follow.
template <SurfaceKind Kind, class T>
struct SurfaceOf {
  using type = void;
};
template <class T>
struct SurfaceOf<SurfaceKind::Plane, T> {
  using type = PlaneSurfaceT<T>;
  template <class Options>
  static type make(const Options&) { return {}; }
};
template <class T>
struct SurfaceOf<SurfaceKind::TwoPlane, T> {
  using type = TwoPlaneSurfaceT<T>;
  template <class Options>
  static type make(const Options& o) { return {o.planeU, o.planeV}; }
};
template <class T>
struct SurfaceOf<SurfaceKind::Cylinder, T> {
  using type = CylinderSurfaceT<T>;
  template <class Options>
  static type make(const Options&) { return {}; }
};
template <class T>
struct SurfaceOf<SurfaceKind::Sphere, T> {
  using type = SphereSurfaceT<T>;
  template <class Options>
  static type make(const Options& o) { return {o.spherePreset}; }
};
template <class T>
struct SurfaceOf<SurfaceKind::Cube, T> {
  using type = CubeSurfaceT<T>;
  template <class Options>
  static type make(const Options& o) { return {o.cubeConvention, o.cubeLayout}; }
};
template <class T>
struct SurfaceOf<SurfaceKind::Octahedral, T> {
  using type = OctahedralSurfaceT<T>;
  template <class Options>
  static type make(const Options&) { return {}; }
};
template <class T>
struct SurfaceOf<SurfaceKind::ShrinkWrap, T> {
  using type = ShrinkWrapSurfaceT<T>;
  template <class Options>
  static type make(const Options&) { return {}; }
};

namespace detail {
// std::variant of the types among Ts that are not void, in their order.
template <class Variant, class... Ts>
struct VariantOfTypes {
  using type = Variant;
};
template <class... Vs, class First, class... Rest>
struct VariantOfTypes<std::variant<Vs...>, First, Rest...> {
  using type = typename VariantOfTypes<
      std::conditional_t<std::is_void_v<First>, std::variant<Vs...>, std::variant<Vs..., First>>, Rest...>::type;
};
template <class T, std::size_t... I>
auto surfaceVariant(std::index_sequence<I...>) ->
    typename VariantOfTypes<std::variant<>, typename SurfaceOf<kSurfaces[I], T>::type...>::type;
}  // namespace detail

// Every surface with a formula of a point, in kSurfaces' order.
template <class T>
using SurfaceT = decltype(detail::surfaceVariant<T>(std::make_index_sequence<std::size(kSurfaces)>()));

// Whether `surface` has a formula of a point (a struct above), rather than a camera's perspective,
// triplanar's blend or charts made from the whole mesh.
template <std::size_t... I>
constexpr bool hasPointFormula(SurfaceKind surface, std::index_sequence<I...>) {
  return ((surface == kSurfaces[I] && !std::is_void_v<typename SurfaceOf<kSurfaces[I], double>::type>) || ...);
}
constexpr bool hasPointFormula(SurfaceKind surface) {
  return hasPointFormula(surface, std::make_index_sequence<std::size(kSurfaces)>());
}

using Probe = ProbeT<double>;
using Sample = SampleT<double>;
using SurfaceNormalRay = SurfaceNormalRayT<double>;
using CentroidRay = CentroidRayT<double>;
using ObjectNormalRay = ObjectNormalRayT<double>;
using ReflectionRay = ReflectionRayT<double>;
using RayMapping = RayMappingT<double>;
using PlaneSurface = PlaneSurfaceT<double>;
using TwoPlaneSurface = TwoPlaneSurfaceT<double>;
using CylinderSurface = CylinderSurfaceT<double>;
using SphereSurface = SphereSurfaceT<double>;
using CubeSurface = CubeSurfaceT<double>;
using Surface = SurfaceT<double>;

// ---- Inline definitions: the per-vertex hot path ----

template <class T>
std::optional<T> firstNonNegativeRoot(T a, T b, T c, T cScale) {
  // An overflowed c (|p|^2 = inf far out) would pass as "on the surface": there it is a miss.
  if (std::isfinite(c) && std::fabs(c) <= T(64) * std::numeric_limits<T>::epsilon() * cScale) return T(0);
  if (a == T(0)) {  // the ray runs parallel to the surface's axis: on it everywhere or nowhere
    if (b != T(0)) {
      const T t = -c / b;
      return t >= T(0) ? std::optional<T>(t) : std::nullopt;
    }
    return c == T(0) ? std::optional<T>(T(0)) : std::nullopt;
  }
  const T discriminant = b * b - T(4) * a * c;
  if (!(discriminant >= T(0))) return std::nullopt;
  // Numerical Recipes' form: q = -(b + sign(b) sqrt(D)) / 2, roots q/a and c/q.
  const T q = T(-0.5) * (b + std::copysign(std::sqrt(discriminant), b));
  T t0 = q / a;
  T t1 = q != T(0) ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  if (t0 >= T(0)) return t0;
  if (t1 >= T(0)) return t1;
  return std::nullopt;
}

template <class T>
bool isZero(const Vec3T<T>& v) {
  return v.x() == T(0) && v.y() == T(0) && v.z() == T(0);
}

// Where the ray p + t d (t >= 0) meets the plane n.x = level: a miss when they are parallel,
// kCornerBehind when only the line does (t < 0). An origin on the plane to 64 ulp hits at t = 0,
// as in firstNonNegativeRoot, so that a vertex on a plane (a cube mesh on its fitted cube) does
// not fall behind by rounding.
template <class T>
HitT<T> rayMeetsPlane(const ProbeT<T>& probe, const Vec3T<T>& n, T level) {
  const Vec3T<T>& p = probe.point;
  const T along = n.dot(probe.direction);
  if (along == T(0)) return noHit<T>(kCornerMiss);
  const T offset = n.dot(p) - level;
  if (std::fabs(offset) <= T(64) * std::numeric_limits<T>::epsilon() * std::max(T(1), p.cwiseAbs().maxCoeff()))
    return hitAt<T>(p);
  const T t = -offset / along;
  if (t < T(0)) return noHit<T>(kCornerBehind);
  return hitAt<T>(p + t * probe.direction);  // a NaN t leaves q not finite: judgeHit says so
}

template <class T>
HitT<T> PlaneSurfaceT<T>::resolve(const ProbeT<T>& probe) const {
  using Kind = typename ProbeT<T>::Kind;
  const Vec3T<T>& p = probe.point;
  switch (probe.kind) {
    case Kind::Foot:
      return hitAt<T>(Vec3T<T>(p.x(), p.y(), T(0)));
    case Kind::Central:  // central projection onto z = 1
      if (!(p.z() > T(0))) return noHit<T>(kCornerMiss);
      return hitAt<T>(Vec3T<T>(p.x() / p.z(), p.y() / p.z(), T(1)));
    case Kind::Ray: {
      HitT<T> hit = rayMeetsPlane(probe, Vec3T<T>(Vec3T<T>::UnitZ()), T(0));
      if (hit) hit.q.z() = T(0);
      return hit;
    }
  }
  return noHit<T>(kCornerMiss);
}

template <class T>
HitT<T> TwoPlaneSurfaceT<T>::resolve(const ProbeT<T>& probe) const {
  using Kind = typename ProbeT<T>::Kind;
  const Vec3T<T>& p = probe.point;
  switch (probe.kind) {
    case Kind::Foot:
      return hitAt<T>(p);
    case Kind::Central: {  // central projection onto a.x = 1
      const T along = axis.dot(p);
      if (!(along > T(0))) return noHit<T>(kCornerMiss);
      return hitAt<T>(Vec3T<T>(p / along));
    }
    case Kind::Ray:
      return rayMeetsPlane(probe, axis, T(0));
  }
  return noHit<T>(kCornerMiss);
}

template <class T>
HitT<T> CylinderSurfaceT<T>::resolve(const ProbeT<T>& probe) const {
  using Kind = typename ProbeT<T>::Kind;
  const Vec3T<T>& p = probe.point;
  switch (probe.kind) {
    case Kind::Foot:
      return sameUvAs<T>(p);  // same azimuth and height as (x/rho, y/rho, z)
    case Kind::Central: {
      const T rho = radialDistance(p.x(), p.y());
      if (!(rho > T(0))) return noHit<T>(kCornerMiss);  // along the axis the ray never meets the side
      return hitAt<T>(Vec3T<T>(p / rho));
    }
    case Kind::Ray: {
      const Vec3T<T>& d = probe.direction;
      if (isZero(d)) return noHit<T>(kCornerMiss);  // no direction (a zero normal): not a ray, even from the side
      const T radial2 = p.x() * p.x() + p.y() * p.y();
      const std::optional<T> t =
          firstNonNegativeRoot(d.x() * d.x() + d.y() * d.y(), T(2) * (p.x() * d.x() + p.y() * d.y()), radial2 - T(1),
                               std::max(T(1), radial2));
      if (!t) return noHit<T>(kCornerMiss);  // no root, or both behind: a miss (§4)
      return hitAt<T>(Vec3T<T>(p + *t * d));
    }
  }
  return noHit<T>(kCornerMiss);
}

template <class T>
HitT<T> SphereSurfaceT<T>::resolve(const ProbeT<T>& probe) const {
  using Kind = typename ProbeT<T>::Kind;
  const Vec3T<T>& p = probe.point;
  switch (probe.kind) {
    case Kind::Foot:
    case Kind::Central:  // radial: the hit point is p/|p|, and (u, v) ignore the scale
      if (isZero(p)) return noHit<T>(kCornerMiss);
      return sameUvAs<T>(p);
    case Kind::Ray: {
      const Vec3T<T>& d = probe.direction;
      if (isZero(d)) return noHit<T>(kCornerMiss);  // no direction (a zero normal): not a ray, even from the surface
      const T p2 = p.squaredNorm();
      const std::optional<T> t = firstNonNegativeRoot(d.squaredNorm(), T(2) * p.dot(d), p2 - T(1), std::max(T(1), p2));
      if (!t) return noHit<T>(kCornerMiss);  // no root, or both behind: a miss (§4)
      return hitAt<T>(Vec3T<T>(p + *t * d));
    }
  }
  return noHit<T>(kCornerMiss);
}

}  // namespace uvtk::param
