// The report of one mapping (`uvtk report`, and a scene's report output): every measure as JSON,
// and one self-contained HTML page with the views.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "io/atomic_file.h"
#include "mapped_mesh.h"

namespace uvtk::cli {

struct ReportArguments {
  std::string json, html;
  std::string views = "checker,uvgrid,stretch,linf,angle,area,seams,layout";
  std::string size = "384x384";
  ViewCamera camera;
  int overlapResolution = 1024, textureSize = 1024, threads = 0;

  void check() const;  // throws UsageError before any work
};
void addReportOptions(CLI::App& app, ReportArguments& arguments);

// Writes the report of `mapped` with its `judgement` (taken at arguments.overlapResolution);
// `input` is the "input" record, `milliseconds` the times of the stages before (none when null).
// The JSON and the page are published together. Returns the report.
nlohmann::json writeReport(const ReportArguments& arguments, const MappedMesh& mapped,
                           const analysis::Judgement& judgement, const nlohmann::json& input,
                           const nlohmann::json& milliseconds = nullptr);
// The same, staged in `outputs` (a scene's).
nlohmann::json writeReport(io::OutputSet& outputs, const ReportArguments& arguments, const MappedMesh& mapped,
                           const analysis::Judgement& judgement, const nlohmann::json& input,
                           const nlohmann::json& milliseconds = nullptr);

}  // namespace uvtk::cli
