// The cut graph of cut_graph.h on the flat index arrays: edges from sorted half-edges, a
// shortest-path tree, a maximal dual spanning tree, pruning, and the splitting of vertex fans.
#include "param/cut_graph.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <string>
#include <utility>

#include "core/disjoint_sets.h"
#include "core/error.h"

namespace uvtk::param {

namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

std::size_t nextCorner(std::size_t corner) { return corner - corner % 3 + (corner + 1) % 3; }

// An edge of a manifold mesh and its one or two triangle sides, each given by the corner it starts
// at (3 f + k); the second side runs the other way, so its corner lies on the first side's end.
struct Edge {
  int a, b;  // a < b
  std::size_t corner[2];  // corner[1] == kNone on the boundary
  bool interior() const { return corner[1] != kNone; }
};

[[noreturn]] void refuse(const std::string& why) { throw UsageError("cutToDisk: " + why); }

std::string edgeName(int a, int b) { return "edge (" + std::to_string(a) + ", " + std::to_string(b) + ")"; }

// The edges of the mesh, in the order of their vertex pairs; refuses a mesh with a triangle that
// repeats a vertex or an edge that is not the two opposite sides of two triangles or one side.
std::vector<Edge> manifoldEdges(const Mesh& mesh) {
  struct HalfEdge {
    int from, to;
    std::size_t corner;
    std::pair<int, int> edge() const { return {std::min(from, to), std::max(from, to)}; }
  };
  std::vector<HalfEdge> halfEdges;
  halfEdges.reserve(3 * mesh.faceCount());
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    const Triangle& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      if (t[k] == t[(k + 1) % 3])
        refuse("not manifold: triangle " + std::to_string(f) + " repeats vertex " + std::to_string(t[k]));
      halfEdges.push_back({t[k], t[(k + 1) % 3], 3 * f + static_cast<std::size_t>(k)});
    }
  }
  std::sort(halfEdges.begin(), halfEdges.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return std::make_pair(x.edge(), x.corner) < std::make_pair(y.edge(), y.corner);
  });

  std::vector<Edge> edges;
  for (std::size_t first = 0, last; first < halfEdges.size(); first = last) {
    const HalfEdge& h = halfEdges[first];
    last = first + 1;
    while (last < halfEdges.size() && halfEdges[last].edge() == h.edge()) ++last;
    Edge edge{h.edge().first, h.edge().second, {h.corner, kNone}};
    if (last - first > 2)
      refuse("not manifold: " + edgeName(edge.a, edge.b) + " has " + std::to_string(last - first) + " faces");
    if (last - first == 2) {
      if (halfEdges[first + 1].from != h.to)
        refuse("not manifold: " + edgeName(edge.a, edge.b) + " has two faces in the same direction");
      edge.corner[1] = halfEdges[first + 1].corner;
    }
    edges.push_back(edge);
  }
  return edges;
}

// The corners joined around their vertex across every interior edge that is not cut: one set per
// piece of each vertex's fan.
DisjointSets cornerFans(std::size_t cornerCount, const std::vector<Edge>& edges, const std::vector<bool>& cut) {
  DisjointSets fans(cornerCount);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!edges[e].interior() || cut[e]) continue;
    const std::size_t c0 = edges[e].corner[0], c1 = edges[e].corner[1];
    fans.join(c0, nextCorner(c1));  // both at the first side's start
    fans.join(nextCorner(c0), c1);  // both at its end
  }
  return fans;
}

// Refuses a vertex whose corners form several fans (two cones touching at their tips), the one
// way left for manifoldEdges' edges to make a mesh that is not manifold.
void requireSingleFans(const Mesh& mesh, const std::vector<Edge>& edges) {
  DisjointSets fans = cornerFans(3 * mesh.faceCount(), edges, std::vector<bool>(edges.size(), false));
  std::vector<std::size_t> fanOf(mesh.vertexCount(), kNone);
  for (std::size_t c = 0; c < 3 * mesh.faceCount(); ++c) {
    const int v = mesh.triangles[c / 3][c % 3];
    const std::size_t fan = fans.find(c);
    if (fanOf[v] == kNone) fanOf[v] = fan;
    if (fanOf[v] != fan) refuse("not manifold: vertex " + std::to_string(v) + " joins several fans");
  }
}

