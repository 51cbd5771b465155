#include "inspect/measures_json.h"

#include <cmath>

namespace uvtk::inspect {

nlohmann::json statisticsJson(const analysis::Statistics& s) {
  const analysis::Histogram& h = s.histogram;
  nlohmann::json edges = nlohmann::json::array();
  for (int i = 0; i <= int(h.weightFraction.size()); ++i) edges.push_back(h.edge(i));
  // Nothing measured (no ok face carries weight): no value rather than a 0 that reads as one.
  const auto measured = [&](double value) { return s.totalWeight > 0.0 ? nlohmann::json(value) : nlohmann::json(nullptr); };
  return {{"mean", measured(s.mean)},
          {"p10", measured(s.p10)},
          {"p50", measured(s.p50)},
          {"p90", measured(s.p90)},
          {"p99", measured(s.p99)},
          {"min", measured(s.min)},
          {"max", measured(s.max)},
          {"histogram",
           {{"spacing", h.spacing == analysis::BinSpacing::Log2 ? "log2" : "linear"},
            {"edges", edges},
            {"weight_fraction", h.weightFraction}}}};
}

nlohmann::json texelDensityJson(const analysis::TexelDensity& d) {
  nlohmann::json out = statisticsJson(d.statistics);
  // Beyond a double's range: no number rather than a wrong one (docs/robustness.md).
  if (!d.finite)
    for (const char* key : {"mean", "p10", "p50", "p90", "p99", "min", "max", "histogram"}) out[key] = nullptr;
  out["finite"] = d.finite;
  out["spread"] = d.spread;
  out["texture_size"] = {d.textureSize.width, d.textureSize.height};
  out["unit"] = "texels per object unit";
  return out;
}

namespace {

nlohmann::json reasonJson(const analysis::Reason& r) {
  return {{"code", analysis::toString(r.rule)},
          {"severity", analysis::toString(r.severity)},
          {"value", r.value},
          {"threshold", r.threshold},
          {"faces", r.faces},
          {"text", r.text()},
          {"advice", analysis::adviceOf(r.rule)}};
}

}  // namespace

nlohmann::json reasonsJson(const analysis::Judgement& judgement) {
  nlohmann::json reasons = nlohmann::json::array();
  for (const analysis::Reason& r : judgement.reasons) reasons.push_back(reasonJson(r));
  return reasons;
}

namespace {

// A threshold of infinity ("never") as JSON's null.
nlohmann::json thresholdJson(double threshold) {
  return std::isinf(threshold) ? nlohmann::json(nullptr) : nlohmann::json(threshold);
}

}  // namespace

nlohmann::json judgementJson(const MappedMesh& mapped, const analysis::Judgement& j) {
  using analysis::FaceStatus;
  const analysis::Summary& s = j.summary;
  nlohmann::json counts;
  for (int k = 0; k < analysis::kFaceStatusCount; ++k)
    counts[analysis::toString(FaceStatus(k))] = s.statusCounts.faces[std::size_t(k)];
  nlohmann::json values, warn, fail, corners;
  const std::size_t okFaces = j.statusCount(FaceStatus::Ok);  // none: the stretches are not measured
  for (int k = 0; k < analysis::kRuleCount; ++k) {
    const auto rule = analysis::Rule(k);
    values[analysis::toString(rule)] = j.values[std::size_t(k)];
    warn[analysis::toString(rule)] = thresholdJson(j.thresholds.of(rule, analysis::Verdict::Warn));
    fail[analysis::toString(rule)] = thresholdJson(j.thresholds.of(rule, analysis::Verdict::Fail));
  }
  for (int reason = 1; reason < kCornerInvalidCount; ++reason)
    corners[cornerInvalidName(reason)] = j.invalidCorners[std::size_t(reason)];
  nlohmann::json bounds = nullptr;
  if (!s.uvBounds.isEmpty())
    bounds = {{"min", {s.uvBounds.min().x(), s.uvBounds.min().y()}},
              {"max", {s.uvBounds.max().x(), s.uvBounds.max().y()}}};
  return {{"verdict", analysis::toString(j.verdict)},
          {"reasons", reasonsJson(j)},
          {"rule_values", values},
          {"thresholds", {{"warn", warn}, {"fail", fail}}},
          {"vertices", mapped.mesh.vertexCount()},
          {"faces", mapped.mesh.faceCount()},
          {"stretch_l2", okFaces > 0 ? nlohmann::json(s.l2Stretch) : nlohmann::json(nullptr)},
          {"stretch_linf", okFaces > 0 ? nlohmann::json(s.linfStretch) : nlohmann::json(nullptr)},
          {"angle", statisticsJson(s.angleDistortion)},
          {"area", statisticsJson(s.areaDistortion)},
          {"stretch_l2_faces", statisticsJson(s.l2Stretches)},
          {"stretch_linf_faces", statisticsJson(s.linfStretches)},
          {"texel_density", texelDensityJson(s.density)},
          {"status_counts", counts},
          {"face_flags",
           {{"invalid", j.invalidFaces},
            {"out_of_range", j.outOfRangeFaces},
            {"seam_straddling", j.straddlingFaces},
            {"unrepaired_seam", j.unrepairedSeamFaces},
            {"pole", s.poleFaces},
            {"cap", j.capFaces},
            {"cube_seam", j.cubeSeamFaces},
            {"sphere_map_singular", j.sphereMapSingularFaces},
            {"overlapping", j.overlappedFaces}}},
          {"invalid_corners", corners},
          {"seams",
           {{"wrap_edges", s.seams.wrapEdges},
            {"cut_edges", s.seams.cutEdges},
            {"length", s.seams.length()},
            {"wrap_length", s.seams.wrapLength},
            {"cut_length", s.seams.cutLength}}},
          {"poles", {{"vertices", s.poleVertices.size()}, {"faces", s.poleFaces}}},
          {"uv_bounds", bounds},
          {"overlap_fraction", s.overlap.fraction()},
          {"overlap",
           {{"resolution", s.overlap.resolution},
            {"covered_pixels", s.overlap.coveredPixels},
            {"overlapped_pixels", s.overlap.overlappedPixels}}}};
}

nlohmann::json blendZoneJson(const views::BlendZone& zone) {
  return {{"threshold", zone.threshold},
          {"pixels", zone.pixels},
          {"covered_pixels", zone.coveredPixels},
          {"invalid_pixels", zone.invalidPixels}};
}

nlohmann::json mipLineJson(const views::MipLine& line) {
  return {{"derivatives", render::toString(line.derivatives)},
          {"seam_fix", render::toString(line.seamFix)},
          {"per_pixel", line.perPixel},
          {"pixels", line.pixels},
          {"covered_pixels", line.coveredPixels},
          {"share", line.share()},
          {"faces", line.faces},
          {"where", {{"pole", line.pole}, {"seam", line.seam}, {"cube_edge", line.cubeEdge}, {"other", line.other}}}};
}

}  // namespace uvtk::inspect
