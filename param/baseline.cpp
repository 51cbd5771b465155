// Topology and seam cutting on the flat index arrays: what decides whether a mesh may go to the
// disk parametrizations of baseline_cgal.cpp, and how a UV map's seams make it one.
#include "param/baseline.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "core/disjoint_sets.h"
#include "core/error.h"

namespace uvtk::param {

namespace {

// One triangle side, directed as the triangle traverses it, and the corner it starts at.
struct HalfEdge {
  int from, to;
  std::size_t corner;  // 3 f + k with triangles[f][k] == from; the corner at `to` is the next one
  std::tuple<int, int> edge() const { return {std::min(from, to), std::max(from, to)}; }
};

std::size_t nextCorner(std::size_t corner) { return corner - corner % 3 + (corner + 1) % 3; }

}  // namespace

const char* toString(Baseline baseline) {
  switch (baseline) {
    case Baseline::Lscm: return "lscm";
    case Baseline::Arap: return "arap";
  }
  return "?";
}

Topology analyzeTopology(const Mesh& mesh) {
  const std::size_t vertexCount = mesh.vertexCount();
  Topology topology;
  topology.manifold = true;

  // Sorting the half-edges brings the sides of each edge together, whatever the mesh is.
  std::vector<HalfEdge> halfEdges;
  halfEdges.reserve(3 * mesh.faceCount());
  std::vector<bool> referenced(vertexCount, false);
  DisjointSets triangleSets(vertexCount);  // vertices joined through triangles
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    const Triangle& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      UVTK_CHECK(t[k] >= 0 && static_cast<std::size_t>(t[k]) < vertexCount);
      halfEdges.push_back({t[k], t[(k + 1) % 3], 3 * f + static_cast<std::size_t>(k)});
      referenced[t[k]] = true;
      triangleSets.join(t[k], t[(k + 1) % 3]);
    }
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) topology.manifold = false;
  }
  std::sort(halfEdges.begin(), halfEdges.end(), [](const HalfEdge& a, const HalfEdge& b) {
    return std::make_tuple(a.edge(), a.corner) < std::make_tuple(b.edge(), b.corner);
  });

  // Corners around a vertex are joined across each interior edge; the vertex is a single fan
  // exactly when all its corners end up in one set.
  DisjointSets fanSets(3 * mesh.faceCount());
  DisjointSets boundarySets(vertexCount);  // vertices joined through boundary edges
  std::vector<bool> onBoundary(vertexCount, false);
  std::size_t edgeCount = 0;
  for (std::size_t first = 0, last; first < halfEdges.size(); first = last) {
    last = first + 1;
    while (last < halfEdges.size() && halfEdges[last].edge() == halfEdges[first].edge()) ++last;
    ++edgeCount;
    const HalfEdge& a = halfEdges[first];
    if (last - first == 1) {
      boundarySets.join(a.from, a.to);
      onBoundary[a.from] = onBoundary[a.to] = true;
    } else if (last - first == 2 && halfEdges[first + 1].from == a.to) {
      const HalfEdge& b = halfEdges[first + 1];
      fanSets.join(a.corner, nextCorner(b.corner));  // both at a.from
      fanSets.join(nextCorner(a.corner), b.corner);  // both at a.to
    } else {
      topology.manifold = false;  // three or more triangles on the edge, or two in the same direction
    }
  }

  std::size_t vertices = 0, fans = 0;
  for (std::size_t v = 0; v < vertexCount; ++v) {
    if (!referenced[v]) continue;
    ++vertices;
    if (triangleSets.find(v) == v) ++topology.components;
    if (onBoundary[v] && boundarySets.find(v) == v) ++topology.boundaryLoops;
  }
  for (std::size_t c = 0; c < 3 * mesh.faceCount(); ++c) fans += fanSets.find(c) == c;
  if (fans != vertices) topology.manifold = false;
  topology.eulerCharacteristic = static_cast<long>(vertices) - static_cast<long>(edgeCount) +
                                 static_cast<long>(mesh.faceCount());
  return topology;
}

CutMesh cutAlongUvSeams(const Mesh& mesh, const UvMap& uv) {
  const std::size_t cornerCount = 3 * mesh.faceCount();
  UVTK_CHECK(uv.uv.size() == cornerCount && uv.faceFlags.size() == mesh.faceCount());
  UVTK_CHECK(uv.w.empty() || uv.w.size() == cornerCount);
  UVTK_CHECK(uv.cornerInvalid.empty() || uv.cornerInvalid.size() == cornerCount);
  constexpr double kTolerance = 1e-9;
  auto valid = [&](std::size_t c) {
    return !uv.faceHas(c / 3, kFaceInvalid) && (uv.cornerInvalid.empty() || uv.cornerInvalid[c] == 0);
  };
  auto sameUv = [&](std::size_t a, std::size_t b) {
    return (uv.uv[a] - uv.uv[b]).cwiseAbs().maxCoeff() <= kTolerance &&
           (uv.w.empty() || std::abs(uv.w[a] - uv.w[b]) <= kTolerance);
  };

  // Each original vertex keeps its index for the first corner on it; a corner that cannot share
  // a vertex already made for its original vertex gets a new one at the end. The new vertices of
  // each original vertex that valid corners may share form a linked list (newest first) through
  // `nextOfSameVertex`; each stands for the UV of the corner that took it.
  CutMesh cut;
  cut.mesh = mesh;  // keeps the per-corner attribute tables, which index corners, not vertices
  cut.vertexOf.resize(mesh.vertexCount());
  std::iota(cut.vertexOf.begin(), cut.vertexOf.end(), 0);
  std::vector<bool> taken(mesh.vertexCount(), false);
  std::vector<int> newestOf(mesh.vertexCount(), -1);
  std::vector<int> nextOfSameVertex(mesh.vertexCount(), -1);
  std::vector<std::size_t> takenBy(mesh.vertexCount());
  for (std::size_t c = 0; c < cornerCount; ++c) {
    const int original = mesh.triangles[c / 3][c % 3];
    int shared = -1;
    if (valid(c)) {
      for (int n = newestOf[original]; n >= 0 && shared < 0; n = nextOfSameVertex[n])
        if (sameUv(takenBy[n], c)) shared = n;
    }
    if (shared < 0) {
      if (!taken[original]) {
        shared = original;
        taken[original] = true;
      } else {
        shared = static_cast<int>(cut.mesh.positions.size());
        cut.mesh.positions.push_back(mesh.positions[original]);
        cut.vertexOf.push_back(original);
        nextOfSameVertex.push_back(-1);
        takenBy.emplace_back();
      }
      takenBy[shared] = c;
      if (valid(c)) {
        nextOfSameVertex[shared] = newestOf[original];
        newestOf[original] = shared;
      }
    }
    cut.mesh.triangles[c / 3][c % 3] = shared;
  }
  return cut;
}

}  // namespace uvtk::param
