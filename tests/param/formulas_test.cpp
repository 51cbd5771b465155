// The S-mapping formulas against hand-computed values and the lecture notes' examples.
#include "param/formulas.h"

#include <gtest/gtest.h>

#include <cmath>

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

TEST(PoleTest, MatchesTheHypotFormOfTheDefinition) {
  const PoleTest isPole(1e-6);
  EXPECT_TRUE(isPole(0.0, 0.0));
  EXPECT_TRUE(isPole(0.999999e-6, 1.0));
  EXPECT_FALSE(isPole(1.000001e-6, 1.0));
  EXPECT_TRUE(isPole(1e-306, 1e-300));   // no underflow
  EXPECT_FALSE(isPole(1e300, 1e300));    // no overflow
  EXPECT_TRUE(PoleTest(0.0)(0.0, 1.0));
  EXPECT_FALSE(PoleTest(0.0)(1e-300, 1.0));
}

TEST(TurnFraction, IsZeroOnPlusXAndGrowsCounterClockwise) {
  EXPECT_EQ(turnFraction(0.0, 1.0), 0.0);
  EXPECT_EQ(turnFraction(1.0, 0.0), 0.25);
  EXPECT_EQ(turnFraction(0.0, -1.0), 0.5);
  EXPECT_EQ(turnFraction(-1.0, 0.0), 0.75);
  EXPECT_DOUBLE_EQ(turnFraction(1.0, 1.0), 0.125);
}

TEST(TurnFraction, PutsPlusAndMinusZeroOnTheSameSideOfTheSeam) {
  EXPECT_EQ(turnFraction(-0.0, 1.0), 0.0);
  EXPECT_FALSE(std::signbit(turnFraction(-0.0, 1.0)));
  EXPECT_EQ(turnFraction(-0.0, -1.0), turnFraction(0.0, -1.0));
  EXPECT_EQ(turnFraction(-0.0, -1.0), 0.5);
}

TEST(TurnFraction, MapsAnglesThatRoundToOneToZero) {
  // atan2 = -1e-300, plus 2 pi rounds to 2 pi: u would be 1.0, which the convention excludes.
  EXPECT_EQ(turnFraction(-1e-300, 1.0), 0.0);
  EXPECT_LT(turnFraction(-1e-10, 1.0), 1.0);
  EXPECT_GT(turnFraction(-1e-10, 1.0), 0.999);
}

TEST(SphereV, KeepsFullPrecisionNearBothPoles) {
  // At 1e-9 rad from a pole, acos(z) would return 0 or an error of ~1e-8 relative; atan2 is exact.
  EXPECT_NEAR(angleFromNearerPole(1e-9, 0.0, 1.0), 1e-9, 1e-24);
  EXPECT_NEAR(angleFromNearerPole(1e-9, 0.0, -1.0), 1e-9, 1e-24);
  // Near the south pole v = psi/pi is small: 1 - phi/pi would leave it an absolute error of
  // 1e-16, a relative one of 1e-7; measured from the south pole it is exact to an ulp.
  EXPECT_NEAR(sphereV(Vec3(1e-9, 0.0, -1.0), SpherePreset::Default), 1e-9 / kPi, 2e-16 * 1e-9 / kPi);
  EXPECT_NEAR(sphereV(Vec3(1e-9, 0.0, 1.0), SpherePreset::Seed004), 1e-9 / kPi, 2e-16 * 1e-9 / kPi);
  EXPECT_EQ(sphereV(Vec3(0.0, 0.0, 1.0), SpherePreset::Seed004), 0.0);
  EXPECT_EQ(sphereV(Vec3(0.0, 0.0, -1.0), SpherePreset::Seed004), 1.0);
  EXPECT_EQ(sphereV(Vec3(1.0, 0.0, 0.0), SpherePreset::Default), 0.5);
  EXPECT_EQ(sphereV(Vec3(1.0, 0.0, -0.0), SpherePreset::Default), 0.5);  // -0: the southern formula, same value
}

