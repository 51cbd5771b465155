// The rasterizer's visibility pass: triangles in clip space in, for every pixel the nearest
// triangle covering its centre out (depth test LESS on a float depth buffer, cleared to 1).
// Clipping against the near and far planes (and a wide guard band) in homogeneous space,
// vertices snapped to 1/256 pixel, coverage by exact integer edge functions with the top-left
// rule, so that triangles sharing an edge cover each pixel centre on it exactly once.
// docs/conventions.md §7.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/math.h"
#include "core/mesh.h"

namespace uvtk::render {

enum class Cull { None, Back, Front };  // front faces are counter-clockwise in window coordinates

struct RasterOptions {
  Cull cull = Cull::Back;
  int threads = 0;  // 0: one per hardware thread; the output does not depend on it
};

// Per pixel, row 0 at the top of the image (window row height - 1).
struct VisibilityBuffer {
  int width = 0, height = 0;
  std::vector<std::int32_t> face;  // triangle index, -1 where nothing was drawn
  std::vector<float> depth;        // window depth in [0, 1]; 1 where nothing was drawn

  std::size_t index(int x, int row) const { return std::size_t(row) * std::size_t(width) + std::size_t(x); }
};

struct RasterStats {
  std::size_t culled = 0;   // triangles removed by face culling
  std::size_t clipped = 0;  // triangles entirely outside the near-far range or the guard band
  std::size_t drawn = 0;    // triangles that reached the edge tests
};

constexpr int kMaxViewport = 16384;  // pixels a side

// Perspective-correct barycentric coordinates of one triangle at any point of the window, from its
// unclipped clip-space corners: with M the 3 x 3 matrix of the corners' (x, y, w) as columns,
// k = M^-1 (X_ndc, Y_ndc, 1) and b = k / (k0 + k1 + k2), which is the interpolation rule
// a = sum(l_i a_i / w_i) / sum(l_i / w_i) in closed form; the derivatives are analytic.
class TriangleInterpolator {
 public:
  TriangleInterpolator(const Vec4& c0, const Vec4& c1, const Vec4& c2, int width, int height);

  bool valid() const { return valid_; }  // false when the triangle is seen edge-on (M singular)

  struct Barycentrics {
    Vec3 b;     // sums to 1
    Vec3 dbdx;  // per pixel to the right
    Vec3 dbdy;  // per pixel up the window (one image row towards the top)
  };
  // At window coordinates (x, y) with y up; the centre of image pixel (i, row) is
  // (i + 0.5, height - row - 0.5).
  Barycentrics at(double x, double y) const;

  // Normalised device depth z/w = a x + b y + c at window (x, y): the coefficients (a, b, c).
  const Vec3& ndcDepthPlane() const { return depthPlane_; }
  // The 3 x 3 matrix whose row i gives k_i = a x + b y + c at window (x, y), column-major: at()
  // reads these nine numbers (and the vectorised shading, render/fragment_simd.h, too).
  const Eigen::Matrix3d& kFromWindow() const { return kFromWindow_; }

 private:
  bool valid_ = false;
  Eigen::Matrix3d kFromWindow_;  // row i: k_i as a x + b y + c in window coordinates
  Vec3 depthPlane_ = Vec3::Zero();
};

// M^-1 for an invertible 3 x 3 M, bit for bit Eigen's M.inverse() (the same operations in the same
// order) at a lower cost in every triangle's set-up (one determinant, no expression templates).
Mat3 inverse3x3(const Mat3& m);

// One drawn triangle's set-up, made once by the rasterizer and shared by the shading of its pixels.
struct DrawnFace {
  std::int32_t face;
  bool front;                         // counter-clockwise in window coordinates (GL's facing)
  TriangleInterpolator interpolator;  // valid: a triangle seen edge-on is not drawn
};

// The frame's triangles set up and binned into square tiles once; each tile is then drawn on its
// own, on any thread and in any order, so that a caller can shade a tile while it is in cache.
// Within a tile the triangles are drawn in input order, whatever the thread count. setUp keeps
// its buffers from one frame to the next (as a GL context keeps its bins): a renderer drawing
// frames of a million triangles faults no new pages once the first frame has grown them.
class TiledRaster {
 public:
  static constexpr int kTileSize = 64;

  TiledRaster();  // nothing set up: no tiles
  // As setUp.
  TiledRaster(const std::vector<Vec4>& clip, const std::vector<Triangle>& triangles, int width, int height,
              const RasterOptions& options);
  TiledRaster(const TiledRaster&) = delete;  // tiles point into the set-up
  TiledRaster& operator=(const TiledRaster&) = delete;
  ~TiledRaster();

  // `clip`: clip-space positions, indexed by `triangles`. Throws UsageError for an empty or too
  // large viewport (more than kMaxViewport pixels a side). Replaces the previous frame's set-up.
  void setUp(const std::vector<Vec4>& clip, const std::vector<Triangle>& triangles, int width, int height,
             const RasterOptions& options);

  int tileCount() const { return tilesX_ * tilesY_; }
  const RasterStats& stats() const { return stats_; }
  // Every drawn face's set-up lies in this one array (the faces a Tile points to), at most one per
  // input triangle: whatever reads them by index from one base (SIMD gathers) can.
  const DrawnFace* drawnFaces() const { return drawnFaces_; }

  // A tile's pixels in window coordinates (y up), inclusive, and what it sees: per pixel
  // (x, y), at index (y - y0) * kTileSize + (x - x0), the nearest triangle (null where nothing
  // was drawn) and its window depth (1 there).
  struct Tile {
    int x0 = 0, x1 = -1, y0 = 0, y1 = -1;
    std::array<const DrawnFace*, kTileSize * kTileSize> face;
    std::array<std::int32_t, kTileSize * kTileSize> faceIndex;  // face[i]->face where face[i] is set, read without it
    std::array<float, kTileSize * kTileSize> depth;
  };
  void draw(int tile, Tile& out) const;

  struct Chunk;  // the set-up and bins of a run of consecutive triangles (raster.cpp)

 private:
  int width_ = 0, height_ = 0, tilesX_ = 0, tilesY_ = 0;
  std::vector<std::int64_t> window_;  // per vertex, snapToWindow's (render/raster_simd.h)
  // Room for one DrawnFace per triangle, constructed only where a face is drawn (chunk c's from
  // its first triangle's index on), so that memory is touched only by drawn faces.
  std::unique_ptr<std::byte[]> drawnStorage_;
  std::size_t drawnCapacity_ = 0;
  DrawnFace* drawnFaces_ = nullptr;
  std::vector<Chunk> chunks_;
  RasterStats stats_;
};

// `clip` = clipFromObject times each of mesh's positions, then, where every vertex's clip
// coordinates lie beyond 2^400 or all below 2^-400 (a mesh at 1e200 or 1e-200 framed by its
// camera), times one power of two that brings them to about 1: homogeneous, the same frame, but
// the set-up's products of coordinates neither overflow nor underflow; any other frame keeps its
// bits. `clip`'s storage is kept when large enough. `threads` (0: one per core) share the vertices.
void clipPositions(const Mesh& mesh, const Mat4& clipFromObject, int threads, std::vector<Vec4>& clip);

// The visibility of the whole frame: TiledRaster's tiles drawn into one buffer.
VisibilityBuffer rasterize(const std::vector<Vec4>& clip, const std::vector<Triangle>& triangles, int width, int height,
                           const RasterOptions& options, RasterStats* stats = nullptr);

}  // namespace uvtk::render
