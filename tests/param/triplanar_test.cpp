// Triplanar projection: the weights and the three projections of each preset pinned to
// hand-computed points (docs/conventions.md, "Triplanar"), their extremes (normals on the axes,
// B = 0, huge B, tiny and huge normals), and project()'s box UVs per face.
#include "param/triplanar.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "meshes/generators.h"
#include "param/projector.h"

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

TriplanarOptions preset(TriplanarPreset p, double tile = 1.0, double blend = 1.0) {
  TriplanarOptions o;
  o.preset = p;
  o.tile = tile;
  o.blend = blend;
  return o;
}

void expectNear(const Vec3& found, const Vec3& expected, double tolerance = 1e-15) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(found[i], expected[i], tolerance) << "component " << i;
}

TEST(TriplanarWeights, AreTheNormalsComponentsToThePowerBOverTheirSum) {
  const TriplanarOptions unity;
  EXPECT_DOUBLE_EQ(triplanarWeights(unity, Vec3(1, 2, 3)).sum(), 1.0);
  // B = 1: |n| / sum |n| = (1, 2, 3) / 6, whatever the normal's length or signs.
  expectNear(triplanarWeights(unity, Vec3(1, 2, 3)), Vec3(1, 2, 3) / 6.0);
  expectNear(triplanarWeights(unity, Vec3(-0.1, 0.2, -0.3)), Vec3(1, 2, 3) / 6.0);
  // B = 2: (1, 4, 9) / 14; B = 0.5: (1, sqrt 2, sqrt 3) / (1 + sqrt 2 + sqrt 3).
  expectNear(triplanarWeights(preset(TriplanarPreset::Unity, 1, 2), Vec3(1, 2, 3)), Vec3(1, 4, 9) / 14.0);
  const double s = 1 + std::sqrt(2.0) + std::sqrt(3.0);
  expectNear(triplanarWeights(preset(TriplanarPreset::Unity, 1, 0.5), Vec3(1, 2, 3)),
             Vec3(1, std::sqrt(2.0), std::sqrt(3.0)) / s);
}

TEST(TriplanarWeights, OnAnAxisTheNormalTakesThatProjectionAlone) {
  const TriplanarOptions unity;
  EXPECT_EQ(triplanarWeights(unity, Vec3(0, 0, -5)), Vec3(0, 0, 1));
  expectNear(triplanarWeights(unity, Vec3(2, 0, 0)), Vec3(1, 0, 0), 0.0);
  expectNear(triplanarWeights(preset(TriplanarPreset::Unity, 1, 40), Vec3(0, -1, 0)), Vec3(0, 1, 0), 0.0);
  // Halfway between two axes: an even split at any B > 0.
  expectNear(triplanarWeights(preset(TriplanarPreset::Unity, 1, 7), Vec3(1, -1, 0)), Vec3(0.5, 0.5, 0), 0.0);
}

TEST(TriplanarWeights, StayFiniteAtTheExtremesOfBAndOfTheNormal) {
  // B = 0: pow(0, 0) = 1, every projection a third, even for an axis normal.
  expectNear(triplanarWeights(preset(TriplanarPreset::Unity, 1, 0), Vec3(0, 0, 1)), Vec3::Constant(1.0 / 3.0));
  // A huge B: |n_i|^B underflows for every component below 1 in a plain pow(|n|, B) / sum, giving
  // 0 / 0; scaled by the largest component, the largest takes it all (ties share).
  expectNear(triplanarWeights(preset(TriplanarPreset::Unity, 1, 1e6), Vec3(0.9, 0.8, 0.1)), Vec3(1, 0, 0), 0.0);
  expectNear(triplanarWeights(preset(TriplanarPreset::Unity, 1, 1e6), Vec3(1, 1, 0.5)), Vec3(0.5, 0.5, 0), 0.0);
  // Normals at 1e-300 and 1e300 have the weights of their direction.
  expectNear(triplanarWeights(preset(TriplanarPreset::Unity, 1, 2), Vec3(1, 2, 3) * 1e-300), Vec3(1, 4, 9) / 14.0);
  expectNear(triplanarWeights(preset(TriplanarPreset::Unity, 1, 2), Vec3(1, 2, 3) * 1e300), Vec3(1, 4, 9) / 14.0);
  // No direction, no weights.
  EXPECT_FALSE(triplanarWeights(TriplanarOptions{}, Vec3::Zero()).allFinite());
  EXPECT_FALSE(triplanarWeights(TriplanarOptions{}, Vec3(1, NAN, 0)).allFinite());
  EXPECT_FALSE(triplanarWeights(TriplanarOptions{}, Vec3(INFINITY, 1, 0)).allFinite());
}

