// The rasterizer's speed-ups (per-vertex snapping, the per-face set-up shared with the shading,
// tiles shaded as soon as they are drawn, the texel index arithmetic) must not move a single bit:
// these scenes' colour and AOVs are pinned by checksums of what the renderer drew before them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/gl_matrices.h"
#include "meshes/generators.h"
#include "render/procedural.h"
#include "render/renderer.h"

namespace uvtk::render {
namespace {
namespace UVTK_TEST_FILE {

// FNV-1a (64 bits) over the bytes of the colour floats, then of the AOV floats.
std::uint64_t checksum(const Rendering& r) {
  std::uint64_t h = 0xcbf29ce484222325u;
  for (const std::vector<float>* pixels : {&r.colour.pixels, &r.aovs.pixels})
    for (float f : *pixels) {
      unsigned char bytes[sizeof f];
      std::memcpy(bytes, &f, sizeof f);
      for (unsigned char b : bytes) h = (h ^ b) * 0x100000001b3u;
    }
  return h;
}

// (s, t, 0, q) with q varying over the mesh, so that the perspective division matters.
std::vector<Vec4> projectiveTexcoords(const Mesh& mesh) {
  std::vector<Vec4> corners;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.positions[std::size_t(t[k])];
      const double q = 1.5 + 0.5 * std::sin(3 * p.z());
      corners.emplace_back(q * (0.7 * p.x() + 0.2 * p.y()), q * (0.5 * p.z() - 0.3 * p.y()), 0.0, q);
    }
  return corners;
}

std::vector<Vec4> directionTexcoords(const Mesh& mesh) {
  std::vector<Vec4> corners;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.positions[std::size_t(t[k])];
      corners.emplace_back(p.x() + 0.1, p.y() - 0.05, p.z(), 1.0);
    }
  return corners;
}

// Every 97th face (from the 6th) has no value, to cover the undefined footprint.
PixelMapping sphericalPixelMapping(double rs, double rt) {
  return PixelMapping{[rs, rt](const Vec3& p, const Vec3& n, std::int32_t face) {
                        const Vec3 d = (p + 0.05 * n).normalized();
                        double s = std::atan2(d.y(), d.x()) / kTwoPi;
                        if (s < 0) s += 1.0;
                        const double t = std::acos(std::clamp(d.z(), -1.0, 1.0)) / kPi;
                        if (face % 97 == 5) return Vec4(std::nan(""), 0, 0, 1);
                        return Vec4(rs * s, rt * t, 0.0, 1.0);
                      },
                      true, true};
}

Camera sphereCamera(const Mesh& mesh, int width, int height) {
  return frameSphere(boundingSphere(mesh.positions), Vec3(1, -2, 0.8), Vec3(0, 0, 1), {}, width, height);
}

// Inside the torus knot's tube, looking along it: triangles cross the near plane and the border.
RenderOptions insideKnot(const Texture& texture) {
  RenderOptions o;
  o.aovs = true;
  o.camera.width = 300, o.camera.height = 200;
  o.camera.viewFromWorld = lookAt(Vec3(3, 0, 0), Vec3(3, 1, 0.5), Vec3(0, 0, 1));
  o.camera.clipFromView = perspective(80.0, 1.5, 0.05, 20.0);
  o.texture = &texture;
  o.sampler = samplerFor(Filter::LinearMipmapLinear, Wrap::Repeat);
  o.raster.cull = Cull::None;
  o.env = EnvMode::Modulate;
  return o;
}

struct RenderIdentity : ::testing::Test {
  RenderIdentity() {
    grid.buildMipmaps();
    cube.buildMipmaps();
  }
  Texture grid = Texture::fromImage(uvGridImage(256), true);
  CubeTexture cube = cubeCheckerTexture(64);
  Mesh sphere = meshes::latLongSphere(48, 25);
  Mesh knot = meshes::torusKnot(2, 3, 256, 24);
  RenderOptions base() const {
    RenderOptions o;
    o.aovs = true;
    o.raster.threads = 2;
    return o;
  }
};

// The checksums were computed from the images the renderer drew before the speed-ups (commit
// 24f02c4): the same scenes rendered by a throwaway program whose raw float colour and AOV
// buffers were hashed with this FNV-1a.
TEST_F(RenderIdentity, ScenesDrawTheImagesTheyDrewBeforeTheSpeedUps) {
  {  // trilinear, mirrored repeat, a labelled grid on a coarse sphere
    TexcoordSource tc;
    tc.corners = meshes::latLongCornerTexcoords(sphere, 2, 1);
    RenderOptions o = base();
    o.camera = sphereCamera(sphere, 320, 200);
    o.texture = &grid;
    o.sampler = samplerFor(Filter::LinearMipmapLinear, Wrap::MirroredRepeat);
    EXPECT_EQ(checksum(render(sphere, tc, o)), 0x12fb5112b0377615u);
  }
  {  // projective coordinates, no culling, 2 x 2 samples, lit and modulated
    TexcoordSource tc;
    tc.corners = projectiveTexcoords(sphere);
    RenderOptions o = base();
    o.camera = sphereCamera(sphere, 160, 120);
    o.texture = &grid;
    o.sampler = samplerFor(Filter::LinearMipmapLinear, Wrap::MirroredRepeat);
    o.raster.cull = Cull::None, o.samplesPerPixel = 4, o.env = EnvMode::Modulate;
    o.envColour = Vec4(0.2, 0.4, 0.9, 1.0);
    o.background = Vec3(0.1, 0.2, 0.3);
    EXPECT_EQ(checksum(render(sphere, tc, o)), 0x66319a15a8c596bbu);
  }
  {  // a seamless cube map, trilinear
    TexcoordSource tc;
    tc.corners = directionTexcoords(sphere);
    RenderOptions o = base();
    o.camera = sphereCamera(sphere, 200, 150);
    o.cubeTexture = &cube;
    o.seamless = true;
    o.sampler = samplerFor(Filter::LinearMipmapLinear, Wrap::ClampToEdge);
    EXPECT_EQ(checksum(render(sphere, tc, o)), 0x1cf55bc3287b8a1cu);
  }
  {  // inside the knot: clipped at the near plane, one thread
    TexcoordSource tc;
    tc.corners = projectiveTexcoords(knot);
    RenderOptions o = insideKnot(grid);
    o.raster.threads = 1;
    EXPECT_EQ(checksum(render(knot, tc, o)), 0x30a5b6a45a4ca9a1u);
  }
  {  // the mapping evaluated at every pixel, lit
    TexcoordSource tc;
    tc.pixelMapping = sphericalPixelMapping(4, 2);
    RenderOptions o = base();
    o.camera = sphereCamera(knot, 240, 160);
    o.env = EnvMode::Modulate;
    o.texture = &grid;
    o.sampler = samplerFor(Filter::LinearMipmapLinear, Wrap::Repeat);
    EXPECT_EQ(checksum(render(knot, tc, o)), 0xd33ab556990251edu);
  }
}

TEST_F(RenderIdentity, OneAndTwoThreadsDrawTheSameImage) {
  TexcoordSource tc;
  tc.corners = projectiveTexcoords(knot);
  for (int spp : {1, 4}) {
    RenderOptions o = insideKnot(grid);
    o.samplesPerPixel = spp;
    o.raster.threads = 1;
    const Rendering one = render(knot, tc, o);
    o.raster.threads = 2;
    const Rendering two = render(knot, tc, o);
    EXPECT_GT(one.coveredPixels, 30000u);
    EXPECT_EQ(one.coveredPixels, two.coveredPixels);
    EXPECT_TRUE(one.colour.pixels == two.colour.pixels) << spp;  // bitwise: no NaN in a colour
    ASSERT_EQ(one.aovs.pixels.size(), two.aovs.pixels.size());
    EXPECT_EQ(std::memcmp(one.aovs.pixels.data(), two.aovs.pixels.data(), one.aovs.pixels.size() * sizeof(float)), 0);
  }
}

bool sameBits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0; }

