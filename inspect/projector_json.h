// A projector's parameters as every JSON record of a mapping writes them, and where --seam-place
// auto put the seam.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/texel_layout.h"
#include "param/projector.h"

namespace uvtk::inspect {

// Every parameter of a projector by its name (the "options" record of a run).
nlohmann::json projectorOptionsJson(const param::ProjectorOptions& options);

// The atlas's charts and measures (the "atlas" record of `uvtk map --json`); a gutter with no second
// chart near is null.
// `gutters` are the layout's (analysis::measureGutters, in texels of the atlas's texture).
nlohmann::json atlasJson(const param::Atlas& atlas, const analysis::Gutters& gutters);

// "12 charts, occupancy 0.612, gutter 4 texels, 312.5 texels per unit": the atlas in a summary line.
std::string atlasLine(const param::Atlas& atlas, const analysis::Gutters& gutters);

// The statistics of a layout's texels (analysis::texelStatistics) as the report's "texels" record.
nlohmann::json texelStatisticsJson(const analysis::TexelStatistics& statistics);

// Where --seam-place auto put the seam, and what it crossed before and after.
nlohmann::json seamPlacementJson(const param::SeamPlacement& placement);

}  // namespace uvtk::inspect
