#include "io/mesh_format.h"

#include <filesystem>

namespace uvtk::io {

const char* const kReadableExtensions = "a .obj, .off, .ply, .stl, .gltf or .glb extension";
const char* const kWritableExtensions = "a .obj, .ply, .gltf or .glb extension";

std::optional<MeshFormat> meshFormatOf(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  for (const MeshFormat format :
       {MeshFormat::obj, MeshFormat::off, MeshFormat::ply, MeshFormat::stl, MeshFormat::gltf, MeshFormat::glb})
    if (extension == extensionOf(format)) return format;
  return std::nullopt;
}

std::optional<MeshFormat> outputFormatOf(const std::string& path) {
  if (std::filesystem::path(path).extension().empty()) return MeshFormat::obj;
  return meshFormatOf(path);
}

const char* extensionOf(MeshFormat format) {
  switch (format) {
    case MeshFormat::obj: return ".obj";
    case MeshFormat::off: return ".off";
    case MeshFormat::ply: return ".ply";
    case MeshFormat::stl: return ".stl";
    case MeshFormat::gltf: return ".gltf";
    case MeshFormat::glb: return ".glb";
  }
  return "";
}

std::string gltfBufferPath(const std::string& gltfPath) {
  return std::filesystem::path(gltfPath).replace_extension(".bin").string();
}

}  // namespace uvtk::io
