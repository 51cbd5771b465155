// Colour scales and the legend strip the views draw below their image: title lines, a colour bar
// with labelled ticks, and a list of swatches with their meaning and counts.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/math.h"
#include "views/palette.h"

namespace uvtk::views {

// A value range on a palette. Values beyond the ends take the end colours.
struct ColourScale {
  Palette palette = Palette::Sequential;
  double lo = 0.0, hi = 1.0;  // the values at the palette's ends; their log10 when logarithmic
  bool logarithmic = false;

  // Where `value` lies on the palette, in [0, 1]: (x - lo) / (hi - lo), x the value or its log10
  // (values <= 10^lo give 0). Precondition: value finite, lo < hi.
  double position(double value) const;
  Vec3 colour(double value) const { return paletteColour(palette, position(value)); }
};

struct Tick {
  double value = 0.0;
  std::string label;
};

struct ColourBar {
  ColourScale scale;
  std::vector<Tick> ticks;
};

// "%.{digits}g", with 0 for -0.
std::string formatNumber(double value, int digits = 3);

// formatNumber with the fewest significant digits in [3, 10] that keeps the labels of `values` distinct.
std::vector<std::string> distinctLabels(const std::vector<double>& values);

struct LegendEntry {
  Vec3 colour = Vec3::Zero();
  std::string label;      // e.g. "flipped: 3"
  int hatchCount = 0;     // >= 2: the swatch shows overlapHatch(hatchCount) over `colour`
};

struct Legend {
  std::vector<std::string> title;  // one line each
  std::optional<ColourBar> bar;
  std::vector<LegendEntry> entries;
  bool empty() const { return title.empty() && !bar && entries.empty(); }
  // Its text: the title lines, the bar's tick labels, the entries' labels (what `uvtk render
  // --json` records, so that every number a legend shows can be checked against the JSON).
  std::vector<std::string> lines() const;
};

// The legend's geometry. Text is views/type.h at kLegendTextSize pixels per em, every line the
// face's line box at that size (17 pixels high); every block is indented by kLegendPadding and
// separated by kLegendLineGap.
constexpr double kLegendTextSize = 13;
constexpr int kLegendPadding = 8;
constexpr int kLegendLineGap = 6;
constexpr int kBarLength = 384, kBarHeight = 16, kTickLength = 4;

// Where withLegend draws the colour bar: kBarLength x kBarHeight pixels, bar pixel i (counted
// from `left`) showing the palette at position (i + 1/2) / kBarLength.
struct BarPlacement {
  int left = 0, top = 0;
  // The column of the bar pixel that holds `position` in [0, 1].
  int columnAt(double position) const;
};
BarPlacement barPlacement(const Legend& legend, int viewHeight);

// `view` (RGB) with the legend in a strip below it, on kPanelColour. The result is
// max(view width, legend width) wide (the legend's widest line plus padding, the bar at least)
// and view height + legend height high; the view keeps its pixels at the top left.
Image withLegend(const Image& view, const Legend& legend);

}  // namespace uvtk::views
