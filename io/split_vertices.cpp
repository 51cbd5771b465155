#include "io/split_vertices.h"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstring>

#include "core/error.h"
#include "core/huge_pages.h"
#include "core/parallel.h"

namespace uvtk::io {
namespace {

// Bitwise equality, so that -0 and +0 (and NaNs of different payloads) never merge silently.
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The corners are sorted by vertex on up to this many threads, each with a count per vertex.
constexpr int kMaxParts = 4;

// `Index` holds a corner number: 32 bits whenever they suffice, which halves the sort's memory.
template <typename Index>
SplitVertices split(const Mesh& mesh, const SplitVertexKey& key, int threads) {
  const std::size_t corners = 3 * mesh.triangles.size();
  const UvMap* uvs = key.uvs;
  const bool useW = key.w && uvs && !uvs->w.empty();
  const bool useNormals = key.normals && mesh.hasNormals();
  const int* vertexOf = mesh.triangles.empty() ? nullptr : mesh.triangles.data()->data();  // corner c: vertexOf[c]
  const auto sameKey = [&](std::size_t a, std::size_t b) {
    if (uvs) {
      const Vec2 p = uvs->writtenUv(a), q = uvs->writtenUv(b);
      if (!(sameBits(p.x(), q.x()) && sameBits(p.y(), q.y()))) return false;
    }
    if (useW && !sameBits(uvs->w[a], uvs->w[b])) return false;
    return !useNormals || mesh.cornerNormals[a / 3][a % 3] == mesh.cornerNormals[b / 3][b % 3];
  };

  const std::size_t vertexCount = mesh.positions.size();
  const int parts = corners < (std::size_t{1} << 16) ? 1 : std::min(threadCount(threads), kMaxParts);
  const auto partBegin = [&](int p) { return corners * std::size_t(p) / std::size_t(parts); };

  // The counting sort, its corners split into parts in corner order: at[p][v] counts the corners of
  // vertex v in part p, then becomes where the next of them goes in byVertex, after those of the
  // earlier parts, so the corners of a vertex stay in corner order. firstOfVertex[v] is where
  // vertex v's corners start.
  std::vector<std::vector<Index>> at(parts);
  parallelFor(parts, parts, [&](int p) {
    at[p].assign(vertexCount, 0);
    for (std::size_t c = partBegin(p), end = partBegin(p + 1); c < end; ++c) ++at[p][vertexOf[c]];
  });
  // The per-corner arrays' pages faulted in on the threads (48 MB each at 4 M faces).
  std::vector<Index> firstOfVertex(vertexCount + 1, 0), byVertex;
  resizeFaultedIn(byVertex, corners, threads);
  for (std::size_t v = 0; v < vertexCount; ++v) {
    Index next = firstOfVertex[v];
    for (int p = 0; p < parts; ++p) {
      const Index count = at[p][v];
      at[p][v] = next;
      next += count;
    }
    firstOfVertex[v + 1] = next;
  }
  parallelFor(parts, parts, [&](int p) {
    for (std::size_t c = partBegin(p), end = partBegin(p + 1); c < end; ++c)
      byVertex[at[p][vertexOf[c]]++] = static_cast<Index>(c);
    std::vector<Index>().swap(at[p]);
  });

  // Each thread takes a range of vertices and numbers their split vertices from 0; the numbers are
  // then offset by those of the ranges before it.
  const int ranges = parts == 1 ? 1 : threadCount(threads);
  const auto rangeBegin = [&](int r) { return vertexCount * std::size_t(r) / std::size_t(ranges); };
  SplitVertices split;
  resizeFaultedIn(split.ofCorner, corners, threads);
  std::vector<std::vector<int>> vertex(ranges);
  std::vector<std::vector<std::size_t>> corner(ranges);
  parallelFor(ranges, ranges, [&](int r) {
    for (std::size_t v = rangeBegin(r), end = rangeBegin(r + 1); v < end; ++v) {
      const std::size_t begin = firstOfVertex[v], last = firstOfVertex[v + 1];
      for (std::size_t i = begin; i < last; ++i) {
        const std::size_t c = byVertex[i];
        std::size_t same = begin;  // an earlier corner of this vertex with the same key, if any
        while (same < i && !sameKey(byVertex[same], c)) ++same;
        if (same < i) {
          split.ofCorner[c] = split.ofCorner[byVertex[same]];
          continue;
        }
        split.ofCorner[c] = static_cast<int>(vertex[r].size());
        vertex[r].push_back(static_cast<int>(v));
        corner[r].push_back(c);
      }
    }
  });
  std::vector<std::size_t> before(ranges + 1, 0);
  for (int r = 0; r < ranges; ++r) before[r + 1] = before[r] + vertex[r].size();
  UVTK_CHECK(before[ranges] <= static_cast<std::size_t>(INT_MAX));
  split.vertex.resize(before[ranges]);
  split.corner.resize(before[ranges]);
  parallelFor(ranges, ranges, [&](int r) {
    std::copy(vertex[r].begin(), vertex[r].end(), split.vertex.begin() + before[r]);
    std::copy(corner[r].begin(), corner[r].end(), split.corner.begin() + before[r]);
    if (before[r] == 0) return;
    const int offset = static_cast<int>(before[r]);
    for (std::size_t i = firstOfVertex[rangeBegin(r)], end = firstOfVertex[rangeBegin(r + 1)]; i < end; ++i)
      split.ofCorner[byVertex[i]] += offset;
  });
  return split;
}

}  // namespace

SplitVertices splitVertices(const Mesh& mesh, const SplitVertexKey& key, int threads) {
  const std::size_t corners = 3 * mesh.triangles.size();
  UVTK_CHECK(!key.uvs || key.uvs->uv.size() == corners);
  if (corners <= UINT32_MAX) return split<std::uint32_t>(mesh, key, threads);
  return split<std::size_t>(mesh, key, threads);
}

}  // namespace uvtk::io
