// The S-mapping formulas: each in exactly one place, each as a free function of local
// coordinates. Conventions: docs/conventions.md (section numbers below refer to it).
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/math.h"

namespace uvtk::param {

// hypot(x, y) without std::hypot's cost where the squares neither overflow nor underflow;
// the fallback keeps huge and tiny coordinates exact.
inline double radialDistance(double x, double y) {
  const double m = std::fmax(std::fabs(x), std::fabs(y));
  if (m > 1e-150 && m < 1e150) return std::sqrt(x * x + y * y);
  return std::hypot(x, y);
}

// atan(t) for |t| <= 0.66 by Cephes' rational approximation (S. L. Moshier, Cephes atan.c,
// 1989), relative error below 2e-16 there.
inline double atanReduced(double t) {
  const double z = t * t;
  const double p = (((-8.750608600031904122785e-01 * z - 1.615753718733365076637e+01) * z -
                     7.500855792314704667340e+01) * z - 1.228866684490136173410e+02) * z - 6.485021904942025371773e+01;
  const double q = ((((z + 2.485846490142306297962e+01) * z + 1.650270098316988542046e+02) * z +
                     4.328810604912902668951e+02) * z + 4.853903996359136964868e+02) * z + 1.945506571482613964425e+02;
  return t + t * (z * p / q);
}

// atan2(y, x) with the conventions of std::atan2 (signed zeros included) within 2 ulp, at a
// fraction of glibc's cost. With a <= b the smaller and larger of |x|, |y|, the angle is
// k pi/4 +- atan(t): t = a/b, or (a - b)/(a + b) above atan(0.66), one division either way.
// Branch-free, so that random directions cost no mispredictions.
// Measured against atan2l in tests/param/formulas_test.cpp; docs/benchmarks.md has the speed.
inline double arcTangent2(double y, double x) {
  // k pi/4 split into a double and its rounding error, and the sign of atan(t), per case
  // (|y| > |x|, x < 0, above atan(0.66)).
  static constexpr double kHigh[8] = {0.0, 0.7853981633974483, 3.141592653589793, 2.356194490192345,
                                      1.5707963267948966, 0.7853981633974483, 1.5707963267948966, 2.356194490192345};
  static constexpr double kLow[8] = {0.0, 3.061616997868383e-17, 1.2246467991473532e-16, 9.184850993605148e-17,
                                     6.123233995736766e-17, 3.061616997868383e-17, 6.123233995736766e-17,
                                     9.184850993605148e-17};
  static constexpr double kSign[8] = {1, 1, -1, -1, -1, -1, 1, 1};
  const double ay = std::fabs(y), ax = std::fabs(x);
  double a = std::min(ax, ay), b = std::max(ax, ay);
  if (b > 0x1p1000) a *= 0x1p-8, b *= 0x1p-8;  // keeps a + b finite; exact, being a power of two
  // Selects written as arithmetic on 0 and 1, which compilers do not turn back into branches.
  const bool aboutQuarter = a > 0.66 * b;
  const double quarter = aboutQuarter;
  const double numerator = a - quarter * b;                                     // exact (Sterbenz)
  const double denominator = b + quarter * a + static_cast<double>(b == 0.0);  // (0, 0) gives 0 / 1
  const int k = 4 * (ay > ax) + 2 * std::signbit(x) + aboutQuarter;
  const double angle = kHigh[k] + (kSign[k] * atanReduced(numerator / denominator) + kLow[k]);
  return std::copysign(angle, y);
}

// Fraction of a full turn of atan2(y, x), in [0, 1): the seam lies on the +x half-plane,
// u grows counter-clockwise seen from +z; +0 and -0 land on the same side (§3).
// Precondition: (x, y) != (0, 0); poles are handled before this is called.
inline double turnFraction(double y, double x) {
  const double theta = arcTangent2(y, x);
  const double u = (theta + static_cast<double>(theta < 0.0) * kTwoPi) * (1.0 / kTwoPi) + 0.0;  // -0 becomes +0
  return u * static_cast<double>(u < 1.0);
}

// The pole test hypot(x, y) <= eps |q| of §5 without a square root: for eps in [0, 1) it holds
// exactly when rho <= eps / sqrt(1 - eps^2) |z|.
struct PoleTest {
  double slope;
  explicit PoleTest(double epsilon) : slope(epsilon / std::sqrt(1.0 - epsilon * epsilon)) {}
  bool operator()(double rho, double z) const { return rho <= slope * std::fabs(z); }
};

// Polar angle from +z in [0, pi]; atan2 keeps full precision near the poles where acos loses
// half the digits (§3).
inline double polarAngle(double x, double y, double z) { return arcTangent2(radialDistance(x, y), z); }

// Cylinder, radius 1, axis z: (u, v) = (turn fraction, z) (§3).
inline Vec2 cylinderUv(const Vec3& q) { return {turnFraction(q.y(), q.x()), q.z()}; }

// Sphere conventions (§3). Each maps a point (any positive scale) to (u, v).
enum class SpherePreset {
  Default,  // u = turn fraction from +x, v = 1 - phi/pi (v = 1 at +z)
  Glu,      // gluSphere: s = 0 at +y, 0.25 at +x, 0.5 at -y, 0.75 at -x; t = 0 at -z, 1 at +z
  Seed004,  // s = atan2(y, x)/(2 pi) in (-1/2, 1/2], t = acos(z)/pi (t = 0 at +z)
};

// v of a sphere preset; defined at the poles, where u is not.
inline double sphereV(const Vec3& q, SpherePreset preset) {
  const double phi = polarAngle(q.x(), q.y(), q.z());
  // The seed writes acos(z)/pi for the unit vector; atan2 gives the same angle, exactly rounded.
  return preset == SpherePreset::Seed004 ? phi / kPi : 1.0 - phi / kPi;
}

// u of a sphere preset. Precondition: q is not on the z axis.
inline double sphereU(const Vec3& q, SpherePreset preset) {
  switch (preset) {
    case SpherePreset::Default: return turnFraction(q.y(), q.x());
    case SpherePreset::Glu: return turnFraction(q.x(), q.y());
    case SpherePreset::Seed004: return arcTangent2(q.y(), q.x()) / kTwoPi + 0.0;
  }
  return 0.0;
}

inline Vec2 sphereUv(const Vec3& q, SpherePreset preset) { return {sphereU(q, preset), sphereV(q, preset)}; }

// Where the u period of a wrapping preset starts: u lies in [start, start + 1).
inline double uPeriodStart(SpherePreset preset) { return preset == SpherePreset::Seed004 ? -0.5 : 0.0; }

// ---- Cube (§3, OpenGL 4.6 table 8.19) ----

enum class CubeFace { PosX, NegX, PosY, NegY, PosZ, NegZ };  // the GL order; index = face id
constexpr int kCubeFaceCount = 6;

// The face of the major axis; ties go to x before y before z, the sign follows the sign bit,
// so +0 picks the + face and -0 the - face.
inline CubeFace majorAxisFace(const Vec3& d) {
  const double ax = std::fabs(d.x()), ay = std::fabs(d.y()), az = std::fabs(d.z());
  if (ax >= ay && ax >= az) return std::signbit(d.x()) ? CubeFace::NegX : CubeFace::PosX;
  if (ay >= az) return std::signbit(d.y()) ? CubeFace::NegY : CubeFace::PosY;
  return std::signbit(d.z()) ? CubeFace::NegZ : CubeFace::PosZ;
}

inline int faceAxis(CubeFace f) { return static_cast<int>(f) / 2; }
inline double faceSign(CubeFace f) { return static_cast<int>(f) % 2 == 0 ? 1.0 : -1.0; }

enum class CubeConvention {
  Gl,      // (sc, tc) from OpenGL's table: seen from outside, s runs right and t runs down
  Direct,  // the seed's: the two remaining coordinates in x, y, z order
};

// The in-face coordinates (sc, tc) of point d on face f, before division by |ma|.
inline Vec2 cubeFaceCoordinates(const Vec3& d, CubeFace f, CubeConvention convention) {
  const double x = d.x(), y = d.y(), z = d.z();
  if (convention == CubeConvention::Direct) {
    switch (faceAxis(f)) {
      case 0: return {y, z};
      case 1: return {x, z};
      default: return {x, y};
    }
  }
  switch (f) {
    case CubeFace::PosX: return {-z, -y};
    case CubeFace::NegX: return {z, -y};
    case CubeFace::PosY: return {x, z};
    case CubeFace::NegY: return {x, -z};
    case CubeFace::PosZ: return {x, -y};
    case CubeFace::NegZ: return {-x, -y};
  }
  return {};
}

// s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2 for a direction d that selects face f.
inline Vec2 cubeFaceSt(const Vec3& d, CubeFace f, CubeConvention convention) {
  const double ma = std::fabs(d[faceAxis(f)]);
  const Vec2 c = cubeFaceCoordinates(d, f, convention);
  return {(c.x() / ma + 1.0) * 0.5, (c.y() / ma + 1.0) * 0.5};
}

enum class CubeLayout {
  Faces,       // per-face [0,1]^2, the face id kept as the third texture coordinate
  Cross,       // 4x3 horizontal cross: -X +Z +X -Z in the middle row, +Y above and -Y below +Z
  Strip,       // 6x1 in the order +X -X +Y -Y +Z -Z
  ThreeByTwo,  // top row +X -X +Y, bottom row -Y +Z -Z
};

// Places face coordinates (s, t) in an atlas. In the atlases every face reads unmirrored seen
// from outside the cube with the image's top at v = 1 (GL's t runs down, so v = 1 - t there;
// the direct convention mirrors s on -X, +Y and -Z, so those are flipped back).
Vec2 cubeAtlasUv(const Vec2& st, CubeFace f, CubeConvention convention, CubeLayout layout);

}  // namespace uvtk::param
