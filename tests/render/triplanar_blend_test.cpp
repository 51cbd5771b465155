// The renderer's blend of three lookups per pixel (PixelMapping::blendAt), as Unity's Triplanar
// node: each lookup with its own derivatives and level of detail, the weights at the pixel.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/error.h"
#include "core/gl_matrices.h"
#include "doubles.h"
#include "render/memory.h"
#include "render/quad_fixture.h"
#include "render/renderer.h"

namespace uvtk::render {
namespace {
namespace UVTK_TEST_FILE {

Texture randomTexture(int size) {
  std::mt19937 random(17);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  TexelLevel level{size, size, {}};
  for (int k = 0; k < size * size; ++k) level.texels.push_back(Rgba(unit(random), unit(random), unit(random), 1.0f));
  return Texture(level, false);
}

Texture solid(const Rgba& colour) { return Texture(TexelLevel{1, 1, {colour}}, false); }

// Unity's Triplanar node: uv = position * tile; x reads uv.zy, y uv.xz, z uv.xy; the weights
// |n|^blend, normalised to sum 1.
TexcoordBlend unityTriplanar(const Vec3& p, const Vec3& n, double tile, double blend) {
  TexcoordBlend out;
  const Vec3 uv = p * tile;
  out.st = {Vec2(uv.z(), uv.y()), Vec2(uv.x(), uv.z()), Vec2(uv.x(), uv.y())};
  const Vec3 w = n.cwiseAbs().array().pow(blend);
  out.weights = w / w.sum();
  return out;
}

PixelMapping blendMapping(std::function<TexcoordBlend(const Vec3&, const Vec3&, std::int32_t)> blendAt) {
  PixelMapping m;
  m.needsNormal = true;
  m.blendAt = std::move(blendAt);
  return m;
}

// A flat quad z = c x + d y over [x0, x0 + size] x [y0, y0 + size], facing the camera, under an
// orthographic camera looking down -z that shows [-1, 1]^2 on n x n pixels.
struct Plane {
  double c, d;
  int n;
  Quad quad;
  Plane(double c_, double d_, double x0, double y0, double size, int n_)
      : c(c_), d(d_), n(n_),
        quad(Vec3(x0, y0, c_ * x0 + d_ * y0), Vec3(size, 0, c_ * size), Vec3(0, size, d_ * size)) {}

