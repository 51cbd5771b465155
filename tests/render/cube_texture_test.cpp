// Cube-map textures (render/cube_texture.h) and cube-mapped rendering: texel-exact lookups through
// every face, the procedural cube maps, GL's per-face filtering against the seamless mode across
// all 24 edges, atlases, the face (s, t) derivative, mipmaps, and the renderer's cube path.
#include "render/cube_texture.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/gl_matrices.h"
#include "render/procedural.h"
#include "render/quad_fixture.h"
#include "render/renderer.h"

namespace uvtk::render {
namespace {
namespace UVTK_TEST_FILE {

// The texel cubeindex:N holds at (i, j) of face f, widened as sampling returns it.
Vec4 indexTexel(int f, int i, int j) {
  return (Rgba(float(i), float(j), float(40 * (f + 1)), 255.0f) / 255.0f).cast<double>();
}

// The direction through the centre of texel (i, j) of face f on an N x N face, scaled by ma.
Vec3 texelCentreDirection(CubeFace f, int i, int j, int n, double ma = 1.0) {
  return glCubeDirection(f, ma * (2.0 * (i + 0.5) / n - 1.0), ma * (2.0 * (j + 0.5) / n - 1.0), ma);
}

TEST(CubeTexture, NearestThroughEveryTexelCentreReadsThatTexelOfCubeIndex) {
  constexpr int n = 32;
  const CubeTexture cube = cubeIndexTexture(n);
  const SamplerState nearest = samplerFor(Filter::Nearest, Wrap::Repeat);
  for (int f = 0; f < kCubeFaceCount; ++f)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        // Any positive length: the division by |ma| makes the direction's scale irrelevant.
        const CubeCoordinates c = cubeCoordinates(texelCentreDirection(CubeFace(f), i, j, n, 3.7));
        ASSERT_EQ(c.face, CubeFace(f)) << f << " " << i << " " << j;
        for (bool seamless : {false, true})
          ASSERT_EQ(sampleCube(cube, nearest, c.face, c.st.x(), c.st.y(), 0.0, seamless), indexTexel(f, i, j))
              << f << " " << i << " " << j << " seamless " << seamless;
      }
}

TEST(CubeTexture, AZeroOrNonFiniteDirectionHasNoFacePoint) {
  for (const Vec3& d : {Vec3(0, 0, 0), Vec3(NAN, 0, 1), Vec3(INFINITY, 0, 0)}) {
    const CubeCoordinates c = cubeCoordinates(d);
    EXPECT_EQ(c.face, CubeFace::PosX);
    EXPECT_FALSE(c.st.allFinite());
  }
  // ... and sampling such a point reads texel (0, 0) of the face, as a 2D texture does.
  const CubeTexture cube = cubeIndexTexture(4);
  for (bool seamless : {false, true})
    EXPECT_EQ(sampleCube(cube, samplerFor(Filter::Linear, Wrap::Repeat), CubeFace::NegY, NAN, 0.5, 0.0, seamless),
              indexTexel(3, 0, 0));
}

// An opaque texel of 8-bit RGB values, as the procedural cube maps store them.
Rgba cubeCheckerTexel(const std::array<int, 3>& rgb) {
  return Rgba(float(rgb[0]), float(rgb[1]), float(rgb[2]), 255.0f) / 255.0f;
}

TEST(CubeCheckerTexture, ColoursEachFaceAndHalvesItsOddChecks) {
  const CubeTexture cube = cubeCheckerTexture(64);  // checks of c = 64 / 8 = 8 texels
  EXPECT_EQ(cube.size(), 64);
  EXPECT_TRUE(cube.eightBit());
  const std::array<std::array<int, 3>, 6> full = {
      {{255, 0, 0}, {0, 255, 255}, {0, 255, 0}, {255, 0, 255}, {0, 0, 255}, {255, 255, 0}}};
  const std::array<std::array<int, 3>, 6> halved = {
      {{127, 0, 0}, {0, 127, 127}, {0, 127, 0}, {127, 0, 127}, {0, 0, 127}, {127, 127, 0}}};
  for (int f = 0; f < kCubeFaceCount; ++f) {
    const TexelLevel& level = cube.face(CubeFace(f)).level(0);
    const auto fullColour = cubeCheckerTexel(full[std::size_t(f)]);
    const auto halvedColour = cubeCheckerTexel(halved[std::size_t(f)]);
    EXPECT_EQ(level.at(0, 0), fullColour) << f;
    EXPECT_EQ(level.at(7, 7), fullColour) << f;      // 0 + 0
    EXPECT_EQ(level.at(8, 0), halvedColour) << f;    // 1 + 0
    EXPECT_EQ(level.at(0, 15), halvedColour) << f;   // 0 + 1
    EXPECT_EQ(level.at(8, 8), fullColour) << f;      // 1 + 1
    EXPECT_EQ(level.at(63, 56), fullColour) << f;    // 7 + 7
    EXPECT_EQ(level.at(55, 63), halvedColour) << f;  // 6 + 7
  }
}

TEST(CubeCheckerTexture, UsesChecksOfOneTexelBelowEightTexelsAndOfNOver8Above) {
  const CubeTexture small = cubeCheckerTexture(4);  // c = max(1, 4 / 8) = 1
  const TexelLevel& posZ = small.face(CubeFace::PosZ).level(0);
  EXPECT_EQ(posZ.at(0, 0), cubeCheckerTexel({0, 0, 255}));
  EXPECT_EQ(posZ.at(1, 0), cubeCheckerTexel({0, 0, 127}));
  EXPECT_EQ(posZ.at(1, 1), cubeCheckerTexel({0, 0, 255}));
  EXPECT_EQ(posZ.at(3, 2), cubeCheckerTexel({0, 0, 127}));
  EXPECT_EQ(cubeCheckerTexture(1).face(CubeFace::NegZ).level(0).at(0, 0), cubeCheckerTexel({255, 255, 0}));
  const CubeTexture twenty = cubeCheckerTexture(20);  // c = 20 / 8 = 2
  const TexelLevel& negX = twenty.face(CubeFace::NegX).level(0);
  EXPECT_EQ(negX.at(1, 1), cubeCheckerTexel({0, 255, 255}));
  EXPECT_EQ(negX.at(2, 1), cubeCheckerTexel({0, 127, 127}));
  EXPECT_EQ(negX.at(19, 0), cubeCheckerTexel({0, 127, 127}));  // 19 / 2 = 9
  EXPECT_EQ(negX.at(19, 19), cubeCheckerTexel({0, 255, 255}));
  EXPECT_THROW(cubeCheckerTexture(0), UsageError);
  EXPECT_THROW(cubeCheckerTexture(4097), UsageError);
  EXPECT_THROW(cubeIndexTexture(257), UsageError);
}

// Linear sampling of cubeindex:8 near +X's s = 1 edge, which is x = 1, z = -1 (+X: sc = -z = 1):
// the edge of -Z at its s = 0 (-Z: sc = -x = -1), on the same row (both have tc = -y).
class CubeEdge : public ::testing::Test {
 protected:
  static constexpr int kN = 8;
  const CubeTexture cube = cubeIndexTexture(kN);
  const SamplerState linearClamp = samplerFor(Filter::Linear, Wrap::ClampToEdge);
  Vec4 at(CubeFace f, double s, double t, bool seamless) const {
    return sampleCube(cube, linearClamp, f, s, t, 0.0, seamless);
  }
};

TEST_F(CubeEdge, ClampReadsOnlyTheFaceButSeamlessBlendsInTheAdjacentFace) {
  // s = 1 - 0.25/8: u = 8 s - 1/2 = 7.25, texels 7 and 8 with weights 3/4, 1/4; t = 3.5/8: row 3 alone.
  const double s = 1 - 0.25 / kN, t = 3.5 / kN;
  EXPECT_EQ(at(CubeFace::PosX, s, t, false), indexTexel(0, 7, 3));
  // 3/4 (7, 3, 40) + 1/4 (0, 3, 240) of -Z's texel (0, 3) = (5.25, 3, 90) / 255, to float texels.
  const Vec4 expected = 0.75 * indexTexel(0, 7, 3) + 0.25 * indexTexel(5, 0, 3);
  EXPECT_LT((expected - Vec4(5.25, 3, 90, 255) / 255.0).cwiseAbs().maxCoeff(), 1e-7);
  EXPECT_LT((at(CubeFace::PosX, s, t, true) - expected).cwiseAbs().maxCoeff(), 1e-12);
}

TEST_F(CubeEdge, TheTexelBeyondACornerIsTheMeanOfTheThreeTexelsMeetingThere) {
  // +X's corner s = t = 1 is (1, -1, -1): +X's texel (7, 7), -Z's (0, 7) (-Z: sc = -x = -1,
  // tc = -y = 1) and -Y's (7, 7) (-Y: sc = x = 1, tc = -z = 1).
  const Vec4 a = indexTexel(0, 7, 7), b = indexTexel(5, 0, 7), c = indexTexel(3, 7, 7);
  const Vec4 mean = (a + b + c) / 3.0;
  EXPECT_EQ(at(CubeFace::PosX, 1.0 - 0.25 / kN, 1.0 - 0.25 / kN, false), a);
  // Weights 9/16, 3/16, 3/16 and 1/16 for the corner texel.
  const Vec4 near = 9.0 / 16 * a + 3.0 / 16 * b + 3.0 / 16 * c + 1.0 / 16 * mean;
  EXPECT_LT((at(CubeFace::PosX, 1.0 - 0.25 / kN, 1.0 - 0.25 / kN, true) - near).cwiseAbs().maxCoeff(), 1e-12);
  // At the corner itself the four weights are 1/4: (a + b + c + mean) / 4 = mean.
  EXPECT_LT((at(CubeFace::PosX, 1.0, 1.0, true) - mean).cwiseAbs().maxCoeff(), 1e-12);
  // The same corner seen from -Z (its s = 0, t = 1) and -Y (s = t = 1) reads the same mean.
  EXPECT_LT((at(CubeFace::NegZ, 0.0, 1.0, true) - mean).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((at(CubeFace::NegY, 1.0, 1.0, true) - mean).cwiseAbs().maxCoeff(), 1e-12);
}

// The texel whose centre direction is nearest (largest cosine) to `d`, over all faces: a reference
// for the seamless neighbour that knows nothing of the table's edges.
Vec4 nearestTexelByAngle(const Vec3& d, int n) {
  double best = -2.0;
  Vec4 texel = Vec4::Zero();
  for (int f = 0; f < kCubeFaceCount; ++f)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double cosine = texelCentreDirection(CubeFace(f), i, j, n).normalized().dot(d.normalized());
        if (cosine > best) best = cosine, texel = indexTexel(f, i, j);
      }
  return texel;
}

TEST_F(CubeEdge, SeamlessAcrossEachOfThe24EdgesReadsTheGeometricallyAdjacentTexel) {
  // A quarter texel from each edge, at each texel along it: 3/4 of the edge texel, 1/4 of the one
  // beyond, whose centre direction is one texel step past the edge on face f's plane.
  const double inside = 1 - 0.25 / kN, outside = 0.25 / kN;
  int checked = 0;
  for (int face = 0; face < kCubeFaceCount; ++face) {
    const CubeFace f = CubeFace(face);
    for (int k = 0; k < kN; ++k) {
      const double along = (k + 0.5) / kN;
      struct Edge {
        double s, t;
        int i, j;              // the edge texel
        int beyondI, beyondJ;  // the texel one beyond the edge, in face f's indices
      };
      const std::array<Edge, 4> edges = {{{outside, along, 0, k, -1, k},
                                          {inside, along, kN - 1, k, kN, k},
                                          {along, outside, k, 0, k, -1},
                                          {along, inside, k, kN - 1, k, kN}}};
      for (const Edge& e : edges) {
        const Vec3 beyond = texelCentreDirection(f, e.beyondI, e.beyondJ, kN);
        const Vec4 expected = 0.75 * indexTexel(face, e.i, e.j) + 0.25 * nearestTexelByAngle(beyond, kN);
        EXPECT_LT((at(f, e.s, e.t, true) - expected).cwiseAbs().maxCoeff(), 1e-12)
            << "face " << face << " texel " << e.i << " " << e.j << " towards " << e.beyondI << " " << e.beyondJ;
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 6 * 4 * kN);
}

TEST(CubeTexture, LayoutImagesRoundTripThroughFromLayoutImage) {
  const CubeTexture cube = cubeIndexTexture(4);
  for (CubeLayout layout : {CubeLayout::Cross, CubeLayout::Strip, CubeLayout::ThreeByTwo}) {
    const CubeTexture back = CubeTexture::fromLayoutImage(cube.layoutImage(layout), layout, "atlas.png", true);
    ASSERT_EQ(back.size(), 4);
    for (int f = 0; f < kCubeFaceCount; ++f)
      EXPECT_EQ(back.face(CubeFace(f)).level(0).texels, cube.face(CubeFace(f)).level(0).texels)
          << "layout " << int(layout) << " face " << f;
  }
}

TEST(CubeTexture, TheCrossAtlasPutsEachFaceInItsCellWithTZeroAtTheCellsTop) {
  const CubeTexture cube = cubeIndexTexture(4);
  const Image atlas = cube.layoutImage(CubeLayout::Cross);
  ASSERT_EQ(atlas.width, 16);
  ASSERT_EQ(atlas.height, 12);
  ASSERT_EQ(atlas.channels, 4);
  const auto pixel = [&](int x, int y) {
    return Vec4(atlas.at(x, y, 0), atlas.at(x, y, 1), atlas.at(x, y, 2), atlas.at(x, y, 3));
  };
  // Cell (column, row from the bottom) -> top-left pixel (4 column, 4 (2 - row)): +X (2, 1) at
  // (8, 4), -X (0, 1) at (0, 4), +Y (1, 2) at (4, 0), -Y (1, 0) at (4, 8), +Z (1, 1) at (4, 4),
  // -Z (3, 1) at (12, 4). Texel (i, j) lies at (x0 + i, y0 + j).
  const std::array<std::array<int, 2>, 6> origin = {{{8, 4}, {0, 4}, {4, 0}, {4, 8}, {4, 4}, {12, 4}}};
  for (int f = 0; f < kCubeFaceCount; ++f) {
    const auto [x0, y0] = origin[std::size_t(f)];
    EXPECT_EQ(pixel(x0, y0), indexTexel(f, 0, 0)) << f;
    EXPECT_EQ(pixel(x0 + 3, y0 + 1), indexTexel(f, 3, 1)) << f;
    EXPECT_EQ(pixel(x0 + 1, y0 + 3), indexTexel(f, 1, 3)) << f;
  }
  EXPECT_EQ(pixel(0, 0), Vec4(0, 0, 0, 1));  // the empty cells are opaque black
  EXPECT_EQ(pixel(15, 11), Vec4(0, 0, 0, 1));
}

// Six n x n RGB images; image f's pixel (x, y) (row y from the top) is (f, x, y) / 255.
std::vector<Image> faceImages(int n) {
  std::vector<Image> images;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    Image image(n, n, 3);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        image.at(x, y, 0) = float(f) / 255.0f;
        image.at(x, y, 1) = float(x) / 255.0f;
        image.at(x, y, 2) = float(y) / 255.0f;
      }
    images.push_back(image);
  }
  return images;
}

const std::vector<std::string> kFaceNames = {"px.png", "nx.png", "py.png", "ny.png", "pz.png", "nz.png"};

// The UsageError message of fromImages (one name per image), or "".
std::string fromImagesError(const std::vector<Image>& images) {
  try {
    CubeTexture::fromImages(images, std::vector<std::string>(kFaceNames.begin(), kFaceNames.begin() + images.size()),
                            true);
  } catch (const UsageError& error) {
    return error.what();
  }
  return "";
}

TEST(CubeTexture, FromImagesReadsEachImagesTopRowAsTheFacesFirstRow) {
  const CubeTexture cube = CubeTexture::fromImages(faceImages(2), kFaceNames, true);
  for (int f = 0; f < kCubeFaceCount; ++f)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x)
        EXPECT_EQ(cube.face(CubeFace(f)).level(0).at(x, y), Rgba(float(f), float(x), float(y), 255.0f) / 255.0f);
}

TEST(CubeTexture, FromImagesRejectsNonSquareOrMismatchedFacesNamingTheFile) {
  std::vector<Image> images = faceImages(4);
  images[3] = Image(4, 3, 3);
  std::string message = fromImagesError(images);
  EXPECT_EQ(message.rfind("ny.png: ", 0), 0u) << message;
  EXPECT_NE(message.find("found 4 x 3"), std::string::npos) << message;

  images = faceImages(4);
  images[5] = Image(8, 8, 3);
  message = fromImagesError(images);
  EXPECT_EQ(message.rfind("nz.png: ", 0), 0u) << message;
  EXPECT_NE(message.find("found 8 x 8"), std::string::npos) << message;

  images = faceImages(4);
  images.pop_back();
  EXPECT_NE(fromImagesError(images), "");  // five faces are not a cube

  try {
    CubeTexture::fromLayoutImage(Image(16, 13, 3), CubeLayout::Cross, "cross.png", true);
    ADD_FAILURE() << "a 16 x 13 cross accepted";
  } catch (const UsageError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("cross.png: ", 0), 0u) << error.what();
  }
}

