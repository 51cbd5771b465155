// `uvtk compare`: every projector x O-mapping x placement fit on one mesh, ranked by a measure,
// with CGAL's LSCM and ARAP as non-projector baselines where the mesh is (or can be cut into) a
// topological disk; a Markdown table, a JSON record and a contact sheet of the best ones.
#include <cstdio>
#include <memory>
#include <string>

#include "commands.h"
#include "core/progress.h"
#include "options/compare_cli.h"
#include "io/mesh_reader.h"
#include "core/error.h"
#include "inspect/run_report.h"
#include "options/verdict_cli.h"
#include "inspect/verdict.h"

namespace uvtk::cli {

using namespace uvtk::inspect;

namespace {

struct CompareCommandArguments {
  std::string input;
  CompareArguments compare;
  VerdictArguments verdict;
};

void runCompare(CompareCommandArguments& a) {
  CompareOptions options = a.compare.resolve();
  if (a.verdict.exitFrom()) throw UsageError("--fail-on: compare takes RULE=VALUE, not warn or fail");
  options.thresholds = a.verdict.thresholds();
  StageClock clock("uvtk compare");
  clock.start("reading", a.input);
  const io::ReadMeshResult input = io::readMesh(a.input);
  clock.stop();
  const Comparison comparison = compareMappings(options, input.mesh, inputJson(a.input, input));
  std::fputs(comparison.table.c_str(), stdout);
  printInputWarnings(a.input, input.warnings);
  if (!quiet())
    std::fprintf(stderr, "uvtk compare: %zu mappings ranked, %zu skipped; best: %s\n",
               comparison.record["ranking"].size(), comparison.skipped, comparison.best.c_str());
  if (comparison.record.contains("best"))
    std::fprintf(stderr, "uvtk compare: wrote %s: %s, %s (as uvtk map %s -o %s %s)\n", options.writeBest.c_str(),
                 comparison.best.c_str(), comparison.record["best"]["verdict"].get<std::string>().c_str(),
                 a.input.c_str(), options.writeBest.c_str(),
                 comparison.record["best"]["map_options"].get<std::string>().c_str());
}

}  // namespace

void addCompareCommand(CLI::App& root) {
  auto a = std::make_shared<CompareCommandArguments>();
  CLI::App* cmd = root.add_subcommand(
      "compare", "Rank every projector x O-mapping x fit (and CGAL's LSCM and ARAP) on a mesh by a distortion measure");
  cmd->add_option("input", a->input, "Input mesh (.obj, .off, .ply, .stl, .gltf, .glb)")->required();
  addCompareOptions(*cmd, a->compare);
  addVerdictOptions(*cmd, a->verdict);
  cmd->callback([a] { runCompare(*a); });
}

}  // namespace uvtk::cli
