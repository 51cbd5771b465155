// Where the layout view puts the UV plane in its image.
#pragma once

#include <Eigen/Geometry>

#include "analysis/overlap.h"
#include "core/math.h"

namespace uvtk::views {

// The square of the UV plane the layout view shows, as a size x size grid: the union of [0, 1]^2
// and `uvBounds` (all valid corners), made square about its centre by growing the shorter side,
// then widened by kLayoutMargin of its side on every side. Pixel (x, y) of the grid (y up) is
// image pixel (x, size - 1 - y).
constexpr double kLayoutMargin = 1.0 / 32.0;
analysis::UvGrid layoutGrid(const Eigen::AlignedBox2d& uvBounds, int size);

// A UV point in the layout image's coordinates (x right, y down; pixel centres at k + 1/2).
Vec2 layoutImagePoint(const analysis::UvGrid& grid, const Vec2& uv);

}  // namespace uvtk::views
