// Cutting closed and multiply bounded meshes into one disk: the topology of the result, its
// correspondence with the input, the vertex count an independent count predicts, LSCM and ARAP
// on the result, and the refusals.
#include "param/cut_graph.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "meshes/generators.h"
#include "param/baseline.h"

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

using EdgeKey = std::pair<int, int>;

EdgeKey key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// How many triangles have each edge.
std::map<EdgeKey, int> edgeUses(const Mesh& mesh) {
  std::map<EdgeKey, int> uses;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++uses[key(t[k], t[(k + 1) % 3])];
  return uses;
}

// What the cut did, counted from the two meshes alone: the input's interior edges that became
// boundary, the vertices on them or on the input's boundary, and the boundary of the result.
struct CutCount {
  std::size_t cutEdges = 0;         // E_c
  std::size_t graphVertices = 0;    // V_G: vertices of the cut edges and of the input's boundary
  std::size_t inputBoundary = 0;    // boundary edges of the input
  std::size_t outputBoundary = 0;   // boundary edges of the result
};

CutCount countCut(const Mesh& mesh, const CutMesh& cut) {
  const std::map<EdgeKey, int> before = edgeUses(mesh), after = edgeUses(cut.mesh);
  CutCount count;
  std::set<EdgeKey> cutEdges;
  std::set<int> graphVertices;
  for (const auto& [edge, uses] : before) {
    if (uses != 1) continue;
    ++count.inputBoundary;
    graphVertices.insert({edge.first, edge.second});
  }
  for (const auto& [edge, uses] : after) {
    if (uses != 1) continue;
    ++count.outputBoundary;
    const EdgeKey original = key(cut.vertexOf[edge.first], cut.vertexOf[edge.second]);
    if (before.at(original) == 2) cutEdges.insert(original);
  }
  for (const EdgeKey& edge : cutEdges) graphVertices.insert({edge.first, edge.second});
  count.cutEdges = cutEdges.size();
  count.graphVertices = graphVertices.size();
  return count;
}

struct Case {
  const char* name;
  Mesh (*make)();
};

const Case kCases[] = {
    {"icosphere", [] { return meshes::icosphere(2); }},
    {"torus", [] { return meshes::torus(24, 12, 1.0, 0.3); }},
    {"torusKnot", [] { return meshes::torusKnot(2, 3, 120, 10); }},
    {"bone", [] { return meshes::bone(40, 16); }},
    {"bumpyBlob", [] { return meshes::bumpyBlob(3); }},
    // Level 2: at levels 3 and 4 the patch has vertices where two fans touch, which cutToDisk refuses.
    {"scannedPatch", [] { return meshes::scannedPatch(4); }},
    {"openCylinder", [] { return meshes::cylinder(16, 4, 1.0, 2.0, false); }},
    {"cube", [] { return meshes::cube(2); }},
};

class CutToDisk : public testing::TestWithParam<Case> {};

TEST_P(CutToDisk, GivesADiskWithTheSameTrianglesOnCopiesOfTheSameVertices) {
  const Mesh mesh = GetParam().make();
  const CutMesh cut = cutToDisk(mesh);

  EXPECT_TRUE(analyzeTopology(cut.mesh).isDisk());
  ASSERT_EQ(cut.mesh.faceCount(), mesh.faceCount());
  ASSERT_EQ(cut.vertexOf.size(), cut.mesh.vertexCount());
  std::vector<bool> seen(mesh.vertexCount(), false);
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int original = mesh.triangles[f][k], vertex = cut.mesh.triangles[f][k];
      ASSERT_EQ(cut.vertexOf[vertex], original) << "corner " << k << " of triangle " << f;
      EXPECT_EQ(cut.mesh.positions[vertex], mesh.positions[original]);
      if (!seen[original]) {
        EXPECT_EQ(vertex, original) << "the first corner keeps the index";
      }
      seen[original] = true;
    }
  }
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) ASSERT_EQ(cut.vertexOf[v], static_cast<int>(v));
}

