// Strict STL reader (ASCII and binary). Corners are welded into vertices by exact position; the
// number of welded corners is MeshWarnings::weldedCorners.
#pragma once

#include <iosfwd>
#include <string>

#include "io/mesh_reader.h"

namespace uvtk::io {

// `name` is the file name used in messages.
ReadMeshResult readStl(std::istream& in, const std::string& name);

}  // namespace uvtk::io
