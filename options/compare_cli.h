// The options of the ranking of every projector configuration on one mesh (`uvtk compare`, and a
// scene's compare output): inspect::CompareOptions as the command line spells them.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "inspect/compare.h"
#include "options/view_camera_cli.h"

namespace uvtk::cli {

struct CompareArguments {
  inspect::CompareOptions options;  // all but the camera, bound to the options directly
  ViewCameraArguments camera;
  std::string textureSize = "1024,1024";  // W,H or N

  void check() const { resolve(); }  // throws UsageError before any work
  inspect::CompareOptions resolve() const;
};
void addCompareOptions(CLI::App& app, CompareArguments& arguments);

}  // namespace uvtk::cli
