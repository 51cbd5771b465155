// The projector options of `uvtk map`, shared with every subcommand that maps a mesh.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "options/option_names.h"
#include "param/projector.h"

namespace uvtk::cli {

// Other tools' projectors, expressed in uvtk's options (docs/conventions.md, "Other tools").
enum class Convention {
  Uvtk,
  Blender,  // uv.sphere_project / uv.cylinder_project, ALIGN_TO_OBJECT, POLAR_ZX
  Assimp,   // aiProcess_GenUVCoords with its default axis +y
  Notes,    // the lecture notes' worked examples (the seeds): cube direct, sphere seed004, object frame
};

// The raw option values as typed; resolve() turns them into ProjectorOptions.
struct ProjectorArguments {
  param::ProjectorOptions options;
  std::string center, axisDir, refDir;
  double scale = 1.0;
  std::string planeU = "1,0,0,0", planeV = "0,1,0,0";
  std::string eye;
  std::string uvScale = "1,1", uvOffset = "0,0";
  std::string seamPlace;  // "auto" or degrees
  Convention convention = Convention::Uvtk;
  CLI::App* app = nullptr;
  bool cameraOwnsEye = false;  // `uvtk render`: --eye and --center belong to the camera
  // --projector camera: --eye and --center above are its gluLookAt eye and centre; where the
  // command's own camera has a name (`uvtk render`: all five; `uvtk report`: --up), the camera
  // projector's option is --proj-NAME instead. The names given are kept for the messages.
  std::string up, projEye, projCenter;
  param::CameraOptionNames cameraNames;

  // Checks combinations and parses vectors; throws UsageError. `--seam-place auto` is left to
  // the caller, which has the mesh (mapByProjector in mapped_mesh.h).
  param::ProjectorOptions resolve() const;
  bool seamPlaceAuto() const { return seamPlace == "auto"; }
};

// Default options for the projector and O-mapping of these names (as --projector and --omap take
// them); throws UsageError for an unknown name.
param::ProjectorOptions projectorNamed(const std::string& projector, const std::string& omap);

const std::string& conventionName(Convention convention);



// Adds --projector, --omap, --fit and all the other mapping options to `app`. With
// `cameraOwnsEye` (uvtk render) the placement's origin is --frame-center and the reflection
// O-mapping's eye is the camera's, set by the caller in arguments.options.eye.
void addProjectorOptions(CLI::App& app, ProjectorArguments& arguments, bool cameraOwnsEye = false);

}  // namespace uvtk::cli
