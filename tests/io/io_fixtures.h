// Small meshes and texts shared by the io tests.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk::io {

// Three vertices of an OBJ, lines 1-3.
inline const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

// Two triangles sharing the edge 0-2, not in one plane.
inline Mesh twoTriangles() {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.5}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

// Per-corner UVs, every corner valid and every face ok.
inline UvMap uvsOf(std::vector<Vec2> uv) {
  UvMap map;
  map.faceFlags.assign(uv.size() / 3, kFaceOk);
  map.cornerInvalid.assign(uv.size(), kCornerValid);
  map.uv = std::move(uv);
  return map;
}

}  // namespace uvtk::io
