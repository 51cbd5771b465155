#include "views/pareto.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "views/canvas.h"
#include "views/legend.h"
#include "views/palette.h"
#include "views/type.h"

namespace uvtk::views {

namespace {

constexpr int kMinSize = 200;
constexpr int kPadding = 8;          // around the chart
constexpr int kLineGap = 6;          // between lines of text
constexpr double kTextSize = 14;        // title (bold), legend, axes
constexpr double kPointLabelSize = 11;  // front labels: smaller, since there may be many
constexpr int kTickLength = 4, kMinorTickLength = 2, kTickGap = 2;
constexpr int kMinLabelSpacing = 6;                 // between neighbouring tick labels
constexpr int kMinGridSpacing = 8;                  // the least decade, in pixels, with a grid line each
constexpr int kMinMinorTickDecade = 40;             // the least decade, in pixels, with minor ticks
constexpr int kSwatchGap = 8, kEntryGap = 20;       // legend: swatch to name, entry to entry
constexpr int kMinPlotSize = 2 * kChartInset + 40;  // the box must hold at least this much
constexpr int kZeroLabelSpace = 8;                  // between the zero row and the tick labels below it
constexpr double kDotRadius = 3.5, kFrontDotRadius = 4.5, kRingRadius = 6.0;
constexpr int kLabelOffset = 8, kLabelRise = 2;  // from a front dot's centre to its label: across, and up or down

const Vec3 kGridColour{0.24, 0.24, 0.24};
const Vec3 kAxisColour{0.60, 0.60, 0.60};

// Every line of chart text is the face's line box at kTextSize.
int lineHeight() { return measureText("", kTextSize).height; }
int textWidth(const std::string& text) { return measureText(text, kTextSize).width; }
void drawLine(Image& image, int x, int top, const std::string& text, Weight weight = Weight::Regular) {
  drawText(image, x, top, text, kTextSize, kTextColour, weight);
}

bool finite(const ChartPoint& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// 0.001 to 1000 written out, beyond that 10 with the exponent in superscript digits (as the SVG
// chart writes them): short, and exact for every decade.
std::string decadeLabel(int exponent) {
  if (exponent >= 0 && exponent <= 3) return "1" + std::string(std::size_t(exponent), '0');
  if (exponent < 0 && exponent >= -3) return "0." + std::string(std::size_t(-exponent - 1), '0') + "1";
  static const char* const kSuperscript[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string label = exponent < 0 ? "10⁻" : "10";
  for (char digit : std::to_string(std::abs(exponent))) label += kSuperscript[digit - '0'];
  return label;
}

// Every `step`-th decade from lo gets a label, the smallest step whose labels keep `needed` pixels
// apart at `spacing` pixels per decade.
int labelStep(double spacing, int needed) { return std::max(1, int(std::ceil(needed / spacing))); }

// The column of a value whose log10 is lx and the row of one whose log10 is ly: from logs, not
// from 10^e, so that decades beyond double's range (10^-324, 10^309) place too.
double columnAt(const ChartFrame& f, double lx) {
  return f.left + kChartInset + (lx - f.xDecadeLo) / (f.xDecadeHi - f.xDecadeLo) * (f.right - f.left - 2 * kChartInset);
}
double rowAt(const ChartFrame& f, double ly) {
  return f.bottom - kChartInset -
         (ly - f.yDecadeLo) / (f.yDecadeHi - f.yDecadeLo) * (f.bottom - f.top - 2 * kChartInset);
}

// A dot's centre on the pixel that holds its position, so that dots are symmetric.
Vec2 dotCentre(const ChartFrame& frame, const ChartPoint& p) {
  const Vec2 at = frame.pixelOf(p.x, p.y);
  return {std::floor(at.x()) + 0.5, std::floor(at.y()) + 0.5};
}

struct Rect {
  int left = 0, top = 0, width = 0, height = 0;
  bool overlaps(const Rect& o) const {
    return left < o.left + o.width && o.left < left + width && top < o.top + o.height && o.top < top + height;
  }
};

// Everything paretoChart places, decided in one place: chartFrame returns its frame.
struct Layout {
  ChartFrame frame;
  std::optional<int> titleTop, yLabelTop, xLabelTop, noteTop;
  std::vector<std::pair<int, int>> legendAt;  // (x, row) of each group's swatch
  int tickLabelTop = 0;                       // the x tick labels' row
  std::size_t skipped = 0;                    // points with a non-finite x or y
};

Layout layoutChart(const std::vector<ChartPoint>& points, const ParetoChartOptions& options) {
  const int width = options.width, height = options.height;
  if (width < kMinSize || height < kMinSize)
    throw UsageError("pareto chart: expected at least " + std::to_string(kMinSize) + " x " + std::to_string(kMinSize) +
                     " pixels, got " + std::to_string(width) + " x " + std::to_string(height));
  Layout layout;
  ChartFrame& frame = layout.frame;
  const ChartDecades decades = chartDecades(points);
  layout.skipped = decades.skipped;
  frame.hasZeroRow = decades.zeroRow;
  frame.xDecadeLo = decades.xLo, frame.xDecadeHi = decades.xHi;
  frame.yDecadeLo = decades.yLo, frame.yDecadeHi = decades.yHi;

  // From the top: title, legend (entries flowing into lines), y label, then the box.
  const int line = lineHeight();
  int row = kPadding;
  if (!options.title.empty()) layout.titleTop = row, row += line + kLineGap;
  int x = kPadding;
  for (const std::string& name : options.groupNames) {
    const int entryWidth = line + kSwatchGap + textWidth(name);
    if (x > kPadding && x + entryWidth > width - kPadding) x = kPadding, row += line + kLineGap;
    layout.legendAt.emplace_back(x, row);
    x += entryWidth + kEntryGap;
  }
  if (!options.groupNames.empty()) row += line + kLineGap;
  if (!options.yLabel.empty()) layout.yLabelTop = row, row += line + kLineGap;
  frame.top = row;

  // From the bottom: note, x label, x tick labels, the zero row, then the box.
  row = height - kPadding;
  if (layout.skipped > 0) row -= line, layout.noteTop = row, row -= kLineGap;
  if (!options.xLabel.empty()) row -= line, layout.xLabelTop = row, row -= kLineGap;
  layout.tickLabelTop = row - line;
  frame.bottom = layout.tickLabelTop - kTickGap - kTickLength - 1;
  if (frame.hasZeroRow) frame.bottom -= kZeroRowGap + kZeroLabelSpace;

  int labelWidth = frame.hasZeroRow ? textWidth("0") : 0;
  for (int e = frame.yDecadeLo; e <= frame.yDecadeHi; ++e) labelWidth = std::max(labelWidth, textWidth(decadeLabel(e)));
  frame.left = kPadding + labelWidth + kTickGap + kTickLength;
  frame.right = width - kPadding - 1;
  if (frame.right - frame.left < kMinPlotSize || frame.bottom - frame.top < kMinPlotSize)
    throw UsageError("pareto chart: " + std::to_string(width) + " x " + std::to_string(height) +
                     " pixels leave too little room for the plot beside its title, legend and labels");
  return layout;
}

// The front's labels beside their dots, alternately above right (where only dominated points lie)
// and below left (where nothing lies but the labels), each trying the other places, then a line
// further out, until it overlaps no dot and no earlier label.
void drawFrontLabels(Image& image, const Layout& layout, const std::vector<ChartPoint>& points,
                     const std::vector<std::size_t>& front, const std::vector<bool>& onFront) {
  const ChartFrame& frame = layout.frame;
  const int height = measureText("", kPointLabelSize).height;
  std::vector<Rect> taken;  // the dots, then the labels drawn
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!finite(points[i])) continue;
    const Vec2 centre = dotCentre(frame, points[i]);
    const int r = int(std::ceil(onFront[i] ? kRingRadius : kDotRadius));
    taken.push_back({int(centre.x()) - r, int(centre.y()) - r, 2 * r + 1, 2 * r + 1});
  }
  for (std::size_t k = 0; k < front.size(); ++k) {
    const ChartPoint& p = points[front[k]];
    const Vec2 centre = dotCentre(frame, p);
    const int width = measureText(p.label, kPointLabelSize).width;
    std::optional<Rect> chosen;
    for (const LabelPlace& place : labelPlaces(k)) {
      const int left = int(centre.x()) + (place.right ? kLabelOffset : -kLabelOffset - width);
      const int out = place.linesOut * (height + kLineGap);
      const int top = int(centre.y()) + (place.above ? -kLabelRise - height - out : kLabelRise + out);
      // Kept in the image, between the box's top and the x tick labels.
      const Rect rect{std::clamp(left, frame.left + 2, image.width - kPadding - width),
                      std::clamp(top, frame.top + 2, layout.tickLabelTop - 2 - height), width, height};
      if (!chosen) chosen = rect;  // the preferred place, should every place overlap
      if (std::none_of(taken.begin(), taken.end(), [&](const Rect& other) { return rect.overlaps(other); })) {
        chosen = rect;
        break;
      }
    }
    drawText(image, chosen->left, chosen->top, p.label, kPointLabelSize, kTextColour);
    taken.push_back(*chosen);
  }
}

void drawAxes(Image& image, const Layout& layout) {
  const ChartFrame& f = layout.frame;
  const double xSpacing = (f.right - f.left - 2.0 * kChartInset) / (f.xDecadeHi - f.xDecadeLo);
  const double ySpacing = (f.bottom - f.top - 2.0 * kChartInset) / (f.yDecadeHi - f.yDecadeLo);
  int widest = 0;
  for (int e = f.xDecadeLo; e <= f.xDecadeHi; ++e) widest = std::max(widest, textWidth(decadeLabel(e)));
  const int xStep = labelStep(xSpacing, widest + kMinLabelSpacing);
  const int yStep = labelStep(ySpacing, lineHeight() + kMinLabelSpacing);
  const int labelRight = f.left - kTickLength - kTickGap;  // y tick labels end here

  // Minor ticks at 2..9 times each decade, where a decade is wide enough to show them apart.
  for (int e = f.xDecadeLo; e < f.xDecadeHi && xSpacing >= kMinMinorTickDecade; ++e)
    for (int m = 2; m <= 9; ++m) {
      const int column = int(columnAt(f, e + std::log10(m)));
      fillRect(image, column, f.bottom + 1, 1, kMinorTickLength, kAxisColour);
      fillRect(image, column, f.top - kMinorTickLength, 1, kMinorTickLength, kAxisColour);
    }
  for (int e = f.yDecadeLo; e < f.yDecadeHi && ySpacing >= kMinMinorTickDecade; ++e)
    for (int m = 2; m <= 9; ++m) {
      const int r = int(rowAt(f, e + std::log10(m)));
      fillRect(image, f.left - kMinorTickLength, r, kMinorTickLength, 1, kAxisColour);
      fillRect(image, f.right + 1, r, kMinorTickLength, 1, kAxisColour);
    }
  // Grid lines and ticks at every decade, or only at the labelled ones where decades crowd.
  for (int e = f.xDecadeLo; e <= f.xDecadeHi; ++e) {
    const bool labelled = (e - f.xDecadeLo) % xStep == 0;
    if (!labelled && xSpacing < kMinGridSpacing) continue;
    const int column = int(columnAt(f, e));
    fillRect(image, column, f.top + 1, 1, f.bottom - f.top - 1, kGridColour);
    fillRect(image, column, f.bottom + 1, 1, kTickLength, kAxisColour);
    if (!labelled) continue;
    const std::string label = decadeLabel(e);
    const int left = std::clamp(column - textWidth(label) / 2, kPadding, image.width - kPadding - textWidth(label));
    drawLine(image, left, layout.tickLabelTop, label);
  }
  for (int e = f.yDecadeLo; e <= f.yDecadeHi; ++e) {
    const bool labelled = (e - f.yDecadeLo) % yStep == 0;
    if (!labelled && ySpacing < kMinGridSpacing) continue;
    const int r = int(rowAt(f, e));
    fillRect(image, f.left + 1, r, f.right - f.left - 1, 1, kGridColour);
    fillRect(image, f.left - kTickLength, r, kTickLength, 1, kAxisColour);
    if (!labelled) continue;
    const std::string label = decadeLabel(e);
    drawLine(image, labelRight - textWidth(label), r - lineHeight() / 2, label);
  }
  // The box, and for zero errors a dotted baseline below it: apart from the log axis it is not on.
  fillRect(image, f.left, f.top, f.right - f.left + 1, 1, kAxisColour);
  fillRect(image, f.left, f.bottom, f.right - f.left + 1, 1, kAxisColour);
  fillRect(image, f.left, f.top, 1, f.bottom - f.top + 1, kAxisColour);
  fillRect(image, f.right, f.top, 1, f.bottom - f.top + 1, kAxisColour);
  if (f.hasZeroRow) {
    const int r = int(f.zeroRowY());
    for (int column = f.left; column <= f.right; column += 4) setPixel(image, column, r, kAxisColour);
    fillRect(image, f.left - kTickLength, r, kTickLength, 1, kAxisColour);
    drawLine(image, labelRight - textWidth("0"), r - lineHeight() / 2, "0");
  }
}

}  // namespace

Vec3 groupColour(int group) {
  // Okabe and Ito (2008), "Color Universal Design": orange, sky blue, bluish green, yellow, blue,
  // vermillion, reddish purple; all stand out on kPanelColour.
  static const Vec3 kColours[] = {{0.902, 0.624, 0.000}, {0.337, 0.706, 0.914}, {0.000, 0.620, 0.451},
                                  {0.941, 0.894, 0.259}, {0.000, 0.447, 0.698}, {0.835, 0.369, 0.000},
                                  {0.800, 0.475, 0.655}};
  constexpr int n = int(std::size(kColours));
  return kColours[((group % n) + n) % n];
}

std::vector<std::size_t> paretoFront(const std::vector<ChartPoint>& points) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (finite(points[i])) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const ChartPoint &p = points[a], &q = points[b];
    return p.x != q.x ? p.x < q.x : p.y != q.y ? p.y < q.y : a < b;
  });
  // Sweeping by x: a run of equal x survives only with its least y, and only if that is below the
  // least y of every smaller x (an equal y at a smaller x dominates too).
  std::vector<std::size_t> front;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < order.size();) {
    const double x = points[order[i]].x, least = points[order[i]].y;
    std::size_t j = i;
    for (; j < order.size() && points[order[j]].x == x; ++j)
      if (least < best && points[order[j]].y == least) front.push_back(order[j]);
    best = std::min(best, least);
    i = j;
  }
  return front;
}

