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

  // Checks combinations and parses vectors; throws UsageError.
  param::ProjectorOptions resolve() const;
};

// Adds --projector, --omap, --fit and all the other mapping options to `app`.
void addProjectorOptions(CLI::App& app, ProjectorArguments& arguments);

}  // namespace uvtk::cli