TEST(CubeTexture, TheFaceStDerivativeAgreesWithACentralDifference) {
  // By hand on +X at (1, 0, 0): s = (-z + 1) / 2, so ds/dz = -1/2, and a radial step moves nothing.
  EXPECT_EQ(cubeFaceStDerivative(Vec3(1, 0, 0), Vec3(0, 0, 1), CubeFace::PosX), Vec2(-0.5, 0));
  EXPECT_EQ(cubeFaceStDerivative(Vec3(2, 0, 0), Vec3(1, 0, 0), CubeFace::PosX), Vec2(0, 0));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 d(uniform(random), uniform(random), uniform(random)),
        dd(uniform(random), uniform(random), uniform(random));
    const CubeFace f = majorAxisFace(d);
    const double h = 1e-6 * d.norm();
    const Vec2 difference = (glCubeFaceSt(Vec3(d + h * dd), f) - glCubeFaceSt(Vec3(d - h * dd), f)) / (2 * h);
    const Vec2 derivative = cubeFaceStDerivative(d, dd, f);
    EXPECT_LE((derivative - difference).norm(), 1e-6 * derivative.norm() + 1e-9)
        << d.transpose() << " along " << dd.transpose();
  }
}

TEST(CubeTexture, MipmappedFacesFilterAsTheirTwoDimensionalTextures) {
  CubeTexture cube = cubeCheckerTexture(16);  // checks of 2 texels
  cube.buildMipmaps();
  ASSERT_TRUE(cube.hasMipmaps());
  ASSERT_EQ(cube.levelCount(), 5);
  // Level 1 keeps one-texel checks; from level 2 on each texel averages 2 full and 2 halved ones:
  // (255 + 255 + 127 + 127) / 4 = 191 exactly.
  EXPECT_EQ(cube.face(CubeFace::PosX).level(2).at(1, 2), cubeCheckerTexel({191, 0, 0}));
  EXPECT_EQ(cube.face(CubeFace::NegY).level(4).at(0, 0), cubeCheckerTexel({191, 0, 191}));

  const SamplerState trilinear = samplerFor(Filter::LinearMipmapLinear, Wrap::ClampToEdge);
  for (int f = 0; f < kCubeFaceCount; ++f)
    for (double lambda : {-0.5, 0.25, 0.7, 1.5, 2.9, 3.5, 7.0})
      for (const Vec2& st : {Vec2(0.5, 0.5), Vec2(0.03, 0.4), Vec2(0.81, 0.97), Vec2(0.27, 0.66)})
        EXPECT_EQ(sampleCube(cube, trilinear, CubeFace(f), st.x(), st.y(), lambda, false),
                  sample(cube.face(CubeFace(f)), trilinear, st.x(), st.y(), lambda))
            << f << " " << lambda << " " << st.transpose();

  // lambda = 1.25 blends 3/4 of level 1 with 1/4 of level 2, each LINEAR.
  const TexelLevel& one = cube.face(CubeFace::PosZ).level(1);
  const TexelLevel& two = cube.face(CubeFace::PosZ).level(2);
  const Vec4 blended = 0.75 * sampleLinear(one, Wrap::ClampToEdge, Wrap::ClampToEdge, 0.3, 0.45) +
                       0.25 * sampleLinear(two, Wrap::ClampToEdge, Wrap::ClampToEdge, 0.3, 0.45);
  EXPECT_LT((sampleCube(cube, trilinear, CubeFace::PosZ, 0.3, 0.45, 1.25, false) - blended).cwiseAbs().maxCoeff(),
            1e-15);

  // Seamless on the 1 x 1 level (lambda >= 4) at s = t = 3/4 of +X: u = v = 1/4, so 9/16 of +X's
  // (191, 0, 0), 3/16 each of -Z's (191, 191, 0) and -Y's (191, 0, 191), 1/16 of the three's mean
  // (191, 191/3, 191/3): G = B = 3/16 191 + 1/48 191 = 191 5/24; without seamless the face alone.
  const Vec4 seamless = sampleCube(cube, trilinear, CubeFace::PosX, 0.75, 0.75, 4.0, true);
  EXPECT_LT((seamless - Vec4(191, 191 * 5 / 24.0, 191 * 5 / 24.0, 255) / 255.0).cwiseAbs().maxCoeff(), 1e-7);
  EXPECT_EQ(sampleCube(cube, trilinear, CubeFace::PosX, 0.75, 0.75, 4.0, false),
            cubeCheckerTexel({191, 0, 0}).cast<double>());
}