TEST(SphereUv, DefaultPresetHasVOneAtPlusZAndZeroAtMinusZ) {
  EXPECT_EQ(sphereV(Vec3(0, 0, 1), SpherePreset::Default), 1.0);
  EXPECT_EQ(sphereV(Vec3(0, 0, -1), SpherePreset::Default), 0.0);
  EXPECT_EQ(sphereUv(Vec3(1, 0, 0), SpherePreset::Default), Vec2(0.0, 0.5));
  EXPECT_EQ(sphereUv(Vec3(0, -3, 0), SpherePreset::Default), Vec2(0.75, 0.5));
}

// Seed 003 (gluSphere's documentation): s = 0 at +y, 0.25 at +x, 0.5 at -y, 0.75 at -x;
// t = 0 at z = -r and 1 at z = +r.
TEST(SphereUv, GluPresetMatchesGluSphere) {
  EXPECT_EQ(sphereU(Vec3(0, 1, 0), SpherePreset::Glu), 0.0);
  EXPECT_EQ(sphereU(Vec3(1, 0, 0), SpherePreset::Glu), 0.25);
  EXPECT_EQ(sphereU(Vec3(0, -1, 0), SpherePreset::Glu), 0.5);
  EXPECT_EQ(sphereU(Vec3(-1, 0, 0), SpherePreset::Glu), 0.75);
  EXPECT_EQ(sphereV(Vec3(0, 0, -2), SpherePreset::Glu), 0.0);
  EXPECT_EQ(sphereV(Vec3(0, 0, 2), SpherePreset::Glu), 1.0);
  EXPECT_DOUBLE_EQ(sphereV(Vec3(1, 0, 1), SpherePreset::Glu), 0.75);  // 45 degrees above the equator
}

// Seed 004: s = atan2(y, x)/(2 pi), t = acos(z)/pi.
TEST(SphereUv, Seed004PresetMatchesTheNotesFormula) {
  const Vec3 p = Vec3(-0.3, -0.5, 0.2).normalized();
  const Vec2 uv = sphereUv(p, SpherePreset::Seed004);
  EXPECT_NEAR(uv.x(), std::atan2(p.y(), p.x()) / (2 * kPi), 1e-16);
  EXPECT_NEAR(uv.y(), std::acos(p.z()) / kPi, 1e-15);
  EXPECT_LT(uv.x(), 0.0);  // the seed's s runs over (-1/2, 1/2]
  EXPECT_EQ(sphereV(Vec3(0, 0, 1), SpherePreset::Seed004), 0.0);
  EXPECT_EQ(uPeriodStart(SpherePreset::Seed004), -0.5);
}

TEST(CylinderUv, IsTurnFractionAndHeight) {
  EXPECT_EQ(cylinderUv(Vec3(0, 1, 0.25)), Vec2(0.25, 0.25));
  EXPECT_EQ(cylinderUv(Vec3(-5, 0, -2)), Vec2(0.5, -2.0));
}

TEST(CubeFace, PicksTheMajorAxis) {
  EXPECT_EQ(majorAxisFace(Vec3(0.9, 0.1, -0.2)), CubeFace::PosX);
  EXPECT_EQ(majorAxisFace(Vec3(-0.9, 0.1, -0.2)), CubeFace::NegX);
  EXPECT_EQ(majorAxisFace(Vec3(0.1, 0.5, -0.2)), CubeFace::PosY);
  EXPECT_EQ(majorAxisFace(Vec3(0.1, -0.5, -0.2)), CubeFace::NegY);
  EXPECT_EQ(majorAxisFace(Vec3(0.1, 0.5, 0.7)), CubeFace::PosZ);
  EXPECT_EQ(majorAxisFace(Vec3(0.1, 0.5, -0.7)), CubeFace::NegZ);
}

