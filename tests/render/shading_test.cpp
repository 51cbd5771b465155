#include "render/shading.h"

#include <gtest/gtest.h>

#include <cmath>

namespace uvtk::render {
namespace {
namespace UVTK_TEST_FILE {

bool near(const Vec4& a, const Vec4& b) { return (a - b).norm() < 1e-12; }

TEST(TextureEnvironment, FollowsTheEquationsOfTheLectureNotes) {
  const Vec4 fragment(0.8, 0.4, 0.2, 0.5), texel(0.5, 1.0, 0.25, 0.75), envColour(0.1, 0.2, 0.3, 0.4);
  // Zachmann's REPLACE: L_out = C_tex; Munzner: "throw away old color".
  EXPECT_TRUE(near(textureEnvironment(EnvMode::Replace, fragment, texel, envColour), texel));
  // MODULATE: L_out = L_Phong . C_tex, component by component (C_ut = C_in C_t).
  EXPECT_TRUE(near(textureEnvironment(EnvMode::Modulate, fragment, texel, envColour), Vec4(0.4, 0.4, 0.05, 0.375)));
  // DECAL: alpha_T T + (1 - alpha_T) F for the colour, the fragment's alpha kept.
  EXPECT_TRUE(near(textureEnvironment(EnvMode::Decal, fragment, texel, envColour),
                   Vec4(0.75 * 0.5 + 0.25 * 0.8, 0.75 * 1.0 + 0.25 * 0.4, 0.75 * 0.25 + 0.25 * 0.2, 0.5)));
  // BLEND: F (1 - T) + C T (C_ut = C_in (1 - C_t) + C_t C_c); alpha Af At.
  EXPECT_TRUE(near(textureEnvironment(EnvMode::Blend, fragment, texel, envColour),
                   Vec4(0.8 * 0.5 + 0.1 * 0.5, 0.4 * 0.0 + 0.2 * 1.0, 0.2 * 0.75 + 0.3 * 0.25, 0.375)));
  // With C_c = 0 (GL's default), BLEND darkens by 1 - C_t, as the Swedish notes say.
  EXPECT_TRUE(near(textureEnvironment(EnvMode::Blend, Vec4(1, 1, 1, 1), texel, Vec4::Zero()), Vec4(0.5, 0.0, 0.75, 0.75)));
}

TEST(HeadlightColour, IsAmbientPlusDiffusePlusSpecularOfGlsLightingEquation) {
  const Lighting l;
  // Facing the light: 0.2*0.2 + 0 + 1 * 0.8 + 1^32 * 0.5 = 1.34, clamped to 1.
  EXPECT_TRUE(near(headlightColour(l, Vec3(0, 0, 1)), Vec4(1, 1, 1, 1)));
  // At 60 degrees: 0.04 + 0.5 * 0.8 + 0.5^32 * 0.5.
  const double c = 0.04 + 0.4 + std::pow(0.5, 32) * 0.5;
  EXPECT_TRUE(near(headlightColour(l, Vec3(std::sqrt(3.0) / 2, 0, 0.5)), Vec4(c, c, c, 1)));
  // Facing away: the ambient term only.
  EXPECT_TRUE(near(headlightColour(l, Vec3(0, 0, -1)), Vec4(0.04, 0.04, 0.04, 1)));
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::render
