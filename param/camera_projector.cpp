#include "param/camera_projector.h"

#include <cmath>

#include "core/error.h"
#include "core/gl_matrices.h"

namespace uvtk::param {

void checkCameraProjector(const CameraProjector& c, const CameraOptionNames& names) {
  const auto fail = [](const std::string& name, const std::string& what) { throw UsageError(name + ": " + what); };
  if (!c.eye.allFinite()) fail(names.eye, "expected finite x,y,z");
  if (!c.center.allFinite()) fail(names.center, "expected finite x,y,z");
  if (!c.up.allFinite()) fail(names.up, "expected finite x,y,z");
  if (!std::isfinite(c.fovyDegrees) || !(c.fovyDegrees > 0.0 && c.fovyDegrees < 180.0))
    fail(names.fovy, "expected degrees in (0, 180)");
  if (!std::isfinite(c.aspect) || !(c.aspect > 0.0)) fail(names.aspect, "expected a positive number");
  const Vec3 forward = c.center - c.eye;
  if (!(forward.norm() > 0.0) || !std::isfinite(forward.norm()))
    fail(names.center, "expected a point other than the eye, at a finite distance");
  if (!(c.up.norm() > 0.0)) fail(names.up, "expected a non-zero direction");
  // lookAt's own test: the sine of the angle between the view direction and up
  if (!(forward.normalized().cross(c.up.normalized()).norm() > 1e-12))
    fail(names.up, "expected a direction not parallel to the view direction (center - eye)");
}

CameraTransform::CameraTransform(const CameraProjector& camera) {
  checkCameraProjector(camera);
  const Mat4 clip = perspective(camera.fovyDegrees, camera.aspect, 1.0, 2.0) *
                    lookAt(camera.eye, camera.center, camera.up);
  rows_.row(0) = clip.row(0);
  rows_.row(1) = clip.row(1);
  rows_.row(2) = clip.row(3);
}

Vec4 CameraTransform::homogeneous(const Vec3& p) const {
  const Vec3 c = rows_ * p.homogeneous();  // (x_c, y_c, w_c)
  return Vec4(0.5 * (c.x() + c.z()), 0.5 * (c.y() + c.z()), 0.0, c.z());
}

}  // namespace uvtk::param
