// The seam edges as the seams and layout views draw them.
#pragma once

#include <cstddef>
#include <vector>

#include "analysis/seams.h"
#include "core/mesh.h"
#include "core/uv_map.h"
#include "views/legend.h"

namespace uvtk::views {

struct SeamMarks {
  std::vector<analysis::SeamEdge> edges;  // drawing order: wraps first, so that cuts stay on top where both meet
  std::size_t wraps = 0;                  // edges[0, wraps) are the wrap seams

  static Vec3 colour(const analysis::SeamEdge& edge) { return edge.wrap ? kWrapSeamColour : kCutColour; }
  // "wrap seam edges: N" and "cut edges: N" in their colours.
  std::vector<LegendEntry> legendEntries() const;
};

// analysis::seamEdgeList(mesh, uv, poleVertices) in drawing order.
SeamMarks seamMarks(const Mesh& mesh, const UvMap& uv, const std::vector<int>& poleVertices);

}  // namespace uvtk::views
