#include "analysis/summary.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <mutex>

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

Summary summarize(const Mesh& mesh, const UvMap& uv, const FaceMeasures& faces, int overlapResolution, int threads,
                  TextureSize textureSize) {
  return summarize(mesh, uv, faces, measureScales(mesh, uv, threads), classifySeamEdges(mesh, uv), overlapResolution,
                   threads, textureSize);
}

Summary summarize(const Mesh& mesh, const UvMap& uv, const FaceMeasures& faces, const MeasureScales& scales,
                  SeamEdges seams, int overlapResolution, int threads, TextureSize textureSize) {
  UVTK_CHECK(faces.size() == mesh.triangles.size() && uv.uv.size() == 3 * faces.size() &&
             uv.faceFlags.size() == faces.size() && textureSize.width >= 1 && textureSize.height >= 1);
  Summary s;
  s.seams = std::move(seams);
  // The counts in fixed chunks on threads, and which faces are ok (the statistics' items).
  constexpr std::size_t kChunk = std::size_t(1) << 16;
  struct Counts {
    StatusCounts status;
    std::size_t poleFaces = 0;
  };
  std::vector<std::uint8_t> ok(faces.size());
  const Counts counts = reduceRanges(
      faces.size(), kChunk, threads, Counts(),
      [&](Counts& n, std::size_t begin, std::size_t end) {
        const FaceStatus* status = faces.status.data();
        for (std::size_t f = begin; f < end; ++f) {
          ++n.status.faces[static_cast<std::size_t>(status[f])];
          n.poleFaces += uv.faceHas(f, kFacePole) ? 1 : 0;
          ok[f] = status[f] == FaceStatus::Ok;
        }
      },
      [](Counts& total, const Counts& n) {
        for (std::size_t k = 0; k < kFaceStatusCount; ++k) total.status.faces[k] += n.status.faces[k];
        total.poleFaces += n.poleFaces;
      });
  s.statusCounts = counts.status;
  s.poleFaces = counts.poleFaces;

  // Sander et al. 2001, "Texture stretch metric": L2(M) = sqrt(sum(A3 L2^2) / sum(A3)), Linf(M) = max Linf, each
  // times sqrt(sum(Auv) / sum(A3)) so that a uniformly scaled layout scores as the isometry. The sums in face
  // order; max(Linf) times the positive normalisation is max(Linf times it), rounding being monotonic.
  // Summed on one thread while another starts the overlap, by the first statistic that needs them.
  AreaTotals& totals = s.okTotals;
  double normalisation = 0.0;
  std::once_flag totalsOnce;
  const auto sumTotals = [&] {
    double linfMax = 0.0, surface = 0.0, uvArea = 0.0;  // locals: the totals would be stored every face
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (!ok[f]) continue;
      surface += faces.area3d[f], uvArea += faces.areaUv[f];
      linfMax = std::max(linfMax, faces[f].linfStretch());
    }
    totals.surface = surface, totals.uv = uvArea;
    normalisation = std::sqrt(1.0 / totals.surfacePerUv());
    if (totals.surface > 0.0) {
      // A3 L2^2 grows as the fourth power of the mesh's size (at 1e77 it overflows): each L2 is taken
      // times the power of two that brings 1 / normalisation (a typical L2) to about 1; exact, undone below.
      const double unit = unitPowerOfTwo(1.0 / normalisation);
      double l2Squares = 0.0;
      for (std::size_t f = 0; f < faces.size(); ++f)
        if (ok[f]) {
          const double l2 = faces[f].l2Stretch() * unit;
          l2Squares += faces.area3d[f] * l2 * l2;
        }
      s.l2Stretch = std::sqrt(l2Squares / totals.surface) / unit * normalisation;
      s.linfStretch = linfMax * normalisation;
    }
  };
  const auto needTotals = [&] { std::call_once(totalsOnce, sumTotals); };
  // Each statistic of the ok faces' values weighted by their 3D areas: the values of every face
  // (those of the faces that are not ok unread) in the worker's buffer, 8 bytes a face, the weights
  // the faces' own areas. A worker sizes its buffer when it first computes a statistic: the
  // overlap's raster, started first, is given back before the other worker needs a second buffer.
  const auto statistics = [&](std::vector<double>& values, auto valueOf, BinSpacing spacing) {
    values.resize(faces.size());
    for (std::size_t f = 0; f < faces.size(); ++f) values[f] = ok[f] ? valueOf(faces[f]) : 0.0;
    return weightedStatistics(values.data(), faces.area3d.data(), ok.data(), faces.size(), spacing);
  };
  // The bounds of the valid UVs: reported, and the UV scale of the densities.
  s.uvBounds = scales.uvBounds;
  s.density.textureSize = textureSize;
  s.density.exponent = std::ilogb(scales.length) - std::ilogb(scales.uv());
  // The longest first (the overlap raster), so that the last task to start is a short one; then
  // the statistics that need the totals, the first of them summing them beside the overlap.
  const std::function<void(std::vector<double>&)> measures[] = {
      [&](std::vector<double>&) { s.overlap = measureOverlap(uv, faces, overlapResolution, threads); },
      [&](std::vector<double>& values) {
        needTotals();
        s.areaDistortion = statistics(
            values, [&](const FaceDistortion& f) { return f.areaDistortion(totals.surfacePerUv()); }, BinSpacing::Linear);
      },
      [&](std::vector<double>& values) {
        needTotals();
        s.l2Stretches =
            statistics(values, [&](const FaceDistortion& f) { return f.l2Stretch() * normalisation; }, BinSpacing::Log2);
      },
      [&](std::vector<double>& values) {
        needTotals();
        s.linfStretches =
            statistics(values, [&](const FaceDistortion& f) { return f.linfStretch() * normalisation; }, BinSpacing::Log2);
      },
      [&](std::vector<double>& values) {
        s.density.scaled = statistics(
            values, [&](const FaceDistortion& f) { return scaledTexelDensity(f, textureSize); }, BinSpacing::Log2);
        unscale(s.density);
      },
      [&](std::vector<double>& values) {
        s.angleDistortion = statistics(values, [](const FaceDistortion& f) { return f.angleDistortion(); }, BinSpacing::Log2);
      },
      [&](std::vector<double>&) { s.poleVertices = poleVerticesOf(mesh, uv); }};
  // Seven independent measures side by side: the overlap, the statistics, the pole vertices.
  const int count = int(std::size(measures));
  std::vector<std::vector<double>> values(std::size_t(workerCount(count, threads)));
  parallelForWorkers(count, threads, [&](int k, int worker) { measures[k](values[std::size_t(worker)]); });
  return s;
}

}  // namespace uvtk::analysis