  Vec3 normal() const { return Vec3(-c, -d, 1).normalized(); }
  RenderOptions options(const Texture& texture) const {
    RenderOptions o;
    o.camera.width = o.camera.height = n;
    o.camera.clipFromView = orthographic(-1, 1, -1, 1, -10, 10);
    o.texture = &texture;
    o.aovs = true;
    return o;
  }
  // The point of the plane seen at the centre of pixel (x, row).
  Vec3 pointAt(int x, int row) const {
    const double px = 2 * (x + 0.5) / n - 1, py = 2 * (n - row - 0.5) / n - 1;
    return Vec3(px, py, c * px + d * py);
  }
};

// Normal (1, 2, 3) / sqrt(14): all three weights positive.
Plane tilted() { return Plane(-1.0 / 3, -2.0 / 3, -0.6, -0.6, 1.2, 96); }

TEST(TriplanarBlend, EveryPixelIsTheWeightedSumOfItsThreeLookups) {
  const Plane plane = tilted();
  const Texture texture = randomTexture(64);
  constexpr double kTile = 1.5, kBlend = 1.0;
  TexcoordSource source;
  source.pixelMapping = blendMapping([&](const Vec3& p, const Vec3& n, std::int32_t) {
    return unityTriplanar(p, n, kTile, kBlend);
  });
  RenderOptions o = plane.options(texture);
  o.sampler = samplerFor(Filter::Linear, Wrap::Repeat);
  const Rendering r = render(plane.quad.mesh, source, o);
  ASSERT_GT(r.coveredPixels, 2000u);
  std::size_t checked = 0;
  for (int row = 0; row < plane.n; ++row)
    for (int x = 0; x < plane.n; ++x) {
      if (r.aovs.at(x, row, 3) < 0) continue;
      const TexcoordBlend expected = unityTriplanar(plane.pointAt(x, row), plane.normal(), kTile, kBlend);
      ASSERT_NEAR(expected.weights.sum(), 1.0, 1e-12);
      ASSERT_GT(expected.weights.minCoeff(), 0.1);
      Vec4 colour = Vec4::Zero();
      for (int i = 0; i < 3; ++i) {
        const Vec2& st = expected.st[std::size_t(i)];
        colour += expected.weights[i] * sample(texture, o.sampler, st.x(), st.y(), 0.0);  // LINEAR either way
      }
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(r.colour.at(x, row, c), colour[c], 1e-6) << x << ", " << row;
      // The weights (1, 2, 3) / 6: u and v are the z lookup's (x, y) * tile.
      ASSERT_NEAR(r.aovs.at(x, row, 0), expected.st[2].x(), 1e-6);
      ASSERT_NEAR(r.aovs.at(x, row, 1), expected.st[2].y(), 1e-6);
      ++checked;
    }
  EXPECT_EQ(checked, r.coveredPixels);
}

TEST(TriplanarBlend, AxisTexturesShowTheWeightsAndAnUnsetOneReadsTheBoundTexture) {
  const Plane plane = tilted();
  const Texture red = solid(Rgba(1, 0, 0, 1)), green = solid(Rgba(0, 1, 0, 1)), blue = solid(Rgba(0, 0, 1, 1));
  TexcoordSource source;
  source.pixelMapping = blendMapping([](const Vec3& p, const Vec3& n, std::int32_t) {
    return unityTriplanar(p, n, 1.0, 2.0);
  });
  RenderOptions o = plane.options(green);  // the y lookup falls back to it
  o.axisTextures = {&red, nullptr, &blue};
  const Rendering r = render(plane.quad.mesh, source, o);
  ASSERT_GT(r.coveredPixels, 2000u);
  // |n|^2 for n = (1, 2, 3) / sqrt(14): (1, 4, 9) / 14, summing to 1.
  const Vec3 weights = Vec3(1, 4, 9) / 14.0;
  for (int row = 0; row < plane.n; ++row)
    for (int x = 0; x < plane.n; ++x) {
      if (r.aovs.at(x, row, 3) < 0) continue;
      double sum = 0.0;
      for (int c = 0; c < 3; ++c) {
        ASSERT_NEAR(r.colour.at(x, row, c), weights[c], 1e-6) << x << ", " << row;
        sum += r.colour.at(x, row, c);
      }
      ASSERT_NEAR(sum, 1.0, 1e-6);
    }
}

TEST(TriplanarBlend, EachLookupHasTheLevelOfDetailOfItsOwnProjection) {
  // The plane z = 4x + 0.5y; 64 pixels over [-1, 1], so a pixel spans 1/32 unit; 64 texels a unit.
  // z lookup (x, y): 2 texels a pixel both ways, lambda 1. x lookup (z, y): d/dx = (4, 0) / 32,
  // d/dy = (0.5, 1) / 32, in texels (8, 0) and (1, 2): lambda 3. y lookup (x, z): (2, 8) and
  // (0, 1): lambda log2(sqrt(68)).
  const Plane plane(4.0, 0.5, -0.5, -0.5, 1.0, 64);
  Texture texture = randomTexture(64);
  texture.buildMipmaps();
  const double lambdas[3] = {3.0, 0.5 * std::log2(68.0), 1.0};
  RenderOptions o = plane.options(texture);
  o.sampler = samplerFor(Filter::LinearMipmapLinear, Wrap::Repeat);
  const auto renderWith = [&](const Vec3& weights) {
    TexcoordSource source;
    source.pixelMapping = blendMapping([weights](const Vec3& p, const Vec3& n, std::int32_t) {
      TexcoordBlend b = unityTriplanar(p, n, 1.0, 1.0);
      b.weights = weights;
      return b;
    });
    return render(plane.quad.mesh, source, o);
  };
  for (int axis = 0; axis < 3; ++axis) {
    const Rendering r = renderWith(Vec3::Unit(axis));
    ASSERT_GT(r.coveredPixels, 900u);
    for (int row = 0; row < plane.n; ++row)
      for (int x = 0; x < plane.n; ++x) {
        if (r.aovs.at(x, row, 3) >= 0) {
          ASSERT_NEAR(r.aovs.at(x, row, 4), lambdas[axis], 1e-6) << axis;
        }
      }
  }
  // Half x, half z: each lookup at its own level, the AOVs of the first of the tied.
  const Rendering r = renderWith(Vec3(0.5, 0, 0.5));
  std::size_t checked = 0;
  for (int row = 0; row < plane.n; ++row)
    for (int x = 0; x < plane.n; ++x) {
      if (r.aovs.at(x, row, 3) < 0) continue;
      const TexcoordBlend b = unityTriplanar(plane.pointAt(x, row), plane.normal(), 1.0, 1.0);
      const Vec4 expected = 0.5 * sample(texture, o.sampler, b.st[0].x(), b.st[0].y(), lambdas[0]) +
                            0.5 * sample(texture, o.sampler, b.st[2].x(), b.st[2].y(), lambdas[2]);
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(r.colour.at(x, row, c), expected[c], 1e-6) << x << ", " << row;
      ASSERT_NEAR(r.aovs.at(x, row, 0), b.st[0].x(), 1e-6);
      ASSERT_NEAR(r.aovs.at(x, row, 1), b.st[0].y(), 1e-6);
      ASSERT_NEAR(r.aovs.at(x, row, 4), lambdas[0], 1e-6);
      ++checked;
    }
  EXPECT_EQ(checked, r.coveredPixels);
}

// A camera at (0, 0, 3) looking at a plane tilted 45 degrees about x, in perspective.
RenderOptions perspectiveOptions(const Texture& texture) {
  RenderOptions o;
  o.camera.width = o.camera.height = 40;
  o.camera.viewFromWorld = lookAt(Vec3(0, 0, 3), Vec3::Zero(), Vec3::UnitY());
  o.camera.clipFromView = perspective(60.0, 1.0, 0.1, 100.0);
  o.texture = &texture;
  o.aovs = true;
  return o;
}
const Quad kTiltedQuad(Vec3(-2, -1.4, 1.4), Vec3(4, 0, 0), Vec3(0, 2.8, -2.8));

TEST(TriplanarBlend, AWeightOfOneReproducesThatAxisAsAPlainMappingBitForBit) {
  Texture texture = randomTexture(64);
  texture.buildMipmaps();
  RenderOptions o = perspectiveOptions(texture);
  o.sampler = samplerFor(Filter::LinearMipmapLinear, Wrap::MirroredRepeat);
  o.env = EnvMode::Modulate;
  o.samplesPerPixel = 4;
  for (int axis = 0; axis < 3; ++axis) {
    TexcoordSource blend, plain;
    blend.pixelMapping = blendMapping([axis](const Vec3& p, const Vec3& n, std::int32_t) {
      TexcoordBlend b = unityTriplanar(p, n, 2.0, 1.0);
      for (int i = 0; i < 3; ++i)
        if (i != axis) b.st[std::size_t(i)] = Vec2(kNaN, kNaN);  // weight 0: never read
      b.weights = Vec3::Unit(axis);
      return b;
    });
    plain.pixelMapping = PixelMapping{[axis](const Vec3& p, const Vec3& n, std::int32_t) {
                                        const Vec2 st = unityTriplanar(p, n, 2.0, 1.0).st[std::size_t(axis)];
                                        return Vec4(st.x(), st.y(), 0, 1);
                                      },
                                      false, true};
    const Rendering a = render(kTiltedQuad.mesh, blend, o), b = render(kTiltedQuad.mesh, plain, o);
    ASSERT_GT(a.coveredPixels, 1000u);
    EXPECT_EQ(a.colour.pixels, b.colour.pixels) << axis;
    EXPECT_EQ(a.aovs.pixels, b.aovs.pixels) << axis;
  }
}

TEST(TriplanarBlend, NoValueShowsWhatAPlainMappingShowsForNoValue) {
  // Left: non-finite weights; middle: the weighted lookup's st non-finite; right: a value.
  Texture texture = randomTexture(16);
  texture.buildMipmaps();
  RenderOptions o = perspectiveOptions(texture);
  o.sampler = samplerFor(Filter::LinearMipmapLinear, Wrap::Repeat);
  TexcoordSource blend, plain;
  blend.pixelMapping = blendMapping([](const Vec3& p, const Vec3& n, std::int32_t) {
    TexcoordBlend b = unityTriplanar(p, n, 1.0, 1.0);
    if (p.x() < -0.5) return TexcoordBlend{{Vec2(kNaN, kNaN), Vec2(kNaN, kNaN), Vec2(kNaN, kNaN)}, Vec3::Constant(kNaN)};
    b.weights = Vec3::UnitZ();
    if (p.x() < 0.5) b.st[2] = Vec2(kNaN, kNaN);
    return b;
  });
  plain.pixelMapping = PixelMapping{[](const Vec3& p, const Vec3&, std::int32_t) {
                                      return p.x() < 0.5 ? Vec4::Constant(kNaN) : Vec4(p.x(), p.y(), 0, 1);
                                    },
                                    false, true};
  const Rendering a = render(kTiltedQuad.mesh, blend, o), b = render(kTiltedQuad.mesh, plain, o);
  EXPECT_EQ(a.colour.pixels, b.colour.pixels);
  std::size_t noValue = 0;
  for (std::size_t k = 0; k < a.aovs.pixels.size(); ++k) {
    const float u = a.aovs.pixels[k], v = b.aovs.pixels[k];
    ASSERT_TRUE(u == v || (std::isnan(u) && std::isnan(v))) << k;
    noValue += std::isnan(u);
  }
  EXPECT_GT(noValue, 2 * 400u);  // u and v of the left and middle pixels
}

TEST(TriplanarBlend, ACubeMapIsRefusedAndAxisTexturesCountInTheMemoryEstimate) {
  const Plane plane = tilted();
  const Texture texture = randomTexture(64), red = solid(Rgba(1, 0, 0, 1)), blue = solid(Rgba(0, 0, 1, 1));
  TexcoordSource source;
  source.pixelMapping = blendMapping([](const Vec3& p, const Vec3& n, std::int32_t) {
    return unityTriplanar(p, n, 1.0, 1.0);
  });
  RenderOptions o = plane.options(texture);
  o.axisTextures = {&red, &texture, &blue};  // the bound one is counted once
  EXPECT_EQ(estimateMemory(plane.quad.mesh, source, o).texture, (64 * 64 + 2) * sizeof(Rgba));

  std::vector<Texture> faces(std::size_t(kCubeFaceCount), solid(Rgba(1, 1, 1, 1)));
  const CubeTexture cube(faces);
  o.texture = nullptr;
  o.cubeTexture = &cube;
  EXPECT_THROW(render(plane.quad.mesh, source, o), UsageError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::render