TEST(TriplanarWeights, MaterialXRaisesToOneOverItsBlendClampedAt003) {
  // NG_triplanarprojection: (|n| / sum)^(1 / max(blend, 0.03)), normalised.
  EXPECT_DOUBLE_EQ(triplanarExponent(preset(TriplanarPreset::MaterialX, 1, 0.5)), 2.0);
  EXPECT_DOUBLE_EQ(triplanarExponent(preset(TriplanarPreset::MaterialX, 1, 0.0)), 1.0 / 0.03);
  EXPECT_DOUBLE_EQ(triplanarExponent(preset(TriplanarPreset::MaterialX, 1, 0.01)), 1.0 / 0.03);
  EXPECT_DOUBLE_EQ(triplanarExponent(preset(TriplanarPreset::Godot, 1, 0.5)), 0.5);
  expectNear(triplanarWeights(preset(TriplanarPreset::MaterialX, 1, 0.5), Vec3(1, 2, 2)), Vec3(1, 4, 4) / 9.0);
  expectNear(triplanarWeights(preset(TriplanarPreset::MaterialX), Vec3(1, 2, 3)), Vec3(1, 2, 3) / 6.0);
}

TEST(TriplanarUv, EachPresetProjectsAsItsSourceDoes) {
  const Vec3 p(1, 2, 3);
  // Unity Shader Graph: Node_UV = Position * Tile; X .zy, Y .xz, Z .xy.
  const TriplanarOptions unity = preset(TriplanarPreset::Unity, 2);
  EXPECT_EQ(triplanarUv(unity, 0, p), Vec2(6, 4));
  EXPECT_EQ(triplanarUv(unity, 1, p), Vec2(2, 6));
  EXPECT_EQ(triplanarUv(unity, 2, p), Vec2(2, 4));
  // MaterialX, upaxis Z: X (y, z), Y (x, z), Z (x, y).
  const TriplanarOptions materialx = preset(TriplanarPreset::MaterialX);
  EXPECT_EQ(triplanarUv(materialx, 0, p), Vec2(2, 3));
  EXPECT_EQ(triplanarUv(materialx, 1, p), Vec2(1, 3));
  EXPECT_EQ(triplanarUv(materialx, 2, p), Vec2(1, 2));
  // Godot: pos = p (1, -1, 1) = (1, -2, 3); X pos.zy (-1, 1) = (-3, -2), Y pos.xz = (1, 3), Z pos.xy = (1, -2).
  const TriplanarOptions godot = preset(TriplanarPreset::Godot);
  EXPECT_EQ(triplanarUv(godot, 0, p), Vec2(-3, -2));
  EXPECT_EQ(triplanarUv(godot, 1, p), Vec2(1, 3));
  EXPECT_EQ(triplanarUv(godot, 2, p), Vec2(1, -2));
  const TriplanarSample s = triplanarAt(unity, p, Vec3(0.1, -0.9, 0.3));
  EXPECT_EQ(s.uv[0], Vec2(6, 4));
  EXPECT_EQ(s.dominant, 1);
}

TEST(TriplanarUv, TheFacingIsGradUCrossGradV) {
  // Unity's projections face -x, -y and +z (it mirrors the texture on the +x, +y and -z faces);
  // MaterialX's x projection (y, z) faces +x; Godot's face -x, -y and -z.
  EXPECT_EQ(triplanarFacing(TriplanarOptions{}, 0), Vec3(-1, 0, 0));
  EXPECT_EQ(triplanarFacing(TriplanarOptions{}, 1), Vec3(0, -1, 0));
  EXPECT_EQ(triplanarFacing(TriplanarOptions{}, 2), Vec3(0, 0, 1));
  EXPECT_EQ(triplanarFacing(preset(TriplanarPreset::MaterialX), 0), Vec3(1, 0, 0));
  EXPECT_EQ(triplanarFacing(preset(TriplanarPreset::Godot), 0), Vec3(-1, 0, 0));
  EXPECT_EQ(triplanarFacing(preset(TriplanarPreset::Godot), 2), Vec3(0, 0, -1));
  // A tile of -2 turns both axes: the same facing, 4 times longer.
  EXPECT_EQ(triplanarFacing(preset(TriplanarPreset::Unity, -2), 2), Vec3(0, 0, 4));
}

