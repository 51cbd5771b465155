// OBJ output with per-corner UVs (`f v/vt` or `f v/vt/vn`), so seams survive the file.
#pragma once

#include <iosfwd>
#include <string>

#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk::io {

struct ObjWriteOptions {
  int significantDigits = 17;  // 17 round-trips a double, 9 a float
  bool writeW = false;         // write `vt u v w` with the UvMap's third component
  bool writeNormals = true;    // keep the mesh's `vn` (when it has them) as `f v/vt/vn`
  std::string header;          // comment lines written first, each prefixed with "# "
};

// Writes positions in order, then the distinct per-corner UVs as `vt`, then normals, then faces.
// `uvs` may be null (faces written as `f v` or `f v//vn`).
void writeObj(std::ostream& out, const Mesh& mesh, const UvMap* uvs, const ObjWriteOptions& options = {});

// The same, atomically into `path` (temporary file + rename); throws OutputError.
void writeObj(const std::string& path, const Mesh& mesh, const UvMap* uvs, const ObjWriteOptions& options = {});

}  // namespace uvtk::io
