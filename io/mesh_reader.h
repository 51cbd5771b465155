// Strict mesh readers. Every malformed input is an InputError whose one-line message names the
// file and the place: "FILE:LINE: error: expected ..., found ..." for text, a byte offset or a
// JSON pointer for binary files and glTF (io/ply_reader.h, io/stl_reader.h, io/gltf_reader.h);
// nothing is repaired silently.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <string_view>

#include "core/mesh.h"

namespace uvtk::io {

struct ReadMeshResult {
  Mesh mesh;
  MeshWarnings warnings;
  // The faces a uvtk writer listed as having corners without a valid UV, whose (0, 0) corners were
  // read as without a UV (io/face_lists.h); as many as warnings.listedInvalidUvFaces.
  std::vector<std::size_t> listedInvalidUvFaces;
};

// Reads by extension (io/mesh_format.h: .obj, .off, .ply, .stl, .gltf, .glb, case-insensitive);
// any other extension is an InputError. A regular OBJ file is read and parsed on `threads` threads
// (0: all, core/parallel.h) by readObjFile; other files are read as streams.
ReadMeshResult readMesh(const std::string& path, int threads = 0);

// `name` is the file name used in messages.
ReadMeshResult readObj(std::istream& in, const std::string& name);
ReadMeshResult readOff(std::istream& in, const std::string& name);

// The bytes of OBJ each thread reads and parses at a time: large enough that a chunk's set-up
// costs nothing, small enough that the threads finish together and hold little text.
inline constexpr std::size_t kObjChunkBytes = std::size_t{4} << 20;

// OBJ split at line ends into chunks of about `chunkBytes`, each read and parsed on one of
// `threads` threads (0: all), then joined: the mesh, warnings and errors (messages and line
// numbers) of readObj, whatever the chunks. readObjFile reads a regular file so (each thread
// reading its own chunks), anything else as readMesh does; readObjText reads text in memory.
ReadMeshResult readObjFile(const std::string& path, int threads = 0, std::size_t chunkBytes = kObjChunkBytes);
ReadMeshResult readObjText(std::string_view text, const std::string& name, int threads = 0,
                           std::size_t chunkBytes = kObjChunkBytes);

}  // namespace uvtk::io
