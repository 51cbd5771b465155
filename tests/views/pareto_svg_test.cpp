// The Pareto chart as SVG, read back with regular expressions: a circle with a hover title per
// point, a front per group, positions on the log scale, text escaped, zero errors on their row.
#include "views/pareto_svg.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <regex>
#include <string>
#include <vector>

#include "core/error.h"

namespace uvtk::views {
namespace {
namespace UVTK_TEST_FILE {

struct Circle {
  double cx, cy;
  std::string title;
};

std::vector<Circle> circlesOf(const std::string& svg) {
  static const std::regex circle(R"re(<circle cx="([-0-9.]+)" cy="([-0-9.]+)"[^>]*><title>([^<]*)</title></circle>)re");
  std::vector<Circle> out;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), circle); it != std::sregex_iterator(); ++it)
    out.push_back({std::stod((*it)[1]), std::stod((*it)[2]), (*it)[3]});
  return out;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The circle whose title starts with `label` (its first line).
const Circle& circleOf(const std::vector<Circle>& circles, const std::string& label) {
  for (const Circle& c : circles)
    if (c.title.rfind(label + "\n", 0) == 0) return c;
  throw std::runtime_error("no circle titled " + label);
}

ParetoChartOptions options() {
  ParetoChartOptions o;
  o.title = "Mapping: time per vertex against max error";
  o.xLabel = "ns per vertex";
  o.yLabel = "max error, texels at 4096";
  o.groupNames = {"plane", "sphere"};
  return o;
}

TEST(ParetoSvg, EveryPointIsACircleTitledWithItsLabelAndBothValuesWithUnits) {
  const std::vector<ChartPoint> points = {{"plane double exact T1", 1.5, 1e-9, 0},
                                          {"plane float exact T1", 0.8, 2e-4, 0},
                                          {"sphere double exact T1", 12.0, 3e-10, 1},
                                          {"sphere float fast T1", 2.5, 0.004, 1},
                                          {"sphere float exact T1", 6.0, 0.004, 1}};  // dominated
  const std::string svg = paretoChartSvg(points, options());
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"960\" height=\"640\"", 0), 0u);
  EXPECT_EQ(svg.substr(svg.size() - 6), "</svg>");
  EXPECT_EQ(svg.find("<?xml"), std::string::npos);
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  EXPECT_EQ(svg.find("href"), std::string::npos);  // nothing external
  EXPECT_NE(svg.find("font-family=\"DejaVu Sans, sans-serif\""), std::string::npos);
  const std::vector<Circle> circles = circlesOf(svg);
  ASSERT_EQ(circles.size(), points.size());
  EXPECT_EQ(circleOf(circles, "sphere float fast T1").title,
            "sphere float fast T1\nns per vertex: 2.5\nmax error, texels at 4096: 0.004");
  for (const ChartPoint& p : points) EXPECT_NO_THROW(circleOf(circles, p.label)) << p.label;
  // Mixed case as given, title, axes and legend.
  for (const char* text : {">Mapping: time per vertex against max error<", ">ns per vertex<",
                           ">max error, texels at 4096<", ">plane<", ">sphere<"})
    EXPECT_NE(svg.find(text), std::string::npos) << text;
  EXPECT_EQ(svg, paretoChartSvg(points, options())) << "the same input gives the same bytes";
}

TEST(ParetoSvg, OneFrontPolylinePerGroupThroughItsFrontPointsInItsColour) {
  const std::vector<ChartPoint> points = {{"a1", 1, 1, 0},  {"a2", 2, 0.5, 0},  {"a3", 3, 2, 0},  // a3 dominated
                                          {"b1", 10, 1, 1}, {"b2", 20, 0.1, 1}, {"c1", 5, 5, 2}};
  const std::string svg = paretoChartSvg(points, options());
  static const std::regex polyline(
      R"re(<polyline class="front" points="([^"]*)" fill="none" stroke="(#[0-9a-f]{6})")re");
  std::vector<std::pair<std::string, std::string>> fronts;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), polyline); it != std::sregex_iterator(); ++it)
    fronts.emplace_back((*it)[1], (*it)[2]);
  ASSERT_EQ(fronts.size(), 3u);
  // Okabe-Ito orange, sky blue, bluish green (groupColour 0, 1, 2).
  EXPECT_EQ(fronts[0].second, "#e69f00");
  EXPECT_EQ(fronts[1].second, "#56b4e9");
  EXPECT_EQ(fronts[2].second, "#009e73");
  EXPECT_EQ(std::count(fronts[0].first.begin(), fronts[0].first.end(), ','), 2) << "a1 and a2, not a3";
  EXPECT_EQ(std::count(fronts[1].first.begin(), fronts[1].first.end(), ','), 2);
  EXPECT_EQ(std::count(fronts[2].first.begin(), fronts[2].first.end(), ','), 1);
  // The front's first vertex is a1's circle, and front circles are ringed, others not.
  const std::vector<Circle> circles = circlesOf(svg);
  const Circle& a1 = circleOf(circles, "a1");
  char expected[64];
  std::snprintf(expected, sizeof expected, "%g,%g", a1.cx, a1.cy);
  EXPECT_EQ(fronts[0].first.rfind(expected, 0), 0u) << fronts[0].first << " vs " << expected;
  EXPECT_EQ(count(svg, "stroke-width=\"1.5\"><title>"), 5u);  // every point but a3
}

