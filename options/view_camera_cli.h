// --view-dir and --up: the camera of the inspection views (inspect::ViewCamera), as `uvtk report`,
// `uvtk compare` and their scene outputs take it.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "inspect/mapped_mesh.h"

namespace uvtk::cli {

struct ViewCameraArguments {
  std::string viewDir = "1,-1.5,0.8", up = "0,0,1";  // "x,y,z" as given

  void check() const { resolve(); }  // throws UsageError for a malformed direction
  inspect::ViewCamera resolve() const;
};
void addViewCameraOptions(CLI::App& app, ViewCameraArguments& arguments);

}  // namespace uvtk::cli
