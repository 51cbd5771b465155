// Options and matrices shared by the texgen tests.
#pragma once

#include <Eigen/Geometry>

#include "core/math.h"
#include "texgen/texgen.h"

namespace uvtk::texgen {

// Options generating s, t, r and q by these modes, every plane and matrix at its default.
inline TexgenOptions withModes(TexgenMode s, TexgenMode t, TexgenMode r = TexgenMode::Off, TexgenMode q = TexgenMode::Off) {
  TexgenOptions o;
  o.coordinates[0].mode = s;
  o.coordinates[1].mode = t;
  o.coordinates[2].mode = r;
  o.coordinates[3].mode = q;
  return o;
}

// A rotation by `radians` about x, as a 4 x 4 matrix.
inline Mat4 rotationX(double radians) {
  Mat4 m = Mat4::Identity();
  m.topLeftCorner<3, 3>() = Eigen::AngleAxisd(radians, Vec3::UnitX()).toRotationMatrix();
  return m;
}

}  // namespace uvtk::texgen
