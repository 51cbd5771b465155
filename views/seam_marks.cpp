#include "views/seam_marks.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace uvtk::views {

std::vector<LegendEntry> seamLegendEntries(const SeamEdges& counts) {
  return {{kWrapSeamColour, "wrap seam edges: " + std::to_string(counts.wrapEdges)},
          {kCutColour, "cut edges: " + std::to_string(counts.cutEdges)}};
}

std::string overlapText(const analysis::Overlap& overlap) {
  char text[160];
  std::snprintf(text, sizeof text, "%.3g %% of %zu covered pixels (%d x %d raster)", 100.0 * overlap.fraction(),
                overlap.coveredPixels, overlap.resolution, overlap.resolution);
  return text;
}

SeamMarks seamMarks(const Mesh& mesh, const UvMap& uv) {
  SeamMarks marks;
  marks.edges = seamEdgeList(mesh, uv);
  std::stable_partition(marks.edges.begin(), marks.edges.end(), [](const SeamEdge& e) { return e.wrap; });
  return marks;
}

}  // namespace uvtk::views
