// Vertices split where the corners meeting at a vertex disagree: what a format with one
// attribute set per vertex (glTF, PLY, OBJ's vt numbering) needs to keep per-corner UVs.
#pragma once

#include <cstddef>
#include <vector>

#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk::io {

struct SplitVertexKey {
  const UvMap* uvs = nullptr;  // split where the written (u, v) differ (UvMap::writtenUv), bit for bit (-0 and +0 apart); null: no UVs
  bool w = false;              // ... and where the UvMap's third component differs
  bool normals = false;        // ... and where the mesh's per-corner normal index differs
};

struct SplitVertices {
  // Per split vertex, in mesh vertex order, then by the first corner (in corner order) that has it:
  std::vector<int> vertex;          // the mesh vertex it is a copy of
  std::vector<std::size_t> corner;  // the first corner (3 f + k) that uses it: its UV and normal are this corner's
  // Per corner (3 f + k): the split vertex it uses. Corners of one split vertex agree on every key.
  std::vector<int> ofCorner;

  std::size_t size() const { return vertex.size(); }
};

// Splits every vertex into one copy per distinct key among its corners. A vertex no face uses
// gets no copy. Linear time: corners bucketed by vertex (a counting sort), each vertex's few
// distinct keys found by a scan; on `threads` threads (0: all, core/parallel.h), each taking a
// range of vertices, with the same result whatever their number.
SplitVertices splitVertices(const Mesh& mesh, const SplitVertexKey& key, int threads = 0);

}  // namespace uvtk::io
