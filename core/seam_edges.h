// Seams and fanned poles of a UV layout, read from the per-corner UVs alone: the one seam rule,
// which the judgement, the views and the seam placement of param/ all read (below param/ and
// analysis/, so that neither holds a second one).
//
// An edge is a pair of vertices; it is examined when exactly two triangles have it (a boundary
// or non-manifold edge is never a seam) and none of the four corners at its endpoints is invalid.
// Vertices that meet at one position on edges of one face are one vertex here (the lowest-numbered
// stands for them): a PLY or glTF is split into a vertex per UV at its seams (io/split_vertices.h),
// and its seams are found as in the OBJ it was written from. It is a seam edge when the two faces give one of its endpoints UVs that differ by
// more than 1e-6 in u or in v. Endpoints that are pole vertices are left out of the comparison:
// a fanned pole has a different u in every face by construction (docs/conventions.md §5).
//   wrap seam: at every compared endpoint the UVs differ by the same non-zero integer in u
//              (within 1e-6) and agree in v (within 1e-6): the two sides meet under REPEAT.
//   cut:       any other difference.
// An edge whose endpoints are both poles is not classified.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk {

struct SeamEdges {
  std::size_t wrapEdges = 0, cutEdges = 0;
  double wrapLength = 0.0, cutLength = 0.0;  // total 3D edge length of each class
  double length() const { return wrapLength + cutLength; }
};

// One seam edge, with the corners of both faces at its endpoints, so that each face's side of
// the edge can be found in the UV layout.
struct SeamEdge {
  int a = 0, b = 0;                      // vertex indices, a < b (the vertices standing for a split vertex)
  std::array<std::size_t, 2> cornerA{};  // per face sharing the edge: its corner (index into UvMap::uv) at a
  std::array<std::size_t, 2> cornerB{};  // and at b
  bool wrap = false;                     // a wrap seam; else a cut
};

// Pole vertices of a fanned pole: vertices of kFacePole faces whose valid corners in those
// faces have u values that differ by more than 1e-6 from any integer; the vertices of those faces
// at one position are one vertex (the lowest-numbered is listed). A ring vertex on the seam
// differs by exactly 1 between its pole faces and is not a pole; a pole mapped with
// PoleMode::None (u = 0 everywhere) is not detected, and needs no exclusion. Ascending order.
std::vector<int> fannedPoleVertices(const Mesh& mesh, const UvMap& uv);

// What a file's UVs cannot say but show: uv.cornerPole set on every corner of fannedPoleVertices.
void markFannedPoles(const Mesh& mesh, UvMap& uv);

// The vertices with a corner at a pole (uv.cornerPole), ascending: what summaries list and count.
std::vector<int> poleVerticesOf(const Mesh& mesh, const UvMap& uv);

// The seam edges in ascending (a, b) order, leaving out endpoints at a pole (uv.cornerPole: a
// vertex with any corner there). Precondition: `uv` has 3 corners per triangle.
std::vector<SeamEdge> seamEdgeList(const Mesh& mesh, const UvMap& uv);

// The counts and lengths of seamEdgeList(mesh, uv) per class.
SeamEdges classifySeamEdges(const Mesh& mesh, const UvMap& uv);

}  // namespace uvtk
