#include "views/pareto_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/markup.h"
#include "views/palette.h"

namespace uvtk::views {

namespace {

constexpr int kMinSize = 200;
constexpr double kPadding = 12;
constexpr double kTitleSize = 16, kTextSize = 13, kTickSize = 12, kPointLabelSize = 11;  // font sizes
constexpr double kLineGap = 6;                                                           // between lines of text
constexpr double kInset = 12;                            // between the box and the outer decades, as the PNG
constexpr double kZeroRowGap = 16, kZeroLabelSpace = 8;  // the zero row below the box, and room below it
constexpr double kTickLength = 5, kMinorTickLength = 3, kTickGap = 3;
constexpr double kMinLabelSpacing = 8;            // between neighbouring tick labels
constexpr double kMinGridSpacing = 8;             // the least decade, in units, with a grid line each
constexpr double kMinMinorTickDecade = 40;        // the least decade with minor ticks
constexpr double kSwatchGap = 6, kEntryGap = 20;  // legend: swatch to name, entry to entry
constexpr double kMinPlotSize = 2 * kInset + 40;
constexpr double kDotRadius = 3.5, kFrontDotRadius = 4.5, kRingWidth = 1.5;
constexpr double kLabelOffset = 9, kLabelRise = 3;  // from a front dot's centre to its label
// DejaVu Sans averages about 0.55 em per character of these labels; a little more keeps the
// estimated boxes (layout, label overlap) on the safe side in whatever sans-serif the reader has.
constexpr double kEmPerCharacter = 0.6;
constexpr double kAscent = 0.76;  // of an em: from a text's top to its baseline

const Vec3 kGridColour{0.24, 0.24, 0.24};
const Vec3 kAxisColour{0.60, 0.60, 0.60};

bool finite(const ChartPoint& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

double textWidth(const std::string& text, double size) { return double(text.size()) * kEmPerCharacter * size; }

// Coordinates with at most two decimals and no trailing zeros: short, and the same bytes every run.
std::string num(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  std::string s = text;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string value(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

std::string hex(const Vec3& colour) {
  char text[8];
  const auto byte = [](double c) { return int(std::lround(std::clamp(c, 0.0, 1.0) * 255.0)); };
  std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(colour.x()), byte(colour.y()), byte(colour.z()));
  return text;
}

// A decade's label: 0.001 to 1000 written out, beyond that 10 with the exponent raised.
struct DecadeLabel {
  std::string base, exponent;  // exponent empty when written out
  double width(double size) const { return textWidth(base, size) + textWidth(exponent, 0.75 * size); }
  std::string svg(double size) const {
    if (exponent.empty()) return xmlEscaped(base);
    return base + "<tspan dy=\"-" + num(0.4 * size) + "\" font-size=\"" + num(0.75 * size) + "\">" + exponent +
           "</tspan>";
  }
};

DecadeLabel decadeLabel(int exponent) {
  if (exponent >= 0 && exponent <= 3) return {"1" + std::string(std::size_t(exponent), '0'), ""};
  if (exponent < 0 && exponent >= -3) return {"0." + std::string(std::size_t(-exponent - 1), '0') + "1", ""};
  return {"10", (exponent < 0 ? "\u2212" : "") + std::to_string(std::abs(exponent))};
}

struct Rect {
  double left = 0, top = 0, width = 0, height = 0;
  bool overlaps(const Rect& o) const {
    return left < o.left + o.width && o.left < left + width && top < o.top + o.height && o.top < top + height;
  }
};

struct Layout {
  double left = 0, top = 0, right = 0, bottom = 0;  // the box
  int xLo = 0, xHi = 1, yLo = 0, yHi = 1;           // log10 at the insets
  bool zeroRow = false;
  std::optional<double> titleTop, yLabelTop, xLabelTop, noteTop;
  std::vector<std::pair<double, double>> legendAt;  // (x, top) of each group's swatch
  double tickLabelTop = 0;
  std::size_t skipped = 0;

  double column(double lx) const { return left + kInset + (lx - xLo) / (xHi - xLo) * (right - left - 2 * kInset); }
  double row(double ly) const { return bottom - kInset - (ly - yLo) / (yHi - yLo) * (bottom - top - 2 * kInset); }
  double zeroRowY() const { return bottom + kZeroRowGap; }
  double xOf(const ChartPoint& p) const { return column(std::log10(p.x)); }
  double yOf(const ChartPoint& p) const { return p.y == 0.0 ? zeroRowY() : row(std::log10(p.y)); }
};

Layout layoutChart(const std::vector<ChartPoint>& points, const ParetoChartOptions& options) {
  const double width = options.width, height = options.height;
  if (options.width < kMinSize || options.height < kMinSize)
    throw UsageError("pareto chart: expected at least " + std::to_string(kMinSize) + " x " + std::to_string(kMinSize) +
                     " units, got " + std::to_string(options.width) + " x " + std::to_string(options.height));
  Layout l;
  const ChartDecades decades = chartDecades(points);
  l.skipped = decades.skipped;
  l.zeroRow = decades.zeroRow;
  l.xLo = decades.xLo, l.xHi = decades.xHi, l.yLo = decades.yLo, l.yHi = decades.yHi;

  // From the top: title, legend (entries flowing into lines), y label, then the box.
  double row = kPadding;
  if (!options.title.empty()) l.titleTop = row, row += kTitleSize + kLineGap;
  double x = kPadding;
  for (const std::string& name : options.groupNames) {
    const double entry = kTextSize + kSwatchGap + textWidth(name, kTextSize);
    if (x > kPadding && x + entry > width - kPadding) x = kPadding, row += kTextSize + kLineGap;
    l.legendAt.emplace_back(x, row);
    x += entry + kEntryGap;
  }
  if (!options.groupNames.empty()) row += kTextSize + kLineGap;
  if (!options.yLabel.empty()) l.yLabelTop = row, row += kTextSize + kLineGap;
  l.top = row + kTickGap;

  // From the bottom: note, x label, x tick labels, the zero row, then the box.
  row = height - kPadding;
  if (l.skipped > 0) row -= kTextSize, l.noteTop = row, row -= kLineGap;
  if (!options.xLabel.empty()) row -= kTextSize, l.xLabelTop = row, row -= kLineGap;
  l.tickLabelTop = row - kTickSize;
  l.bottom = l.tickLabelTop - kTickGap - kTickLength;
  if (l.zeroRow) l.bottom -= kZeroRowGap + kZeroLabelSpace;

  double labelWidth = l.zeroRow ? textWidth("0", kTickSize) : 0;
  for (int e = l.yLo; e <= l.yHi; ++e) labelWidth = std::max(labelWidth, decadeLabel(e).width(kTickSize));
  l.left = kPadding + labelWidth + kTickGap + kTickLength;
  l.right = width - kPadding;
  if (l.right - l.left < kMinPlotSize || l.bottom - l.top < kMinPlotSize)
    throw UsageError("pareto chart: " + std::to_string(options.width) + " x " + std::to_string(options.height) +
                     " units leave too little room for the plot beside its title, legend and labels");
  return l;
}

std::string text(double x, double top, double size, const std::string& content, const char* anchor = nullptr) {
  return "<text x=\"" + num(x) + "\" y=\"" + num(top + kAscent * size) + "\" font-size=\"" + num(size) + "\"" +
         (anchor ? std::string(" text-anchor=\"") + anchor + "\"" : "") + ">" + content + "</text>\n";
}

std::string line(double x1, double y1, double x2, double y2, const Vec3& colour, const char* extra = "") {
  return "<line x1=\"" + num(x1) + "\" y1=\"" + num(y1) + "\" x2=\"" + num(x2) + "\" y2=\"" + num(y2) + "\" stroke=\"" +
         hex(colour) + "\"" + extra + "/>\n";
}

std::string axes(const Layout& l) {
  std::string svg;
  const double xSpacing = (l.right - l.left - 2 * kInset) / (l.xHi - l.xLo);
  const double ySpacing = (l.bottom - l.top - 2 * kInset) / (l.yHi - l.yLo);
  double widest = 0;
  for (int e = l.xLo; e <= l.xHi; ++e) widest = std::max(widest, decadeLabel(e).width(kTickSize));
  const int xStep = std::max(1, int(std::ceil((widest + kMinLabelSpacing) / xSpacing)));
  const int yStep = std::max(1, int(std::ceil((kTickSize + kMinLabelSpacing) / ySpacing)));
  const double labelRight = l.left - kTickLength - kTickGap;

  // Minor ticks at 2..9 times each decade, where a decade is wide enough to show them apart.
  for (int e = l.xLo; e < l.xHi && xSpacing >= kMinMinorTickDecade; ++e)
    for (int m = 2; m <= 9; ++m) {
      const double c = l.column(e + std::log10(m));
      svg += line(c, l.bottom, c, l.bottom + kMinorTickLength, kAxisColour);
    }
  for (int e = l.yLo; e < l.yHi && ySpacing >= kMinMinorTickDecade; ++e)
    for (int m = 2; m <= 9; ++m) {
      const double r = l.row(e + std::log10(m));
      svg += line(l.left - kMinorTickLength, r, l.left, r, kAxisColour);
    }
  // Grid lines and ticks at every decade, or only at the labelled ones where decades crowd.
  for (int e = l.xLo; e <= l.xHi; ++e) {
    const bool labelled = (e - l.xLo) % xStep == 0;
    if (!labelled && xSpacing < kMinGridSpacing) continue;
    const double c = l.column(e);
    svg += line(c, l.top, c, l.bottom, kGridColour);
    svg += line(c, l.bottom, c, l.bottom + kTickLength, kAxisColour);
    if (!labelled) continue;
    const DecadeLabel label = decadeLabel(e);
    const double half = label.width(kTickSize) / 2;
    const double centre = std::clamp(c, kPadding + half, l.right - half);
    svg += text(centre, l.tickLabelTop, kTickSize, label.svg(kTickSize), "middle");
  }
  for (int e = l.yLo; e <= l.yHi; ++e) {
    const bool labelled = (e - l.yLo) % yStep == 0;
    if (!labelled && ySpacing < kMinGridSpacing) continue;
    const double r = l.row(e);
    svg += line(l.left, r, l.right, r, kGridColour);
    svg += line(l.left - kTickLength, r, l.left, r, kAxisColour);
    if (labelled) svg += text(labelRight, r - kTickSize / 2, kTickSize, decadeLabel(e).svg(kTickSize), "end");
  }
  svg += "<rect x=\"" + num(l.left) + "\" y=\"" + num(l.top) + "\" width=\"" + num(l.right - l.left) + "\" height=\"" +
         num(l.bottom - l.top) + "\" fill=\"none\" stroke=\"" + hex(kAxisColour) + "\"/>\n";
  // Zero errors on a dotted row below the box: apart from the log axis they are not on.
  if (l.zeroRow) {
    const double r = l.zeroRowY();
    svg += "<line class=\"zero-row\" x1=\"" + num(l.left) + "\" y1=\"" + num(r) + "\" x2=\"" + num(l.right) +
           "\" y2=\"" + num(r) + "\" stroke=\"" + hex(kAxisColour) + "\" stroke-dasharray=\"1 3\"/>\n";
    svg += line(l.left - kTickLength, r, l.left, r, kAxisColour);
    svg += text(labelRight, r - kTickSize / 2, kTickSize, "0", "end");
  }
  return svg;
}

// The front's labels beside their dots, alternately above right (where only dominated points lie)
// and below left (where nothing lies but the labels), each trying the other places, then a line
// further out, until its estimated box overlaps no dot and no earlier label: as the PNG places them.
std::string frontLabels(const Layout& l, const ParetoChartOptions& options, const std::vector<ChartPoint>& points,
                        const std::vector<std::size_t>& front, const std::vector<bool>& onFront) {
  std::vector<Rect> taken;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!finite(points[i])) continue;
    const double r = onFront[i] ? kFrontDotRadius + kRingWidth : kDotRadius;
    taken.push_back({l.xOf(points[i]) - r, l.yOf(points[i]) - r, 2 * r, 2 * r});
  }
  std::string svg;
  for (std::size_t k = 0; k < front.size(); ++k) {
    const ChartPoint& p = points[front[k]];
    const double x = l.xOf(p), y = l.yOf(p), width = textWidth(p.label, kPointLabelSize);
    std::optional<Rect> chosen;
    for (const LabelPlace& place : labelPlaces(k)) {
      const double left = x + (place.right ? kLabelOffset : -kLabelOffset - width);
      const double out = place.linesOut * (kPointLabelSize + kLineGap);
      const double top = y + (place.above ? -kLabelRise - kPointLabelSize - out : kLabelRise + out);
      // Kept in the picture, between the box's top and the x tick labels.
      const Rect rect{std::clamp(left, l.left + 2, std::max(l.left + 2, options.width - kPadding - width)),
                      std::clamp(top, l.top + 2, l.tickLabelTop - 2 - kPointLabelSize), width, kPointLabelSize};
      if (!chosen) chosen = rect;  // the preferred place, should every place overlap
      if (std::none_of(taken.begin(), taken.end(), [&](const Rect& other) { return rect.overlaps(other); })) {
        chosen = rect;
        break;
      }
    }
    svg += text(chosen->left, chosen->top, kPointLabelSize, xmlEscaped(p.label));
    taken.push_back(*chosen);
  }
  return svg;
}

}  // namespace


std::string paretoChartSvg(const std::vector<ChartPoint>& points, const ParetoChartOptions& options) {
  const Layout l = layoutChart(points, options);
  const std::string width = std::to_string(options.width), height = std::to_string(options.height);
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + width + "\" height=\"" + height +
                    "\" viewBox=\"0 0 " + width + " " + height + "\" role=\"img\" aria-label=\"" +
                    xmlEscaped(options.title) + "\" font-family=\"DejaVu Sans, sans-serif\" fill=\"" +
                    hex(kTextColour) + "\">\n";
  svg += "<rect width=\"" + width + "\" height=\"" + height + "\" fill=\"" + hex(kPanelColour) + "\"/>\n";
  svg += axes(l);

  const std::vector<std::vector<std::size_t>> fronts = paretoFrontsByGroup(points);
  std::vector<bool> onFront(points.size(), false);
  std::vector<std::size_t> front;  // every group's
  for (const std::vector<std::size_t>& groupFront : fronts) {
    std::string coordinates;
    for (std::size_t i : groupFront) {
      coordinates += (coordinates.empty() ? "" : " ") + num(l.xOf(points[i])) + "," + num(l.yOf(points[i]));
      onFront[i] = true;
    }
    svg += "<polyline class=\"front\" points=\"" + coordinates + "\" fill=\"none\" stroke=\"" +
           hex(groupColour(points[groupFront.front()].group)) + "\" stroke-width=\"2\"/>\n";
    front.insert(front.end(), groupFront.begin(), groupFront.end());
  }
  svg += frontLabels(l, options, points, front, onFront);

  // Dots last, so that lines and labels never hide them; the front's ringed, on top.
  const auto dot = [&](std::size_t i) {
    const ChartPoint& p = points[i];
    const std::string ring =
        onFront[i] ? "\" stroke=\"" + hex(kTextColour) + "\" stroke-width=\"" + num(kRingWidth) : "";
    return "<circle cx=\"" + num(l.xOf(p)) + "\" cy=\"" + num(l.yOf(p)) + "\" r=\"" +
           num(onFront[i] ? kFrontDotRadius : kDotRadius) + "\" fill=\"" + hex(groupColour(p.group)) + ring +
           "\"><title>" +
           xmlEscaped(p.label + "\n" + (options.xLabel.empty() ? "x" : options.xLabel) + ": " + value(p.x) + "\n" +
                      (options.yLabel.empty() ? "y" : options.yLabel) + ": " + value(p.y)) +
           "</title></circle>\n";
  };
  for (std::size_t i = 0; i < points.size(); ++i)
    if (finite(points[i]) && !onFront[i]) svg += dot(i);
  for (std::size_t i : front) svg += dot(i);

  if (l.titleTop)
    svg += "<text x=\"" + num(kPadding) + "\" y=\"" + num(*l.titleTop + kAscent * kTitleSize) + "\" font-size=\"" +
           num(kTitleSize) + "\" font-weight=\"bold\">" + xmlEscaped(options.title) + "</text>\n";
  for (std::size_t g = 0; g < l.legendAt.size(); ++g) {
    const auto [x, top] = l.legendAt[g];
    svg += "<rect x=\"" + num(x) + "\" y=\"" + num(top) + "\" width=\"" + num(kTextSize) + "\" height=\"" +
           num(kTextSize) + "\" fill=\"" + hex(groupColour(int(g))) + "\"/>\n";
    svg += text(x + kTextSize + kSwatchGap, top, kTextSize, xmlEscaped(options.groupNames[g]));
  }
  if (l.yLabelTop) svg += text(kPadding, *l.yLabelTop, kTextSize, xmlEscaped(options.yLabel));
  if (l.xLabelTop) svg += text((l.left + l.right) / 2, *l.xLabelTop, kTextSize, xmlEscaped(options.xLabel), "middle");
  if (l.noteTop)
    svg += text(kPadding, *l.noteTop, kTextSize,
                std::to_string(l.skipped) + (l.skipped == 1 ? " point" : " points") + " skipped: not finite");
  return svg + "</svg>";
}

}  // namespace uvtk::views