TEST(ParetoSvg, XPositionsFollowTheLogScale) {
  const std::vector<ChartPoint> points = {
      {"x1", 1, 1, 0}, {"x2", 2, 1, 0}, {"x10", 10, 1, 0}, {"x100", 100, 1, 0}, {"x30", 30, 1, 0}};
  const std::vector<Circle> circles = circlesOf(paretoChartSvg(points, options()));
  const double c1 = circleOf(circles, "x1").cx, c2 = circleOf(circles, "x2").cx, c10 = circleOf(circles, "x10").cx,
               c30 = circleOf(circles, "x30").cx, c100 = circleOf(circles, "x100").cx;
  EXPECT_LT(c1, c2);
  EXPECT_LT(c2, c10);
  EXPECT_LT(c10, c30);
  EXPECT_LT(c30, c100);
  // A decade spans the same width; 2 lies log10(2) of the way along it (coordinates in 0.01 units).
  EXPECT_NEAR(c10 - c1, c100 - c10, 0.02);
  EXPECT_NEAR((c2 - c1) / (c10 - c1), std::log10(2.0), 1e-3);
  EXPECT_NEAR((c30 - c10) / (c100 - c10), std::log10(3.0), 1e-3);
}

TEST(ParetoSvg, DecadeLabelsInRealUnits) {
  const std::vector<ChartPoint> points = {{"a", 0.002, 1e-6, 0}, {"b", 900, 1e-4, 0}};
  const std::string svg = paretoChartSvg(points, options());
  for (const char* label : {">0.001<", ">0.01<", ">0.1<", ">1<", ">1000<"})
    EXPECT_NE(svg.find(label), std::string::npos) << label;
  // 1e-6 and 1e-4 on the y axis: 10 with a raised exponent, a real minus sign.
  EXPECT_NE(svg.find("10<tspan dy=\"-4.8\" font-size=\"9\">\u22126</tspan>"), std::string::npos);
  EXPECT_NE(svg.find("10<tspan dy=\"-4.8\" font-size=\"9\">\u22124</tspan>"), std::string::npos);
}

TEST(ParetoSvg, EscapesEveryText) {
  ParetoChartOptions o = options();
  o.title = "a <b> & \"c\"";
  o.groupNames = {"<g&>"};
  const std::string svg = paretoChartSvg({{"<&>'", 1, 1, 0}, {"p", 2, 0.5, 0}}, o);
  EXPECT_EQ(svg.find("<&>"), std::string::npos);
  EXPECT_EQ(svg.find("<b>"), std::string::npos);
  EXPECT_NE(svg.find("<title>&lt;&amp;&gt;&#39;\nns per vertex: 1"), std::string::npos);
  EXPECT_NE(svg.find("aria-label=\"a &lt;b&gt; &amp; &quot;c&quot;\""), std::string::npos);
  EXPECT_NE(svg.find(">&lt;g&amp;&gt;</text>"), std::string::npos);
  EXPECT_NE(svg.find(">&lt;&amp;&gt;&#39;</text>"), std::string::npos) << "a front point's label";
}

TEST(ParetoSvg, ZeroErrorsLieOnTheZeroRowBelowTheBox) {
  const std::vector<ChartPoint> points = {{"exact", 3, 0, 0}, {"fast", 1, 0.01, 0}, {"slow", 9, 0.1, 0}};
  const std::string svg = paretoChartSvg(points, options());
  static const std::regex zeroRow(R"re(<line class="zero-row" x1="[-0-9.]+" y1="([-0-9.]+)")re");
  static const std::regex box(
      R"re(<rect x="[-0-9.]+" y="([-0-9.]+)" width="[-0-9.]+" height="([-0-9.]+)" fill="none")re");
  std::smatch row, frame;
  ASSERT_TRUE(std::regex_search(svg, row, zeroRow));
  ASSERT_TRUE(std::regex_search(svg, frame, box));
  const double zeroY = std::stod(row[1]), boxBottom = std::stod(frame[1]) + std::stod(frame[2]);
  const std::vector<Circle> circles = circlesOf(svg);
  EXPECT_EQ(circleOf(circles, "exact").cy, zeroY);
  EXPECT_GT(zeroY, boxBottom);
  EXPECT_LT(circleOf(circles, "fast").cy, boxBottom);
  EXPECT_LT(circleOf(circles, "slow").cy, circleOf(circles, "fast").cy) << "larger errors higher";
  EXPECT_NE(svg.find(">0</text>"), std::string::npos);
  // No zero error, no zero row.
  EXPECT_EQ(paretoChartSvg({points[1], points[2]}, options()).find("zero-row"), std::string::npos);
}

TEST(ParetoSvg, SkipsNonFinitePointsWithANoteAndRefusesWhatLogAxesCannotShow) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const std::string svg = paretoChartSvg({{"ok", 1, 1, 0}, {"nan", nan, 1, 0}, {"inf", 2, inf, 0}}, options());
  EXPECT_EQ(circlesOf(svg).size(), 1u);
  EXPECT_NE(svg.find(">2 points skipped: not finite</text>"), std::string::npos);
  EXPECT_NE(paretoChartSvg({{"ok", 1, 1, 0}, {"nan", nan, 1, 0}}, options()).find(">1 point skipped"),
            std::string::npos);
  EXPECT_THROW(paretoChartSvg({{"nan", nan, 1, 0}}, options()), UsageError);
  EXPECT_THROW(paretoChartSvg({}, options()), UsageError);
  EXPECT_THROW(paretoChartSvg({{"zero cost", 0, 1, 0}}, options()), UsageError);
  EXPECT_THROW(paretoChartSvg({{"negative error", 1, -1, 0}}, options()), UsageError);
  ParetoChartOptions small = options();
  small.width = 199;
  EXPECT_THROW(paretoChartSvg({{"ok", 1, 1, 0}}, small), UsageError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::views