TEST_P(CutToDisk, AddsTheVerticesThatCountingTheCutPredicts) {
  const Mesh mesh = GetParam().make();
  const CutMesh cut = cutToDisk(mesh);
  const CutCount count = countCut(mesh, cut);
  const long chi = analyzeTopology(mesh).eulerCharacteristic;

  // Each cut edge becomes two boundary edges.
  EXPECT_EQ(count.outputBoundary, count.inputBoundary + 2 * count.cutEdges);
  // Locally: a vertex of the graph (cut plus boundary) splits into as many vertices as the result's
  // boundary passes through it, so V_disk = V - V_G + boundary length.
  EXPECT_EQ(cut.mesh.vertexCount(), mesh.vertexCount() - count.graphVertices + count.outputBoundary);
  // Globally: Euler characteristic 1 after adding E_c edges.
  EXPECT_EQ(static_cast<long>(cut.mesh.vertexCount() - mesh.vertexCount()),
            static_cast<long>(count.cutEdges) + 1 - chi);
  if (count.inputBoundary == 0) {
    // A connected cut graph of a closed genus-g mesh has 2g independent cycles.
    EXPECT_EQ(static_cast<long>(count.cutEdges) - static_cast<long>(count.graphVertices) + 1, 2 - chi);
  }
}

INSTANTIATE_TEST_SUITE_P(SampleMeshes, CutToDisk, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<Case>& row) { return std::string(row.param.name); });

TEST(CutToDisk, LeavesADiskAsItIs) {
  for (const Mesh& mesh : {meshes::scannedPatch(4), meshes::planeGrid(8, 5, 2.0, 1.0)}) {
    const CutMesh cut = cutToDisk(mesh);
    EXPECT_EQ(cut.mesh.triangles, mesh.triangles);
    EXPECT_EQ(cut.mesh.vertexCount(), mesh.vertexCount());
  }
}

TEST(CutToDisk, OpensAClosedGenusZeroMeshAlongTwoEdges) {
  for (const Mesh& mesh : {meshes::icosphere(2), meshes::bone(40, 16), meshes::cube(2)}) {
    const CutMesh cut = cutToDisk(mesh);
    EXPECT_EQ(countCut(mesh, cut).cutEdges, 2u);
    EXPECT_EQ(cut.mesh.vertexCount(), mesh.vertexCount() + 1);
  }
}

TEST(CutToDisk, JoinsTheTwoBoundaryLoopsOfAnOpenCylinderAlongOneArc) {
  const Mesh mesh = meshes::cylinder(16, 4, 1.0, 2.0, false);
  const CutMesh cut = cutToDisk(mesh);
  // The shortest arc between the rims runs straight up: 4 stacks.
  EXPECT_EQ(countCut(mesh, cut).cutEdges, 4u);
}

TEST(CutToDisk, CutsATorusAlongItsShortestLoopsThroughTheBasePoint) {
  const Mesh mesh = meshes::torus(24, 12, 1.0, 0.3);
  const CutMesh cut = cutToDisk(mesh);
  // One circle around the tube (12 edges) and the inner equator (24 edges), the base point's two
  // greedy loops.
  EXPECT_EQ(countCut(mesh, cut).cutEdges, 36u);
}

TEST(CutToDisk, LetsLscmAndArapParameterizeATorusAndATorusKnot) {
  for (const Mesh& mesh : {meshes::torus(24, 12, 1.0, 0.3), meshes::torusKnot(2, 3, 120, 10)}) {
    const CutMesh cut = cutToDisk(mesh);
    for (Baseline baseline : {Baseline::Lscm, Baseline::Arap}) {
      SCOPED_TRACE(toString(baseline));
      const UvMap uv = parameterizeDisk(cut.mesh, baseline);
      ASSERT_EQ(uv.uv.size(), 3 * mesh.faceCount());
      for (const Vec2& p : uv.uv) ASSERT_TRUE(std::isfinite(p.x()) && std::isfinite(p.y()));
    }
  }
}

// The message of the UsageError cutToDisk throws on `mesh`.
std::string refusal(const Mesh& mesh) {
  try {
    cutToDisk(mesh);
  } catch (const UsageError& error) {
    return error.what();
  }
  return "no UsageError";
}

TEST(CutToDisk, RefusesSeveralComponents) {
  Mesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(5, 0, 0), Vec3(6, 0, 0), Vec3(5, 1, 0)};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  EXPECT_EQ(refusal(mesh), "cutToDisk: 2 components");
}

TEST(CutToDisk, RefusesAnEdgeOfThreeTriangles) {
  Mesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1)};
  mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  EXPECT_EQ(refusal(mesh), "cutToDisk: not manifold: edge (0, 1) has 3 faces");
}

TEST(CutToDisk, RefusesTwoClosedSurfacesTouchingAtAVertex) {
  // Two tetrahedra sharing vertex 0: every edge has two opposite sides, but vertex 0 has two fans.
  Mesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1),
                    Vec3(-1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, -1)};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3},
                    {0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6}};
  EXPECT_EQ(refusal(mesh), "cutToDisk: not manifold: vertex 0 joins several fans");
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param
