// `uvtk report --html`: one self-contained page (pictures embedded as data URIs, histograms as
// inline SVG, no external file), readable offline in any browser.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/image.h"

namespace uvtk::cli {

// The page for `report` (the JSON `uvtk report` writes) and the named view pictures.
std::string htmlReport(const nlohmann::json& report, const std::vector<std::pair<std::string, Image>>& views);

}  // namespace uvtk::cli
