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
#include "options/projector_cli.h"
#include "options/texgen_cli.h"
#include "options/view_camera_cli.h"
#include "render/camera.h"
#include "render/renderer.h"
#include "render/texture.h"
#include "views/views.h"

namespace uvtk::cli {

// The minification filters by their GL names in lower case; the wrap modes, texture environments
// and face culling modes by the values their options take.
extern const std::vector<std::pair<std::string, render::Filter>> kFilterNames;
extern const std::vector<std::pair<std::string, render::Wrap>> kWrapNames;
extern const std::vector<std::pair<std::string, render::EnvMode>> kEnvNames;
extern const std::vector<std::pair<std::string, render::Cull>> kCullNames;

struct CameraArguments {
  enum class Mode { Auto, Explicit };
  Mode mode = Mode::Auto;
  // up "": 0,0,1 for the automatic camera along viewDir (report's views' camera), 0,1,0 with an eye
  std::string eye, center = "0,0,0", up, viewDir = kViewDirection, ortho;
  double fovy = 45.0;
  std::optional<double> zNear, zFar;
  CLI::App* app = nullptr;  // where the options were parsed; none: the defaults

  // gluLookAt + gluPerspective or glOrtho as given, or framing the mesh (`worldFromObject`
  // applied) when automatic; throws UsageError for malformed or conflicting values, and InputError
  // naming `meshFile` for a mesh too large to frame.
  render::Camera make(const Mesh& mesh, const std::string& meshFile, const Mat4& worldFromObject, int width,
                      int height) const;
  void check() const;  // what make() would refuse, before any work
  bool explicitCamera() const;
};
// --camera, --eye, --center, --up, --view-dir, --fovy, --near, --far, --ortho; without `lookAt`, not
// --eye, --center, --up, --view-dir and --fovy (a command that has them under those names already).
void addCameraOptions(CLI::App& app, CameraArguments& arguments, bool lookAt = true);

struct TextureArguments {
  std::string source = "checker:64:8";
  render::Filter filter = render::Filter::Nearest;
  std::string wrap;  // --wrap as given, empty when not; wrapMode() is the mode used
  render::EnvMode env = render::EnvMode::Replace;
  std::string envColour = "0,0,0,0";
  bool seamless = false;
  bool twoSided = false;

  // Whether the source names a cube map: cube[:N], cubeindex[:N], cubefaces:..., cubecross:...,
  // cubestrip:..., cube3x2:... (the word bare or before a colon).
  bool cubeMap() const;
  // The image files the source reads (none for a procedural texture; UsageError for a malformed
  // source), and the source with each replaced by resolve(file) (a scene's, against its folder).
  std::vector<std::string> files() const;
  void resolveFiles(const std::function<std::string(const std::string& file)>& resolve);
  // Throws UsageError for a malformed source or --seamless with a 2D texture, before any work.
  void check() const;
  // --wrap, else clamp_to_edge for a cube map (GL's default REPEAT would filter a face's edge with
  // its opposite edge) and repeat for a 2D texture.
  render::Wrap wrapMode() const;
  // The texture, with mipmaps only when the filter reads them.
  inspect::BoundTexture load() const;
  // The sampling and shading as the renderer takes them; throws UsageError for a malformed --env-color.
  inspect::TextureOptions options() const;
};
// `sourceOption` is "--texture" in `uvtk render`; a scene's texture calls it "--source".
void addTextureOptions(CLI::App& app, TextureArguments& arguments, const std::string& sourceOption);

struct FrameArguments {
  enum class Uv { PerVertex, PerPixel, Baked };
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

  // Checks the values for a frame written to `output` (and fills the default AOV file name);
  // throws UsageError. Nothing is written when a check fails.
  void check(const std::string& output);
  std::pair<int, int> imageSize() const;
  std::vector<views::View> views() const;
  bool showsMeasures() const;  // a view draws distortion measures
  bool needsExact() const;     // per-pixel UVs or the uverror view
  analysis::TextureSize densityTexture() const;  // --texture-size
  // The values as the renderer takes them, once check() has passed.
  inspect::FrameOptions options() const;
};
// --size, --cull, --background and --uv: the frame's options that `uvtk bench --render` shares
// (its --threads and --spp are lists of values to time).
void addFrameSceneOptions(CLI::App& app, FrameArguments& arguments);
// addFrameSceneOptions, then --threads, --spp, the AOVs and the inspection views.
void addFrameOptions(CLI::App& app, FrameArguments& arguments);

// Throws UsageError unless `frame` can draw `texture` with texture coordinates from `projector`
// (none: texgen's or the file's, which are directions to a cube map): a cube map needs directions or
// the cube projector's face ids, and the cubeface AOV a cube map. Before any work.
void checkTextureUse(const FrameArguments& frame, const TextureArguments& texture,
                     const param::ProjectorOptions* projector);

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
