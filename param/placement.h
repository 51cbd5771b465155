// Placement: the projector's frame. localFromObject takes object coordinates to the frame in
// which the intermediate surface has its canonical form (docs/conventions.md §2).
#pragma once

#include <optional>
#include <vector>

#include "core/math.h"

namespace uvtk::param {

enum class SurfaceKind { Plane, TwoPlane, Cylinder, Sphere, Cube };

enum class Fit {
  None,  // local = object coordinates
  BBox,  // axis-aligned bounding box; --axis picks the object axis that becomes local z
  Center,  // the bounding box's centre only: object axes (permuted by --axis) and object units
  Pca,   // principal axes (CGAL linear_least_squares_fitting_3)
  Obb,   // CGAL oriented_bounding_box
};

// An explicit frame: local z along axisDir, local x along refDir made orthogonal to it,
// origin at center, and `scale` object units per local unit.
struct ExplicitFrame {
  Vec3 center = Vec3::Zero();
  Vec3 axisDir = Vec3::UnitZ();
  Vec3 refDir = Vec3::UnitX();
  double scale = 1.0;
};

struct PlacementOptions {
  Fit fit = Fit::BBox;
  int axis = 2;                        // 0, 1, 2: object x, y or z becomes local z (bbox fit)
  std::optional<ExplicitFrame> frame;  // when set, it replaces the fit
  // The pca or obb fit's axes when the caller has them already (principalAxes or
  // orientedBoxAxes of the same positions), so that mapping one mesh many ways fits it once.
  std::optional<Mat3> spreadAxes;
  // A turn of the frame about its local z axis, counter-clockwise seen from +z, after the fit or
  // the explicit frame: it moves the seam of a wrapping surface to this azimuth.
  double turnDegrees = 0.0;
};

// The frame for `surface` over `positions`. Fitted scales: plane, the box's x, y extent to
// [0,1]^2; cylinder, radius 1 and height to [0,1]; sphere, radius 1; cube, the box to [-1,1]^3.
// Two-plane projectors work in object space, so their placement is the identity.
// Throws UsageError for an explicit frame with a zero or parallel direction or scale <= 0.
Affine3 fitPlacement(const std::vector<Vec3>& positions, SurfaceKind surface, const PlacementOptions& options);

// The rotation whose rows are the object-space directions of the fitted frame's axes, ordered
// by decreasing spread, with signs fixed so that each axis' largest component is positive.
// Implemented with CGAL (placement_cgal.cpp, the only file that includes it).
Mat3 principalAxes(const std::vector<Vec3>& positions);
Mat3 orientedBoxAxes(const std::vector<Vec3>& positions);

}  // namespace uvtk::param
