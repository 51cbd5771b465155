// Texture sampling against hand-computed values: GL 4.6 compatibility profile §8.14 and the
// lecture notes' linear-filter example.
#include "render/texture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "core/error.h"
#include "doubles.h"

namespace uvtk::render {
namespace {
namespace UVTK_TEST_FILE {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A level whose texels carry the given red values (green, blue 0, alpha 1), row j = 0 first.
TexelLevel redLevel(int width, int height, const std::vector<float>& reds) {
  TexelLevel level;
  level.width = width;
  level.height = height;
  for (float red : reds) level.texels.emplace_back(red, 0.0f, 0.0f, 1.0f);
  return level;
}

// An 8 x 8 texture that is 1 at texel (0, 0) and 0 elsewhere: texel (0, 0) of level k is 4^-k
// (1, 1/4, 1/16, 1/64), so the value sampled at s = t = 0 names the level.
Texture impulseTexture() {
  std::vector<float> reds(64, 0.0f);
  reds[0] = 1.0f;
  Texture texture(redLevel(8, 8, reds), false);
  texture.buildMipmaps();
  return texture;
}

SamplerState sampler(Filter minFilter, Filter magFilter, Wrap wrap = Wrap::ClampToEdge) {
  SamplerState state;
  state.minFilter = minFilter;
  state.magFilter = magFilter;
  state.wrapS = state.wrapT = wrap;
  return state;
}

TEST(WrapTexel, RepeatTakesThePositiveModulo) {
  EXPECT_EQ(wrapTexel(0, 4, Wrap::Repeat), 0);
  EXPECT_EQ(wrapTexel(3, 4, Wrap::Repeat), 3);
  EXPECT_EQ(wrapTexel(4, 4, Wrap::Repeat), 0);
  EXPECT_EQ(wrapTexel(7, 4, Wrap::Repeat), 3);
  EXPECT_EQ(wrapTexel(-1, 4, Wrap::Repeat), 3);
  EXPECT_EQ(wrapTexel(-4, 4, Wrap::Repeat), 0);
  EXPECT_EQ(wrapTexel(-5, 4, Wrap::Repeat), 3);
  EXPECT_EQ(wrapTexel((std::int64_t(1) << 62) + 1, 4, Wrap::Repeat), 1);
  EXPECT_EQ(wrapTexel(std::numeric_limits<std::int64_t>::min(), 3, Wrap::Repeat), 1);  // -2^63 = -3074457345618258603 * 3 + 1
  EXPECT_EQ(wrapTexel(12345, 1, Wrap::Repeat), 0);
}

TEST(WrapTexel, ClampToEdgeClampsToTheFirstAndLastTexel) {
  EXPECT_EQ(wrapTexel(-1, 4, Wrap::ClampToEdge), 0);
  EXPECT_EQ(wrapTexel(-1000000000000, 4, Wrap::ClampToEdge), 0);
  EXPECT_EQ(wrapTexel(2, 4, Wrap::ClampToEdge), 2);
  EXPECT_EQ(wrapTexel(4, 4, Wrap::ClampToEdge), 3);
  EXPECT_EQ(wrapTexel(1000000000000, 4, Wrap::ClampToEdge), 3);
}

TEST(WrapTexel, MirroredRepeatReflectsEveryOtherCopy) {
  // size 3: (i mod 6) - 3 for i = -3..5 is 0 1 2 -3 -2 -1 0 1 2; mirror gives 0 1 2 2 1 0 0 1 2;
  // 2 minus that: 2 1 0 0 1 2 2 1 0.
  const int expected[] = {2, 1, 0, 0, 1, 2, 2, 1, 0};
  for (int i = -3; i <= 5; ++i) EXPECT_EQ(wrapTexel(i, 3, Wrap::MirroredRepeat), expected[i + 3]) << i;
  // 6e12 + 1 mod 6 = 1, as i = 1.
  EXPECT_EQ(wrapTexel(6000000000001, 3, Wrap::MirroredRepeat), 1);
  // -6e12 - 1 mod 6 = 5, as i = -1 and i = 5: 0.
  EXPECT_EQ(wrapTexel(-6000000000001, 3, Wrap::MirroredRepeat), 0);
}

TEST(SampleNearest, PicksTheTexelUnderFloorOfSTimesWidth) {
  const TexelLevel level = redLevel(4, 1, {10, 11, 12, 13});
  const auto red = [&](double s, Wrap wrap) { return sampleNearest(level, wrap, wrap, s, 0.5).x(); };
  EXPECT_EQ(red(0.0, Wrap::Repeat), 10);
  EXPECT_EQ(red(0.2499, Wrap::Repeat), 10);
  EXPECT_EQ(red(0.25, Wrap::Repeat), 11);  // on the boundary: floor(1) = 1
  EXPECT_EQ(red(0.99, Wrap::Repeat), 13);
  EXPECT_EQ(red(1.0, Wrap::Repeat), 10);  // floor(4) = 4 wraps to 0
  EXPECT_EQ(red(1.0, Wrap::ClampToEdge), 13);
  EXPECT_EQ(red(1.0, Wrap::MirroredRepeat), 13);
  EXPECT_EQ(red(-0.1, Wrap::Repeat), 13);  // floor(-0.4) = -1
  EXPECT_EQ(red(-0.1, Wrap::ClampToEdge), 10);
  EXPECT_EQ(red(-0.1, Wrap::MirroredRepeat), 10);
  EXPECT_EQ(red(1e300, Wrap::ClampToEdge), 13);
  EXPECT_EQ(red(-1e300, Wrap::Repeat), 10);  // clamped to -2^62, a multiple of 4
}

TEST(SampleLinear, ReproducesTheLectureNotesOneDimensionalExample) {
  // T = 4 texels 8 0 0 0 spread over B = 12 pixels: pixel x takes texel position x T / B, i its
  // floor, a its fraction, and (1 - a) t_i + a t_i+1 with the last texel's neighbour clamped.
  // x = 0: 8; x = 1: position 1/3, (2/3) 8 = 16/3; x = 2: 2/3, 8/3; x >= 3: texels 1..3, 0.
  const TexelLevel level = redLevel(4, 1, {8, 0, 0, 0});
  const double expected[12] = {8, 16.0 / 3, 8.0 / 3, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  for (int x = 0; x < 12; ++x) {
    const double s = (x * 4.0 / 12.0 + 0.5) / 4.0;  // s W - 1/2 = x T / B
    EXPECT_NEAR(sampleLinear(level, Wrap::ClampToEdge, Wrap::ClampToEdge, s, 0.5).x(), expected[x], 1e-12) << x;
  }
}

TEST(SampleLinear, FollowsGlPixelCentresUnderRepeatAndClampToEdge) {
  // GL samples pixel x at its centre, s = (x + 1/2) / 12, so u = s 4 - 1/2 = (x - 1) / 3:
  //   x = 0: u = -1/3, i0 = -1, a = 2/3. REPEAT: t3 (0) and t0 (8): 16/3. CLAMP: t0, t0: 8.
  //   x = 1: u = 0: 8.   x = 2: u = 1/3: (2/3) 8 = 16/3.   x = 3: u = 2/3: 8/3.
  //   x = 4..10: u = 1 .. 3, only texels 1..3 (the weight of texel 0 is 0 at x = 10): 0.
  //   x = 11: u = 10/3, i0 = 3, a = 1/3. REPEAT: t3 and t0: 8/3. CLAMP: t3, t3: 0.
  const TexelLevel level = redLevel(4, 1, {8, 0, 0, 0});
  const double repeat[12] = {16.0 / 3, 8, 16.0 / 3, 8.0 / 3, 0, 0, 0, 0, 0, 0, 0, 8.0 / 3};
  const double clamp[12] = {8, 8, 16.0 / 3, 8.0 / 3, 0, 0, 0, 0, 0, 0, 0, 0};
  for (int x = 0; x < 12; ++x) {
    const double s = (x + 0.5) / 12.0;
    EXPECT_NEAR(sampleLinear(level, Wrap::Repeat, Wrap::Repeat, s, 0.5).x(), repeat[x], 1e-12) << x;
    EXPECT_NEAR(sampleLinear(level, Wrap::ClampToEdge, Wrap::ClampToEdge, s, 0.5).x(), clamp[x], 1e-12) << x;
  }
}

TEST(SampleLinear, BlendsTheTwoByTwoTexelsBilinearly) {
  // 2 x 2 texels t00 = 1, t10 = 2, t01 = 4, t11 = 8. At s = 5/8, t = 3/8: u = 3/4, v = 1/4,
  // i0 = j0 = 0, a = 3/4, b = 1/4: (1/4)(3/4) 1 + (3/4)(3/4) 2 + (1/4)(1/4) 4 + (3/4)(1/4) 8 = 49/16.
  const TexelLevel level = redLevel(2, 2, {1, 2, 4, 8});
  EXPECT_DOUBLE_EQ(sampleLinear(level, Wrap::ClampToEdge, Wrap::ClampToEdge, 0.625, 0.375).x(), 49.0 / 16);
  // The centre of texel (1, 0) is that texel alone.
  EXPECT_DOUBLE_EQ(sampleLinear(level, Wrap::Repeat, Wrap::Repeat, 0.75, 0.25).x(), 2.0);
}

TEST(TextureFromImage, PutsTheTopRowAtTOneAndSpreadsTheChannels) {
  Image grey(2, 2, 1);
  grey.at(0, 0, 0) = 0.25f;  // top left: texel (0, 1)
  grey.at(1, 1, 0) = 0.75f;  // bottom right: texel (1, 0)
  const Texture fromGrey = Texture::fromImage(grey, false);
  EXPECT_EQ(fromGrey.level(0).at(0, 1), Rgba(0.25f, 0.25f, 0.25f, 1.0f));
  EXPECT_EQ(fromGrey.level(0).at(1, 0), Rgba(0.75f, 0.75f, 0.75f, 1.0f));
  EXPECT_EQ(fromGrey.level(0).at(0, 0), Rgba(0.0f, 0.0f, 0.0f, 1.0f));

  Image greyAlpha(1, 1, 2);
  greyAlpha.pixels = {0.5f, 0.25f};
  EXPECT_EQ(Texture::fromImage(greyAlpha, false).level(0).at(0, 0), Rgba(0.5f, 0.5f, 0.5f, 0.25f));
  Image rgb(1, 1, 3);
  rgb.pixels = {0.1f, 0.2f, 0.3f};
  EXPECT_EQ(Texture::fromImage(rgb, false).level(0).at(0, 0), Rgba(0.1f, 0.2f, 0.3f, 1.0f));
  Image rgba(1, 1, 4);
  rgba.pixels = {0.1f, 0.2f, 0.3f, 0.4f};
  EXPECT_EQ(Texture::fromImage(rgba, true).level(0).at(0, 0), Rgba(0.1f, 0.2f, 0.3f, 0.4f));

  EXPECT_THROW(Texture::fromImage(Image(2, 2, 5), false), UsageError);
  EXPECT_THROW(Texture::fromImage(Image(0, 2, 3), false), UsageError);
}

TEST(Texture, RejectsAnEmptyOrInconsistentBaseLevel) {
  EXPECT_THROW(Texture(redLevel(0, 1, {}), false), UsageError);
  EXPECT_THROW(Texture(redLevel(2, 2, {1, 2, 3}), false), UsageError);
}

TEST(BuildMipmaps, HalvesEachSideDownToOneByOne) {
  Texture wide(redLevel(8, 4, std::vector<float>(32, 0.5f)), false);
  wide.buildMipmaps();
  ASSERT_EQ(wide.levelCount(), 4);  // 8x4, 4x2, 2x1, 1x1
  EXPECT_EQ(wide.level(1).width, 4);
  EXPECT_EQ(wide.level(1).height, 2);
  EXPECT_EQ(wide.level(2).width, 2);
  EXPECT_EQ(wide.level(2).height, 1);
  EXPECT_EQ(wide.level(3).width, 1);
  EXPECT_EQ(wide.level(3).height, 1);

  Texture odd(redLevel(5, 3, std::vector<float>(15, 0.5f)), false);
  odd.buildMipmaps();
  ASSERT_EQ(odd.levelCount(), 3);  // 5x3, 2x1, 1x1
  EXPECT_EQ(odd.level(1).width, 2);
  EXPECT_EQ(odd.level(1).height, 1);
  EXPECT_EQ(odd.level(2).width, 1);
  EXPECT_EQ(odd.level(2).height, 1);
  EXPECT_EQ(odd.level(2).at(0, 0).x(), 0.5f);  // a constant stays constant

  Texture single(redLevel(1, 1, {0.5f}), false);
  single.buildMipmaps();
  EXPECT_EQ(single.levelCount(), 1);
}

TEST(BuildMipmaps, AveragesTwoByTwoBlocksOnEvenSizes) {
  // 4 x 2: row j = 0 is 1 2 3 4, row j = 1 is 5 6 7 8.
  Texture texture(redLevel(4, 2, {1, 2, 3, 4, 5, 6, 7, 8}), false);
  texture.buildMipmaps();
  EXPECT_EQ(texture.level(1).at(0, 0).x(), 3.5f);  // (1 + 2 + 5 + 6) / 4
  EXPECT_EQ(texture.level(1).at(1, 0).x(), 5.5f);  // (3 + 4 + 7 + 8) / 4
  EXPECT_EQ(texture.level(2).at(0, 0).x(), 4.5f);
  EXPECT_EQ(texture.level(1).at(0, 0).w(), 1.0f);
}

TEST(BuildMipmaps, WeighsTheTexelsOfAnOddSizeByTheAreaTheyShare) {
  Texture three(redLevel(3, 1, {1, 2, 6}), false);
  three.buildMipmaps();
  ASSERT_EQ(three.levelCount(), 2);
  EXPECT_FLOAT_EQ(three.level(1).at(0, 0).x(), 3.0f);  // (1 + 2 + 6) / 3

  // 5 -> 2: coarse texel 0 covers fine [0, 2.5): (t0 + t1 + t2 / 2) / 2.5, texel 1 (t2 / 2 + t3 + t4) / 2.5.
  Texture five(redLevel(5, 1, {1, 2, 4, 8, 16}), false);
  five.buildMipmaps();
  EXPECT_FLOAT_EQ(five.level(1).at(0, 0).x(), float((1 + 2 + 2) / 2.5));
  EXPECT_FLOAT_EQ(five.level(1).at(1, 0).x(), float((2 + 8 + 16) / 2.5));
  EXPECT_FLOAT_EQ(five.level(2).at(0, 0).x(), float((1 + 2 + 2 + 2 + 8 + 16) / 5.0));

  // 2 x 3: the axes weigh separately; t's texel of height 3 has weights 1/3 each.
  Texture tall(redLevel(2, 3, {0, 2, 4, 6, 8, 10}), false);
  tall.buildMipmaps();
  ASSERT_EQ(tall.levelCount(), 2);
  EXPECT_FLOAT_EQ(tall.level(1).at(0, 0).x(), 5.0f);  // the mean of all six
}

TEST(BuildMipmaps, RoundsEachEightBitLevelFromThePreviousRoundedOne) {
  const float one = 1.0f / 255.0f;
  Texture pair(redLevel(2, 1, {0.0f, one}), true);
  pair.buildMipmaps();
  EXPECT_EQ(pair.level(1).at(0, 0).x(), one);  // the mean 0.5 / 255 rounds half away from zero to 1 / 255

  Texture quarter(redLevel(2, 2, {0.0f, one, 0.0f, 0.0f}), true);
  quarter.buildMipmaps();
  EXPECT_EQ(quarter.level(1).at(0, 0).x(), 0.0f);  // 0.25 / 255 rounds to 0

  // Bytes 0 1 0 0: level 1 is round(0.5) = 1 and 0, level 2 round(0.5) = 1 from those, where the
  // exact mean of the base, 0.25, would round to 0.
  Texture chained(redLevel(4, 1, {0.0f, one, 0.0f, 0.0f}), true);
  chained.buildMipmaps();
  EXPECT_EQ(chained.level(1).at(0, 0).x(), one);
  EXPECT_EQ(chained.level(1).at(1, 0).x(), 0.0f);
  EXPECT_EQ(chained.level(2).at(0, 0).x(), one);
  EXPECT_EQ(chained.level(2).at(0, 0).w(), 1.0f);

  Texture unrounded(redLevel(4, 1, {0.0f, one, 0.0f, 0.0f}), false);
  unrounded.buildMipmaps();
  EXPECT_FLOAT_EQ(unrounded.level(2).at(0, 0).x(), 0.25f * one);
}

TEST(BuildMipmaps, DoesNothingWhenTheLevelsExist) {
  Texture texture = impulseTexture();
  const float before = texture.level(1).at(0, 0).x();
  texture.buildMipmaps();
  EXPECT_EQ(texture.levelCount(), 4);
  EXPECT_EQ(texture.level(1).at(0, 0).x(), before);
}

TEST(LevelOfDetail, IsTheBinaryLogarithmOfTexelsPerPixel) {
  // 256 texels, ds/dx = dt/dy = 1/64: 4 texels per pixel, lambda = log2 4 = 2.
  EXPECT_EQ(levelOfDetail(256, 256, Vec2(1.0 / 64, 0.0), Vec2(0.0, 1.0 / 64)), 2.0);
  // ds/dx = 3/256, dt/dx = 4/256: a 3-4-5 footprint of 5 texels.
  EXPECT_DOUBLE_EQ(levelOfDetail(256, 256, Vec2(3.0 / 256, 4.0 / 256), Vec2(0.0, 0.0)), std::log2(5.0));
  // Magnification: half a texel per pixel.
  EXPECT_EQ(levelOfDetail(256, 256, Vec2(1.0 / 512, 0.0), Vec2(0.0, 1.0 / 512)), -1.0);
}

TEST(LevelOfDetail, TakesTheLongerOfTheTwoFootprintAxes) {
  EXPECT_EQ(levelOfDetail(256, 256, Vec2(1.0 / 64, 0.0), Vec2(0.0, 1.0 / 16)), 4.0);
  EXPECT_EQ(levelOfDetail(256, 256, Vec2(1.0 / 16, 0.0), Vec2(0.0, 1.0 / 64)), 4.0);
  // Width and height scale their own coordinate: 64 x 16 with ds/dx = dt/dy = 1/16 gives 4 and 1.
  EXPECT_EQ(levelOfDetail(64, 16, Vec2(1.0 / 16, 0.0), Vec2(0.0, 1.0 / 16)), 2.0);
}

// levelOfDetail computes only the longer axis's hypot when the squared lengths tell it apart: the
// result must be bit for bit GL's formula with both, also for axes within an ulp of each other
// and for squares that overflow or underflow.
TEST(LevelOfDetail, IsBitForBitTheFormulaWithBothAxes) {
  const auto formula = [](int w, int h, const Vec2& dx, const Vec2& dy) {
    return std::log2(std::max(std::hypot(dx.x() * w, dx.y() * h), std::hypot(dy.x() * w, dy.y() * h)));
  };
  std::mt19937_64 random(26);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-600, 600);
  for (int i = 0; i < 200000; ++i) {
    const double scale = std::ldexp(1.0, i % 4 == 0 ? exponent(random) : exponent(random) / 40);
    Vec2 dx(unit(random) * scale, unit(random) * scale), dy(unit(random) * scale, unit(random) * scale);
    switch (i % 5) {
      case 1: dy = Vec2(dx.y(), dx.x()); break;                                  // equal lengths
      case 2: dy = Vec2(std::nextafter(dx.x(), 2.0 * dx.x()), dx.y()); break;    // an ulp apart
      case 3: dy = dx * (1.0 + 1e-9 * unit(random)); break;                       // about the margin
      default: break;
    }
    const int w = 1 << (i % 12), h = 1 << ((i / 12) % 12);
    const double expected = formula(w, h, dx, dy), actual = levelOfDetail(w, h, dx, dy);
    ASSERT_TRUE(actual == expected || (std::isnan(actual) && std::isnan(expected)))
        << dx.transpose() << " / " << dy.transpose() << ": " << actual << " != " << expected;
  }
  EXPECT_EQ(levelOfDetail(1, 1, Vec2(1e200, 0.0), Vec2(0.0, 1e199)), std::log2(1e200));  // squares overflow
  EXPECT_EQ(levelOfDetail(1, 1, Vec2(1e-200, 0.0), Vec2(0.0, 1e-201)), std::log2(1e-200));  // squares underflow
}

TEST(LevelOfDetail, IsMinusInfinityForNoFootprintAndPlusInfinityForAnUndefinedOne) {
  EXPECT_EQ(levelOfDetail(256, 256, Vec2(0.0, 0.0), Vec2(0.0, 0.0)), -kInf);
  EXPECT_EQ(levelOfDetail(256, 256, Vec2(kInf, 0.0), Vec2(0.0, 0.0)), kInf);
  EXPECT_EQ(levelOfDetail(256, 256, Vec2(kNaN, 0.0), Vec2(0.0, 0.0)), kInf);
  EXPECT_EQ(levelOfDetail(256, 256, Vec2(0.0, 0.0), Vec2(0.0, kNaN)), kInf);
}

TEST(Sample, NearestMipmapNearestRoundsLambdaToTheNearestLevel) {
  const Texture texture = impulseTexture();  // q = 3; texel (0, 0) of level d is 4^-d
  const SamplerState state = sampler(Filter::NearestMipmapNearest, Filter::Nearest);
  const auto level = [&](double lambda) { return sample(texture, state, 0.0, 0.0, lambda).x(); };
  EXPECT_EQ(level(0.4), 1.0);         // lambda <= 1/2: d = 0
  EXPECT_EQ(level(0.6), 0.25);        // ceil(1.1) - 1 = 1
  EXPECT_EQ(level(1.49), 0.25);       // ceil(1.99) - 1 = 1
  EXPECT_EQ(level(1.51), 1.0 / 16);   // ceil(2.01) - 1 = 2
  EXPECT_EQ(level(3.4), 1.0 / 64);    // ceil(3.9) - 1 = 3
  EXPECT_EQ(level(3.6), 1.0 / 64);    // beyond q + 1/2: q
  EXPECT_EQ(level(1e9), 1.0 / 64);
  EXPECT_EQ(level(kInf), 1.0 / 64);
  // Within level 1 (4 x 4) s = t = 0.2 is texel floor(0.8) = 0, not floor(8 0.2) = 1 of the base.
  EXPECT_EQ(sample(texture, state, 0.2, 0.2, 1.0).x(), 0.25);
}

TEST(Sample, LinearMipmapLinearBlendsTheTwoLevelsAroundLambda) {
  const Texture texture = impulseTexture();
  const SamplerState state = sampler(Filter::LinearMipmapLinear, Filter::Linear);
  // At s = t = 0 under CLAMP_TO_EDGE LINEAR sees only texel (0, 0) of a level.
  // lambda = 1.25: d1 = 1, d2 = 2, (3/4)(1/4) + (1/4)(1/16) = 13/64.
  EXPECT_DOUBLE_EQ(sample(texture, state, 0.0, 0.0, 1.25).x(), 13.0 / 64);
  EXPECT_DOUBLE_EQ(sample(texture, state, 0.0, 0.0, 2.0).x(), 1.0 / 16);  // frac 0: level 2 alone
  EXPECT_DOUBLE_EQ(sample(texture, state, 0.0, 0.0, 3.0).x(), 1.0 / 64);  // lambda >= q: level q
  EXPECT_DOUBLE_EQ(sample(texture, state, 0.0, 0.0, 7.5).x(), 1.0 / 64);
  // NEAREST_MIPMAP_LINEAR at lambda 0.5: (1/2) 1 + (1/2)(1/4) = 5/8.
  EXPECT_DOUBLE_EQ(sample(texture, sampler(Filter::NearestMipmapLinear, Filter::Nearest), 0.0, 0.0, 0.5).x(), 0.625);
}

TEST(Sample, MagnifiesWithLevelZeroAndTheMagnificationFilter) {
  const Texture texture = impulseTexture();
  // s = t = 3/32: u = v = 3/4 - 1/2 = 1/4, LINEAR gives (3/4)(3/4) 1 = 9/16; NEAREST texel (0, 0): 1.
  const double s = 3.0 / 32;
  EXPECT_DOUBLE_EQ(sample(texture, sampler(Filter::LinearMipmapLinear, Filter::Nearest), s, s, -1.0).x(), 1.0);
  EXPECT_DOUBLE_EQ(sample(texture, sampler(Filter::NearestMipmapNearest, Filter::Linear), s, s, 0.0).x(), 9.0 / 16);
  EXPECT_DOUBLE_EQ(sample(texture, sampler(Filter::Nearest, Filter::Linear), s, s, -kInf).x(), 9.0 / 16);
}

TEST(Sample, MovesTheCrossoverToOneHalfForLinearMagnificationWithNearestMipmaps) {
  const Texture texture = impulseTexture();
  const double s = 3.0 / 32;  // LINEAR on level 0: 9/16, NEAREST: 1
  for (Filter minFilter : {Filter::NearestMipmapNearest, Filter::NearestMipmapLinear}) {
    const SamplerState state = sampler(minFilter, Filter::Linear);
    EXPECT_DOUBLE_EQ(sample(texture, state, s, s, 0.4).x(), 9.0 / 16);  // c = 1/2: still magnified
    EXPECT_DOUBLE_EQ(sample(texture, state, s, s, 0.5).x(), 9.0 / 16);
  }
  // Just past c: NEAREST_MIPMAP_NEAREST takes level ceil(1.01) - 1 = 1, texel floor(3/8) = 0: 1/4.
  EXPECT_DOUBLE_EQ(sample(texture, sampler(Filter::NearestMipmapNearest, Filter::Linear), s, s, 0.51).x(), 0.25);
  // With c = 0 lambda 0.4 minifies: NEAREST_MIPMAP_NEAREST with a NEAREST magnification filter
  // takes level 0 with NEAREST.
  EXPECT_DOUBLE_EQ(sample(texture, sampler(Filter::NearestMipmapNearest, Filter::Nearest), s, s, 0.4).x(), 1.0);
  // LINEAR_MIPMAP_LINEAR keeps c = 0: lambda 0.4 blends levels 0 and 1 with LINEAR. Level 1
  // (4 x 4) at s = 3/32: u = 3/8 - 1/2 = -1/8, clamped texel 0 with weight 1: 1/4 in each axis.
  EXPECT_DOUBLE_EQ(sample(texture, sampler(Filter::LinearMipmapLinear, Filter::Linear), s, s, 0.4).x(),
                   0.6 * 9.0 / 16 + 0.4 * 0.25);
}

TEST(Sample, MinifiesWithoutMipmapsOnLevelZero) {
  Texture texture(redLevel(4, 1, {8, 0, 0, 0}), false);
  EXPECT_DOUBLE_EQ(sample(texture, sampler(Filter::Nearest, Filter::Nearest), 0.3, 0.5, 5.0).x(), 0.0);
  EXPECT_DOUBLE_EQ(sample(texture, sampler(Filter::Linear, Filter::Linear), 0.25, 0.5, 5.0).x(), 4.0);
}

TEST(Sample, GivesTheFirstTexelForNonFiniteCoordinates) {
  const Texture texture = impulseTexture();
  const SamplerState state = sampler(Filter::LinearMipmapLinear, Filter::Linear, Wrap::Repeat);
  EXPECT_EQ(sample(texture, state, kNaN, 0.9, 2.0).x(), 1.0);
  EXPECT_EQ(sample(texture, state, 0.9, kInf, -1.0).x(), 1.0);
  EXPECT_EQ(sample(texture, state, 0.9, 0.9, -1.0).x(), 0.0);
}

TEST(SampleDeathTest, AMipmapFilterWithoutMipmapsIsAProgrammerError) {
  const Texture texture(redLevel(4, 4, std::vector<float>(16, 0.5f)), false);
  EXPECT_DEATH(sample(texture, sampler(Filter::LinearMipmapLinear, Filter::Linear), 0.5, 0.5, 2.0), "check failed");
}

TEST(SamplerFor, PairsTheNamedFilterWithItsMagnificationFilter) {
  EXPECT_EQ(samplerFor(Filter::Nearest, Wrap::Repeat).magFilter, Filter::Nearest);
  EXPECT_EQ(samplerFor(Filter::NearestMipmapNearest, Wrap::Repeat).magFilter, Filter::Nearest);
  EXPECT_EQ(samplerFor(Filter::NearestMipmapLinear, Wrap::Repeat).magFilter, Filter::Nearest);
  EXPECT_EQ(samplerFor(Filter::Linear, Wrap::Repeat).magFilter, Filter::Linear);
  EXPECT_EQ(samplerFor(Filter::LinearMipmapNearest, Wrap::Repeat).magFilter, Filter::Linear);
  const SamplerState state = samplerFor(Filter::LinearMipmapLinear, Wrap::MirroredRepeat);
  EXPECT_EQ(state.minFilter, Filter::LinearMipmapLinear);
  EXPECT_EQ(state.magFilter, Filter::Linear);
  EXPECT_EQ(state.wrapS, Wrap::MirroredRepeat);
  EXPECT_EQ(state.wrapT, Wrap::MirroredRepeat);
}

TEST(NeedsMipmaps, IsTrueForTheFourMipmapFilters) {
  EXPECT_FALSE(needsMipmaps(Filter::Nearest));
  EXPECT_FALSE(needsMipmaps(Filter::Linear));
  EXPECT_TRUE(needsMipmaps(Filter::NearestMipmapNearest));
  EXPECT_TRUE(needsMipmaps(Filter::LinearMipmapNearest));
  EXPECT_TRUE(needsMipmaps(Filter::NearestMipmapLinear));
  EXPECT_TRUE(needsMipmaps(Filter::LinearMipmapLinear));
}

TEST(Sample, APowerOfTwoRepeatTextureBlendsItsLevelsExactlyAsSampleLinearDoes) {
  // sample() wraps such a texture by masks; the result must be GL's blend of the per-level taps.
  TexelLevel base;
  base.width = 16, base.height = 8;
  for (int j = 0; j < base.height; ++j)
    for (int i = 0; i < base.width; ++i)
      base.texels.emplace_back(float(i) / 16.0f, float(j) / 7.0f, float((i * 7 + j * 3) % 11) / 10.0f, 1.0f);
  Texture texture(std::move(base), false);
  texture.buildMipmaps();
  const SamplerState sampler = samplerFor(Filter::LinearMipmapLinear, Wrap::Repeat);
  std::mt19937_64 random(26);
  std::uniform_real_distribution<double> coordinate(-40.0, 40.0), lambda(-1.0, 5.0);
  for (int n = 0; n < 20000; ++n) {
    const double s = coordinate(random), t = coordinate(random), l = lambda(random);
    const LevelChoice choice = chooseLevels(sampler, texture.levelCount(), l);
    Vec4 expected = Vec4::Zero();
    for (int k = 0; k < choice.count; ++k)
      expected += choice.weight[std::size_t(k)] *
                  sampleLinear(texture.level(choice.level[std::size_t(k)]), Wrap::Repeat, Wrap::Repeat, s, t);
    const Vec4 actual = sample(texture, sampler, s, t, l);
    ASSERT_EQ(std::memcmp(actual.data(), expected.data(), sizeof(double) * 4), 0) << s << " " << t << " " << l;
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::render
