#include "inspect/compare.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "analysis/distortion.h"
#include "analysis/summary.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "inspect/map_parameters.h"
#include "inspect/mapped_mesh.h"
#include "param/make_projector.h"
#include "inspect/measures_json.h"
#include "core/progress.h"
#include "io/mesh_writer.h"
#include "param/projector_names.h"
#include "render/camera.h"
#include "inspect/run_report.h"
#include "views/views.h"
#include "io/json_text.h"

namespace uvtk::inspect {

namespace {

// The --by measure; a mapping without a single ok face has no measure and comes last in its verdict.
double rankKey(const analysis::Summary& s, RankBy by) {
  if (s.statusCounts[analysis::FaceStatus::Ok] == 0) return std::numeric_limits<double>::infinity();
  switch (by) {
    case RankBy::StretchL2:
      return s.l2Stretch;
    case RankBy::StretchLinf:
      return s.linfStretch;
    case RankBy::Angle:
      return s.angleDistortion.mean;
    case RankBy::SeamLength:
      return s.seams.length();
  }
  return 0.0;
}

RankedMapping measure(std::string name, MappedMesh mapped, const CompareOptions& a) {
  RankedMapping c;
  c.name = std::move(name);
  c.mapped = std::move(mapped);
  c.judgement = c.mapped.judge(a.thresholds, a.overlapResolution, 0, a.textureSize);
  c.key = rankKey(c.summary(), a.by);
  c.record = judgementJson(c.mapped, c.judgement);
  c.record["name"] = c.name;
  c.record["first_reason"] = c.judgement.firstReason();
  addMappingOrigin(c.record, c.mapped);
  return c;
}

// Pass, then warn, then fail; inside a verdict by the --by measure, ties by the shorter seam.
bool ranksBefore(const RankedMapping& x, const RankedMapping& y) {
  if (x.judgement.verdict != y.judgement.verdict) return x.judgement.verdict < y.judgement.verdict;
  return x.key < y.key || (x.key == y.key && x.summary().seams.length() < y.summary().seams.length());
}

// The atlas (or LSCM, ARAP per chart) for compare's texture and margin.
param::ProjectorOptions atlasOptions(param::SurfaceKind surface, const CompareOptions& a) {
  param::ProjectorOptions o;
  o.surface = surface;
  o.placement.fit = param::Fit::None;
  o.atlas.textureSize = {a.textureSize.width, a.textureSize.height};
  o.atlas.marginTexels = a.margin;
  return o;
}

// The projector configurations compare runs: every surface x O-mapping (the reflection needs an
// eye, which compare does not have) x fit (bbox about each axis, PCA, oriented box; the two-plane
// projector works in object space, so one fit). The cube is laid out as a cross, so that its faces
// do not overlap in UV.
std::vector<std::pair<std::string, param::ProjectorOptions>> configurations(const Mesh& mesh,
                                                                             const CompareOptions& a) {
  using namespace param;
  const std::pair<const char*, RayKind> rays[] = {
      {"isn", RayKind::SurfaceNormal}, {"centroid", RayKind::Centroid}, {"normal", RayKind::ObjectNormal}};
  const auto fitted = [&mesh](Fit fit, int axis) {
    PlacementOptions placement;
    placement.fit = fit;
    placement.axis = axis;
    if (fit == Fit::Pca && !mesh.positions.empty()) placement.spreadAxes = principalAxes(mesh.positions);
    if (fit == Fit::Obb && !mesh.positions.empty()) placement.spreadAxes = orientedBoxAxes(mesh.positions);
    return placement;
  };
  // The spread axes are fitted once for all the surfaces and O-mappings.
  const std::pair<const char*, PlacementOptions> fits[] = {{"bbox-x", fitted(Fit::BBox, 0)},
                                                           {"bbox-y", fitted(Fit::BBox, 1)},
                                                           {"bbox-z", fitted(Fit::BBox, 2)},
                                                           {"pca", fitted(Fit::Pca, 2)},
                                                           {"obb", fitted(Fit::Obb, 2)}};
  std::vector<std::pair<std::string, ProjectorOptions>> out;
  for (const SurfaceKind surface : kSurfaces) {
    const SurfaceTraits& traits = traitsOf(surface);
    if (traits.isPerspective || traits.blendsProjections) continue;  // a view's and the engines' blend, not a layout
    if (traits.chartsFromMesh) {  // the atlas, one configuration; the flattening baselines apart (addBaselines)
      if (traits.chartMap == ChartMap::Plane) out.emplace_back(traits.name, atlasOptions(surface, a));
      continue;
    }
    for (const auto& [rayName, ray] : rays)
      for (const auto& [fitName, fit] : fits) {
        if (!traits.fitsToMesh && fitName != std::string("bbox-z")) continue;
        ProjectorOptions o;
        o.surface = surface;
        o.ray = ray;
        o.placement = fit;
        o.cubeLayout = CubeLayout::Cross;
        const std::string fitLabel = traits.fitsToMesh ? fitName : "object";
        out.emplace_back(std::string(traits.name) + "/" + rayName + "/" + fitLabel, o);
      }
  }
  return out;
}

// LSCM and ARAP as `uvtk map --projector lscm|arap` makes them: of the whole mesh where it is a
// topological disk, else of each chart of the atlas (cut there, so they run where they can
// succeed on any mesh), packed as the atlas. Charts where they failed keep their plane projection:
// the record and stderr name them and why. Skipped (with the reason) only beyond
// --baseline-max-faces or when the atlas cannot be made.
void addBaselines(const Mesh& mesh, const CompareOptions& a, std::vector<RankedMapping>& baselines,
                  nlohmann::json& skipped) {
  for (const param::SurfaceKind surface : param::kSurfaces) {
    const param::SurfaceTraits& traits = param::traitsOf(surface);
    if (!traits.chartsFromMesh || traits.chartMap == param::ChartMap::Plane) continue;  // LSCM and ARAP
    const std::string name = traits.name;
    if (mesh.faceCount() > std::size_t(a.baselineMaxFaces)) {
      skipped.push_back({{"name", name}, {"reason", "more than --baseline-max-faces " + std::to_string(a.baselineMaxFaces) + " faces"}});
      continue;
    }
    try {
      RankedMapping row = measure(name, mapByProjector(mesh, atlasOptions(surface, a), false), a);
      const param::Atlas& atlas = *row.mapped.projection->atlas;
      if (atlas.fallbackCharts > 0) {
        row.record["fallback_charts"] = atlas.fallbackCharts;
        row.record["fallback_reasons"] = atlas.fallbackReasons;
        std::string note = "uvtk compare: " + name + ": " + std::to_string(atlas.fallbackCharts) + " of " +
                           std::to_string(atlas.charts.size()) + " charts kept their plane projection";
        for (const std::string& reason : atlas.fallbackReasons) note += "; " + reason;
        printProgressMessage(note);
      }
      baselines.push_back(std::move(row));
    } catch (const UsageError& e) {
      skipped.push_back({{"name", name}, {"reason", e.what()}});
      printProgressMessage("uvtk compare: " + name + " skipped: " + e.what());
    }
  }
}

// The line above the table when nothing passes: what stops the best candidates.
std::string nothingPassesLine(const std::vector<RankedMapping>& ranked) {
  if (ranked.empty() || ranked.front().judgement.verdict == analysis::Verdict::Pass) return "";
  std::string line = "No mapping passes. The best: ";
  for (std::size_t i = 0; i < std::min<std::size_t>(3, ranked.size()); ++i)
    line += (i == 0 ? "" : "; ") + ranked[i].name + " (" + analysis::toString(ranked[i].judgement.verdict) + ": " +
            ranked[i].judgement.firstReason() + ")";
  return line + ".\n\n";
}

std::string markdownTable(const std::vector<RankedMapping>& ranked, RankBy by) {
  static const char* kByNames[] = {"L2 stretch", "Linf stretch", "angle (mean)", "seam length"};
  std::string table = nothingPassesLine(ranked) + "Ranked by verdict, then by " + kByNames[int(by)] +
                      " (ties: the shorter seam).\n\n"
                      "| rank | mapping | verdict | L2 stretch | Linf stretch | angle (mean) | seam length | flipped "
                      "area | overlap | why |\n"
                      "|---:|---|---|---:|---:|---:|---:|---:|---:|---|\n";
  char row[512];
  for (std::size_t i = 0; i < ranked.size(); ++i) {
    const RankedMapping& c = ranked[i];
    std::string why = c.judgement.reasonsText();
    if (c.record.contains("fallback_charts"))  // LSCM or ARAP failed on some charts: say so where the row is read
      why += std::string(why.empty() ? "" : "; ") + std::to_string(c.record["fallback_charts"].get<std::size_t>()) +
             " charts kept their plane projection (see stderr)";
    // A mapping without an ok face has no stretch or angle to show: "—", as its JSON's null.
    const bool measured = c.summary().statusCounts[analysis::FaceStatus::Ok] > 0;
    const auto shown = [&](double value) {
      char text[32] = "—";
      if (measured) std::snprintf(text, sizeof text, "%.5g", value);
      return std::string(text);
    };
    std::snprintf(row, sizeof row, "| %zu | %s | %s | %s | %s | %s | %.5g | %.3g%% | %.3g%% | ", i + 1, c.name.c_str(),
                  analysis::toString(c.judgement.verdict), shown(c.summary().l2Stretch).c_str(),
                  shown(c.summary().linfStretch).c_str(), shown(c.summary().angleDistortion.mean).c_str(),
                  c.summary().seams.length(), 100.0 * c.judgement.values[std::size_t(analysis::Rule::FlippedArea)],
                  100.0 * c.summary().overlap.fraction());
    table += row + (why.empty() ? std::string("-") : why) + " |\n";
  }
  return table;
}

}  // namespace

const ChoiceNames<RankBy> kRankByNames = {{"stretch_l2", RankBy::StretchL2},
                                           {"stretch_linf", RankBy::StretchLinf},
                                           {"angle", RankBy::Angle},
                                           {"seam_length", RankBy::SeamLength}};

CompareOptions readCompareOptions(const param::ParameterDictionary& p) {
  constexpr int kMost = std::numeric_limits<int>::max();
  CompareOptions o;
  o.json = p.getText("json").value_or("");
  o.markdown = p.getText("markdown").value_or("");
  o.sheet = p.getText("sheet").value_or("");
  o.writeBest = p.getText("write-best").value_or("");
  o.by = p.getChoice("by", kRankByNames, o.by);
  o.top = p.getInteger("top", o.top, 1, kMost);
  o.tileSize = p.getInteger("tile-size", o.tileSize, kMinTileSize, kMaxTileSize);
  o.camera.viewDir = p.getVector<3>("view-dir").value_or(o.camera.viewDir);
  o.camera.up = p.getVector<3>("up").value_or(o.camera.up);
  o.overlapResolution = readOverlapResolution(p, o.overlapResolution);
  if (const std::optional<std::array<int, 2>> size = param::readTextureSize(p))
    o.textureSize = {(*size)[0], (*size)[1]};
  o.seamPlaceAuto = p.getBool("seam-place-auto", o.seamPlaceAuto);
  o.baselines = !p.getBool("no-baselines", !o.baselines);
  o.baselineMaxFaces = p.getInteger("baseline-max-faces", o.baselineMaxFaces, 0, kMost);
  o.margin = p.getInteger("margin", o.margin, 0, kMost);
  o.threads = p.getInteger("threads", o.threads, 0, 1024);
  o.thresholds = readThresholds(p);
  o.check();
  return o;
}

std::vector<std::string> compareParameterNames() {
  return {"json", "markdown", "sheet", "write-best", "by", "top", "tile-size", "view-dir", "up", "overlap-resolution",
          "texture-size", "seam-place-auto", "no-baselines", "baseline-max-faces", "margin", "threads", "fail-on",
          "warn-on"};
}

void CompareOptions::check() const {
  if (top < 1) throw UsageError("--top: expected at least 1");
  if (tileSize < kMinTileSize || tileSize > kMaxTileSize)
    throw UsageError("--tile-size: expected " + std::to_string(kMinTileSize) + " to " + std::to_string(kMaxTileSize) +
                     " pixels");
  checkOverlapResolution(overlapResolution);
  if (!sheet.empty()) io::checkImageType(sheet, io::PixelType::UInt8);
  if (!writeBest.empty()) io::checkMeshOutput(writeBest, io::MeshWriteOptions{}, "--write-best");
  if (!(margin >= 0 && 2 * margin < std::min(textureSize.width, textureSize.height)))
    throw UsageError("--margin: expected texels from 0 to less than half the texture");
}

Comparison rankMappings(const CompareOptions& a, const Mesh& mesh, const nlohmann::json& input) {
  StageClock clock("uvtk compare");
  nlohmann::json skipped = nlohmann::json::array();
  const auto all = configurations(mesh, a);
  // Room for all at once: a RankedMapping is copied, not moved, when the vector grows (its
  // judgement's Eigen box has no noexcept move), and copying mapped meshes took seconds.
  std::vector<RankedMapping> ranked;
  ranked.reserve(all.size() + 2);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto& [name, options] = all[i];
    clock.start("mapping", name + " (" + std::to_string(i + 1) + "/" + std::to_string(all.size()) + ")");
    const bool wraps = param::traitsOf(options.surface).wraps;
    try {
      ranked.push_back(measure(name, mapByProjector(mesh, options, a.seamPlaceAuto && wraps), a));
    } catch (const UsageError& e) {
      skipped.push_back({{"name", name}, {"reason", e.what()}});
    }
    clock.stop();
  }
  std::stable_sort(ranked.begin(), ranked.end(), ranksBefore);
  if (a.baselines) {
    clock.start("baselines", "LSCM, ARAP");
    std::vector<RankedMapping> baselines;
    baselines.reserve(2);
    addBaselines(mesh, a, baselines, skipped);
    for (RankedMapping& b : baselines) ranked.push_back(std::move(b));
    std::stable_sort(ranked.begin(), ranked.end(), ranksBefore);
    clock.stop();
  }

