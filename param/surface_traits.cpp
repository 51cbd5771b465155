#include "param/surface_traits.h"

#include "param/projector.h"
#include "param/surfaces.h"

namespace uvtk::param {

const SurfaceTraits& traitsOf(SurfaceKind surface) {
  using S = UnitShape;
  //                                   name         wraps  per-tri fits  axis   blends persp. face ids shape
  static const SurfaceTraits kPlane{"plane", false, false, true, true, false, false, false, S::Plane};
  static const SurfaceTraits kTwoPlane{"two-plane", false, false, false, false, false, false, false, S::None};
  static const SurfaceTraits kCylinder{"cylinder", true, false, true, false, false, false, false, S::Cylinder};
  static const SurfaceTraits kSphere{"sphere", true, false, true, false, false, false, false, S::Ball};
  static const SurfaceTraits kCube{"cube", false, true, true, false, false, false, true, S::Cube};
  static const SurfaceTraits kCamera{"camera", false, false, false, false, false, true, false, S::None};
  static const SurfaceTraits kTriplanar{"triplanar", false, true, true, false, true, false, false, S::Box};
  static const SurfaceTraits kOctahedral{"octahedral", false, false, true, false, false, false, false, S::Ball};
  static const SurfaceTraits kShrinkWrap{"shrink-wrap", false, false, true, false, false, false, false, S::Ball};
  static const SurfaceTraits kAtlas{"atlas", false, true, false, false, false, false, false, S::None, true};
  static const SurfaceTraits kLscm{"lscm", false, true, false, false, false, false, false, S::None, true};
  static const SurfaceTraits kArap{"arap", false, true, false, false, false, false, false, S::None, true};
  switch (surface) {
    case SurfaceKind::Plane: return kPlane;
    case SurfaceKind::TwoPlane: return kTwoPlane;
    case SurfaceKind::Cylinder: return kCylinder;
    case SurfaceKind::Sphere: return kSphere;
    case SurfaceKind::Cube: return kCube;
    case SurfaceKind::Camera: return kCamera;
    case SurfaceKind::Triplanar: return kTriplanar;
    case SurfaceKind::Octahedral: return kOctahedral;
    case SurfaceKind::ShrinkWrap: return kShrinkWrap;
    case SurfaceKind::Atlas: return kAtlas;
    case SurfaceKind::Lscm: return kLscm;
    case SurfaceKind::Arap: return kArap;
  }
  return kSphere;  // unreachable: every enumerator is above
}

// Why a projector found no value at a finite point (docs/conventions.md §4): the reason the
// mapping carried, and for a miss which miss the options make it.
const char* invalidReasonText(const ProjectorOptions& o, CornerInvalid reason) {
  static_assert(kSensibleRange == 2.0, "the out-of-range text below names the factor");
  const SurfaceTraits& traits = traitsOf(o.surface);
  if (traits.blendsProjections || traits.chartsFromMesh) return "the result is not finite";
  if (traits.isPerspective)
    return reason == kCornerBehind ? "the point is at or behind the camera's eye plane (q <= 0)"
                                   : "the result is not finite";
  switch (reason) {
    case kCornerBehind:
      return traits.shape == UnitShape::Cube ? "the ray meets the cube face's plane only behind the point"
                                             : "the ray meets the plane only behind the point";
    case kCornerOutOfRange:
      return "the hit lies beyond 2 times the fitted extent";
    case kCornerNotFinite:
      return "the result is not finite";
    default:
      break;
  }
  if (o.ray == RayKind::Centroid || (o.ray == RayKind::Reflection && o.atInfinity))
    return traits.shape == UnitShape::Cylinder ? "the central ray runs along the cylinder's axis"
           : traits.shape == UnitShape::Ball   ? "the point is the sphere's centre"
                                               : "the central ray points away from the surface";
  if (o.ray == RayKind::SurfaceNormal)  // isn misses nothing else (the cylinder's axis is a pole)
    return traits.shape == UnitShape::Cube ? "the point is the cube's centre" : "the point is the sphere's centre";
  switch (traits.shape) {
    case UnitShape::Plane:
    case UnitShape::None:
      return "the ray is parallel to the plane";
    case UnitShape::Cylinder:
      return "the ray misses the cylinder";
    case UnitShape::Ball:
      return "the ray misses the sphere";
    case UnitShape::Cube:
      return "the ray misses the cube, or is parallel to its face's plane";
    case UnitShape::Box:
      break;
  }
  return "the ray misses the surface";
}

}  // namespace uvtk::param
