#include "core/gl_matrices.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

// The point a clip-space vector lands on after the perspective divide.
Vec3 ndc(const Vec4& clip) { return clip.head<3>() / clip.w(); }

TEST(LookAt, EqualsTheGluLookAtMatrixOfAWorkedExample) {
  // eye (3,0,0) looking at the origin, up +y: f = (-1,0,0), s = f x up = (0,0,-1), u = (0,1,0);
  // rows s, u, -f and the translation -(s.eye, u.eye, -f.eye) = (0, 0, -3).
  Mat4 expected;
  expected << 0, 0, -1, 0,  //
      0, 1, 0, 0,           //
      1, 0, 0, -3,          //
      0, 0, 0, 1;
  EXPECT_EQ(lookAt(Vec3(3, 0, 0), Vec3::Zero(), Vec3(0, 2, 0)), expected);
  // GL's initial modelview: eye at the origin looking down -z.
  EXPECT_EQ(lookAt(Vec3::Zero(), Vec3(0, 0, -1), Vec3::UnitY()), Mat4::Identity());
  // A general one: the eye goes to the origin and the center onto -z.
  const Mat4 m = lookAt(Vec3(1, 2, 3), Vec3(-2, 0.5, 1), Vec3(0.3, 1, 0));
  EXPECT_LT((m * Vec4(1, 2, 3, 1) - Vec4(0, 0, 0, 1)).norm(), 1e-15);
  EXPECT_LT((m * Vec4(-2, 0.5, 1, 1) - Vec4(0, 0, -Vec3(3, 1.5, 2).norm(), 1)).norm(), 1e-14);
  EXPECT_NEAR((m.topLeftCorner<3, 3>() * m.topLeftCorner<3, 3>().transpose() - Mat3::Identity()).norm(), 0.0, 1e-15);
}

// A mesh at 1e200 puts the eye 1e200 from the center: the direction's squared length overflows,
// so the frame is normalised without squaring (the worked example scaled by 2^664, exactly).
TEST(LookAt, AnEyeFarBeyondTheSquareRootOfTheLargestDoubleStillGivesTheFrame) {
  const double big = std::ldexp(1.0, 664);  // about 1.2e200
  const Mat4 m = lookAt(Vec3(3 * big, 0, 0), Vec3::Zero(), Vec3(0, 2 * big, 0));
  ASSERT_TRUE(m.allFinite());
  const Mat3 rotation = lookAt(Vec3(3, 0, 0), Vec3::Zero(), Vec3(0, 2, 0)).topLeftCorner<3, 3>();
  EXPECT_EQ(Mat3(m.topLeftCorner<3, 3>()), rotation);
  EXPECT_EQ(m(2, 3), -3 * big);
}

TEST(LookAt, CoincidentEyeAndCenterOrAParallelUpAreUsageErrors) {
  EXPECT_THROW(lookAt(Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3::UnitY()), UsageError);
  EXPECT_THROW(lookAt(Vec3::Zero(), Vec3(0, 5, 0), Vec3(0, -2, 0)), UsageError);
  EXPECT_THROW(lookAt(Vec3::Zero(), Vec3(0, 0, -1), Vec3::Zero()), UsageError);
}

TEST(Perspective, MapsTheFrustumCornersOntoTheNdcCube) {
  // fovy 90 degrees: tan(45) = 1, so at depth d the frustum spans y in [-d, d] and x in [-2d, 2d].
  const Mat4 p = perspective(90.0, 2.0, 0.5, 10.0);
  EXPECT_LT((ndc(p * Vec4(1.0, 0.5, -0.5, 1)) - Vec3(1, 1, -1)).norm(), 1e-15);
  EXPECT_LT((ndc(p * Vec4(-20.0, -10.0, -10.0, 1)) - Vec3(-1, -1, 1)).norm(), 1e-14);
  // w_clip is the distance in front of the eye.
  EXPECT_EQ((p * Vec4(0, 0, -3, 1)).w(), 3.0);
  EXPECT_THROW(perspective(0.0, 1.0, 0.1, 1.0), UsageError);
  EXPECT_THROW(perspective(180.0, 1.0, 0.1, 1.0), UsageError);
  EXPECT_THROW(perspective(45.0, 1.0, 0.0, 1.0), UsageError);
  EXPECT_THROW(perspective(45.0, 1.0, 2.0, 1.0), UsageError);
}

TEST(Orthographic, MapsTheBoxOntoTheNdcCube) {
  const Mat4 o = orthographic(-1, 3, 2, 4, 1, 5);
  EXPECT_LT((o * Vec4(-1, 2, -1, 1) - Vec4(-1, -1, -1, 1)).norm(), 1e-15);
  EXPECT_LT((o * Vec4(3, 4, -5, 1) - Vec4(1, 1, 1, 1)).norm(), 1e-15);
  EXPECT_LT((o * Vec4(1, 3, -3, 1) - Vec4(0, 0, 0, 1)).norm(), 1e-15);
  EXPECT_THROW(orthographic(1, 1, 0, 1, 0, 1), UsageError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