TEST(CubeFace, BreaksTiesXBeforeYBeforeZAndSignByTheSignBit) {
  EXPECT_EQ(majorAxisFace(Vec3(1, 1, 0)), CubeFace::PosX);
  EXPECT_EQ(majorAxisFace(Vec3(-1, 1, 1)), CubeFace::NegX);
  EXPECT_EQ(majorAxisFace(Vec3(0, -1, 1)), CubeFace::NegY);
  EXPECT_EQ(majorAxisFace(Vec3(0.5, 1, -1)), CubeFace::PosY);
  EXPECT_EQ(majorAxisFace(Vec3(0.0, 0.0, 0.0)), CubeFace::PosX);
  EXPECT_EQ(majorAxisFace(Vec3(-0.0, 0.0, 0.0)), CubeFace::NegX);
}

// OpenGL 4.6 table 8.19, one direction per face, (s, t) worked by hand:
// s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2.
TEST(CubeFaceSt, FollowsTheOpenGlTableOnEveryFace) {
  struct Case { Vec3 v; CubeFace face; Vec2 st; };
  const Case cases[] = {
      {{0.8, 0.2, -0.4}, CubeFace::PosX, {(0.4 / 0.8 + 1) / 2, (-0.2 / 0.8 + 1) / 2}},   // sc = -z, tc = -y
      {{-0.8, 0.2, -0.4}, CubeFace::NegX, {(-0.4 / 0.8 + 1) / 2, (-0.2 / 0.8 + 1) / 2}},  // sc = +z, tc = -y
      {{0.2, 0.8, -0.4}, CubeFace::PosY, {(0.2 / 0.8 + 1) / 2, (-0.4 / 0.8 + 1) / 2}},    // sc = +x, tc = +z
      {{0.2, -0.8, -0.4}, CubeFace::NegY, {(0.2 / 0.8 + 1) / 2, (0.4 / 0.8 + 1) / 2}},    // sc = +x, tc = -z
      {{0.2, -0.4, 0.8}, CubeFace::PosZ, {(0.2 / 0.8 + 1) / 2, (0.4 / 0.8 + 1) / 2}},     // sc = +x, tc = -y
      {{0.2, -0.4, -0.8}, CubeFace::NegZ, {(-0.2 / 0.8 + 1) / 2, (0.4 / 0.8 + 1) / 2}},   // sc = -x, tc = -y
  };
  for (const Case& c : cases) {
    ASSERT_EQ(majorAxisFace(c.v), c.face);
    const Vec2 st = cubeFaceSt(c.v, c.face, CubeConvention::Gl);
    EXPECT_DOUBLE_EQ(st.x(), c.st.x()) << "face " << static_cast<int>(c.face);
    EXPECT_DOUBLE_EQ(st.y(), c.st.y()) << "face " << static_cast<int>(c.face);
  }
}

// Seed 002: the vector (-0.2, 0.5, -0.84) selects the -Z face and (-0.2, 0.5) maps to (0.38, 0.80).
TEST(CubeFaceSt, DirectConventionReproducesTheSeedExample) {
  const Vec3 r(-0.2, 0.5, -0.84);
  ASSERT_EQ(majorAxisFace(r), CubeFace::NegZ);
  const Vec2 st = cubeFaceSt(r, CubeFace::NegZ, CubeConvention::Direct);
  EXPECT_NEAR(st.x(), 0.38, 0.005);
  EXPECT_NEAR(st.y(), 0.80, 0.005);
  EXPECT_DOUBLE_EQ(st.x(), (-0.2 / 0.84 + 1) / 2);
  EXPECT_DOUBLE_EQ(st.y(), (0.5 / 0.84 + 1) / 2);
}

