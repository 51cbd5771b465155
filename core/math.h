// Small math vocabulary of the toolkit: Eigen types under short names, in double precision
// unless a precision is chosen (Vec2T, Vec3T).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace uvtk {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec4 = Eigen::Vector4d;
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix4d;
// An affine map between frames; named aFromB: it takes coordinates in frame B to frame A.
using Affine3 = Eigen::Transform<double, 3, Eigen::Affine>;

// The same vectors in a chosen precision (float, double, or long double for references).
template <class T>
using Vec2T = Eigen::Matrix<T, 2, 1>;
template <class T>
using Vec3T = Eigen::Matrix<T, 3, 1>;
template <class T>
using Vec4T = Eigen::Matrix<T, 4, 1>;

constexpr double kPi = 3.14159265358979323846264338327950288;

// The bounding box of 2D points as they are added, in four scalars that stay in registers through
// a loop over millions of corners (an Eigen::AlignedBox2d extended in a loop stayed in memory:
// three to five times slower). std::min and std::max in AlignedBox2d::extend's order, so box() is
// bit for bit the AlignedBox2d of the same points in the same order (empty without any).
struct Bounds2 {
  double lowX = std::numeric_limits<double>::max(), lowY = std::numeric_limits<double>::max();
  double highX = std::numeric_limits<double>::lowest(), highY = std::numeric_limits<double>::lowest();

  void extend(const Vec2& p) {
    lowX = std::min(lowX, p.x()), lowY = std::min(lowY, p.y());
    highX = std::max(highX, p.x()), highY = std::max(highY, p.y());
  }
  void extend(const Bounds2& b) {
    lowX = std::min(lowX, b.lowX), lowY = std::min(lowY, b.lowY);
    highX = std::max(highX, b.highX), highY = std::max(highY, b.highY);
  }
  Eigen::AlignedBox2d box() const { return Eigen::AlignedBox2d(Vec2(lowX, lowY), Vec2(highX, highY)); }
};

// The power of two that brings `largest` (> 0) into [1, 2), or as near as a double's exponent
// reaches (2^1023 for a subnormal: its ilogb is below -1023); 1 when it is not finite and positive.
// Scaling by it is exact, so directions and ratios computed afterwards are unchanged.
inline double unitPowerOfTwo(double largest) {
  if (!(largest > 0.0) || !std::isfinite(largest)) return 1.0;
  return std::ldexp(1.0, std::clamp(-std::ilogb(largest), -1022, 1023));
}
// The same for the largest |entry| of `m`.
inline double unitPowerOfTwo(const Mat3& m) { return unitPowerOfTwo(m.cwiseAbs().maxCoeff()); }

// The inverse of a 3x3 matrix with entries anywhere in a double's range (1e-300 .. 1e300): inverted
// at unit scale, so the determinant (the cube of the scale) neither overflows nor underflows. Equal
// bit for bit to Eigen's inverse wherever that one stays in range.
inline Mat3 inverseAtAnyScale(const Mat3& m) {
  const double s = unitPowerOfTwo(m);
  return (m * s).inverse() * s;
}
constexpr double kTwoPi = 2.0 * kPi;

}  // namespace uvtk
