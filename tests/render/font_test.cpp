// The 5 x 7 bitmap font pixel by pixel.
#include "render/font.h"

#include <gtest/gtest.h>

#include <climits>
#include <string>

#include "core/error.h"

namespace uvtk::render {
namespace {
namespace UVTK_TEST_FILE {

const float kInk[4] = {1.0f, 0.5f, 0.25f, 1.0f};

int countSet(const Image& image) {
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) count += image.at(x, y, 0) > 0.0f;
  return count;
}

TEST(DrawText, SetsTheScaledPixelsOfTheGlyph) {
  // '1' is, from the top: ..#.. / .##.. / ..#.. (four times) / .###.  At scale 2 from (1, 1) the
  // font pixel (column c, row r) is the block x in [1 + 2c, 3 + 2c), y in [1 + 2r, 3 + 2r).
  Image image(16, 16, 1);
  drawText(image, 1, 1, "1", 2, kInk);
  EXPECT_EQ(image.at(5, 1, 0), 1.0f);   // row 0, column 2
  EXPECT_EQ(image.at(6, 2, 0), 1.0f);
  EXPECT_EQ(image.at(4, 1, 0), 0.0f);   // row 0, column 1
  EXPECT_EQ(image.at(7, 1, 0), 0.0f);   // row 0, column 3
  EXPECT_EQ(image.at(3, 3, 0), 1.0f);   // row 1, column 1
  EXPECT_EQ(image.at(4, 4, 0), 1.0f);
  EXPECT_EQ(image.at(3, 5, 0), 0.0f);   // row 2, column 1
  EXPECT_EQ(image.at(3, 13, 0), 1.0f);  // row 6, columns 1..3
  EXPECT_EQ(image.at(8, 14, 0), 1.0f);
  EXPECT_EQ(image.at(9, 14, 0), 0.0f);  // row 6, column 4
  EXPECT_EQ(image.at(5, 15, 0), 0.0f);  // below the glyph
  EXPECT_EQ(countSet(image), 10 * 4);   // ten font pixels of four image pixels each
}

TEST(DrawText, WritesTheColourToEachChannelAndAdvancesSixColumns) {
  Image image(12, 7, 3);
  drawText(image, 0, 0, "--", 1, kInk);  // '-' is row 3, columns 0..4
  EXPECT_EQ(image.at(0, 3, 0), 1.0f);
  EXPECT_EQ(image.at(0, 3, 1), 0.5f);
  EXPECT_EQ(image.at(0, 3, 2), 0.25f);
  EXPECT_EQ(image.at(4, 3, 0), 1.0f);
  EXPECT_EQ(image.at(5, 3, 0), 0.0f);  // the blank column between glyphs
  EXPECT_EQ(image.at(6, 3, 0), 1.0f);
  EXPECT_EQ(image.at(10, 3, 0), 1.0f);
  EXPECT_EQ(image.at(11, 3, 0), 0.0f);
}

TEST(DrawText, DrawsLowerCaseAsCapitalsAndUnknownCharactersAsQuestionMarks) {
  Image lower(6, 7, 1), upper(6, 7, 1), unknown(6, 7, 1), question(6, 7, 1);
  drawText(lower, 0, 0, "g", 1, kInk);
  drawText(upper, 0, 0, "G", 1, kInk);
  drawText(unknown, 0, 0, "~", 1, kInk);
  drawText(question, 0, 0, "?", 1, kInk);
  EXPECT_EQ(lower.pixels, upper.pixels);
  EXPECT_EQ(unknown.pixels, question.pixels);
  EXPECT_GT(countSet(question), 0);
  Image space(6, 7, 1);
  drawText(space, 0, 0, " ", 1, kInk);
  EXPECT_EQ(countSet(space), 0);
}

TEST(DrawText, SkipsThePixelsOutsideTheImage) {
  Image whole(16, 16, 1), clipped(16, 16, 1);
  drawText(whole, 0, 0, "1", 2, kInk);
  // From (-4, -2) font columns 0, 1 and row 0 fall outside: of the ten pixels of '1' it loses
  // row 0's, row 1's column 1 and row 6's column 1, and font pixel (2, 1) lands at (0, 0).
  drawText(clipped, -4, -2, "1", 2, kInk);
  EXPECT_EQ(countSet(whole), 10 * 4);
  EXPECT_EQ(countSet(clipped), (10 - 3) * 4);
  EXPECT_EQ(clipped.at(0, 0, 0), 1.0f);
  EXPECT_EQ(clipped.at(1, 1, 0), 1.0f);

  // '#' starts with row .#.#.: at (2, 2) and scale 3 only its blank first block lies in a 4 x 4
  // image; text far off any side draws nothing and overflows nothing.
  Image corner(4, 4, 1);
  drawText(corner, 2, 2, "#####", 3, kInk);
  drawText(corner, INT_MAX - 2, INT_MAX - 2, "#", 1000, kInk);
  drawText(corner, INT_MIN, INT_MIN, "##########", 1000000, kInk);
  EXPECT_EQ(countSet(corner), 0);
}

TEST(DrawText, RejectsAScaleBelowOne) {
  Image image(8, 8, 1);
  EXPECT_THROW(drawText(image, 0, 0, "A", 0, kInk), UsageError);
}

TEST(TextWidth, IsSixColumnsPerGlyphLessTheLastGap) {
  EXPECT_EQ(textWidth("", 3), 0);
  EXPECT_EQ(textWidth("A", 1), 5);
  EXPECT_EQ(textWidth("AB", 2), 22);
  EXPECT_EQ(textWidth("A1", 6), 66);
  EXPECT_EQ(textHeight(3), 21);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::render
