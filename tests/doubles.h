// Doubles as the tests make and compare them.
#pragma once

#include <cstring>
#include <limits>

#include "core/math.h"

namespace uvtk {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Bit-for-bit equality, as the tests that promise identical results compare: 0.0 and -0.0 differ,
// a NaN equals the same NaN.
inline bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Points within 1e-6 of each other in every coordinate.
inline bool near(const Vec3& a, const Vec3& b) { return (a - b).cwiseAbs().maxCoeff() < 1e-6; }

}  // namespace uvtk
