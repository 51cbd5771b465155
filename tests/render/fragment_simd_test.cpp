// The vectorised fragments against the scalar functions they replace, bit for bit: the sampler
// against sample() for every filter, wrap and texture kind it takes (and which it refuses), the
// barycentrics against TriangleInterpolator::at, lambda against levelOfDetail.
#include "render/fragment_simd.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>

#include "core/gl_matrices.h"
#include "meshes/generators.h"
#include "render/camera.h"
#include "render/procedural.h"
#include "doubles.h"

namespace uvtk::render {
namespace {
namespace UVTK_TEST_FILE {

Texture floatTexture() {
  TexelLevel base;
  base.width = base.height = 8;
  base.texels.assign(64, Rgba(0.3f, 0.1f, 0.7f, 1.0f));
  return Texture(std::move(base), false);
}

TEST(VectorisedTexture, TakesPackedPowerOfTwoTexturesAndClampedOnesOfAnySize) {
  Texture checker = checkerTexture(64, 8), npot = Texture::fromImage(uvGridImage(100), true), smooth = floatTexture();
  checker.buildMipmaps(), npot.buildMipmaps();
  EXPECT_TRUE(checker.packed() && checker.standardBytes());
  EXPECT_TRUE(npot.packed() && npot.standardBytes());
  for (Wrap wrap : {Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat})
    EXPECT_TRUE(vectorisedTexture(checker, samplerFor(Filter::LinearMipmapLinear, wrap), false).has_value());
  EXPECT_TRUE(vectorisedTexture(npot, samplerFor(Filter::Linear, Wrap::ClampToEdge), false).has_value());
  EXPECT_FALSE(vectorisedTexture(npot, samplerFor(Filter::Linear, Wrap::Repeat), false).has_value());
  EXPECT_FALSE(vectorisedTexture(npot, samplerFor(Filter::Linear, Wrap::MirroredRepeat), false).has_value());
  EXPECT_FALSE(vectorisedTexture(smooth, samplerFor(Filter::Linear, Wrap::ClampToEdge), false).has_value());
}

// sampleTexels gives what sample() gives, for each channel, on random coordinates far and near,
// every kind of lambda, and lists the fragments whose s or t is not finite.
TEST(SampleTexels, IsSampleBitForBitForEveryFilterAndWrap) {
  if (!fragmentsVectorised()) GTEST_SKIP() << "no fused multiply-add on this processor: the scalar path shades";
  Texture checker = checkerTexture(64, 8), grid = Texture::fromImage(uvGridImage(128), true),
          npot = Texture::fromImage(uvGridImage(100), true);
  checker.buildMipmaps(), grid.buildMipmaps(), npot.buildMipmaps();
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const auto batch = std::make_unique<FragmentBatch>();
  std::size_t checked = 0;
  for (const Texture* texture : {&checker, &grid, &npot})
    for (int f = 0; f < 6; ++f)
      for (int w = 0; w < 3; ++w) {
        const SamplerState sampler = samplerFor(Filter(f), Wrap(w));
        const std::optional<FragmentTexture> vectorised = vectorisedTexture(*texture, sampler, true);
        if (!vectorised) continue;
        for (int round = 0; round < 20; ++round) {
          batch->count = FragmentBatch::kSize;
          for (std::size_t j = 0; j < batch->count; ++j) {
            // Every fourth round, coordinates whose texel index lies beyond 2^51 (the integer
            // conversion's fast range) and beyond the clamp at 2^62.
            const double huge = round % 4 == 3 && j % 5 == 2 ? 1e17 : 3.0;
            const double scale = j % 5 == 0 ? 1e6 : j % 5 == 1 ? 0.01 : huge;
            batch->s[j] = scale * unit(random), batch->t[j] = scale * unit(random);
            batch->lambda[j] = 8.0 * unit(random) + 2.0;
            if (j % 37 == 3) batch->lambda[j] = nan;
            if (j % 41 == 4) batch->lambda[j] = inf;
            if (j % 43 == 5) batch->lambda[j] = -inf;
            if (j % 47 == 6) batch->lambda[j] = std::floor(batch->lambda[j]) + 0.5;  // NEAREST_MIPMAP's boundary
            if (j % 97 == 7) batch->s[j] = nan;
            if (j % 101 == 8) batch->t[j] = inf;
          }
          sampleTexels(*vectorised, *batch);
          std::size_t unsampled = 0;
          for (std::size_t j = 0; j < batch->count; ++j) {
            if (!std::isfinite(batch->s[j]) || !std::isfinite(batch->t[j])) {
              ASSERT_LT(unsampled, batch->unsampledCount);
              EXPECT_EQ(batch->unsampled[unsampled++], std::int64_t(j));
              continue;
            }
            const Vec4 expected = sample(*texture, sampler, batch->s[j], batch->t[j], batch->lambda[j]);
            const double got[4] = {batch->red[j], batch->green[j], batch->blue[j], batch->alpha[j]};
            for (int c = 0; c < 4; ++c)
              ASSERT_TRUE(sameBits(got[c], expected[c]))
                  << "filter " << f << " wrap " << w << " s " << batch->s[j] << " t " << batch->t[j] << " lambda "
                  << batch->lambda[j] << " channel " << c << ": " << got[c] << " vs " << expected[c];
            ++checked;
          }
          EXPECT_EQ(unsampled, batch->unsampledCount);
        }
      }
  EXPECT_GT(checked, 100000u);
}

// The batch's barycentrics are TriangleInterpolator::at's, its lambda levelOfDetail's of its own
// derivatives, and (s, t) the interpolated coordinates divided by q, on every pixel of a knot.
TEST(ShadeFragments, AreTheInterpolatorsBarycentricsAndTheLevelOfDetailOfTheirDerivatives) {
  if (!fragmentsVectorised()) GTEST_SKIP() << "no fused multiply-add on this processor: the scalar path shades";
  const Mesh knot = meshes::torusKnot(2, 3, 128, 16);  // about 1000 pixels: one batch a tile
  const Camera camera = frameSphere(boundingSphere(knot.positions), Vec3(1, -2, 0.8), Vec3(0, 0, 1), {}, 160, 120);
  std::vector<Vec4> clip, corners;
  for (const Vec3& p : knot.positions) clip.push_back(camera.clipFromView * camera.viewFromWorld * p.homogeneous());
  for (const Triangle& t : knot.triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = knot.positions[std::size_t(t[k])];
      corners.emplace_back(1.5 * p.x(), p.y() - p.z(), 0.0, 1.25 + 0.25 * std::sin(p.z()));
    }
  const TiledRaster raster(clip, knot.triangles, camera.width, camera.height, RasterOptions{});
  FragmentFrame frame;
  frame.drawnFaces = raster.drawnFaces(), frame.corners = corners.data()->data();
  frame.textureWidth = 256, frame.textureHeight = 64, frame.lodBias = 0.25;
  const auto tile = std::make_unique<TiledRaster::Tile>();
  const auto batch = std::make_unique<FragmentBatch>();
  std::size_t checked = 0;
  for (int index = 0; index < raster.tileCount(); ++index) {
    raster.draw(index, *tile);
    std::vector<const DrawnFace*> faces;
    batch->count = 0;
    for (int y = tile->y0; y <= tile->y1; ++y)
      for (int x = tile->x0; x <= tile->x1 && batch->count < FragmentBatch::kSize; ++x) {
        const DrawnFace* drawn = tile->face[std::size_t(y - tile->y0) * TiledRaster::kTileSize + std::size_t(x - tile->x0)];
        if (!drawn) continue;
        const std::size_t j = batch->count++;
        batch->x[j] = x + 0.5, batch->y[j] = y + 0.5;
        batch->drawn[j] = drawn - frame.drawnFaces, batch->corners[j] = 12 * std::int64_t(drawn->face);
        faces.push_back(drawn);
      }
    if (batch->count == 0) continue;
    for (std::size_t j = batch->count; j % 16 != 0; ++j)
      batch->x[j] = batch->x[0], batch->y[j] = batch->y[0], batch->drawn[j] = batch->drawn[0], batch->corners[j] = batch->corners[0];
    shadeFragments(frame, *batch);
    std::vector<bool> undecided(batch->count, false);
    for (std::size_t k = 0; k < batch->undecidedCount; ++k) undecided[std::size_t(batch->undecided[k])] = true;
    for (std::size_t j = 0; j < batch->count; ++j) {
      const TriangleInterpolator::Barycentrics b = faces[j]->interpolator.at(batch->x[j], batch->y[j]);
      ASSERT_TRUE(sameBits(b.b[0], batch->b0[j]) && sameBits(b.b[1], batch->b1[j]) && sameBits(b.b[2], batch->b2[j]));
      const Vec4* c = &corners[3 * std::size_t(faces[j]->face)];
      const Vec4 tc = b.b[0] * c[0] + b.b[1] * c[1] + b.b[2] * c[2];
      EXPECT_NEAR(batch->s[j], tc.x() / tc.w(), 1e-12);
      EXPECT_NEAR(batch->t[j], tc.y() / tc.w(), 1e-12);
      if (undecided[j]) continue;
      const double lambda = levelOfDetail(256, 64, Vec2(batch->dsdx[j], batch->dtdx[j]), Vec2(batch->dsdy[j], batch->dtdy[j])) + 0.25;
      ASSERT_TRUE(sameBits(lambda, batch->lambda[j])) << lambda << " vs " << batch->lambda[j];
      ++checked;
    }
  }
  EXPECT_GT(checked, 700u);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::render
