// The atlas's packer: its charts' boxes laid into the texture at one density, with a margin
// around each (docs/conventions.md, "The atlas", Packing). Bottom-left skyline packing of the
// boxes, and the search for the largest density at which they fit.
#pragma once

#include <cstddef>
#include <vector>

#include "core/math.h"
#include "param/atlas.h"

namespace uvtk::param {

// Where a chart's box lies.
struct Placement {
  Vec2 at;      // the box's lower left corner in the tile, in texels
  int tile;
  bool turned;  // a quarter turn: the box lies w x h as h x w
};

// Each chart's place, at one density (texels per unit of the boxes).
struct Packing {
  bool fits = false;  // false: the boxes do not fit one texture even at no size
  double density = 0.0;
  std::vector<Placement> placements;
};

// The texels one chart's box may span along u and v: the texture less the margin along its
// border and the box's own margin.
Vec2 chartRoom(const AtlasOptions& options);

// The density at which the boxes' area fills the texture less its border margin: no packing
// beats it.
double areaDensity(const std::vector<Vec2>& sizes, const AtlasOptions& options);

// One density for every chart: the largest at which all fit, or the one asked for, over as
// many tiles as it takes. Boxes go in by decreasing height, area or longer side, turned where
// that sits lower or never turned: the strategy that packs the densest wins (the first on a
// tie). Beyond 2000 charts, only the first: each try then costs tens of milliseconds.
// `scale`: the object units in one unit of the boxes (a power of two; makeAtlas).
Packing packCharts(const std::vector<Vec2>& size, const std::vector<AtlasChart>& charts, const AtlasOptions& options,
                   double scale);

// Throws the UsageError for `charts` charts whose margins alone do not fit the texture.
[[noreturn]] void throwChartsDoNotFit(std::size_t charts, const AtlasOptions& options);

}  // namespace uvtk::param
