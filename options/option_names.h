// The names of the mapping options' choices, as the command line, the scenes and every JSON
// record spell them, without the parser (no CLI11): the library that reports a mapping (inspect/)
// writes the same names the options read.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/arithmetic.h"
#include "param/projector.h"
#include "param/projector_names.h"
#include "texgen/texgen.h"

namespace uvtk::cli {

extern const std::vector<std::pair<std::string, texgen::TexgenMode>> kTexgenModeNames;

const std::string& precisionName(Precision precision);
const std::string& mathName(MathMode math);
const char* texgenModeName(texgen::TexgenMode mode);

// Every option of a projector by its option name (the "options" record of a run).
nlohmann::json projectorOptionsJson(const param::ProjectorOptions& options);

// Where --seam-place auto put the seam, and what it crossed before and after.
nlohmann::json seamPlacementJson(const param::SeamPlacement& placement);

// The same as one line on stderr, above a progress bar.
void printSeamPlacement(const param::SeamPlacement& placement);

}  // namespace uvtk::cli
