// The S-mapping formulas: each in exactly one place, each as a free function of local
// coordinates. Conventions: docs/conventions.md (section numbers below refer to it).
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

#include "core/cube.h"
#include "core/math.h"

namespace uvtk::param {

// hypot(x, y) without std::hypot's cost where the squares neither overflow nor underflow in T;
// the fallback keeps huge and tiny coordinates exact.
template <class T>
T radialDistance(T x, T y) {
  // Squares of magnitudes in (kLow, 1/kLow) neither overflow nor lose digits to subnormals.
  constexpr T kLow = std::is_same_v<T, float> ? T(1e-15f) : T(1e-150);
  const T m = std::fmax(std::fabs(x), std::fabs(y));
  if (m > kLow && m < T(1) / kLow) return std::sqrt(x * x + y * y);
  return std::hypot(x, y);
}

// Fraction of a full turn of the angle theta = atan2(y, x) in (-pi, pi], in [0, 1): the seam
// lies on the +x half-plane, u grows counter-clockwise seen from +z; +0 and -0 land on the same
// side (§3). Written without branches so that a block of angles vectorises.
template <class T>
T turnFromAngle(T theta) {
  constexpr T kTurn = T(kTwoPi), kInverseTurn = T(1.0 / kTwoPi);
  const T u = (theta + static_cast<T>(theta < T(0)) * kTurn) * kInverseTurn + T(0);  // -0 becomes +0
  return u * static_cast<T>(u < T(1));
}

// The turn fraction of (x, y) with libm's atan2. Precondition: (x, y) != (0, 0); poles are
// handled before this is called.
template <class T>
T turnFraction(T y, T x) {
  return turnFromAngle(std::atan2(y, x));
}

// The pole test hypot(x, y) <= eps |q| of §5 without a square root: for eps in [0, 1) it holds
// exactly when rho <= eps / sqrt(1 - eps^2) |z|.
struct PoleTest {
  double slope;
  explicit PoleTest(double epsilon) : slope(epsilon / std::sqrt(1.0 - epsilon * epsilon)) {}
  template <class T>
  bool operator()(T rho, T z) const {
    return rho <= static_cast<T>(slope) * std::fabs(z);
  }
};

// The angle from the nearer pole, in [0, pi/2]: atan2 keeps full precision near the poles where
// acos loses half the digits, and measuring from the nearer pole keeps it where v is small (§3).
template <class T>
T angleFromNearerPole(T x, T y, T z) {
  return std::atan2(radialDistance(x, y), std::fabs(z));
}

// Cylinder, radius 1, axis z: (u, v) = (turn fraction, z) (§3).
template <class T>
Vec2T<T> cylinderUv(const Vec3T<T>& q) {
  return {turnFraction(q.y(), q.x()), q.z()};
}

// Sphere conventions (§3). Each maps a point (any positive scale) to (u, v).
enum class SpherePreset {
  Default,  // u = turn fraction from +x, v = 1 - phi/pi (v = 1 at +z)
  Glu,      // gluSphere: s = 0 at +y, 0.25 at +x, 0.5 at -y, 0.75 at -x; t = 0 at -z, 1 at +z
  Seed004,  // s = atan2(y, x)/(2 pi) in (-1/2, 1/2], t = acos(z)/pi (t = 0 at +z)
};

// The arctangent arguments (y, x) of a sphere preset's azimuth at q (§3).
template <class T>
std::pair<T, T> sphereAzimuthArguments(const Vec3T<T>& q, SpherePreset preset) {
  return preset == SpherePreset::Glu ? std::pair<T, T>(q.x(), q.y()) : std::pair<T, T>(q.y(), q.x());
}

// u of a sphere preset from its azimuth angle (atan2 of sphereAzimuthArguments).
template <class T>
T sphereUFromAngle(T azimuth, SpherePreset preset) {
  return preset == SpherePreset::Seed004 ? azimuth / T(kTwoPi) + T(0) : turnFromAngle(azimuth);
}

// v of a sphere preset from the angle psi from the nearer pole (the southern one when z has its
// sign bit set); defined at the poles, where u is not. With phi = psi or pi - psi the polar angle
// from +z, v = 1 - phi/pi, but each hemisphere is computed where it needs no cancellation.
template <class T>
T sphereVFromPoleAngle(T psi, bool southern, SpherePreset preset) {
  const T fraction = psi / T(kPi);
  // The seed writes acos(z)/pi for the unit vector (t = 0 at +z): the same angle, measured downwards.
  const bool fromZero = southern != (preset == SpherePreset::Seed004);
  return fromZero ? fraction : T(1) - fraction;
}

// v and u of a sphere preset at a point q (any positive scale), with libm's atan2. u needs q off
// the z axis.
template <class T>
T sphereV(const Vec3T<T>& q, SpherePreset preset) {
  return sphereVFromPoleAngle(angleFromNearerPole(q.x(), q.y(), q.z()), std::signbit(q.z()), preset);
}

template <class T>
T sphereU(const Vec3T<T>& q, SpherePreset preset) {
  const auto [y, x] = sphereAzimuthArguments(q, preset);
  return sphereUFromAngle(std::atan2(y, x), preset);
}

template <class T>
Vec2T<T> sphereUv(const Vec3T<T>& q, SpherePreset preset) {
  return {sphereU(q, preset), sphereV(q, preset)};
}

// Where the u period of a wrapping preset starts: u lies in [start, start + 1).
inline double uPeriodStart(SpherePreset preset) { return preset == SpherePreset::Seed004 ? -0.5 : 0.0; }

// ---- Cube (§3): face selection and GL's table live in core/cube.h ----

enum class CubeConvention {
  Gl,      // (sc, tc) from OpenGL's table: seen from outside, s runs right and t runs down
  Direct,  // the seed's: the two remaining coordinates in x, y, z order
};

// The in-face coordinates (sc, tc) of point d on face f, before division by |ma|.
template <class T>
Vec2T<T> cubeFaceCoordinates(const Vec3T<T>& d, CubeFace f, CubeConvention convention) {
  if (convention == CubeConvention::Gl) return glCubeFaceCoordinates(d, f);
  switch (faceAxis(f)) {
    case 0:
      return {d.y(), d.z()};
    case 1:
      return {d.x(), d.z()};
    default:
      return {d.x(), d.y()};
  }
}

// s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2 for a direction d that selects face f.
template <class T>
Vec2T<T> cubeFaceSt(const Vec3T<T>& d, CubeFace f, CubeConvention convention) {
  return faceStFromCoordinates(cubeFaceCoordinates(d, f, convention), d[faceAxis(f)]);
}

// Places face coordinates (s, t) in an atlas. In the atlases every face reads unmirrored seen
// from outside the cube with the image's top at v = 1 (GL's t runs down, so v = 1 - t there;
// the direct convention mirrors s on -X, +Y and -Z, so those are flipped back).
template <class T>
Vec2T<T> cubeAtlasUv(const Vec2T<T>& st, CubeFace f, CubeConvention convention, CubeLayout layout) {
  if (layout == CubeLayout::Faces) return st;
  Vec2T<T> oriented = st;
  if (convention == CubeConvention::Gl) {
    oriented.y() = T(1) - st.y();
  } else if (f == CubeFace::NegX || f == CubeFace::PosY || f == CubeFace::NegZ) {
    oriented.x() = T(1) - st.x();
  }
  const CubeLayoutCell cell = cubeLayoutCell(f, layout);
  return {(T(cell.column) + oriented.x()) / T(cell.columns), (T(cell.row) + oriented.y()) / T(cell.rows)};
}

}  // namespace uvtk::param
