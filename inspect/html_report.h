// HTML pages: `uvtk report --html`, one self-contained page (pictures embedded as data URIs,
// histograms as inline SVG, no external file), and the gallery of a scene run, which links the
// files the run wrote next to it. Both read offline in any browser.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/image.h"

namespace uvtk::inspect {

// The page for `report` (the JSON `uvtk report` writes) and the named view pictures.
std::string htmlReport(const nlohmann::json& report, const std::vector<std::pair<std::string, Image>>& views);

// The gallery page of a scene run: `run` holds the title, the scene, the stages with their times,
// the outputs (each with its kind and files) and the failures. Pictures and links are relative to
// the page at `pagePath`, and only to files that exist.
std::string galleryHtml(const nlohmann::json& run, const std::string& pagePath);

}  // namespace uvtk::inspect
