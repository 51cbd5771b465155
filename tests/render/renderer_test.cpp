#include "render/renderer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/gl_matrices.h"
#include "render/procedural.h"
#include "render/quad_fixture.h"

namespace uvtk::render {
namespace {
namespace UVTK_TEST_FILE {

Texture rampTexture(int width, int height) {  // every texel a distinct colour
  TexelLevel level{width, height, {}};
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      level.texels.push_back(Rgba(i / 255.0f, j / 255.0f, float((i + j) % 7) / 255.0f, 1.0f));
  return Texture(level, true);
}

TEST(Render, AScreenFillingQuadUnderAnOrthographicCameraReproducesTheTextureTexelForPixel) {
  const Quad quad(Vec3(-1, -1, 0), Vec3(2, 0, 0), Vec3(0, 2, 0));
  const Texture texture = rampTexture(64, 48);
  RenderOptions o;
  o.camera.width = 64, o.camera.height = 48;
  o.camera.clipFromView = orthographic(-1, 1, -1, 1, -1, 1);
  o.texture = &texture;
  const Rendering r = render(quad.mesh, quad.texcoords, o);
  for (int row = 0; row < 48; ++row)
    for (int x = 0; x < 64; ++x) {
      const Rgba& texel = texture.level(0).at(x, 47 - row);  // the top row shows t near 1
      for (int c = 0; c < 3; ++c) ASSERT_EQ(r.colour.at(x, row, c), texel[c]) << x << ", " << row;
    }
  EXPECT_EQ(r.coveredPixels, 64u * 48u);
}

// A camera at (0, 0, 3) looking at the origin, and a plane through the origin tilted 45 degrees
// about x, large enough to fill the view.
struct TiltedPlane {
  int size = 65;
  Mat4 view = lookAt(Vec3(0, 0, 3), Vec3::Zero(), Vec3::UnitY());
  Mat4 projection = perspective(60.0, 1.0, 0.1, 100.0);
  Vec3 a = Vec3(40, 0, 0), b = Vec3(0, 40 * std::cos(kPi / 4), -40 * std::sin(kPi / 4));
  Vec3 origin = -0.5 * (a + b);
  Quad quad{origin, a, b};

