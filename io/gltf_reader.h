// glTF 2.0 reader (.gltf with external or data-URI buffers, .glb) through tinygltf. Errors name
// the file and a JSON pointer ("FILE: /meshes/0/primitives/1/indices: error: ...") or, in a GLB's
// container, a byte offset ("FILE: byte N: error: ...").
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>

#include "io/mesh_reader.h"

namespace uvtk::io {

// Reads the file `path` from `in` (a GLB when its extension is .glb or its bytes start with
// "glTF"); external buffers are resolved against the path's folder.
ReadMeshResult readGltf(std::istream& in, const std::string& path);

// Reads a file's bytes (`binary`: a GLB container); `name` is used in messages, external buffer
// URIs are resolved against `folder` (empty: none may be read).
ReadMeshResult readGltf(std::string_view bytes, const std::string& name, const std::string& folder, bool binary);

}  // namespace uvtk::io
