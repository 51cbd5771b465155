// The image plugin (io/image_backend.h), opened on first use so that a process that reads no image
// never loads OpenImageIO. Looked for, in order: $UVTK_IMAGE_PLUGIN when set; ../lib/uvtk/ beside
// the executable or shared object this code is linked into (an installed prefix); the build
// tree's plugin, for programs run from the build tree.
#pragma once

#include <string>

#include "io/image_backend.h"

namespace uvtk::io {

// The plugin's functions, loaded once (thread-safe) by the first call; null when it cannot be
// loaded, with `error` set to one line naming the path tried and why it failed.
const backend::Functions* imagePlugin(std::string& error);

}  // namespace uvtk::io
