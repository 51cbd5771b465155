// Small math vocabulary of the toolkit: Eigen types under short names, in double precision
// unless a precision is chosen (Vec2T, Vec3T).
#pragma once

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
constexpr double kTwoPi = 2.0 * kPi;

}  // namespace uvtk
