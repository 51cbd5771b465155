// STL output, binary or ASCII: triangles and positions only (STL holds no UVs, no shared vertices).
#pragma once

#include <iosfwd>
#include <string>

#include "core/mesh.h"

namespace uvtk::io {

struct StlWriteOptions {
  bool ascii = false;  // `solid ... endsolid`; else binary (80-byte header, uint32 count, 50 bytes a triangle)
  // Binary: the header is "uvtk", a space and this text, cut or padded with NUL bytes to 80 bytes (so
  // it never starts with "solid", which some readers take for ASCII). ASCII: the solid's name after
  // "uvtk", line breaks and other control characters as spaces.
  std::string header;
  std::string name = "STL";  // the output's name in messages (the path, when writing a file)
};

// Writes every triangle in mesh order, corners in their order, positions as float32 (ASCII: the
// shortest text that reads back as the same float) and the facet normal as the unit normal of the
// float triangle (0 0 0 when it has no area). A position a float cannot hold (magnitude beyond
// 3.40282347e+38) is an OutputError "NAME: error: cannot write: ...", thrown before anything is
// written.
void writeStl(std::ostream& out, const Mesh& mesh, const StlWriteOptions& options = {});

}  // namespace uvtk::io
