// libFuzzer target: the STL reader, then mapping and writing what it accepts (mesh_fuzzer.h); and
// a round trip: what the reader accepts, written by the STL writer in either form, reads back as
// the same mesh (the same float positions in the same order, the same triangles).
#include <cstdlib>
#include <sstream>
#include <string>

#include "io/stl_reader.h"
#include "io/stl_writer.h"
#include "mesh_fuzzer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  uvtk::fuzz::readMapAndWrite(&uvtk::io::readStl, data, size);
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  uvtk::io::ReadMeshResult first;
  try {
    first = uvtk::io::readStl(in, "fuzz");
  } catch (const uvtk::InputError&) {
    return 0;
  }
  for (const bool ascii : {false, true}) {
    uvtk::io::StlWriteOptions options;
    options.ascii = ascii;
    std::ostringstream out;
    uvtk::io::writeStl(out, first.mesh, options);
    std::istringstream written(out.str());
    const uvtk::io::ReadMeshResult again = uvtk::io::readStl(written, "written");  // an InputError here is a bug
    if (again.mesh.positions != first.mesh.positions || again.mesh.triangles != first.mesh.triangles ||
        again.warnings.weldedCorners != first.warnings.weldedCorners)
      std::abort();
  }
  return 0;
}
