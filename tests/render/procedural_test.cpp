// The procedural textures texel for texel, and the names that denote them.
#include "render/procedural.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>
#include <string>

#include "core/error.h"
#include "render/font.h"

namespace uvtk::render {
namespace {
namespace UVTK_TEST_FILE {

const Rgba kWhite(1.0f, 1.0f, 1.0f, 1.0f);
const Rgba kBlack(0.0f, 0.0f, 0.0f, 1.0f);

bool isBlack(const Image& image, int x, int y) {
  return image.at(x, y, 0) == 0.0f && image.at(x, y, 1) == 0.0f && image.at(x, y, 2) == 0.0f;
}

std::array<float, 3> colourAt(const Image& image, int x, int y) {
  return {image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)};
}

// The UsageError message of proceduralTexture(name), or "" when it does not throw one.
std::string errorOf(const std::string& name) {
  try {
    proceduralTexture(name);
  } catch (const UsageError& error) {
    return error.what();
  }
  return "";
}

TEST(CheckerTexture, IsWhiteAtTheOriginAndAlternatesEverySquare) {
  const Texture texture = checkerTexture(16, 4);
  EXPECT_TRUE(texture.eightBit());
  EXPECT_EQ(texture.width(), 16);
  EXPECT_EQ(texture.height(), 16);
  const TexelLevel& level = texture.level(0);
  EXPECT_EQ(level.at(0, 0), kWhite);
  EXPECT_EQ(level.at(3, 3), kWhite);
  EXPECT_EQ(level.at(4, 0), kBlack);  // 4/4 + 0/4 = 1
  EXPECT_EQ(level.at(0, 4), kBlack);
  EXPECT_EQ(level.at(4, 4), kWhite);    // 1 + 1 = 2
  EXPECT_EQ(level.at(15, 12), kWhite);  // 3 + 3 = 6
  EXPECT_EQ(level.at(11, 12), kBlack);  // 2 + 3 = 5
}

TEST(CheckerTexture, RejectsSizesOutsideOneTo16384) {
  EXPECT_THROW(checkerTexture(8, 0), UsageError);
  EXPECT_THROW(checkerTexture(8, 16385), UsageError);
  EXPECT_THROW(checkerTexture(0, 0), UsageError);
  EXPECT_THROW(checkerTexture(16385, 8), UsageError);
  EXPECT_EQ(checkerTexture(1, 1).level(0).at(0, 0), kWhite);
}

TEST(ProceduralTexture, ParsesCheckerWithAndWithoutTheSquareSize) {
  const std::optional<Texture> given = proceduralTexture("checker:64:8");
  ASSERT_TRUE(given.has_value());
  EXPECT_EQ(given->width(), 64);
  EXPECT_EQ(given->height(), 64);
  EXPECT_EQ(sampleNearest(given->level(0), Wrap::Repeat, Wrap::Repeat, 0.5 / 64, 0.5 / 64), kWhite);
  EXPECT_EQ(sampleNearest(given->level(0), Wrap::Repeat, Wrap::Repeat, 8.5 / 64, 0.5 / 64), kBlack);

  const std::optional<Texture> byDefault = proceduralTexture("checker:16");  // squares of 8
  ASSERT_TRUE(byDefault.has_value());
  EXPECT_EQ(byDefault->level(0).at(7, 0), kWhite);
  EXPECT_EQ(byDefault->level(0).at(8, 0), kBlack);
  EXPECT_EQ(byDefault->level(0).at(8, 8), kWhite);
}

TEST(ProceduralTexture, RejectsMalformedCheckerNamesNamingTheText) {
  for (const char* name :
       {"checker", "checker:", "checker:x", "checker:8:0", "checker:8x", "checker:8:4:2", "checker:-8", "checker: 8",
        "checker:16385", "checker:8:16385", "checker:8:", "checker:99999999999"})
    EXPECT_EQ(errorOf(name), std::string("texture '") + name + "': expected checker:N[:C] with 1 <= N, C <= 16384")
        << name;
}

TEST(ProceduralTexture, ASquareLargerThanTheTextureMakesItWhite) {
  // checker:4 keeps the default C = 8: all 4 x 4 texels lie in the white square of texel (0, 0).
  const std::optional<Texture> small = proceduralTexture("checker:4");
  ASSERT_TRUE(small.has_value());
  for (const Rgba& texel : small->level(0).texels) EXPECT_EQ(texel, kWhite);
  EXPECT_EQ(proceduralTexture("checker:8:9")->level(0).at(7, 7), kWhite);
}

TEST(ProceduralTexture, BuildsTheUvGridAtTheDefaultOrTheGivenSize) {
  const std::optional<Texture> small = proceduralTexture("uvgrid:64");
  ASSERT_TRUE(small.has_value());
  EXPECT_EQ(small->width(), 64);
  EXPECT_TRUE(small->eightBit());
  const std::optional<Texture> standard = proceduralTexture("uvgrid");
  ASSERT_TRUE(standard.has_value());
  EXPECT_EQ(standard->width(), 1024);
  EXPECT_EQ(standard->height(), 1024);
}

TEST(ProceduralTexture, RejectsMalformedUvGridNamesNamingTheText) {
  for (const char* name : {"uvgrid:", "uvgrid:63", "uvgrid:8193", "uvgrid:abc", "uvgrid:256:2"})
    EXPECT_EQ(errorOf(name), std::string("texture '") + name + "': expected uvgrid[:N] with 64 <= N <= 8192") << name;
}

TEST(ProceduralTexture, LeavesEveryOtherNameToTheFileReaders) {
  EXPECT_FALSE(proceduralTexture("brick.png").has_value());
  EXPECT_FALSE(proceduralTexture("textures/checker.png").has_value());
  EXPECT_FALSE(proceduralTexture("checker.png").has_value());
  EXPECT_FALSE(proceduralTexture("checkers:8").has_value());
  EXPECT_FALSE(proceduralTexture("uvgrid2.png").has_value());
  EXPECT_FALSE(proceduralTexture("").has_value());
}

// The uv grid at N = 256: cells of 32 x 32 pixels, cell column A at x 0..31, cell row 1 (v = 0)
// at the bottom, y 224..255.
class UvGrid : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { grid_ = new Image(uvGridImage(256)); }
  static void TearDownTestSuite() { delete grid_; }
  static const Image& grid() { return *grid_; }