TEST_F(RenderIdentity, EachPixelsSharedSetUpIsTheTriangleInterpolatorOfItsFace) {
  const RenderOptions o = insideKnot(grid);
  const Mat4 clipFromObject = o.camera.clipFromView * o.camera.viewFromWorld;
  std::vector<Vec4> clip;
  for (const Vec3& p : knot.positions) clip.push_back(clipFromObject * p.homogeneous());
  const TiledRaster raster(clip, knot.triangles, o.camera.width, o.camera.height, o.raster);
  const VisibilityBuffer visible = rasterize(clip, knot.triangles, o.camera.width, o.camera.height, o.raster);
  std::size_t checked = 0;
  for (int index = 0; index < raster.tileCount(); ++index) {
    const auto tile = std::make_unique<TiledRaster::Tile>();
    raster.draw(index, *tile);
    for (int y = tile->y0; y <= tile->y1; ++y)
      for (int x = tile->x0; x <= tile->x1; ++x) {
        const DrawnFace* drawn = tile->face[std::size_t(y - tile->y0) * TiledRaster::kTileSize + std::size_t(x - tile->x0)];
        const std::size_t i = visible.index(x, o.camera.height - 1 - y);
        ASSERT_EQ(drawn ? drawn->face : -1, visible.face[i]) << x << ", " << y;
        if (!drawn) continue;
        const Triangle& t = knot.triangles[std::size_t(drawn->face)];
        const TriangleInterpolator fresh(clip[std::size_t(t[0])], clip[std::size_t(t[1])], clip[std::size_t(t[2])],
                                         o.camera.width, o.camera.height);
        ASSERT_TRUE(fresh.valid() && drawn->interpolator.valid());
        const TriangleInterpolator::Barycentrics a = drawn->interpolator.at(x + 0.5, y + 0.5);
        const TriangleInterpolator::Barycentrics b = fresh.at(x + 0.5, y + 0.5);
        ASSERT_TRUE(sameBits(a.b, b.b) && sameBits(a.dbdx, b.dbdx) && sameBits(a.dbdy, b.dbdy)) << x << ", " << y;
        ASSERT_TRUE(sameBits(drawn->interpolator.ndcDepthPlane(), fresh.ndcDepthPlane()));
        ++checked;
      }
  }
  EXPECT_GT(checked, 30000u);
}

