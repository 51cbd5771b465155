// The renderer against a real OpenGL: every scene is drawn by uvtk and by Mesa's fixed-function
// pipeline through OSMesa with the same matrices, texels, sampler and environment, and the two
// images are compared pixel by pixel. OSMesa runs on its default gallium driver, llvmpipe (here
// Mesa 22.3.6, LLVM 15, 256-bit vectors; GALLIUM_DRIVER=softpipe would select softpipe, which
// passes all but the llvmpipe-specific mipmap and seamless cube map tests, skipped then). The
// statistics of every scene are printed ("[mesa] ...") and recorded as test properties.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "render/mesa_scene.h"
#include "render/procedural.h"
#include "render/renderer.h"
#include "texgen/texgen.h"

namespace uvtk::render {
namespace {
namespace UVTK_TEST_FILE {

using namespace mesa;

// The sphere of 16 x 8 quads, textured through its fixed corners.
Scene sphere(std::string name, const Texture& texture, Filter filter) {
  Scene s = sphereMesh(std::move(name), 16, 8);
  s.texture = &texture;
  s.filter = filter;
  return s;
}

// The scene with texture coordinates from texgen: uvtk gets generateTexcoords' corners, Mesa
// the same options as glTexGen state.
Scene withTexgen(Scene s, texgen::TexgenOptions options) {
  s.texgen = texgenCorners(s, std::move(options));
  return s;
}

Scene texgenSphere(std::string name, const Texture& texture, Filter filter, texgen::TexgenOptions options) {
  return withTexgen(sphere(std::move(name), texture, filter), std::move(options));
}

// A finer sphere, nearer, looking up a cube map with (s, t, r) from texgen `mode` (NORMAL_MAP or
// REFLECTION_MAP) on all three: uvtk interpolates the generated (s, t, r, q = 1) corners. It fills
// the view but its left and right sides; the eye-space directions it shows cross the +Z face's
// four edges and corners (and with REFLECTION_MAP every face towards the rim).
Scene cubeMappedSphere(std::string name, const CubeTexture& cube, Filter filter, bool seamless,
                       texgen::TexgenMode mode) {
  Scene base = sphereMesh(std::move(name), 32, 16);
  base.camera = perspectiveCamera(Vec3(0.2, 0.3, 2.3), Vec3::Zero(), 45.0, 0.5, 10.0);
  texgen::TexgenOptions options;
  for (int i = 0; i < 3; ++i) options.coordinates[std::size_t(i)] = {mode, Vec4::Zero()};
  Scene s = withTexgen(std::move(base), options);
  s.cubeTexture = &cube;
  s.seamless = seamless;
  s.filter = filter;
  s.wrap = Wrap::ClampToEdge;
  return s;
}

// Both renderings of one scene: uvtk's with its AOVs, Mesa's colours and Mesa's face ids.
struct Renderings {
  Rendering ours;
  std::vector<std::uint8_t> theirs, theirFaces;

