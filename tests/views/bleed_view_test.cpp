// The bleed view, texel by texel: two 8-texel squares one texel apart in a 64 x 64 texture; at
// level 1 (32 x 32) the gap is half a texel and the facing columns clash. Each texel's colour says
// what it holds, and the legend's figures are texelStatistics' for that level.
#include <gtest/gtest.h>

#include <string>

#include "analysis/texel_layout.h"
#include "core/error.h"
#include "views/canvas.h"
#include "views/mapped_layout.h"
#include "views/palette.h"
#include "views/views.h"

namespace uvtk::views {
namespace {
namespace UVTK_TEST_FILE {

// A square of `side` texels at texel (x, y) of a 64 x 64 texture: two triangles, one chart.
void addSquare(Mapped& m, double x, double y, double side) {
  const int base = int(m.mesh.positions.size());
  const Vec2 corners[4] = {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
  for (const Vec2& c : corners) m.mesh.positions.emplace_back(c.x(), c.y(), 0.0);
  for (const Triangle& t : {Triangle{base, base + 1, base + 2}, Triangle{base, base + 2, base + 3}}) {
    m.mesh.triangles.push_back(t);
    for (int k = 0; k < 3; ++k) m.uv.uv.push_back(corners[t[k] - base] / 64.0);
    m.uv.faceFlags.push_back(kFaceOk);
  }
}

Mapped twoSquaresOneTexelApart() {
  Mapped m;
  addSquare(m, 8, 8, 8);
  addSquare(m, 17, 8, 8);
  analysis::JudgementOptions options;
  options.textureSize = {64, 64};
  m.judgement = analysis::judge(m.mesh, m.uv, options);
  return m;
}

// The picture's colour at the centre of texel (x, y) of a level of `texels` a side, v up.
Vec3 texelColour(const Image& image, int x, int y, int texels) {
  const int pixels = image.width / texels;
  return pixelColour(image, x * pixels + pixels / 2, image.width - 1 - (y * pixels + pixels / 2));
}

TEST(BleedView, EachTexelShowsWhatItHoldsAndTheLegendTheLevelsFigures) {
  const Mapped m = twoSquaresOneTexelApart();
  ViewOptions o;
  o.layoutSize = 64;
  const DrawnView drawn = drawViewAndLegend(View::Bleed, m.input(), o);  // the first level where they mix
  ASSERT_EQ(drawn.image.width, 64);
  const analysis::TexelStatistics statistics = analysis::texelStatistics(m.mesh, m.uv, 64, 64);
  ASSERT_EQ(statistics.firstBleedLevel, std::optional<int>(1));
  const analysis::TexelLevel& level = statistics.levels[1];
  const std::vector<std::string> expected = {
      "texels at mip level 1 (32 x 32) of a 64 x 64 texture, 2 charts",
      "gutter 0.5 texels here; charts first mix at level 1",
      "mapped: " + std::to_string(level.mapped) + " texels",
      "gutter a lookup reads: " + std::to_string(level.touched - level.mapped),
      "two charts: 0",
      "clashes (a lookup mixes charts): " + std::to_string(level.clashes),
      "empty"};
  EXPECT_EQ(drawn.legend.lines(), expected);
  // Level 1: A covers texels 4..7, B 8..12 (texel 8's children 16 and 17 hold B): columns 7 and 8
  // clash over rows 4..7, 8 texels; a texel beside a chart is the gutter's reach; far ones empty.
  EXPECT_EQ(level.clashes, 8u);
  const Image& image = drawn.image;
  const Vec3 a = texelColour(image, 5, 5, 32), b = texelColour(image, 10, 5, 32);
  for (const Vec3& chart : {a, b})
    for (const Vec3& other : {Vec3(1.00, 0.85, 0.10), Vec3(0.90, 0.10, 0.10), Vec3(0.45, 0.45, 0.45), kLayoutBackground})
      EXPECT_GT((chart - other).cwiseAbs().maxCoeff(), 0.05);
  EXPECT_GT((a - b).cwiseAbs().maxCoeff(), 0.05);  // two charts, two colours
  for (int y = 4; y <= 7; ++y) {
    EXPECT_LT((texelColour(image, 7, y, 32) - Vec3(1.00, 0.85, 0.10)).cwiseAbs().maxCoeff(), 1e-6) << y;
    EXPECT_LT((texelColour(image, 8, y, 32) - Vec3(1.00, 0.85, 0.10)).cwiseAbs().maxCoeff(), 1e-6) << y;
    EXPECT_LT((texelColour(image, 3, y, 32) - Vec3(0.45, 0.45, 0.45)).cwiseAbs().maxCoeff(), 1e-6) << y;
  }
  EXPECT_LT((texelColour(image, 1, 1, 32) - kLayoutBackground).cwiseAbs().maxCoeff(), 1e-6);

  // At level 0 the squares are apart: no clash, the gap's texels are the gutter's reach.
  o.bleedLevel = 0;
  const DrawnView zero = drawViewAndLegend(View::Bleed, m.input(), o);
  EXPECT_EQ(zero.legend.lines()[5], "clashes (a lookup mixes charts): 0");
  EXPECT_LT((texelColour(zero.image, 16, 10, 64) - Vec3(0.45, 0.45, 0.45)).cwiseAbs().maxCoeff(), 1e-6);
  o.bleedLevel = 7;  // a 64 x 64 texture has levels 0 to 6
  EXPECT_THROW(drawViewAndLegend(View::Bleed, m.input(), o), UsageError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::views
