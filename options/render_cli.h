// The option groups of `uvtk render`, shared with scene files (uvtk run): the camera, the texture
// and the frame (size, culling, sampling, what is drawn). A scene's camera, texture and render
// output take the same options under the same names.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "io/atomic_file.h"
#include "inspect/frame.h"
#include "inspect/mapped_mesh.h"
#include "inspect/render_parameters.h"
#include "options/projector_cli.h"
#include "options/texgen_cli.h"
#include "options/view_camera_cli.h"
#include "render/camera.h"
#include "render/renderer.h"
#include "render/texture.h"
#include "views/views.h"

namespace uvtk::cli {

using inspect::kCullNames;
using inspect::kEnvNames;
using inspect::kFilterNames;
using inspect::kWrapNames;

// The options as the command line gives them; settings() hands the given ones to the engine's
// reader (inspect/render_parameters.h) as typed parameters.
struct CameraArguments {
  enum class Mode { Auto, Explicit };
  Mode mode = Mode::Auto;
  // up "": 0,0,1 for the automatic camera along viewDir (report's views' camera), 0,1,0 with an eye
  std::string eye, center = "0,0,0", up, viewDir = kViewDirection, ortho;
  double fovy = 45.0;
  std::optional<double> zNear, zFar;
  CLI::App* app = nullptr;  // where the options were parsed; none: the defaults

  void addTo(param::ParameterDictionary& parameters) const;  // the given ones, typed
  // UsageError for malformed or conflicting values.
  inspect::CameraSettings settings() const;
};
// --camera, --eye, --center, --up, --view-dir, --fovy, --near, --far, --ortho; without `lookAt`, not
// --eye, --center, --up, --view-dir and --fovy (a command that has them under those names already).
void addCameraOptions(CLI::App& app, CameraArguments& arguments, bool lookAt = true);

struct TextureArguments {
  std::string source = "checker:64:8";
  render::Filter filter = render::Filter::Nearest;
  std::string wrap;  // --wrap as given, empty when not
  render::EnvMode env = render::EnvMode::Replace;
  std::string envColour = "0,0,0,0";
  bool seamless = false;
  bool twoSided = false;
  CLI::App* app = nullptr;  // where the options were parsed: tells --filter given from its default

  void addTo(param::ParameterDictionary& parameters) const;  // as "texture", "filter", ...
  // UsageError for a malformed source or value, --seamless with a 2D texture.
  inspect::TextureSettings settings() const;
};
// `sourceOption` is "--texture" in `uvtk render`.
void addTextureOptions(CLI::App& app, TextureArguments& arguments, const std::string& sourceOption);

struct FrameArguments {
  using Uv = inspect::UvSource;
  std::string size = "512x512";
  render::Cull cull = render::Cull::Back;
  int threads = 0;
  int samplesPerPixel = 1;
  std::string background = "0,0,0";
  Uv uv = Uv::PerVertex;
  render::Derivatives derivatives = render::Derivatives::Analytic;
  render::SeamFix seamFix = render::SeamFix::None;
  std::string aov, aovOutput;
  std::string view;  // inspection views instead of the textured picture
  views::View layoutFill = views::View::Stretch;
  int layoutSize = 512;
  std::optional<int> bleedLevel;  // the bleed view's mip level
  int checks = 16;  // the checker view's checks across the unit square
  std::string textureSize = "1024,1024";  // W,H or N: the texture the density view counts texels of
  CLI::App* app = nullptr;  // where the options were parsed: tells --uv given from its default

  // The options addFrameSceneOptions registers, typed.
  void addSceneTo(param::ParameterDictionary& parameters) const;
  // UsageError for a malformed value or a combination that makes no sense.
  inspect::FrameSettings settings() const;
};
// --size, --cull, --background, --uv, --derivatives and --seam-fix: the frame's options that `uvtk
// bench --render` shares (its --threads and --spp are lists of values to time).
void addFrameSceneOptions(CLI::App& app, FrameArguments& arguments);
// addFrameSceneOptions, then --threads, --spp, the AOVs and the inspection views.
void addFrameOptions(CLI::App& app, FrameArguments& arguments);

// `uvtk render` on one mesh file: the paths and the option groups as parsed.
struct RenderJob {
  std::string input, output, json, model;  // model: --model's 16 numbers, empty for the identity
  CameraArguments camera;
  TextureArguments texture;
  FrameArguments frame;
  ProjectorArguments projector;
  TexgenArguments texgen;
};

struct RenderResult {
  nlohmann::json record;  // the JSON summary, written when the job names a file
  std::string line;       // "WxH, N faces drawn, ..." for the textured picture; empty when views were drawn
};

// Checks every option before any work (UsageError), reads the mesh, makes the camera, maps the
// mesh (the projector, its reflection O-mapping seeing from the camera's eye; texgen under the
// camera's view; or the file's UVs), loads the texture, draws, publishes the outputs together and
// prints the input's and the mapping's notes.
RenderResult renderMeshFile(RenderJob job);

}  // namespace uvtk::cli
