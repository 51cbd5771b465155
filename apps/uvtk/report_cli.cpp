#include "report_cli.h"

#include "options/cli_values.h"
#include "core/error.h"
#include "html_report.h"
#include "io/atomic_file.h"
#include "measures_json.h"
#include "options/projector_cli.h"
#include "render/procedural.h"
#include "summary_json.h"
#include "views/views.h"

namespace uvtk::cli {

void addReportOptions(CLI::App& app, ReportArguments& a) {
  app.add_option("--json", a.json, "Write every measure as JSON");
  app.add_option("--html", a.html, "Write one self-contained HTML page with the views, measures and histograms");
  app.add_option("--views", a.views, "The views on the HTML page")->capture_default_str();
  app.add_option("--size", a.size, "Size of each view WxH")->capture_default_str();
  a.camera.addOptions(app);
  app.add_option("--texture-size", a.textureSize, "Texels across the texture whose texels uverror counts")
      ->capture_default_str();
  app.add_option("--overlap-resolution", a.overlapResolution, "Pixels across the layout raster that measures overlap")
      ->capture_default_str();
  app.add_option("--threads", a.threads, "Threads for the views (0: one per hardware thread)")->capture_default_str();
}

void ReportArguments::check() const {
  if (json.empty() && html.empty()) throw UsageError("expected --json OUT.json, --html OUT.html or both");
  if (overlapResolution < 1 || overlapResolution > 16384)
    throw UsageError("--overlap-resolution: expected 1 to 16384 pixels");
  if (textureSize < 1 || textureSize > 16384) throw UsageError("--texture-size: expected 1 to 16384 texels");
  if (!html.empty()) views::parseViewList(views);
  parseImageSize(size, "--size");
  camera.check();
}

nlohmann::json writeReport(io::OutputSet& outputs, const ReportArguments& a, const MappedMesh& mapped,
                           const analysis::Judgement& judgement, const nlohmann::json& input,
                           const nlohmann::json& milliseconds) {
  nlohmann::json report = judgementJson(mapped, judgement);
  report["tool"] = {{"name", "uvtk"}, {"version", UVTK_VERSION}};
  report["input"] = input;
  report["texcoords"] = mapped.source;
  if (mapped.projection) report["mapping"] = summaryJson(mapped.projection->summary);
  addMappingOrigin(report, mapped);

  std::vector<std::pair<std::string, Image>> pictures;
  if (!a.html.empty()) {
    const auto [width, height] = parseImageSize(a.size, "--size");
    const render::Texture texture = render::checkerTexture(a.textureSize, std::max(1, a.textureSize / 8));
    const views::ViewInput in = mapped.viewInput(&judgement);
    views::ViewOptions options;
    options.render.camera = a.camera.frame(mapped.mesh, width, height);
    options.render.raster.threads = a.threads;
    options.render.raster.cull = render::Cull::None;
    options.render.texture = &texture;
    for (const views::View view : views::parseViewList(a.views)) {
      if (views::needsExactMapping(view) && !mapped.exact) continue;  // the file's UVs have no exact mapping
      pictures.emplace_back(views::toString(view), views::drawView(view, in, options));
    }
    report["views"] = nlohmann::json::array();
    for (const auto& picture : pictures) report["views"].push_back(picture.first);
  }
  if (!milliseconds.is_null()) report["milliseconds"] = milliseconds;
  if (!a.json.empty()) outputs.writeText(a.json, report.dump(2) + "\n");
  if (!a.html.empty()) outputs.writeText(a.html, htmlReport(report, pictures));
  return report;
}

nlohmann::json writeReport(const ReportArguments& a, const MappedMesh& mapped, const analysis::Judgement& judgement,
                           const nlohmann::json& input, const nlohmann::json& milliseconds) {
  io::OutputSet outputs;
  nlohmann::json report = writeReport(outputs, a, mapped, judgement, input, milliseconds);
  outputs.publish();
  return report;
}

}  // namespace uvtk::cli
