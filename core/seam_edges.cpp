#include "core/seam_edges.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <utility>

#include "core/error.h"
#include "core/math.h"
#include "core/huge_pages.h"

namespace uvtk {

namespace {

constexpr double kUvTolerance = 1e-6;

bool cornerValid(const UvMap& uv, std::size_t corner) {
  return uv.cornerInvalid.empty() || uv.cornerInvalid[corner] == 0;
}

// The distance of x from the nearest integer.
double offInteger(double x) { return std::fabs(x - std::round(x)); }

// One side of an edge: the face, and its corners at the edge's lower and higher vertex.
struct HalfEdge {
  int lower, higher;  // vertices (through the stand-ins, when there are any), lower <= higher
  std::size_t cornerLower, cornerHigher;  // indices into uv.uv
  std::size_t corner;                     // the corner it leaves: cornerLower or cornerHigher
};

// The vertex that stands for v: itself when `standIn` is empty.
int standInOf(const std::vector<int>& standIn, int v) { return standIn.empty() ? v : standIn[std::size_t(v)]; }

// The half-edge leaving corner c = 3 f + k of face f (towards corner k + 1).
HalfEdge halfEdge(const Mesh& mesh, const std::vector<int>& standIn, std::size_t c) {
  const std::size_t f = c / 3, k = c % 3, next = (k + 1) % 3;
  HalfEdge e{standInOf(standIn, mesh.triangles[f][int(k)]), standInOf(standIn, mesh.triangles[f][int(next)]), c,
             3 * f + next, c};
  if (e.lower > e.higher) std::swap(e.lower, e.higher), std::swap(e.cornerLower, e.cornerHigher);
  return e;
}

// Every face's three half-edges, named by the corner each leaves, grouped by their lower vertex
// (a counting sort: linear where a comparison sort of 3 F half-edges is not): v's are
// order[v == 0 ? 0 : end[v - 1], end[v]). 4 bytes a half-edge (with a key each, 4 M faces took 96
// MB instead of 48).
struct HalfEdgesByLowerVertex {
  std::vector<std::uint32_t> order, end;
  std::uint32_t begin(std::size_t v) const { return v == 0 ? 0 : end[v - 1]; }
};

HalfEdgesByLowerVertex halfEdgesByLowerVertex(const Mesh& mesh, const std::vector<int>& standIn) {
  const std::size_t corners = 3 * mesh.triangles.size();
  UVTK_CHECK(corners <= std::numeric_limits<std::uint32_t>::max());
  HalfEdgesByLowerVertex h;
  // end[v + 1] counts v's half-edges; summed, end[v] is where v's start; placing them moves it to
  // where they end.
  h.end.assign(mesh.positions.size() + 1, 0);
  for (std::size_t c = 0; c < corners; ++c) ++h.end[std::size_t(halfEdge(mesh, standIn, c).lower) + 1];
  for (std::size_t v = 1; v < h.end.size(); ++v) h.end[v] += h.end[v - 1];
  resizeFaultedIn(h.order, corners);
  for (std::size_t c = 0; c < corners; ++c) h.order[h.end[std::size_t(halfEdge(mesh, standIn, c).lower)]++] = std::uint32_t(c);
  h.end.pop_back();
  return h;
}

// Stand-ins for `vertices` (any order, repeats allowed): each one at the position of a
// lower-numbered one of them (equal coordinates) stands in for by the lowest such; every other
// vertex of the mesh for itself. Empty when no two of them share a position.
std::vector<int> standInsByPosition(const Mesh& mesh, std::vector<int> vertices) {
  std::sort(vertices.begin(), vertices.end(), [&](int a, int b) {
    const Vec3 &p = mesh.positions[std::size_t(a)], &q = mesh.positions[std::size_t(b)];
    return std::tie(p.x(), p.y(), p.z(), a) < std::tie(q.x(), q.y(), q.z(), b);
  });
  std::vector<int> standIn;
  for (std::size_t i = 1, first = 0; i < vertices.size(); ++i) {
    const int v = vertices[i], lowest = vertices[first];
    if (v == vertices[i - 1]) continue;
    if (mesh.positions[std::size_t(v)] != mesh.positions[std::size_t(lowest)]) {
      first = i;
      continue;
    }
    if (standIn.empty()) {
      standIn.resize(mesh.positions.size());
      for (std::size_t u = 0; u < standIn.size(); ++u) standIn[u] = int(u);
    }
    standIn[std::size_t(v)] = lowest;
  }
  return standIn;
}

// seamEdgeList with the vertices taken through `standIn`; the vertices of the edges that only
// one face has are added to `boundary` when it is given.
std::vector<SeamEdge> seamEdgesThrough(const Mesh& mesh, const UvMap& uv, const std::vector<int>& standIn,
                                       std::vector<int>* boundary) {
  std::vector<char> isPole(mesh.positions.size(), 0);
  for (std::size_t corner = 0; corner < uv.cornerPole.size(); ++corner)
    if (uv.cornerPole[corner] != 0) isPole[std::size_t(standInOf(standIn, mesh.triangles[corner / 3][corner % 3]))] = 1;

  // Two corners of a vertex differ beyond kUvTolerance times the layout's extent: UVs in object
  // units, 1e-3 or 1e3 wide, cut where a unit layout cuts (the wrap tests stay in units of the period).
  Bounds2 box;
  for (std::size_t corner = 0; corner < uv.uv.size(); ++corner)
    if (cornerValid(uv, corner) && uv.uv[corner].allFinite()) box.extend(uv.uv[corner]);
  const double extent = box.lowX > box.highX ? 0.0 : std::max(box.highX - box.lowX, box.highY - box.lowY);
  const double cutTolerance = kUvTolerance * (extent > 0.0 && std::isfinite(extent) ? extent : 1.0);

  // Each vertex's half-edges, ordered by (higher vertex, corner), so that the sides of one edge
  // are adjacent; each made once (its face read once, where it lies in memory).
  const HalfEdgesByLowerVertex byLower = halfEdgesByLowerVertex(mesh, standIn);
  std::vector<SeamEdge> seams;
  std::vector<HalfEdge> sides;  // one vertex's
  for (std::size_t v = 0; v < byLower.end.size(); ++v) {
    sides.clear();
    for (std::uint32_t i = byLower.begin(v); i < byLower.end[v]; ++i)
      sides.push_back(halfEdge(mesh, standIn, byLower.order[i]));
    std::sort(sides.begin(), sides.end(), [](const HalfEdge& a, const HalfEdge& b) {
      return std::pair(a.higher, a.corner) < std::pair(b.higher, b.corner);
    });
    for (std::size_t first = 0, end; first < sides.size(); first = end) {
      // The sides of one edge: the same lower and higher vertex.
      const HalfEdge& a = sides[first];
      end = first + 1;
      while (end < sides.size() && sides[end].higher == a.higher) ++end;
      if (a.lower == a.higher) continue;  // two corners of one face at one vertex: no edge
      if (end - first == 1 && boundary) boundary->insert(boundary->end(), {a.lower, a.higher});
      if (end - first != 2) continue;  // a boundary or non-manifold edge
      const HalfEdge& b = sides[first + 1];
      if (!cornerValid(uv, a.cornerLower) || !cornerValid(uv, a.cornerHigher) || !cornerValid(uv, b.cornerLower) ||
          !cornerValid(uv, b.cornerHigher))
        continue;
      const std::pair<int, Vec2> differences[2] = {{a.lower, uv.uv[a.cornerLower] - uv.uv[b.cornerLower]},
                                                   {a.higher, uv.uv[a.cornerHigher] - uv.uv[b.cornerHigher]}};
      bool compared = false, differs = false, wraps = true;
      double shift = 0.0;  // the integer u offset of the first compared endpoint
      for (const auto& [vertex, d] : differences) {
        if (isPole[static_cast<std::size_t>(vertex)]) continue;
        differs = differs || std::fabs(d.x()) > cutTolerance || std::fabs(d.y()) > cutTolerance;
        const bool integerShift =
            std::fabs(d.x()) > 0.5 && offInteger(d.x()) <= kUvTolerance && std::fabs(d.y()) <= kUvTolerance;
        if (!compared) shift = std::round(d.x());
        wraps = wraps && integerShift && std::round(d.x()) == shift;
        compared = true;
      }
      if (!compared || !differs) continue;
      seams.push_back({a.lower, a.higher, {a.cornerLower, b.cornerLower}, {a.cornerHigher, b.cornerHigher}, wraps});
    }
  }
  return seams;
}

}  // namespace

std::vector<int> fannedPoleVertices(const Mesh& mesh, const UvMap& uv) {
  UVTK_CHECK(uv.uv.size() == 3 * mesh.triangles.size() && uv.faceFlags.size() == mesh.triangles.size());
  // A pole split into a vertex per face (a PLY or glTF) is one pole: its copies meet at one position.
  std::vector<int> poleFaceVertices;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    if (uv.faceHas(f, kFacePole)) poleFaceVertices.insert(poleFaceVertices.end(), mesh.triangles[f].begin(), mesh.triangles[f].end());
  if (poleFaceVertices.empty()) return {};
  const std::vector<int> standIn = standInsByPosition(mesh, std::move(poleFaceVertices));
  enum : std::uint8_t { kUnseen, kSeen, kPole };
  std::vector<std::uint8_t> state(mesh.positions.size(), kUnseen);
  std::vector<double> firstU(mesh.positions.size(), 0.0);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (!uv.faceHas(f, kFacePole)) continue;
    for (int k = 0; k < 3; ++k) {
      const std::size_t corner = 3 * f + static_cast<std::size_t>(k);
      const auto v = static_cast<std::size_t>(standInOf(standIn, mesh.triangles[f][k]));
      if (!cornerValid(uv, corner)) continue;
      const double u = uv.uv[corner].x();
      if (state[v] == kUnseen) state[v] = kSeen, firstU[v] = u;
      // Any two of the vertex's u values differ by a non-integer exactly when one differs so from the first.
      else if (offInteger(u - firstU[v]) > kUvTolerance) state[v] = kPole;
    }
  }
  std::vector<int> poles;
  for (std::size_t v = 0; v < state.size(); ++v)
    if (state[v] == kPole) poles.push_back(static_cast<int>(v));
  return poles;
}

