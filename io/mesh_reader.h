// Strict mesh readers. Every malformed input is an InputError whose one-line message names the
// file and the place: "FILE:LINE: error: expected ..., found ..." for text, a byte offset or a
// JSON pointer for binary files and glTF (io/ply_reader.h, io/stl_reader.h, io/gltf_reader.h);
// nothing is repaired silently.
#pragma once

#include <iosfwd>
#include <string>

#include "core/mesh.h"

namespace uvtk::io {

struct ReadMeshResult {
  Mesh mesh;
  MeshWarnings warnings;
};

// Reads by extension (io/mesh_format.h: .obj, .off, .ply, .stl, .gltf, .glb, case-insensitive);
// any other extension is an InputError.
ReadMeshResult readMesh(const std::string& path);

// `name` is the file name used in messages.
ReadMeshResult readObj(std::istream& in, const std::string& name);
ReadMeshResult readOff(std::istream& in, const std::string& name);

}  // namespace uvtk::io
