// The measures of a UV layout (analysis/summary.h) as JSON: the record `uvtk report` writes and
// `uvtk compare` ranks. Key names are part of the interface (docs/views.md, README).
#pragma once

#include <nlohmann/json.hpp>

#include "analysis/judgement.h"
#include "inspect/mapped_mesh.h"
#include "views/views.h"

namespace uvtk::inspect {

// mean, p10, p50, p90, p99, min, max (area-weighted) and the histogram.
nlohmann::json statisticsJson(const analysis::Statistics& statistics);

// statisticsJson of the densities in texels per object unit (each null when !finite), with finite,
// spread (p90 / p10), texture_size [W, H] and unit "texels per object unit".
nlohmann::json texelDensityJson(const analysis::TexelDensity& density);

// The judgement of a mapping: verdict, reasons ({code, severity, value, threshold, faces}), rule_values,
// thresholds, vertices, faces, stretch_l2, stretch_linf, angle, area, stretch_l2_faces,
// stretch_linf_faces, texel_density, status_counts, face_flags, invalid_corners, seams, poles, uv_bounds,
// overlap_fraction, overlap. Every number is read from `judgement`.
nlohmann::json judgementJson(const MappedMesh& mapped, const analysis::Judgement& judgement);

// A judgement's reasons, each as {code, severity, value, threshold, faces, text}.
nlohmann::json reasonsJson(const analysis::Judgement& judgement);

// A triplanar blend zone (views::blendZone) as {threshold, pixels, covered_pixels, invalid_pixels}.
nlohmann::json blendZoneJson(const views::BlendZone& zone);

// The seam mip line (views::mipLine) as {derivatives, seam_fix, per_pixel, pixels, covered_pixels,
// share, faces, where: {pole, seam, cube_edge, other}}.
nlohmann::json mipLineJson(const views::MipLine& line);

}  // namespace uvtk::inspect
