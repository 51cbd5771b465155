#include "measures_json.h"

namespace uvtk::cli {

nlohmann::json statisticsJson(const analysis::Statistics& s) {
  const analysis::Histogram& h = s.histogram;
  nlohmann::json edges = nlohmann::json::array();
  for (int i = 0; i <= int(h.weightFraction.size()); ++i) edges.push_back(h.edge(i));
  return {{"mean", s.mean},
          {"p50", s.p50},
          {"p90", s.p90},
          {"p99", s.p99},
          {"min", s.min},
          {"max", s.max},
          {"histogram",
           {{"spacing", h.spacing == analysis::BinSpacing::Log2 ? "log2" : "linear"},
            {"edges", edges},
            {"weight_fraction", h.weightFraction}}}};
}

nlohmann::json measuresJson(const MappedMesh& mapped, const analysis::Summary& s) {
  using analysis::FaceStatus;
  nlohmann::json counts;
  for (int k = 0; k < analysis::kFaceStatusCount; ++k)
    counts[analysis::toString(FaceStatus(k))] = s.statusCounts.faces[std::size_t(k)];
  // The projector knows its pole vertices (§5); from UVs alone only fanned poles show.
  const std::size_t poleVertices = mapped.projection ? mapped.projection->summary.poleVertices : s.poleVertices.size();
  nlohmann::json bounds = nullptr;
  if (!s.uvBounds.isEmpty())
    bounds = {{"min", {s.uvBounds.min().x(), s.uvBounds.min().y()}},
              {"max", {s.uvBounds.max().x(), s.uvBounds.max().y()}}};
  return {{"vertices", mapped.mesh.vertexCount()},
          {"faces", mapped.mesh.faceCount()},
          {"stretch_l2", s.l2Stretch},
          {"stretch_linf", s.linfStretch},
          {"angle", statisticsJson(s.angleDistortion)},
          {"area", statisticsJson(s.areaDistortion)},
          {"stretch_l2_faces", statisticsJson(s.l2Stretches)},
          {"stretch_linf_faces", statisticsJson(s.linfStretches)},
          {"status_counts", counts},
          {"seams",
           {{"wrap_edges", s.seams.wrapEdges},
            {"cut_edges", s.seams.cutEdges},
            {"length", s.seams.length()},
            {"wrap_length", s.seams.wrapLength},
            {"cut_length", s.seams.cutLength}}},
          {"poles", {{"vertices", poleVertices}, {"faces", s.poleFaces}}},
          {"uv_bounds", bounds},
          {"overlap_fraction", s.overlap.fraction()},
          {"overlap",
           {{"resolution", s.overlap.resolution},
            {"covered_pixels", s.overlap.coveredPixels},
            {"overlapped_pixels", s.overlap.overlappedPixels}}}};
}

}  // namespace uvtk::cli
