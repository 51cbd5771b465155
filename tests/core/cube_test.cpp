// The cube of GL's cube maps (core/cube.h): face selection with its ties, GL 4.6 table 8.19 and its
// inverse, and the atlas layouts' cells, all against hand-computed values.
#include "core/cube.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdlib>

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

struct Hit {
  Vec3 direction;
  CubeFace face;
  Vec2 st;
};

TEST(CubeFace, EachAxisDirectionHitsItsFaceAtTheCentre) {
  const std::array<Hit, 6> hits = {{{Vec3(1, 0, 0), CubeFace::PosX, Vec2(0.5, 0.5)},
                                    {Vec3(-1, 0, 0), CubeFace::NegX, Vec2(0.5, 0.5)},
                                    {Vec3(0, 1, 0), CubeFace::PosY, Vec2(0.5, 0.5)},
                                    {Vec3(0, -1, 0), CubeFace::NegY, Vec2(0.5, 0.5)},
                                    {Vec3(0, 0, 1), CubeFace::PosZ, Vec2(0.5, 0.5)},
                                    {Vec3(0, 0, -1), CubeFace::NegZ, Vec2(0.5, 0.5)}}};
  for (const Hit& h : hits) {
    const CubeFace f = majorAxisFace(h.direction);
    EXPECT_EQ(f, h.face) << h.direction.transpose();
    EXPECT_EQ(glCubeFaceSt(h.direction, f), h.st) << h.direction.transpose();
    EXPECT_EQ(faceAxis(f), int(f) / 2);
    EXPECT_EQ(faceSign(f) * h.direction[faceAxis(f)], 1.0);  // the face's axis points along the direction
  }
}

TEST(CubeFace, TiesOnEdgesAndCornersGoToXBeforeYBeforeZ) {
  // (s, t) by table 8.19 with |ma| = 1, e.g. (1, 1, 0) on +X: sc = -z = 0, tc = -y = -1, so (1/2, 0).
  const std::array<Hit, 8> hits = {{
      {Vec3(1, 1, 0), CubeFace::PosX, Vec2(0.5, 0.0)},
      {Vec3(0, -1, 1), CubeFace::NegY, Vec2(0.5, 0.0)},    // sc = x = 0, tc = -z = -1
      {Vec3(1, 1, 1), CubeFace::PosX, Vec2(0.0, 0.0)},     // sc = -z = -1, tc = -y = -1
      {Vec3(-1, 1, 1), CubeFace::NegX, Vec2(1.0, 0.0)},    // sc = z = 1, tc = -y = -1
      {Vec3(0, 1, -1), CubeFace::PosY, Vec2(0.5, 0.0)},    // sc = x = 0, tc = z = -1
      {Vec3(-1, -1, -1), CubeFace::NegX, Vec2(0.0, 1.0)},  // sc = z = -1, tc = -y = 1
      {Vec3(2, 0, -2), CubeFace::PosX, Vec2(1.0, 0.5)},    // sc = -z = 2, tc = 0, |ma| = 2
      {Vec3(0, -3, -3), CubeFace::NegY, Vec2(0.5, 1.0)},   // sc = x = 0, tc = -z = 3, |ma| = 3
  }};
  for (const Hit& h : hits) {
    const CubeFace f = majorAxisFace(h.direction);
    EXPECT_EQ(f, h.face) << h.direction.transpose();
    EXPECT_EQ(glCubeFaceSt(h.direction, f), h.st) << h.direction.transpose();
  }
}

TEST(CubeFace, TheSignBitDecidesForZeroSoMinusZeroPicksTheMinusFace) {
  // Only the zero vector has a zero major component; all ties go to x, and its sign bit decides.
  EXPECT_EQ(majorAxisFace(Vec3(0.0, 0.0, 0.0)), CubeFace::PosX);
  EXPECT_EQ(majorAxisFace(Vec3(-0.0, 0.0, 0.0)), CubeFace::NegX);
  EXPECT_EQ(majorAxisFace(Vec3(0.0, -0.0, -0.0)), CubeFace::PosX);
  EXPECT_EQ(majorAxisFace(Vec3(-0.0, -0.0, -0.0)), CubeFace::NegX);
  // On an axis the other components' signs do not matter: (+0, +0, -1) and (-0, -0, -1) are -Z.
  EXPECT_EQ(majorAxisFace(Vec3(-0.0, -0.0, -1.0)), CubeFace::NegZ);
  EXPECT_EQ(majorAxisFace(Vec3(0.0, 0.0, -1.0)), CubeFace::NegZ);
}

