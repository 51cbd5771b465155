// A UV layout as a texture holds it, level by level of its mipmap pyramid: which texels each chart
// fills, which a bilinear lookup reaches, where two charts mix, and how far apart the charts lie
// (docs/conventions.md, "Texels of a layout"). What a baker fills and a GPU filters, rather than
// the layout's geometry alone: the seams a player sees are charts bleeding into each other at the
// levels where the gutter between them has shrunk below a texel.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk::analysis {

// The charts of a layout: faces joined across an edge whose two endpoints have equal UVs (within
// 1e-9, u and v) in both faces; a face with an invalid corner is a chart of its own. Chart ids in
// order of each chart's first face.
std::vector<int> uvCharts(const Mesh& mesh, const UvMap& uv);

// How far apart the charts lie in a W x H texture: the smallest distance, in texels, between
// edges of two charts (0 where they touch or overlap), and from any valid corner to the border of
// its [k, k + 1) tile (UDIM tiles: u and v are taken modulo 1). Infinity where there is no second
// chart, or no valid corner.
struct Gutters {
  double betweenCharts = 0.0, toBorder = 0.0;
};
Gutters measureGutters(const Mesh& mesh, const UvMap& uv, const std::vector<int>& chartOfFace, int width, int height);

// One level of the pyramid: W_L = max(1, W >> L), likewise H_L. Level 0 is rasterised (a texel is
// mapped when its centre lies in a face: the baker's rule, shared edges counted once; the
// conservative count takes a texel whose square meets a face); level L + 1 takes each texel's 2 x 2
// children at level L (GL's box filter), so a texel holds every chart its children hold.
struct TexelLevel {
  int level = 0, width = 0, height = 0;
  std::size_t mapped = 0;              // texels holding a chart
  std::size_t mappedConservative = 0;  // level 0: texels whose square meets a face (else = mapped)
  std::size_t touched = 0;             // texels a bilinear lookup inside a mapped texel may read: mapped, dilated by one
  std::size_t overwritten = 0;         // texels holding two charts or more
  std::size_t clashes = 0;             // texels whose bilinear footprint (3 x 3 neighbourhood) holds two charts or more
  double gutterTexels = 0.0;           // the smallest gutter between charts, in this level's texels
};

struct TexelStatistics {
  std::vector<TexelLevel> levels;   // from W x H down to 1 x 1
  std::size_t charts = 0;
  Gutters gutters;                  // at level 0
  std::optional<int> firstBleedLevel;  // the first level with a clash; none when the charts never mix
};

// The charts each texel of one level holds: a chart id, kTexelEmpty or kTexelMixed (two or more),
// row-major from v = 0 (index y * width + x).
constexpr std::int32_t kTexelEmpty = -1, kTexelMixed = -2;
struct TexelOwners {
  int level = 0, width = 0, height = 0;
  std::vector<std::int32_t> owner;
  std::int32_t at(int x, int y) const { return owner[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
  // Texel (x, y) holds one chart and its bilinear footprint (3 x 3 neighbourhood) another, or it
  // holds two: a lookup there mixes charts.
  bool clashes(int x, int y) const;
  // Texel (x, y) is empty but a bilinear lookup of a mapped neighbour reads it: the gutter's reach.
  bool touchedOnly(int x, int y) const;
};

// The largest side texelStatistics rasters.
constexpr int kMaxTexelSide = 8192;

// The statistics of `uv` (3 corners per face) in a width x height texture (1 to 8192 each;
// UsageError beyond). Faces with an invalid corner are left out. Cost: the faces' texels at level
// 0 plus 4/3 W H for the pyramid, 4 bytes a texel.
// `levels`, when given, receives every level's texels (4/3 W H of them, 4 bytes each), as counted.
TexelStatistics texelStatistics(const Mesh& mesh, const UvMap& uv, int width, int height,
                                std::vector<TexelOwners>* levels = nullptr);

}  // namespace uvtk::analysis
