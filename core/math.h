// Small math vocabulary of the toolkit: Eigen types under short names, in double precision.
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

constexpr double kPi = 3.14159265358979323846264338327950288;
constexpr double kTwoPi = 2.0 * kPi;

}  // namespace uvtk
