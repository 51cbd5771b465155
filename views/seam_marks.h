// The seam edges as the seams and layout views draw them.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "analysis/overlap.h"
#include "core/seam_edges.h"
#include "core/mesh.h"
#include "core/uv_map.h"
#include "views/legend.h"

namespace uvtk::views {

struct SeamMarks {
  std::vector<SeamEdge> edges;  // drawing order: wraps first, so that cuts stay on top where both meet

  static Vec3 colour(const SeamEdge& edge) { return edge.wrap ? kWrapSeamColour : kCutColour; }
};

// "wrap seam edges: N" and "cut edges: N" in their colours, N from the judgement's summary.
std::vector<LegendEntry> seamLegendEntries(const SeamEdges& counts);

// "0.42 % of 123456 covered pixels (1024 x 1024 raster)": the judgement's overlap, as the JSON has it.
std::string overlapText(const analysis::Overlap& overlap);

// seamEdgeList(mesh, uv) in drawing order.
SeamMarks seamMarks(const Mesh& mesh, const UvMap& uv);

}  // namespace uvtk::views
