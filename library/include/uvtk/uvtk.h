// uvtk: texture coordinates for triangle meshes, and proof that they are right. The whole library
// (find_package(uvtk) ... target_link_libraries(app PRIVATE uvtk::uvtk)); docs/library.md.
#pragma once

#include "uvtk/inspect.h"
#include "uvtk/mapping.h"
#include "uvtk/mesh.h"