 private:
  static Image* grid_;
};
Image* UvGrid::grid_ = nullptr;

TEST_F(UvGrid, IsAnRgbImageOfEightBitValues) {
  EXPECT_EQ(grid().width, 256);
  EXPECT_EQ(grid().height, 256);
  EXPECT_EQ(grid().channels, 3);
  for (float value : grid().pixels) {
    ASSERT_GE(value, 0.0f);
    ASSERT_LE(value, 1.0f);
    ASSERT_NEAR(value * 255.0f, std::round(value * 255.0f), 1e-3f) << value;
  }
}

TEST_F(UvGrid, GivesEveryCellADistinctPaleColour) {
  std::set<std::array<float, 3>> colours;
  for (int cellY = 0; cellY < 8; ++cellY)
    for (int column = 0; column < 8; ++column) {
      const std::array<float, 3> colour = colourAt(grid(), 32 * column + 4, 32 * cellY + 4);  // off lines and text
      for (float channel : colour) EXPECT_GE(channel, 0.5f);
      colours.insert(colour);
    }
  EXPECT_EQ(colours.size(), 64u);
  EXPECT_NE(colourAt(grid(), 4, 228), colourAt(grid(), 4, 4));  // A1 at the bottom, A8 at the top
}

TEST_F(UvGrid, DrawsGridLinesOneTexelWideInsideAndTwoAtTheBorder) {
  for (int k = 1; k < 8; ++k) {
    EXPECT_TRUE(isBlack(grid(), 32 * k, 100)) << k;
    EXPECT_TRUE(isBlack(grid(), 100, 32 * k)) << k;
    EXPECT_FALSE(isBlack(grid(), 32 * k + 1, 100)) << k;
    EXPECT_FALSE(isBlack(grid(), 32 * k - 1, 100)) << k;
  }
  for (int edge : {0, 1, 254, 255}) {
    EXPECT_TRUE(isBlack(grid(), edge, 100)) << edge;
    EXPECT_TRUE(isBlack(grid(), 100, edge)) << edge;
  }
  EXPECT_FALSE(isBlack(grid(), 2, 100));
  EXPECT_FALSE(isBlack(grid(), 253, 100));
}

TEST_F(UvGrid, LabelsEachCellWithItsColumnLetterAndRowDigit) {
  // Label scale max(1, 32 / 21) = 1: "A1" is 11 x 7 pixels, centred at (32 - 11) / 2 = 10,
  // (32 - 7) / 2 = 12 in its cell. Its dark pixels are exactly those of drawText.
  const float ink[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  const struct {
    const char* label;
    int x0, y0;
  } cells[] = {{"A1", 0, 224}, {"A8", 0, 0}, {"H8", 224, 0}, {"C5", 64, 96}};
  for (const auto& cell : cells) {
    Image expected(32, 32, 1);
    drawText(expected, 10, 12, cell.label, 1, ink);
    int dark = 0;
    for (int y = 2; y < 24; ++y)  // inside the lines, above A1's arrow
      for (int x = 2; x < 30; ++x) {
        EXPECT_EQ(isBlack(grid(), cell.x0 + x, cell.y0 + y), expected.at(x, y, 0) > 0.0f)
            << cell.label << " " << x << " " << y;
        dark += isBlack(grid(), cell.x0 + x, cell.y0 + y);
      }
    EXPECT_GT(dark, 20) << cell.label;
  }
}

TEST_F(UvGrid, PointsTheArrowInCellA1AlongPlusU) {
  // Cell A1: w = h = 32, top y0 = 224. Shaft row 224 + 5 32/6 = 250 from x = 32/5 = 6 to
  // 4 32/5 = 25; the head's column 25 - d spans rows 250 +- d/2 for d = 0..5.
  EXPECT_TRUE(isBlack(grid(), 25, 250));  // the tip
  EXPECT_TRUE(isBlack(grid(), 6, 250));   // the tail
  EXPECT_TRUE(isBlack(grid(), 20, 248));  // the head's back corners
  EXPECT_TRUE(isBlack(grid(), 20, 252));
  EXPECT_FALSE(isBlack(grid(), 26, 250));  // nothing beyond the tip
  EXPECT_FALSE(isBlack(grid(), 5, 250));
  EXPECT_FALSE(isBlack(grid(), 7, 249));  // no head at the tail
  EXPECT_FALSE(isBlack(grid(), 7, 251));
  int left = 0, right = 0;
  for (int y = 248; y <= 252; ++y)
    for (int x = 6; x <= 25; ++x) (x <= 15 ? left : right) += isBlack(grid(), x, y);
  EXPECT_EQ(left, 10);        // the shaft alone
  EXPECT_EQ(right, 10 + 12);  // the shaft and the head: 2 + 2 + 4 + 4 more pixels
}

TEST(UvGridImage, LeavesOutLabelsTooWideForTheirCell) {
  // N = 64: cells of 8 pixels, "A1" needs 11. Inside the lines of cell C5 (x 17..23, y 25..31)
  // every pixel keeps the cell's colour.
  const Image small = uvGridImage(64);
  for (int y = 25; y < 32; ++y)
    for (int x = 17; x < 24; ++x) EXPECT_EQ(colourAt(small, x, y), colourAt(small, 17, 25)) << x << " " << y;
  EXPECT_FALSE(isBlack(small, 17, 25));
}

TEST(UvGridImage, RejectsSizesOutside64To8192) {
  EXPECT_THROW(uvGridImage(63), UsageError);
  EXPECT_THROW(uvGridImage(8193), UsageError);
  EXPECT_EQ(uvGridImage(64).width, 64);
}

// The SPHERE_MAP checker texels of spheremap:64:8 by its definition: x = 2 (i + 1/2) / 64 - 1,
// y likewise with j, theta = 2 asin(hypot(x, y)), band a = floor(theta 8 / pi), sector
// b = floor(phi 8 / pi). (The four centre texels lie on diagonals, phi 8 / pi = 2, 6, 10, 14
// exactly, a check boundary left to atan2's rounding, so their neighbours are checked instead.)
TEST(SphereMapCheckerTexture, ColoursTexelsByTheirReflectionsBandAndSector) {
  const Texture texture = sphereMapCheckerTexture(64, 8);
  EXPECT_TRUE(texture.eightBit());
  EXPECT_EQ(texture.width(), 64);
  EXPECT_EQ(texture.height(), 64);
  const TexelLevel& level = texture.level(0);
  const Rgba white = kWhite, black = kBlack;
  const Rgba orange = Rgba(255, 160, 0, 255) / 255.0f, blue = Rgba(0, 64, 160, 255) / 255.0f;
  const Rgba grey = Rgba(128, 128, 128, 255) / 255.0f;
  // (33, 32): x = 3/64, y = 1/64, theta = 0.0988 (a = 0), phi = atan(1/3) = 0.322 (b = 0): light, in front.
  EXPECT_EQ(level.at(33, 32), white);
  // (32, 33): phi = atan(3) = 1.249, b = floor(3.18) = 3: dark, in front.
  EXPECT_EQ(level.at(32, 33), black);
  // (45, 40): x = 0.4219, y = 0.2656, d^2 = 0.2485 < 1/2, theta = 1.0495 (a = 2), phi = 0.5617 (b = 1).
  EXPECT_EQ(level.at(45, 40), black);
  // Just inside the rim, behind: (63, 32): d^2 = 0.96924, theta = 2.7890 (a = 7), phi = 0.0159 (b = 0):
  // dark; (62, 32): d^2 = 0.90869, theta = 2.5276 (a = 6), b = 0: light; (32, 63): a = 7, phi = 1.555
  // (b = 3): light; (0, 32): phi = 3.126 (b = 7), a = 7: light.
  EXPECT_EQ(level.at(63, 32), blue);
  EXPECT_EQ(level.at(62, 32), orange);
  EXPECT_EQ(level.at(32, 63), orange);
  EXPECT_EQ(level.at(0, 32), orange);
  // Outside the disc: the corners, d^2 = 2 (63/64)^2 > 1.
  for (const auto& [i, j] : {std::pair{0, 0}, std::pair{63, 0}, std::pair{0, 63}, std::pair{63, 63}})
    EXPECT_EQ(level.at(i, j), grey) << i << " " << j;
  EXPECT_THROW(sphereMapCheckerTexture(7, 8), UsageError);
  EXPECT_THROW(sphereMapCheckerTexture(64, 65), UsageError);
}

TEST(SphereMapCheckerTexture, SphereMapCoordinatesOfAReflectionLandOnItsCheck) {
  // docs/conventions.md section 6: s = rx / m + 1/2, t = ry / m + 1/2, m = 2 sqrt(rx^2 + ry^2 + (rz + 1)^2).
  // The texel found there must hold the check of r's own theta and phi. A texel's centre is up to
  // sqrt(2)/512 from the point in (x, y), i.e. up to 0.02 rad in theta for theta <= 2.6 and in phi
  // for theta >= 0.3; directions 0.05 of a check (0.039 rad) or more from a check boundary are used.
  constexpr int n = 512, k = 4;
  const Texture texture = sphereMapCheckerTexture(n, k);
  const std::array<Rgba, 4> checks = {kWhite, kBlack, Rgba(255, 160, 0, 255) / 255.0f, Rgba(0, 64, 160, 255) / 255.0f};
  const auto nearCheckBoundary = [](double checksCoordinate) {
    const double f = checksCoordinate - std::floor(checksCoordinate);
    return f < 0.05 || f > 0.95;
  };
  std::mt19937 random(11);
  std::normal_distribution<double> normal;
  int checked = 0;
  while (checked < 500) {
    const Vec3 r = Vec3(normal(random), normal(random), normal(random)).normalized();
    const double theta = std::atan2(std::hypot(r.x(), r.y()), r.z());
    double phi = std::atan2(r.y(), r.x());
    if (phi < 0) phi += kTwoPi;
    if (theta < 0.3 || theta > 2.6 || nearCheckBoundary(theta * k / kPi) || nearCheckBoundary(phi * k / kPi)) continue;
    const double m = 2 * std::sqrt(r.x() * r.x() + r.y() * r.y() + (r.z() + 1) * (r.z() + 1));
    const double s = r.x() / m + 0.5, t = r.y() / m + 0.5;
    const int a = int(std::floor(theta * k / kPi)), b = int(std::floor(phi * k / kPi));
    const bool behind = theta > kPi / 2;
    EXPECT_EQ(sampleNearest(texture.level(0), Wrap::ClampToEdge, Wrap::ClampToEdge, s, t),
              checks[std::size_t(2 * behind + (a + b) % 2)])
        << r.transpose() << ": theta " << theta << ", phi " << phi;
    ++checked;
  }
}

// The UsageError message of proceduralCubeTexture(name), or "" when it does not throw one.
std::string cubeErrorOf(const std::string& name) {
  try {
    proceduralCubeTexture(name);
  } catch (const UsageError& error) {
    return error.what();
  }
  return "";
}

TEST(ProceduralTexture, ParsesCubeMapAndSphereMapNames) {
  const std::optional<CubeTexture> cube = proceduralCubeTexture("cube");
  ASSERT_TRUE(cube.has_value());
  EXPECT_EQ(cube->size(), 64);
  EXPECT_EQ(proceduralCubeTexture("cube:16")->size(), 16);
  EXPECT_EQ(proceduralCubeTexture("cubeindex")->size(), 64);
  const std::optional<CubeTexture> index = proceduralCubeTexture("cubeindex:256");
  ASSERT_TRUE(index.has_value());
  EXPECT_EQ(index->face(CubeFace::NegZ).level(0).at(255, 3), Rgba(255, 3, 240, 255) / 255.0f);
  // A cube map is not a 2D texture and the other way round, but both names are procedural.
  EXPECT_FALSE(proceduralTexture("cube:16").has_value());
  EXPECT_FALSE(proceduralCubeTexture("spheremap:16").has_value());
  EXPECT_FALSE(proceduralCubeTexture("checker:16").has_value());
  for (const char* name : {"cube", "cube:16", "cubeindex:8", "spheremap", "spheremap:16:2"})
    EXPECT_TRUE(isProceduralName(name)) << name;

  const std::optional<Texture> sphereMap = proceduralTexture("spheremap");
  ASSERT_TRUE(sphereMap.has_value());
  EXPECT_EQ(sphereMap->width(), 256);
  // Texel (12, 8) of 16: x = 9/16, y = 1/16, theta = 1.203, phi = 0.1107. spheremap:16 keeps K = 8:
  // a = floor(3.06) = 3, b = 0, dark; spheremap:16:1 has one band and two sectors: a = b = 0, light.
  EXPECT_EQ(proceduralTexture("spheremap:16")->level(0).at(12, 8), kBlack);
  EXPECT_EQ(proceduralTexture("spheremap:16:1")->level(0).at(12, 8), kWhite);
}

TEST(ProceduralTexture, RejectsMalformedCubeMapAndSphereMapNamesNamingTheText) {
  EXPECT_EQ(cubeErrorOf("cubeindex:300"), "texture 'cubeindex:300': expected cubeindex[:N] with 1 <= N <= 256");
  EXPECT_EQ(cubeErrorOf("cube:0"), "texture 'cube:0': expected cube[:N] with 1 <= N <= 4096");
  EXPECT_EQ(cubeErrorOf("cube:"), "texture 'cube:': expected cube[:N] with 1 <= N <= 4096");
  EXPECT_EQ(cubeErrorOf("cube:8:2"), "texture 'cube:8:2': expected cube[:N] with 1 <= N <= 4096");
  for (const char* name : {"spheremap:8:0", "spheremap:7", "spheremap:8:65", "spheremap:8:2:1"})
    EXPECT_EQ(errorOf(name),
              std::string("texture '") + name + "': expected spheremap[:N[:K]] with 8 <= N <= 8192, 1 <= K <= 64")
        << name;
  // The same names are malformed whichever of the two functions reads them.
  EXPECT_NE(errorOf("cubeindex:300"), "");
  EXPECT_NE(cubeErrorOf("spheremap:8:0"), "");
  EXPECT_THROW(isProceduralName("cube:x"), UsageError);
}

TEST(ProceduralTexture, LeavesCubeLikeFileNamesToTheFileReaders) {
  for (const char* name : {"cube.png", "cubeindex.exr", "cubes:8", "spheremap.png", "textures/cube:8.png"}) {
    EXPECT_FALSE(isProceduralName(name)) << name;
    EXPECT_FALSE(proceduralCubeTexture(name).has_value()) << name;
    EXPECT_FALSE(proceduralTexture(name).has_value()) << name;
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::render
