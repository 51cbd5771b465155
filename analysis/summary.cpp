#include "analysis/summary.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/parallel.h"

namespace uvtk::analysis {

Summary summarize(const Mesh& mesh, const UvMap& uv, const std::vector<FaceDistortion>& faces, int overlapResolution,
                  const std::vector<int>* poleVertices, int threads) {
  UVTK_CHECK(faces.size() == mesh.triangles.size() && uv.uv.size() == 3 * faces.size() &&
             uv.faceFlags.size() == faces.size());
  Summary s;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    ++s.statusCounts.faces[static_cast<std::size_t>(faces[f].status)];
    s.poleFaces += uv.faceHas(f, kFacePole) ? 1 : 0;
  }

  // Sander et al. 2001, "Texture stretch metric": L2(M) = sqrt(sum(A3 L2^2) / sum(A3)), Linf(M) = max Linf, each
  // times sqrt(sum(Auv) / sum(A3)) so that a uniformly scaled layout scores as the isometry.
  const AreaTotals totals = okAreaTotals(faces);
  const double normalisation = std::sqrt(1.0 / totals.surfacePerUv());
  std::vector<double> weights, angles, areas, l2, linf;
  double l2Squares = 0.0;
  for (const FaceDistortion& face : faces) {
    if (face.status != FaceStatus::Ok) continue;
    weights.push_back(face.area3d);
    angles.push_back(face.angleDistortion);
    areas.push_back(face.areaDistortion);
    l2.push_back(face.l2Stretch * normalisation);
    linf.push_back(face.linfStretch * normalisation);
    l2Squares += face.area3d * face.l2Stretch * face.l2Stretch;
  }
  if (totals.surface > 0.0) {
    s.l2Stretch = std::sqrt(l2Squares / totals.surface) * normalisation;
    s.linfStretch = *std::max_element(linf.begin(), linf.end());
  }
  const struct {
    Statistics* out;
    const std::vector<double>* values;
    BinSpacing spacing;
  } measures[] = {{&s.angleDistortion, &angles, BinSpacing::Log2},
                  {&s.areaDistortion, &areas, BinSpacing::Linear},
                  {&s.l2Stretches, &l2, BinSpacing::Log2},
                  {&s.linfStretches, &linf, BinSpacing::Log2}};
  s.poleVertices = poleVertices ? *poleVertices : fannedPoleVertices(mesh, uv);
  std::sort(s.poleVertices.begin(), s.poleVertices.end());
  // Six independent measures side by side: the statistics, the seams, the overlap and bounds.
  parallelFor(6, threads, [&](int k) {
    if (k < 4) {
      *measures[k].out = weightedStatistics(*measures[k].values, weights, measures[k].spacing);
    } else if (k == 4) {
      s.seams = classifySeamEdges(mesh, uv, s.poleVertices);
    } else {
      for (std::size_t corner = 0; corner < uv.uv.size(); ++corner)
        if (uv.cornerInvalid.empty() || uv.cornerInvalid[corner] == 0) s.uvBounds.extend(uv.uv[corner]);
      s.overlap = measureOverlap(uv, faces, overlapResolution);
    }
  });
  return s;
}

}  // namespace uvtk::analysis
