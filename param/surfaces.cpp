#include "param/surfaces.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace uvtk::param {

TwoPlaneSurface::TwoPlaneSurface(const Vec4& e1, const Vec4& e2) {
  const double n1 = e1.head<3>().norm(), n2 = e2.head<3>().norm();
  if (!(n1 > 0.0) || !(n2 > 0.0) || !std::isfinite(n1) || !std::isfinite(n2))
    throw UsageError("two-plane: each plane needs a finite, non-zero normal (a, b, c)");
  planeU = e1 / n1;
  planeV = e2 / n2;
  const Vec3 a = planeU.head<3>().cross(planeV.head<3>());
  const double sine = a.norm();  // |n1 x n2| of the unit normals: the sine of their angle
  if (!(sine > 1e-12))
    throw UsageError("two-plane: the planes are parallel (the sine of their angle is below 1e-12)");
  axis = a / sine;
}

namespace {

// The face of the box [-1,1]^3 that the ray p + t d (t >= 0) first meets: the exit face from
// inside, the entry face from outside (slab method).
std::optional<CubeFace> boxFaceHit(const Vec3& p, const Vec3& d) {
  double tEnter = -INFINITY, tExit = INFINITY;
  int enterAxis = -1, exitAxis = -1;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      if (std::fabs(p[a]) > 1.0) return std::nullopt;
      continue;
    }
    double tNear = (-1.0 - p[a]) / d[a], tFar = (1.0 - p[a]) / d[a];
    if (tNear > tFar) std::swap(tNear, tFar);
    if (tNear > tEnter) tEnter = tNear, enterAxis = a;
    if (tFar < tExit) tExit = tFar, exitAxis = a;
  }
  if (exitAxis < 0 || !(tEnter <= tExit) || tExit < 0.0) return std::nullopt;
  const bool inside = tEnter < 0.0;
  const int axis = inside ? exitAxis : enterAxis;
  const bool positive = inside ? d[axis] > 0.0 : d[axis] < 0.0;
  return static_cast<CubeFace>(2 * axis + (positive ? 0 : 1));
}

std::optional<CubeFace> faceOfDirection(const Vec3& d) {
  if (isZero(d) || !d.allFinite()) return std::nullopt;
  return majorAxisFace(d);
}

}  // namespace

std::optional<CubeFace> CubeSurface::chooseFace(const Probe& probe, const Vec3& faceNormal) const {
  switch (probe.kind) {
    case Probe::Kind::Foot:  // box mapping; a degenerate triangle falls back to its centroid
      return faceOfDirection(isZero(faceNormal) ? probe.point : faceNormal);
    case Probe::Kind::Central: return faceOfDirection(probe.point);
    case Probe::Kind::Ray: return boxFaceHit(probe.point, probe.direction);
  }
  return std::nullopt;
}

std::optional<CubeFace> CubeSurface::cornerFace(const Probe& probe) const {
  if (probe.kind == Probe::Kind::Ray) return boxFaceHit(probe.point, probe.direction);
  return faceOfDirection(probe.point);
}

std::optional<Vec2> CubeSurface::projectOnFace(const Probe& probe, CubeFace f) const {
  const int a = faceAxis(f);
  const double sign = faceSign(f);
  const Vec3& p = probe.point;
  switch (probe.kind) {
    case Probe::Kind::Foot: {  // orthographic: (sc + 1)/2 with sc, tc of p itself
      const Vec2 c = cubeFaceCoordinates(p, f, convention);
      return Vec2((c.x() + 1.0) * 0.5, (c.y() + 1.0) * 0.5);
    }
    case Probe::Kind::Central:  // central projection onto the face plane
      if (!(p[a] * sign > 0.0)) return std::nullopt;
      return cubeFaceSt(p, f, convention);
    case Probe::Kind::Ray: {
      const Vec3& d = probe.direction;
      if (d[a] == 0.0) return std::nullopt;
      Vec3 hit = p + ((sign - p[a]) / d[a]) * d;
      hit[a] = sign;
      return cubeFaceSt(hit, f, convention);
    }
  }
  return std::nullopt;
}

Vec2 cubeAtlasUv(const Vec2& st, CubeFace f, CubeConvention convention, CubeLayout layout) {
  if (layout == CubeLayout::Faces) return st;
  Vec2 oriented = st;
  if (convention == CubeConvention::Gl) {
    oriented.y() = 1.0 - st.y();
  } else if (f == CubeFace::NegX || f == CubeFace::PosY || f == CubeFace::NegZ) {
    oriented.x() = 1.0 - st.x();
  }
  const int face = static_cast<int>(f);
  int column = 0, row = 0, columns = 1, rows = 1;
  switch (layout) {
    case CubeLayout::Faces: break;
    case CubeLayout::Strip: column = face, columns = 6; break;
    case CubeLayout::ThreeByTwo: column = face % 3, row = face < 3 ? 1 : 0, columns = 3, rows = 2; break;
    case CubeLayout::Cross: {
      // (column, row from the bottom) of +X -X +Y -Y +Z -Z
      static constexpr int kCell[kCubeFaceCount][2] = {{2, 1}, {0, 1}, {1, 2}, {1, 0}, {1, 1}, {3, 1}};
      column = kCell[face][0], row = kCell[face][1], columns = 4, rows = 3;
      break;
    }
  }
  return {(column + oriented.x()) / columns, (row + oriented.y()) / rows};
}

}  // namespace uvtk::param