void markFannedPoles(const Mesh& mesh, UvMap& uv) {
  const std::vector<int> poles = fannedPoleVertices(mesh, uv);
  if (poles.empty()) return;
  std::vector<char> isPole(mesh.positions.size(), 0);
  for (int v : poles) isPole[std::size_t(v)] = 1;
  uv.cornerPole.assign(uv.uv.size(), 0);
  for (std::size_t corner = 0; corner < uv.cornerPole.size(); ++corner)
    uv.cornerPole[corner] = isPole[std::size_t(mesh.triangles[corner / 3][corner % 3])];
}

std::vector<int> poleVerticesOf(const Mesh& mesh, const UvMap& uv) {
  if (uv.cornerPole.empty()) return {};
  UVTK_CHECK(uv.cornerPole.size() == 3 * mesh.triangles.size());
  std::vector<char> isPole(mesh.positions.size(), 0);
  for (std::size_t corner = 0; corner < uv.cornerPole.size(); ++corner)
    if (uv.cornerPole[corner] != 0) isPole[std::size_t(mesh.triangles[corner / 3][corner % 3])] = 1;
  std::vector<int> poles;
  for (std::size_t v = 0; v < isPole.size(); ++v)
    if (isPole[v]) poles.push_back(int(v));
  return poles;
}

