// OBJ output with per-corner UVs (`f v/vt` or `f v/vt/vn`), so seams survive the file.
#pragma once

#include <iosfwd>
#include <string>

#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk::io {

class OutputSet;

struct ObjWriteOptions {
  bool floatPrecision = false;  // UVs as the shortest text that round-trips a float (<= 9 digits), not a double (<= 17)
  bool writeW = false;          // write `vt u v w` with the UvMap's third component (0 where it has none)
  std::string header;           // comment lines written first, each prefixed with "# "
  int threads = 0;              // threads formatting the text (0: all, core/parallel.h); the bytes are the same
};

// Writes, in this order: the header, `v` in mesh order (shortest text that round-trips the
// double), one `vt` per distinct (vertex, u, v[, w]) in vertex order (so a mesh without seams has
// vt i for v i), the mesh's `vn` when it has them, then the faces in mesh order as `f v/vt/vn`
// (or `f v/vt`, `f v//vn`, `f v`: `uvs` may be null). A face with an invalid corner is listed in
// a comment before the faces; its invalid corners carry `vt 0 0`.
void writeObj(std::ostream& out, const Mesh& mesh, const UvMap* uvs, const ObjWriteOptions& options = {});

// The same, atomically into `path` (temporary file + rename); throws OutputError.
void writeObj(const std::string& path, const Mesh& mesh, const UvMap* uvs, const ObjWriteOptions& options = {});
// The same, staged in `outputs`, which publishes it with the command's other outputs.
void writeObj(OutputSet& outputs, const std::string& path, const Mesh& mesh, const UvMap* uvs,
              const ObjWriteOptions& options = {});

}  // namespace uvtk::io
