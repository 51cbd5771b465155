// libFuzzer target: the OBJ reader, then mapping and writing what it accepts. The chunked reader
// of regular files (many chunks on two threads, re-read where a chunk depends on what precedes
// it) must agree with the stream reader on every input: the same mesh, warnings and message.
#include "mesh_fuzzer.h"

namespace {

bool sameWarnings(const uvtk::MeshWarnings& a, const uvtk::MeshWarnings& b) {
  return a.degenerateFaces == b.degenerateFaces && a.unreferencedVertices == b.unreferencedVertices &&
         a.nonSimplePolygons == b.nonSimplePolygons && a.firstNonSimplePolygonLine == b.firstNonSimplePolygonLine &&
         a.vertexColours == b.vertexColours && a.parameterVertices == b.parameterVertices;
}

bool sameMesh(const uvtk::Mesh& a, const uvtk::Mesh& b) {
  return a.positions == b.positions && a.triangles == b.triangles && a.texcoords == b.texcoords &&
         a.cornerTexcoords == b.cornerTexcoords && a.normals == b.normals && a.cornerNormals == b.cornerNormals;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::string streamError, chunkError;
  uvtk::io::ReadMeshResult streamed, chunked;
  try {
    std::istringstream in(text);
    streamed = uvtk::io::readObj(in, "fuzz");
  } catch (const uvtk::InputError& e) {
    streamError = e.what();
  }
  try {
    chunked = uvtk::io::readObjText(text, "fuzz", 2, 1 + size % 61);
  } catch (const uvtk::InputError& e) {
    chunkError = e.what();
  }
  if (streamError != chunkError) std::abort();
  if (streamError.empty() && (!sameMesh(streamed.mesh, chunked.mesh) || !sameWarnings(streamed.warnings, chunked.warnings)))
    std::abort();
  return uvtk::fuzz::readMapAndWrite(&uvtk::io::readObj, data, size);
}
