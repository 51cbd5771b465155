// Cutting a closed or multiply bounded surface open into one topological disk, so that the disk
// parametrizations of param/baseline.h (LSCM, ARAP) run on any connected manifold mesh.
#pragma once

#include "core/mesh.h"
#include "param/baseline.h"

namespace uvtk::param {

// The mesh cut open along a cut graph into one topological disk (Topology::isDisk()).
//
// Algorithm: the greedy system of loops of Erickson & Whittlesey (2005), a tree-cotree cut graph
// (Eppstein 2003) whose loops are short; on a mesh with boundary, the whole boundary plays the
// base point, as in Gu, Gortler & Hoppe's "Geometry images" (2002):
//   1. T: the shortest-path tree (Dijkstra over edge lengths) from the referenced vertex nearest
//      the referenced vertices' centroid on a closed mesh, from every boundary vertex at once on
//      an open one.
//   2. C: the spanning tree of the dual graph (triangles, adjacent across the interior edges not in
//      T) of maximal weight, an edge ab weighing the length of the loop it closes through T,
//      dist(a) + |ab| + dist(b) (Kruskal). The edges C crosses are glued; the long loops go.
//   3. The interior edges C does not cross, with the boundary edges, form a graph: T, the boundary
//      and 2 - chi more edges on a closed mesh, 1 - chi on an open one. Its dangling branches are
//      pruned (an interior vertex with a single edge loses it) until none is left. What remains,
//      less the boundary, is the cut graph: on a closed mesh of genus g, 2g loops through the base
//      point (the shortest such system); on an open one, arcs that join the boundary loops and
//      open the handles; nothing on a disk. A closed genus-0 mesh keeps the last two edges, a
//      path a-b-c, so that it gets a boundary at all (a single edge would not do: its two
//      triangles would still share the vertex pair (a, b), and topology here identifies vertices
//      by index).
//   4. Every vertex's fan of corners is split at the cut edges, one vertex per piece.
// Cost O(E log E) for E edges.
//
// Result: the triangles in the input's order, corner k of triangle f on a vertex w with
// vertexOf[w] == mesh.triangles[f][k]. Vertex v < mesh.vertexCount() keeps its index (taken by its
// first corner); the copies follow in corner order: E_c + 1 - chi of them for a cut graph of E_c
// edges on a mesh of Euler characteristic chi. The per-corner attribute tables are copied as they
// are. A mesh that is already a disk comes back unchanged.
//
// Preconditions: the triangles form one connected manifold surface (Topology::manifold, one
// component); unreferenced vertices are kept and ignored. Otherwise throws UsageError saying why
// ("cutToDisk: 3 components", "cutToDisk: not manifold: edge (4, 7) has 3 faces").
CutMesh cutToDisk(const Mesh& mesh);

}  // namespace uvtk::param
