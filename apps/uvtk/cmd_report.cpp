// `uvtk report`: every measure of a UV layout (the file's own UVs, or a projector's) as JSON, and
// as one self-contained HTML page with the views and histograms.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "analysis/distortion.h"
#include "analysis/summary.h"
#include "cli_values.h"
#include "commands.h"
#include "core/error.h"
#include "html_report.h"
#include "io/atomic_file.h"
#include "io/checksum.h"
#include "io/mesh_reader.h"
#include "mapped_mesh.h"
#include "measures_json.h"
#include "projector_cli.h"
#include "render/camera.h"
#include "render/procedural.h"
#include "run_report.h"
#include "summary_json.h"
#include "views/views.h"

namespace uvtk::cli {

namespace {

struct ReportArguments {
  std::string input, json, html;
  std::string views = "checker,uvgrid,stretch,linf,angle,area,seams,layout";
  std::string size = "384x384";
  ViewCamera camera;
  int overlapResolution = 1024, textureSize = 1024, threads = 0;
  ProjectorArguments projector;
};

void runReport(const ReportArguments& a) {
  if (a.json.empty() && a.html.empty()) throw UsageError("expected --json OUT.json, --html OUT.html or both");
  if (a.overlapResolution < 1 || a.overlapResolution > 16384)
    throw UsageError("--overlap-resolution: expected 1 to 16384 pixels");
  if (a.textureSize < 1 || a.textureSize > 16384) throw UsageError("--texture-size: expected 1 to 16384 texels");
  const bool projectorGiven = given(a.projector.app, "--projector");
  const param::ProjectorOptions projectorOptions = a.projector.resolve();
  const std::vector<views::View> views = a.html.empty() ? std::vector<views::View>() : views::parseViewList(a.views);
    const auto [width, height] = parseImageSize(a.size, "--size");
  a.camera.check();

  StageClock clock("uvtk report");
  clock.start("reading", a.input);
  io::ReadMeshResult input = io::readMesh(a.input);
  nlohmann::json inputSummary = inputJson(a.input, input);
  inputSummary["sha256"] = io::sha256File(a.input);
  const double readMs = clock.stop();

  clock.start("texture coordinates", std::to_string(input.mesh.faceCount()) + " faces");
  const MappedMesh mapped = projectorGiven
                                ? mapByProjector(std::move(input.mesh), projectorOptions, a.projector.seamPlaceAuto())
                                : withFileUvs(std::move(input.mesh), a.input);
  const double mapMs = clock.stop();

  clock.start("measuring", std::to_string(mapped.mesh.faceCount()) + " faces");
  const MappedMesh::Measures measures = mapped.measure(a.overlapResolution);
  const analysis::Summary& summary = measures.summary;
  const double measureMs = clock.stop();

  nlohmann::json report = measuresJson(mapped, summary);
  report["tool"] = {{"name", "uvtk"}, {"version", UVTK_VERSION}};
  report["input"] = inputSummary;
  report["texcoords"] = mapped.source;
  if (mapped.projector) {
    report["options"] = projectorOptionsJson(*mapped.projector);
    report["mapping"] = summaryJson(mapped.projection->summary);
  }
  if (mapped.seamPlacement) report["seam_placement"] = seamPlacementJson(*mapped.seamPlacement);

  std::vector<std::pair<std::string, Image>> pictures;
  if (!views.empty()) {
    clock.start("drawing views", a.views);
    const render::Texture texture = render::checkerTexture(a.textureSize, std::max(1, a.textureSize / 8));
    const views::ViewInput in = mapped.viewInput(measures);
    views::ViewOptions options;
    options.render.camera = a.camera.frame(mapped.mesh, width, height);
    options.render.raster.threads = a.threads;
    options.render.raster.cull = render::Cull::None;
    options.render.texture = &texture;
    for (const views::View view : views) {
      if (views::needsExactMapping(view) && !mapped.exact) continue;  // the file's UVs have no exact mapping
      pictures.emplace_back(views::toString(view), views::drawView(view, in, options));
    }
    report["views"] = nlohmann::json::array();
    for (const auto& picture : pictures) report["views"].push_back(picture.first);
    clock.stop();
  }
  report["milliseconds"] = {{"read", readMs}, {"texcoords", mapMs}, {"measure", measureMs}};

  if (!a.json.empty()) io::writeFileAtomically(a.json, report.dump(2) + "\n");
  if (!a.html.empty()) io::writeFileAtomically(a.html, htmlReport(report, pictures));
  printMappingNotes(a.input, input.warnings, mapped);
  std::fprintf(stderr, "uvtk report: %zu faces, L2 stretch %.6g, Linf stretch %.6g, %zu seam edges, overlap %.4g%%\n",
               mapped.mesh.faceCount(), summary.l2Stretch, summary.linfStretch,
               summary.seams.wrapEdges + summary.seams.cutEdges, 100.0 * summary.overlap.fraction());
}

}  // namespace

void addReportCommand(CLI::App& root) {
  auto a = std::make_shared<ReportArguments>();
  CLI::App* cmd = root.add_subcommand(
      "report", "Measure a UV layout (the file's own UVs, or a projector's): distortion, seams, poles, overlap");
  cmd->add_option("input", a->input, "Input mesh (.obj or .off)")->required();
  cmd->add_option("--json", a->json, "Write every measure as JSON");
  cmd->add_option("--html", a->html, "Write one self-contained HTML page with the views, measures and histograms");
  cmd->add_option("--views", a->views, "The views on the HTML page")->capture_default_str();
  cmd->add_option("--size", a->size, "Size of each view WxH")->capture_default_str();
  a->camera.addOptions(*cmd);
  cmd->add_option("--texture-size", a->textureSize, "Texels across the texture whose texels uverror counts")
      ->capture_default_str();
  cmd->add_option("--overlap-resolution", a->overlapResolution, "Pixels across the layout raster that measures overlap")
      ->capture_default_str();
  cmd->add_option("--threads", a->threads, "Threads for the views (0: one per hardware thread)")->capture_default_str();
  addProjectorOptions(*cmd, a->projector);
  cmd->callback([a] { runReport(*a); });
}

}  // namespace uvtk::cli
