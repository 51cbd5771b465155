#include "param/surface_traits.h"

#include "param/projector.h"
#include "param/surfaces.h"

namespace uvtk::param {

const SurfaceTraits& traitsOf(SurfaceKind surface) {
  //                                   name    wraps  per-tri fits   axis   blends perspective face ids
  static const SurfaceTraits kPlane{"plane", false, false, true, true, false, false, false};
  static const SurfaceTraits kTwoPlane{"two-plane", false, false, false, false, false, false, false};
  static const SurfaceTraits kCylinder{"cylinder", true, false, true, false, false, false, false};
  static const SurfaceTraits kSphere{"sphere", true, false, true, false, false, false, false};
  static const SurfaceTraits kCube{"cube", false, true, true, false, false, false, true};
  static const SurfaceTraits kCamera{"camera", false, false, false, false, false, true, false};
  static const SurfaceTraits kTriplanar{"triplanar", false, true, true, false, true, false, false};
  switch (surface) {
    case SurfaceKind::Plane: return kPlane;
    case SurfaceKind::TwoPlane: return kTwoPlane;
    case SurfaceKind::Cylinder: return kCylinder;
    case SurfaceKind::Sphere: return kSphere;
    case SurfaceKind::Cube: return kCube;
    case SurfaceKind::Camera: return kCamera;
    case SurfaceKind::Triplanar: return kTriplanar;
  }
  return kSphere;  // unreachable: every enumerator is above
}

// Why a projector found no value at a finite point (docs/conventions.md §4): the reason the
// mapping carried, and for a miss which miss the options make it.
const char* invalidReasonText(const ProjectorOptions& o, CornerInvalid reason) {
  static_assert(kSensibleRange == 2.0, "the out-of-range text below names the factor");
  if (o.surface == SurfaceKind::Triplanar) return "the result is not finite";
  if (o.surface == SurfaceKind::Camera)
    return reason == kCornerBehind ? "the point is at or behind the camera's eye plane (q <= 0)"
                                   : "the result is not finite";
  switch (reason) {
    case kCornerBehind:
      return o.surface == SurfaceKind::Cube ? "the ray meets the cube face's plane only behind the point"
                                            : "the ray meets the plane only behind the point";
    case kCornerOutOfRange:
      return "the hit lies beyond 2 times the fitted extent";
    case kCornerNotFinite:
      return "the result is not finite";
    default:
      break;
  }
  if (o.ray == RayKind::Centroid || (o.ray == RayKind::Reflection && o.atInfinity))
    return o.surface == SurfaceKind::Cylinder ? "the central ray runs along the cylinder's axis"
           : o.surface == SurfaceKind::Sphere ? "the point is the sphere's centre"
                                              : "the central ray points away from the surface";
  if (o.ray == RayKind::SurfaceNormal)  // isn misses nothing else (the cylinder's axis is a pole)
    return o.surface == SurfaceKind::Cube ? "the point is the cube's centre" : "the point is the sphere's centre";
  switch (o.surface) {
    case SurfaceKind::Plane:
    case SurfaceKind::TwoPlane:
      return "the ray is parallel to the plane";
    case SurfaceKind::Cylinder:
      return "the ray misses the cylinder";
    case SurfaceKind::Sphere:
      return "the ray misses the sphere";
    case SurfaceKind::Cube:
      return "the ray misses the cube, or is parallel to its face's plane";
    case SurfaceKind::Camera:
    case SurfaceKind::Triplanar:
      break;
  }
  return "the ray misses the surface";
}

}  // namespace uvtk::param
