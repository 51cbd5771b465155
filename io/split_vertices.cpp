#include "io/split_vertices.h"

#include <climits>
#include <cstring>

#include "core/error.h"

namespace uvtk::io {
namespace {

// Bitwise equality, so that -0 and +0 (and NaNs of different payloads) never merge silently.
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

SplitVertices splitVertices(const Mesh& mesh, const SplitVertexKey& key) {
  const std::size_t corners = 3 * mesh.triangles.size();
  const UvMap* uvs = key.uvs;
  UVTK_CHECK(!uvs || uvs->uv.size() == corners);
  const bool useW = key.w && uvs && !uvs->w.empty();
  const bool useNormals = key.normals && mesh.hasNormals();
  const auto vertexOf = [&](std::size_t c) { return mesh.triangles[c / 3][c % 3]; };
  const auto sameKey = [&](std::size_t a, std::size_t b) {
    if (uvs && !(sameBits(uvs->uv[a].x(), uvs->uv[b].x()) && sameBits(uvs->uv[a].y(), uvs->uv[b].y()))) return false;
    if (useW && !sameBits(uvs->w[a], uvs->w[b])) return false;
    return !useNormals || mesh.cornerNormals[a / 3][a % 3] == mesh.cornerNormals[b / 3][b % 3];
  };

  const std::size_t vertexCount = mesh.positions.size();
  std::vector<std::size_t> firstOfVertex(vertexCount + 1, 0), byVertex(corners);
  for (std::size_t c = 0; c < corners; ++c) ++firstOfVertex[vertexOf(c) + 1];
  for (std::size_t v = 0; v < vertexCount; ++v) firstOfVertex[v + 1] += firstOfVertex[v];
  {
    std::vector<std::size_t> next(firstOfVertex.begin(), firstOfVertex.end() - 1);
    for (std::size_t c = 0; c < corners; ++c) byVertex[next[vertexOf(c)]++] = c;
  }

  SplitVertices split;
  split.ofCorner.resize(corners);
  for (std::size_t v = 0; v < vertexCount; ++v) {
    const std::size_t begin = firstOfVertex[v], end = firstOfVertex[v + 1];
    for (std::size_t i = begin; i < end; ++i) {
      const std::size_t c = byVertex[i];
      std::size_t same = begin;  // an earlier corner of this vertex with the same key, if any
      while (same < i && !sameKey(byVertex[same], c)) ++same;
      if (same < i) {
        split.ofCorner[c] = split.ofCorner[byVertex[same]];
        continue;
      }
      UVTK_CHECK(split.vertex.size() < static_cast<std::size_t>(INT_MAX));
      split.ofCorner[c] = static_cast<int>(split.vertex.size());
      split.vertex.push_back(static_cast<int>(v));
      split.corner.push_back(c);
    }
  }
  return split;
}

}  // namespace uvtk::io
