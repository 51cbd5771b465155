// The camera that frames a mesh (render/camera.h), at the numerical extremes.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "render/camera.h"

namespace uvtk::render {
namespace {
namespace UVTK_TEST_FILE {

// A mesh at 1e200: its bounding sphere and the camera framing it stay finite (the radius was the
// square root of an overflowed squared length), and equal the unit mesh's scaled by the power of two.
TEST(BoundingSphere, OfPointsAt1e200IsFiniteAndScalesExactly) {
  const std::vector<Vec3> unit{{1, 2, 3}, {-1, 0, 2}, {0.5, -2, -1}};
  const double big = std::ldexp(1.0, 664);
  std::vector<Vec3> far;
  for (const Vec3& p : unit) far.push_back(p * big);
  const BoundingSphere a = boundingSphere(unit), b = boundingSphere(far);
  ASSERT_TRUE(std::isfinite(b.radius) && b.center.allFinite());
  EXPECT_EQ(b.center, a.center * big);
  EXPECT_NEAR(b.radius / big, a.radius, 1e-15 * a.radius);
  const Camera camera = frameSphere(b, Vec3(1, -1.5, 0.8), Vec3::UnitZ(), {}, 64, 48);
  EXPECT_TRUE(camera.viewFromWorld.allFinite() && camera.clipFromView.allFinite());
  // The sphere's centre lands at the middle of the picture.
  const Vec4 clip = camera.clipFromView * camera.viewFromWorld * Vec4(b.center.x(), b.center.y(), b.center.z(), 1.0);
  EXPECT_NEAR(clip.x() / clip.w(), 0.0, 1e-12);
  EXPECT_NEAR(clip.y() / clip.w(), 0.0, 1e-12);
}

// At 1.5e308 the eye (centre plus about 2.7 radii) lies beyond the largest double: an input error
// saying so, not lookAt's "must be finite" as a usage error. At 1e300 the camera is framed.
TEST(FrameSphere, RefusesASphereWhoseEyeWouldOverflowAndFramesOneAt1e300) {
  BoundingSphere huge;
  huge.center = Vec3(0, 0, 0), huge.radius = 1.5e308;
  for (const bool orthographic : {false, true}) {
    try {
      frameSphere(huge, Vec3(1, -1.5, 0.8), Vec3::UnitZ(), {orthographic, 45.0}, 64, 48);
      ADD_FAILURE() << "framed a sphere of radius 1.5e308";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("too large for a camera to frame"), std::string::npos) << e.what();
    }
  }
  BoundingSphere large;
  large.center = Vec3(1e300, 0, 0), large.radius = 1e300;
  const Camera camera = frameSphere(large, Vec3(1, -1.5, 0.8), Vec3::UnitZ(), {}, 64, 48);
  EXPECT_TRUE(camera.viewFromWorld.allFinite() && camera.clipFromView.allFinite());
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::render
