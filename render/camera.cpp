#include "render/camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/error.h"
#include "core/gl_matrices.h"

namespace uvtk::render {

Vec3 Camera::eye() const {
  const Mat3 r = viewFromWorld.topLeftCorner<3, 3>();
  return -(r.inverse() * viewFromWorld.block<3, 1>(0, 3));
}

BoundingSphere boundingSphere(const std::vector<Vec3>& points) {
  BoundingSphere s;
  if (points.empty()) return s;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec3& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  // Beyond about 1e154 a squared length overflows, below about 1e-154 it underflows: halves and
  // stableNorm there (elsewhere the same bits as before).
  s.center = 0.5 * (lo + hi);
  if (!s.center.allFinite()) s.center = 0.5 * lo + 0.5 * hi;
  for (const Vec3& p : points) {
    const double squared = (p - s.center).squaredNorm();
    s.radius = std::max(s.radius, std::isnormal(squared) ? std::sqrt(squared) : (p - s.center).stableNorm());
  }
  return s;
}

Camera frameSphere(const BoundingSphere& sphere, const Vec3& eyeDirection, const Vec3& up, const Projection& projection,
                   int width, int height, const std::string& meshFile) {
  if (width <= 0 || height <= 0) throw UsageError("the image size must be positive");
  if (!(eyeDirection.norm() > 0.0)) throw UsageError("camera auto: the viewing direction is zero");
  const double aspect = double(width) / double(height);
  // A point-like mesh still gets a finite view volume.
  const double radius = sphere.radius > 0.0 ? sphere.radius : 1.0;
  const Vec3 direction = eyeDirection.normalized();
  Camera camera;
  camera.width = width;
  camera.height = height;
  // Beyond about 1e307 the eye and the far plane lie past the largest double: said, not a lookAt failure.
  const auto checkRoom = [&](double distance) {
    if (std::isfinite(distance + 2.0 * radius) && (sphere.center + distance * direction).allFinite()) return;
    char message[200];
    std::snprintf(message, sizeof message,
                  "the mesh (bounding sphere of radius %.3g) is too large for a camera to frame: the eye would lie "
                  "beyond the largest double; scale it below about 1e307",
                  radius);
    throw InputError(meshFile.empty() ? std::string(message) : meshFile + ": error: " + message);
  };
  if (projection.orthographic) {
    const double half = 1.05 * radius;
    const double distance = 3.0 * radius;
    checkRoom(distance);
    camera.viewFromWorld = lookAt(sphere.center + distance * direction, sphere.center, up);
    const double hx = aspect >= 1.0 ? half * aspect : half, hy = aspect >= 1.0 ? half : half / aspect;
    camera.clipFromView = orthographic(-hx, hx, -hy, hy, distance - 2.0 * radius, distance + 2.0 * radius);
    return camera;
  }
  const double halfFovy = projection.fovyDegrees * kPi / 360.0;
  const double halfFovx = std::atan(std::tan(halfFovy) * aspect);
  // The sphere, shrunk to 90% of the field, touches the narrower half-angle's cone.
  const double distance = radius / (0.9 * std::sin(std::min(halfFovy, halfFovx)));
  checkRoom(distance);
  camera.viewFromWorld = lookAt(sphere.center + distance * direction, sphere.center, up);
  const double zNear = std::max(0.5 * (distance - radius), 1e-6 * distance);
  camera.clipFromView = perspective(projection.fovyDegrees, aspect, zNear, distance + 2.0 * radius);
  return camera;
}

}  // namespace uvtk::render
