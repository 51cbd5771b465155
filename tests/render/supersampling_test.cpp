#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/gl_matrices.h"
#include "render/procedural.h"
#include "render/quad_fixture.h"
#include "render/renderer.h"

namespace uvtk::render {
namespace {
namespace UVTK_TEST_FILE {

Texture uniformTexture(const Rgba& colour) {
  Texture texture(TexelLevel{1, 1, {colour}}, false);
  texture.buildMipmaps();
  return texture;
}

// A plane tilted 45 degrees about x under a perspective camera, filling the view, so that the
// texture coordinates, their derivatives and the level of detail vary over the image.
struct TiltedPlane {
  Vec3 a = Vec3(40, 0, 0), b = Vec3(0, 40 * std::cos(kPi / 4), -40 * std::sin(kPi / 4));
  Quad quad{-0.5 * (a + b), a, b};

  RenderOptions options(const Texture& texture) const {
    RenderOptions o;
    o.camera.width = 33, o.camera.height = 27;
    o.camera.viewFromWorld = lookAt(Vec3(0, 0, 3), Vec3::Zero(), Vec3::UnitY());
    o.camera.clipFromView = perspective(60.0, 33.0 / 27.0, 0.1, 100.0);
    o.texture = &texture;
    o.sampler = samplerFor(Filter::LinearMipmapLinear, Wrap::Repeat);
    o.env = EnvMode::Modulate;
    o.aovs = true;
    return o;
  }
};

TEST(Supersampling, OneSamplePerPixelIsTheDefaultRenderingBitForBit) {
  const TiltedPlane s;
  Texture texture = checkerTexture(64, 4);
  texture.buildMipmaps();
  const RenderOptions defaults = s.options(texture);
  RenderOptions one = defaults;
  one.samplesPerPixel = 1;
  const Rendering expected = render(s.quad.mesh, s.quad.texcoords, defaults);
  const Rendering actual = render(s.quad.mesh, s.quad.texcoords, one);
  EXPECT_EQ(actual.colour.pixels, expected.colour.pixels);
  EXPECT_EQ(actual.aovs.pixels, expected.aovs.pixels);
  EXPECT_EQ(actual.coveredPixels, expected.coveredPixels);
}

TEST(Supersampling, APixelHalfCoveredByAnEdgeIsTheMeanOfQuadAndBackground) {
  // 4 x 4 pixels; the quad spans window x in [-4, 2.5] (NDC [-3, 0.25]) and the full height. With
  // 2 x 2 samples at x + 0.25 and x + 0.75, pixel column 2 has its left samples (x = 2.25) covered
  // and its right ones (x = 2.75) not; no sample lies on the edge.
  const Quad quad(Vec3(-3, -2, 0), Vec3(3.25, 0, 0), Vec3(0, 4, 0));
  const Rgba quadColour(1.0f, 0.6f, 0.2f, 1.0f);
  const Texture texture = uniformTexture(quadColour);
  RenderOptions o;
  o.camera.width = o.camera.height = 4;
  o.camera.clipFromView = orthographic(-1, 1, -1, 1, -1, 1);
  o.texture = &texture;
  o.background = Vec3(0.0, 0.2, 1.0);
  o.samplesPerPixel = 4;
  o.aovs = true;
  const Rendering r = render(quad.mesh, quad.texcoords, o);
  ASSERT_EQ(r.colour.width, 4);
  ASSERT_EQ(r.colour.height, 4);
  for (int row = 0; row < 4; ++row)
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(r.colour.at(1, row, c), quadColour[c]);
      EXPECT_NEAR(r.colour.at(2, row, c), 0.5 * (quadColour[c] + o.background[c]), 1.0 / 255.0) << row << ", " << c;
      EXPECT_EQ(r.colour.at(3, row, c), float(o.background[c]));
    }
  EXPECT_NEAR(r.colour.at(2, 0, 2), 0.6, 1e-6);  // (0.2 + 1) / 2: really the mean, not either side
  EXPECT_EQ(r.coveredPixels, 12u);               // columns 0 to 2
  // The AOVs are those of sample (1, 1) of each block, at x + 0.75: uncovered in column 2.
  EXPECT_EQ(r.aovs.at(2, 0, 3), -1.0f);
  EXPECT_GE(r.aovs.at(1, 0, 3), 0.0f);
}

TEST(Supersampling, AUniformlyColouredCoveringQuadLooksTheSameWithSixteenSamples) {
  const TiltedPlane s;
  const Texture texture = uniformTexture(Rgba(0.3f, 0.7f, 0.9f, 1.0f));
  RenderOptions o = s.options(texture);
  o.env = EnvMode::Replace;  // lighting would vary between the samples
  const Rendering one = render(s.quad.mesh, s.quad.texcoords, o);
  o.samplesPerPixel = 16;
  const Rendering sixteen = render(s.quad.mesh, s.quad.texcoords, o);
  ASSERT_EQ(one.coveredPixels, 33u * 27u);
  EXPECT_EQ(sixteen.coveredPixels, one.coveredPixels);
  ASSERT_EQ(sixteen.colour.width, one.colour.width);
  ASSERT_EQ(sixteen.colour.height, one.colour.height);
  EXPECT_EQ(sixteen.colour.pixels, one.colour.pixels);
}

TEST(Supersampling, WithAnOddGridTheAovsAreThoseOfThePixelCentreAtTheSamplesLevelOfDetail) {
  const TiltedPlane s;
  Texture texture = checkerTexture(256, 8);
  texture.buildMipmaps();
  RenderOptions o = s.options(texture);
  const Rendering one = render(s.quad.mesh, s.quad.texcoords, o);
  o.samplesPerPixel = 9;
  const Rendering nine = render(s.quad.mesh, s.quad.texcoords, o);
  ASSERT_EQ(nine.aovs.width, one.aovs.width);
  ASSERT_EQ(nine.aovs.channelNames, one.aovs.channelNames);
  for (int row = 0; row < one.aovs.height; ++row)
    for (int x = 0; x < one.aovs.width; ++x) {
      EXPECT_NEAR(nine.aovs.at(x, row, 0), one.aovs.at(x, row, 0), 1e-5);
      EXPECT_NEAR(nine.aovs.at(x, row, 1), one.aovs.at(x, row, 1), 1e-5);
      EXPECT_NEAR(nine.aovs.at(x, row, 2), one.aovs.at(x, row, 2), 1e-6);
      EXPECT_NEAR(nine.aovs.at(x, row, 4), one.aovs.at(x, row, 4) - std::log2(3.0), 1e-4);
    }
}

TEST(Supersampling, OnlySquaresFrom1To256AreAccepted) {
  const Quad quad(Vec3(-1, -1, 0), Vec3(2, 0, 0), Vec3(0, 2, 0));
  const Texture texture = uniformTexture(Rgba(1, 1, 1, 1));
  RenderOptions o;
  o.camera.width = o.camera.height = 4;
  o.camera.clipFromView = orthographic(-1, 1, -1, 1, -1, 1);
  o.texture = &texture;
  for (int spp : {0, 2, 5, 300, -4, 255, 257}) {
    o.samplesPerPixel = spp;
    try {
      render(quad.mesh, quad.texcoords, o);
      ADD_FAILURE() << spp << " was accepted";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("found " + std::to_string(spp)), std::string::npos) << e.what();
    }
  }
  for (int spp : {1, 4, 9, 256}) {
    o.samplesPerPixel = spp;
    EXPECT_EQ(render(quad.mesh, quad.texcoords, o).coveredPixels, 16u) << spp;
  }
  // The supersampled frame must fit the rasterizer.
  o.camera.width = 2048;
  o.samplesPerPixel = 81;
  EXPECT_THROW(render(quad.mesh, quad.texcoords, o), UsageError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::render