// A 72 x 72 orthographic view of the square [-1.5, 1.5]^2 and a quad over [-1, 1]^2: pixels 12..59
// of each axis, u = (x - 12 + 1/2) / 48 across it and v likewise upwards.
struct CubeQuad {
  static constexpr int kSize = 72, kN = 32;
  Quad quad{Vec3(-1, -1, 0), Vec3(2, 0, 0), Vec3(0, 2, 0)};
  const CubeTexture cube = cubeIndexTexture(kN);

  RenderOptions options() const {
    RenderOptions o;
    o.camera.width = o.camera.height = kSize;
    o.camera.clipFromView = orthographic(-1.5, 1.5, -1.5, 1.5, -1, 1);
    o.cubeTexture = &cube;
    o.sampler = samplerFor(Filter::Nearest, Wrap::ClampToEdge);
    o.aovs = true;
    return o;
  }
  // The quad's corners with (s, t, r, q) = texcoord(u, v).
  template <class F>
  TexcoordSource corners(F texcoord) const {
    TexcoordSource source;
    for (const Vec4& c : quad.texcoords.corners) source.corners.push_back(texcoord(c.x(), c.y()));
    return source;
  }
  // The face (s, t) runs over [0.15, 0.8] on the quad: s N = 4.8 + 20.8 (x - 12 + 1/2) / 48 =
  // (301 + 26 (x - 12)) / 60, odd over 60, so every pixel centre is at least 1/60 texel from a
  // texel boundary, and the texel column is floor of that.
  static int texelColumn(int x) { return (301 + 26 * (x - 12)) / 60; }
  static int texelRow(int row) { return texelColumn(kSize - 1 - row); }  // v grows upwards
};