  Comparison out;
  out.table = markdownTable(ranked, a.by);
  for (const nlohmann::json& s : skipped)  // every mapping not ranked, with its reason, under the table
    out.table += "\nNot ranked: " + s["name"].get<std::string>() + ": " + s["reason"].get<std::string>() + "\n";
  out.record = {{"tool", {{"name", "uvtk"}, {"version", UVTK_VERSION}}},
                {"input", input},
                {"rank_by", nameOf(kRankByNames, a.by)},
                {"order", "verdict (pass, warn, fail), then rank_by, then seam length"},
                {"ranking", nlohmann::json::array()},
                {"skipped", skipped}};
  for (std::size_t i = 0; i < ranked.size(); ++i) {
    nlohmann::json record = ranked[i].record;
    record["rank"] = i + 1;
    out.record["ranking"].push_back(std::move(record));
  }
  out.best = ranked.empty() ? "none" : ranked.front().name;
  out.skipped = skipped.size();
  out.ranking = std::move(ranked);
  return out;
}

Image comparisonSheet(const Comparison& comparison, const CompareOptions& a) {
  const std::vector<RankedMapping>& ranked = comparison.ranking;
  const std::size_t count = std::min(ranked.size(), std::size_t(std::max(a.top, 1)));
  std::vector<std::pair<std::string, Image>> tiles;
  for (std::size_t i = 0; i < count; ++i) {
    const RankedMapping& c = ranked[i];
    const views::ViewInput in = c.mapped.viewInput(&c.judgement);
    views::ViewOptions options;
    options.render.camera = a.camera.frame(c.mapped.mesh, inputPath(comparison.record.value("input", nlohmann::json())),
                                           a.tileSize, a.tileSize);
    options.render.raster = {render::Cull::None, a.threads};
    for (const views::View view : {views::View::Checker, views::View::Stretch})
      tiles.emplace_back("#" + std::to_string(i + 1) + " " + analysis::toString(c.judgement.verdict) + " " + c.name +
                             " " + views::toString(view),
                         views::drawView(view, in, options));
  }
  return views::contactSheet(tiles, 4);
}


