// Strict PLY reader (ASCII, binary little and big endian). Errors name the file and the place:
// "FILE:LINE: error: ..." in the header and in ASCII data, "FILE: byte N: error: ..." in binary data.
#pragma once

#include <iosfwd>
#include <string>

#include "io/mesh_reader.h"

namespace uvtk::io {

// `name` is the file name used in messages.
ReadMeshResult readPly(std::istream& in, const std::string& name);

}  // namespace uvtk::io
