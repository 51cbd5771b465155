// Triangulation of a face with more than three corners, as the mesh readers meet them.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "core/math.h"

namespace uvtk::io {

// Corner numbers (0..n-1) of one triangle of a polygon, in the polygon's orientation.
using PolygonTriangle = std::array<int, 3>;

// A polygon is simple here when it is planar (no corner farther from its Newell plane than
// kNonPlanarTolerance times its bounding-box diagonal), has a non-zero area, and its boundary,
// projected to that plane, touches itself nowhere but where consecutive edges meet (repeated
// consecutive corners are allowed). A twisted quad whose corners are 1 % of its size off the plane
// is non-planar: its two possible triangulations then differ visibly.
inline constexpr double kNonPlanarTolerance = 0.01;
// Ear clipping and the simplicity test are quadratic at worst: a non-convex polygon with more corners
// is fanned and called non-simple. At the limit, a comb takes 0.2 s, a star of 16384 spikes 8 s.
inline constexpr std::size_t kMaxEarClippingCorners = 32768;

// Reuses its scratch space across polygons, so reading a mesh of a million faces allocates nothing
// per face.
class PolygonTriangulator {
 public:
  // Replaces `triangles` with n - 2 triangles covering the polygon whose corners are
  // positions[corners[0]], ..., positions[corners[n - 1]] (n >= 3). A strictly convex polygon gives
  // the fan from its first corner, (0, i, i + 1), in O(n); any other simple polygon is ear-clipped in
  // its best-fit plane, so no triangle folds over. Returns whether the polygon is simple (above); a
  // polygon that is not is still triangulated, by what ear clipping makes of it. A triangle
  // (n = 3) is returned as it is, and is simple.
  bool triangulate(const std::vector<Vec3>& positions, const std::vector<int>& corners,
                   std::vector<PolygonTriangle>& triangles);

 private:
  void findEdges();
  bool strictlyConvex() const;
  bool earClip(std::vector<PolygonTriangle>& triangles);
  bool isEar(int b);
  bool isConvex(int b) const;
  bool boundaryIsSimple();

  std::vector<Vec3> relative_;  // the corners less the first, scaled by a power of two to about unit size
  std::vector<Vec2> points_;    // the same in the plane's frame
  std::vector<int> starts_;     // the corners whose next one is at another point
  std::vector<int> order_;      // scratch for the simplicity test
  std::vector<int> previous_, next_;  // the ring of corners not yet clipped
  std::vector<char> convex_, alive_, listed_;
  // listed_: the corners that were not strictly convex at the start, by x, and those that became so
  // later (only in a polygon that is not simple); some may be convex or clipped by now.
  std::vector<int> reflex_, lateReflex_;
};

}  // namespace uvtk::io
