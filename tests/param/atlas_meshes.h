// Meshes of every kind the atlas must handle, beside the generators' like-real ones: a spiral
// ramp that overlaps itself under any one projection, open, non-manifold, many components,
// slivers, mixed winding, far, tiny and huge. Shared by the atlas's geometry and verdict tests.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "meshes/generators.h"

namespace uvtk::test {

// Appends `part` to `mesh`.
inline void appendMesh(Mesh& mesh, const Mesh& part) {
  const int base = int(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
  for (Triangle t : part.triangles) mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

inline Mesh transformed(Mesh mesh, double scale, const Vec3& offset) {
  for (Vec3& p : mesh.positions) p = scale * p + offset;
  return mesh;
}

// A helicoid strip: `turns` turns of a ramp from radius r0 to r1 rising `rise` a turn. Seen along
// its axis every turn covers the one below: one planar projection overlaps itself.
inline Mesh spiralRamp(int turns, int segmentsPerTurn, double r0, double r1, double rise) {
  Mesh m;
  const int n = turns * segmentsPerTurn;
  for (int i = 0; i <= n; ++i) {
    const double a = 2.0 * M_PI * i / segmentsPerTurn, z = rise * i / segmentsPerTurn;
    m.positions.emplace_back(r0 * std::cos(a), r0 * std::sin(a), z);
    m.positions.emplace_back(r1 * std::cos(a), r1 * std::sin(a), z);
  }
  for (int i = 0; i < n; ++i) {
    const int a = 2 * i, b = a + 1, c = a + 2, d = a + 3;
    m.triangles.push_back({a, b, d});
    m.triangles.push_back({a, d, c});
  }
  return m;
}

// A grid with every third cell missing: an open surface with many holes.
inline Mesh holedGrid(int n) {
  Mesh grid = meshes::planeGrid(n, n, 1.0, 1.0);
  Mesh m;
  m.positions = grid.positions;
  for (std::size_t f = 0; f < grid.triangles.size(); ++f)
    if ((f / 2) % 3 != 1) m.triangles.push_back(grid.triangles[f]);
  return m;
}

// Three quads sharing one edge (a book of three pages) and two cubes touching at a corner.
inline Mesh nonManifold() {
  Mesh m;
  m.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {1, 0, 1}, {-1, 0.2, 0}, {-1, 0.2, 1}, {0.1, 1, 0}, {0.1, 1, 1}};
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {0, 1, 5}, {0, 5, 4}, {0, 6, 7}, {0, 7, 1}};
  appendMesh(m, transformed(meshes::cube(1), 0.5, Vec3(3, 0, 0)));
  appendMesh(m, transformed(meshes::cube(1), 0.5, Vec3(4, 1, 1)));
  return m;
}

// A grid whose every other row is squashed to nearly nothing: slivers, and faces of zero area.
inline Mesh slivers(int n) {
  Mesh m = meshes::planeGrid(n, n, 1.0, 1.0);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const int row = int(i) / (n + 1);
    if (row % 2 == 1) m.positions[i].y() = m.positions[i - std::size_t(n + 1)].y() + (row % 4 == 1 ? 1e-9 : 0.0);
  }
  return m;
}

// Every other face wound the wrong way round.
inline Mesh mixedWinding(Mesh m) {
  for (std::size_t f = 0; f < m.triangles.size(); f += 2) std::swap(m.triangles[f][1], m.triangles[f][2]);
  return m;
}

// Many small closed components side by side.
inline Mesh manyComponents(int count) {
  Mesh m;
  for (int i = 0; i < count; ++i) appendMesh(m, transformed(meshes::icosphere(1), 0.3, Vec3(i % 10, i / 10, 0.1 * i)));
  return m;
}

// A mesh with the name a failing test prints.
struct NamedMesh {
  std::string name;
  Mesh mesh;
};

// Twenty-odd meshes of every kind: the generators' bundled and like-real meshes, and the above.
inline std::vector<NamedMesh> atlasMeshes() {
  std::vector<NamedMesh> out;
  for (const meshes::BundledMesh& b : meshes::bundledMeshes()) out.push_back({b.file, b.mesh});
  out.push_back({"torus_knot_2_3", meshes::torusKnot(2, 3, 256, 16)});
  out.push_back({"torus_knot_3_5", meshes::torusKnot(3, 5, 300, 12, 0.25)});
  out.push_back({"bone", meshes::bone(120, 32)});
  out.push_back({"scanned_patch", meshes::scannedPatch(4)});
  out.push_back({"bumpy_blob", meshes::bumpyBlob(4)});
  out.push_back({"spiral_ramp", spiralRamp(4, 48, 0.5, 1.5, 0.3)});
  out.push_back({"long_thin_cylinder", meshes::cylinder(24, 200, 0.01, 20.0, true)});
  out.push_back({"holed_grid", holedGrid(30)});
  out.push_back({"non_manifold", nonManifold()});
  out.push_back({"slivers", slivers(20)});
  out.push_back({"mixed_winding_torus", mixedWinding(meshes::torus(48, 24, 1.0, 0.3))});
  out.push_back({"many_components", manyComponents(60)});
  out.push_back({"far_from_origin", transformed(meshes::bumpyBlob(3), 1.0, Vec3(1e6, -2e6, 3e5))});
  out.push_back({"tiny", transformed(meshes::torusKnot(2, 3, 128, 12), 1e-6, Vec3::Zero())});
  out.push_back({"huge", transformed(meshes::bone(48, 24), 1e6, Vec3::Zero())});
  out.push_back({"fine_sphere", meshes::latLongSphere(200, 100)});
  return out;
}

}  // namespace uvtk::test