  int face(int x, int row) const { return int(ours.aovs.at(x, row, 3)); }
  int mesaFace(int x, int row) const {
    const std::uint8_t* p = &theirFaces[(std::size_t(row) * kWidth + std::size_t(x)) * 4];
    return int(p[0] | (p[1] << 8) | (p[2] << 16)) - 1;
  }
  int mesa(int x, int row, int channel) const {
    return theirs[(std::size_t(row) * kWidth + std::size_t(x)) * 4 + std::size_t(channel)];
  }
  // A pixel is an edge pixel when uvtk's face AOV changes within its 3 x 3 neighbourhood.
  bool isEdge(int x, int row) const {
    for (int ny = std::max(0, row - 1); ny <= std::min(kHeight - 1, row + 1); ++ny)
      for (int nx = std::max(0, x - 1); nx <= std::min(kWidth - 1, x + 1); ++nx)
        if (face(nx, ny) != face(x, row)) return true;
    return false;
  }
};

Renderings renderBoth(Mesa& mesa, const Scene& s) {
  return {render(s.mesh, texcoords(s), uvtkOptions(s)), mesa.draw(s, Mesa::Pass::Colour),
          mesa.draw(s, Mesa::Pass::FaceIds)};
}

// Pixel statistics of one comparison. Differences are in 8-bit steps (1/255), per pixel the
// largest over R, G and B.
struct Comparison {
  std::string scene;
  std::size_t covered = 0;              // pixels uvtk drew
  std::size_t compared = 0;             // covered non-edge pixels
  std::size_t equal = 0;                // ... with identical RGB bytes
  std::size_t interiorFaceDiffers = 0;  // non-edge pixels (background included) where Mesa drew another face
  int maxDifference = 0;
  double meanDifference = 0;  // over channels of the compared pixels
  std::size_t edge = 0, edgeFaceDiffers = 0;
  std::string firstDifference;  // the first compared pixel that differs, for the log
  // |uvtk's lambda - Mesa's| where either is below the coarsest level (compareWithMesasLevelOfDetail).
  double lodDifferenceMax = 0, lodDifferenceMean = 0;

  double equalFraction() const { return compared ? double(equal) / double(compared) : 0.0; }

