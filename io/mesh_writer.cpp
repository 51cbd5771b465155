#include "io/mesh_writer.h"

#include <sys/stat.h>

#include <filesystem>
#include <sstream>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/gltf_writer.h"
#include "io/mesh_format.h"
#include "io/obj_writer.h"
#include "io/ply_writer.h"
#include "io/stl_writer.h"
#include "io/temporary_file.h"

namespace uvtk::io {

namespace {

// A .gltf's buffer goes to a name the user did not give: a FIFO there would hang the write, a
// device would take the bytes and leave a glTF that cannot be read back. Only a regular file (or
// a new name) may be written; links are followed as outputs follow them.
void checkGltfBuffer(const std::string& path) {
  const std::string buffer = gltfBufferPath(path);
  struct stat status {};
  if (::stat(buffer.c_str(), &status) != 0 || S_ISREG(status.st_mode) || S_ISDIR(status.st_mode)) return;
  const char* kind = S_ISFIFO(status.st_mode)  ? "a FIFO"
                     : S_ISSOCK(status.st_mode) ? "a socket"
                     : S_ISCHR(status.st_mode)  ? "a character device"
                                                : "a block device";
  throw writeError(path, std::string("its buffer goes to ") + buffer + ", which is " + kind +
                             ", not a file (a .glb output holds its buffer inside)");
}

}  // namespace

void checkMeshOutput(const std::string& path, const MeshWriteOptions& options, const std::string& what, bool uvs) {
  const std::optional<MeshFormat> format = outputFormatOf(path);
  if (!format || *format == MeshFormat::off || (uvs && !writesUvs(*format))) {
    const std::string extension = std::filesystem::path(path).extension().string();
    throw UsageError(what + ": expected " + (uvs ? kWritableExtensions : "a .obj, .ply, .stl, .gltf or .glb extension") +
                     ", found " + (extension.empty() ? "none" : "'" + extension + "'") + " (" + path + ")");
  }
  if (options.writeW && *format != MeshFormat::obj)
    throw UsageError("--write-w: only an OBJ holds a third UV component; " + path + " is not one");
  if (options.ascii && *format != MeshFormat::ply && *format != MeshFormat::stl)
    throw UsageError("--ascii: only for a .ply or .stl output; " + path + " is neither");
  if (*format == MeshFormat::gltf) checkGltfBuffer(path);
}

void writeMesh(OutputSet& outputs, const std::string& path, const Mesh& mesh, const UvMap* uvs,
               const MeshWriteOptions& options) {
  checkMeshOutput(path, options, "-o", uvs != nullptr);
  std::vector<Vec3> normals;  // computed per vertex, when the mesh has none of its own
  if (options.computedNormals && !mesh.hasNormals() && *outputFormatOf(path) != MeshFormat::obj)
    normals = areaWeightedVertexNormals(mesh);
  const std::vector<Vec3>* vertexNormals = normals.empty() ? nullptr : &normals;
  switch (*outputFormatOf(path)) {
    case MeshFormat::obj: {
      ObjWriteOptions obj;
      obj.header = options.header;
      obj.floatPrecision = options.floatDigits;
      obj.writeW = options.writeW;
      obj.threads = options.threads;
      return writeObj(outputs, path, mesh, uvs, obj);
    }
    case MeshFormat::ply: {
      PlyWriteOptions ply;
      ply.ascii = options.ascii;
      ply.header = options.header;
      ply.vertexNormals = vertexNormals;
      return outputs.write(path, [&](std::ostream& out) { writePly(out, mesh, uvs, ply); });
    }
    case MeshFormat::glb:
    case MeshFormat::gltf: {
      GltfWriteOptions gltf;
      gltf.generator = "uvtk " UVTK_VERSION;
      gltf.vertexNormals = vertexNormals;
      gltf.name = path;
      if (*outputFormatOf(path) == MeshFormat::glb)
        return outputs.write(path, [&](std::ostream& out) { writeGlb(out, mesh, uvs, gltf); });
      // The buffer is written first and the JSON from the same call, so both are staged or neither.
      const std::string bufferPath = gltfBufferPath(path);
      const std::string bufferUri = std::filesystem::path(bufferPath).filename().string();
      std::string json;
      outputs.write(bufferPath, [&](std::ostream& binary) {
        std::ostringstream text;
        writeGltf(text, binary, bufferUri, mesh, uvs, gltf);
        json = text.str();
      });
      return outputs.writeText(path, json);
    }
    case MeshFormat::stl: {
      StlWriteOptions stl;
      stl.ascii = options.ascii;
      stl.header = options.header;
      stl.name = path;
      return outputs.write(path, [&](std::ostream& out) { writeStl(out, mesh, stl); });
    }
    case MeshFormat::off:
      break;
  }
  UVTK_CHECK(false);
}

void writeMesh(const std::string& path, const Mesh& mesh, const UvMap* uvs, const MeshWriteOptions& options) {
  OutputSet outputs;
  writeMesh(outputs, path, mesh, uvs, options);
  outputs.publish();
}

}  // namespace uvtk::io
