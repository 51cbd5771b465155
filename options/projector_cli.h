// The projector options of `uvtk map`, shared with every subcommand that maps a mesh.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "param/make_projector.h"
#include "param/projector.h"

namespace uvtk::cli {

// The projector options as CLI11 parsed them (typed, once); parameters() hands the ones given to
// param::makeProjector, which checks and combines them.
struct ProjectorArguments {
  param::ProjectorOptions options;  // the choices, flags and numbers
  std::string center, axisDir, refDir;
  double scale = 1.0;
  std::string planeU, planeV;
  std::string eye;
  std::string uvScale, uvOffset;
  std::string seamPlace;  // "auto" or degrees
  param::Convention convention = param::Convention::Uvtk;
  std::string up, projEye, projCenter;
  double texelsPerUnit = 0.0;  // --texels-per-unit (the options hold it as "not given" until then)
  CLI::App* app = nullptr;
  // The command's names for the projector's parameters: `uvtk render` (cameraOwnsEye) calls the
  // placement's origin --frame-center and the camera projector's --proj-eye, --proj-center, ...;
  // where the command's camera has --up, the camera projector's is --proj-up.
  param::ProjectorContext context;

  // The options given on the command line, typed, each at its option's name.
  param::ParameterDictionary parameters() const;
  // param::makeProjector of parameters(): throws UsageError.
  param::ProjectorRequest resolve() const;
};

// Default options for the projector and O-mapping of these names (as --projector and --omap take
// them); throws UsageError for an unknown name.
param::ProjectorOptions projectorNamed(const std::string& projector, const std::string& omap);




// Adds --projector, --omap, --fit and all the other mapping options to `app`. With
// `cameraOwnsEye` (uvtk render) the placement's origin is --frame-center and the reflection
// O-mapping's eye is the camera's, set by the caller in arguments.options.eye.
void addProjectorOptions(CLI::App& app, ProjectorArguments& arguments, bool cameraOwnsEye = false);

}  // namespace uvtk::cli