Comparison compareMappings(io::OutputSet& outputs, const CompareOptions& a, const Mesh& mesh,
                           const nlohmann::json& input) {
  Comparison out = rankMappings(a, mesh, input);
  if (!a.markdown.empty()) outputs.writeText(a.markdown, out.table);
  if (!a.sheet.empty()) {
    StageClock clock("uvtk compare");
    clock.start("drawing", a.sheet);
    io::writeImage(outputs, a.sheet, comparisonSheet(out, a), io::PixelType::UInt8);
    clock.stop();
  }
  if (!a.writeBest.empty() && !out.ranking.empty()) {
    const RankedMapping& best = out.ranking.front();
    io::MeshWriteOptions write;
    write.header = "uvtk compare: the first-ranked mapping, " + best.name;
    io::writeMesh(outputs, a.writeBest, best.mapped.mesh, &best.mapped.uv, write);
    out.record["best"] = {{"name", best.name},
                          {"output", a.writeBest},
                          {"verdict", analysis::toString(best.judgement.verdict)},
                          {"map_options", best.mapped.projector ? mapOptionsOf(*best.mapped.projector) : ""}};
  }
  if (!a.json.empty()) outputs.writeText(a.json, io::jsonText(out.record, 2) + "\n");
  return out;
}

std::string mapOptionsOf(const param::ProjectorOptions& o) {
  using namespace param;
  const SurfaceTraits& traits = traitsOf(o.surface);
  std::string line = std::string("--projector ") + traits.name;
  if (traits.chartsFromMesh) {
    char extra[96];
    std::snprintf(extra, sizeof extra, " --texture-size %d,%d --margin %g", o.atlas.textureSize[0], o.atlas.textureSize[1],
                  o.atlas.marginTexels);
    return line + extra;
  }
  line += std::string(" --omap ") + nameOf(kRayNames, o.ray);
  if (traits.fitsToMesh) {
    line += std::string(" --fit ") + nameOf(kFitNames, o.placement.fit);
    if (o.placement.fit == Fit::BBox) line += std::string(" --axis ") + nameOf(kAxisNames, o.placement.axis);
  }
  if (traits.hasFaceIds) line += std::string(" --cube-layout ") + nameOf(kCubeLayoutNames, o.cubeLayout);
  return line;
}

Comparison compareMappings(const CompareOptions& a, const Mesh& mesh, const nlohmann::json& input) {
  io::OutputSet outputs;
  Comparison comparison = compareMappings(outputs, a, mesh, input);
  outputs.publish();
  return comparison;
}

}  // namespace uvtk::inspect