TEST(CubeFace, TheSeedVectorSelectsMinusZAtGlsTableCoordinates) {
  // -Z: sc = -x = 0.2, tc = -y = -0.5, |ma| = 0.84. (The `direct` convention's (0.38, 0.80) is
  // param's choice, not GL's.)
  const Vec3 d(-0.2, 0.5, -0.84);
  ASSERT_EQ(majorAxisFace(d), CubeFace::NegZ);
  const Vec2 c = glCubeFaceCoordinates(d, CubeFace::NegZ);
  EXPECT_EQ(c, Vec2(0.2, -0.5));
  const Vec2 st = glCubeFaceSt(d, CubeFace::NegZ);
  EXPECT_NEAR(st.x(), 0.6190476190476190, 1e-15);  // (0.2 / 0.84 + 1) / 2 = 13 / 21
  EXPECT_NEAR(st.y(), 0.2023809523809524, 1e-15);  // (-0.5 / 0.84 + 1) / 2 = 17 / 84
  EXPECT_NEAR(st.x(), 13.0 / 21.0, 1e-15);
  EXPECT_NEAR(st.y(), 17.0 / 84.0, 1e-15);
}

TEST(CubeFace, FaceStFromCoordinatesDividesByTheMagnitudeOfTheMajorAxis) {
  EXPECT_EQ(faceStFromCoordinates(Vec2(1, -2), -4.0), Vec2(0.625, 0.25));  // (1/4 + 1)/2, (-2/4 + 1)/2
  EXPECT_EQ(faceStFromCoordinates(Vec2(1, -2), 4.0), Vec2(0.625, 0.25));
}

TEST(CubeFace, GlCubeDirectionInvertsTheTableOnEveryFaceExactlyInIntegers) {
  const std::array<std::array<int, 3>, 5> points = {{{0, 0, 1}, {3, -2, 5}, {-4, 4, 4}, {7, 1, 9}, {-6, -8, 8}}};
  for (int face = 0; face < kCubeFaceCount; ++face) {
    const CubeFace f = CubeFace(face);
    for (const auto& [sc, tc, ma] : points) {
      const Eigen::Vector3i d = glCubeDirection<int>(f, sc, tc, ma);
      EXPECT_EQ(d[faceAxis(f)], faceSign(f) * ma) << face;
      EXPECT_EQ(glCubeFaceCoordinates<int>(d, f), Eigen::Vector2i(sc, tc)) << face << ": " << sc << " " << tc;
      // Strictly inside the face the direction selects it; on its edges the ties decide (above).
      const CubeFace selected = majorAxisFace(Vec3(d.cast<double>()));
      if (std::abs(sc) < ma && std::abs(tc) < ma) {
        EXPECT_EQ(selected, f) << face << ": " << sc << " " << tc;
      }
    }
    // And the other way round, for a direction that is not on a lattice.
    const Vec3 d = glCubeDirection(f, 0.3125, -0.71875, 1.5);
    const Vec3 back = glCubeDirection(f, glCubeFaceCoordinates(d, f).x(), glCubeFaceCoordinates(d, f).y(), 1.5);
    EXPECT_EQ(back, d) << face;
    EXPECT_EQ(majorAxisFace(d), f) << face;
    EXPECT_EQ(glCubeFaceSt(d, f), Vec2((0.3125 / 1.5 + 1) / 2, (-0.71875 / 1.5 + 1) / 2)) << face;
  }
}

TEST(CubeLayout, CrossPlacesTheFacesOnA4By3GridCountedFromTheBottom) {
  const std::array<std::array<int, 2>, 6> cells = {{{2, 1}, {0, 1}, {1, 2}, {1, 0}, {1, 1}, {3, 1}}};
  for (int f = 0; f < kCubeFaceCount; ++f) {
    const CubeLayoutCell c = cubeLayoutCell(CubeFace(f), CubeLayout::Cross);
    EXPECT_EQ(c.column, cells[std::size_t(f)][0]) << f;
    EXPECT_EQ(c.row, cells[std::size_t(f)][1]) << f;
    EXPECT_EQ(c.columns, 4);
    EXPECT_EQ(c.rows, 3);
  }
}

TEST(CubeLayout, StripAnd3x2PlaceTheFacesInGlOrder) {
  // 3x2: top row (row 1) +X -X +Y, bottom row (row 0) -Y +Z -Z.
  const std::array<std::array<int, 2>, 6> threeByTwo = {{{0, 1}, {1, 1}, {2, 1}, {0, 0}, {1, 0}, {2, 0}}};
  for (int f = 0; f < kCubeFaceCount; ++f) {
    const CubeLayoutCell strip = cubeLayoutCell(CubeFace(f), CubeLayout::Strip);
    EXPECT_EQ(strip.column, f);
    EXPECT_EQ(strip.row, 0);
    EXPECT_EQ(strip.columns, 6);
    EXPECT_EQ(strip.rows, 1);
    const CubeLayoutCell cell = cubeLayoutCell(CubeFace(f), CubeLayout::ThreeByTwo);
    EXPECT_EQ(cell.column, threeByTwo[std::size_t(f)][0]) << f;
    EXPECT_EQ(cell.row, threeByTwo[std::size_t(f)][1]) << f;
    EXPECT_EQ(cell.columns, 3);
    EXPECT_EQ(cell.rows, 2);
    const CubeLayoutCell single = cubeLayoutCell(CubeFace(f), CubeLayout::Faces);
    EXPECT_EQ(single.column + single.row, 0);
    EXPECT_EQ(single.columns * single.rows, 1);
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
