// The two stages of Bier & Sloan (1986) as types. A RayMapping (O-mapping) turns a vertex into
// a Probe; a Surface (intermediate surface) resolves the probe to a hit point q and gives the
// (u, v) of q (S-mapping). Every surface composes with every ray mapping (docs/conventions.md §4).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <variant>

#include "core/math.h"
#include "param/formulas.h"

namespace uvtk::param {

// What an O-mapping sends to the surface, in the surface's local frame.
struct Probe {
  enum class Kind {
    Foot,     // the point itself; the surface takes the foot of its own normal through it
    Central,  // the ray from the local origin through `point` (a direction when at infinity)
    Ray,      // the ray point + t direction, first hit t >= 0 (planes: the line's crossing)
  };
  Kind kind = Kind::Foot;
  Vec3 point = Vec3::Zero();
  Vec3 direction = Vec3::Zero();
};

// A vertex as the O-mappings see it: local position, unit local normal (zero when unused).
struct Sample {
  Vec3 p;
  Vec3 n;
};

// ---- O-mappings ----

struct SurfaceNormalRay {  // `isn`: along the intermediate surface's own normal
  static constexpr bool kNeedsNormal = false;
  Probe probe(const Sample& s) const { return {Probe::Kind::Foot, s.p, Vec3::Zero()}; }
};

struct CentroidRay {  // `centroid`: from the local origin through the point
  static constexpr bool kNeedsNormal = false;
  Probe probe(const Sample& s) const { return {Probe::Kind::Central, s.p, Vec3::Zero()}; }
};

struct ObjectNormalRay {  // `normal`: from the point along its normal
  static constexpr bool kNeedsNormal = true;
  Probe probe(const Sample& s) const { return {Probe::Kind::Ray, s.p, s.n}; }
};

struct ReflectionRay {  // `reflection`: the view ray from the eye, mirrored about the normal
  static constexpr bool kNeedsNormal = true;
  Vec3 eye;                 // local frame
  bool atInfinity = false;  // look up by direction only, as from the surface's centre
  Probe probe(const Sample& s) const {
    const Vec3 view = (s.p - eye).normalized();
    const Vec3 r = view - 2.0 * s.n.dot(view) * s.n;  // R = V - 2 (N.V) N
    return atInfinity ? Probe{Probe::Kind::Central, r, Vec3::Zero()} : Probe{Probe::Kind::Ray, s.p, r};
  }
};

using RayMapping = std::variant<SurfaceNormalRay, CentroidRay, ObjectNormalRay, ReflectionRay>;

// ---- Intermediate surfaces ----
// resolve() returns the hit point q (local frame; radial surfaces may return any positive
// multiple of it, since their (u, v) and pole tests are scale-invariant) or nothing on a miss.

// The smallest t >= 0 with a t^2 + b t + c = 0, computed without cancellation. c is the
// implicit function at the ray's origin; where |c| <= 64 eps cScale the origin counts as on the
// surface and t = 0, so that a vertex of a mesh fitted to the surface hits itself whichever way
// rounding went.
inline std::optional<double> firstNonNegativeRoot(double a, double b, double c, double cScale);

struct PlaneSurface {  // z = 0, (u, v) = (x, y)
  static constexpr bool kWraps = false;
  std::optional<Vec3> resolve(const Probe& probe) const;
  Vec2 uvAt(const Vec3& q) const { return {q.x(), q.y()}; }
};

// Two planes E1, E2 in object space: u, v are true signed distances to them. Rays meet the
// plane a.x = 0 (Central: a.x = 1) with a = n1 x n2 / |n1 x n2|, so that the planes
// x = 0 and y = 0 reproduce PlaneSurface.
struct TwoPlaneSurface {
  static constexpr bool kWraps = false;
  Vec4 planeU;  // normalised so that (a, b, c) has unit length
  Vec4 planeV;
  Vec3 axis;    // a
  // Throws UsageError for a zero normal or parallel planes.
  TwoPlaneSurface(const Vec4& e1, const Vec4& e2);
  std::optional<Vec3> resolve(const Probe& probe) const;
  Vec2 uvAt(const Vec3& q) const {
    return {planeU.head<3>().dot(q) + planeU[3], planeV.head<3>().dot(q) + planeV[3]};
  }
};

struct CylinderSurface {  // radius 1 about the z axis
  static constexpr bool kWraps = true;
  std::optional<Vec3> resolve(const Probe& probe) const;
  Vec2 uvAt(const Vec3& q) const { return cylinderUv(q); }
  double vAt(const Vec3& q) const { return q.z(); }
  double uStart() const { return 0.0; }
  double uPerTurn() const { return 1.0; }  // u grows counter-clockwise seen from +z
};

struct SphereSurface {  // radius 1 about the origin
  static constexpr bool kWraps = true;
  SpherePreset preset = SpherePreset::Default;
  std::optional<Vec3> resolve(const Probe& probe) const;
  Vec2 uvAt(const Vec3& q) const { return sphereUv(q, preset); }
  double vAt(const Vec3& q) const { return sphereV(q, preset); }
  double uStart() const { return uPeriodStart(preset); }
  double uPerTurn() const { return preset == SpherePreset::Glu ? -1.0 : 1.0; }  // gluSphere's s runs clockwise
};

// The box [-1, 1]^3. Faces are chosen per triangle (chooseFace); each corner is then projected
// onto that face's plane by its own probe (projectOnFace).
struct CubeSurface {
  static constexpr bool kWraps = false;
  CubeConvention convention = CubeConvention::Gl;
  CubeLayout layout = CubeLayout::Faces;
  // `faceNormal` is the triangle's normal, used by Foot probes (box mapping).
  std::optional<CubeFace> chooseFace(const Probe& probe, const Vec3& faceNormal) const;
  // The face a corner alone would choose (Foot probes: the major axis of its position).
  std::optional<CubeFace> cornerFace(const Probe& probe) const;
  // Face coordinates (s, t) of the probe on face f's plane, before the layout.
  std::optional<Vec2> projectOnFace(const Probe& probe, CubeFace f) const;
  Vec2 uvAt(const Vec2& st, CubeFace f) const { return cubeAtlasUv(st, f, convention, layout); }
};

using Surface = std::variant<PlaneSurface, TwoPlaneSurface, CylinderSurface, SphereSurface, CubeSurface>;


// ---- Inline definitions: the per-vertex hot path ----

inline std::optional<double> firstNonNegativeRoot(double a, double b, double c, double cScale) {
  if (std::fabs(c) <= 64.0 * std::numeric_limits<double>::epsilon() * cScale) return 0.0;
  if (a == 0.0) {  // the ray runs parallel to the surface's axis: on it everywhere or nowhere
    if (b != 0.0) {
      const double t = -c / b;
      return t >= 0.0 ? std::optional<double>(t) : std::nullopt;
    }
    return c == 0.0 ? std::optional<double>(0.0) : std::nullopt;
  }
  const double discriminant = b * b - 4.0 * a * c;
  if (!(discriminant >= 0.0)) return std::nullopt;
  // Numerical Recipes' form: q = -(b + sign(b) sqrt(D)) / 2, roots q/a and c/q.
  const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
  double t0 = q / a;
  double t1 = q != 0.0 ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  if (t0 >= 0.0) return t0;
  if (t1 >= 0.0) return t1;
  return std::nullopt;
}

inline bool isZero(const Vec3& v) { return v.x() == 0.0 && v.y() == 0.0 && v.z() == 0.0; }

// The crossing of the ray's line with the plane n.x = 0; nothing when they are parallel.
inline std::optional<Vec3> lineMeetsPlane(const Probe& probe, const Vec3& n) {
  const double along = n.dot(probe.direction);
  if (along == 0.0) return std::nullopt;
  return Vec3(probe.point - (n.dot(probe.point) / along) * probe.direction);
}

inline std::optional<Vec3> PlaneSurface::resolve(const Probe& probe) const {
  const Vec3& p = probe.point;
  switch (probe.kind) {
    case Probe::Kind::Foot: return Vec3(p.x(), p.y(), 0.0);
    case Probe::Kind::Central:  // central projection onto z = 1
      if (!(p.z() > 0.0)) return std::nullopt;
      return Vec3(p.x() / p.z(), p.y() / p.z(), 1.0);
    case Probe::Kind::Ray: {
      std::optional<Vec3> hit = lineMeetsPlane(probe, Vec3::UnitZ());
      if (hit) hit->z() = 0.0;
      return hit;
    }
  }
  return std::nullopt;
}

inline std::optional<Vec3> TwoPlaneSurface::resolve(const Probe& probe) const {
  const Vec3& p = probe.point;
  switch (probe.kind) {
    case Probe::Kind::Foot: return p;
    case Probe::Kind::Central: {  // central projection onto a.x = 1
      const double along = axis.dot(p);
      if (!(along > 0.0)) return std::nullopt;
      return Vec3(p / along);
    }
    case Probe::Kind::Ray: return lineMeetsPlane(probe, axis);
  }
  return std::nullopt;
}

inline std::optional<Vec3> CylinderSurface::resolve(const Probe& probe) const {
  const Vec3& p = probe.point;
  switch (probe.kind) {
    case Probe::Kind::Foot: return p;  // same azimuth and height as (x/rho, y/rho, z)
    case Probe::Kind::Central: {
      const double rho = radialDistance(p.x(), p.y());
      if (!(rho > 0.0)) return std::nullopt;  // along the axis the ray never meets the side
      return Vec3(p / rho);
    }
    case Probe::Kind::Ray: {
      const Vec3& d = probe.direction;
      const std::optional<double> t =
          firstNonNegativeRoot(d.x() * d.x() + d.y() * d.y(), 2.0 * (p.x() * d.x() + p.y() * d.y()),
                               p.x() * p.x() + p.y() * p.y() - 1.0, std::max(1.0, p.x() * p.x() + p.y() * p.y()));
      if (!t) return std::nullopt;
      return Vec3(p + *t * d);
    }
  }
  return std::nullopt;
}

inline std::optional<Vec3> SphereSurface::resolve(const Probe& probe) const {
  const Vec3& p = probe.point;
  switch (probe.kind) {
    case Probe::Kind::Foot:
    case Probe::Kind::Central:  // radial: the hit point is p/|p|, and (u, v) ignore the scale
      if (isZero(p)) return std::nullopt;
      return p;
    case Probe::Kind::Ray: {
      const Vec3& d = probe.direction;
      const std::optional<double> t = firstNonNegativeRoot(d.squaredNorm(), 2.0 * p.dot(d), p.squaredNorm() - 1.0, std::max(1.0, p.squaredNorm()));
      if (!t) return std::nullopt;
      return Vec3(p + *t * d);
    }
  }
  return std::nullopt;
}

}  // namespace uvtk::param