// A float texture of values that are no multiples of 1/255, of any size.
Texture smoothTexture(int width, int height) {
  TexelLevel base;
  base.width = width, base.height = height;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      base.texels.emplace_back(float(0.5 + 0.5 * std::sin(0.37 * i + 0.11 * j)), float(i) / float(width),
                               float(j) / float(height), float(0.25 + 0.5 * ((i ^ j) & 1)));
  Texture t(std::move(base), false);
  t.buildMipmaps();
  return t;
}

// The images of every filter, wrap and environment, texture kind, derivative mode, bias, sample
// count and cull mode the renderer has, pinned before the shading was vectorised (issue 26): a
// name per configuration and the checksum of what it drew.
TEST_F(RenderIdentity, EveryConfigurationDrawsTheImageItDrewBeforeTheVectorisedShading) {
  Texture npot = Texture::fromImage(uvGridImage(100), true);
  npot.buildMipmaps();
  const Texture smooth = smoothTexture(64, 64), smoothNpot = smoothTexture(48, 20);
  TexcoordSource projective, perPixel, directions;
  projective.corners = projectiveTexcoords(sphere);
  perPixel.pixelMapping = sphericalPixelMapping(3, 2);
  directions.corners = directionTexcoords(sphere);
  const std::map<std::string, std::uint64_t> expected = {
#include "render/render_matrix_checksums.inc"
  };
  std::map<std::string, std::uint64_t> drawn;
  const auto draw = [&](const std::string& name, const TexcoordSource& tc, RenderOptions o) {
    o.camera = sphereCamera(sphere, 96, 72);
    drawn[name] = checksum(render(sphere, tc, o));
  };
  const char* filterNames[] = {"nearest", "linear", "nmn", "lmn", "nml", "lml"};
  const char* wrapNames[] = {"repeat", "clamp", "mirror"};
  const char* envNames[] = {"replace", "modulate", "decal", "blend"};
  for (int f = 0; f < 6; ++f)
    for (int w = 0; w < 3; ++w)
      for (int e = 0; e < 4; ++e) {
        RenderOptions o = base();
        o.texture = &grid;
        o.sampler = samplerFor(Filter(f), Wrap(w));
        o.env = EnvMode(e);
        o.envColour = Vec4(0.2, 0.4, 0.9, 0.5);
        draw(std::string(filterNames[f]) + "/" + wrapNames[w] + "/" + envNames[e], projective, o);
      }
  for (int f = 0; f < 6; ++f) {
    RenderOptions o = base();
    o.sampler = samplerFor(Filter(f), Wrap::Repeat);
    o.texture = &npot;
    draw(std::string("npot/") + filterNames[f], projective, o);
    o.texture = &smooth;
    draw(std::string("float/") + filterNames[f], projective, o);
    RenderOptions decal = o;  // the smooth texture's alpha varies
    decal.env = EnvMode::Decal;
    draw(std::string("float-decal/") + filterNames[f], projective, decal);
    o.texture = &smoothNpot;
    draw(std::string("float-npot/") + filterNames[f], projective, o);
    o.texture = &grid;
    draw(std::string("per-pixel/") + filterNames[f], perPixel, o);
    o.texture = nullptr, o.cubeTexture = &cube;
    o.sampler.wrapS = o.sampler.wrapT = Wrap::ClampToEdge;
    draw(std::string("cube/") + filterNames[f], directions, o);
    o.seamless = true;
    draw(std::string("cube-seamless/") + filterNames[f], directions, o);
  }
  RenderOptions o = base();
  o.texture = &grid;
  o.sampler = samplerFor(Filter::LinearMipmapLinear, Wrap::Repeat);
  for (double bias : {-1.0, 1.5}) {
    RenderOptions biased = o;
    biased.lodBias = bias;
    draw("bias/" + std::to_string(bias), projective, biased);
  }
  for (Derivatives derivatives : {Derivatives::QuadCoarse, Derivatives::QuadFine}) {
    RenderOptions quad = o;
    quad.derivatives = derivatives;
    draw(std::string("quad/") + toString(derivatives), projective, quad);
    draw(std::string("quad-per-pixel/") + toString(derivatives), perPixel, quad);
  }
  for (int spp : {4, 9}) {
    RenderOptions samples = o;
    samples.samplesPerPixel = spp;
    draw("spp/" + std::to_string(spp), projective, samples);
  }
  for (Cull cull : {Cull::Front, Cull::None}) {
    RenderOptions culled = o;
    culled.raster.cull = cull;
    culled.background = Vec3(0.1, 0.2, 0.3);
    draw(std::string("cull/") + (cull == Cull::Front ? "front" : "none"), projective, culled);
  }
  RenderOptions plain = o;
  plain.aovs = false, plain.raster.threads = 1;
  draw("no-aovs", projective, plain);
  for (const auto& [name, sum] : drawn) {
    const auto found = expected.find(name);
    EXPECT_TRUE(found != expected.end() && found->second == sum)
        << "{\"" << name << "\", 0x" << std::hex << sum << "u},";
  }
  EXPECT_EQ(drawn.size(), expected.size());
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::render
