// The measures of a UV layout (analysis/summary.h) as JSON: the record `uvtk report` writes and
// `uvtk compare` ranks. Key names are part of the interface (docs/views.md, README).
#pragma once

#include <nlohmann/json.hpp>

#include "analysis/summary.h"
#include "mapped_mesh.h"

namespace uvtk::cli {

// mean, p50, p90, p99, min, max (area-weighted) and the histogram.
nlohmann::json statisticsJson(const analysis::Statistics& statistics);

// vertices, faces, stretch_l2, stretch_linf, angle, area, stretch_l2_faces, stretch_linf_faces,
// status_counts, seams, poles, uv_bounds, overlap_fraction, overlap.
nlohmann::json measuresJson(const MappedMesh& mapped, const analysis::Summary& summary);

}  // namespace uvtk::cli
