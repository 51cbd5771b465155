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
#include "inspect/mapped_mesh.h"
#include "inspect/measures_json.h"
#include "param/baseline.h"
#include "param/cut_graph.h"
#include "render/camera.h"
#include "inspect/run_report.h"
#include "views/views.h"

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

// The projector configurations compare runs: every surface x O-mapping (the reflection needs an
// eye, which compare does not have) x fit (bbox about each axis, PCA, oriented box; the two-plane
// projector works in object space, so one fit). The cube is laid out as a cross, so that its faces
// do not overlap in UV.
std::vector<std::pair<std::string, param::ProjectorOptions>> configurations(const Mesh& mesh) {
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

// LSCM and ARAP of the mesh if it is a disk, else of the mesh cut open along the UV seams of the
// best-ranked projector that does not fail and whose seams cut it into a disk (a sphere's or a
// cylinder's seam opens a closed mesh into one piece; a cube's cuts it into six), else along a cut
// graph (param::cutToDisk: a knotted or higher-genus mesh); skipped records say why not.
void addBaselines(const Mesh& mesh, const std::vector<RankedMapping>& ranked, const CompareOptions& a,
                  std::vector<RankedMapping>& baselines, nlohmann::json& skipped) {
  const auto skip = [&](const std::string& reason) {
    for (const char* name : {"lscm", "arap"}) skipped.push_back({{"name", name}, {"reason", reason}});
  };
  if (mesh.faceCount() > std::size_t(a.baselineMaxFaces))
    return skip("more than --baseline-max-faces " + std::to_string(a.baselineMaxFaces) + " faces");
  const RankedMapping* seams = nullptr;
  Mesh disk = mesh;
  if (!param::analyzeTopology(mesh).isDisk()) {
    for (const RankedMapping& c : ranked) {
      if (c.judgement.verdict == analysis::Verdict::Fail || !c.mapped.projector) continue;
      // Cut without fanning the poles: a fanned pole splits into a vertex per face, and ARAP then
      // folds those slivers over each other.
      param::ProjectorOptions unfanned = *c.mapped.projector;
      unfanned.pole = param::PoleMode::None;
      const MappedMesh mapped = mapByProjector(mesh, unfanned, false);
      param::CutMesh cut = param::cutAlongUvSeams(mapped.mesh, mapped.uv);
      if (!param::analyzeTopology(cut.mesh).isDisk()) continue;
      disk = std::move(cut.mesh);
      seams = &c;
      break;
    }
    if (!seams) {
      try {
        disk = param::cutToDisk(mesh).mesh;
      } catch (const UsageError& e) {
        return skip(std::string("the mesh is not a topological disk, and cannot be cut into one: ") + e.what());
      }
    }
  }
  const bool cut = disk.vertexCount() != mesh.vertexCount();
  const std::string cutFrom = seams ? seams->name : cut ? "cut graph" : "";
  for (const param::Baseline baseline : {param::Baseline::Lscm, param::Baseline::Arap}) {
    const std::string name =
        std::string(param::toString(baseline)) + (cutFrom.empty() ? "" : " (cut: " + cutFrom + ")");
    try {
      MappedMesh mapped;
      mapped.uv = param::parameterizeDisk(disk, baseline);
      // Measured on the uncut mesh (same triangles in the same order), so that the cut shows as seams.
      mapped.mesh = seams ? seams->mapped.mesh : mesh;
      mapped.source = param::toString(baseline);
      baselines.push_back(measure(name, std::move(mapped), a));
      if (!cutFrom.empty()) baselines.back().record["cut_along"] = cutFrom;
    } catch (const UsageError& e) {
      skipped.push_back({{"name", name}, {"reason", e.what()}});
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
    const std::string why = c.judgement.reasonsText();
    std::snprintf(row, sizeof row, "| %zu | %s | %s | %.5g | %.5g | %.5g | %.5g | %.3g%% | %.3g%% | ", i + 1,
                  c.name.c_str(), analysis::toString(c.judgement.verdict), c.summary().l2Stretch,
                  c.summary().linfStretch, c.summary().angleDistortion.mean, c.summary().seams.length(),
                  100.0 * c.judgement.values[std::size_t(analysis::Rule::FlippedArea)],
                  100.0 * c.summary().overlap.fraction());
    table += row + (why.empty() ? std::string("-") : why) + " |\n";
  }
  return table;
}

}  // namespace

void CompareOptions::check() const {
  if (top < 1) throw UsageError("--top: expected at least 1");
  if (tileSize < 16 || tileSize > 4096) throw UsageError("--tile-size: expected 16 to 4096 pixels");
  if (overlapResolution < 1 || overlapResolution > 16384)
    throw UsageError("--overlap-resolution: expected 1 to 16384 pixels");
  if (!sheet.empty()) io::checkImageType(sheet, io::PixelType::UInt8);
}

Comparison rankMappings(const CompareOptions& a, const Mesh& mesh, const nlohmann::json& input) {
  StageClock clock("uvtk compare");
  std::vector<RankedMapping> ranked;
  nlohmann::json skipped = nlohmann::json::array();
  const auto all = configurations(mesh);
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
    addBaselines(mesh, ranked, a, baselines, skipped);
    for (RankedMapping& b : baselines) ranked.push_back(std::move(b));
    std::stable_sort(ranked.begin(), ranked.end(), ranksBefore);
    clock.stop();
  }

  Comparison out;
  out.table = markdownTable(ranked, a.by);
  static const char* kRankNames[] = {"stretch_l2", "stretch_linf", "angle", "seam_length"};
  out.record = {{"tool", {{"name", "uvtk"}, {"version", UVTK_VERSION}}},
                {"input", input},
                {"rank_by", kRankNames[int(a.by)]},
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
  if (!a.json.empty()) outputs.writeText(a.json, out.record.dump(2) + "\n");
  return out;
}

Comparison compareMappings(const CompareOptions& a, const Mesh& mesh, const nlohmann::json& input) {
  io::OutputSet outputs;
  Comparison comparison = compareMappings(outputs, a, mesh, input);
  outputs.publish();
  return comparison;
}

}  // namespace uvtk::inspect
