#include "core/gl_matrices.h"

#include <cmath>

#include "core/error.h"

namespace uvtk {

Mat4 lookAt(const Vec3& eye, const Vec3& center, const Vec3& up) {
  if (!eye.allFinite() || !center.allFinite() || !up.allFinite())
    throw UsageError("lookAt: eye, center and up must be finite");
  const Vec3 forward = center - eye;
  if (forward == Vec3::Zero()) throw UsageError("lookAt: the eye and the center coincide");
  if (up == Vec3::Zero()) throw UsageError("lookAt: the up vector is zero");
  // An eye 1e200 (1e-200) from the center, a mesh at 1e200 (1e-200), overflows (underflows)
  // squaredNorm: normalise without squaring there (elsewhere Eigen's normalized, bit for bit as before).
  const auto unit = [](const Vec3& v) { return std::isnormal(v.squaredNorm()) ? v.normalized() : v.stableNormalized(); };
  const Vec3 f = unit(forward);
  const Vec3 side = f.cross(unit(up));
  const double sine = side.norm();
  if (!(sine > 1e-12)) throw UsageError("lookAt: the up vector is parallel to the viewing direction");
  const Vec3 s = side / sine;
  const Vec3 u = s.cross(f);
  Mat4 m = Mat4::Identity();  // gluLookAt: rows s, u, -f, times a translation by -eye
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m.block<3, 1>(0, 3) = -(m.topLeftCorner<3, 3>() * eye);
  return m;
}

Mat4 perspective(double fovyDegrees, double aspect, double zNear, double zFar) {
  if (!(fovyDegrees > 0.0 && fovyDegrees < 180.0)) throw UsageError("perspective: fovy must lie in (0, 180) degrees");
  if (!(aspect > 0.0 && std::isfinite(aspect))) throw UsageError("perspective: the aspect ratio must be positive");
  if (!(zNear > 0.0 && zFar > zNear && std::isfinite(zFar)))
    throw UsageError("perspective: expected 0 < near < far");
  const double f = 1.0 / std::tan(fovyDegrees * kPi / 360.0);  // cot(fovy / 2)
  Mat4 m = Mat4::Zero();  // gluPerspective's matrix
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (zFar + zNear) / (zNear - zFar);
  // Beyond about 1e154 the product overflows, below about 1e-154 it underflows: divide first there
  // (elsewhere GLU's order, bit for bit).
  const double product = 2.0 * zFar * zNear;
  m(2, 3) = std::isnormal(product) ? product / (zNear - zFar) : 2.0 * zFar * (zNear / (zNear - zFar));
  m(3, 2) = -1.0;
  return m;
}

Mat4 orthographic(double left, double right, double bottom, double top, double zNear, double zFar) {
  if (!(right != left && top != bottom && zFar != zNear) ||
      !(std::isfinite(left) && std::isfinite(right) && std::isfinite(bottom) && std::isfinite(top) &&
        std::isfinite(zNear) && std::isfinite(zFar)))
    throw UsageError("orthographic: expected finite bounds with left != right, bottom != top, near != far");
  Mat4 m = Mat4::Identity();  // glOrtho's matrix
  m(0, 0) = 2.0 / (right - left);
  m(1, 1) = 2.0 / (top - bottom);
  m(2, 2) = -2.0 / (zFar - zNear);
  m(0, 3) = -(right + left) / (right - left);
  m(1, 3) = -(top + bottom) / (top - bottom);
  m(2, 3) = -(zFar + zNear) / (zFar - zNear);
  return m;
}

}  // namespace uvtk
