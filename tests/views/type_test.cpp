// The views' typeface (views/type.h): metrics that order as the glyphs do, ink inside the measured
// box, anti-aliased coverage blended over the image, kerning, UTF-8, and the same pixels on every
// call and every thread.
#include "views/type.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "views/canvas.h"
#include "views/palette.h"

namespace uvtk::views {
namespace {
namespace UVTK_TEST_FILE {

const Vec3 kInk{0.9, 0.8, 0.1};
const Vec3 kBackground{0.1, 0.2, 0.3};

Image panel(int width, int height) {
  Image image(width, height, 3);
  fillRect(image, 0, 0, width, height, kBackground);
  return image;
}

// A colour as the image stores it, in floats.
Vec3 stored(const Vec3& colour) {
  Image pixel(1, 1, 3);
  setPixel(pixel, 0, 0, colour);
  return pixelColour(pixel, 0, 0);
}

bool isBackground(const Image& image, int x, int row) { return pixelColour(image, x, row) == stored(kBackground); }

// The smallest box holding every pixel that is not background: {left, top, right, bottom}, exclusive
// right and bottom; all -1 when there is none.
std::vector<int> inkBox(const Image& image) {
  std::vector<int> box{-1, -1, -1, -1};
  for (int row = 0; row < image.height; ++row)
    for (int x = 0; x < image.width; ++x) {
      if (isBackground(image, x, row)) continue;
      if (box[0] < 0) box = {x, row, x + 1, row + 1};
      box = {std::min(box[0], x), std::min(box[1], row), std::max(box[2], x + 1), std::max(box[3], row + 1)};
    }
  return box;
}

TEST(Type, EmptyTextIsTheFacesLineBox) {
  for (double size : {9.0, 13.0, 14.0, 15.0, 40.0}) {
    const TextMetrics empty = measureText("", size);
    EXPECT_EQ(empty.width, 0);
    EXPECT_GT(empty.ascent, 0);
    EXPECT_GT(empty.descent, 0);
    EXPECT_EQ(empty.height, empty.ascent + empty.descent);
    // DejaVu Sans: ascender 1901 and descender 483 of 2048 units per em, rounded outwards.
    EXPECT_EQ(empty.height, int(std::ceil(size * 1901 / 2048)) + int(std::ceil(size * 483 / 2048))) << size;
    // Ordinary text keeps that box, so lines of one size share a baseline.
    const TextMetrics text = measureText("Seams and poles: 12", size);
    EXPECT_EQ(text.ascent, empty.ascent);
    EXPECT_EQ(text.descent, empty.descent);
  }
  Image image = panel(20, 20);
  drawText(image, 2, 2, "", 13, kInk);
  EXPECT_EQ(inkBox(image)[0], -1);
}

TEST(Type, WidthsFollowTheGlyphs) {
  EXPECT_LT(measureText("ii", 13).width, measureText("WW", 13).width);
  EXPECT_LT(measureText("W", 13).width, measureText("WW", 13).width);
  EXPECT_LT(measureText("stretch", 13).width, measureText("stretch", 26).width);
  EXPECT_LT(measureText("stretch", 13).width, measureText("stretch", 13, Weight::Bold).width);
  // A space advances without ink.
  EXPECT_GT(measureText("a b", 13).width, measureText("ab", 13).width);
}

TEST(Type, InkLiesInsideTheMeasuredBox) {
  for (const std::string text : {"Agjy|Q", "L2 stretch, normalised (1: isometric)", "≥1.5", "σ₁/σ₂ × 10⁻²", "j", "ÅÉ"}) {
    for (Weight weight : {Weight::Regular, Weight::Bold}) {
      SCOPED_TRACE(text);
      const TextMetrics m = measureText(text, 15, weight);
      Image image = panel(m.width + 40, m.height + 40);
      drawText(image, 20, 20, text, 15, kInk, weight);
      const std::vector<int> box = inkBox(image);
      ASSERT_GE(box[0], 0);
      EXPECT_GE(box[0], 20);
      EXPECT_GE(box[1], 20);
      EXPECT_LE(box[2], 20 + m.width);
      EXPECT_LE(box[3], 20 + m.height);
      // And it fills the box's width nearly: no more than a pixel or two of side bearing each side.
      EXPECT_LE(box[0], 22);
      EXPECT_GE(box[2], 20 + m.width - 3);
    }
  }
}

// Coverage is blended: fully covered pixels take the ink exactly, edges lie strictly between.
TEST(Type, GlyphEdgesAreAntiAliased) {
  Image image = panel(60, 30);
  drawText(image, 4, 4, "Os", 20, kInk);
  int full = 0, partial = 0;
  const Vec3 ink = stored(kInk), background = stored(kBackground);
  for (int row = 0; row < image.height; ++row)
    for (int x = 0; x < image.width; ++x) {
      const Vec3 c = pixelColour(image, x, row);
      if (c == ink) {
        ++full;
        continue;
      }
      if (c == background) continue;
      // old (1 - a) + ink a, one a for all three channels, 0 < a < 1.
      const double a = (c.x() - background.x()) / (ink.x() - background.x());
      EXPECT_GT(a, 0.0);
      EXPECT_LT(a, 1.0);
      for (int k = 1; k < 3; ++k) EXPECT_NEAR(c[k], background[k] + a * (ink[k] - background[k]), 1e-5) << x << ", " << row;
      ++partial;
    }
  EXPECT_GT(full, 10);
  EXPECT_GT(partial, 10);  // the round O and s cannot be drawn with whole pixels only
}

TEST(Type, DrawingIsDeterministicAndPositional) {
  const std::string text = "UV error, in texels of 1024×1024";
  Image a = panel(320, 30), b = panel(320, 30), moved = panel(320, 30);
  drawText(a, 3, 5, text, 13, kInk);
  drawText(b, 3, 5, text, 13, kInk);
  EXPECT_EQ(a.pixels, b.pixels);
  // One pixel right and down: the same pixels, shifted (pens stay on whole pixels).
  drawText(moved, 4, 6, text, 13, kInk);
  for (int row = 0; row + 1 < 30; ++row)
    for (int x = 0; x + 1 < 320; ++x) ASSERT_EQ(pixelColour(a, x, row), pixelColour(moved, x + 1, row + 1)) << x << ", " << row;
}

// Glyphs are cached under one lock: threads drawing at once get what one thread draws alone.
TEST(Type, ThreadsDrawTheSamePixels) {
  Image alone = panel(200, 24);
  drawText(alone, 2, 2, "Threads ≥ 4: σ²", 17, kInk, Weight::Bold);
  std::vector<Image> images(4, panel(200, 24));
  std::vector<std::thread> threads;
  for (Image& image : images)
    threads.emplace_back([&image] {
      for (double size : {11.0, 12.0, 16.0}) measureText("warm another size", size);
      drawText(image, 2, 2, "Threads ≥ 4: σ²", 17, kInk, Weight::Bold);
    });
  for (std::thread& thread : threads) thread.join();
  for (const Image& image : images) EXPECT_EQ(image.pixels, alone.pixels);
}

TEST(Type, Utf8IsDecoded) {
  // "≥" is one character the face has, not three bytes drawn as missing glyphs.
  const TextMetrics geq = measureText("≥", 15), question = measureText("?", 15);
  EXPECT_LT(geq.width, 2 * question.width);
  Image a = panel(40, 30), b = panel(40, 30), missing = panel(40, 30), fffd = panel(40, 30);
  drawText(a, 4, 4, "≥", 15, kInk);
  drawText(b, 4, 4, "?", 15, kInk);
  EXPECT_NE(inkBox(a)[0], -1);
  EXPECT_NE(a.pixels, b.pixels);
  // Malformed UTF-8 (a lone continuation byte, "≥" cut short, an overlong '>') draws as U+FFFD,
  // one per byte that cannot start a character.
  drawText(missing, 4, 4, "\xB3", 15, kInk);
  drawText(fffd, 4, 4, "\xEF\xBF\xBD", 15, kInk);
  EXPECT_NE(inkBox(fffd)[0], -1);
  EXPECT_EQ(missing.pixels, fffd.pixels);
  const int twice = measureText("\xEF\xBF\xBD\xEF\xBF\xBD", 15).width;
  EXPECT_EQ(measureText("\xE2\x89", 15).width, twice);
  EXPECT_EQ(measureText("\xC0\xBE", 15).width, twice);
  EXPECT_GT(twice, measureText("\xEF\xBF\xBD", 15).width);
}

TEST(Type, KerningPairsDrawCloser) {
  // DejaVu Sans has a 'kern' table (FT_HAS_KERNING): A V -0.83 pixels at 13 pixels per em, drawn
  // one pixel closer; T o -2.2, two.
  EXPECT_LT(measureText("AV", 13).width, measureText("A", 13).width + measureText("V", 13).width);
  EXPECT_LT(measureText("To", 13).width, measureText("T", 13).width + measureText("o", 13).width);
  // No pair between H and H.
  EXPECT_EQ(measureText("HH", 13).width, 2 * measureText("H", 13).width);
}

TEST(Type, ClipsAtTheImageEdges) {
  Image whole = panel(80, 30), clipped = panel(80, 30);
  drawText(whole, 10, 5, "Clip", 18, kInk);
  drawText(clipped, 10 - 80, 5 - 30, "Clip", 18, kInk);  // entirely outside: nothing
  EXPECT_EQ(inkBox(clipped)[0], -1);
  Image left = panel(80, 30);
  drawText(left, -6, 5, "Clip", 18, kInk);  // partly outside: the rest as drawn whole, shifted
  for (int row = 0; row < 30; ++row)
    for (int x = 0; x + 16 < 80; ++x) ASSERT_EQ(pixelColour(left, x, row), pixelColour(whole, x + 16, row));
  drawText(left, std::numeric_limits<int>::max() - 4, std::numeric_limits<int>::min(), "far", 18, kInk);  // no overflow
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::views
