// The projector options of `uvtk map`, shared with every subcommand that maps a mesh.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "param/projector.h"

namespace uvtk::cli {

// The raw option values as typed; resolve() turns them into ProjectorOptions.
struct ProjectorArguments {
  param::ProjectorOptions options;
  std::string center, axisDir, refDir;
  double scale = 1.0;
  std::string planeU = "1,0,0,0", planeV = "0,1,0,0";
  std::string eye;
  std::string uvScale = "1,1", uvOffset = "0,0";
  CLI::App* app = nullptr;
  bool cameraOwnsEye = false;  // `uvtk render`: --eye and --center belong to the camera

  // Checks combinations and parses vectors; throws UsageError.
  param::ProjectorOptions resolve() const;
};

// Adds --projector, --omap, --fit and all the other mapping options to `app`. With
// `cameraOwnsEye` (uvtk render) the placement's origin is --frame-center and the reflection
// O-mapping's eye is the camera's, set by the caller in arguments.options.eye.
void addProjectorOptions(CLI::App& app, ProjectorArguments& arguments, bool cameraOwnsEye = false);

}  // namespace uvtk::cli