std::vector<SeamEdge> seamEdgeList(const Mesh& mesh, const UvMap& uv) {
  UVTK_CHECK(uv.uv.size() == 3 * mesh.triangles.size());
  UVTK_CHECK(uv.cornerPole.empty() || uv.cornerPole.size() == uv.uv.size());
  std::vector<int> boundary;
  std::vector<SeamEdge> seams = seamEdgesThrough(mesh, uv, {}, &boundary);
  // A file split at its seams (PLY, glTF: io/split_vertices.h) has them as boundary edges whose
  // vertices repeat positions; welded there, they are edges of two faces again.
  const std::vector<int> standIn = standInsByPosition(mesh, std::move(boundary));
  if (standIn.empty()) return seams;
  return seamEdgesThrough(mesh, uv, standIn, nullptr);
}

SeamEdges classifySeamEdges(const Mesh& mesh, const UvMap& uv) {
  SeamEdges seams;
  for (const SeamEdge& e : seamEdgeList(mesh, uv)) {
    const double length = (mesh.positions[e.a] - mesh.positions[e.b]).stableNorm();  // norm() squares 1e200 to inf
    if (e.wrap) ++seams.wrapEdges, seams.wrapLength += length;
    else ++seams.cutEdges, seams.cutLength += length;
  }
  return seams;
}

}  // namespace uvtk
