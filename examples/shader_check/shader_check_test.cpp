// Checks the shader formulas of shader.h against uvtk's mappings, point by point.
#include <gtest/gtest.h>
#include <uvtk/point.h>
#include <uvtk/testing.h>

#include <cmath>
#include <vector>

#include "shader.h"

namespace {

using shader::vec3;
using uvtk::point::Mapping;
using uvtk::point::Status;

// Points all around the origin: a latitude-longitude grid that includes the poles and the seam.
std::vector<vec3> spherePoints() {
  std::vector<vec3> points;
  for (int i = 0; i <= 12; ++i)
    for (int j = 0; j < 24; ++j) {
      const double theta = shader::PI * i / 12, phi = 2 * shader::PI * j / 24, r = 0.5 + (i + j) % 4;
      points.push_back({r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi), r * std::cos(theta)});
    }
  return points;
}

// (a) u compared modulo 1: the shader's negative u is a whole turn from uvtk's; at the poles only v.
TEST(ShaderCheck, EquirectangularMatchesTheSphereProjector) {
  const Mapping reference("--projector sphere");
  // Below the x axis the shader's u is negative: at (0, -1, 0) it is -0.25 where uvtk's is 0.75, the
  // same place in the texture one turn apart, which EXPECT_UV_NEAR accepts.
  EXPECT_DOUBLE_EQ(shader::equirectangular({0, -1, 0}).x, -0.25);
  EXPECT_DOUBLE_EQ(reference.at({0, -1, 0}).u, 0.75);
  EXPECT_UV_NEAR(shader::equirectangular({0, -1, 0}), reference.at({0, -1, 0}), 1e-12);
  for (const vec3& p : spherePoints()) {
    const uvtk::point::Result expected = reference.at({p.x, p.y, p.z});
    EXPECT_UV_NEAR(shader::equirectangular(p), expected, 1e-9);
  }
  // At the centre neither has a value: uvtk says so instead of returning NaN.
  EXPECT_UV_STATUS(reference.at({0, 0, 0}), Status::Invalid);
}

// (b) The default texgen view is GL's initial one (eye at the origin looking down -z): object
// coordinates are eye coordinates, so the shader gets the same position and normal.
TEST(ShaderCheck, SphereMapMatchesTexgen) {
  const Mapping reference("--texgen sphere_map");
  const vec3 normals[] = {{0, 0, 1}, {0.3, -0.2, 1}, {1, 1, 1}, {-0.5, 0.1, 0.2}, {0, 1, 0}};
  for (const vec3& p : spherePoints())
    for (const vec3& n : normals) {
      const uvtk::point::Result expected = reference.at({p.x, p.y, p.z}, {n.x, n.y, n.z});
      if (expected.status == Status::Pole) continue;  // m = 0: the shader divides by zero there
      EXPECT_UV_NEAR(shader::sphereMap(p, n), expected, 1e-12);
    }
  // Looking straight down -z at a surface whose normal is perpendicular: reflection (0, 0, -1).
  EXPECT_UV_STATUS(reference.at({0, 0, -2}, {1, 0, 0}), Status::Pole);
}

}  // namespace
