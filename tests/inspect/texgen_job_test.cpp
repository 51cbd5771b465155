// The projective division an OBJ of texgen's coordinates needs (docs/conventions.md §6): values
// worked by hand.
#include "inspect/texgen_job.h"

#include <gtest/gtest.h>

#include <limits>

namespace uvtk::inspect {
namespace {
namespace UVTK_TEST_FILE {

// One face, (s, t) and r at each corner, all valid.
UvMap oneFace(const Vec2& a, const Vec2& b, const Vec2& c, double r) {
  UvMap uv;
  uv.uv = {a, b, c};
  uv.w = {r, r, r};
  uv.faceFlags = {kFaceOk};
  uv.cornerInvalid = {kCornerValid, kCornerValid, kCornerValid};
  return uv;
}

TEST(DivideByQ, NothingWhenQIsOneOrAbsent) {
  const UvMap uv = oneFace({1, 2}, {3, 4}, {5, 6}, 7);
  for (const std::vector<double>& q : {std::vector<double>{1, 1, 1}, std::vector<double>{}}) {
    const ProjectiveDivision d = divideByQ(uv, q);
    EXPECT_FALSE(d.applied);
    EXPECT_EQ(d.qNotOneCorners, 0u);
    EXPECT_EQ(d.qZeroCorners, 0u);
    EXPECT_TRUE(d.uv.uv.empty());
  }
}

TEST(DivideByQ, DividesSTAndRWhereQIsNotOne) {
  const ProjectiveDivision d = divideByQ(oneFace({1, 2}, {3, 4}, {5, 6}, 8), {2, 1, 4});
  ASSERT_TRUE(d.applied);
  EXPECT_EQ(d.qNotOneCorners, 2u);
  EXPECT_EQ(d.qZeroCorners, 0u);
  EXPECT_EQ(d.uv.uv[0], Vec2(0.5, 1));
  EXPECT_EQ(d.uv.uv[1], Vec2(3, 4));  // q = 1: as generated
  EXPECT_EQ(d.uv.uv[2], Vec2(1.25, 1.5));
  EXPECT_EQ(d.uv.w[0], 4.0);
  EXPECT_EQ(d.uv.w[1], 8.0);
  EXPECT_EQ(d.uv.w[2], 2.0);
  EXPECT_EQ(d.uv.faceFlags[0], kFaceOk);
}

TEST(DivideByQ, AZeroOrOverflowingQuotientIsAnInvalidCornerWrittenAsZero) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  const ProjectiveDivision d = divideByQ(oneFace({1, 2}, {1e300, 1}, {3, 4}, 1), {0, tiny, -1});
  ASSERT_TRUE(d.applied);
  EXPECT_EQ(d.qNotOneCorners, 3u);
  EXPECT_EQ(d.qZeroCorners, 2u);  // q = 0, and 1e300 / tiny = inf
  for (int c : {0, 1}) {
    EXPECT_EQ(d.uv.uv[c], Vec2(0, 0));
    EXPECT_EQ(d.uv.w[c], 0.0);
    EXPECT_EQ(d.uv.cornerInvalid[c], kCornerNotFinite);
  }
  EXPECT_EQ(d.uv.uv[2], Vec2(-3, -4));
  EXPECT_EQ(d.uv.cornerInvalid[2], kCornerValid);
  EXPECT_TRUE(d.uv.faceFlags[0] & kFaceInvalid);
}

TEST(DivideByQ, AnInvalidCornerIsNeitherCountedNorDivided) {
  UvMap uv = oneFace({1, 2}, {3, 4}, {5, 6}, 0);
  uv.cornerInvalid[0] = kCornerNotFinite;
  EXPECT_FALSE(divideByQ(uv, {0, 1, 1}).applied);  // q = 0 only where there is no value anyway
  const ProjectiveDivision d = divideByQ(uv, {0, 2, 1});
  ASSERT_TRUE(d.applied);
  EXPECT_EQ(d.qNotOneCorners, 1u);
  EXPECT_EQ(d.qZeroCorners, 0u);
  EXPECT_EQ(d.uv.uv[0], Vec2(1, 2));
  EXPECT_EQ(d.uv.uv[1], Vec2(1.5, 2));
}

TEST(TexgenWritesR, WhenRIsGeneratedOrTheMatrixFeedsIt) {
  texgen::TexgenOptions options;
  options.coordinates[2].mode = texgen::TexgenMode::Off;
  EXPECT_FALSE(texgenWritesR(options));
  options.textureMatrix(2, 0) = 1.0;  // r = s + r
  EXPECT_TRUE(texgenWritesR(options));
  options.textureMatrix = Mat4::Identity();
  options.coordinates[2].mode = texgen::TexgenMode::ObjectLinear;
  EXPECT_TRUE(texgenWritesR(options));
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::inspect
