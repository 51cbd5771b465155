// The tolerance model on hand-made references: a 2 x 2-texel texture, pixels whose (u, v), face
// and lambda are set directly, and valid intervals computed by hand.
#include "verify/image_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "core/error.h"

namespace uvtk::verify {
namespace {
namespace UVTK_TEST_FILE {

using render::Filter;
using render::Wrap;

// Texels (i, j), grey: (0, 0) 0, (1, 0) 0.4, (0, 1) 0.8, (1, 1) 1; its level 1 is their mean, 0.55.
render::Texture greyTexture() {
  render::TexelLevel level{2, 2, {}};
  for (float g : {0.0f, 0.4f, 0.8f, 1.0f}) level.texels.emplace_back(g, g, g, 1.0f);
  render::Texture texture(level, false);
  texture.buildMipmaps();
  return texture;
}

struct PixelAov {
  double u, v, lambda;
  int face = 0;
};

// A width x height reference whose every pixel has the AOVs `aov(x, row)`; its colour is unused,
// and it has no renderings with quad derivatives.
template <class F>
Reference reference(int width, int height, F aov) {
  render::Rendering r;
  r.colour = Image(width, height, 3);
  r.aovs = Image(width, height, 5);
  for (int row = 0; row < height; ++row)
    for (int x = 0; x < width; ++x) {
      const PixelAov a = aov(x, row);
      r.aovs.at(x, row, 0) = float(a.u), r.aovs.at(x, row, 1) = float(a.v), r.aovs.at(x, row, 2) = 0.5f;
      r.aovs.at(x, row, 3) = float(a.face), r.aovs.at(x, row, 4) = float(a.lambda);
    }
  Reference out;
  out.analytic = std::move(r);
  return out;
}

render::RenderOptions optionsFor(const render::Texture& texture, Filter filter, Wrap wrap = Wrap::Repeat) {
  render::RenderOptions o;
  o.texture = &texture;
  o.sampler = render::samplerFor(filter, wrap);
  o.background = Vec3(0.2, 0.3, 0.4);
  o.aovs = true;
  return o;
}

Image greyShot(int width, int height, double grey) { return Image(width, height, 3, float(grey)); }

// The centre pixel of a 3 x 3 reference around (u, v) with lambda, against a grey shot. (u, v)
// steps by 10^-4 per pixel along x and y alike: an isotropic footprint along the texel axes, where
// every approximation of rho the check allows is the exact one (max(m_u, m_v) = rho).
struct Centre {
  bool pass;
  ImageCheckResult result;
  const InvalidPixel* invalid() const {
    for (const InvalidPixel& p : result.firstInvalid)
      if (p.x == 1 && p.row == 1) return &p;
    return nullptr;
  }
};

Centre checkOne(const render::RenderOptions& o, double u, double v, double lambda, double grey) {
  const auto aov = [&](int x, int row) { return PixelAov{u + (x - 1) * 1e-4, v + (row - 1) * 1e-4, lambda}; };
  ImageCheckResult result = checkImage(greyShot(3, 3, grey), reference(3, 3, aov), o, false);
  const bool red = result.errorMask.at(1, 1, 0) == 1.0f && result.errorMask.at(1, 1, 1) == 0.0f;
  return {!red, std::move(result)};
}

TEST(ImageCheck, NearestMagnificationAllowsTheOneTexelWithinTheColourThreshold) {
  const render::Texture texture = greyTexture();
  const auto o = optionsFor(texture, Filter::Nearest);
  // (0.3, 0.7) on 2 x 2 texels: floor(0.6) = 0, floor(1.4) = 1, texel (0, 1) = 0.8. Threshold 2^-7.
  EXPECT_TRUE(checkOne(o, 0.3, 0.7, -1.0, 0.8).pass);
  EXPECT_TRUE(checkOne(o, 0.3, 0.7, -1.0, 0.8 + 0.99 / 128).pass);
  EXPECT_FALSE(checkOne(o, 0.3, 0.7, -1.0, 0.8 + 1.01 / 128).pass);
  EXPECT_FALSE(checkOne(o, 0.3, 0.7, -1.0, 0.8 - 1.01 / 128).pass);
  // One texel over along s (1, 1) = 1, or along t (wrapped: (0, 0)) = 0: both invalid.
  EXPECT_FALSE(checkOne(o, 0.3, 0.7, -1.0, 1.0).pass);
  EXPECT_FALSE(checkOne(o, 0.3, 0.7, -1.0, 0.0).pass);
  // On a texel boundary (s w = 1 exactly) the coordinate rounding allows both texels.
  EXPECT_TRUE(checkOne(o, 0.5, 0.7, -1.0, 0.8).pass);
  EXPECT_TRUE(checkOne(o, 0.5, 0.7, -1.0, 1.0).pass);
  EXPECT_FALSE(checkOne(o, 0.5, 0.7, -1.0, 0.4).pass);
}

TEST(ImageCheck, BilinearIntervalIsTheExactBlendWidenedByTheWeightRounding) {
  const render::Texture texture = greyTexture();
  const auto o = optionsFor(texture, Filter::Linear);
  // (0.5, 0.5): s w - 1/2 = 0.5, so alpha = beta = 1/2 over texels 0, 0.4, 0.8, 1: 0.55. The weights
  // may be off by e = 2^-16 (weight) + 2^-20 (coordinate: max(1, |1|) 2^-20 texels); the blend's
  // slopes are 0.3 along alpha and 0.7 along beta and its alpha beta term -0.2, so the lookups
  // give 0.55 - e - 0.2 e^2 to 0.55 + e - 0.2 e^2.
  const Centre invalid = checkOne(o, 0.5, 0.5, -1.0, 0.0);
  ASSERT_NE(invalid.invalid(), nullptr);
  const double e = std::exp2(-16) + std::exp2(-20), threshold = 1.0 / 128;
  EXPECT_NEAR(invalid.invalid()->low.x(), 0.55 - e - threshold, 1e-6);
  EXPECT_NEAR(invalid.invalid()->high.x(), 0.55 + e + threshold, 1e-6);
  EXPECT_TRUE(checkOne(o, 0.5, 0.5, -1.0, 0.55).pass);
  EXPECT_TRUE(checkOne(o, 0.5, 0.5, -1.0, 0.55 + threshold + 0.9 * e).pass);
  EXPECT_FALSE(checkOne(o, 0.5, 0.5, -1.0, 0.55 + threshold + 2 * e).pass);
  // Half a texel off (the texel (0, 0) centre's value, 0) is far outside.
  EXPECT_FALSE(checkOne(o, 0.25, 0.25, -1.0, 0.55).pass);
}

TEST(ImageCheck, TrilinearIsLinearInTheLevelWeightWithinTheLodTolerance) {
  const render::Texture texture = greyTexture();
  const auto o = optionsFor(texture, Filter::LinearMipmapLinear);
  // (0.25, 0.25) is texel (0, 0)'s centre: level 0 gives 0, level 1 (1 x 1) 0.55. lambda = 0.5:
  // f = 0.5 -+ (2^-6 lod + 2^-16 weight), 0.275 -+ 0.55 (2^-6 + 2^-16) = -+ 0.0086021, and the
  // colour threshold 8 - 2 bits: 2^-6. Bound 0.275 + 0.0242271 (the level-0 taps add < 1e-5).
  EXPECT_EQ(*checkOne(o, 0.25, 0.25, 0.5, 0.275).result.precision.colorBits, 6);
  EXPECT_TRUE(checkOne(o, 0.25, 0.25, 0.5, 0.275).pass);
  EXPECT_TRUE(checkOne(o, 0.25, 0.25, 0.5, 0.275 + 0.0242).pass);
  EXPECT_FALSE(checkOne(o, 0.25, 0.25, 0.5, 0.275 + 0.0243).pass);
  EXPECT_TRUE(checkOne(o, 0.25, 0.25, 0.5, 0.275 - 0.0242).pass);
  EXPECT_FALSE(checkOne(o, 0.25, 0.25, 0.5, 0.275 - 0.0243).pass);
  // lambda + 1 reads level 1 alone: 0.55, invalid at lambda 0.5.
  EXPECT_TRUE(checkOne(o, 0.25, 0.25, 1.5, 0.55).pass);
  EXPECT_FALSE(checkOne(o, 0.25, 0.25, 0.5, 0.55).pass);
}

TEST(ImageCheck, MagnificationAndMinificationBothCountWhereLambdaStraddlesTheCrossover) {
  const render::Texture texture = greyTexture();
  // NEAREST_MIPMAP_NEAREST with NEAREST magnification: c = 0. At lambda 2^-9 (within 2^-8 of 0) both
  // level 0 (texel (0, 0) = 0) and level 1 (0.55, d = 0 up to lambda 1/2: still level 0) ...
  const auto o = optionsFor(texture, Filter::NearestMipmapNearest);
  EXPECT_TRUE(checkOne(o, 0.25, 0.25, 0.0, 0.0).pass);
  EXPECT_FALSE(checkOne(o, 0.25, 0.25, 0.0, 0.55).pass);
  // ... and around lambda 1/2 the level switches to 1: both allowed there, only one either side.
  EXPECT_TRUE(checkOne(o, 0.25, 0.25, 0.5, 0.0).pass);
  EXPECT_TRUE(checkOne(o, 0.25, 0.25, 0.5, 0.55).pass);
  EXPECT_FALSE(checkOne(o, 0.25, 0.25, 0.45, 0.55).pass);
  EXPECT_FALSE(checkOne(o, 0.25, 0.25, 0.55, 0.0).pass);
  // LINEAR magnification with NEAREST_MIPMAP_NEAREST moves the crossover to c = 1/2 (GL 4.6 §8.15).
  render::RenderOptions half = o;
  half.sampler.magFilter = Filter::Linear;
  EXPECT_TRUE(checkOne(half, 0.5, 0.5, 0.3, 0.55).pass);     // LINEAR at level 0: 0.55 as well
  EXPECT_TRUE(checkOne(half, 0.25, 0.25, 0.3, 0.0).pass);    // LINEAR at the texel's centre
  EXPECT_FALSE(checkOne(half, 0.25, 0.25, 0.3, 0.55).pass);  // not yet level 1
}

TEST(ImageCheck, WrapModesAreAppliedAsTheRendererAppliesThem) {
  const render::Texture texture = greyTexture();
  // s = 1.3: 2.6 texels, floor 2. REPEAT: texel 0; CLAMP_TO_EDGE: texel 1; MIRRORED_REPEAT: texel 1.
  // t = 0.2: row 0. So 0 (repeat) or 0.4 (clamp, mirror).
  EXPECT_TRUE(checkOne(optionsFor(texture, Filter::Nearest, Wrap::Repeat), 1.3, 0.2, -1, 0.0).pass);
  EXPECT_FALSE(checkOne(optionsFor(texture, Filter::Nearest, Wrap::Repeat), 1.3, 0.2, -1, 0.4).pass);
  EXPECT_TRUE(checkOne(optionsFor(texture, Filter::Nearest, Wrap::ClampToEdge), 1.3, 0.2, -1, 0.4).pass);
  EXPECT_FALSE(checkOne(optionsFor(texture, Filter::Nearest, Wrap::ClampToEdge), 1.3, 0.2, -1, 0.0).pass);
  EXPECT_TRUE(checkOne(optionsFor(texture, Filter::Nearest, Wrap::MirroredRepeat), 1.3, 0.2, -1, 0.4).pass);
  // Far outside, clamped: the edge texel, however far.
  EXPECT_TRUE(checkOne(optionsFor(texture, Filter::Linear, Wrap::ClampToEdge), -1e30, 0.0, -1, 0.0).pass);
  EXPECT_FALSE(checkOne(optionsFor(texture, Filter::Linear, Wrap::ClampToEdge), -1e30, 0.0, -1, 0.4).pass);
}

TEST(ImageCheck, LodIntervalIsWidenedByTheNeighboursOfTheSameFaceOnly) {
  const render::Texture texture = greyTexture();
  const auto o = optionsFor(texture, Filter::NearestMipmapNearest);
  // 3 x 3 pixels, all at texel (0, 0)'s centre with lambda 0.2 (level 0, value 0), but the top-left
  // corner at lambda 0.8 (level 1, 0.55). The centre may show 0.55 when that corner is the same face.
  const auto check = [&](int cornerFace) {
    Image shot = greyShot(3, 3, 0.0);
    for (int c = 0; c < 3; ++c) shot.at(1, 1, c) = 0.55f, shot.at(0, 0, c) = 0.55f;
    return checkImage(shot, reference(3, 3, [&](int x, int row) {
                        const bool corner = x == 0 && row == 0;
                        return PixelAov{0.25, 0.25, corner ? 0.8 : 0.2, corner ? cornerFace : 0};
                      }),
                      o, false);
  };
  EXPECT_TRUE(check(0).pass);
  const ImageCheckResult other = check(1);  // a diagonal neighbour of another face: no widening, no edge
  EXPECT_EQ(other.invalid, 1u);
  ASSERT_EQ(other.firstInvalid.size(), 1u);
  EXPECT_EQ(other.firstInvalid[0].x, 1);
  EXPECT_EQ(other.firstInvalid[0].row, 1);
}

TEST(ImageCheck, RhoMayBeApproximatedFromBelowByTheLargestDerivative) {
  const render::Texture texture = greyTexture();
  const auto o = optionsFor(texture, Filter::NearestMipmapNearest);
  // At texel (0, 0)'s centre with lambda 0.9: level 1 (0.55); level 0 (value 0) is below 1/2.
  // Along the texel axes max(m_u, m_v) = rho: only level 1.
  EXPECT_TRUE(checkOne(o, 0.25, 0.25, 0.9, 0.55).pass);
  EXPECT_FALSE(checkOne(o, 0.25, 0.25, 0.9, 0.0).pass);
  // Diagonal: d(s, t)/dx = (1, 1) 10^-4, d(s, t)/dy = (-1, 1) 10^-4, so rho = sqrt 2 max(m_u, m_v):
  // GL's lower bound on rho is half a level lower, lambda 0.4 reads level 0.
  const auto diagonal = [](int x, int row) {
    return PixelAov{0.25 + ((x - 1) - (row - 1)) * 1e-4, 0.25 + ((x - 1) + (row - 1)) * 1e-4, 0.9};
  };
  const ImageCheckResult result = checkImage(greyShot(3, 3, 0.0), reference(3, 3, diagonal), o, false);
  EXPECT_EQ(result.invalid, 0u);
}

TEST(ImageCheck, PixelsAtAnEdgeMayShowTheirFourNeighboursSurfaces) {
  const render::Texture texture = greyTexture();
  const auto o = optionsFor(texture, Filter::Nearest);
  // 3 x 1: face 0 at texel value 0, face 0, background. The middle pixel may be background; the
  // first may not (its neighbour is the same face).
  const Reference r = reference(3, 1, [](int x, int) { return PixelAov{0.25, 0.25, -1.0, x == 2 ? -1 : 0}; });
  Image shot = greyShot(3, 1, 0.0);
  for (int c = 0; c < 3; ++c) shot.at(2, 0, c) = float(o.background[c]);
  EXPECT_TRUE(checkImage(shot, r, o, false).pass);
  Image edge = shot;
  for (int c = 0; c < 3; ++c) edge.at(1, 0, c) = float(o.background[c]), edge.at(2, 0, c) = 0.0f;
  EXPECT_TRUE(checkImage(edge, r, o, false).pass);  // the edge moved by a pixel's fraction, both ways
  Image far = shot;
  for (int c = 0; c < 3; ++c) far.at(0, 0, c) = float(o.background[c]);
  const ImageCheckResult result = checkImage(far, r, o, false);
  EXPECT_EQ(result.invalid, 1u);
  EXPECT_EQ(result.checked, 3u);
  EXPECT_NEAR(result.invalidShare, 1.0 / 3, 1e-12);
  // The error mask: red where invalid, the shot at a third elsewhere.
  EXPECT_EQ(result.errorMask.at(0, 0, 0), 1.0f);
  EXPECT_EQ(result.errorMask.at(0, 0, 1), 0.0f);
  EXPECT_FLOAT_EQ(result.errorMask.at(2, 0, 2), float(o.background[2] / 3));
}

TEST(ImageCheck, DefaultsFollowTheFilterAndTheMappingAndBadBitsAreUsageErrors) {
  const auto nearest = render::samplerFor(Filter::Nearest, Wrap::Repeat);
  const auto trilinear = render::samplerFor(Filter::NearestMipmapLinear, Wrap::Repeat);
  EXPECT_EQ(*resolvePrecision({}, nearest, false).lodBits, 6);
  EXPECT_EQ(*resolvePrecision({}, nearest, true).lodBits, 6);
  EXPECT_EQ(*resolvePrecision({}, nearest, false).colorBits, 7);
  EXPECT_EQ(*resolvePrecision({}, trilinear, false).colorBits, 6);
  ImagePrecision p;
  p.coordBits = 0;
  EXPECT_THROW(resolvePrecision(p, nearest, false), UsageError);
  p = {};
  p.colorBits = 17;
  EXPECT_THROW(resolvePrecision(p, nearest, false), UsageError);
}

TEST(ImageCheck, UnsupportedRenderingsAndMismatchedShotsAreUsageErrors) {
  const render::Texture texture = greyTexture();
  const Reference r = reference(2, 2, [](int, int) { return PixelAov{0.25, 0.25, -1.0}; });
  const Image shot = greyShot(2, 2, 0.0);
  auto o = optionsFor(texture, Filter::Nearest);
  EXPECT_TRUE(checkImage(shot, r, o, false).pass);
  EXPECT_THROW(checkImage(greyShot(3, 2, 0.0), r, o, false), UsageError);
  auto modulate = o;
  modulate.env = render::EnvMode::Modulate;
  EXPECT_THROW(checkImage(shot, r, modulate, false), UsageError);
  auto supersampled = o;
  supersampled.samplesPerPixel = 4;
  EXPECT_THROW(checkImage(shot, r, supersampled, false), UsageError);
  auto none = o;
  none.texture = nullptr;
  EXPECT_THROW(checkImage(shot, r, none, false), UsageError);
  Reference noAovs = r;
  noAovs.analytic.aovs = Image();
  EXPECT_THROW(checkImage(shot, noAovs, o, false), UsageError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::verify
