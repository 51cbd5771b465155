#include "inspect/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <tuple>
#include <optional>

#include "core/error.h"
#include "core/number_text.h"
#include "param/make_projector.h"
#include "inspect/html_report.h"
#include "inspect/map_parameters.h"
#include "inspect/mesh_view.h"
#include "inspect/projector_json.h"
#include "inspect/measures_json.h"
#include "inspect/run_report.h"
#include "inspect/summary_json.h"
#include "inspect/verdict.h"
#include "io/atomic_file.h"
#include "render/procedural.h"
#include "io/json_text.h"

namespace uvtk::inspect {

void ReportOptions::check() const {
  checkOverlapResolution(overlapResolution);
  if (textureSize.width < 1 || textureSize.height < 1 || textureSize.width > 16384 || textureSize.height > 16384)
    throw UsageError("--texture-size: expected 1 to 16384 texels");
}

std::pair<int, int> readImageSize(const param::ParameterDictionary& p, const std::string& name,
                                  std::pair<int, int> fallback) {
  if (!p.given(name)) return fallback;
  if (p.givenAsText(name)) return parseImageSize(*p.getText(name), p.spelled(name));
  if (p.givenAsNumbers(name)) {
    const Eigen::Vector2d wh = *p.getVector<2>(name);
    if (wh != wh.array().floor().matrix() || wh.minCoeff() < 1 || wh.maxCoeff() > 16384)
      throw UsageError(p.spelled(name) + ": expected W, H with 1 <= W, H <= 16384");
    return {int(wh.x()), int(wh.y())};
  }
  const int n = p.getInteger(name, 0, 1, 16384);
  return {n, n};
}

ReportOptions readReportOptions(const param::ParameterDictionary& p) {
  ReportOptions o;
  o.json = p.getText("json").value_or("");
  o.html = p.getText("html").value_or("");
  const bool viewsGiven = p.given("views");
  if (!o.html.empty() && viewsGiven) {  // the page's views: read only for a page
    std::string list;
    for (const std::string& name : p.getTexts("views")) list += (list.empty() ? "" : ",") + name;
    o.views = views::parseViewList(list, p.spelled("views"));
  }
  std::tie(o.width, o.height) = readImageSize(p, "size", {o.width, o.height});
  o.camera.viewDir = p.getVector<3>("view-dir").value_or(o.camera.viewDir);
  o.camera.up = p.getVector<3>("up").value_or(o.camera.up);
  if (const std::optional<std::array<int, 2>> size = param::readTextureSize(p))
    o.textureSize = {(*size)[0], (*size)[1]};
  o.overlapResolution = readOverlapResolution(p, o.overlapResolution);
  o.threads = p.getInteger("threads", o.threads, 0, 1024);
  o.view3dFaces = std::size_t(p.getInteger("view3d-faces", int(o.view3dFaces), 0, std::numeric_limits<int>::max()));
  return o;
}

std::vector<std::string> reportParameterNames() {
  return {"json", "html", "views", "size", "view-dir", "up", "texture-size", "overlap-resolution", "threads",
          "view3d-faces"};
}

namespace {

// The views the page shows: the file's UVs have no exact mapping to compare with.
std::vector<views::View> pageViews(const MappedMesh& mapped, const ReportOptions& options) {
  std::vector<views::View> out;
  if (options.html.empty()) return out;
  for (const views::View view : options.views)
    if (!views::needsExactMapping(view) || mapped.exact) out.push_back(view);
  return out;
}

// The texture uverror counts texels in: W x H, checks of an eighth of the smaller side as
// render::checkerTexture's (whose texture is square).
render::Texture uverrorTexture(analysis::TextureSize size) {
  if (size.width == size.height) return render::checkerTexture(size.width, std::max(1, size.width / 8));
  render::checkTextureSize(size.width, size.height);
  const int c = std::max(1, std::min(size.width, size.height) / 8);
  render::TexelLevel base;
  base.width = size.width, base.height = size.height;
  base.texels.resize(std::size_t(size.width) * std::size_t(size.height));
  for (int j = 0; j < size.height; ++j)
    for (int i = 0; i < size.width; ++i)
      base.texels[std::size_t(j) * std::size_t(size.width) + std::size_t(i)] =
          (i / c + j / c) % 2 == 0 ? render::Rgba(1.0f, 1.0f, 1.0f, 1.0f) : render::Rgba(0.0f, 0.0f, 0.0f, 1.0f);
  return render::Texture(std::move(base), true);
}

}  // namespace

nlohmann::json reportJson(const MappedMesh& mapped, const analysis::Judgement& judgement, const ReportOptions& options,
                          const nlohmann::json& input) {
  nlohmann::json report = judgementJson(mapped, judgement);
  report["tool"] = {{"name", "uvtk"}, {"version", UVTK_VERSION}};
  report["input"] = input;
  report["texcoords"] = mapped.source;
  if (mapped.projection) report["mapping"] = summaryJson(mapped.projection->summary, mapped.projector && param::traitsOf(mapped.projector->surface).blendsProjections);
  addMappingOrigin(report, mapped);
  const analysis::TextureSize& size = options.textureSize;
  if (size.width <= 8192 && size.height <= 8192)  // 4 bytes a texel: beyond, the report says why not
    report["texels"] = texelStatisticsJson(analysis::texelStatistics(mapped.mesh, mapped.uv, size.width, size.height));
  else
    report["texels"] = {{"skipped", "the texels of a layout are counted for textures of at most 8192 a side"}};
  if (!options.html.empty()) {
    report["views"] = nlohmann::json::array();
    for (const views::View view : pageViews(mapped, options)) report["views"].push_back(views::toString(view));
  }
  return report;
}

std::string reportSummaryText(const std::string& input, const MappedMesh& mapped, const analysis::Judgement& j,
                              const ReportOptions& options) {
  const analysis::Summary& s = j.summary;
  std::string text;
  char line[512];
  std::snprintf(line, sizeof line, "%s: %zu vertices, %zu faces; UVs from the %s\n", input.c_str(),
                mapped.mesh.vertexCount(), mapped.mesh.faceCount(), mapped.source.c_str());
  text += line;
  text += verdictLine(j).substr(0, verdictLine(j).find(':')) + "\n";
  for (const analysis::Reason& r : j.reasons)
    text += "  " + std::string(analysis::toString(r.severity)) + ": " + r.text() + "\n    advice: " +
            analysis::adviceOf(r.rule) + "\n";
  std::snprintf(line, sizeof line,
                "stretch: L2 %.4g, Linf %.4g (1: isometric up to scale); angle distortion mean %.4g\n"
                "seams: %zu edges (%zu wrap, %zu cut), length %.4g; poles: %zu vertices\n"
                "overlap: %.3g %% of the covered raster; flipped faces: %zu; invalid faces: %zu\n",
                s.l2Stretch, s.linfStretch, s.angleDistortion.mean, s.seams.wrapEdges + s.seams.cutEdges,
                s.seams.wrapEdges, s.seams.cutEdges, s.seams.length(), s.poleVertices.size(),
                100.0 * s.overlap.fraction(), j.statusCount(analysis::FaceStatus::Flipped), j.invalidFaces);
  text += line;
  const analysis::TextureSize& size = options.textureSize;
  if (size.width <= 8192 && size.height <= 8192) {
    const analysis::TexelStatistics t = analysis::texelStatistics(mapped.mesh, mapped.uv, size.width, size.height);
    char gutter[64] = "no second chart";
    if (std::isfinite(t.gutters.betweenCharts)) std::snprintf(gutter, sizeof gutter, "gutter %.3g texels", t.gutters.betweenCharts);
    char bleed[64] = "charts never mix";
    if (t.firstBleedLevel) std::snprintf(bleed, sizeof bleed, "charts first mix at mip level %d", *t.firstBleedLevel);
    std::snprintf(line, sizeof line, "texels at %d x %d: %zu charts, %zu texels mapped, %s, %s\n", size.width,
                  size.height, t.charts, t.levels.front().mapped, gutter, bleed);
    text += line;
  }
  text += "(--json OUT.json or --html OUT.html for every measure)\n";
  return text;
}

nlohmann::json writeReport(io::OutputSet& outputs, const ReportOptions& o, const MappedMesh& mapped,
                           const analysis::Judgement& judgement, const nlohmann::json& input,
                           const nlohmann::json& milliseconds, std::optional<analysis::Judgement>* judged) {
  const std::vector<views::View> shown = pageViews(mapped, o);
  std::optional<render::Texture> texture;  // the views' (uverror counts its texels, mipline its levels)
  views::ViewOptions options;
  if (!shown.empty()) {
    texture = uverrorTexture(o.textureSize);
    options.render.camera = o.camera.frame(mapped.mesh, inputPath(input), o.width, o.height);
    options.render.raster.threads = o.threads;
    options.render.raster.cull = render::Cull::None;
    options.render.texture = &*texture;
    options.perPixel = mapped.exact.has_value();  // the mip line of the mapping as a shader evaluates it
  }
  const views::ViewInput in = mapped.viewInput(&judgement);
  // A page with the mipline view measures the line: the mip_line rule joins the verdict.
  std::optional<analysis::Judgement> withLine;
  std::optional<views::MipLine> line;
  if (std::find(shown.begin(), shown.end(), views::View::MipLine) != shown.end()) {
    line = views::mipLine(in, options);
    if (line->perPixel) {
      withLine = judgement;
      analysis::setMeasuredRule(*withLine, analysis::Rule::MipLine, line->share(), line->faces);
    }
  }
  const analysis::Judgement& page = withLine ? *withLine : judgement;
  nlohmann::json report = reportJson(mapped, page, o, input);
  if (line) report["mip_line"] = mipLineJson(*line);
  std::vector<std::pair<std::string, Image>> pictures;
  for (const views::View view : shown) {
    pictures.emplace_back(views::toString(view), views::drawView(view, in, options));
    if ((view == views::View::Weights || view == views::View::BlendZone) && !report.contains("blend_zone")) {
      report["blend_zone"] = blendZoneJson(views::blendZone(in, options));
    }
  }
  if (!milliseconds.is_null()) report["milliseconds"] = milliseconds;
  if (!o.json.empty()) outputs.writeText(o.json, io::jsonText(report, 2) + "\n");
  if (!o.html.empty()) {
    std::string view3d;
    if (o.view3dFaces > 0) {
      MeshViewOptions viewOptions;
      viewOptions.faceBudget = o.view3dFaces;
      viewOptions.camera = o.camera;
      view3d = meshViewHtml(mapped, page, viewOptions);
    }
    outputs.writeText(o.html, htmlReport(report, pictures, view3d));
  }
  if (judged) *judged = std::move(withLine);
  return report;
}

nlohmann::json writeReport(const ReportOptions& o, const MappedMesh& mapped, const analysis::Judgement& judgement,
                           const nlohmann::json& input, const nlohmann::json& milliseconds,
                           std::optional<analysis::Judgement>* judged) {
  io::OutputSet outputs;
  nlohmann::json report = writeReport(outputs, o, mapped, judgement, input, milliseconds, judged);
  outputs.publish();
  return report;
}

}  // namespace uvtk::inspect
