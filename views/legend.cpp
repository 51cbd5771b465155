#include "views/legend.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

#include "core/error.h"
#include "views/canvas.h"
#include "views/type.h"

namespace uvtk::views {

namespace {

constexpr int kSwatchGap = 8;       // between a swatch and its label
constexpr int kTickLabelGap = 2;    // between a tick mark and its label
constexpr int kMinLabelSpacing = 6; // between neighbouring tick labels; a label that would come closer is left out

// Every line is the face's line box at kLegendTextSize, whatever its text.
int lineHeight() { return measureText("", kLegendTextSize).height; }
int textWidth(const std::string& text) { return measureText(text, kLegendTextSize).width; }
void drawLine(Image& image, int x, int top, const std::string& text) { drawText(image, x, top, text, kLegendTextSize, kTextColour); }

// A swatch: a square as high as the text's ascent, centred on its line.
int swatchSize() { return measureText("", kLegendTextSize).ascent; }

void drawBar(Image& image, const ColourBar& bar, const BarPlacement& at) {
  for (int i = 0; i < kBarLength; ++i)
    fillRect(image, at.left + i, at.top, 1, kBarHeight, paletteColour(bar.scale.palette, (i + 0.5) / kBarLength));
  const int markTop = at.top + kBarHeight, labelTop = markTop + kTickLength + kTickLabelGap;
  for (const Tick& tick : bar.ticks) fillRect(image, at.columnAt(bar.scale.position(tick.value)), markTop, 1, kTickLength, kTextColour);
  // The end labels first, since they say where the scale clamps; then the others where they fit.
  std::vector<std::size_t> order;
  if (!bar.ticks.empty()) order = {0, bar.ticks.size() - 1};
  for (std::size_t k = 1; k + 1 < bar.ticks.size(); ++k) order.push_back(k);
  std::vector<std::pair<int, int>> drawn;  // [left, right) of the labels drawn
  for (std::size_t k : order) {
    const Tick& tick = bar.ticks[k];
    const int width = textWidth(tick.label);
    const int column = at.columnAt(bar.scale.position(tick.value));
    const int left = std::clamp(column - width / 2, at.left, at.left + kBarLength - width);
    const bool fits = std::none_of(drawn.begin(), drawn.end(), [&](const std::pair<int, int>& other) {
      return left < other.second + kMinLabelSpacing && other.first < left + width + kMinLabelSpacing;
    });
    if (!fits) continue;
    drawLine(image, left, labelTop, tick.label);
    drawn.emplace_back(left, left + width);
  }
}

void drawSwatch(Image& image, int x, int lineTop, const LegendEntry& entry) {
  const int size = swatchSize(), row = lineTop + (lineHeight() - size) / 2;
  fillRect(image, x, row, size, size, entry.colour);
  for (int j = row; j < row + size; ++j)
    for (int i = x; i < x + size; ++i)
      if (std::optional<Vec3> hatch = overlapHatch(entry.hatchCount, i, j)) setPixel(image, i, j, *hatch);
}

// Walks the legend's blocks from `top` down, drawing them when `image` is given; returns the
// strip's width and height. The one place that decides the legend's geometry.
std::pair<int, int> paintLegend(const Legend& legend, int top, Image* image) {
  const int line = lineHeight();
  int right = 0;  // the rightmost column used
  auto text = [&](int x, int y, const std::string& label) {
    if (image) drawLine(*image, x, y, label);
    right = std::max(right, x + textWidth(label));
  };
  for (std::size_t k = 0; k < legend.title.size(); ++k)
    text(kLegendPadding, top + kLegendPadding + int(k) * (line + kLegendLineGap), legend.title[k]);
  const BarPlacement bar = barPlacement(legend, top);  // just below the title lines
  int y = bar.top;
  if (legend.bar) {
    if (image) drawBar(*image, *legend.bar, bar);
    right = std::max(right, bar.left + kBarLength);
    y += kBarHeight + kTickLength + kTickLabelGap + line + kLegendLineGap;
  }
  for (const LegendEntry& entry : legend.entries) {
    if (image) drawSwatch(*image, kLegendPadding, y, entry);
    text(kLegendPadding + swatchSize() + kSwatchGap, y, entry.label);
    y += line + kLegendLineGap;
  }
  return {right + kLegendPadding, y - kLegendLineGap + kLegendPadding - top};
}

}  // namespace

std::string formatNumber(double value, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, value + 0.0);  // + 0.0 turns -0 into 0
  return text;
}

double ColourScale::position(double value) const {
  UVTK_CHECK(std::isfinite(value) && lo < hi);
  if (logarithmic && value <= std::pow(10.0, lo)) return 0.0;  // also 0, whose log10 is -infinity
  const double x = logarithmic ? std::log10(value) : value;
  return std::clamp((x - lo) / (hi - lo), 0.0, 1.0);
}

std::vector<std::string> distinctLabels(const std::vector<double>& values) {
  std::vector<std::string> labels;
  for (int digits = 3; digits <= 10; ++digits) {
    labels.clear();
    for (double value : values) labels.push_back(formatNumber(value, digits));
    if (std::set<std::string>(labels.begin(), labels.end()).size() == labels.size()) break;
  }
  return labels;
}

int BarPlacement::columnAt(double position) const {
  return left + std::min(kBarLength - 1, int(std::clamp(position, 0.0, 1.0) * kBarLength));
}

BarPlacement barPlacement(const Legend& legend, int viewHeight) {
  return {kLegendPadding, viewHeight + kLegendPadding + int(legend.title.size()) * (lineHeight() + kLegendLineGap)};
}

std::vector<std::string> Legend::lines() const {
  std::vector<std::string> out = title;
  if (bar)
    for (const Tick& tick : bar->ticks) out.push_back(tick.label);
  for (const LegendEntry& entry : entries) out.push_back(entry.label);
  return out;
}

Image withLegend(const Image& view, const Legend& legend) {
  UVTK_CHECK(view.channels == 3);
  const auto [width, height] = paintLegend(legend, view.height, nullptr);
  Image out(std::max(view.width, width), view.height + height, 3);
  fillRect(out, 0, 0, out.width, out.height, kPanelColour);
  for (int row = 0; row < view.height; ++row)
    std::copy_n(&view.pixels[view.index(0, row)], 3 * std::size_t(view.width), &out.pixels[out.index(0, row)]);
  paintLegend(legend, view.height, &out);
  return out;
}

}  // namespace uvtk::views
