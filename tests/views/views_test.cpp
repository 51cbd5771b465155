// The vocabulary of the views: names, colour maps, scales, legends, the contact sheet, and the
// analysis functions the views draw from (seam edge lists, coverage counts).
#include "views/views.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/overlap.h"
#include "core/error.h"
#include "core/seam_edges.h"
#include "doubles.h"
#include "views/canvas.h"
#include "views/legend.h"
#include "views/palette.h"
#include "views/type.h"

namespace uvtk::views {
namespace {
namespace UVTK_TEST_FILE {

// Colours compared as an Image stores them, in float.

// ---- names ----

TEST(ViewNames, RoundTripAndParseLists) {
  for (View v : {View::Checker, View::Uvgrid, View::Stretch, View::Linf, View::Angle, View::Area, View::Seams,
                 View::UvError, View::Layout}) {
    ASSERT_EQ(parseView(toString(v)), v);
    EXPECT_EQ(needsExactMapping(v), v == View::UvError);
  }
  EXPECT_STREQ(toString(View::UvError), "uverror");
  EXPECT_FALSE(parseView("Stretch"));
  EXPECT_FALSE(parseView(""));
  EXPECT_EQ(parseViewList("stretch,seams,uverror"), (std::vector<View>{View::Stretch, View::Seams, View::UvError}));
  EXPECT_EQ(parseViewList("layout"), (std::vector<View>{View::Layout}));
}

TEST(ViewNames, ABadEntryIsAUsageErrorNamingItAndTheValidNames) {
  try {
    parseViewList("stretch,strech,area");
    FAIL() << "no exception";
  } catch (const UsageError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'strech'"), std::string::npos) << message;
    for (const char* name : {"checker", "uvgrid", "stretch", "linf", "angle", "area", "seams", "uverror", "layout"})
      EXPECT_NE(message.find(name), std::string::npos) << message;
  }
  for (const char* list : {"", "stretch,", ",stretch", "stretch,,area", "stretch area"})
    EXPECT_THROW(parseViewList(list), UsageError) << "'" << list << "'";
}

// ---- colour maps ----

double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
double luminance(const Vec3& c) {  // relative luminance of an sRGB colour (ITU-R BT.709 primaries)
  return 0.2126 * srgbToLinear(c.x()) + 0.7152 * srgbToLinear(c.y()) + 0.0722 * srgbToLinear(c.z());
}

TEST(Palette, SequentialIsViridisWithRisingLuminance) {
  EXPECT_TRUE(paletteColour(Palette::Sequential, 0.0).isApprox(Vec3(0.267004, 0.004874, 0.329415), 1e-12));
  EXPECT_TRUE(paletteColour(Palette::Sequential, 1.0).isApprox(Vec3(0.993248, 0.906157, 0.143936), 1e-12));
  EXPECT_TRUE(paletteColour(Palette::Sequential, 0.5).isApprox(Vec3(0.127568, 0.566949, 0.550556), 1e-12));  // entry 128
  EXPECT_EQ(paletteColour(Palette::Sequential, -3.0), paletteColour(Palette::Sequential, 0.0));  // clamped
  EXPECT_EQ(paletteColour(Palette::Sequential, 7.0), paletteColour(Palette::Sequential, 1.0));
  double previous = -1.0;
  for (int k = 0; k <= 1000; ++k) {
    const double y = luminance(paletteColour(Palette::Sequential, k / 1000.0));
    ASSERT_GT(y, previous) << k;
    previous = y;
  }
}

TEST(Palette, DivergingIsWhiteAtTheCentreRedBelowBlueAbove) {
  EXPECT_EQ(paletteColour(Palette::Diverging, 0.5), Vec3(1.0, 1.0, 1.0));
  const Vec3 low = paletteColour(Palette::Diverging, 0.0), high = paletteColour(Palette::Diverging, 1.0);
  EXPECT_GT(low.x(), low.y() + 0.3);
  EXPECT_GT(low.x(), low.z() + 0.2);
  EXPECT_GT(high.z(), high.x() + 0.3);
  EXPECT_GT(high.z(), 1.5 * high.y());
  // Whiter towards the centre from both sides.
  for (double t : {0.1, 0.2, 0.3, 0.4}) {
    EXPECT_LT(luminance(paletteColour(Palette::Diverging, t)), luminance(paletteColour(Palette::Diverging, t + 0.05)));
    EXPECT_GT(luminance(paletteColour(Palette::Diverging, 1.0 - t)), 0.0);
    EXPECT_LT(luminance(paletteColour(Palette::Diverging, 1.0 - t)), luminance(paletteColour(Palette::Diverging, 0.95 - t)));
  }
}

TEST(ColourScale, LinearAndLogarithmicPositions) {
  const ColourScale linear{Palette::Sequential, 1.0, 3.0, false};
  EXPECT_DOUBLE_EQ(linear.position(1.0), 0.0);
  EXPECT_DOUBLE_EQ(linear.position(2.5), 0.75);
  EXPECT_DOUBLE_EQ(linear.position(9.0), 1.0);
  EXPECT_DOUBLE_EQ(linear.position(0.0), 0.0);
  const ColourScale decades{Palette::Sequential, -4.0, 2.0, true};
  EXPECT_DOUBLE_EQ(decades.position(0.0), 0.0);
  EXPECT_DOUBLE_EQ(decades.position(1e-7), 0.0);
  EXPECT_NEAR(decades.position(1e-1), 0.5, 1e-15);
  EXPECT_DOUBLE_EQ(decades.position(100.0), 1.0);
  // Area: symmetric about 0, which is white.
  const ColourScale area{Palette::Diverging, -0.5, 0.5, false};
  EXPECT_EQ(area.colour(0.0), Vec3(1.0, 1.0, 1.0));
  EXPECT_GT(area.colour(0.4).z(), area.colour(0.4).x());  // compressed: blue
  EXPECT_GT(area.colour(-0.4).x(), area.colour(-0.4).z());  // stretched: red
}

TEST(Legend, LabelsAreDistinctWithFewDigits) {
  EXPECT_EQ(distinctLabels({1.0, 1.5, 2.0}), (std::vector<std::string>{"1", "1.5", "2"}));
  EXPECT_EQ(distinctLabels({1.0, 1.00002, 1.00004}), (std::vector<std::string>{"1", "1.00002", "1.00004"}));
  EXPECT_EQ(formatNumber(-0.0), "0");
}

TEST(Legend, StripBelowTheViewWithBarSwatchesAndText) {
  Image view(50, 40, 3, 0.25f);
  Legend legend;
  legend.title = {"Title"};
  legend.bar = ColourBar{{Palette::Sequential, 0.0, 1.0, false}, {{0.0, "0"}, {1.0, "1"}}};
  legend.entries = {{Vec3(1, 0, 1), "flipped: 1"}, {Vec3(0.3, 0.3, 0.3), "twice", 2}};
  const Image out = withLegend(view, legend);
  EXPECT_EQ(out.width, 2 * kLegendPadding + kBarLength);  // the bar is wider than the view
  EXPECT_GT(out.height, view.height + kBarHeight);
  EXPECT_EQ(pixelColour(out, 10, 10), Vec3::Constant(0.25f).cast<double>());  // the view, untouched
  EXPECT_TRUE(near(pixelColour(out, 100, 10), kPanelColour));  // right of the view: panel
  const BarPlacement bar = barPlacement(legend, view.height);
  for (int i : {0, 100, kBarLength - 1}) {
    const Vec3 expected = paletteColour(Palette::Sequential, (i + 0.5) / kBarLength);
    EXPECT_TRUE(near(pixelColour(out, bar.left + i, bar.top + kBarHeight / 2), expected)) << i;
  }
  EXPECT_EQ(bar.columnAt(0.0), bar.left);
  EXPECT_EQ(bar.columnAt(1.0), bar.left + kBarLength - 1);
  // The swatches: the flipped colour and the hatched one are in the strip.
  bool magenta = false, white = false;
  for (int row = view.height; row < out.height; ++row)
    for (int x = 0; x < out.width; ++x) {
      magenta = magenta || pixelColour(out, x, row) == Vec3(1, 0, 1);
      white = white || pixelColour(out, x, row) == Vec3(1, 1, 1);
    }
  EXPECT_TRUE(magenta);
  EXPECT_TRUE(white);
}

// ---- contact sheet ----

TEST(ContactSheet, GridOfTilesWithTheirLabelsUnderThem) {
  const Image black(40, 30, 3, 0.0f), grey(1, 1, 1, 0.5f);
  Image green(20, 50, 3, 0.0f);
  for (int row = 0; row < 50; ++row)
    for (int x = 0; x < 20; ++x) green.at(x, row, 1) = 1.0f;
  const std::vector<std::pair<std::string, Image>> tiles = {{"A", black}, {"Green tile ≥ 2", green}, {"G", grey}};
  const Image sheet = contactSheet(tiles, 2);
  const TextMetrics label = measureText("Green tile ≥ 2", 15);
  const int pad = 8, gap = 4, text = label.height;
  EXPECT_EQ(text, measureText("A", 15).height);  // one line box for all labels
  const int column0 = 40, column1 = std::max(20, label.width);
  EXPECT_GT(column1, 20);  // the label is wider than its tile
  EXPECT_EQ(sheet.width, pad + column0 + pad + column1 + pad);
  EXPECT_EQ(sheet.height, pad + (50 + gap + text) + pad + (1 + gap + text) + pad);
  EXPECT_EQ(sheet.channels, 3);
  EXPECT_EQ(pixelColour(sheet, pad, pad), Vec3::Zero());                                 // the black tile
  EXPECT_EQ(pixelColour(sheet, pad + column0 + pad + 19, pad + 49), Vec3(0, 1, 0));      // green tile's last pixel
  const int row1 = pad + 50 + gap + text + pad;
  EXPECT_EQ(pixelColour(sheet, pad, row1), Vec3::Constant(0.5));                        // grey spread to RGB
  EXPECT_TRUE(near(pixelColour(sheet, pad + 1, row1), kPanelColour));

  // The label under the green tile, exactly as drawText draws it on the panel at 15 pixels per em.
  Image expected(sheet.width, sheet.height, 3);
  fillRect(expected, 0, 0, expected.width, expected.height, kPanelColour);
  drawText(expected, pad + column0 + pad, pad + 50 + gap, "Green tile ≥ 2", 15, kTextColour);
  int textPixels = 0;
  for (int row = pad + 50 + gap; row < pad + 50 + gap + text; ++row)
    for (int x = pad + column0 + pad; x < sheet.width - pad; ++x) {
      ASSERT_EQ(pixelColour(sheet, x, row), pixelColour(expected, x, row)) << x << ", " << row;
      textPixels += !near(pixelColour(sheet, x, row), kPanelColour);
    }
  EXPECT_GT(textPixels, 50);

  EXPECT_THROW(contactSheet({}, 2), UsageError);
  EXPECT_THROW(contactSheet(tiles, 0), UsageError);
}

// ---- the analysis functions behind the seams and layout views ----

// Two triangles sharing the edge (1, 2); the second face's UVs moved by one in u: a wrap seam.
TEST(SeamEdgeList, GivesTheCornersOfBothSides) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {2, 1, 3}};
  UvMap uv;
  uv.uv = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 0}, {2, 1}};
  uv.faceFlags.assign(2, kFaceOk);
  const std::vector<SeamEdge> edges = seamEdgeList(mesh, uv);
  ASSERT_EQ(edges.size(), 1u);
  EXPECT_EQ(edges[0].a, 1);
  EXPECT_EQ(edges[0].b, 2);
  EXPECT_TRUE(edges[0].wrap);
  EXPECT_EQ(edges[0].cornerA, (std::array<std::size_t, 2>{1, 4}));
  EXPECT_EQ(edges[0].cornerB, (std::array<std::size_t, 2>{2, 3}));
  EXPECT_EQ(classifySeamEdges(mesh, uv).wrapEdges, 1u);

  uv.uv[4].y() += 0.5;  // vertex 1 no longer a whole turn apart: a cut
  ASSERT_EQ(seamEdgeList(mesh, uv).size(), 1u);
  EXPECT_FALSE(seamEdgeList(mesh, uv)[0].wrap);
}

