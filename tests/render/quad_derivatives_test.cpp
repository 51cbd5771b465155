// Derivatives as a GPU takes them (RenderOptions::derivatives): differences across 2 x 2 pixel quads,
// coarse and fine, checked against an independent recount by ray casting; the seam line of a
// per-pixel atan2 mapping where a GPU shows it, and the remedies that remove it (textureGrad,
// Tarini's choice of u); the level-of-detail bias.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>

#include "core/error.h"
#include "core/gl_matrices.h"
#include "render/procedural.h"
#include "render/quad_fixture.h"
#include "render/renderer.h"

namespace uvtk::render {
namespace {
namespace UVTK_TEST_FILE {

constexpr double kPi = 3.14159265358979323846;

// checker:64:8 with its mipmaps; its coarsest level is mid grey.
float lodAt(const Rendering& r, int x, int row) { return r.aovs.at(x, row, 4); }
int faceAt(const Rendering& r, int x, int row) { return int(r.aovs.at(x, row, 3)); }

RenderOptions trilinear(const Texture& texture, const Camera& camera, Derivatives derivatives) {
  RenderOptions o;
  o.camera = camera;
  o.texture = &texture;
  o.sampler = samplerFor(Filter::LinearMipmapLinear, Wrap::Repeat);
  o.derivatives = derivatives;
  o.aovs = true;
  return o;
}

// A face-on square 64 pixels across with u, v from 0 to 2 on a 64-texel texture: 2 texels per pixel
// along x and y, lambda = log2(2) = 1 at every pixel whichever way the derivatives are taken.
TEST(QuadDerivatives, AnAffineMappingHasTheSameLevelOfDetailInEveryMode) {
  Quad quad(Vec3(-1, -1, 0), Vec3(2, 0, 0), Vec3(0, 2, 0));
  for (Vec4& c : quad.texcoords.corners) c.head<2>() *= 2.0;
  Camera camera;
  camera.width = camera.height = 64;
  camera.clipFromView = orthographic(-1, 1, -1, 1, -1, 1);
  const Texture texture = mipmappedChecker(64, 8);
  for (Derivatives d : {Derivatives::Analytic, Derivatives::QuadCoarse, Derivatives::QuadFine}) {
    const Rendering r = render(quad.mesh, quad.texcoords, trilinear(texture, camera, d));
    ASSERT_EQ(r.coveredPixels, 64u * 64u);
    for (int row = 0; row < 64; ++row)
      for (int x = 0; x < 64; ++x) ASSERT_NEAR(lodAt(r, x, row), 1.0, 1e-6) << x << "," << row;
  }
}

// The square tilted away from a perspective camera, its (u, v) recounted by casting the ray through
// a window point onto its plane: the quad differences of that recount give lambda.
struct TiltedSquare {
  Quad quad{Vec3(-1, -1, 0), Vec3(2, 0, 0), Vec3(0, 2, 0)};
  Camera camera;
  TiltedSquare() {
    for (Vec4& c : quad.texcoords.corners) c.head<2>() *= 4.0;
    camera.width = camera.height = 96;
    camera.viewFromWorld = lookAt(Vec3(0, -2.2, 1.6), Vec3(0, 0.2, 0), Vec3(0, 0, 1));
    camera.clipFromView = perspective(60.0, 1.0, 0.1, 10.0);
  }
  // (u, v) = 4 ((x + 1)/2, (y + 1)/2) where the ray through window (wx, wy) meets z = 0.
  Vec2 uvAt(double wx, double wy) const {
    const Mat4 worldFromClip = (camera.clipFromView * camera.viewFromWorld).inverse();
    const Vec4 ndc(2.0 * wx / camera.width - 1.0, 2.0 * wy / camera.height - 1.0, 0.0, 1.0);
    const Vec4 a = worldFromClip * Vec4(ndc.x(), ndc.y(), -1.0, 1.0), b = worldFromClip * Vec4(ndc.x(), ndc.y(), 1.0, 1.0);
    const Vec3 p = a.head<3>() / a.w(), q = b.head<3>() / b.w();
    const Vec3 hit = p + (q - p) * (p.z() / (p.z() - q.z()));
    return 4.0 * Vec2((hit.x() + 1.0) / 2.0, (hit.y() + 1.0) / 2.0);
  }
};

double lambdaOf(const Vec2& dx, const Vec2& dy, int size) {
  return std::log2(std::max((dx * size).norm(), (dy * size).norm()));
}

TEST(QuadDerivatives, CoarseAndFineDifferencesMatchARayCastRecount) {
  const TiltedSquare scene;
  const Texture texture = mipmappedChecker(64, 8);
  const Rendering coarse = render(scene.quad.mesh, scene.quad.texcoords, trilinear(texture, scene.camera, Derivatives::QuadCoarse));
  const Rendering fine = render(scene.quad.mesh, scene.quad.texcoords, trilinear(texture, scene.camera, Derivatives::QuadFine));
  const Rendering exact = render(scene.quad.mesh, scene.quad.texcoords, trilinear(texture, scene.camera, Derivatives::Analytic));
  ASSERT_GT(coarse.coveredPixels, 2000u);
  int checked = 0, differ = 0;
  for (int row = 0; row < 96; ++row)
    for (int x = 0; x < 96; ++x) {
      if (faceAt(coarse, x, row) < 0) continue;
      const int y = 95 - row;  // window row, y up
      const double x0 = (x & ~1) + 0.5, y0 = (y & ~1) + 0.5, wx = x + 0.5, wy = y + 0.5;
      const Vec2 c00 = scene.uvAt(x0, y0);
      const double coarseLambda = lambdaOf(scene.uvAt(x0 + 1, y0) - c00, scene.uvAt(x0, y0 + 1) - c00, 64);
      const double fineLambda = lambdaOf(scene.uvAt(x0 + 1, wy) - scene.uvAt(x0, wy), scene.uvAt(wx, y0 + 1) - scene.uvAt(wx, y0), 64);
      ASSERT_NEAR(lodAt(coarse, x, row), coarseLambda, 1e-5) << x << "," << row;
      ASSERT_NEAR(lodAt(fine, x, row), fineLambda, 1e-5) << x << "," << row;
      // Differences over one pixel stay close to the derivative of this smooth mapping.
      EXPECT_NEAR(lodAt(coarse, x, row), lodAt(exact, x, row), 0.1);
      differ += lodAt(coarse, x, row) != lodAt(exact, x, row);
      ++checked;
    }
  EXPECT_EQ(checked, int(coarse.coveredPixels));
  EXPECT_GT(differ, checked / 2);  // perspective: the quad differences are not the derivatives
}

// A sphere about the origin, with per-pixel u = atan2(x', -z') / 2 pi + 1/2, v = 1/2 + asin(y) / pi,
// (x', z') the point turned 0.1 radian about y: u wraps from 1 to 0 on a meridian in front of the
// camera, a few pixels off the centre column (a seam on a quad boundary shows no line).
struct SeamSphere {
  Mesh mesh;
  TexcoordSource texcoords;
  Camera camera;
  SeamSphere(int longitudes, int latitudes) {
    for (int j = 0; j <= latitudes; ++j)
      for (int i = 0; i < longitudes; ++i) {
        const double theta = kPi * j / latitudes, phi = 2 * kPi * (i + 0.5) / longitudes;
        mesh.positions.emplace_back(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      }
    for (int j = 0; j < latitudes; ++j)
      for (int i = 0; i < longitudes; ++i) {
        const int a = j * longitudes + i, b = j * longitudes + (i + 1) % longitudes;
        mesh.triangles.push_back({a, b, b + longitudes});
        mesh.triangles.push_back({a, b + longitudes, a + longitudes});
      }
    PixelMapping m;
    m.wrapsS = true;
    m.texcoordAt = [](const Vec3& p, const Vec3&, std::int32_t) {
      const Vec3 d = p.normalized();
      const double x = d.x() * std::cos(0.1) + d.z() * std::sin(0.1), z = d.z() * std::cos(0.1) - d.x() * std::sin(0.1);
      return Vec4(std::atan2(x, -z) / (2 * kPi) + 0.5, 0.5 + std::asin(d.y()) / kPi, 0.0, 1.0);
    };
    texcoords.pixelMapping = m;
    camera.width = camera.height = 128;
    camera.viewFromWorld = lookAt(Vec3(0, 0, 4), Vec3(0, 0, 0), Vec3(0, 1, 0));
    camera.clipFromView = perspective(35.0, 1.0, 0.5, 10.0);
  }
};

// Pixels whose quad level of detail exceeds the analytic one by more than 1: on the seam (u within
// 0.1 of 0 or 1) or at a pole (v within 0.05 of 0 or 1), nowhere else.
struct MipLine {
  int seam = 0, pole = 0;
  double offGrey = 0.0;  // the largest |red - 1/2| on the seam
};
MipLine mipLine(const Rendering& quad, const Rendering& analytic) {
  MipLine line;
  for (int row = 0; row < quad.aovs.height; ++row)
    for (int x = 0; x < quad.aovs.width; ++x) {
      if (faceAt(quad, x, row) < 0 || !(lodAt(quad, x, row) > lodAt(analytic, x, row) + 1.0f)) continue;
      const double u = quad.aovs.at(x, row, 0), v = quad.aovs.at(x, row, 1);
      if (std::fabs(u - std::round(u)) < 0.1) {
        ++line.seam;
        line.offGrey = std::max(line.offGrey, std::fabs(quad.colour.at(x, row, 0) - 0.5));
      } else {
        EXPECT_LT(std::min(v, 1.0 - v), 0.05) << x << "," << row;
        ++line.pole;
      }
    }
  return line;
}

TEST(QuadDerivatives, APerPixelAtan2MappingShowsTheSeamLineAndItsFixesRemoveIt) {
  const SeamSphere sphere(48, 24);
  const Texture texture = mipmappedChecker(64, 8);
  const Rendering analytic = render(sphere.mesh, sphere.texcoords, trilinear(texture, sphere.camera, Derivatives::Analytic));
  ASSERT_GT(analytic.coveredPixels, 5000u);
  for (Derivatives d : {Derivatives::QuadCoarse, Derivatives::QuadFine}) {
    RenderOptions o = trilinear(texture, sphere.camera, d);
    const Rendering gpu = render(sphere.mesh, sphere.texcoords, o);
    const MipLine line = mipLine(gpu, analytic);
    // One or two pixels wide down the visible half meridian (about 100 rows), the coarsest level
    // of a checker there: mid grey.
    EXPECT_GT(line.seam, 80) << int(d);
    EXPECT_LT(line.seam, 2 * 110) << int(d);
    EXPECT_LT(line.offGrey, 0.02);

    o.seamFix = SeamFix::Grad;  // textureGrad with the analytic derivatives: the analytic picture
    const Rendering grad = render(sphere.mesh, sphere.texcoords, o);
    EXPECT_EQ(grad.colour.pixels, analytic.colour.pixels);
    const MipLine none = mipLine(grad, analytic);
    EXPECT_EQ(none.seam + none.pole, 0);

    o.seamFix = SeamFix::Tarini;  // the seam goes, the poles stay
    const Rendering tarini = render(sphere.mesh, sphere.texcoords, o);
    const MipLine fixed = mipLine(tarini, analytic);
    EXPECT_EQ(fixed.seam, 0) << int(d);
    EXPECT_EQ(fixed.pole, line.pole) << int(d);
    EXPECT_EQ(tarini.coveredPixels, analytic.coveredPixels);
  }
}

TEST(QuadDerivatives, TariniNeedsAPerPixelMappingThatWraps) {
  const TiltedSquare scene;
  const Texture texture = mipmappedChecker(64, 8);
  RenderOptions o = trilinear(texture, scene.camera, Derivatives::QuadCoarse);
  o.seamFix = SeamFix::Tarini;
  EXPECT_THROW(render(scene.quad.mesh, scene.quad.texcoords, o), UsageError);
}

// GL's TEXTURE_LOD_BIAS: lambda + bias, so a picture one level blurrier.
TEST(QuadDerivatives, TheLodBiasAddsToLambda) {
  const TiltedSquare scene;
  const Texture texture = mipmappedChecker(64, 8);
  RenderOptions o = trilinear(texture, scene.camera, Derivatives::Analytic);
  const Rendering plain = render(scene.quad.mesh, scene.quad.texcoords, o);
  o.lodBias = 1.0;
  const Rendering biased = render(scene.quad.mesh, scene.quad.texcoords, o);
  int changed = 0;
  for (int row = 0; row < 96; ++row)
    for (int x = 0; x < 96; ++x) {
      if (faceAt(plain, x, row) < 0) continue;
      ASSERT_NEAR(lodAt(biased, x, row), lodAt(plain, x, row) + 1.0, 1e-6);
      changed += biased.colour.at(x, row, 0) != plain.colour.at(x, row, 0);
    }
  EXPECT_GT(changed, 1000);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::render
