// Strict OBJ and OFF readers. Every malformed input is an InputError whose message reads
// "FILE:LINE: error: expected ..., found ..."; nothing is repaired silently.
#pragma once

#include <iosfwd>
#include <string>

#include "core/mesh.h"

namespace uvtk::io {

struct ReadMeshResult {
  Mesh mesh;
  MeshWarnings warnings;
};

// Reads by extension (.obj or .off, case-insensitive); any other extension is an InputError.
ReadMeshResult readMesh(const std::string& path);

// `name` is the file name used in messages.
ReadMeshResult readObj(std::istream& in, const std::string& name);
ReadMeshResult readOff(std::istream& in, const std::string& name);

}  // namespace uvtk::io
