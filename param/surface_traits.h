// What each surface is, answered in one place: every layer asks traitsOf() rather than comparing
// the surface enum (a surface added here and in its formula is known everywhere).
#pragma once

#include "param/placement.h"

namespace uvtk::param {

// The unit shape a fit puts the mesh on (§2), which also bounds the sensible hits (§4).
enum class UnitShape {
  None,      // object space (two-plane) or no surface (camera)
  Plane,     // [0, 1]^2 x {0}, looking along the smallest spread
  Cylinder,  // radius 1 about z, z in [0, 1]
  Ball,      // the unit ball (the sphere, and the maps of its directions)
  Cube,      // [-1, 1]^3, each axis to its own extent
  Box,       // the mesh's box scaled by its largest extent, from its low corner (triplanar)
};

// How the charts made from a whole mesh are laid flat (param/atlas.h): each by its projection
// direction (the atlas, Smart UV Project's way), or flattened by LSCM or ARAP (the baselines).
enum class ChartMap { Plane, Lscm, Arap };

// What a surface is. A surface with a formula of a point declares its own (surfaces.h, kTraits).
struct SurfaceTraits {
  const char* name;         // as every face spells it (param/projector_names.h)
  bool wraps;               // u turns about the axis with period 1: a seam, poles, --seam-place, the math mode
  bool choosesPerTriangle;  // a projection per triangle (cube faces, triplanar axes): no per-vertex mapping
  bool fitsToMesh;          // its placement is fitted to the mesh (two-plane works in object space)
  bool projectsAlongAxis;   // one projection along local z (the plane): stretch is measured against it
  bool blendsProjections;   // three projections blended by the normal per pixel (triplanar)
  bool isPerspective;       // a camera's perspective, with a q per corner; no surface, no placement
  bool hasFaceIds;          // a face id per corner (the cube's six), written as w by its faces layout
  UnitShape shape;
  // Charts made from the whole mesh (the atlas, param/atlas.h): no formula of a point alone, so no
  // per-vertex evaluation without the mesh; each face's chart is linear, so it is exact per pixel.
  bool chartsFromMesh = false;
  ChartMap chartMap = ChartMap::Plane;  // with chartsFromMesh: how its charts are laid flat
};

const SurfaceTraits& traitsOf(SurfaceKind surface);

// Every surface, in the order help and messages list them (placement.h's list).
#define UVTK_SURFACE_VALUE(kind) SurfaceKind::kind,
inline constexpr SurfaceKind kSurfaces[] = {UVTK_SURFACE_KINDS(UVTK_SURFACE_VALUE)};
#undef UVTK_SURFACE_VALUE

}  // namespace uvtk::param
