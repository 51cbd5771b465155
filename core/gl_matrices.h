// The matrices of OpenGL's utility library: gluLookAt, gluPerspective and glOrtho, in double
// precision. Shared by texgen (the view its EYE_LINEAR planes live in) and the renderer's camera.
#pragma once

#include "core/math.h"

namespace uvtk {

// gluLookAt: f = normalize(center - eye), s = normalize(f x normalize(up)), u = s x f, rows
// s, u, -f, then a translation by -eye. Throws UsageError for eye == center, a zero up or an
// up parallel to f (the sine of their angle below 1e-12).
Mat4 lookAt(const Vec3& eye, const Vec3& center, const Vec3& up);

// gluPerspective: fovy in degrees in (0, 180), aspect = width / height > 0, 0 < zNear < zFar.
// Throws UsageError otherwise.
Mat4 perspective(double fovyDegrees, double aspect, double zNear, double zFar);

// glOrtho: l != r, b != t, zNear != zFar. Throws UsageError otherwise.
Mat4 orthographic(double left, double right, double bottom, double top, double zNear, double zFar);

}  // namespace uvtk
