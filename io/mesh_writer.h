// Mesh output chosen by extension: OBJ, PLY, glTF (.gltf + .bin) or GLB, each with per-corner UVs;
// STL for a mesh without UVs (it holds none).
#pragma once

#include <string>

#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk::io {

class OutputSet;

struct MeshWriteOptions {
  std::string header;           // OBJ and PLY: comment lines; glTF: ignored
  bool floatDigits = false;     // OBJ: UV text that round-trips a float, not a double
  bool writeW = false;          // OBJ: `vt u v w` (the cube face id); the other formats hold two components
  bool ascii = false;           // PLY: ASCII instead of binary little endian
  // PLY and glTF: a normal per vertex when the mesh has none of its own: the area-weighted vertex
  // normal, the one projectors cast rays along, so a mapping of the written file sees the same rays.
  bool computedNormals = true;
  int threads = 0;  // OBJ: threads formatting the text (0: one per core); the bytes do not depend on it
};

// Throws UsageError when `path` is not an extension writeMesh writes (with `uvs`: one that holds
// them), or `options` ask what its format cannot hold (--write-w beyond OBJ, --ascii beyond PLY and
// STL). `what` names the option ("-o"). Throws OutputError when a .gltf's buffer (the .bin beside
// it, which the user did not name) would go to a FIFO, socket or device.
void checkMeshOutput(const std::string& path, const MeshWriteOptions& options, const std::string& what = "-o",
                     bool uvs = true);

// Stages `path` (and, for .gltf, its buffer: gltfBufferPath) in `outputs` by its extension.
void writeMesh(OutputSet& outputs, const std::string& path, const Mesh& mesh, const UvMap* uvs,
               const MeshWriteOptions& options = {});

// The same, published at once (atomically; throws OutputError).
void writeMesh(const std::string& path, const Mesh& mesh, const UvMap* uvs, const MeshWriteOptions& options = {});

}  // namespace uvtk::io
