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

// The page for `report` (the JSON `uvtk report` writes): first the verdict with its reasons, the
// 3D view `view3d` (meshViewHtml; none when empty) and the key measures with their meaning; then
// every measure in collapsible groups, the named view pictures and the histograms.
std::string htmlReport(const nlohmann::json& report, const std::vector<std::pair<std::string, Image>>& views,
                       const std::string& view3d = {});

// The gallery page of a scene run: `run` holds the title, the scene, the stages with their times,
// the outputs (each with its kind and files) and the failures. Pictures and links are relative to
// the page at `pagePath`, and only to files that exist. Each mapping's verdict badge opens its
// report page where it has one; `views3d` are the 3D views (meshViewHtml) with their titles, the
// first one open; a bench output's chart is inlined (its record's "svg").
std::string galleryHtml(const nlohmann::json& run, const std::string& pagePath,
                        const std::vector<std::pair<std::string, std::string>>& views3d = {});

}  // namespace uvtk::inspect
