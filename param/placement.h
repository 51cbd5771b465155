// Placement: the projector's frame. localFromObject takes object coordinates to the frame in
// which the intermediate surface has its canonical form (docs/conventions.md §2).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/math.h"

namespace uvtk::param {

// Every surface, in the order help and messages list them. A surface with a formula of a point
// adds itself here and in param/surfaces.h alone (its struct, formula, name and traits); the
// others have their traits in param/surface_traits.cpp. Camera is no intermediate surface: the
// perspective projection of param/camera_projector.h, which bypasses placement, O-mapping, seams
// and poles. Triplanar neither: three planar projections blended by the normal
// (param/triplanar.h), placed as the others are. The atlas, LSCM and ARAP make charts from the
// whole mesh.
#define UVTK_SURFACE_KINDS(SURFACE)                                                                          \
  SURFACE(Plane) SURFACE(TwoPlane) SURFACE(Cylinder) SURFACE(Sphere) SURFACE(Cube) SURFACE(Camera)           \
  SURFACE(Triplanar) SURFACE(Octahedral) SURFACE(ShrinkWrap) SURFACE(Atlas) SURFACE(Lscm) SURFACE(Arap)

#define UVTK_SURFACE_ENUMERATOR(kind) kind,
enum class SurfaceKind { UVTK_SURFACE_KINDS(UVTK_SURFACE_ENUMERATOR) };
#undef UVTK_SURFACE_ENUMERATOR

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
// A zero extent takes another: plane x or y the larger of the two, z that one; cylinder height
// the radius; cube a half extent the largest; triplanar the box's lowest corner to the origin
// and its largest extent to 1, the same scale on every axis (texels stay square); and with nothing left (or a zero radius) the
// UnitBox's unit, half the box's largest extent rounded up to a power of two (1 for a single
// point). The fits are scale-invariant: the mesh times 2^n has the same frame after it (linear
// times 2^-n, the same translation). Any finite positions give a finite frame with orthonormal
// axes: each axis' scale is kept within [2^-1022, 2^1022] and small enough that the translation
// stays below 2^1020, which only a mesh wider than about 2^1022, a mesh or a box axis thinner than
// about 2^-1021, or a flat mesh about 2^1020 times its size from the object origin ever needs.
// Two-plane projectors work in object space, so their placement is the identity.
// Throws UsageError for an explicit frame with a zero or parallel direction or scale <= 0. Its passes
// over the positions run on `threads` threads (0: one per core), with the same frame on any number.
Affine3 fitPlacement(const std::vector<Vec3>& positions, SurfaceKind surface, const PlacementOptions& options,
                     int threads = 1);

// The rotation whose rows are the object-space directions of the fitted frame's axes, ordered
// by decreasing spread, with signs fixed so that each axis' largest component is positive.
// Implemented with CGAL (placement_cgal.cpp, the only file that includes it). Both fit the
// positions' UnitBox, so they give the same axes at every scale and any finite coordinates, and
// fit the distinct positions, so a vertex repeated (split at a seam) counts once.
// Zero extent along object axes: one such axis (a sheet) is kept exactly as the last row, the
// others fitted in its plane; two (an axis-parallel line) or three (one point) keep the object
// axes, the line's first.
Mat3 principalAxes(const std::vector<Vec3>& positions);
Mat3 orientedBoxAxes(const std::vector<Vec3>& positions);

// The positions moved to a unit box, where every fit works so that no overflow, underflow or
// floating-point trap reaches CGAL or Eigen (coordinates near 1e103 made CGAL's oriented box die
// of SIGFPE: its predicates' products overflow): unit = 2^-exponent (p - corner), corner the
// bounding box's low corner, 2^exponent the smallest power of two above the largest half extent,
// so that every unit coordinate is in [0, 2). A power of two scales exactly: a mesh and the same
// mesh times 2^n give the same unit positions and so the same fit, and so does the mesh moved far
// from the origin (p - corner is exact there). All points equal: exponent 0. The positions must
// be finite (the readers refuse the rest; checked).
struct UnitBox {
  std::vector<Vec3> unit;
  Vec3 corner = Vec3::Zero();
  int exponent = 0;
  std::array<bool, 3> flat{};  // the object axes along which every position is the same
};
UnitBox toUnitBox(const std::vector<Vec3>& positions, int threads = 1);

}  // namespace uvtk::param
