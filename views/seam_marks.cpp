#include "views/seam_marks.h"

#include <algorithm>
#include <string>

namespace uvtk::views {

std::vector<LegendEntry> SeamMarks::legendEntries() const {
  return {{kWrapSeamColour, "wrap seam edges: " + std::to_string(wraps)},
          {kCutColour, "cut edges: " + std::to_string(edges.size() - wraps)}};
}

SeamMarks seamMarks(const Mesh& mesh, const UvMap& uv, const std::vector<int>& poleVertices) {
  SeamMarks marks;
  marks.edges = analysis::seamEdgeList(mesh, uv, poleVertices);
  const auto cuts = std::stable_partition(marks.edges.begin(), marks.edges.end(),
                                          [](const analysis::SeamEdge& e) { return e.wrap; });
  marks.wraps = std::size_t(cuts - marks.edges.begin());
  return marks;
}

}  // namespace uvtk::views
