// The OBJ and OFF targets share one body: read the bytes as a mesh; a mesh that reads is mapped by
// a projector chosen from the input's size and written back as OBJ, where no non-finite number may
// appear unflagged.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "core/error.h"
#include "io/mesh_reader.h"
#include "io/obj_writer.h"
#include "param/projector.h"

namespace uvtk::fuzz {

using Reader = io::ReadMeshResult (*)(std::istream&, const std::string&);

inline int readMapAndWrite(Reader read, const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  io::ReadMeshResult result;
  try {
    result = read(in, "fuzz");
  } catch (const InputError&) {
    return 0;  // the expected way to refuse bad input
  }
  param::ProjectorOptions options;
  constexpr param::SurfaceKind kSurfaces[] = {param::SurfaceKind::Plane, param::SurfaceKind::Cylinder,
                                              param::SurfaceKind::Sphere, param::SurfaceKind::Cube};
  options.surface = kSurfaces[size % 4];
  constexpr param::RayKind kRays[] = {param::RayKind::SurfaceNormal, param::RayKind::Centroid,
                                      param::RayKind::ObjectNormal};
  options.ray = kRays[(size / 4) % 3];
  const param::Projection projection = param::project(result.mesh, options);
  std::ostringstream out;
  io::writeObj(out, projection.mesh, &projection.uv);
  const std::string text = out.str();
  // Invalid corners are flagged in a comment and written as vt 0 0; "nan" or "inf" is a bug.
  if (text.find("nan") != std::string::npos || text.find("inf") != std::string::npos) std::abort();
  return 0;
}

}  // namespace uvtk::fuzz
