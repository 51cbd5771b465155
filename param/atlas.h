// The projector atlas: a mesh cut into charts that one planar projection each maps without a
// flipped face or an overlap of its own, the charts laid side by side in [0, 1]^2 at one texel
// density with a gutter between them (docs/conventions.md, "The atlas"). It is what Blender's
// Smart UV Project, 3ds Max's flatten mapping and xatlas's charts-and-packer do; the charts here
// are the plane S-mapping of §2 with a placement of their own, so every chart is linear in object
// space and a face's UVs are exact at every point of it.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"
#include "core/mesh.h"
#include "param/surface_traits.h"

namespace uvtk::param {

// How each chart is flattened: its plane projection, or CGAL's LSCM or ARAP (param/baseline.h) of
// the chart, which fall back to the plane where they fail, flip or overlap themselves.

struct AtlasOptions {
  ChartMap chartMap = ChartMap::Plane;
  // A face joins the projection direction nearest its normal; directions are added until every
  // face has one within this angle (Smart UV Project's "angle limit"). It bounds each chart's
  // stretch: a face at angle a to its direction is shortened by cos a across the slope.
  double angleLimitDegrees = 66.0;
  double marginTexels = 4.0;              // the gutter between charts and from the texture's border
  std::array<int, 2> textureSize{1024, 1024};  // the texels the margin and the density count in
  // Texels per object unit for every chart; without it, the largest density at which every chart
  // fits one texture. With it, charts that do not fit go on to further tiles, UDIM order: tile k
  // covers u in [k mod 10, k mod 10 + 1), v in [k div 10, k div 10 + 1).
  std::optional<double> texelsPerUnit;
};

// Throws UsageError for values no type rules out (an angle outside (0, 90), a negative margin, ...).
void checkAtlasOptions(const AtlasOptions& options);

// One chart's projection: uv = linear * (p - origin) + offset for a point p of its faces (object
// space), where the chart is a plane projection (`solved` false); an LSCM or ARAP chart's UVs are
// its own per corner.
struct AtlasChart {
  Vec3 direction = Vec3::UnitZ();  // the projection's direction (unit): the faces look along it
  Vec3 origin = Vec3::Zero();
  Eigen::Matrix<double, 2, 3> linear = Eigen::Matrix<double, 2, 3>::Zero();
  Vec2 offset = Vec2::Zero();
  std::size_t faces = 0;
  int tile = 0;  // 0 unless texelsPerUnit asked for more than one texture
  bool solved = false;  // flattened by LSCM or ARAP (ChartMap), not projected

  Vec2 uvAt(const Vec3& p) const { return linear * (p - origin) + offset; }
};

struct Atlas {
  std::vector<Vec2> uv;          // 3 per triangle, in the mesh's order
  std::vector<int> chartOfFace;  // index into charts
  std::vector<AtlasChart> charts;
  std::size_t directions = 0;       // projection directions the charts were grouped by
  std::size_t splitCharts = 0;      // charts split because their projection overlapped itself
  std::size_t mergedCharts = 0;     // charts merged into a neighbour (param/atlas.cpp)
  std::size_t cutCharts = 0;        // charts added by cutting those that pack poorly (too long, or hollow)
  std::size_t degenerateFaces = 0;  // faces of no area, given to a neighbour's chart (or their own)
  // LSCM or ARAP: the charts that kept their plane projection instead, and why (the first few).
  std::size_t fallbackCharts = 0;
  std::vector<std::string> fallbackReasons;
  double texelsPerUnit = 0.0;       // the density every chart has, in texels of textureSize
  int tiles = 1;
  double occupancy = 0.0;  // the charts' UV area over the tiles' area (the gutters: analysis::measureGutters)
  std::size_t seamEdges = 0;  // mesh edges whose faces lie in different charts
  double seamLength = 0.0;    // their total length in object space
  double stretchBound = 1.0;  // 1 / cos(angle limit): no chart stretches a face more
};

// The atlas of a mesh. With LSCM or ARAP, a mesh that is a topological disk is one chart. Deterministic: the same mesh and options give the same bits. Cost
// O(F log F) for F faces (the edge table's sort), plus the packing's search over densities.
// Throws UsageError when the charts cannot fit the texture even with no area of their own (more
// charts than margins fit: a larger texture or a smaller margin helps), or, with texelsPerUnit,
// when one chart alone is larger than a texture.
// `threads` (0: one per core) check charts side by side; the result does not depend on them.
Atlas makeAtlas(const Mesh& mesh, const AtlasOptions& options, int threads = 0);

}  // namespace uvtk::param
