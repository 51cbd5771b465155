// The Pareto chart of views/pareto.h as an inline SVG element, for HTML pages (`uvtk bench --html`,
// a scene's bench output and its gallery): real text in a sans-serif typeface, mixed case, and
// every point's label and values on hover (a <title> per point). Self-contained: no external
// reference and no script.
#pragma once

#include <string>
#include <vector>

#include "views/pareto.h"

namespace uvtk::views {

// An <svg> element of options.width x options.height user units (no <?xml?> header): the title,
// the legend of groupNames, log-log axes padded to whole decades with a grid and labels at the
// decades (0.001, 0.01, 0.1, 1, 10, 100, 1000, beyond that 10 with a superscript exponent; every
// n-th where decades crowd), the axis labels, one <circle> per finite point in its group's colour
// with a <title> of its label and both values under the axis labels, each group's Pareto front
// (paretoFrontsByGroup) as a <polyline> in its colour with its points ringed and labelled, y = 0
// points on a dotted row labelled "0" below the box (the <line class="zero-row">), and a note of
// the points skipped for a non-finite x or y. The same input gives the same bytes. Throws
// UsageError for no finite point, a finite point with x <= 0 or y < 0, or a width or height < 200.
std::string paretoChartSvg(const std::vector<ChartPoint>& points, const ParetoChartOptions& options);

}  // namespace uvtk::views
