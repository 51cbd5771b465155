#include <gtest/gtest.h>

#include <cmath>

#include "meshes/generators.h"
#include "param/placement.h"
#include "param/projector.h"

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

TEST(ProjectorAtPoints, EqualsMapVerticesThenTheUvTransformForEveryWrappingOrPlanarSurface) {
  const Mesh mesh = meshes::icosphere(2);
  const std::vector<Vec3> normals = areaWeightedVertexNormals(mesh);
  for (SurfaceKind surface : {SurfaceKind::Plane, SurfaceKind::TwoPlane, SurfaceKind::Cylinder, SurfaceKind::Sphere})
    for (RayKind ray : {RayKind::SurfaceNormal, RayKind::Centroid, RayKind::ObjectNormal, RayKind::Reflection}) {
      ProjectorOptions o;
      o.surface = surface;
      o.ray = ray;
      if (ray == RayKind::Reflection) o.eye = Vec3(0.5, -3, 1);
      o.uvTransform.scale = Vec2(2, 3);
      o.uvTransform.rotateDegrees = 30;
      const Affine3 frame = fitPlacement(mesh.positions, surface, o.placement);
      std::vector<VertexUv> expected;
      Projector(o, frame).mapVertices(mesh.positions, normals, expected);
      const Projector mapping(o, frame);
      EXPECT_EQ(mapping.traits().wraps, surface == SurfaceKind::Cylinder || surface == SurfaceKind::Sphere);
      EXPECT_EQ(mapping.needsNormal(), ray == RayKind::ObjectNormal || ray == RayKind::Reflection);
      for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const PointUv got = mapping.at(mesh.positions[v], normals[v]);
        ASSERT_EQ(got.state, expected[v].state);
        if (got.state == CornerState::Invalid) continue;
        EXPECT_LT((got.uv - o.uvTransform.apply(expected[v].uv)).norm(), 1e-12) << int(surface) << " " << int(ray);
      }
    }
}

TEST(ProjectorAtPoints, TheCubeTakesTheFaceOfEachPointsOwnProbe) {
  ProjectorOptions o;
  o.surface = SurfaceKind::Cube;
  o.cubeLayout = CubeLayout::Faces;  // each face's own (s, t)
  o.ray = RayKind::Centroid;  // a central projection: GL's cube-map lookup of the direction
  o.placement.fit = Fit::None;
  const Projector mapping(o, Affine3::Identity());
  // GL's face table (conventions §3): +x face sc = -z, tc = -y, ma = x; (s, t) = ((sc/ma + 1)/2, (tc/ma + 1)/2).
  const PointUv onPlusX = mapping.at(Vec3(2, 0.5, -1), Vec3::Zero());
  ASSERT_EQ(onPlusX.state, CornerState::Ok);
  EXPECT_LT((onPlusX.uv - Vec2((0.5 + 1) / 2, (-0.25 + 1) / 2)).norm(), 1e-15);
  // +y face: sc = x, tc = z.
  const PointUv onPlusY = mapping.at(Vec3(0.5, 2, -1), Vec3::Zero());
  EXPECT_LT((onPlusY.uv - Vec2((0.25 + 1) / 2, (-0.5 + 1) / 2)).norm(), 1e-15);
}

TEST(ProjectorAtPoints, ACapFaceMapsByTheCapProjectionMirroredOnTheBottom) {
  ProjectorOptions o;
  o.surface = SurfaceKind::Cylinder;
  o.cylinderCaps = true;
  o.placement.fit = Fit::None;
  o.capLayout = CapLayout::Stacked;
  const Projector stacked(o, Affine3::Identity());
  EXPECT_LT((stacked.at(Vec3(0.5, -0.5, 1), Vec3::UnitZ(), true).uv - Vec2(0.75, 0.25)).norm(), 1e-15);
  EXPECT_LT((stacked.at(Vec3(0.5, -0.5, 0), -Vec3::UnitZ(), true).uv - Vec2(0.25, 0.25)).norm(), 1e-15);
  // Not a cap face: the cylinder, u from the azimuth of (0.5, -0.5): 7/8, v = z.
  EXPECT_LT((stacked.at(Vec3(0.5, -0.5, 0.3), Vec3::Zero(), false).uv - Vec2(0.875, 0.3)).norm(), 1e-15);
  // Beside (the default): the top cap's square is [0, 1/2] x [1/2, 1], the bottom's [1/2, 1] x [1/2, 1],
  // the side band v in [0, 1/2].
  o.capLayout = CapLayout::Beside;
  const Projector beside(o, Affine3::Identity());
  EXPECT_LT((beside.at(Vec3(0.5, -0.5, 1), Vec3::UnitZ(), true).uv - Vec2(0.375, 0.625)).norm(), 1e-15);
  EXPECT_LT((beside.at(Vec3(0.5, -0.5, 0), -Vec3::UnitZ(), true).uv - Vec2(0.625, 0.625)).norm(), 1e-15);
  EXPECT_LT((beside.at(Vec3(0.5, -0.5, 0.3), Vec3::Zero(), false).uv - Vec2(0.875, 0.15)).norm(), 1e-15);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param
