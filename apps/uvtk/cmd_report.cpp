// `uvtk report`: every measure of a UV layout (the file's own UVs, or a projector's) as JSON, and
// as one self-contained HTML page with the views and histograms.
#include <cstdio>
#include <memory>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>

#include "options/cli_values.h"
#include "commands.h"
#include "core/progress.h"
#include "io/checksum.h"
#include "io/mesh_reader.h"
#include "inspect/mapped_mesh.h"
#include "options/projector_cli.h"
#include "options/report_cli.h"
#include "inspect/run_report.h"
#include "options/verdict_cli.h"
#include "inspect/verdict.h"

namespace uvtk::cli {

using namespace uvtk::inspect;

namespace {

struct ReportCommandArguments {
  std::string input;
  ReportArguments report;
  ProjectorArguments projector;
  VerdictArguments verdict;
};

void runReport(const ReportCommandArguments& a) {
  a.report.check();
  a.verdict.check();
  const bool projectorGiven = given(a.projector.app, "--projector");
  const param::ProjectorRequest projector = a.projector.resolve();

  StageClock clock("uvtk report");
  clock.start("reading", a.input);
  io::ReadMeshResult input = io::readMesh(a.input);
  nlohmann::json inputSummary = inputJson(a.input, input);
  inputSummary["sha256"] = io::sha256File(a.input);
  const double readMs = clock.stop();

  clock.start("texture coordinates", std::to_string(input.mesh.faceCount()) + " faces");
  const MappedMesh mapped = projectorGiven
                                ? mapByProjector(std::move(input.mesh), projector.options, projector.seamPlaceAuto)
                                : withFileUvs(std::move(input.mesh), a.input);
  const double mapMs = clock.stop();

  clock.start("measuring", std::to_string(mapped.mesh.faceCount()) + " faces");
  const analysis::Judgement judgement = mapped.judge(a.verdict.thresholds(), a.report.overlapResolution, 0,
                                                     a.report.options().textureSize);
  const double measureMs = clock.stop();

  inspect::ReportOptions reportOptions = a.report.options();
  if (reportOptions.json.empty() && reportOptions.html.empty()) {  // no file asked for: a summary on the terminal
    printMappingNotes(a.input, input.warnings, mapped);
    std::fputs(reportSummaryText(a.input, mapped, judgement, reportOptions).c_str(), stdout);
    enforceVerdict(a.verdict, judgement.verdict, "uvtk report");
    return;
  }
  clock.start("writing", a.report.html.empty() ? a.report.json : a.report.html);
  // A triplanar page shows its blend too, unless --views says what to show.
  if (projectorGiven && param::traitsOf(projector.options.surface).blendsProjections && !reportOptions.html.empty() &&
      !given(a.projector.app, "--views"))
    reportOptions.views.insert(reportOptions.views.end(), {views::View::Weights, views::View::BlendZone});
  std::optional<analysis::Judgement> withLine;  // with the mip line's rule when the page draws it
  writeReport(reportOptions, mapped, judgement, inputSummary,
              {{"read", readMs}, {"texcoords", mapMs}, {"measure", measureMs}}, &withLine);
  const analysis::Judgement& judged = withLine ? *withLine : judgement;
  clock.stop();
  printMappingNotes(a.input, input.warnings, mapped);
  const analysis::Summary& summary = judgement.summary;
  if (!quiet())
    std::fprintf(stderr,
               "uvtk report: %zu faces, L2 stretch %.6g, Linf stretch %.6g, %zu seam edges, overlap %.4g%%; %s\n",
               mapped.mesh.faceCount(), summary.l2Stretch, summary.linfStretch,
               summary.seams.wrapEdges + summary.seams.cutEdges, 100.0 * summary.overlap.fraction(),
               verdictLine(judged).c_str());
  enforceVerdict(a.verdict, judged.verdict, "uvtk report");
}

}  // namespace

void addReportCommand(CLI::App& root) {
  auto a = std::make_shared<ReportCommandArguments>();
  CLI::App* cmd = root.add_subcommand(
      "report", "Measure a UV layout (the file's own UVs, or a projector's): distortion, seams, poles, overlap");
  cmd->add_option("input", a->input, "Input mesh (.obj, .off, .ply, .stl, .gltf, .glb)")->required();
  addReportOptions(*cmd, a->report);
  addProjectorOptions(*cmd, a->projector);
  addVerdictOptions(*cmd, a->verdict);
  cmd->callback([a] { runReport(*a); });
}

}  // namespace uvtk::cli
