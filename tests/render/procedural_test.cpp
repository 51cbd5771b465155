// The procedural textures texel for texel, and the names that denote them.
#include "render/procedural.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>
#include <string>

#include "core/error.h"
#include "render/font.h"

namespace uvtk::render {
namespace {

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
  EXPECT_EQ(level.at(4, 0), kBlack);   // 4/4 + 0/4 = 1
  EXPECT_EQ(level.at(0, 4), kBlack);
  EXPECT_EQ(level.at(4, 4), kWhite);   // 1 + 1 = 2
  EXPECT_EQ(level.at(15, 12), kWhite); // 3 + 3 = 6
  EXPECT_EQ(level.at(11, 12), kBlack); // 2 + 3 = 5
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
  for (const char* name : {"checker", "checker:", "checker:x", "checker:8:0", "checker:8x", "checker:8:4:2",
                           "checker:-8", "checker: 8", "checker:16385", "checker:8:16385", "checker:8:",
                           "checker:99999999999"})
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
        EXPECT_EQ(isBlack(grid(), cell.x0 + x, cell.y0 + y), expected.at(x, y, 0) > 0.0f) << cell.label << " " << x << " " << y;
        dark += isBlack(grid(), cell.x0 + x, cell.y0 + y);
      }
    EXPECT_GT(dark, 20) << cell.label;
  }
}

TEST_F(UvGrid, PointsTheArrowInCellA1AlongPlusU) {
  // Cell A1: w = h = 32, top y0 = 224. Shaft row 224 + 5 32/6 = 250 from x = 32/5 = 6 to
  // 4 32/5 = 25; the head's column 25 - d spans rows 250 +- d/2 for d = 0..5.
  EXPECT_TRUE(isBlack(grid(), 25, 250));   // the tip
  EXPECT_TRUE(isBlack(grid(), 6, 250));    // the tail
  EXPECT_TRUE(isBlack(grid(), 20, 248));   // the head's back corners
  EXPECT_TRUE(isBlack(grid(), 20, 252));
  EXPECT_FALSE(isBlack(grid(), 26, 250));  // nothing beyond the tip
  EXPECT_FALSE(isBlack(grid(), 5, 250));
  EXPECT_FALSE(isBlack(grid(), 7, 249));   // no head at the tail
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

}  // namespace
}  // namespace uvtk::render
