// The verification renderer: a mesh with texture coordinates from any source (a file, a
// projector, texgen) drawn as OpenGL's fixed-function pipeline draws it, or with the mapping
// evaluated exactly at every pixel. Tile by tile, the visibility (render/raster.h), then each
// visible pixel shaded once while the tile is in cache: perspective-correct texture coordinates
// and their analytic derivatives, GL's level of detail and filters, the texture environment.
// docs/conventions.md §7 and §9. Supersampling draws the same frame at n times the width and
// height and box-filters each n x n block.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/image.h"
#include "core/mesh.h"
#include "render/camera.h"
#include "render/cube_texture.h"
#include "render/raster.h"
#include "render/shading.h"
#include "render/texture.h"

namespace uvtk::render {

// Three lookups blended per pixel (triplanar): their texture coordinates and weights at a point.
struct TexcoordBlend {
  std::array<Vec2, 3> st;
  Vec3 weights = Vec3::Zero();  // weights >= 0, sum 1; a non-finite st or weights: no value
};

// Texture coordinates evaluated at each pixel: the fragment's object-space position (interpolated
// perspective-correctly) and unit normal (interpolated and renormalised) go through the mapping.
// Exactly one of texcoordAt and blendAt is set.
struct PixelMapping {
  // (s, t, r, q) at a point of triangle `face`; non-finite where the mapping has no value.
  std::function<Vec4(const Vec3& position, const Vec3& normal, std::int32_t face)> texcoordAt;
  bool wrapsS = false;  // s has period 1: its derivatives take the nearest difference
  bool needsNormal = false;
  // Set instead of texcoordAt: the colour is sum_i w_i texture_i(st_i), each lookup with its own
  // derivatives (central differences of its st) and level of detail, the weights taken at the
  // fragment alone. A lookup of weight 0 is not made. Non-finite weights, or a non-finite st of
  // positive weight, show what texcoordAt's non-finite value shows. 2D textures only.
  std::function<TexcoordBlend(const Vec3& position, const Vec3& normal, std::int32_t face)> blendAt{};
};

// Where the texture coordinates come from: per corner (interpolated), or per pixel.
struct TexcoordSource {
  std::vector<Vec4> corners;                 // (s, t, r, q), 3 per triangle; used without pixelMapping
  std::optional<PixelMapping> pixelMapping;  // evaluated at every pixel instead
  // With a cube-map texture: r is a cube face id (0..5, GL's order; the cube projector's faces
  // layout) and (s, t) the point on that face, instead of (s, t, r) / q being a direction.
  bool cubeFaceIds = false;
};

// How the texture coordinates' screen-space derivatives (and so the level of detail) are taken.
// Analytic: exact at the pixel (per-pixel mappings: central differences a thousandth of a pixel
// apart, across a wrap the nearest difference). QuadCoarse, QuadFine: as a GPU's dFdxCoarse/dFdxFine
// (GLSL 4.60 §8.14.2), differences of the coordinates at the centres of the 2 x 2 pixel quad, the
// triangle's attributes extrapolated to those of its pixels it does not cover (helper invocations);
// coarse takes the quad's bottom row and left column (window y up) for all four pixels, fine each
// pixel's own row and column. Raw differences: across a wrap of a per-pixel mapping they jump by
// about 1, the coarsest level is chosen there, and the "seam line" a GPU shows appears.
enum class Derivatives { Analytic, QuadCoarse, QuadFine };

// What a shader does about that line (with quad derivatives; ignored with analytic ones).
// Grad: textureGrad with the analytic derivatives, i.e. the analytic level of detail.
// Tarini: per pixel, s taken as fract(s) or fract(s + 1/2) - 1/2, whichever has the smaller quad
// difference |ds/dx| + |ds/dy| (Tarini 2012, "Cylindrical and Toroidal Parameterizations Without
// Vertex Seams"); the lookup itself reads s unchanged, equal to either modulo 1. Per-pixel
// mappings that wrap in s only.
enum class SeamFix { None, Grad, Tarini };

const char* toString(Derivatives derivatives);  // "analytic", "quad-coarse", "quad-fine"
const char* toString(SeamFix fix);              // "none", "grad", "tarini"

struct RenderOptions {
  Camera camera;
  Derivatives derivatives = Derivatives::Analytic;
  SeamFix seamFix = SeamFix::None;
  double lodBias = 0.0;  // GL's TEXTURE_LOD_BIAS: added to lambda before the level is chosen
  Mat4 worldFromObject = Mat4::Identity();
  RasterOptions raster;
  // The bound texture, 2D or cube map (exactly one), with its mipmaps when the filter needs them.
  const Texture* texture = nullptr;
  const CubeTexture* cubeTexture = nullptr;
  // With a blend (PixelMapping::blendAt), lookup i reads axisTextures[i] when set, else `texture`;
  // each with its own size for the level of detail, its mipmaps when the filter needs them.
  std::array<const Texture*, 3> axisTextures{};
  SamplerState sampler;
  bool seamless = false;  // cube maps: GL's TEXTURE_CUBE_MAP_SEAMLESS
  EnvMode env = EnvMode::Replace;
  Vec4 envColour = Vec4::Zero();  // GL_TEXTURE_ENV_COLOR, read by BLEND
  Lighting lighting;
  Vec3 background = Vec3::Zero();
  bool aovs = false;  // also fill Rendering::aovs
  // n^2 for an n x n grid of samples in each pixel, at offsets ((i + 0.5) / n, (j + 0.5) / n):
  // the frame is drawn at n times the width and height (same projection, each sample the centre
  // of a pixel of that frame, its level of detail from that pixel's footprint) and each pixel's
  // colour is the mean of its samples. One of 1, 4, 9, ..., 256.
  int samplesPerPixel = 1;
};

struct Rendering {
  Image colour;  // RGB, row 0 at the top
  // With RenderOptions::aovs: channels u, v (s/q, t/q as interpolated, before wrapping), depth
  // (window depth), face (triangle index, -1 for the background) and lod (lambda); the background
  // has u = v = lod = 0 and depth 1. With a blend, u, v and lod are those of the lookup of largest
// weight (of equal weights the first, x before y before z). With a cube map, u and v are the (s, t) on the selected face
  // and a sixth channel, cubeface, holds its id (0..5; -1 on the background and where there is no
  // direction). With n x n samples per pixel, every channel is that of the
  // single sample (n/2, n/2) (integer division; column, row from the top left): the pixel's centre
  // for odd n, half a sample right of and below it for even n; lod is then that of the sample's
  // smaller footprint, log2(n) below the pixel's.
  Image aovs;
  RasterStats raster;                    // of the frame drawn, n times larger a side with supersampling
  std::size_t coveredPixels = 0;         // pixels where the mesh covers at least one sample
  // rasterMs: the vertices to clip space, the triangles' set-up and binning into tiles; shadeMs:
  // each tile's edge and depth tests and its shading, and the box filter.
  double rasterMs = 0.0, shadeMs = 0.0;
};

// Throws UsageError when the texture coordinates do not match the mesh (3 per triangle) and
// there is no pixel mapping, when SeamFix::Tarini has no per-pixel mapping that wraps in s, when
// there is no texture or two, when a blend has a cube map, when samplesPerPixel is not one of the
// allowed squares, or when the supersampled frame exceeds kMaxViewport pixels a side.
Rendering render(const Mesh& mesh, const TexcoordSource& texcoords, const RenderOptions& options);

struct TileScratch;  // a worker's tile and fragments (renderer.cpp)

// A renderer that keeps its buffers from one frame to the next (the clip positions, the raster's
// set-up and bins, the images), as a GL context keeps its framebuffer and bins: frames of one
// size allocate, and fault in, their memory once. render() above is one frame of a new renderer.
class Renderer {
 public:
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // The frame, as render() draws it, valid until the next call. Throws as render().
  const Rendering& render(const Mesh& mesh, const TexcoordSource& texcoords, const RenderOptions& options);
  // The last frame, moved out (its buffers are then drawn afresh by the next call).
  Rendering take() { return std::move(frame_); }

 private:
  std::vector<Vec4> clip_;
  TiledRaster raster_;
  Rendering frame_, samples_;               // samples_: the supersampled frame before the box filter
  std::vector<std::uint8_t> sampleCovered_;  // per sample of samples_
  std::vector<std::unique_ptr<TileScratch>> scratch_;  // per worker thread
};

}  // namespace uvtk::render
