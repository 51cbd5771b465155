// Issue 6, numerical extremes of the renderer: one row per case, each row stating the documented
// behaviour that its failure messages repeat (docs/extremes.md lists every row). Triangles crossing
// the near plane with w near 0, texture coordinates of 1e9 under REPEAT, 1 x 1 textures under every
// filter, and the largest textures (refused with a UsageError before anything is allocated).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/gl_matrices.h"
#include "doubles.h"
#include "meshes/generators.h"
#include "render/camera.h"
#include "render/procedural.h"
#include "render/renderer.h"
#include "render/texture.h"

namespace uvtk::render {
namespace {
namespace UVTK_TEST_FILE {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kSize = 64;
constexpr double kNear = 0.1;

// ---- triangles crossing the near plane, a corner at w near 0 ----

// View space = world space, the eye at the origin looking down -z: clip w = -z.
RenderOptions nearPlaneOptions(const Texture& texture) {
  RenderOptions o;
  o.camera.width = o.camera.height = kSize;
  o.camera.clipFromView = perspective(90.0, 1.0, kNear, 100.0);
  o.raster.cull = Cull::None;
  o.texture = &texture;
  o.aovs = true;
  return o;
}

struct Vertex {
  Vec3 position;
  Vec2 st;
};

// The reference: the triangle clipped by hand at z = -near in view space (texture coordinates are
// linear in space, so the clipped corners get them by linear interpolation), fan-triangulated.
void clipAtNearPlane(const std::vector<Vertex>& triangle, Mesh& mesh, TexcoordSource& texcoords) {
  std::vector<Vertex> polygon;
  for (std::size_t i = 0; i < 3; ++i) {
    const Vertex& a = triangle[i];
    const Vertex& b = triangle[(i + 1) % 3];
    const double da = -kNear - a.position.z(), db = -kNear - b.position.z();  // >= 0: in front of the near plane
    if (da >= 0) polygon.push_back(a);
    if ((da >= 0) != (db >= 0)) {
      const double t = da / (da - db);
      polygon.push_back({a.position + t * (b.position - a.position), a.st + t * (b.st - a.st)});
    }
  }
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    const int first = int(mesh.positions.size());
    for (std::size_t k : {std::size_t(0), i, i + 1}) {
      mesh.positions.push_back(polygon[k].position);
      texcoords.corners.emplace_back(polygon[k].st.x(), polygon[k].st.y(), 0.0, 1.0);
    }
    mesh.triangles.push_back({first, first + 1, first + 2});
  }
}

struct NearPlaneRow {
  const char* expected;
  Vertex corners[3];
  bool drawsSomething;
};

const std::vector<NearPlaneRow>& nearPlaneRows() {
  static const std::vector<NearPlaneRow> rows = {
      {"a corner behind the eye (w = -1), one on the eye plane (w = 0), one in front: drawn as the triangle "
       "clipped at the near plane by hand, no NaN",
       {{{-0.5, -0.5, -1}, {0, 0}}, {{0.5, -0.5, 0}, {1, 0}}, {{0, 0.5, 1}, {0, 1}}},
       true},
      {"a corner at w = 1e-300 (just in front of the eye plane): as the clipped reference, no NaN",
       {{{-0.5, -0.5, -1}, {0, 0}}, {{0.5, -0.5, -1e-300}, {1, 0}}, {{0, 0.5, -1}, {0, 1}}},
       true},
      {"a corner at w = -1e-300 (just behind the eye plane): as the clipped reference, no NaN",
       {{{-0.5, -0.5, -1}, {0, 0}}, {{0.5, -0.5, 1e-300}, {1, 0}}, {{0, 0.5, -1}, {0, 1}}},
       true},
      {"a corner at w = 5e-324 (subnormal): as the clipped reference, no NaN",
       {{{-0.5, -0.5, -1}, {0, 0}}, {{0.5, -0.5, -5e-324}, {1, 0}}, {{0, 0.5, -1}, {0, 1}}},
       true},
      {"two corners behind (w = -2 and w = -1e-300), one in front: the small clipped triangle, no NaN",
       {{{-0.5, -0.5, -1}, {0, 0}}, {{0.5, -0.5, 2}, {1, 0}}, {{0, 0.5, 1e-300}, {0, 1}}},
       true},
      {"a corner at the eye (0, 0, 0): the triangle's plane passes through the eye, seen edge-on it covers "
       "nothing, as the reference; no crash",
       {{{-0.5, -0.5, -1}, {0, 0}}, {{0, 0, 0}, {1, 0}}, {{0.5, -0.5, -1}, {0, 1}}},
       false},
      {"a corner at w = 1e-300 with x = 1e300 (x/w overflows): the guard band clips it, as the reference",
       {{{-0.5, -0.5, -1}, {0, 0}}, {{1e300, -0.5, -1e-300}, {1, 0}}, {{0, 0.5, -1}, {0, 1}}},
       true},
      {"every corner within 1e-300 of the eye plane: entirely clipped, nothing drawn, no crash",
       {{{-0.5, -0.5, -1e-300}, {0, 0}}, {{0.5, -0.5, 0}, {1, 0}}, {{0, 0.5, 1e-300}, {0, 1}}},
       false},
  };
  return rows;
}

class NearPlaneExtremes : public testing::TestWithParam<std::size_t> {};

TEST_P(NearPlaneExtremes, CoverageAsTheClippedReferenceAndNoNaN) {
  const NearPlaneRow& row = nearPlaneRows()[GetParam()];
  SCOPED_TRACE(row.expected);
  const std::vector<Vertex> corners(std::begin(row.corners), std::end(row.corners));
  Mesh mesh;
  TexcoordSource texcoords;
  for (const Vertex& v : corners) {
    mesh.positions.push_back(v.position);
    texcoords.corners.emplace_back(v.st.x(), v.st.y(), 0.0, 1.0);
  }
  mesh.triangles = {{0, 1, 2}};
  Mesh clipped;
  TexcoordSource clippedTexcoords;
  clipAtNearPlane(corners, clipped, clippedTexcoords);

  const Texture texture = checkerTexture(8, 1);
  const RenderOptions o = nearPlaneOptions(texture);
  const Rendering r = render(mesh, texcoords, o);
  for (float value : r.colour.pixels) ASSERT_TRUE(std::isfinite(value));
  for (float value : r.aovs.pixels) ASSERT_TRUE(std::isfinite(value));
  EXPECT_EQ(r.coveredPixels > 0, row.drawsSomething) << r.coveredPixels << " pixels";
  if (clipped.triangles.empty()) {
    EXPECT_EQ(r.coveredPixels, 0u);
    return;
  }
  const Rendering reference = render(clipped, clippedTexcoords, o);
  // Coverage: pixel for pixel but where a clipped edge passes within rounding of a pixel centre.
  std::size_t differing = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const bool covered = r.aovs.at(x, y, 3) >= 0, coveredByReference = reference.aovs.at(x, y, 3) >= 0;
      if (covered != coveredByReference) {
        ++differing;
        continue;
      }
      if (!covered) continue;
      // The interpolation is from the unclipped corners: the same texture coordinates as the reference's.
      EXPECT_NEAR(r.aovs.at(x, y, 0), reference.aovs.at(x, y, 0), 1e-5) << x << ", " << y;
      EXPECT_NEAR(r.aovs.at(x, y, 1), reference.aovs.at(x, y, 1), 1e-5) << x << ", " << y;
    }
  EXPECT_LE(differing, 2u) << "of " << reference.coveredPixels << " covered pixels";
  EXPECT_EQ(reference.coveredPixels > 0, row.drawsSomething);
}

INSTANTIATE_TEST_SUITE_P(Rows, NearPlaneExtremes, testing::Range<std::size_t>(0, nearPlaneRows().size()));

// ---- texture coordinates of 1e9 under REPEAT ----

// An n x m texture whose every texel is a distinct colour.
Texture rampTexture(int width, int height) {
  TexelLevel level{width, height, {}};
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      level.texels.emplace_back(float(i + 1) / 255.0f, float(j + 1) / 255.0f, float((i * 7 + j) % 11) / 255.0f, 1.0f);
  return Texture(level, true);
}

struct FarCoordinateRow {
  const char* expected;
  int width, height;
  Wrap wrap;
  double s, t;          // sampled
  double sNear, tNear;  // must sample as these
  bool everyFilter;     // false: NEAREST only
};

TEST(RenderExtremes, TextureCoordinatesOf1e9SampleAsTheirFractionalPart) {
  const FarCoordinateRow rows[] = {
      {"REPEAT, 4 x 4, (1e9 + 0.25, 1e9 + 0.75), exactly representable: every filter as at (0.25, 0.75)", 4, 4,
       Wrap::Repeat, 1e9 + 0.25, 1e9 + 0.75, 0.25, 0.75, true},
      {"REPEAT, 3 x 5 (not powers of two), (1e9 + 0.25, -1e9 + 0.5): every filter as at (0.25, 0.5)", 3, 5,
       Wrap::Repeat, 1e9 + 0.25, -1e9 + 0.5, 0.25, 0.5, true},
      {"REPEAT, 64 x 64, (1e9 + 0.25, 1e9 + 0.125): every filter as at (0.25, 0.125)", 64, 64, Wrap::Repeat, 1e9 + 0.25,
       1e9 + 0.125, 0.25, 0.125, true},
      {"REPEAT, 4 x 4, (1e15 + 0.25, 0.125): s W - 1/2 = 4e15 + 0.5 is still exact (below 2^52): every filter", 4, 4,
       Wrap::Repeat, 1e15 + 0.25, 0.125, 0.25, 0.125, true},
      {"REPEAT, 64 x 64, 1e15 + 0.25: NEAREST exact; LINEAR's s W - 1/2 = 6.4e16 + 15.5 rounds (ulp 8), the "
       "documented limit of double texel coordinates",
       64, 64, Wrap::Repeat, 1e15 + 0.25, 0.125, 0.25, 0.125, false},
      {"MIRRORED_REPEAT, 4 x 4, 1e9 + 0.25 (an even number of periods): every filter as at 0.25", 4, 4,
       Wrap::MirroredRepeat, 1e9 + 0.25, 0.75, 0.25, 0.75, true},
      {"CLAMP_TO_EDGE, 4 x 4, 1e9 + 0.25: NEAREST gives the last texel, as at s = 0.99", 4, 4, Wrap::ClampToEdge,
       1e9 + 0.25, 0.25, 0.99, 0.25, false},
  };
  for (const FarCoordinateRow& row : rows) {
    SCOPED_TRACE(row.expected);
    Texture texture = rampTexture(row.width, row.height);
    texture.buildMipmaps();
    for (Filter filter : {Filter::Nearest, Filter::Linear, Filter::NearestMipmapNearest, Filter::LinearMipmapNearest,
                          Filter::NearestMipmapLinear, Filter::LinearMipmapLinear})
      for (double lambda : {0.0, 0.7, 1.5}) {
        const SamplerState sampler = samplerFor(filter, row.wrap);
        const Vec4 far = sample(texture, sampler, row.s, row.t, lambda);
        EXPECT_TRUE(far.allFinite());
        if (row.everyFilter) {
          EXPECT_EQ(far, sample(texture, sampler, row.sNear, row.tNear, lambda))
              << "filter " << int(filter) << ", lambda " << lambda;
        }
      }
    const Rgba nearest = sampleNearest(texture.level(0), row.wrap, row.wrap, row.s, row.t);
    EXPECT_EQ(nearest, sampleNearest(texture.level(0), row.wrap, row.wrap, row.sNear, row.tNear));
  }
}

TEST(RenderExtremes, CoordinatesBeyondTheTexelRangeGiveATexelNotUndefinedBehaviour) {
  struct Row {
    const char* expected;
    double s;
  };
  const Row rows[] = {
      {"s = 1e300: clamped to 2^62 texels before the integer conversion, a texel of the texture", 1e300},
      {"s = -1e300: likewise", -1e300},
      {"s = +inf: texel (0, 0) (documented for non-finite coordinates)", kInf},
      {"s = NaN: texel (0, 0)", kNaN},
  };
  const Texture texture = rampTexture(4, 4);
  for (const Row& row : rows)
    for (Wrap wrap : {Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat})
      for (Filter filter : {Filter::Nearest, Filter::Linear}) {
        const Vec4 texel = sample(texture, samplerFor(filter, wrap), row.s, 0.5, 0.0);
        EXPECT_TRUE(texel.allFinite()) << row.expected;
        EXPECT_GE(texel.minCoeff(), 0.0) << row.expected;
        EXPECT_LE(texel.maxCoeff(), 1.0) << row.expected;
      }
}

TEST(RenderExtremes, AQuadWhoseTextureCoordinatesAreOffsetBy1e9DrawsTheSameImage) {
  // "a screen-filling quad with (s, t) + 1e9 under REPEAT: the image of (s, t), NEAREST identical, LINEAR within
  // 1e-5 (the interpolated s carries 1e9 eps = 1.2e-7)"
  const Texture texture = rampTexture(64, 64);
  for (Filter filter : {Filter::Nearest, Filter::Linear}) {
    Rendering images[2];
    for (int shifted = 0; shifted < 2; ++shifted) {
      Mesh mesh;
      mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
      mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
      const double offset = shifted ? 1e9 : 0.0;
      const Vec4 st[4] = {{offset, offset, 0, 1},
                          {offset + 1, offset, 0, 1},
                          {offset + 1, offset + 1, 0, 1},
                          {offset, offset + 1, 0, 1}};
      TexcoordSource texcoords;
      for (const Triangle& t : mesh.triangles)
        for (int v : t) texcoords.corners.push_back(st[v]);
      RenderOptions o;
      o.camera.width = o.camera.height = 64;
      o.camera.clipFromView = orthographic(-1, 1, -1, 1, -1, 1);
      o.texture = &texture;
      o.sampler = samplerFor(filter, Wrap::Repeat);
      images[shifted] = render(mesh, texcoords, o);
    }
    ASSERT_EQ(images[0].coveredPixels, 64u * 64u);
    for (std::size_t i = 0; i < images[0].colour.pixels.size(); ++i) {
      if (filter == Filter::Nearest) {
        ASSERT_EQ(images[1].colour.pixels[i], images[0].colour.pixels[i]) << "NEAREST, value " << i;
      } else {
        ASSERT_NEAR(images[1].colour.pixels[i], images[0].colour.pixels[i], 1e-5) << "LINEAR, value " << i;
      }
    }
  }
}

// ---- 1 x 1 textures: every filter, every wrap, any coordinate and level of detail ----

TEST(RenderExtremes, AOneByOneTextureGivesItsTexelUnderEveryFilter) {
  const Rgba colour(0.2f, 0.4f, 0.6f, 0.8f);
  Texture texture(TexelLevel{1, 1, {colour}}, false);
  texture.buildMipmaps();  // nothing to build: 1 x 1 is complete
  EXPECT_EQ(texture.levelCount(), 1);
  EXPECT_TRUE(texture.hasMipmaps());
  const Vec4 expected = colour.cast<double>();
  for (Filter filter : {Filter::Nearest, Filter::Linear, Filter::NearestMipmapNearest, Filter::LinearMipmapNearest,
                        Filter::NearestMipmapLinear, Filter::LinearMipmapLinear})
    for (Wrap wrap : {Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat})
      for (double s : {0.0, 0.3, 0.999, -0.5, 1e9 + 0.25, -1e300, kInf, kNaN})
        for (double lambda : {-kInf, -3.0, 0.0, 0.3, 0.5, 0.7, 5.0, kInf, kNaN}) {
          const Vec4 got = sample(texture, samplerFor(filter, wrap), s, 0.7, lambda);
          // LINEAR blends four copies of the texel with weights that sum to 1 up to rounding.
          EXPECT_LE((got - expected).cwiseAbs().maxCoeff(), 1e-15)
              << "1 x 1: every filter returns the texel; filter " << int(filter) << ", wrap " << int(wrap) << ", s "
              << s << ", lambda " << lambda;
        }
}

TEST(RenderExtremes, AOneByOneTextureDrawsItsColourOnEveryCoveredPixel) {
  // "1 x 1 texture, LINEAR_MIPMAP_LINEAR, a tilted quad under perspective: every covered pixel is the texel"
  const Rgba colour(0.2f, 0.4f, 0.6f, 1.0f);
  Texture texture(TexelLevel{1, 1, {colour}}, false);
  texture.buildMipmaps();
  Mesh mesh;
  mesh.positions = {{-3, -1, -2}, {3, -1, -2}, {3, 1, -40}, {-3, 1, -40}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  TexcoordSource texcoords;
  const Vec4 st[4] = {{0, 0, 0, 1}, {50, 0, 0, 1}, {50, 50, 0, 1}, {0, 50, 0, 1}};
  for (const Triangle& t : mesh.triangles)
    for (int v : t) texcoords.corners.push_back(st[v]);
  RenderOptions o = nearPlaneOptions(texture);
  o.sampler = samplerFor(Filter::LinearMipmapLinear, Wrap::Repeat);
  const Rendering r = render(mesh, texcoords, o);
  ASSERT_GT(r.coveredPixels, 0u);
  for (int row = 0; row < kSize; ++row)
    for (int x = 0; x < kSize; ++x) {
      if (r.aovs.at(x, row, 3) < 0) continue;
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(r.colour.at(x, row, c), colour[c], 1e-6) << x << ", " << row;
    }
}

// ---- the largest textures: 16 bytes a texel, so 16384 x 16384 would take 4 GiB: refused ----

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(RenderExtremes, TexturesAbove2GiBAreRefusedWithAUsageErrorBeforeAllocating) {
  const std::string refusal =
      "texture: 16384 x 16384 texels would take 4 GiB as float RGBA, more than the 2 GiB limit (134217728 texels, "
      "e.g. 16384 x 8192)";
  struct Row {
    const char* expected;
    std::function<void()> make;
    std::string message;
  };
  const Row rows[] = {
      {"Texture of 16384 x 16384 (no texels given): the size is refused first",
       [] {
         Texture(TexelLevel{16384, 16384, {}}, true);
       },
       refusal},
      {"checkerTexture(16384, 8): refused before allocating", [] { checkerTexture(16384, 8); }, refusal},
      {"proceduralTexture(\"checker:16384\"): refused before allocating", [] { proceduralTexture("checker:16384"); },
       refusal},
      {"16384 x 8193 (one row over 2^27 texels): refused", [] { checkTextureSize(16384, 8193); },
       "texture: 16384 x 8193 texels would take 2.00024 GiB as float RGBA, more than the 2 GiB limit (134217728 "
       "texels, e.g. 16384 x 8192)"},
      {"16384 x 8192 (2^27 texels, 2 GiB): accepted by the size check", [] { checkTextureSize(16384, 8192); },
       "accepted"},
      {"a 16384 x 1 texture: accepted and sampled like any other",
       [] {
         Texture texture = rampTexture(16384, 1);
         if (!sample(texture, samplerFor(Filter::Linear, Wrap::Repeat), 0.5, 0.5, 0.0).allFinite())
           throw UsageError("not finite");
       },
       "accepted"},
  };
  for (const Row& row : rows) EXPECT_EQ(errorOf(row.make), row.message) << row.expected;
}

// A mesh at 2^700 or 2^-700 (1e210, 1e-211), framed by its bounding sphere, draws the picture of
// the same mesh at unit scale bit for bit: a power of two scales every position exactly, and the
// frame's bounding sphere, lookAt, perspective and clip coordinates keep every quotient of the
// unit-scale frame (before, products of two coordinates overflowed or underflowed: nothing drawn).
TEST(RenderExtremes, AMeshAt2To700Or2ToMinus700DrawsTheUnitScalePicture) {
  const Mesh unit = meshes::icosphere(3);
  TexcoordSource texcoords;
  for (const Triangle& t : unit.triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = unit.positions[t[k]];
      texcoords.corners.emplace_back(p.x(), p.y(), 0.0, 1.0);  // a planar mapping, the same at every scale
    }
  const Texture texture = rampTexture(16, 16);
  const auto draw = [&](double scale, const Projection& projection) {
    Mesh mesh = unit;
    for (Vec3& p : mesh.positions) p *= scale;
    RenderOptions o;
    o.camera = frameSphere(boundingSphere(mesh.positions), Vec3(1, 2, 3), Vec3::UnitY(), projection, 48, 32);
    o.texture = &texture;
    o.sampler.minFilter = o.sampler.magFilter = Filter::Linear;
    o.raster.cull = Cull::None;
    return render(mesh, texcoords, o);
  };
  for (const Projection projection : {Projection{false, 45.0}, Projection{true, 45.0}}) {
    const Rendering reference = draw(1.0, projection);
    EXPECT_GT(reference.coveredPixels, 400u);
    for (const double scale : {0x1p700, 0x1p-700}) {
      const Rendering r = draw(scale, projection);
      EXPECT_EQ(r.coveredPixels, reference.coveredPixels) << scale << " orthographic " << projection.orthographic;
      EXPECT_EQ(r.colour.pixels, reference.colour.pixels) << scale << " orthographic " << projection.orthographic;
    }
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::render
