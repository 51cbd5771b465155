// Meshes as value types: positions, triangles and what a file may carry per corner; reading them
// from OBJ and OFF files and writing them back. Part of <uvtk/uvtk.h> (docs/library.md).
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <cstdint>
#include <string>
#include <vector>

#include "uvtk/export.h"

namespace uvtk::api {

using Vector2 = std::array<double, 2>;
using Vector3 = std::array<double, 3>;
using Triangle = std::array<int, 3>;  // three indices, counter-clockwise seen from the front

// A file could not be read: "PATH:LINE: error: ..." (the command line's exit 3).
class UVTK_API InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  ~InputError() override;  // the library's: one type identity across shared objects
};

// An output could not be written, and nothing was left behind: "PATH: error: cannot write: ..."
// (exit 4). Bad options and arguments throw std::invalid_argument (exit 2).
class UVTK_API OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  ~OutputError() override;
};

// A parameter of the wrong kind (a number where true or false belongs, None where a choice
// belongs): Python's TypeError. Other refused values are std::invalid_argument, which it derives from.
class UVTK_API ParameterTypeError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
  ~ParameterTypeError() override;
};

struct Mesh {
  std::vector<Vector3> positions;   // object space
  std::vector<Triangle> triangles;  // indices into positions; polygons arrive triangulated
  // What a file may carry per corner (OBJ vt and vn). A corner table is empty or has one entry
  // per triangle; an index of -1 means that corner has none.
  std::vector<Vector3> texcoords;  // (u, v, w); w = 0 when the file gave two components
  std::vector<Triangle> cornerTexcoords;
  std::vector<Vector3> normals;
  std::vector<Triangle> cornerNormals;
  // Empty, or one per triangle: the pole faces (kFacePole) and the faces turned away from a planar
  // projection (kFaceTurnedAway) that a uvtk writer listed in the file (uvtk/mapping.h's flags),
  // which the UVs alone cannot tell; report() judges them as the map that wrote the file did.
  std::vector<std::uint8_t> faceFlags;
};

// What a reader accepted with a warning rather than an error.
struct MeshWarnings {
  std::size_t degenerateFaces = 0;          // two equal corner indices or zero area
  std::size_t unreferencedVertices = 0;     // vertices no face uses
  std::size_t nonSimplePolygons = 0;        // polygons self-intersecting, non-planar or of zero area
  std::size_t firstNonSimplePolygonLine = 0;  // the line of the first of them; 0 when there is none
  std::size_t vertexColours = 0;            // OBJ `v x y z r g b` lines: the colours are dropped
  std::size_t parameterVertices = 0;        // OBJ `vp` lines, ignored
  std::size_t weldedCorners = 0;            // STL: corners that became an earlier corner's vertex (same position)
  std::size_t skippedPrimitives = 0;        // glTF: primitives of points or lines, left out
  // Faces a uvtk writer listed as having corners without a valid UV: their (0, 0) corners read as without a UV.
  std::size_t listedInvalidUvFaces = 0;
};

// Reads a mesh file by its extension (.obj, .off, .ply, .stl, .gltf, .glb; docs/formats.md) as
// `uvtk map` does: strictly (throws InputError naming the file and the line, byte or JSON
// pointer), polygons ear-clipped into triangles. `warnings`, when given, receives what was accepted
// with a warning. `threads` parse a large OBJ (0: one per hardware thread; the same mesh).
UVTK_API Mesh readMesh(const std::string& path, MeshWarnings* warnings = nullptr, int threads = 0);

// Checks a mesh built in memory as a reader checks a file: indices within the positions, finite
// coordinates, corner tables of one entry per triangle. Throws std::invalid_argument naming the
// first problem; returns the warnings.
UVTK_API MeshWarnings checkMesh(const Mesh& mesh);

// Writes `mesh` by the path's extension (.obj, .ply, .glb, .gltf + .bin) with its own texture
// coordinates and normals, if any. Written whole or not
// at all (a temporary renamed onto `path`); throws OutputError.
UVTK_API void writeMesh(const std::string& path, const Mesh& mesh);

// "0.1.0": the version of the library (uvtk --version).
UVTK_API std::string version();

}  // namespace uvtk::api
