// The options of the report of one mapping (`uvtk report`, and a scene's report output):
// inspect::ReportOptions as the command line spells them.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "inspect/report.h"
#include "options/view_camera_cli.h"

namespace uvtk::cli {

struct ReportArguments {
  std::string json, html;
  std::string views = "checker,uvgrid,stretch,linf,angle,area,seams,layout,bleed";
  std::string size = "384x384";
  ViewCameraArguments camera;
  std::string textureSize = "1024,1024";  // W,H or N
  int overlapResolution = analysis::kOverlapFollowsMesh, threads = 0;
  std::size_t view3dFaces = 200000;

  void check() const { options(); }  // throws UsageError before any work
  inspect::ReportOptions options() const;
};
void addReportOptions(CLI::App& app, ReportArguments& arguments);

}  // namespace uvtk::cli
