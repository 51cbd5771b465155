// A projector's parameters as every JSON record of a mapping writes them, and where --seam-place
// auto put the seam.
#pragma once

#include <nlohmann/json.hpp>

#include "param/projector.h"

namespace uvtk::inspect {

// Every parameter of a projector by its name (the "options" record of a run).
nlohmann::json projectorOptionsJson(const param::ProjectorOptions& options);

// Where --seam-place auto put the seam, and what it crossed before and after.
nlohmann::json seamPlacementJson(const param::SeamPlacement& placement);

}  // namespace uvtk::inspect
