// What `uvtk render` and a scene's render output draw, set up without the command line: a texture
// bound by name (procedural, image files, cube maps), the renderer's options for a frame, and the
// textured picture or the inspection views, in memory or written.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/image.h"
#include "inspect/mapped_mesh.h"
#include "io/atomic_file.h"
#include "render/camera.h"
#include "render/renderer.h"
#include "render/texture.h"
#include "views/views.h"

namespace uvtk::inspect {

// A loaded texture: 2D or a cube map.
struct BoundTexture {
  std::optional<render::Texture> flat;
  std::optional<render::CubeTexture> cube;
};

// Whether `source` names a cube map: cube[:N], cubeindex[:N], cubefaces:..., cubecross:...,
// cubestrip:..., cube3x2:... (the word bare or before a colon).
bool isCubeMapSource(const std::string& source);
// The image files `source` reads: none for a procedural texture; UsageError for a malformed source.
std::vector<std::string> textureFiles(const std::string& source);
// `source` with each of its files replaced by resolve(file) (a scene's, against its folder).
std::string resolveTextureFiles(const std::string& source,
                                const std::function<std::string(const std::string& file)>& resolve);
// The texture `source` names, with mipmaps only when `filter` reads them.
BoundTexture loadTexture(const std::string& source, render::Filter filter);

// How a frame samples and shades its texture.
struct TextureOptions {
  render::Filter filter = render::Filter::Nearest;  // minification filter
  render::Wrap wrap = render::Wrap::Repeat;         // of s and t (a cube map's: of each face)
  render::EnvMode env = render::EnvMode::Replace;   // texture environment
  Vec4 envColour = Vec4::Zero();                    // GL_TEXTURE_ENV_COLOR for blend
  bool seamless = false;                            // cube maps: filter across face edges
  bool twoSided = false;                            // lighting: GL_LIGHT_MODEL_TWO_SIDE
};

// What a frame draws and how.
struct FrameOptions {
  int width = 512, height = 512;               // pixels
  render::Cull cull = render::Cull::Back;      // face culling; front faces are counter-clockwise
  int threads = 0;                             // 0: one per hardware thread
  int samplesPerPixel = 1;                     // a regular n x n grid, box-filtered
  Vec3 background = Vec3::Zero();              // colour r,g,b in [0, 1]
  bool perPixel = false;                       // evaluate the mapping at every pixel (else per vertex)
  bool baked = false;                          // per vertex: the camera projector's divided (u, v), not (s, t, q)
  render::Derivatives derivatives = render::Derivatives::Analytic;  // how the level of detail's derivatives are taken
  render::SeamFix seamFix = render::SeamFix::None;                  // with quad derivatives
  std::vector<std::string> aovs;               // the float AOV channels (Rendering::aovs names); none: no AOVs
  std::vector<views::View> views;              // inspection views instead of the textured picture
  views::View layoutFill = views::View::Stretch;  // the measure that fills the layout view
  int layoutSize = 512;                        // pixels across the layout view's UV square
  std::optional<int> bleedLevel;               // the bleed view's mip level (unset: where charts first mix)
  int checks = 16;                             // the checker view's checks across the unit square

  bool showsMeasures() const;  // a view draws distortion measures
  bool needsExact() const;     // per-pixel UVs or the uverror view
  bool samplesTexture() const { return views.empty(); }  // the textured picture; views draw their own
};

// The renderer's options for a frame: camera, texture (which must outlive them), sampling.
render::RenderOptions renderOptions(const FrameOptions& frame, const TextureOptions& texture,
                                    const BoundTexture& bound, const render::Camera& camera,
                                    const Mat4& worldFromObject);

// One inspection view of `mapped` with its legend, in memory; `judgement` may be null for a view
// without measures.
Image renderView(views::View view, const MappedMesh& mapped, const analysis::Judgement* judgement,
                 const views::ViewOptions& options);

// A frame in memory: the picture (the textured one, or the views, several as a contact sheet),
// the AOVs when asked for, and the JSON record of the frame (without its output files).
struct DrawnFrame {
  Image picture;
  std::optional<Image> aovs;
  nlohmann::json record;
};

// Draws `mapped` as `frame` asks; `judgement` is called only when a view shows measures. A frame
// that needs the exact mapping (FrameOptions::needsExact) needs a mapped.exact.
DrawnFrame drawFrame(const FrameOptions& frame, const MappedMesh& mapped, const render::RenderOptions& options,
                     const std::function<const analysis::Judgement&()>& judgement);

// drawFrame, staged in `outputs`: the picture at `output`, the AOVs at `aovOutput`. Returns the
// record of the frame.
nlohmann::json writeFrame(io::OutputSet& outputs, const FrameOptions& frame, const std::string& output,
                          const std::string& aovOutput, const MappedMesh& mapped,
                          const render::RenderOptions& options,
                          const std::function<const analysis::Judgement&()>& judgement);

}  // namespace uvtk::inspect
