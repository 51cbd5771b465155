// The camera, the texture and the frame of a picture as typed parameters: `uvtk render`'s
// options, a scene's cameras, textures and render outputs, `uvtk bench --render`, the library's
// RenderOptions and Python's render() keywords fill a dictionary, and these read it once, with the
// rules of which parameters go together.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analysis/judgement.h"
#include "core/names.h"
#include "inspect/frame.h"
#include "param/parameters.h"
#include "param/projector.h"

namespace uvtk::inspect {

// The minification filters by their GL names in lower case; the wrap modes, texture environments
// and face culling modes by the values their parameters take.
extern const ChoiceNames<render::Filter> kFilterNames;
extern const ChoiceNames<render::Wrap> kWrapNames;
extern const ChoiceNames<render::EnvMode> kEnvNames;
extern const ChoiceNames<render::Cull> kCullNames;
// Where a frame's texture coordinates come from: interpolated per vertex, the mapping at every
// pixel, or the camera projector's divided (u, v) per vertex as an OBJ holds them.
enum class UvSource { PerVertex, PerPixel, Baked };
extern const ChoiceNames<UvSource> kUvNames;
extern const ChoiceNames<render::Derivatives> kDerivativeNames;
extern const ChoiceNames<render::SeamFix> kSeamFixNames;
extern const ChoiceNames<views::View> kLayoutFillNames;  // the measures the layout view fills with

// A frame's camera: automatic (framing the mesh's bounding sphere along viewDir, or eye - center)
// or explicit (gluLookAt + gluPerspective, or glOrtho).
struct CameraSettings {
  std::optional<bool> explicitMode;  // "camera" as given: explicit; unset: explicit when eye is given
  std::optional<Vec3> eye;
  Vec3 center = Vec3::Zero();
  std::optional<Vec3> up;  // unset: 0,0,1 along viewDir (0,1,0 within 18 degrees of z), 0,1,0 with an eye
  Vec3 viewDir = ViewCamera{}.viewDir;
  double fovy = 45.0;
  std::optional<double> zNear, zFar;  // explicit camera; 0.1 and 100 when unset
  bool orthoAuto = false;             // glOrtho framing the mesh (automatic camera)
  std::optional<Vec4> orthoBox;       // glOrtho left, right, bottom, top

  bool explicitCamera() const { return explicitMode.value_or(eye.has_value()); }
  bool orthographic() const { return orthoAuto || orthoBox.has_value(); }
  // The camera for a picture of `mesh` (`worldFromObject` applied); InputError naming `meshFile`
  // for a mesh too large to frame.
  render::Camera make(const Mesh& mesh, const std::string& meshFile, const Mat4& worldFromObject, int width,
                      int height) const;
};

// camera, eye, center, up, view-dir, fovy, near, far, ortho; UsageError for a combination that
// makes no sense (an explicit camera without an eye, near with the automatic camera, ...).
CameraSettings readCameraSettings(const param::ParameterDictionary& parameters);
std::vector<std::string> cameraParameterNames();

// A texture by name (procedural, image files, cube maps) and how it is sampled and shaded.
struct TextureSettings {
  std::string source = "checker:64:8";
  render::Filter filter = render::Filter::Nearest;
  std::optional<render::Wrap> wrap;  // unset: clamp_to_edge for a cube map, repeat for a 2D texture
  render::EnvMode env = render::EnvMode::Replace;
  Vec4 envColour = Vec4::Zero();
  bool seamless = false;
  bool twoSided = false;

  bool cubeMap() const;
  std::vector<std::string> files() const;  // the image files the source reads
  void resolveFiles(const std::function<std::string(const std::string& file)>& resolve);
  render::Wrap wrapMode() const;
  BoundTexture load() const;  // with mipmaps only when the filter reads them
  TextureOptions options() const;
};

// `sourceName` ("texture" in `uvtk render`, "source" in a scene's texture), filter, wrap, env,
// env-color, seamless, two-sided; UsageError for a malformed source or seamless with a 2D texture.
TextureSettings readTextureSettings(const param::ParameterDictionary& parameters, const std::string& sourceName);
std::vector<std::string> textureParameterNames(const std::string& sourceName);

// What a frame draws, with what only its readers need: whether "uv" was given (a triplanar blend
// is drawn per pixel unless it was), the texture the density view counts texels in, and the AOV
// file of a command that writes one.
struct FrameSettings {
  FrameOptions frame;
  bool uvGiven = false;
  analysis::TextureSize densityTexture{1024, 1024};
  std::string aovOutput;
};

// size, cull, background, uv, derivatives, seam-fix, threads, spp, aov, aov-output, view,
// layout-fill, layout-size, bleed-level, checks, texture-size; UsageError for a value out of range
// or a combination that makes no sense (views with AOVs).
FrameSettings readFrameSettings(const param::ParameterDictionary& parameters);
std::vector<std::string> frameParameterNames();
// Those `uvtk bench --render` takes (it times lists of threads and samples): size, cull,
// background, uv, derivatives, seam-fix.
FrameSettings readFrameSceneSettings(const param::ParameterDictionary& parameters);
std::vector<std::string> frameSceneParameterNames();

// Checks that `frame` can be written to `output` (the picture's type, the AOVs' file, which
// defaults to the output with .exr), before any work; UsageError.
void checkFrameOutputs(FrameSettings& frame, const std::string& output);

// UsageError unless `frame` can draw `texture` with texture coordinates from `projector` (none:
// texgen's or the file's, which are directions to a cube map): a cube map needs directions or the
// cube projector's face ids, and the cubeface AOV a cube map.
void checkTextureUse(const FrameOptions& frame, const TextureSettings& texture,
                     const param::ProjectorOptions* projector);

}  // namespace uvtk::inspect
