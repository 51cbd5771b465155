// The mesh-wide report of a UV layout: face counts per status, the stretch of Sander, Snyder,
// Gortler and Hoppe, "Texture Mapping Progressive Meshes" (SIGGRAPH 2001) over the whole mesh,
// area-weighted statistics of the per-face measures, seams, poles, UV bounds and overlap.
//
// Only status-ok faces enter the stretch values and the statistics (the sums sum(A3), sum(Auv)
// included); pole, flipped, backfacing, degenerate and invalid faces are reported by count.
// The stretch values are normalised by sqrt(sum(Auv) / sum(A3)), so that they do not depend on
// the scale of the layout: an isometry up to a uniform scale scores 1, and nothing scores below 1.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "analysis/distortion.h"
#include "analysis/overlap.h"
#include "core/seam_edges.h"
#include "analysis/statistics.h"
#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk::analysis {

struct StatusCounts {
  std::array<std::size_t, kFaceStatusCount> faces{};
  std::size_t operator[](FaceStatus status) const { return faces[static_cast<std::size_t>(status)]; }
};

// Texel density, texels per object unit: sqrt(Auv W H / A3) per face with Auv in UV units and A3
// in object units (docs/conventions.md, "Texel density"). FaceDistortion's areas are measured at
// scale (measureLengthScale, measureUvScale: powers of two), so a face's density is computed at
// that scale and multiplied by 2^exponent, exactly; a density beyond a double's range is flagged
// (finite = false), never infinite.
struct TexelDensity {
  TextureSize textureSize;
  int exponent = 0;  // log2(measureLengthScale(mesh) / measureUvScale(uv))
  // Over the ok faces, weighted by A3, log2-spaced bins: `scaled` in texels per object unit times
  // 2^-exponent (always finite), `statistics` in texels per object unit (zeros when !finite).
  Statistics scaled, statistics;
  bool finite = true;   // every ok face's density, times 2^exponent, is a normal double
  double spread = 0.0;  // p90 / p10 of the ok faces' densities (scale-free); 0 when there is no ok face
};

// sqrt(Auv W H / A3) of a face with A3 > 0, at the measure scale (times 2^-exponent).
double scaledTexelDensity(const FaceDistortion& face, TextureSize size);
// The face's density in texels per object unit: may be 0 or infinite where !density.finite.
double texelDensity(const FaceDistortion& face, const TexelDensity& density);

struct Summary {
  StatusCounts statusCounts;
  AreaTotals okTotals;  // okAreaTotals(faces): the normalisation of the stretches
  // sqrt(sum(A3 L2^2) / sum(A3)) sqrt(sum(Auv) / sum(A3)); 0 when there is no ok face.
  double l2Stretch = 0.0;
  // max(Linf) sqrt(sum(Auv) / sum(A3)); 0 when there is no ok face.
  double linfStretch = 0.0;
  // Over the ok faces, weighted by A3, 32 bins each. The per-face L2 and Linf enter normalised
  // as the mesh values are (a face at 1 is stretched like an isometric layout of the same area).
  // Ratios get log2-spaced bins (angle, L2, Linf); area distortion, already a log2, linear bins.
  Statistics angleDistortion, areaDistortion, l2Stretches, linfStretches;
  TexelDensity density;
  SeamEdges seams;                 // classifySeamEdges: pole corners (UvMap::cornerPole) compare nothing
  std::size_t poleFaces = 0;       // faces flagged kFacePole, whatever their status
  std::vector<int> poleVertices;   // poleVerticesOf: the vertices with a corner at a pole, ascending
  Eigen::AlignedBox2d uvBounds;    // over every valid corner; empty when there is none
  Overlap overlap;
};

// The report for `faces` = measureFaces(mesh, uv, ...), with the poles the UVs' source marked
// (UvMap::cornerPole); the overlap at measureOverlap(uv, faces, overlapResolution). Preconditions:
// matching sizes, a texture of at least 1 x 1 texels. The second form takes the scales `faces` were
// measured at (measureScales) and the seam edges (classifySeamEdges(mesh, uv)) from its caller,
// which may have classified them while the faces were measured.
Summary summarize(const Mesh& mesh, const UvMap& uv, const FaceMeasures& faces,
                  int overlapResolution = kOverlapFollowsMesh, int threads = 0, TextureSize textureSize = {});
Summary summarize(const Mesh& mesh, const UvMap& uv, const FaceMeasures& faces, const MeasureScales& scales,
                  SeamEdges seams, int overlapResolution, int threads, TextureSize textureSize);

}  // namespace uvtk::analysis