TEST(CubeRender, DirectionsWithinOneFaceReadTheTexelsTheyPointAt) {
  const CubeQuad q;
  for (int face = 0; face < kCubeFaceCount; ++face) {
    const CubeFace f = CubeFace(face);
    // The corners carry directions on face f's plane (|ma| = 1) with sc, tc in [-0.7, 0.6]:
    // s = (sc + 1) / 2 in [0.15, 0.8], linear in u as the interpolation is.
    const Rendering r = render(q.quad.mesh, q.corners([&](double u, double v) {
      const Vec3 d = glCubeDirection(f, -0.7 + 1.3 * u, -0.7 + 1.3 * v, 1.0);
      return Vec4(d.x(), d.y(), d.z(), 1.0);
    }),
                               q.options());
    ASSERT_EQ(r.aovs.channels, 6);
    EXPECT_EQ(r.aovs.channelNames.back(), "cubeface");
    EXPECT_EQ(r.coveredPixels, 48u * 48u);
    for (int row = 0; row < CubeQuad::kSize; ++row)
      for (int x = 0; x < CubeQuad::kSize; ++x) {
        const bool covered = x >= 12 && x < 60 && row >= 12 && row < 60;
        ASSERT_EQ(r.aovs.at(x, row, 5), covered ? float(face) : -1.0f) << face << ": " << x << " " << row;
        if (!covered) continue;
        const Vec4 texel = indexTexel(face, CubeQuad::texelColumn(x), CubeQuad::texelRow(row));
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(r.colour.at(x, row, c), float(texel[c])) << face << ": " << x << " " << row;
        EXPECT_NEAR(r.aovs.at(x, row, 0), 0.15 + 0.65 * (x - 12 + 0.5) / 48, 1e-6);
        EXPECT_NEAR(r.aovs.at(x, row, 1), 0.15 + 0.65 * (59 - row + 0.5) / 48, 1e-6);
      }
  }
}