// Unit right triangles at (0, 0) and moved by (1/4, 1/4), on an 8 x 8 grid over [0, 2]^2: cell
// centres at 1/8 + k/4.
TEST(CoverageCounts, CountsEachCentreByTheFacesCoveringIt) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 0}, {1.25, 0.25, 0}, {0.25, 1.25, 0}};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  UvMap uv;
  for (const Vec3& p : mesh.positions) uv.uv.push_back(p.head<2>());
  uv.faceFlags.assign(2, kFaceOk);
  const analysis::FaceMeasures faces = analysis::measureFaces(mesh, uv);
  const analysis::UvGrid grid{Eigen::AlignedBox2d(Vec2(0, 0), Vec2(2, 2)), 8};
  const std::vector<std::uint8_t> counts = analysis::coverageCounts(uv, faces, grid);
  auto at = [&](int x, int y) { return int(counts[std::size_t(y * 8 + x)]); };
  EXPECT_EQ(at(0, 0), 1);  // (1/8, 1/8): the first only
  EXPECT_EQ(at(1, 1), 2);  // (3/8, 3/8): both
  EXPECT_EQ(at(3, 1), 1);  // (7/8, 3/8): the second only
  EXPECT_EQ(at(7, 7), 0);
  std::vector<std::size_t> seen;
  analysis::forEachCoveredPixel(uv, faces, grid, [&](std::size_t face, int x, int y) {
    if (x == 1 && y == 1) seen.push_back(face);
  });
  EXPECT_EQ(seen, (std::vector<std::size_t>{0, 1}));  // face by face in index order
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::views
