// Reference parametrizations for `uvtk compare`: the classical methods that flatten a mesh by
// optimisation instead of projecting it, computed by CGAL's Surface_mesh_parameterization
// (docs/conventions.md, "Reference parametrizations (CGAL)"). Both need a topological disk, so
// this header also answers what the topology of a mesh is and cuts a mesh open along its UV seams;
// cutToDisk (param/cut_graph.h) cuts any connected manifold mesh open along a short cut graph instead.
#pragma once

#include <cstddef>
#include <vector>

#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk::param {

enum class Baseline {
  Lscm,  // least squares conformal maps (Lévy et al. 2002): angles, free boundary
  Arap,  // as-rigid-as-possible (Liu et al. 2008): angles and areas, free boundary
};

const char* toString(Baseline baseline);  // "lscm", "arap"

// The topology of a triangle mesh whose vertices are identified by index. Vertices no triangle
// references are ignored.
struct Topology {
  std::size_t components = 0;     // of the triangles, joined where they share a vertex
  std::size_t boundaryLoops = 0;  // of the edges in one triangle only, joined where they meet
  // Every triangle has three distinct vertices, every edge lies in at most two triangles that
  // traverse it in opposite directions, and every vertex's triangles form one fan.
  bool manifold = false;
  long eulerCharacteristic = 0;  // vertices - edges + triangles

  bool isDisk() const { return manifold && components == 1 && boundaryLoops == 1 && eulerCharacteristic == 1; }
};

Topology analyzeTopology(const Mesh& mesh);

// A mesh cut along the seams of a UV map: corner k of triangle f lies on vertex
// mesh.triangles[f][k] as before, but two corners of one original vertex share a vertex only
// when their texture coordinates (u, v and w, if the map has w) agree within 1e-9. A seam (an
// edge whose two triangles give an endpoint different UVs) thus becomes boundary. A corner with
// cornerInvalid set, and every corner of a triangle flagged kFaceInvalid, gets a vertex of its own.
// Vertex v < mesh.vertexCount() stays vertex v (taken by its first corner), so a map without
// seams leaves the mesh as it is; the copies that cutting adds follow, in corner order.
struct CutMesh {
  Mesh mesh;                  // triangles and per-corner attributes in the input's order
  std::vector<int> vertexOf;  // the original vertex of each vertex
};

CutMesh cutAlongUvSeams(const Mesh& mesh, const UvMap& uv);

// The LSCM or ARAP parametrization of a mesh that is a topological disk (Topology::isDisk):
// three UVs per triangle in the mesh's order, scaled uniformly and translated so that their
// bounding box has its lower corner at (0, 0) and its longer side of length 1; no face flags.
// Throws UsageError saying why when the mesh is not a disk ("3 boundary loops", "not manifold"),
// has a degenerate triangle, or when CGAL fails. Implemented with CGAL (baseline_cgal.cpp).
UvMap parameterizeDisk(const Mesh& mesh, Baseline baseline);

}  // namespace uvtk::param
