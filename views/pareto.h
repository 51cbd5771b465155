// A Pareto chart of cost against error (e.g. `uvtk bench`: ns per vertex against max error in
// texels) on log-log axes, drawn with the views' own canvas and typeface (views/type.h), in the
// legend's style: kTextColour on kPanelColour.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/math.h"

namespace uvtk::views {

struct ChartPoint {
  std::string label;  // e.g. "sphere float fast T4"
  double x = 0;       // cost, e.g. ns per vertex (> 0)
  double y = 0;       // error, e.g. max error in texels (>= 0)
  int group = 0;      // colour group (e.g. one per projector); the legend names groups
};

struct ParetoChartOptions {
  std::string title, xLabel, yLabel;    // each left out when empty
  std::vector<std::string> groupNames;  // legend: group i's colour and name
  int width = 960, height = 640;
};

// The colour of a group's dots: the Okabe-Ito colour-blind-safe set without black, repeating
// every 7 groups (negative groups too).
Vec3 groupColour(int group);

// Indices of the points no other point dominates (another point with x <= and y <= and one of them
// strictly less), ordered by increasing x (equal points by index). Points with a non-finite x or y
// are ignored.
std::vector<std::size_t> paretoFront(const std::vector<ChartPoint>& points);

// paretoFront within each group: one front per group present, by increasing group number. A front
// compares configurations of one kind (one projector), never one kind's speed with another's accuracy.
std::vector<std::vector<std::size_t>> paretoFrontsByGroup(const std::vector<ChartPoint>& points);

// The whole decades a chart of `points` spans: x from floor(log10 of the least x) to ceil(log10 of
// the greatest), at least one decade; y likewise over the non-zero values (0 .. 1 when all are 0);
// whether some y is 0 (the zero row), and how many points a non-finite x or y leaves out. Throws
// UsageError for no finite point, or a finite point with x <= 0 or y < 0 (log axes).
struct ChartDecades {
  int xLo = 0, xHi = 1, yLo = 0, yHi = 1;
  bool zeroRow = false;
  std::size_t skipped = 0;
};
ChartDecades chartDecades(const std::vector<ChartPoint>& points);

// Where the label of the k-th point of a front may go, in the order tried: beside the dot to its
// right or left, above or below, `linesOut` lines further out. Even k try above right first, odd k
// below left, so that neighbouring labels alternate.
struct LabelPlace {
  bool right, above;
  int linesOut;
};
const std::array<LabelPlace, 6>& labelPlaces(std::size_t k);

// Where paretoChart puts data: the plot box and its decades.
struct ChartFrame {
  // The box's lines lie on columns left and right and rows top and bottom; the decades span the
  // box less kChartInset pixels on each side.
  int left = 0, top = 0, right = 0, bottom = 0;
  int xDecadeLo = 0, xDecadeHi = 1;  // log10 of the x values at the box's left and right insets
  int yDecadeLo = 0, yDecadeHi = 1;  // log10 of the y values at the box's bottom and top insets
  bool hasZeroRow = false;           // some point has y = 0: a baseline row is drawn below the box

  // The image position (x right, y down, pixel (i, j) covers [i, i + 1) x [j, j + 1)) of a data
  // point, x > 0, y >= 0 finite: log-linear within the box, or on the zero row for y = 0.
  Vec2 pixelOf(double x, double y) const;
  // The image y of y = 0 points: the centre of the row kZeroRowGap below the box's bottom line.
  double zeroRowY() const;
};

constexpr int kChartInset = 12;  // between the box's lines and the outer decades
constexpr int kZeroRowGap = 16;  // between the box's bottom line and the zero row

// The frame paretoChart draws `points` in. Throws UsageError for no finite points, a finite point
// with x <= 0 or y < 0, width or height < 200, or a size that leaves the plot box too small.
ChartFrame chartFrame(const std::vector<ChartPoint>& points, const ParetoChartOptions& options);

// An RGB chart of options.width x options.height: the title (bold), the legend of groupNames,
// log-log axes padded to whole decades with tick labels (... 10⁻⁴, 0.001, 0.01, 0.1, 1, 10, 100,
// 1000, 10⁴ ...; every n-th where decades crowd), one dot per point in its group's colour, each
// group's Pareto front joined by a line in its colour, its dots ringed and labelled beside them
// (alternately above right and below left, moved to another side or a line further out while they
// overlap a dot or an earlier label), y = 0 points on a row labelled "0" below the box, the axis
// labels, and a note of the points skipped for a non-finite x or y. Text is views/type.h: 14
// pixels per em, the front's labels 11. Throws as chartFrame.
Image paretoChart(const std::vector<ChartPoint>& points, const ParetoChartOptions& options);

}  // namespace uvtk::views
