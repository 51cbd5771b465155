// layout: the UV triangles filled by a measure's colour, overlaps hatched, seam edges drawn on
// both sides, the unit square framed.
#include <algorithm>
#include <cfloat>
#include <cstdint>
#include <string>

#include "analysis/overlap.h"
#include "core/error.h"
#include "views/canvas.h"
#include "views/draw.h"
#include "views/layout.h"
#include "views/legend.h"
#include "views/measure.h"
#include "views/palette.h"
#include "views/seam_marks.h"

namespace uvtk::views {

namespace {

constexpr int kSeamWidth = 2, kFrameWidth = 1;  // pixels
constexpr int kMinSize = 16, kMaxSize = 16384;

std::string range(double lo, double hi) { return formatNumber(lo) + ".." + formatNumber(hi); }

}  // namespace

analysis::UvGrid layoutGrid(const Eigen::AlignedBox2d& uvBounds, int size) {
  Eigen::AlignedBox2d content(Vec2::Zero(), Vec2::Ones());
  content.extend(uvBounds);  // an empty box (no valid corner) leaves the unit square
  // The square with margins in the grid's scaled units (a layout spanning -1e308 .. 1e308 has no size in UV units).
  analysis::UvGrid grid = analysis::uvGridOver(content, size);
  const Eigen::AlignedBox2d& shown = grid.bounds;
  const double half = 0.5 * shown.sizes().maxCoeff() * (1.0 + 2.0 * kLayoutMargin);
  const Vec2 centre = shown.center();
  grid.bounds = Eigen::AlignedBox2d(centre - Vec2::Constant(half), centre + Vec2::Constant(half));
  return grid;
}

Vec2 layoutImagePoint(const analysis::UvGrid& grid, const Vec2& uv) {
  const Vec2 relative = (uv * grid.scale - grid.bounds.min()).cwiseQuotient(grid.bounds.sizes());
  return Vec2(relative.x(), 1.0 - relative.y()) * grid.resolution;
}

DrawnView drawLayout(const ViewInput& in, const ViewOptions& options) {
  UVTK_CHECK(in.judgement);
  const analysis::Judgement& judgement = *in.judgement;
  if (!isMeasure(options.layoutFill))
    throw UsageError(std::string("layout: expected a fill of stretch, linf, angle or area, found '") +
                     toString(options.layoutFill) + "'");
  if (options.layoutSize < kMinSize || options.layoutSize > kMaxSize)
    throw UsageError("layout: expected a size in " + std::to_string(kMinSize) + ".." + std::to_string(kMaxSize) +
                     ", found " + std::to_string(options.layoutSize));
  const UvMap& uv = *in.uv;
  const FaceColouring colouring = colourByMeasure(options.layoutFill, judgement);
  const analysis::UvGrid grid = layoutGrid(judgement.summary.uvBounds, options.layoutSize);
  const int n = grid.resolution;

  Image image(n, n, 3);
  fillRect(image, 0, 0, n, n, kLayoutBackground);
  // Painter's order: where faces overlap the later one shows, and the hatching says so.
  analysis::forEachCoveredPixel(uv, judgement.faces, grid,
                                [&](std::size_t face, int x, int y) { setPixel(image, x, n - 1 - y, colouring.colours[face]); });
  const std::vector<std::uint8_t> counts = analysis::coverageCounts(uv, judgement.faces, grid);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int count = counts[std::size_t(y) * std::size_t(n) + std::size_t(x)];
      if (std::optional<Vec3> hatch = overlapHatch(count, x, n - 1 - y)) setPixel(image, x, n - 1 - y, *hatch);
    }

  const Vec2 square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int k = 0; k < 4; ++k)
    drawSegment(image, layoutImagePoint(grid, square[k]), layoutImagePoint(grid, square[(k + 1) % 4]), kFrameWidth, kFrameColour);

  // Each seam edge on both of its faces' sides.
  const SeamMarks seams = seamMarks(*in.mesh, uv);
  for (const SeamEdge& edge : seams.edges)
    for (int side = 0; side < 2; ++side)
      drawSegment(image, layoutImagePoint(grid, uv.uv[edge.cornerA[side]]), layoutImagePoint(grid, uv.uv[edge.cornerB[side]]),
                  kSeamWidth, SeamMarks::colour(edge));

  Legend legend = colouring.legend;
  // The shown square in UV units, as far as a double reaches.
  const auto uvUnits = [&](double x) { return std::clamp(x / grid.scale, -DBL_MAX, DBL_MAX); };
  const Eigen::AlignedBox2d& shown = grid.bounds;
  legend.title.insert(legend.title.begin(), "UV layout, u " + range(uvUnits(shown.min().x()), uvUnits(shown.max().x())) +
                                                "   v " + range(uvUnits(shown.min().y()), uvUnits(shown.max().y())));
  // The hatching is drawn at this picture's resolution; the numbers are the judgement's.
  const analysis::Overlap& overlap = judgement.summary.overlap;
  legend.entries.push_back({kLayoutBackground, "overlap: " + overlapText(overlap), 2});
  legend.entries.push_back({kLayoutBackground, "faces overlapping: " + std::to_string(judgement.overlappedFaces), 3});
  for (const LegendEntry& entry : seamLegendEntries(judgement.summary.seams)) legend.entries.push_back(entry);
  legend.entries.push_back({kFrameColour, "frame: the unit square"});
  return {image, legend};
}

}  // namespace uvtk::views