std::vector<std::vector<std::size_t>> paretoFrontsByGroup(const std::vector<ChartPoint>& points) {
  std::vector<int> groups;
  for (const ChartPoint& p : points) groups.push_back(p.group);
  std::sort(groups.begin(), groups.end());
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  std::vector<std::vector<std::size_t>> fronts;
  for (int group : groups) {
    std::vector<ChartPoint> members;
    std::vector<std::size_t> index;  // of each member in `points`
    for (std::size_t i = 0; i < points.size(); ++i)
      if (points[i].group == group) members.push_back(points[i]), index.push_back(i);
    std::vector<std::size_t> front = paretoFront(members);
    for (std::size_t& i : front) i = index[i];
    if (!front.empty()) fronts.push_back(std::move(front));
  }
  return fronts;
}

Vec2 ChartFrame::pixelOf(double x, double y) const {
  UVTK_CHECK(std::isfinite(x) && std::isfinite(y) && x > 0.0 && y >= 0.0);
  return {columnAt(*this, std::log10(x)), y == 0.0 ? zeroRowY() : rowAt(*this, std::log10(y))};
}

double ChartFrame::zeroRowY() const { return bottom + kZeroRowGap + 0.5; }

const std::array<LabelPlace, 6>& labelPlaces(std::size_t k) {
  static constexpr std::array<LabelPlace, 6> kAboveRight{
      {{true, true, 0}, {false, false, 0}, {true, false, 0}, {false, true, 0}, {true, true, 1}, {false, false, 1}}};
  static constexpr std::array<LabelPlace, 6> kBelowLeft{
      {{false, false, 0}, {true, true, 0}, {false, true, 0}, {true, false, 0}, {false, false, 1}, {true, true, 1}}};
  return k % 2 == 0 ? kAboveRight : kBelowLeft;
}

