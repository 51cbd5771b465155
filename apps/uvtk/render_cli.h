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

#include "mapped_mesh.h"
#include "render/camera.h"
#include "render/renderer.h"
#include "render/texture.h"
#include "views/views.h"

namespace uvtk::cli {

// The minification filters by their GL names in lower case.
extern const std::vector<std::pair<std::string, render::Filter>> kFilterNames;

struct CameraArguments {
  enum class Mode { Auto, Explicit };
  Mode mode = Mode::Auto;
  std::string eye, center = "0,0,0", up = "0,1,0", viewDir = "0,0,1", ortho;
  double fovy = 45.0;
  std::optional<double> zNear, zFar;
  CLI::App* app = nullptr;  // where the options were parsed; none: the defaults

  // gluLookAt + gluPerspective or glOrtho as given, or framing the mesh (`worldFromObject`
  // applied) when automatic; throws UsageError for malformed or conflicting values.
  render::Camera make(const Mesh& mesh, const Mat4& worldFromObject, int width, int height) const;
  void check() const;  // what make() would refuse, before any work
  bool explicitCamera() const;
};
void addCameraOptions(CLI::App& app, CameraArguments& arguments);

struct TextureArguments {
  std::string source = "checker:64:8";
  render::Filter filter = render::Filter::Nearest;
  render::Wrap wrap = render::Wrap::Repeat;
  render::EnvMode env = render::EnvMode::Replace;
  std::string envColour = "0,0,0,0";

  bool procedural() const;
  // The texture, with mipmaps only when the filter reads them.
  render::Texture load() const;
};
// `sourceOption` is "--texture" in `uvtk render`; a scene's texture calls it "--source".
void addTextureOptions(CLI::App& app, TextureArguments& arguments, const std::string& sourceOption);

struct FrameArguments {
  enum class Uv { PerVertex, PerPixel };
  std::string size = "512x512";
  render::Cull cull = render::Cull::Back;
  int threads = 0;
  int samplesPerPixel = 1;
  std::string background = "0,0,0";
  Uv uv = Uv::PerVertex;
  std::string aov, aovOutput;
  std::string view;  // inspection views instead of the textured picture
  views::View layoutFill = views::View::Stretch;
  int layoutSize = 512;

  // Checks the values for a frame written to `output` (and fills the default AOV file name);
  // throws UsageError. Nothing is written when a check fails.
  void check(const std::string& output);
  std::pair<int, int> imageSize() const;
  std::vector<views::View> views() const;
  bool showsMeasures() const;  // a view draws distortion measures
  bool needsExact() const;     // per-pixel UVs or the uverror view
};
void addFrameOptions(CLI::App& app, FrameArguments& arguments);

// The renderer's options for a frame: camera, texture (which must outlive them), sampling.
render::RenderOptions renderOptions(const FrameArguments& frame, const TextureArguments& texture,
                                    const render::Texture* image, const render::Camera& camera,
                                    const Mat4& worldFromObject);

// Draws `mapped` into `output` as `frame` asks: the textured picture (and AOVs), or the inspection
// views; `measures` is called only when a view shows distortion. Returns the JSON record of the frame.
// A frame that needs the exact mapping (FrameArguments::needsExact) needs a mapped.exact.
nlohmann::json drawFrame(const FrameArguments& frame, const std::string& output, const MappedMesh& mapped,
                         const render::RenderOptions& options,
                         const std::function<const MappedMesh::Measures&()>& measures);

}  // namespace uvtk::cli