  // Accumulates one compared pixel: uvtk's RGB against Mesa's bytes.
  void add(const Vec3& ours, const Renderings& r, int x, int row) {
    ++compared;
    int difference = 0;
    std::array<int, 3> a{}, b{};
    for (int c = 0; c < 3; ++c) {
      a[std::size_t(c)] = toByte(ours[c]);
      b[std::size_t(c)] = r.mesa(x, row, c);
      const int d = std::abs(a[std::size_t(c)] - b[std::size_t(c)]);
      difference = std::max(difference, d);
      meanDifference += d;  // a sum until finish()
    }
    maxDifference = std::max(maxDifference, difference);
    equal += difference == 0;
    if (difference != 0 && firstDifference.empty()) {
      std::ostringstream out;
      out << "; first difference at (" << x << ", " << row << "): uvtk " << a[0] << " " << a[1] << " " << a[2]
          << ", Mesa " << b[0] << " " << b[1] << " " << b[2] << ", uv " << r.ours.aovs.at(x, row, 0) << " "
          << r.ours.aovs.at(x, row, 1) << ", lod " << r.ours.aovs.at(x, row, 4);
      if (r.ours.aovs.channels > 5) out << ", cube face " << r.ours.aovs.at(x, row, 5);
      firstDifference = out.str();
    }
  }
  void finish();
};

std::ostream& operator<<(std::ostream& out, const Comparison& c) {
  out << c.scene << ": compared " << c.compared << " (identical " << c.equal << " = " << 100.0 * c.equalFraction()
      << "%, max diff " << c.maxDifference << ", mean diff " << c.meanDifference << ")";
  if (c.covered)
    out << ", covered " << c.covered << ", edge " << c.edge << " (coverage differs " << c.edgeFaceDiffers
        << "), interior coverage differs " << c.interiorFaceDiffers;
  if (c.lodDifferenceMax > 0)
    out << ", lambda differs by max " << c.lodDifferenceMax << ", mean " << c.lodDifferenceMean;
  return out << c.firstDifference;
}

void Comparison::finish() {
  if (compared) meanDifference /= 3.0 * double(compared);
  std::cout << "[mesa] " << *this << "\n";
  std::ostringstream out;
  out << *this;
  testing::Test::RecordProperty(scene, out.str());
}

// Which edge pixels a comparison takes: none, or those where Mesa drew the triangle uvtk drew. An
// edge pixel's colour is that triangle's at the pixel centre in both, but for its level of detail,
// which Mesa takes per 2 x 2 quad across the edge: fine for filters without mipmaps.
enum class EdgePixels { Skipped, WhereSameTriangle };

// uvtk's image against Mesa's over the non-edge pixels (and the edge pixels `edges` says), and
// the coverage of both everywhere.
Comparison compare(const Scene& s, const Renderings& r, EdgePixels edges = EdgePixels::Skipped) {
  Comparison c;
  c.scene = s.name;
  for (int row = 0; row < kHeight; ++row)
    for (int x = 0; x < kWidth; ++x) {
      c.covered += r.face(x, row) >= 0;
      const bool sameFace = r.face(x, row) == r.mesaFace(x, row);
      if (r.isEdge(x, row)) {
        ++c.edge;
        c.edgeFaceDiffers += !sameFace;
        if (edges == EdgePixels::Skipped || !sameFace) continue;
      } else {
        c.interiorFaceDiffers += !sameFace;
      }
      if (r.face(x, row) < 0) continue;  // the background: its coverage is all there is to compare
      c.add(Vec3(r.ours.colour.at(x, row, 0), r.ours.colour.at(x, row, 1), r.ours.colour.at(x, row, 2)), r, x, row);
    }
  c.finish();
  return c;
}

void expectCoverageAgrees(const Comparison& c) {
  EXPECT_EQ(c.interiorFaceDiffers, 0u) << c;
  // Both snap vertices to 1/256 pixel and own edges by the top-left rule, so only a centre within
  // rounding distance of an edge may fall differently: measured 0 pixels in every scene but the
  // ground plane (1 of 488, on its far edge near the horizon).
  EXPECT_LE(c.edgeFaceDiffers, c.edge / 200) << c;
}

// Every scene must show enough of itself for its statistics to mean something.
void expectSubstantial(const Comparison& c) { EXPECT_GE(c.compared, std::size_t(kWidth * kHeight / 8)) << c; }

// NEAREST: all pixels but those whose texel coordinate lies within float rounding of a texel
// boundary (Mesa interpolates in float, uvtk in double). Measured: 100% in every scene.
void expectNearestMatch(const Comparison& c) {
  expectSubstantial(c);
  expectCoverageAgrees(c);
  EXPECT_GE(c.equalFraction(), 0.999) << c;
}

// LINEAR: llvmpipe's float filter (Mesa::Filtering::Float: its default 8-bit fixed-point weights
// made these scenes only 47.9% (ramp texture, lit) to 96.6% (checker) identical, though never
// more than 1 step apart) against uvtk's double one can round the last bit differently.
// Measured: 99.81% to 100% identical, never more than 1 step apart.
void expectLinearMatch(const Comparison& c) {
  expectSubstantial(c);
  expectCoverageAgrees(c);
  EXPECT_GE(c.equalFraction(), 0.995) << c;
  EXPECT_LE(c.maxDifference, 1) << c;
}

TEST(MesaRender, PerspectiveTexturedQuadsMatchMesaPixelForPixel) {
  Mesa mesa(Mesa::Filtering::Float);
  ASSERT_TRUE(mesa.ok());
  std::cout << "[mesa] " << mesa.renderer() << "\n";
  testing::Test::RecordProperty("GL_RENDERER", mesa.renderer());
  const Texture checker = checkerTexture(64, 8);
  const Texture ramp = rampTexture(32, 32);
  for (const Texture* texture : {&checker, &ramp}) {
    const std::string name = texture == &checker ? "quad checker:64:8" : "quad ramp32";
    const auto scene = [&](const std::string& variant, Filter filter, Wrap wrap, double lo, double hi) {
      const Scene s = tiltedQuad(name + " " + variant, *texture, filter, wrap, lo, hi);
      return compare(s, renderBoth(mesa, s));
    };
    expectNearestMatch(scene("nearest repeat", Filter::Nearest, Wrap::Repeat, -0.5, 1.5));
    expectLinearMatch(scene("linear clamp", Filter::Linear, Wrap::ClampToEdge, -0.25, 1.25));
    expectLinearMatch(scene("linear mirrored", Filter::Linear, Wrap::MirroredRepeat, -1.5, 2.5));
  }
}

TEST(MesaRender, CulledDepthTestedSphereMatchesMesaPixelForPixel) {
  Mesa mesa(Mesa::Filtering::Float);
  ASSERT_TRUE(mesa.ok());
  const Texture ramp = rampTexture(32, 32);
  const Scene nearest = sphere("sphere ramp32 nearest", ramp, Filter::Nearest);
  expectNearestMatch(compare(nearest, renderBoth(mesa, nearest)));
  const Scene linear = sphere("sphere ramp32 linear", ramp, Filter::Linear);
  expectLinearMatch(compare(linear, renderBoth(mesa, linear)));
}

TEST(MesaRender, TexgenObjectLinearAndSphereMapMatchMesasGeneratedCoordinates) {
  Mesa mesa(Mesa::Filtering::Float);
  ASSERT_TRUE(mesa.ok());
  const Texture ramp = rampTexture(32, 32);
  texgen::TexgenOptions objectLinear;
  objectLinear.coordinates[0] = {texgen::TexgenMode::ObjectLinear, Vec4(0.35, -0.2, 0.15, 0.5)};
  objectLinear.coordinates[1] = {texgen::TexgenMode::ObjectLinear, Vec4(0.1, 0.3, -0.25, 0.5)};
  objectLinear.coordinates[3] = {texgen::TexgenMode::ObjectLinear, Vec4(0.1, 0.05, 0.2, 1.0)};  // projective
  texgen::TexgenOptions sphereMap;
  sphereMap.coordinates[0] = {texgen::TexgenMode::SphereMap, Vec4::Zero()};
  sphereMap.coordinates[1] = {texgen::TexgenMode::SphereMap, Vec4::Zero()};
  for (const auto& [name, options] :
       {std::pair{"texgen object linear", objectLinear}, std::pair{"texgen sphere map", sphereMap}}) {
    const Scene nearest = texgenSphere(std::string(name) + " nearest", ramp, Filter::Nearest, options);
    expectNearestMatch(compare(nearest, renderBoth(mesa, nearest)));
    const Scene linear = texgenSphere(std::string(name) + " linear", ramp, Filter::Linear, options);
    expectLinearMatch(compare(linear, renderBoth(mesa, linear)));
  }
}

// Cube maps (GL 4.6 §8.13): a sphere whose NORMAL_MAP or REFLECTION_MAP (s, t, r) looks up
// cubeindex:32 (every texel's bytes name its face and texel) and cube:64, faces filtered alone
// with CLAMP_TO_EDGE as GL does without TEXTURE_CUBE_MAP_SEAMLESS; LINEAR also on cubeindex:4,
// whose half-texel bands along the face edges cover a fifth to a third of the sphere (there the
// seamless mode below differs). Every pixel both drew with the same triangle is compared (all but one).
// Measured on llvmpipe: NEAREST 100% identical in all four scenes; LINEAR 100% but for cube:64
// (99.98% with reflection_map, 99.99% with normal_map, max diff 1: float against double weights).
TEST(MesaRender, CubeMappedSphereMatchesMesaPerFace) {
  Mesa mesa(Mesa::Filtering::Float);
  ASSERT_TRUE(mesa.ok());
  const CubeTexture index = cubeIndexTexture(32), checker = cubeCheckerTexture(64), coarse = cubeIndexTexture(4);
  for (const auto& [mode, modeName] : {std::pair{texgen::TexgenMode::ReflectionMap, "reflection_map"},
                                       std::pair{texgen::TexgenMode::NormalMap, "normal_map"}})
    for (const auto& [cube, cubeName] :
         {std::pair{&index, "cubeindex:32"}, std::pair{&checker, "cube:64"}, std::pair{&coarse, "cubeindex:4"}}) {
      const std::string name = std::string("cube ") + modeName + " " + cubeName;
      if (cube != &coarse) {
        const Scene nearest = cubeMappedSphere(name + " nearest", *cube, Filter::Nearest, false, mode);
        expectNearestMatch(compare(nearest, renderBoth(mesa, nearest), EdgePixels::WhereSameTriangle));
      }
      const Scene linear = cubeMappedSphere(name + " linear clamp", *cube, Filter::Linear, false, mode);
      expectLinearMatch(compare(linear, renderBoth(mesa, linear), EdgePixels::WhereSameTriangle));
    }
}

// Where a seamless LINEAR lookup of uvtk's rendering reaches beyond its face: pixels with a tap
// beyond an edge, those with a tap beyond a corner (both indices out), and those whose bytes
// differ from the same scene filtered per face.
struct SeamlessReach {
  std::size_t acrossEdge = 0, beyondCorner = 0, differsFromPerFace = 0;
};

SeamlessReach seamlessReach(const Scene& s, const Rendering& seamless) {
  Scene perFace = s;
  perFace.seamless = false;
  const Rendering clamped = render(s.mesh, texcoords(s), uvtkOptions(perFace));
  const int n = s.cubeTexture->size();
  // LINEAR's taps floor(c n - 1/2) and one more, the upper one read when its weight is not 0.
  const auto outside = [n](double c) {
    const LinearTap tap = linearTap(std::clamp(c, 0.0, 1.0), n);
    return tap.lower < 0 || (tap.lower + 1 >= n && tap.alpha > 0);
  };
  SeamlessReach reach;
  for (int row = 0; row < kHeight; ++row)
    for (int x = 0; x < kWidth; ++x) {
      if (seamless.aovs.at(x, row, 3) < 0) continue;
      const bool outS = outside(seamless.aovs.at(x, row, 0)), outT = outside(seamless.aovs.at(x, row, 1));
      reach.acrossEdge += outS || outT;
      reach.beyondCorner += outS && outT;
      bool differs = false;
      for (int c = 0; c < 3; ++c)
        differs |= toByte(clamped.colour.at(x, row, c)) != toByte(seamless.colour.at(x, row, c));
      reach.differsFromPerFace += differs;
    }
  std::cout << "[mesa] " << s.name << ": a tap beyond an edge at " << reach.acrossEdge << " pixels, beyond a corner at "
            << reach.beyondCorner << ", differs from per-face filtering at " << reach.differsFromPerFace << "\n";
  return reach;
}

// GL_TEXTURE_CUBE_MAP_SEAMLESS against uvtk's seamless mode: LINEAR reads across face edges, and
// beyond a cube corner the mean of the three texels meeting there (GL 4.6 §8.14.2's suggestion,
// which llvmpipe follows). cubeindex:4's texels are large enough for the cube corners in view to
// cover pixels. Measured on llvmpipe: 100% identical but for cube:64 (99.97% with reflection_map,
// 99.99% with normal_map, max diff 1), with the two modes differing at 316, 180, 2634 pixels
// (reflection_map: cubeindex:32, cube:64, cubeindex:4) and 184, 89, 1725 (normal_map), of which
// 1, 0, 288 and 1, 0, 167 read beyond a corner. softpipe agrees only to 97.2% (cubeindex:4) and
// differs away from corners too: on cube:64 by up to 59 steps at +Y's s = 0.0066, t = 0.5, where
// GL's LINEAR weight of the -X texels beyond the edge is 1 - frac(64 s - 1/2) = 8% (uvtk's blue
// 15 of -X's 191) and softpipe gives them about 40% (74). The bounds are therefore llvmpipe's.
TEST(MesaRender, SeamlessCubeMapFilteringMatchesMesas) {
  Mesa mesa(Mesa::Filtering::Float);
  ASSERT_TRUE(mesa.ok());
  if (!mesa.seamlessCubeMaps()) GTEST_SKIP() << mesa.renderer() << " has neither GL 3.2 nor ARB_seamless_cube_map";
  if (mesa.renderer().rfind("llvmpipe", 0) != 0) GTEST_SKIP() << "the bounds are llvmpipe's, not " << mesa.renderer();
  const CubeTexture index = cubeIndexTexture(32), checker = cubeCheckerTexture(64), coarse = cubeIndexTexture(4);
  for (const auto& [mode, modeName] : {std::pair{texgen::TexgenMode::ReflectionMap, "reflection_map"},
                                       std::pair{texgen::TexgenMode::NormalMap, "normal_map"}})
    for (const auto& [cube, cubeName] :
         {std::pair{&index, "cubeindex:32"}, std::pair{&checker, "cube:64"}, std::pair{&coarse, "cubeindex:4"}}) {
      const Scene s = cubeMappedSphere(std::string("cube ") + modeName + " " + cubeName + " linear seamless", *cube,
                                       Filter::Linear, true, mode);
      const Renderings r = renderBoth(mesa, s);
      expectLinearMatch(compare(s, r, EdgePixels::WhereSameTriangle));
      const SeamlessReach reach = seamlessReach(s, r.ours);
      EXPECT_GE(reach.differsFromPerFace, 50u) << s.name;  // the scene tells the two modes apart
      if (cube == &coarse) {
        EXPECT_GE(reach.beyondCorner, 50u) << s.name;
      }
    }
}

TEST(MesaRender, HeadlitModulatedSphereMatchesMesasLighting) {
  Mesa mesa(Mesa::Filtering::Float);
  ASSERT_TRUE(mesa.ok());
  const Texture ramp = rampTexture(32, 32);
  Scene s = sphere("sphere ramp32 linear modulate", ramp, Filter::Linear);
  s.env = EnvMode::Modulate;
  // Mesa lights the vertices in float, uvtk in double: the same 1-step bound as LINEAR alone.
  expectLinearMatch(compare(s, renderBoth(mesa, s)));
}

// The sphere opened towards the camera (the triangles whose centre lies within 60 degrees of the
// eye's direction left out), drawn without culling, lit: around the hole the outside's front
// faces, through it the inside's back faces, which GL lights with their normals negated when
// two-sided and leaves in the ambient term when not.
Scene openSphere(std::string name, const Texture& texture, bool twoSided) {
  Scene s = sphere(std::move(name), texture, Filter::Linear);
  const Vec3 eyeInWorld(0.2, 0.3, 2.0);  // nearer than sphere()'s: more pixels inside faces
  s.camera = perspectiveCamera(eyeInWorld, Vec3::Zero(), 45.0, 0.5, 10.0);
  const Vec3 eye = (s.worldFromObject.inverse() * eyeInWorld.homogeneous()).head<3>().normalized();
  std::vector<Triangle> kept;
  std::vector<Vec4> corners;
  for (std::size_t f = 0; f < s.mesh.triangles.size(); ++f) {
    const Triangle& t = s.mesh.triangles[f];
    const Vec3 centre = (s.mesh.positions[std::size_t(t[0])] + s.mesh.positions[std::size_t(t[1])] +
                         s.mesh.positions[std::size_t(t[2])]) / 3.0;
    if (centre.normalized().dot(eye) > 0.5) continue;
    kept.push_back(t);
    for (std::size_t k = 0; k < 3; ++k) corners.push_back(s.corners[3 * f + k]);
  }
  s.mesh.triangles = std::move(kept);
  s.corners = std::move(corners);
  s.cull = Cull::None;
  s.env = EnvMode::Modulate;
  s.twoSided = twoSided;
  return s;
}

TEST(MesaRender, BackFacesLitOneAndTwoSidedMatchMesasLighting) {
  Mesa mesa(Mesa::Filtering::Float);
  ASSERT_TRUE(mesa.ok());
  const Texture ramp = rampTexture(32, 32);
  const Scene one = openSphere("open sphere ramp32 linear modulate one-sided", ramp, false);
  const Scene two = openSphere("open sphere ramp32 linear modulate two-sided", ramp, true);
  const Renderings r1 = renderBoth(mesa, one), r2 = renderBoth(mesa, two);
  expectLinearMatch(compare(one, r1));
  expectLinearMatch(compare(two, r2));
  // The inside shows through the hole: the two lightings differ there, by far more than rounding.
  std::size_t brighter = 0;
  for (int row = 0; row < kHeight; ++row)
    for (int x = 0; x < kWidth; ++x)
      brighter += r2.ours.colour.at(x, row, 0) > r1.ours.colour.at(x, row, 0) + 0.2f;
  EXPECT_GE(brighter, 500u);
}

// log2 as llvmpipe computes it for a mipmap-linear filter (gallivm lp_build_fast_log2): the
// exponent plus the mantissa less one, piecewise linear between powers of two.
double piecewiseLinearLog2(double x) {
  int exponent = 0;
  const double mantissa = 2 * std::frexp(x, &exponent);  // x = mantissa 2^(exponent - 1), mantissa in [1, 2)
  return (exponent - 1) + (mantissa - 1);
}

// uvtk's sampler fed with the level of detail Mesa computes, to isolate every other part of the
// mipmapped lookup (the levels, level selection, the blend between levels): per 2 x 2 quad of
// the window (rows 2k, 2k + 1), one lambda from the differences of (s, t) from its top-left pixel
// to the right and lower neighbours (gallivm lp_build_packed_ddx_ddy; the top-left in uvtk's
// image, found by trying: the bottom-left matches only 72% of linear_mipmap_linear pixels), its
// log2 as llvmpipe takes it (exact for mipmap-nearest filters). Quads are compared where uvtk
// drew one face on all four pixels, using uvtk's (u, v) AOV.
Comparison compareWithMesasLevelOfDetail(const Scene& s, const Renderings& r) {
  Comparison c;
  c.scene = s.name + " with Mesa's per-quad lambda";
  const SamplerState sampler = samplerFor(s.filter, s.wrap);
  const auto uv = [&](int x, int row) { return Vec2(r.ours.aovs.at(x, row, 0), r.ours.aovs.at(x, row, 1)); };
  const double coarsest = s.texture->levelCount() - 1;
  std::size_t lodCount = 0;
  for (int row = 0; row < kHeight; row += 2)
    for (int x = 0; x < kWidth; x += 2) {
      const int f = r.face(x, row);
      if (f < 0 || r.face(x + 1, row) != f || r.face(x, row + 1) != f || r.face(x + 1, row + 1) != f) continue;
      const double lambda = levelOfDetail(s.texture->width(), s.texture->height(), uv(x + 1, row) - uv(x, row),
                                          uv(x, row + 1) - uv(x, row));
      const double lambdaUsed =
          s.filter == Filter::LinearMipmapLinear ? 0.5 * piecewiseLinearLog2(std::exp2(2 * lambda)) : lambda;
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
          const Vec2 p = uv(x + dx, row + dy);
          c.add(sample(*s.texture, sampler, p.x(), p.y(), lambdaUsed).head<3>(), r, x + dx, row + dy);
          const double ours = r.ours.aovs.at(x + dx, row + dy, 4);
          if (std::min(ours, lambda) >= coarsest) continue;  // both take the 1 x 1 level
          c.lodDifferenceMax = std::max(c.lodDifferenceMax, std::abs(ours - lambda));
          c.lodDifferenceMean += std::abs(ours - lambda);
          ++lodCount;
        }
    }
  if (lodCount) c.lodDifferenceMean /= double(lodCount);
  c.finish();
  return c;
}

// Mesa takes one lambda per 2 x 2 quad from finite differences, uvtk the analytic derivative at
// each pixel, so the images differ where the two lambdas straddle a level switch (NEAREST_MIPMAP_
// NEAREST) or blend the levels in other proportions (LINEAR_MIPMAP_LINEAR). Measured on llvmpipe:
//   nearest_mipmap_nearest: 98.51% identical, max diff 128 (a whole level: white against grey), mean 1.90
//   linear_mipmap_linear:   62.74% identical, max diff 17, mean 1.19
// With Mesa's lambda substituted, uvtk's lookup gives 100% and 99.95% identical (max diff 1): the
// levels, the level selection and the blend between levels agree, and all of the difference is
// lambda's, which differs from uvtk's by at most 0.24 (mean 0.073) below the coarsest level.
TEST(MesaRender, MipmappedRecedingPlaneMatchesMesaUpToItsPerQuadLevelOfDetail) {
  Mesa mesa(Mesa::Filtering::Float);
  ASSERT_TRUE(mesa.ok());
  if (mesa.renderer().rfind("llvmpipe", 0) != 0) GTEST_SKIP() << "the bounds are llvmpipe's, not " << mesa.renderer();
  Texture checker = checkerTexture(64, 8);
  checker.buildMipmaps();
  const double period = 2.0;  // 64 texels every 2 units
  const Scene nearest =
      groundPlane("ground checker:64:8 nearest_mipmap_nearest", checker, Filter::NearestMipmapNearest, period);
  const Scene linear =
      groundPlane("ground checker:64:8 linear_mipmap_linear", checker, Filter::LinearMipmapLinear, period);
  for (const Scene* s : {&nearest, &linear}) {
    const Renderings r = renderBoth(mesa, *s);
    const Comparison direct = compare(*s, r);
    expectSubstantial(direct);
    expectCoverageAgrees(direct);
    const Comparison emulated = compareWithMesasLevelOfDetail(*s, r);
    EXPECT_GE(emulated.compared, direct.compared * 9 / 10) << emulated;  // whole quads cover nearly all
    EXPECT_GE(emulated.equalFraction(), 0.995) << emulated;
    EXPECT_LE(emulated.maxDifference, 1) << emulated;
    // A finite difference across one pixel against the derivative at the pixel: a quarter level
    // on this plane; a derivative off by a factor of 2 would be a whole level off.
    EXPECT_LE(emulated.lodDifferenceMax, 0.3) << emulated;
    EXPECT_LE(emulated.lodDifferenceMean, 0.1) << emulated;
    if (s == &nearest) {
      EXPECT_GE(direct.equalFraction(), 0.98) << direct;
    } else {
      // A trilinear texel moves by at most 255 steps per level of lambda.
      EXPECT_LE(direct.maxDifference, 255 * emulated.lodDifferenceMax) << direct;
      EXPECT_LE(direct.meanDifference, 1.5) << direct;
    }
  }
}

TEST(MesaRender, TriangleCrossingTheEyePlaneIsClippedAsMesaClipsIt) {
  Mesa mesa(Mesa::Filtering::Float);
  ASSERT_TRUE(mesa.ok());
  const Texture ramp = rampTexture(32, 32);
  Scene s;
  s.name = "eye-plane triangle ramp32 nearest";
  // The second corner lies behind the eye (w < 0): only near clipping makes the triangle drawable.
  s.mesh.positions = {Vec3(-2.5, 0, -12), Vec3(0.3, 0, 5), Vec3(3, 0, -12)};
  s.mesh.triangles = {{0, 1, 2}};
  for (const Vec3& p : s.mesh.positions) s.corners.emplace_back(p.x() / 3, -p.z() / 3, 0.0, 1.0);
  s.camera = perspectiveCamera(Vec3(0, 1, 0), Vec3(0.3, 0.2, -4), 60.0, 0.1, 50.0);
  s.texture = &ramp;
  expectNearestMatch(compare(s, renderBoth(mesa, s)));
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::render