ChartDecades chartDecades(const std::vector<ChartPoint>& points) {
  ChartDecades out;
  double xMin = std::numeric_limits<double>::infinity(), xMax = -xMin, yMin = xMin, yMax = -xMin;
  for (const ChartPoint& p : points) {
    if (!finite(p)) {
      ++out.skipped;
      continue;
    }
    if (p.x <= 0.0 || p.y < 0.0)
      throw UsageError("pareto chart: point \"" + p.label + "\" has cost " + formatNumber(p.x) + " and error " +
                       formatNumber(p.y) + "; expected cost > 0 and error >= 0 for log axes");
    xMin = std::min(xMin, p.x), xMax = std::max(xMax, p.x);
    if (p.y == 0.0)
      out.zeroRow = true;
    else
      yMin = std::min(yMin, p.y), yMax = std::max(yMax, p.y);
  }
  if (out.skipped == points.size())
    throw UsageError("pareto chart: no point with a finite cost and error among " + std::to_string(points.size()));
  out.xLo = int(std::floor(std::log10(xMin)));
  out.xHi = std::max(out.xLo + 1, int(std::ceil(std::log10(xMax))));
  if (yMin <= yMax) {  // else only zero errors: any decade serves
    out.yLo = int(std::floor(std::log10(yMin)));
    out.yHi = std::max(out.yLo + 1, int(std::ceil(std::log10(yMax))));
  }
  return out;
}

