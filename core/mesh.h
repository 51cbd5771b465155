// The triangle mesh as flat arrays: what every hot loop of the toolkit reads.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/math.h"

namespace uvtk {

using Triangle = std::array<int, 3>;  // three indices, counter-clockwise seen from the front

struct Mesh {
  std::vector<Vec3> positions;      // object space
  std::vector<Triangle> triangles;  // indices into positions; polygons arrive triangulated

  // Attributes a file may carry per corner (OBJ `vt`, `vn`). A corner table is either empty or
  // has one entry per triangle; an index of -1 means that corner has no attribute.
  std::vector<Vec3> texcoords;  // (u, v, w); w = 0 when the file gave two components
  std::vector<Triangle> cornerTexcoords;
  std::vector<Vec3> normals;
  std::vector<Triangle> cornerNormals;
  // FaceFlag bits (core/uv_map.h) a uvtk writer listed in the file, one per triangle, or empty:
  // kFacePole and kFaceTurnedAway (io/face_lists.h), which the file's UVs alone cannot tell.
  std::vector<std::uint8_t> listedFaceFlags;

  std::size_t vertexCount() const { return positions.size(); }
  std::size_t faceCount() const { return triangles.size(); }
  bool hasTexcoords() const { return !cornerTexcoords.empty(); }
  bool hasNormals() const { return !cornerNormals.empty(); }
};

// Counts of what a reader accepted with a warning rather than an error.
struct MeshWarnings {
  std::size_t degenerateFaces = 0;        // two equal corner indices or zero area
  std::size_t unreferencedVertices = 0;   // vertices no face uses
  // Faces of more than three corners that are self-intersecting, non-planar or of zero area
  // (io/polygon_triangulation.h): triangulated all the same, perhaps folding over themselves.
  std::size_t nonSimplePolygons = 0;
  std::size_t firstNonSimplePolygonLine = 0;  // the line of the first of them; 0 when there is none
  std::size_t vertexColours = 0;              // OBJ `v x y z r g b` lines: the colours are dropped
  std::size_t parameterVertices = 0;          // OBJ `vp` lines (free-form geometry), ignored
  std::size_t weldedCorners = 0;      // STL: corners that became an earlier corner's vertex (same position, bit for bit)
  std::size_t skippedPrimitives = 0;  // glTF: primitives of points or lines, not triangles, left out
  // Faces a uvtk writer listed as having corners without a valid UV (io/face_lists.h): their
  // (0, 0) corners are read as without a UV.
  std::size_t listedInvalidUvFaces = 0;
};

// Twice the area-weighted normal of a triangle: the cross product of two edges.
template <class T>
Vec3T<T> triangleAreaNormal(const Vec3T<T>& a, const Vec3T<T>& b, const Vec3T<T>& c) {
  return (b - a).cross(c - a);
}

// Per-vertex unit normals, the area-weighted mean of the adjacent faces' normals.
// A vertex with no adjacent face of non-zero area gets (0, 0, 0).
std::vector<Vec3> areaWeightedVertexNormals(const Mesh& mesh);

// One normal per corner (3 per triangle): the file's normal where the corner has one,
// else the area-weighted vertex normal. Every returned vector has unit length or is zero.
std::vector<Vec3> cornerNormals(const Mesh& mesh);

// Counts degenerate faces (repeated index or zero area) and vertices no face references, on
// `threads` threads (0: one per core).
MeshWarnings checkMesh(const Mesh& mesh, int threads = 1);

}  // namespace uvtk
