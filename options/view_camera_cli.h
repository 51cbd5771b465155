// --view-dir and --up: the camera of the inspection views (inspect::ViewCamera), as `uvtk report`,
// `uvtk compare` and their scene outputs take it.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "inspect/mapped_mesh.h"

namespace uvtk::cli {

// Where every picture looks from unless told: report's views, compare's sheet, render's automatic
// camera and check's pictures.
inline constexpr const char* kViewDirection = "1,-1.5,0.8";
inline constexpr const char* kViewUp = "0,0,1";

struct ViewCameraArguments {
  std::string viewDir = kViewDirection, up = kViewUp;  // "x,y,z" as given

  void check() const { resolve(); }  // throws UsageError for a malformed direction
  inspect::ViewCamera resolve() const;
};
void addViewCameraOptions(CLI::App& app, ViewCameraArguments& arguments);

}  // namespace uvtk::cli
