// libFuzzer target: the OFF reader, then mapping and writing what it accepts.
#include "mesh_fuzzer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return uvtk::fuzz::readMapAndWrite(&uvtk::io::readOff, data, size);
}
