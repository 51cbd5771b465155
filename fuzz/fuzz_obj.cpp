// libFuzzer target: the OBJ reader, then mapping and writing what it accepts.
#include "mesh_fuzzer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return uvtk::fuzz::readMapAndWrite(&uvtk::io::readObj, data, size);
}