TEST(CubeRender, FaceIdsInRLookUpThatFaceAtTheGivenSt) {
  const CubeQuad q;
  for (int face = 0; face < kCubeFaceCount; ++face) {
    TexcoordSource source =
        q.corners([&](double u, double v) { return Vec4(0.15 + 0.65 * u, 0.15 + 0.65 * v, face, 1.0); });
    source.cubeFaceIds = true;
    const Rendering r = render(q.quad.mesh, source, q.options());
    for (int row = 12; row < 60; ++row)
      for (int x = 12; x < 60; ++x) {
        ASSERT_EQ(r.aovs.at(x, row, 5), float(face));
        const Vec4 texel = indexTexel(face, CubeQuad::texelColumn(x), CubeQuad::texelRow(row));
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(r.colour.at(x, row, c), float(texel[c])) << face << ": " << x << " " << row;
      }
  }
}

TEST(CubeRender, ExactlyOneTextureMustBeBound) {
  const CubeQuad q;
  const Texture flat = checkerTexture(8, 2);
  RenderOptions both = q.options();
  both.texture = &flat;
  EXPECT_THROW(render(q.quad.mesh, q.quad.texcoords, both), UsageError);
  RenderOptions neither = q.options();
  neither.cubeTexture = nullptr;
  EXPECT_THROW(render(q.quad.mesh, q.quad.texcoords, neither), UsageError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::render
