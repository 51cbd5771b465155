// Two texture-coordinate formulas as one writes them in a GLSL shader, here in C++ (double precision,
// GLSL's names) so that a test can check them against uvtk. This is the code under test.
#pragma once

#include <cmath>

namespace shader {

struct vec2 {
  double x, y;
};
struct vec3 {
  double x, y, z;
};

constexpr double PI = 3.14159265358979323846;

inline double dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double length(vec3 a) { return std::sqrt(dot(a, a)); }
inline vec3 normalize(vec3 a) {
  const double l = length(a);
  return {a.x / l, a.y / l, a.z / l};
}
inline vec3 reflect(vec3 i, vec3 n) {  // GLSL: I - 2 dot(N, I) N
  const double d = 2.0 * dot(n, i);
  return {i.x - d * n.x, i.y - d * n.y, i.z - d * n.z};
}
inline double atan(double y, double x) { return std::atan2(y, x); }  // GLSL's two-argument atan

// (a) Equirectangular (latitude-longitude) lookup of an object-space point: u in (-1/2, 1/2], v = 1
// at +z. uvtk's sphere gives u in [0, 1): the two differ by a whole turn where u < 0.
inline vec2 equirectangular(vec3 p) { return {atan(p.y, p.x) / (2.0 * PI), 1.0 - std::acos(p.z / length(p)) / PI}; }

// (b) The classic sphere map (GL_SPHERE_MAP) in eye space: the unit vector from the eye to the
// vertex, reflected about the normal.
inline vec2 sphereMap(vec3 eyePosition, vec3 eyeNormal) {
  const vec3 u = normalize(eyePosition);
  const vec3 r = reflect(u, normalize(eyeNormal));
  const double m = 2.0 * std::sqrt(r.x * r.x + r.y * r.y + (r.z + 1.0) * (r.z + 1.0));
  return {r.x / m + 0.5, r.y / m + 0.5};
}

}  // namespace shader
