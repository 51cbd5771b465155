// PLY output: vertices split where per-corner UVs (or normals) differ, `s t` per vertex.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk::io {

struct PlyWriteOptions {
  bool ascii = false;  // `format ascii 1.0`; else binary_little_endian
  std::string header;  // comment lines written first in the header, each prefixed with "comment "
  // Normals per mesh vertex (nx ny nz / NORMAL), written when the mesh has none of its own; null: none.
  const std::vector<Vec3>* vertexNormals = nullptr;
};

void writePly(std::ostream& out, const Mesh& mesh, const UvMap* uvs, const PlyWriteOptions& options = {});

}  // namespace uvtk::io
