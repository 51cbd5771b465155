#include "analysis/summary.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>

#include "core/error.h"
#include "core/parallel.h"

namespace uvtk::analysis {

double scaledTexelDensity(const FaceDistortion& face, TextureSize size) {
  // Square roots first: the ratio of a tiny UV area to a large 3D area could underflow to 0.
  return std::sqrt(face.areaUv) / std::sqrt(face.area3d) * std::sqrt(double(size.width) * double(size.height));
}

double texelDensity(const FaceDistortion& face, const TexelDensity& density) {
  return std::ldexp(scaledTexelDensity(face, density.textureSize), density.exponent);
}

namespace {

// The scaled statistics times 2^exponent, or !finite when the smallest or the largest density
// leaves the normal doubles (the others lie between them).
void unscale(TexelDensity& d) {
  const Statistics& s = d.scaled;
  d.spread = s.p10 > 0.0 ? std::min(s.p90 / s.p10, std::numeric_limits<double>::max()) : 0.0;
  if (s.totalWeight <= 0.0) return;
  d.finite = std::isnormal(std::ldexp(s.min, d.exponent)) && std::isfinite(std::ldexp(s.max, d.exponent));
  if (!d.finite) return;
  Statistics& t = d.statistics;
  t = s;
  for (double* x : {&t.mean, &t.p10, &t.p50, &t.p90, &t.p99, &t.min, &t.max, &t.histogram.lo, &t.histogram.hi})
    *x = std::ldexp(*x, d.exponent);
}

}  // namespace

Summary summarize(const Mesh& mesh, const UvMap& uv, const std::vector<FaceDistortion>& faces, int overlapResolution,
                  const std::vector<int>* poleVertices, int threads, TextureSize textureSize) {
  UVTK_CHECK(faces.size() == mesh.triangles.size() && uv.uv.size() == 3 * faces.size() &&
             uv.faceFlags.size() == faces.size() && textureSize.width >= 1 && textureSize.height >= 1);
  Summary s;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    ++s.statusCounts.faces[static_cast<std::size_t>(faces[f].status)];
    s.poleFaces += uv.faceHas(f, kFacePole) ? 1 : 0;
  }

  // Sander et al. 2001, "Texture stretch metric": L2(M) = sqrt(sum(A3 L2^2) / sum(A3)), Linf(M) = max Linf, each
  // times sqrt(sum(Auv) / sum(A3)) so that a uniformly scaled layout scores as the isometry.
  const AreaTotals totals = okAreaTotals(faces);
  const double normalisation = std::sqrt(1.0 / totals.surfacePerUv());
  double l2Squares = 0.0, linfMax = 0.0;
  for (const FaceDistortion& face : faces) {
    if (face.status != FaceStatus::Ok) continue;
    l2Squares += face.area3d * face.l2Stretch() * face.l2Stretch();
    linfMax = std::max(linfMax, face.linfStretch() * normalisation);
  }
  if (totals.surface > 0.0) {
    s.l2Stretch = std::sqrt(l2Squares / totals.surface) * normalisation;
    s.linfStretch = linfMax;
  }
  // Each statistic of the ok faces' values weighted by their 3D areas: the areas gathered once, each
  // measure's values where its statistic is computed, 8 bytes a face (the statistic reads them a few times).
  std::vector<double> okAreas;
  okAreas.reserve(s.statusCounts[FaceStatus::Ok]);
  for (const FaceDistortion& face : faces)
    if (face.status == FaceStatus::Ok) okAreas.push_back(face.area3d);
  const auto statistics = [&](auto valueOf, BinSpacing spacing) {
    std::vector<double> values;
    values.reserve(okAreas.size());
    for (const FaceDistortion& face : faces)
      if (face.status == FaceStatus::Ok) values.push_back(valueOf(face));
    return weightedStatistics(values, okAreas, spacing);
  };
  const std::function<void()> measures[] = {
      [&] { s.angleDistortion = statistics([](const FaceDistortion& f) { return f.angleDistortion(); }, BinSpacing::Log2); },
      [&] { s.areaDistortion = statistics([](const FaceDistortion& f) { return f.areaDistortion; }, BinSpacing::Linear); },
      [&] { s.l2Stretches = statistics([&](const FaceDistortion& f) { return f.l2Stretch() * normalisation; }, BinSpacing::Log2); },
      [&] { s.linfStretches = statistics([&](const FaceDistortion& f) { return f.linfStretch() * normalisation; }, BinSpacing::Log2); },
      [&] {
        s.density.textureSize = textureSize;
        s.density.exponent = std::ilogb(measureLengthScale(mesh)) - std::ilogb(measureUvScale(uv));
        s.density.scaled = statistics([&](const FaceDistortion& f) { return scaledTexelDensity(f, textureSize); },
                                      BinSpacing::Log2);
        unscale(s.density);
      },
      [&] { s.seams = classifySeamEdges(mesh, uv, s.poleVertices); },
      [&] {
        for (std::size_t corner = 0; corner < uv.uv.size(); ++corner)
          if (uv.cornerInvalid.empty() || uv.cornerInvalid[corner] == 0) s.uvBounds.extend(uv.uv[corner]);
        s.overlap = measureOverlap(uv, faces, overlapResolution);
      }};
  s.poleVertices = poleVertices ? *poleVertices : fannedPoleVertices(mesh, uv);
  std::sort(s.poleVertices.begin(), s.poleVertices.end());
  // Seven independent measures side by side: the statistics, the density, the seams, the overlap and bounds.
  parallelFor(int(std::size(measures)), threads, [&](int k) { measures[k](); });
  return s;
}

}  // namespace uvtk::analysis