// The edges at each vertex: edges[begin[v] .. begin[v + 1]).
struct Incidence {
  std::vector<std::size_t> begin, edges;
};

Incidence incidence(std::size_t vertexCount, const std::vector<Edge>& edges) {
  Incidence in;
  in.begin.assign(vertexCount + 1, 0);
  for (const Edge& e : edges) ++in.begin[e.a + 1], ++in.begin[e.b + 1];
  std::partial_sum(in.begin.begin(), in.begin.end(), in.begin.begin());
  in.edges.resize(2 * edges.size());
  std::vector<std::size_t> next(in.begin.begin(), in.begin.end() - 1);
  for (std::size_t e = 0; e < edges.size(); ++e) in.edges[next[edges[e].a]++] = in.edges[next[edges[e].b]++] = e;
  return in;
}

double length(const Mesh& mesh, const Edge& e) { return (mesh.positions[e.a] - mesh.positions[e.b]).norm(); }

int otherEnd(const Edge& e, int v) { return e.a == v ? e.b : e.a; }

// The referenced vertex nearest the referenced vertices' centroid.
int centralVertex(const Mesh& mesh, const Incidence& in) {
  Vec3 sum = Vec3::Zero();
  std::size_t count = 0;
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
    if (in.begin[v + 1] > in.begin[v]) sum += mesh.positions[v], ++count;
  const Vec3 centroid = sum / static_cast<double>(count);
  int best = -1;
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    if (in.begin[v + 1] == in.begin[v]) continue;
    if (best < 0 || (mesh.positions[v] - centroid).squaredNorm() < (mesh.positions[best] - centroid).squaredNorm())
      best = static_cast<int>(v);
  }
  return best;
}

// Dijkstra's shortest-path tree from `sources`: each vertex's distance and the edges of the tree.
struct PathTree {
  std::vector<double> distance;  // per vertex
  std::vector<bool> inTree;      // per edge
};

PathTree shortestPathTree(const Mesh& mesh, const std::vector<Edge>& edges, const Incidence& in,
                          const std::vector<int>& sources) {
  PathTree tree{std::vector<double>(mesh.vertexCount(), std::numeric_limits<double>::infinity()),
                std::vector<bool>(edges.size(), false)};
  std::vector<std::size_t> parentEdge(mesh.vertexCount(), kNone);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (int s : sources) {
    tree.distance[s] = 0.0;
    queue.push({0.0, s});
  }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > tree.distance[v]) continue;
    for (std::size_t i = in.begin[v]; i < in.begin[v + 1]; ++i) {
      const std::size_t e = in.edges[i];
      const int w = otherEnd(edges[e], v);
      if (d + length(mesh, edges[e]) < tree.distance[w]) {
        tree.distance[w] = d + length(mesh, edges[e]);
        parentEdge[w] = e;
        queue.push({tree.distance[w], w});
      }
    }
  }
  for (std::size_t e : parentEdge)
    if (e != kNone) tree.inTree[e] = true;
  return tree;
}

// Per edge, whether the dual spanning tree crosses it: Kruskal over the interior edges outside
// the path tree, heaviest first, an edge weighing the loop it closes through the tree.
std::vector<bool> maximalDualTree(const Mesh& mesh, const std::vector<Edge>& edges, const PathTree& tree) {
  std::vector<double> loop(edges.size());
  std::vector<std::size_t> order;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!edges[e].interior() || tree.inTree[e]) continue;
    loop[e] = tree.distance[edges[e].a] + length(mesh, edges[e]) + tree.distance[edges[e].b];
    order.push_back(e);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return loop[x] > loop[y]; });
  std::vector<bool> crossed(edges.size(), false);
  DisjointSets faces(mesh.faceCount());
  std::size_t joins = 0;
  for (std::size_t e : order)
    if (faces.join(edges[e].corner[0] / 3, edges[e].corner[1] / 3)) crossed[e] = true, ++joins;
  // A tree hanging from a single base point, or from the boundary, separates no triangles.
  UVTK_CHECK(joins + 1 == mesh.faceCount());
  return crossed;
}

