// The camera ("project from view") projector: UVs from a camera's perspective projection, as
// Blender's Project from View, 3ds Max's View Align or Houdini's perspective UV Texture make them.
// It has no intermediate surface: no placement, O-mapping, seam or pole (docs/conventions.md,
// "The camera projector").
#pragma once

#include <string>

#include "core/math.h"

namespace uvtk::param {

// gluLookAt(eye, center, up) and gluPerspective(fovy, aspect, near, far) (OpenGL 2.1 reference
// pages). near and far only clip: they change z_c, never x_c, y_c or w_c, so they are not options.
struct CameraProjector {
  Vec3 eye = Vec3(0, 0, 1);
  Vec3 center = Vec3::Zero();
  Vec3 up = Vec3::UnitY();
  double fovyDegrees = 45.0;  // gluPerspective's field of view in y, in (0, 180)
  double aspect = 1.0;        // width / height, > 0
};

// The options that set a CameraProjector, as the messages name them (`uvtk render` says --proj-eye, ...).
struct CameraOptionNames {
  std::string eye = "--eye", center = "--center", up = "--up", fovy = "--fovy", aspect = "--aspect";
};

// Throws UsageError naming the option for a non-finite value, eye == center, an up that is zero
// or parallel to the view direction, fovy outside (0, 180) or an aspect that is not positive.
void checkCameraProjector(const CameraProjector& camera, const CameraOptionNames& names = {});

// The rows of P V that give x_c, y_c and w_c (P's z row, the only one near and far enter, is left out).
class CameraTransform {
 public:
  explicit CameraTransform(const CameraProjector& camera);  // checks it (checkCameraProjector)
  // (s, t, 0, q) = ((x_c + w_c)/2, (y_c + w_c)/2, 0, w_c) of an object-space point: u = s/q =
  // x_ndc/2 + 1/2, v = t/q. q <= 0 (at or behind the eye plane) has no (u, v).
  Vec4 homogeneous(const Vec3& p) const;

 private:
  Eigen::Matrix<double, 3, 4> rows_;  // x_c, y_c, w_c
};

}  // namespace uvtk::param