  RenderOptions options(const Texture& texture) const {
    RenderOptions o;
    o.camera.width = o.camera.height = size;
    o.camera.viewFromWorld = view;
    o.camera.clipFromView = projection;
    o.texture = &texture;
    o.aovs = true;
    return o;
  }
  // The (u, v) where the ray through window point (x, y) (y up) meets the plane.
  Vec2 analyticUv(double x, double y) const {
    const double t = std::tan(kPi / 6);
    const Vec3 eye(0, 0, 3), d((2 * x / size - 1) * t, (2 * y / size - 1) * t, -1);
    const Vec3 n = a.cross(b);
    const Vec3 hit = eye + d * ((origin - eye).dot(n) / d.dot(n));
    return Vec2((hit - origin).dot(a) / a.squaredNorm(), (hit - origin).dot(b) / b.squaredNorm());
  }
};

TEST(Render, TextureCoordinatesArePerspectiveCorrectAtEveryPixel) {
  const TiltedPlane s;
  const Texture texture = checkerTexture(64, 8);
  const Rendering r = render(s.quad.mesh, s.quad.texcoords, s.options(texture));
  ASSERT_EQ(r.coveredPixels, std::size_t(s.size * s.size));
  double worstLinear = 0.0;
  const Mat4 clipFromWorld = s.projection * s.view;
  for (int row = 0; row < s.size; ++row)
    for (int x = 0; x < s.size; ++x) {
      const double wx = x + 0.5, wy = s.size - row - 0.5;
      const Vec2 expected = s.analyticUv(wx, wy);
      EXPECT_NEAR(r.aovs.at(x, row, 0), expected.x(), 1e-5);
      EXPECT_NEAR(r.aovs.at(x, row, 1), expected.y(), 1e-5);
      // Screen-space linear interpolation of the same triangle would miss by far more.
      const int face = int(r.aovs.at(x, row, 3));
      Vec2 p[3], uv[3];
      for (int k = 0; k < 3; ++k) {
        const Vec4 c = clipFromWorld *
                       s.quad.mesh.positions[std::size_t(s.quad.mesh.triangles[std::size_t(face)][k])].homogeneous();
        p[k] = Vec2((c.x() / c.w() + 1) * 0.5 * s.size, (c.y() / c.w() + 1) * 0.5 * s.size);
        uv[k] = s.quad.texcoords.corners[std::size_t(3 * face + k)].head<2>();
      }
      Eigen::Matrix2d m;
      m << p[0] - p[2], p[1] - p[2];
      const Eigen::Vector2d l = m.inverse() * (Vec2(wx, wy) - p[2]);
      const Vec2 linear = l[0] * uv[0] + l[1] * uv[1] + (1 - l[0] - l[1]) * uv[2];
      worstLinear = std::max(worstLinear, (linear - expected).norm());
    }
  EXPECT_GT(worstLinear, 1e-2);
}

TEST(Render, TheLevelOfDetailIsLog2OfTheLongerTexelFootprintOfThePixel) {
  const TiltedPlane s;
  const Texture texture = mipmappedChecker(256, 8);
  RenderOptions o = s.options(texture);
  o.sampler = samplerFor(Filter::LinearMipmapLinear, Wrap::Repeat);
  const Rendering r = render(s.quad.mesh, s.quad.texcoords, o);
  // At the centre pixel the ray runs along the axis, 3 units to the plane: one pixel spans
  // 2 tan(30 deg) 3 / 65 units across, and 1 / cos(45 deg) times that along the tilted
  // direction; 256 texels cover 40 units. lambda = log2(256 / 40 * sqrt(2) * 2 tan(30) 3 / 65).
  const double centre = std::log2(256.0 / 40.0 * std::sqrt(2.0) * 2.0 * std::tan(kPi / 6) * 3.0 / 65.0);
  EXPECT_NEAR(r.aovs.at(32, 32, 4), centre, 1e-5);
  // Everywhere: against central differences of the analytic intersection.
  for (int row = 0; row < s.size; row += 4)
    for (int x = 0; x < s.size; x += 4) {
      const double wx = x + 0.5, wy = s.size - row - 0.5, h = 1e-3;
      const Vec2 dx = (s.analyticUv(wx + h, wy) - s.analyticUv(wx - h, wy)) / (2 * h) * 256.0;
      const Vec2 dy = (s.analyticUv(wx, wy + h) - s.analyticUv(wx, wy - h)) / (2 * h) * 256.0;
      EXPECT_NEAR(r.aovs.at(x, row, 4), std::log2(std::max(dx.norm(), dy.norm())), 1e-5) << x << ", " << row;
    }
}

TEST(Render, ATriangleCrossingTheEyePlaneShowsTheAnalyticTextureCoordinates) {
  // The ground y = -1 under a camera at the origin looking down -z; the triangle reaches 50 units
  // behind the eye. Its texture coordinates are affine in x and z.
  Mesh mesh;
  mesh.positions = {Vec3(-50, -1, -50), Vec3(0, -1, 50), Vec3(50, -1, -50)};
  mesh.triangles = {{0, 1, 2}};
  TexcoordSource texcoords;
  for (const Vec3& p : mesh.positions) texcoords.corners.push_back(Vec4((p.x() + 50) / 100, (p.z() + 50) / 100, 0, 1));
  const Texture texture = checkerTexture(8, 1);
  RenderOptions o;
  o.camera.width = 64, o.camera.height = 48;
  o.camera.clipFromView = perspective(90.0, 64.0 / 48.0, 0.1, 200.0);
  o.texture = &texture;
  o.aovs = true;
  const Rendering r = render(mesh, texcoords, o);
  std::size_t checked = 0;
  for (int row = 0; row < 48; ++row)
    for (int x = 0; x < 64; ++x) {
      if (r.aovs.at(x, row, 3) < 0) continue;
      const double t = 1.0;  // tan(45 deg)
      const Vec3 d((2 * (x + 0.5) / 64 - 1) * t * 64 / 48, (2 * (48 - row - 0.5) / 48 - 1) * t, -1);
      const Vec3 hit = d * (-1.0 / d.y());
      EXPECT_NEAR(r.aovs.at(x, row, 0), (hit.x() + 50) / 100, 1e-6);
      EXPECT_NEAR(r.aovs.at(x, row, 1), (hit.z() + 50) / 100, 1e-6);
      ++checked;
    }
  EXPECT_GT(checked, 1000u);
}

TEST(Render, AnExactPixelMappingOfALinearMapEqualsPerVertexInterpolation) {
  const TiltedPlane s;
  const Texture texture = checkerTexture(64, 8);
  TexcoordSource exact;
  const Vec3 a = s.a, b = s.b, origin = s.origin;
  exact.pixelMapping =
      PixelMapping{[a, b, origin](const Vec3& p, const Vec3&, std::int32_t) {
                     return Vec4((p - origin).dot(a) / a.squaredNorm(), (p - origin).dot(b) / b.squaredNorm(), 0, 1);
                   },
                   false, false};
  const Rendering perVertex = render(s.quad.mesh, s.quad.texcoords, s.options(texture));
  const Rendering perPixel = render(s.quad.mesh, exact, s.options(texture));
  for (std::size_t i = 0; i < perVertex.aovs.pixels.size(); i += 5) {
    EXPECT_NEAR(perPixel.aovs.pixels[i], perVertex.aovs.pixels[i], 1e-6);
    EXPECT_NEAR(perPixel.aovs.pixels[i + 1], perVertex.aovs.pixels[i + 1], 1e-6);
    EXPECT_NEAR(perPixel.aovs.pixels[i + 4], perVertex.aovs.pixels[i + 4], 1e-4);  // lod by differences
  }
}

TEST(Render, TheImageDoesNotDependOnTheThreadCount) {
  const TiltedPlane s;
  const Texture texture = mipmappedChecker(256, 8);
  RenderOptions o = s.options(texture);
  o.sampler = samplerFor(Filter::LinearMipmapLinear, Wrap::MirroredRepeat);
  o.env = EnvMode::Modulate;
  o.raster.threads = 1;
  const Rendering one = render(s.quad.mesh, s.quad.texcoords, o);
  o.raster.threads = 3;
  const Rendering three = render(s.quad.mesh, s.quad.texcoords, o);
  EXPECT_EQ(one.colour.pixels, three.colour.pixels);
  EXPECT_EQ(one.aovs.pixels, three.aovs.pixels);
}

TEST(Render, TheBackgroundFillsUncoveredPixelsAndTheAovsMarkThem) {
  const Quad quad(Vec3(-0.5, -0.5, 0), Vec3(1, 0, 0), Vec3(0, 1, 0));  // the middle half of the view
  const Texture texture = checkerTexture(8, 8);                        // all white
  RenderOptions o;
  o.camera.width = o.camera.height = 8;
  o.camera.clipFromView = orthographic(-1, 1, -1, 1, -1, 1);
  o.texture = &texture;
  o.background = Vec3(0.25, 0.5, 0.75);
  o.aovs = true;
  const Rendering r = render(quad.mesh, quad.texcoords, o);
  EXPECT_EQ(r.coveredPixels, 16u);
  EXPECT_EQ(r.colour.at(0, 0, 1), 0.5f);
  EXPECT_EQ(r.colour.at(4, 4, 1), 1.0f);
  EXPECT_EQ(r.aovs.at(0, 0, 3), -1.0f);
  EXPECT_EQ(r.aovs.at(0, 0, 2), 1.0f);
  EXPECT_EQ(r.aovs.at(4, 4, 2), 0.5f);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::render
