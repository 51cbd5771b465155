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
