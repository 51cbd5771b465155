// The maps of directions added as surfaces (docs/conventions.md §3): the octahedral map and 3ds
// Max's shrink wrap, at hand-computed directions, their seams and their singular point.
#include <gtest/gtest.h>

#include "meshes/generators.h"
#include "param/projector.h"

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

constexpr SurfaceKind kDirectionMaps[] = {SurfaceKind::Octahedral, SurfaceKind::ShrinkWrap};

// The surface's (u, v) and state at object-space points, in object coordinates (no fit).
std::vector<VertexUv> at(SurfaceKind surface, const std::vector<Vec3>& points, RayKind ray = RayKind::SurfaceNormal) {
  ProjectorOptions o;
  o.surface = surface;
  o.ray = ray;
  o.placement.fit = Fit::None;
  std::vector<VertexUv> out;
  Projector(o, Affine3::Identity()).mapVertices(points, std::vector<Vec3>(points.size(), Vec3::UnitZ()), out);
  return out;
}

void expectUv(const VertexUv& got, double u, double v, CornerState state = CornerState::Ok) {
  EXPECT_EQ(got.state, state);
  EXPECT_NEAR(got.uv.x(), u, 1e-15);
  EXPECT_NEAR(got.uv.y(), v, 1e-15);
}

TEST(Octahedral, TheFormulaAtHandComputedDirections) {
  // p = d / |d|_1; below the equator (1 - |py|) sign px, (1 - |px|) sign py; (u, v) = p / 2 + 1/2.
  const std::vector<VertexUv> r = at(SurfaceKind::Octahedral, {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}, {1, 1, 1},
                                                               {0, 0, -1}, {1, 2, -1}, {-1, 2, -1}, {-3, -3, -2}});
  expectUv(r[0], 0.5, 0.5);          // +z: the centre
  expectUv(r[1], 1.0, 0.5);          // +x: the right corner of the diamond
  expectUv(r[2], 0.5, 0.0);          // -y
  expectUv(r[3], 2.0 / 3, 2.0 / 3);  // (1/3, 1/3)
  expectUv(r[4], 1.0, 1.0);          // -z: sign(0) = +1, folded to the corner (1, 1)
  expectUv(r[5], 0.75, 0.875);       // (1/4, 1/2, -1/4) folds to (1/2, 3/4)
  expectUv(r[6], 0.25, 0.875);       // (-1/4, 1/2, -1/4) folds to (-1/2, 3/4)
  expectUv(r[7], 0.1875, 0.1875);    // (-3/8, -3/8, -1/4) folds to (-5/8, -5/8): 3/16
  for (const VertexUv& v : r) EXPECT_EQ(v.state, CornerState::Ok);  // no pole anywhere
}

TEST(Octahedral, ItsSeamsAreTheFourLowerEdges) {
  // Across a lower edge (y = 0, z < 0) the fold sends the two sides half a square apart; across an
  // upper edge (y = 0, z > 0) the map is continuous.
  const double e = 1e-9;
  const std::vector<VertexUv> r = at(SurfaceKind::Octahedral, {{1, e, -1}, {1, -e, -1}, {1, e, 1}, {1, -e, 1}});
  EXPECT_NEAR(r[0].uv.y() - r[1].uv.y(), 0.5, 1e-8);
  EXPECT_NEAR(r[2].uv.y() - r[3].uv.y(), 0.0, 1e-8);
  EXPECT_NEAR(r[0].uv.x(), r[1].uv.x(), 1e-8);
}

TEST(ShrinkWrap, TheFormulaAtHandComputedDirections) {
  // theta from +z, phi from +x: (u, v) = (1/2 + (theta/pi) cos phi / 2, 1/2 + (theta/pi) sin phi / 2).
  const std::vector<VertexUv> r =
      at(SurfaceKind::ShrinkWrap, {{0, 0, 2}, {3, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, 1, -1}, {1, 1, 0}});
  expectUv(r[0], 0.5, 0.5);    // +z: the centre, whatever phi
  expectUv(r[1], 0.75, 0.5);   // theta = pi/2, phi = 0
  expectUv(r[2], 0.5, 0.75);   // phi = pi/2
  expectUv(r[3], 0.25, 0.5);   // phi = pi
  expectUv(r[4], 0.5, 0.875);  // theta = 3 pi/4
  expectUv(r[5], 0.5 + 0.25 * std::sqrt(0.5), 0.5 + 0.25 * std::sqrt(0.5));
}

