#include "param/surfaces.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace uvtk::param {

template <class T>
TwoPlaneSurfaceT<T>::TwoPlaneSurfaceT(const Vec4& e1, const Vec4& e2) {
  const double n1 = e1.head<3>().norm(), n2 = e2.head<3>().norm();
  if (!(n1 > 0.0) || !(n2 > 0.0) || !std::isfinite(n1) || !std::isfinite(n2))
    throw UsageError("two-plane: each plane needs a finite, non-zero normal (a, b, c)");
  const Vec4 unitU = e1 / n1, unitV = e2 / n2;
  const Vec3 a = unitU.head<3>().cross(unitV.head<3>());
  const double sine = a.norm();  // |n1 x n2| of the unit normals: the sine of their angle
  if (!(sine > 1e-12)) throw UsageError("two-plane: the planes are parallel (the sine of their angle is below 1e-12)");
  planeU = unitU.cast<T>();
  planeV = unitV.cast<T>();
  axis = (a / sine).cast<T>();
}

namespace {

// The face of the box [-1,1]^3 that the ray p + t d (t >= 0) first meets: the exit face from
// inside, the entry face from outside (slab method).
template <class T>
std::optional<CubeFace> boxFaceHit(const Vec3T<T>& p, const Vec3T<T>& d) {
  T tEnter = -std::numeric_limits<T>::infinity(), tExit = std::numeric_limits<T>::infinity();
  int enterAxis = -1, exitAxis = -1;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == T(0)) {
      if (std::fabs(p[a]) > T(1)) return std::nullopt;
      continue;
    }
    T tNear = (T(-1) - p[a]) / d[a], tFar = (T(1) - p[a]) / d[a];
    if (tNear > tFar) std::swap(tNear, tFar);
    if (tNear > tEnter) tEnter = tNear, enterAxis = a;
    if (tFar < tExit) tExit = tFar, exitAxis = a;
  }
  if (exitAxis < 0 || !(tEnter <= tExit) || tExit < T(0)) return std::nullopt;
  const bool inside = tEnter < T(0);
  const int axis = inside ? exitAxis : enterAxis;
  const bool positive = inside ? d[axis] > T(0) : d[axis] < T(0);
  return static_cast<CubeFace>(2 * axis + (positive ? 0 : 1));
}

template <class T>
std::optional<CubeFace> faceOfDirection(const Vec3T<T>& d) {
  if (isZero(d) || !d.allFinite()) return std::nullopt;
  return majorAxisFace(d);
}

}  // namespace

template <class T>
std::optional<CubeFace> CubeSurfaceT<T>::chooseFace(const ProbeT<T>& probe, const Vec3T<T>& faceNormal) const {
  using Kind = typename ProbeT<T>::Kind;
  switch (probe.kind) {
    case Kind::Foot:  // box mapping; a degenerate triangle falls back to its centroid
      return faceOfDirection(isZero(faceNormal) ? probe.point : faceNormal);
    case Kind::Central:
      return faceOfDirection(probe.point);
    case Kind::Ray:
      return boxFaceHit(probe.point, probe.direction);
  }
  return std::nullopt;
}

template <class T>
std::optional<CubeFace> CubeSurfaceT<T>::cornerFace(const ProbeT<T>& probe) const {
  if (probe.kind == ProbeT<T>::Kind::Ray) return boxFaceHit(probe.point, probe.direction);
  return faceOfDirection(probe.point);
}

template <class T>
HitT<T> CubeSurfaceT<T>::projectOnFace(const ProbeT<T>& probe, CubeFace f) const {
  using Kind = typename ProbeT<T>::Kind;
  const int a = faceAxis(f);
  const T sign = T(faceSign(f));
  const Vec3T<T>& p = probe.point;
  HitT<T> hit = noHit<T>(kCornerMiss);
  switch (probe.kind) {
    case Kind::Foot:  // orthographic: p moved along the face's axis onto its plane
      hit = hitAt<T>(p);
      break;
    case Kind::Central:  // central projection onto the face plane
      if (!(p[a] * sign > T(0))) return noHit<T>(kCornerMiss);
      hit = hitAt<T>(Vec3T<T>(p / std::fabs(p[a])));
      break;
    case Kind::Ray:
      hit = rayMeetsPlane(probe, Vec3T<T>(Vec3T<T>::Unit(a)), sign);
      break;
  }
  if (hit) hit.q[a] = sign;
  return hit;
}

template struct TwoPlaneSurfaceT<float>;
template struct TwoPlaneSurfaceT<double>;
template struct TwoPlaneSurfaceT<long double>;
template struct CubeSurfaceT<float>;
template struct CubeSurfaceT<double>;
template struct CubeSurfaceT<long double>;

}  // namespace uvtk::param