ChartFrame chartFrame(const std::vector<ChartPoint>& points, const ParetoChartOptions& options) {
  return layoutChart(points, options).frame;
}

Image paretoChart(const std::vector<ChartPoint>& points, const ParetoChartOptions& options) {
  const Layout layout = layoutChart(points, options);
  const ChartFrame& frame = layout.frame;
  Image image(options.width, options.height, 3);
  fillRect(image, 0, 0, image.width, image.height, kPanelColour);
  drawAxes(image, layout);

  std::vector<std::size_t> front;  // every group's front
  for (const std::vector<std::size_t>& groupFront : paretoFrontsByGroup(points)) {
    for (std::size_t k = 1; k < groupFront.size(); ++k)
      drawSegment(image, dotCentre(frame, points[groupFront[k - 1]]), dotCentre(frame, points[groupFront[k]]), 2,
                  groupColour(points[groupFront[k]].group));
    front.insert(front.end(), groupFront.begin(), groupFront.end());
  }
  std::vector<bool> onFront(points.size(), false);
  for (std::size_t i : front) onFront[i] = true;
  drawFrontLabels(image, layout, points, front, onFront);
  // Dots last, so that lines and labels never hide them; the front's dots ringed, on top.
  for (std::size_t i = 0; i < points.size(); ++i)
    if (finite(points[i]) && !onFront[i])
      drawDot(image, dotCentre(frame, points[i]), kDotRadius, groupColour(points[i].group));
  for (std::size_t i : front) {
    drawDot(image, dotCentre(frame, points[i]), kRingRadius, kTextColour);
    drawDot(image, dotCentre(frame, points[i]), kFrontDotRadius, groupColour(points[i].group));
  }

  if (layout.titleTop) drawLine(image, kPadding, *layout.titleTop, options.title, Weight::Bold);
  for (std::size_t g = 0; g < layout.legendAt.size(); ++g) {
    const auto [x, row] = layout.legendAt[g];
    fillRect(image, x, row, lineHeight(), lineHeight(), groupColour(int(g)));
    drawLine(image, x + lineHeight() + kSwatchGap, row, options.groupNames[g]);
  }
  if (layout.yLabelTop) drawLine(image, kPadding, *layout.yLabelTop, options.yLabel);
  if (layout.xLabelTop) {
    const int centre = (frame.left + frame.right) / 2;
    drawLine(image, std::max(kPadding, centre - textWidth(options.xLabel) / 2), *layout.xLabelTop, options.xLabel);
  }
  if (layout.noteTop) {
    const std::string note =
        std::to_string(layout.skipped) + (layout.skipped == 1 ? " point" : " points") + " skipped: not finite";
    drawLine(image, kPadding, *layout.noteTop, note);
  }
  return image;
}

}  // namespace uvtk::views
