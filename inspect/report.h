// The report of one mapping (`uvtk report`, a scene's report output, uvtk.report() in Python):
// every measure as JSON, and one self-contained HTML page with the views.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/atomic_file.h"
#include "inspect/mapped_mesh.h"
#include "param/parameters.h"
#include "views/views.h"

namespace uvtk::inspect {

struct ReportOptions {
  std::string json;                 // the JSON file to write; empty: none
  std::string html;                 // the HTML page to write; empty: none
  std::vector<views::View> views{   // the views on the HTML page
      views::View::Checker, views::View::Uvgrid, views::View::Stretch, views::View::Linf,
      views::View::Angle,   views::View::Area,   views::View::Seams,   views::View::Layout};
  int width = 384, height = 384;    // pixels of each view
  ViewCamera camera;                // the views' camera
  int overlapResolution = analysis::kOverlapFollowsMesh;  // or pixels across the overlap raster
  analysis::TextureSize textureSize;  // the texture texel density (the judgement's) and uverror count in
  int threads = 0;                  // threads for the views (0: one per hardware thread)
  std::size_t view3dFaces = 200000;  // the page's 3D view: faces shown before it decimates; 0: no 3D view

  void check() const;  // throws UsageError for a value out of range, before any work
};

// The report's options as every face gives them (the command line, a scene, the library,
// Python's keywords): "json", "html", "views" (names, as a comma list or a list; read for a page
// only), "size" (WxH, N, or W and H), "view-dir", "up", "texture-size", "overlap-resolution",
// "threads", "view3d-faces". Throws UsageError (ParameterTypeError for a value of the wrong kind)
// naming the parameter; no file is asked for here.
ReportOptions readReportOptions(const param::ParameterDictionary& parameters);

// Every name readReportOptions reads.
std::vector<std::string> reportParameterNames();

// A picture's size from the parameter `name`: "WxH" or "N" (NxN) as text, an integer N, or the
// numbers W, H, each 1 to 16384; `fallback` when not given.
std::pair<int, int> readImageSize(const param::ParameterDictionary& parameters, const std::string& name,
                                  std::pair<int, int> fallback);

// The report of `mapped` with its `judgement` (taken at options.overlapResolution), writing
// nothing: every measure, the tool, `input` (the "input" record), the mapping's origin, and with
// an HTML page the names of the views it shows. `uvtk report --json` writes this, with the times.
nlohmann::json reportJson(const MappedMesh& mapped, const analysis::Judgement& judgement, const ReportOptions& options,
                          const nlohmann::json& input);

// The report in a few lines for a terminal (`uvtk report FILE` without --json or --html): the
// mesh, the verdict with each reason and its advice, the key measures and the layout's texels.
std::string reportSummaryText(const std::string& input, const MappedMesh& mapped, const analysis::Judgement& judgement,
                              const ReportOptions& options);

// Writes the report to options.json and the page to options.html, published together;
// `milliseconds` are the times of the stages before (none when null). Returns the report. A page
// with the mipline view measures the mapping's mip line (per pixel when it has an exact form) and
// adds the mip_line rule to the verdict: `judged`, when given, receives that judgement (none when
// the page measured no line, the verdict then `judgement`'s).
nlohmann::json writeReport(const ReportOptions& options, const MappedMesh& mapped,
                           const analysis::Judgement& judgement, const nlohmann::json& input,
                           const nlohmann::json& milliseconds = nullptr, std::optional<analysis::Judgement>* judged = nullptr);
// The same, staged in `outputs` (a scene's).
nlohmann::json writeReport(io::OutputSet& outputs, const ReportOptions& options, const MappedMesh& mapped,
                           const analysis::Judgement& judgement, const nlohmann::json& input,
                           const nlohmann::json& milliseconds = nullptr, std::optional<analysis::Judgement>* judged = nullptr);

}  // namespace uvtk::inspect
