#include "param/surface_traits.h"

#include <type_traits>

#include "core/error.h"
#include "param/projector.h"
#include "param/surfaces.h"

namespace uvtk::param {

namespace {

// The traits of the surfaces without a formula of a point; the others declare theirs (kTraits).
const SurfaceTraits& tableTraits(SurfaceKind surface) {
  using S = UnitShape;
  //                                   name         wraps  per-tri fits  axis   blends persp. face ids shape
  static const SurfaceTraits kCamera{"camera", false, false, false, false, false, true, false, S::None};
  static const SurfaceTraits kTriplanar{"triplanar", false, true, true, false, true, false, false, S::Box};
  static const SurfaceTraits kAtlas{"atlas", false, true, false, false, false, false, false, S::None, true};
  static const SurfaceTraits kLscm{"lscm", false, true, false, false, false, false, false, S::None, true, ChartMap::Lscm};
  static const SurfaceTraits kArap{"arap", false, true, false, false, false, false, false, S::None, true, ChartMap::Arap};
  if (surface == SurfaceKind::Camera) return kCamera;
  if (surface == SurfaceKind::Triplanar) return kTriplanar;
  if (surface == SurfaceKind::Atlas) return kAtlas;
  if (surface == SurfaceKind::Lscm) return kLscm;
  UVTK_CHECK(surface == SurfaceKind::Arap);  // every surface without a struct is above
  return kArap;
}

template <SurfaceKind Kind>
const SurfaceTraits& traitsOfKind() {
  using Surface = typename SurfaceOf<Kind, double>::type;
  if constexpr (std::is_void_v<Surface>) return tableTraits(Kind);
  else return Surface::kTraits;
}

}  // namespace

const SurfaceTraits& traitsOf(SurfaceKind surface) {
  switch (surface) {
#define UVTK_SURFACE_TRAITS(kind) \
  case SurfaceKind::kind:         \
    return traitsOfKind<SurfaceKind::kind>();
    UVTK_SURFACE_KINDS(UVTK_SURFACE_TRAITS)
#undef UVTK_SURFACE_TRAITS
  }
  UVTK_CHECK(false);  // a value outside the enumeration
  return tableTraits(SurfaceKind::Arap);
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
