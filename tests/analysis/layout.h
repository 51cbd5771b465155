// Hand-made meshes with per-corner UVs for the analysis tests.
#pragma once

#include <utility>
#include <vector>

#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk::analysis {

// A mesh and per-corner UVs, every corner valid and no face flagged.
struct Layout {
  Mesh mesh;
  UvMap uv;

  // A triangle of its own three vertices, mapped to (ua, ub, uc).
  void add(const Vec3& a, const Vec3& b, const Vec3& c, const Vec2& ua, const Vec2& ub, const Vec2& uc) {
    const int first = int(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, b, c});
    mesh.triangles.push_back({first, first + 1, first + 2});
    uv.uv.insert(uv.uv.end(), {ua, ub, uc});
    uv.faceFlags.push_back(kFaceOk);
    uv.cornerInvalid.insert(uv.cornerInvalid.end(), {0, 0, 0});
  }
};

inline Layout makeLayout(std::vector<Vec3> positions, std::vector<Triangle> triangles, std::vector<Vec2> uvs) {
  Layout l;
  l.mesh.positions = std::move(positions);
  l.mesh.triangles = std::move(triangles);
  l.uv.uv = std::move(uvs);
  l.uv.faceFlags.assign(l.mesh.triangles.size(), kFaceOk);
  l.uv.cornerInvalid.assign(l.uv.uv.size(), 0);
  return l;
}

}  // namespace uvtk::analysis