// Per edge, whether it is cut: the interior edges the dual tree does not cross, less the dangling
// branches. Boundary edges count towards a vertex's degree but are never cut or pruned, so the
// branches that join boundary loops stay. On a closed mesh the last two edges stay.
std::vector<bool> prunedCutGraph(std::size_t vertexCount, const std::vector<Edge>& edges, const Incidence& in,
                                 const std::vector<bool>& crossed, bool closed) {
  std::vector<bool> cut(edges.size(), false);
  std::vector<std::size_t> degree(vertexCount, 0);
  std::size_t remaining = 0;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (crossed[e]) continue;
    ++degree[edges[e].a], ++degree[edges[e].b];
    if (edges[e].interior()) cut[e] = true, ++remaining;
  }
  std::vector<int> leaves;
  for (std::size_t v = 0; v < vertexCount; ++v)
    if (degree[v] == 1) leaves.push_back(static_cast<int>(v));
  while (!leaves.empty() && (!closed || remaining > 2)) {
    const int v = leaves.back();
    leaves.pop_back();
    if (degree[v] != 1) continue;  // pruned to 0 since it was queued
    // Degree 1 means an interior vertex (a boundary vertex has two boundary edges): its edge is cut.
    std::size_t i = in.begin[v];
    while (!cut[in.edges[i]]) ++i;
    const std::size_t e = in.edges[i];
    cut[e] = false;
    --remaining;
    --degree[v];
    const int w = otherEnd(edges[e], v);
    if (--degree[w] == 1) leaves.push_back(w);
  }
  return cut;
}

// The mesh with every vertex split into the pieces of its fan between cut edges.
CutMesh cutAlong(const Mesh& mesh, const std::vector<Edge>& edges, const std::vector<bool>& cut) {
  DisjointSets fans = cornerFans(3 * mesh.faceCount(), edges, cut);
  CutMesh result;
  result.mesh = mesh;  // keeps the per-corner attribute tables, which index corners, not vertices
  result.vertexOf.resize(mesh.vertexCount());
  std::iota(result.vertexOf.begin(), result.vertexOf.end(), 0);
  std::vector<bool> taken(mesh.vertexCount(), false);
  std::vector<int> vertexOfFan(3 * mesh.faceCount(), -1);
  for (std::size_t c = 0; c < 3 * mesh.faceCount(); ++c) {
    const int original = mesh.triangles[c / 3][c % 3];
    int& vertex = vertexOfFan[fans.find(c)];
    if (vertex < 0 && !taken[original]) {
      vertex = original;
      taken[original] = true;
    } else if (vertex < 0) {
      vertex = static_cast<int>(result.mesh.positions.size());
      result.mesh.positions.push_back(mesh.positions[original]);
      result.vertexOf.push_back(original);
    }
    result.mesh.triangles[c / 3][c % 3] = vertex;
  }
  return result;
}

}  // namespace

CutMesh cutToDisk(const Mesh& mesh) {
  const Topology topology = analyzeTopology(mesh);
  if (topology.components != 1) refuse(std::to_string(topology.components) + " components");
  const std::vector<Edge> edges = manifoldEdges(mesh);
  if (!topology.manifold) requireSingleFans(mesh, edges);
  UVTK_CHECK(topology.manifold);

  const Incidence in = incidence(mesh.vertexCount(), edges);
  std::vector<int> sources;
  for (const Edge& e : edges)
    if (!e.interior()) sources.push_back(e.a), sources.push_back(e.b);
  const bool closed = sources.empty();
  if (closed) sources.push_back(centralVertex(mesh, in));

  const PathTree tree = shortestPathTree(mesh, edges, in, sources);
  const std::vector<bool> crossed = maximalDualTree(mesh, edges, tree);
  return cutAlong(mesh, edges, prunedCutGraph(mesh.vertexCount(), edges, in, crossed, closed));
}

}  // namespace uvtk::param
