// The Pareto chart: the front of a hand-made set, and the chart checked pixel by pixel where the
// frame says a point lies (its dot, the zero row, the front line), its decades and its errors.
#include "views/pareto.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "doubles.h"
#include "views/canvas.h"
#include "views/palette.h"
#include "views/type.h"

namespace uvtk::views {
namespace {
namespace UVTK_TEST_FILE {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The colour of the pixel that holds image position `at`.
Vec3 colourAt(const Image& image, const Vec2& at) {
  return pixelColour(image, int(std::floor(at.x())), int(std::floor(at.y())));
}

// Colours are stored as floats.
testing::AssertionResult sameColour(const Vec3& actual, const Vec3& expected) {
  if ((actual - expected).cwiseAbs().maxCoeff() < 1e-6) return testing::AssertionSuccess();
  return testing::AssertionFailure() << actual.transpose() << " vs " << expected.transpose();
}

ParetoChartOptions options() {
  ParetoChartOptions o;
  o.title = "Projectors: speed against accuracy";
  o.xLabel = "ns per vertex";
  o.yLabel = "Max error (texels)";
  o.groupNames = {"planar", "sphere", "cylinder"};
  return o;
}

TEST(ParetoFrontTest, KeepsUndominatedPointsByIncreasingX) {
  const std::vector<ChartPoint> points = {
      {"A", 1, 10},      // 0: front
      {"B", 2, 5},       // 1: front
      {"C", 2, 7},       // 2: same x as B, larger y
      {"D", 3, 5},       // 3: same y as B, larger x
      {"E", 4, 1},       // 4: front
      {"F", 4, 1},       // 5: equal to E, so neither dominates the other
      {"G", 0.5, kNaN},  // 6: ignored
      {"H", kInf, 0},    // 7: ignored
      {"I", 5, 2},       // 8: dominated by E
      {"J", 10, 0},      // 9: front, exact
      {"K", 0.8, 20},    // 10: front, the cheapest
      {"L", 20, 0},      // 11: as exact as J, dearer
  };
  EXPECT_EQ(paretoFront(points), (std::vector<std::size_t>{10, 0, 1, 4, 5, 9}));
}

// Each group's own front: a fast inexact point of one group does not hide another group's points.
TEST(ParetoFrontTest, OneFrontPerGroup) {
  std::vector<ChartPoint> points = {{"A", 1, 10}, {"B", 2, 5}, {"C", 0.5, 1}, {"D", 3, 3}, {"E", 4, 4}};
  points[0].group = points[1].group = points[3].group = 2;  // A, B, D: one projector
  points[2].group = points[4].group = 0;                    // C dominates all of them, and E
  EXPECT_EQ(paretoFront(points), (std::vector<std::size_t>{2}));
  EXPECT_EQ(paretoFrontsByGroup(points), (std::vector<std::vector<std::size_t>>{{2}, {0, 1, 3}}));
}

TEST(ParetoFrontTest, EmptyWithoutFinitePoints) {
  EXPECT_TRUE(paretoFront({}).empty());
  EXPECT_TRUE(paretoFront({{"A", kNaN, 1}, {"B", 1, -kInf}}).empty());
  EXPECT_EQ(paretoFront({{"A", kNaN, 1}, {"B", 3, 4}}), (std::vector<std::size_t>{1}));
}

TEST(ParetoChartTest, HasTheRequestedSize) {
  const std::vector<ChartPoint> points = {{"A", 1, 0.5}, {"B", 30, 0.01}};
  const Image chart = paretoChart(points, options());
  EXPECT_EQ(chart.width, 960);
  EXPECT_EQ(chart.height, 640);
  EXPECT_EQ(chart.channels, 3);
  ParetoChartOptions small = options();
  small.width = 300, small.height = 220;
  const Image smaller = paretoChart(points, small);
  EXPECT_EQ(smaller.width, 300);
  EXPECT_EQ(smaller.height, 220);
}

TEST(ParetoChartTest, DecadesPaddedToWholeDecades) {
  const ChartFrame frame = chartFrame({{"A", 0.003, 0.4}, {"B", 250, 2e-5}, {"C", 7, 0}}, options());
  EXPECT_EQ(frame.xDecadeLo, -3);
  EXPECT_EQ(frame.xDecadeHi, 3);
  EXPECT_EQ(frame.yDecadeLo, -5);
  EXPECT_EQ(frame.yDecadeHi, 0);
  // A single value on a decade still spans one.
  const ChartFrame single = chartFrame({{"A", 10, 10}}, options());
  EXPECT_EQ(single.xDecadeLo, 1);
  EXPECT_EQ(single.xDecadeHi, 2);
  EXPECT_EQ(single.yDecadeLo, 1);
  EXPECT_EQ(single.yDecadeHi, 2);
}

TEST(ParetoChartTest, DecadesEquallySpacedWithinTheBox) {
  const ChartFrame frame = chartFrame({{"A", 1, 1}, {"B", 100, 100}}, options());
  const double y = 10;
  const double xStep1 = frame.pixelOf(10, y).x() - frame.pixelOf(1, y).x();
  const double xStep2 = frame.pixelOf(100, y).x() - frame.pixelOf(10, y).x();
  EXPECT_GT(xStep1, 0);
  EXPECT_NEAR(xStep1, xStep2, 1.0);
  // Errors grow upwards.
  const double yStep1 = frame.pixelOf(y, 1).y() - frame.pixelOf(y, 10).y();
  const double yStep2 = frame.pixelOf(y, 10).y() - frame.pixelOf(y, 100).y();
  EXPECT_GT(yStep1, 0);
  EXPECT_NEAR(yStep1, yStep2, 1.0);
  // The outer decades lie inside the box, kChartInset from its lines.
  EXPECT_DOUBLE_EQ(frame.pixelOf(1, 1).x(), frame.left + kChartInset);
  EXPECT_DOUBLE_EQ(frame.pixelOf(100, 1).x(), frame.right - kChartInset);
  EXPECT_DOUBLE_EQ(frame.pixelOf(1, 1).y(), frame.bottom - kChartInset);
  EXPECT_DOUBLE_EQ(frame.pixelOf(1, 100).y(), frame.top + kChartInset);
}

TEST(ParetoChartTest, DrawsDecadesBeyondDoubleRange) {
  // Decades 10^-324 (below the least subnormal) and 10^309 (beyond the largest double).
  const std::vector<ChartPoint> points = {{"TINY", 5e-324, 1e308, 0}, {"HUGE", 1.5e308, 5e-324, 1}};
  const ChartFrame frame = chartFrame(points, options());
  EXPECT_EQ(frame.xDecadeLo, -324);
  EXPECT_EQ(frame.xDecadeHi, 309);
  const Image chart = paretoChart(points, options());
  for (const ChartPoint& p : points)
    EXPECT_TRUE(sameColour(colourAt(chart, frame.pixelOf(p.x, p.y)), groupColour(p.group)));
}

TEST(ParetoChartTest, DotsTakeTheirGroupColourAtTheirPixel) {
  const std::vector<ChartPoint> points = {
      {"PLANAR FAST", 2, 0.3, 0}, {"SPHERE FLOAT", 40, 0.002, 1},
      {"CYLINDER", 300, 0.05, 2}, {"SLOW AND BAD", 500, 1, 1},  // off the front: a plain dot
      {"GROUP 9", 0.02, 3, 9},                                  // beyond the named groups: the colours repeat
  };
  const Image chart = paretoChart(points, options());
  const ChartFrame frame = chartFrame(points, options());
  for (const ChartPoint& p : points) {
    SCOPED_TRACE(p.label);
    EXPECT_TRUE(sameColour(colourAt(chart, frame.pixelOf(p.x, p.y)), groupColour(p.group)));
  }
  EXPECT_TRUE(sameColour(groupColour(9), groupColour(2)));
  EXPECT_NE(groupColour(0), groupColour(1));
}

TEST(ParetoChartTest, ZeroErrorOnTheBaselineBelowTheBox) {
  const std::vector<ChartPoint> points = {{"EXACT", 50, 0, 1}, {"FAST", 1, 0.1, 0}};
  const ChartFrame frame = chartFrame(points, options());
  ASSERT_TRUE(frame.hasZeroRow);
  const Vec2 at = frame.pixelOf(50, 0);
  EXPECT_DOUBLE_EQ(at.y(), frame.zeroRowY());
  EXPECT_GT(at.y(), frame.bottom + 1);
  EXPECT_GT(at.y(), frame.pixelOf(50, std::pow(10.0, frame.yDecadeLo)).y());
  const Image chart = paretoChart(points, options());
  EXPECT_TRUE(sameColour(colourAt(chart, at), groupColour(1)));
  // Without zero errors there is no baseline.
  EXPECT_FALSE(chartFrame({{"FAST", 1, 0.1, 0}}, options()).hasZeroRow);
}

TEST(ParetoChartTest, FrontJoinedByALine) {
  // Unlabelled, so that only the line can lie between the dots.
  const std::vector<ChartPoint> points = {{"", 1, 10}, {"", 100, 0.1}, {"", 1000, 300}};
  const Image chart = paretoChart(points, options());
  const ChartFrame frame = chartFrame(points, options());
  // Dots sit on the centre of the pixel that holds their position.
  auto centre = [&](double x, double y) {
    const Vec2 at = frame.pixelOf(x, y);
    return Vec2(std::floor(at.x()) + 0.5, std::floor(at.y()) + 0.5);
  };
  EXPECT_TRUE(sameColour(colourAt(chart, 0.5 * (centre(1, 10) + centre(100, 0.1))), groupColour(0)));
  // The dominated point is not joined (and the midpoint is on no grid line).
  const Vec2 off = 0.5 * (centre(100, 0.1) + centre(1000, 300));
  EXPECT_TRUE(sameColour(colourAt(chart, off), kPanelColour));
}

TEST(ParetoChartTest, FrontsNeverJoinTwoGroups) {
  // Group 1's point at (30, 0.3) would be on a front over all points; per group, nothing joins it to (1, 10).
  std::vector<ChartPoint> points = {{"", 1, 10}, {"", 30, 0.3}, {"", 1000, 0.05}};
  points[1].group = 1;
  const Image chart = paretoChart(points, options());
  const ChartFrame frame = chartFrame(points, options());
  auto centre = [&](double x, double y) {
    const Vec2 at = frame.pixelOf(x, y);
    return Vec2(std::floor(at.x()) + 0.5, std::floor(at.y()) + 0.5);
  };
  EXPECT_TRUE(sameColour(colourAt(chart, 0.5 * (centre(1, 10) + centre(30, 0.3))), kPanelColour));
  EXPECT_TRUE(sameColour(colourAt(chart, 0.5 * (centre(1, 10) + centre(1000, 0.05))), groupColour(0)));
}

TEST(ParetoChartTest, NonFinitePointsLeaveRoomForANote) {
  const std::vector<ChartPoint> finite = {{"A", 1, 1}, {"B", 10, 0.1}};
  std::vector<ChartPoint> withNaN = finite;
  withNaN.push_back({"C", kNaN, 1});
  EXPECT_LT(chartFrame(withNaN, options()).bottom, chartFrame(finite, options()).bottom);
  // The note is left-aligned text on the bottom line, where the centred x label would be otherwise.
  auto textPixelsBottomLeft = [](const Image& chart) {
    const int line = measureText("", 14).height;  // the chart's text size
    int count = 0;
    for (int row = chart.height - 8 - line; row < chart.height; ++row)  // the last line, 8 pixels from the edge
      for (int x = 0; x < 100; ++x) count += (pixelColour(chart, x, row) - kPanelColour).norm() > 1e-6;
    return count;
  };
  EXPECT_GT(textPixelsBottomLeft(paretoChart(withNaN, options())), 20);
  EXPECT_EQ(textPixelsBottomLeft(paretoChart(finite, options())), 0);
}

TEST(ParetoChartTest, RejectsBadInput) {
  const std::vector<ChartPoint> points = {{"A", 1, 1}};
  EXPECT_THROW(paretoChart({}, options()), UsageError);
  EXPECT_THROW(paretoChart({{"A", kNaN, 1}, {"B", 1, kInf}}, options()), UsageError);
  EXPECT_THROW(paretoChart({{"A", 0, 1}}, options()), UsageError);
  EXPECT_THROW(paretoChart({{"A", 1, -0.5}}, options()), UsageError);
  ParetoChartOptions narrow = options();
  narrow.width = 199;
  EXPECT_THROW(paretoChart(points, narrow), UsageError);
  ParetoChartOptions low = options();
  low.height = 199;
  EXPECT_THROW(chartFrame(points, low), UsageError);
  // Enough pixels, but a legend that leaves no room for the plot.
  ParetoChartOptions crowded = options();
  crowded.width = crowded.height = 200;
  crowded.groupNames.assign(12, "A LONG GROUP NAME");
  EXPECT_THROW(paretoChart(points, crowded), UsageError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::views
