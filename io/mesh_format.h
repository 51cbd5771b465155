// The mesh file formats, known by their extension (case-insensitive): what readMesh reads and
// writeMesh writes.
#pragma once

#include <optional>
#include <string>

namespace uvtk::io {

enum class MeshFormat { obj, off, ply, stl, gltf, glb };

// The format of `path` by its extension; nullopt for any other extension (or none).
std::optional<MeshFormat> meshFormatOf(const std::string& path);

// The format a mesh is written in: by the extension, and OBJ, the default, for a path without one
// (`-` for standard output, a device such as /dev/null, `-o out`); nullopt for another extension.
std::optional<MeshFormat> outputFormatOf(const std::string& path);

// ".obj", ".off", ...
const char* extensionOf(MeshFormat format);

// Whether writeMesh writes the format: it keeps per-corner UVs (OFF and STL hold none).
inline bool writesUvs(MeshFormat format) { return format != MeshFormat::off && format != MeshFormat::stl; }

// glTF 2.0, as .gltf (+ .bin) or .glb: float32 attributes, v running down.
inline bool isGltf(MeshFormat format) { return format == MeshFormat::gltf || format == MeshFormat::glb; }

// "a .obj, .off, .ply, .stl, .gltf or .glb extension" and "a .obj, .ply, .gltf or .glb extension":
// what messages expect of an input and of an output.
extern const char* const kReadableExtensions;
extern const char* const kWritableExtensions;

// The file a .gltf's buffer is written to beside it: the same path with the extension .bin.
std::string gltfBufferPath(const std::string& gltfPath);

}  // namespace uvtk::io
