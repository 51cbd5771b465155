// The options of `uvtk check` as typed, and the comparison they ask for (inspect/check.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "inspect/check.h"
#include "inspect/image_check_job.h"
#include "options/mapping_options.h"
#include "options/render_cli.h"
#include "options/verdict_cli.h"
#include "options/view_camera_cli.h"
#include "verify/image_check.h"

namespace uvtk::cli {

struct CheckArguments {
  std::string input, against, json, view;
  std::string viewSize = "512x512", viewDir = kViewDirection, viewUp = kViewUp;
  std::string wrap = "none";
  std::optional<double> tolerance;
  int textureSize = 1024;
  int worst = 10;
  bool partial = false;
  MappingArguments mapping;
  std::vector<std::string> mappingOptions;  // every option addMappingOptions added
  VerdictArguments verdict;                 // of the stored UVs as a layout (docs/conventions.md §11)
  std::vector<std::string> uvOptions;       // the options of the UV comparison alone: not with --image

  // --image: a picture another renderer made of the mesh, checked against uvtk's rendering with
  // `uvtk render`'s options (docs/check.md, "Checking a screenshot"). --eye, --center, --up and
  // --fovy are then the camera's, --view-dir the automatic camera's, --wrap the texture's and
  // --model the model matrix, as in `uvtk render`.
  std::string image, errorMask;
  CameraArguments camera;
  TextureArguments texture;
  FrameArguments frame;
  verify::ImagePrecision precision;
  std::vector<std::string> imageOptions;  // the options --image alone takes
  CLI::App* app = nullptr;

  // The comparison, every option checked first (UsageError) so that nothing is read or written for
  // a bad command line: a mapping option with --against, --wrap without it, --seam cut.
  inspect::CheckOptions resolve() const;
};

// --image, the camera's, texture's and frame's options of `uvtk render` that `uvtk check` does not
// have under the same name already, and the tolerances; recorded in imageOptions.
void addImageCheckOptions(CLI::App& app, CheckArguments& arguments);

// `uvtk check --image`: every option checked first (UsageError: an option of the UV comparison,
// --projector camera, what `uvtk render` refuses), then the mesh read and mapped as `uvtk render`
// maps it, the texture loaded, the shot checked (inspect/image_check_job.h).
inspect::ImageCheckRun checkImageFile(CheckArguments arguments);

}  // namespace uvtk::cli