// In the cross atlas, a point on an edge shared by two faces has one atlas position.
TEST(CubeAtlasUv, CrossLayoutIsContinuousAcrossTheFoldedEdges) {
  auto atlas = [](const Vec3& p, CubeFace f) {
    return cubeAtlasUv(cubeFaceSt(p, f, CubeConvention::Gl), f, CubeConvention::Gl, CubeLayout::Cross);
  };
  // +Z | +X share x = 1, z = 1; -X | +Z share x = -1, z = 1; +X | -Z share x = 1, z = -1;
  // +Y over +Z share y = 1, z = 1; -Y under +Z share y = -1, z = 1.
  for (double s : {-0.7, 0.0, 0.45}) {
    EXPECT_TRUE(atlas(Vec3(1, s, 1), CubeFace::PosZ).isApprox(atlas(Vec3(1, s, 1), CubeFace::PosX), 1e-15));
    EXPECT_TRUE(atlas(Vec3(-1, s, 1), CubeFace::NegX).isApprox(atlas(Vec3(-1, s, 1), CubeFace::PosZ), 1e-15));
    EXPECT_TRUE(atlas(Vec3(1, s, -1), CubeFace::PosX).isApprox(atlas(Vec3(1, s, -1), CubeFace::NegZ), 1e-15));
    EXPECT_TRUE(atlas(Vec3(s, 1, 1), CubeFace::PosY).isApprox(atlas(Vec3(s, 1, 1), CubeFace::PosZ), 1e-15));
    EXPECT_TRUE(atlas(Vec3(s, -1, 1), CubeFace::NegY).isApprox(atlas(Vec3(s, -1, 1), CubeFace::PosZ), 1e-15));
  }
  // The +Z face sits in the second column of the middle row, unmirrored: +x right, +y up.
  EXPECT_TRUE(atlas(Vec3(-1, -1, 1), CubeFace::PosZ).isApprox(Vec2(0.25, 1.0 / 3.0), 1e-15));
  EXPECT_TRUE(atlas(Vec3(1, 1, 1), CubeFace::PosZ).isApprox(Vec2(0.5, 2.0 / 3.0), 1e-15));
}

TEST(CubeAtlasUv, StripAndThreeByTwoPlaceFacesInTheirCells) {
  const Vec2 centre(0.5, 0.5);
  for (int f = 0; f < kCubeFaceCount; ++f) {
    const CubeFace face = static_cast<CubeFace>(f);
    EXPECT_TRUE(cubeAtlasUv(centre, face, CubeConvention::Gl, CubeLayout::Strip).isApprox(Vec2((f + 0.5) / 6, 0.5)));
    EXPECT_TRUE(cubeAtlasUv(centre, face, CubeConvention::Gl, CubeLayout::ThreeByTwo)
                    .isApprox(Vec2((f % 3 + 0.5) / 3, f < 3 ? 0.75 : 0.25)));
    EXPECT_EQ(cubeAtlasUv(Vec2(0.1, 0.2), face, CubeConvention::Gl, CubeLayout::Faces), Vec2(0.1, 0.2));
  }
}

// Opposite faces read unmirrored from outside: walking right on a face seen from outside
// increases u on both +Z and -Z in the direct convention's atlas.
TEST(CubeAtlasUv, DirectConventionAtlasDoesNotMirrorOppositeFaces) {
  auto atlasU = [](const Vec3& p, CubeFace f) {
    return cubeAtlasUv(cubeFaceSt(p, f, CubeConvention::Direct), f, CubeConvention::Direct, CubeLayout::Strip).x();
  };
  // Seen from outside, right on +Z is +x; right on -Z is -x.
  EXPECT_LT(atlasU(Vec3(-0.5, 0, 1), CubeFace::PosZ), atlasU(Vec3(0.5, 0, 1), CubeFace::PosZ));
  EXPECT_LT(atlasU(Vec3(0.5, 0, -1), CubeFace::NegZ), atlasU(Vec3(-0.5, 0, -1), CubeFace::NegZ));
  // Right on -X (seen from outside) is -y; right on +Y is -x.
  EXPECT_LT(atlasU(Vec3(-1, 0.5, 0), CubeFace::NegX), atlasU(Vec3(-1, -0.5, 0), CubeFace::NegX));
  EXPECT_LT(atlasU(Vec3(0.5, 1, 0), CubeFace::PosY), atlasU(Vec3(-0.5, 1, 0), CubeFace::PosY));
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param
