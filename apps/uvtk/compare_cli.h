// The ranking of every projector configuration on one mesh (`uvtk compare`, and a scene's compare
// output), with CGAL's LSCM and ARAP as baselines: a Markdown table, JSON, a contact sheet.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "core/mesh.h"
#include "io/atomic_file.h"
#include "mapped_mesh.h"

namespace uvtk::cli {

enum class RankBy { StretchL2, StretchLinf, Angle, SeamLength };

struct CompareArguments {
  std::string json, markdown, sheet;
  RankBy by = RankBy::StretchL2;
  int top = 8, tileSize = 256, overlapResolution = 512, baselineMaxFaces = 200000, threads = 0;
  bool seamPlaceAuto = false, baselines = true;
  ViewCamera camera;
  analysis::Thresholds thresholds;  // the verdict's (uvtk compare's --fail-on/--warn-on, a scene's "thresholds")

  void check() const;  // throws UsageError before any work
};
void addCompareOptions(CLI::App& app, CompareArguments& arguments);

struct Comparison {
  nlohmann::json record;  // what --json writes
  std::string table;      // the Markdown table
  std::string best;       // the first-ranked mapping's name
  std::size_t skipped = 0;
};

// Maps `mesh` with every configuration, ranks them and writes the outputs `arguments` names,
// published together; `input` is the "input" record.
Comparison compareMappings(const CompareArguments& arguments, const Mesh& mesh, const nlohmann::json& input);
// The same, staged in `outputs` (a scene's).
Comparison compareMappings(io::OutputSet& outputs, const CompareArguments& arguments, const Mesh& mesh,
                           const nlohmann::json& input);

}  // namespace uvtk::cli