TEST(ShrinkWrap, ItsOneSingularPointIsTheSouthPole) {
  // -z: every azimuth's limit lies on the circle of radius 1/2; the corner is a pole, written at
  // phi = 0. +z is an ordinary point (the centre). The cylinder's and sphere's two poles are not.
  const std::vector<VertexUv> r = at(SurfaceKind::ShrinkWrap, {{0, 0, -1}, {0, 0, 1}, {1e-9, 0, -1}});
  expectUv(r[0], 1.0, 0.5, CornerState::Pole);
  expectUv(r[1], 0.5, 0.5, CornerState::Ok);
  EXPECT_EQ(r[2].state, CornerState::Pole);  // within --pole-eps of the axis
  // A mesh's faces around -z carry the pole flag; those around +z do not.
  ProjectorOptions o;
  o.surface = SurfaceKind::ShrinkWrap;
  const Projection p = project(meshes::latLongSphere(16, 8), o);
  EXPECT_GT(p.summary.poleFaces, 0u);
  for (const int f : p.summary.poleFaceList)
    for (int k = 0; k < 3; ++k) EXPECT_LT(p.mesh.positions[std::size_t(p.mesh.triangles[std::size_t(f)][k])].z(), 0.9);
}

TEST(DirectionMaps, TakeEveryRayMappingAndBothPrecisions) {
  // The central ray and the isn foot see the same direction from the origin; float within 1e-6.
  for (const SurfaceKind s : kDirectionMaps) {
    const std::vector<Vec3> points = {{0.3, -0.2, 0.7}, {-0.5, 0.1, -0.4}};
    const std::vector<VertexUv> foot = at(s, points), central = at(s, points, RayKind::Centroid);
    for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(foot[i].uv, central[i].uv);
    ProjectorOptions o;
    o.surface = s;
    o.placement.fit = Fit::None;
    o.arithmetic.precision = Precision::Float;
    std::vector<VertexUv> single;
    Projector(o, Affine3::Identity()).mapVertices(points, {}, single);
    for (std::size_t i = 0; i < points.size(); ++i) EXPECT_NEAR((single[i].uv - foot[i].uv).norm(), 0.0, 1e-6);
  }
}

TEST(DirectionMaps, EveryValidUvLiesInTheUnitSquareUnderEveryRayMapping) {
  // A direction's (u, v) whatever the hit: the octahedron's square, the shrink wrap's disc of radius 1/2.
  const Mesh knot = meshes::torusKnot(2, 3, 96, 8, 0.3), box = meshes::cube(3);
  for (const SurfaceKind s : kDirectionMaps)
    for (const RayKind ray : {RayKind::SurfaceNormal, RayKind::Centroid, RayKind::ObjectNormal, RayKind::Reflection})
      for (const Mesh* mesh : {&knot, &box}) {
        ProjectorOptions o;
        o.surface = s;
        o.ray = ray;
        o.eye = Vec3(0.3, -0.2, 5.0);
        const Projection p = project(*mesh, o);
        std::size_t valid = 0;
        for (std::size_t i = 0; i < p.uv.uv.size(); ++i) {
          if (p.uv.cornerInvalid[i] != kCornerValid) continue;
          ++valid;
          ASSERT_GE(p.uv.uv[i].minCoeff(), 0.0) << int(s) << " " << int(ray) << " corner " << i;
          ASSERT_LE(p.uv.uv[i].maxCoeff(), 1.0) << int(s) << " " << int(ray) << " corner " << i;
        }
        EXPECT_GT(valid, p.uv.uv.size() / 2) << int(s) << " " << int(ray);
      }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param
