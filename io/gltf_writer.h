// glTF 2.0 output: one buffer, one mesh of one triangle primitive, one node, one scene.
#pragma once

#include <array>

#include <iosfwd>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk::io {

struct GltfWriteOptions {
  std::string generator;  // asset.generator, e.g. "uvtk 0.3.0"
  std::string copyright;  // asset.copyright when not empty
  // Normals per mesh vertex (nx ny nz / NORMAL), written when the mesh has none of its own; null: none.
  const std::vector<Vec3>* vertexNormals = nullptr;
  std::string name = "glTF";  // the output's name in messages (the path, when writing a file)
};

// TEXCOORD_0 as a glTF holds a UV: float32 (u, 1 - v), glTF's v running down the image.
std::array<float, 2> gltfTexcoord(const Vec2& uv);

// Whether the UV triangle (a, b, c) has an area and, as a glTF holds it (gltfTexcoord), none:
// float32 lost it (UVs far from [0, 1], or a triangle finer than float32's steps: 2^-24 near
// v = 0, where 1 - v is near 1). `uvtk map` warns with the count of such faces among the measured ones.
bool collapsesInGltfTexcoords(const Vec2& a, const Vec2& b, const Vec2& c);

// A .glb: the JSON chunk and the binary chunk in one stream.
void writeGlb(std::ostream& out, const Mesh& mesh, const UvMap* uvs, const GltfWriteOptions& options = {});

// A .gltf and its buffer: the JSON to `json`, naming the buffer by `binaryUri` (the buffer's file
// name relative to the JSON's folder, e.g. "model.bin"; percent-encoded into the uri where it
// holds other than letters, digits, '-', '.', '_', '~' and '/'), and the buffer's bytes to `binary`.
// Both throw OutputError "NAME: error: cannot write: ..." before writing anything when a UV is
// beyond float32's range or the mesh has no triangle. Positions always fit: a mesh far from the
// origin, or of a size float32 cannot hold, is placed by the node's translation and scale
// (gltf_writer.cpp).
void writeGltf(std::ostream& json, std::ostream& binary, const std::string& binaryUri, const Mesh& mesh,
               const UvMap* uvs, const GltfWriteOptions& options = {});

}  // namespace uvtk::io