TEST(TriplanarAxis, TheLargestComponentWinsAndTiesGoToTheLowerAxis) {
  EXPECT_EQ(dominantAxis(Vec3(0.1, -0.9, 0.3)), 1);
  EXPECT_EQ(dominantAxis(Vec3(0, 0, -1)), 2);
  EXPECT_EQ(dominantAxis(Vec3(1, -1, 0)), 0);
  EXPECT_EQ(dominantAxis(Vec3(0, 1, 1)), 1);
  EXPECT_EQ(dominantAxis(Vec3(1, 1, 1)), 0);
  EXPECT_EQ(dominantAxis(Vec3::Zero()), 0);
}

TEST(TriplanarOptions, RefuseATileOfZeroAndANegativeOrNonFiniteBlend) {
  EXPECT_THROW(checkTriplanarOptions(preset(TriplanarPreset::Unity, 0)), UsageError);
  EXPECT_THROW(checkTriplanarOptions(preset(TriplanarPreset::Unity, INFINITY)), UsageError);
  EXPECT_THROW(checkTriplanarOptions(preset(TriplanarPreset::Unity, 1, -1)), UsageError);
  EXPECT_THROW(checkTriplanarOptions(preset(TriplanarPreset::Unity, 1, NAN)), UsageError);
  EXPECT_NO_THROW(checkTriplanarOptions(preset(TriplanarPreset::Unity, -3, 0)));
}

TEST(TriplanarProject, EachFaceCarriesItsDominantAxisProjectionOfItsCorners) {
  Mesh mesh = meshes::icosphere(2);
  for (Vec3& p : mesh.positions) p = Vec3(3 * p.x() + 5, p.y() - 2, 0.5 * p.z());  // an ellipsoid off the origin
  ProjectorOptions o;
  o.surface = SurfaceKind::Triplanar;
  o.placement.fit = Fit::None;
  o.triplanar = preset(TriplanarPreset::Unity, 1.5, 4);
  const Projection projection = project(mesh, o, 2);
  ASSERT_EQ(projection.triplanarAxis.size(), mesh.faceCount());
  std::array<std::size_t, 3> counts{};
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3 n = (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
    const int axis = dominantAxis(n);
    EXPECT_EQ(projection.triplanarAxis[f], axis) << "face " << f;
    ++counts[std::size_t(axis)];
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(projection.uv.uv[3 * f + std::size_t(k)], triplanarUv(o.triplanar, axis, mesh.positions[t[k]]));
  }
  EXPECT_EQ(projection.summary.triplanarFaces, counts);
  EXPECT_GT(counts[0], 0u);
  EXPECT_GT(counts[1], 0u);
  EXPECT_GT(counts[2], 0u);
  EXPECT_EQ(projection.summary.invalidFaces, 0u);
  // mapVertices maps single vertices, which have no face to choose by.
  std::vector<VertexUv> out;
  EXPECT_THROW(Projector(o, Affine3::Identity()).mapVertices(mesh.positions, {}, out), UsageError);
}

TEST(TriplanarProject, TheBboxFitIsUniformAndTheMappingFollowsThePlacement) {
  // A box 4 x 2 x 1 from (1, 1, 1): the fit moves its lowest corner to the origin and scales by 1/4.
  Mesh mesh = meshes::cube(1);  // [-1, 1]^3
  for (Vec3& p : mesh.positions) p = Vec3(3 + 2 * p.x(), 2 + p.y(), 1.5 + 0.5 * p.z());
  ProjectorOptions o;
  o.surface = SurfaceKind::Triplanar;
  o.placement.fit = Fit::BBox;
  const Projection projection = project(mesh, o, 1);
  const Vec3 local = projection.localFromObject * Vec3(5, 3, 2);
  EXPECT_NEAR(local.x(), 1.0, 1e-15);
  EXPECT_NEAR(local.y(), 0.5, 1e-15);
  EXPECT_NEAR(local.z(), 0.25, 1e-15);
  const Projector mapping(o, projection.localFromObject);
  const TriplanarSample s = mapping.blendAt(Vec3(5, 3, 2), Vec3(0, 0, 1));
  EXPECT_NEAR(s.uv[2].x(), 1.0, 1e-15);
  EXPECT_NEAR(s.uv[2].y(), 0.5, 1e-15);
  expectNear(s.weights, Vec3(0, 0, 1), 0.0);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param
