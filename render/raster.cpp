#include "render/raster.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <type_traits>

#include "core/error.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/huge_pages.h"
#include "render/raster_simd.h"

namespace uvtk::render {

namespace {


constexpr int kSubpixelBits = 8;  // vertices snap to 1/256 pixel, as GL hardware commonly does
constexpr std::int64_t kSubpixel = std::int64_t(1) << kSubpixelBits;
constexpr std::int64_t kHalfPixel = kSubpixel / 2;
constexpr int kTileSize = TiledRaster::kTileSize;

struct Point {
  std::int32_t x, y;  // below 2^28 in magnitude inside the guard band
};

// One triangle ready for the edge tests: counter-clockwise, snapped, with its pixel bounds and
// its face's set-up, which the shading of its pixels reads. A clipped face is a fan of several.
static_assert(std::is_trivially_destructible_v<DrawnFace>, "the drawn faces are never destroyed, only overwritten");

struct SetupTriangle {
  const DrawnFace* drawn;
  std::int32_t face;
  Vec3 depthPlane;  // window depth a x + b y + c (glDepthRange(0, 1)): drawing reads no DrawnFace
  Point v[3];
  int x0, x1, y0, y1;  // inclusive pixel range (window coordinates, y up)
};

// The clip-space half-spaces a visible point satisfies: near, far, and the guard band, wide
// enough to leave every visible pixel untouched and narrow enough that snapped window
// coordinates stay below 2^21 pixels (so edge functions fit in 64 bits).
struct ClipPlanes {
  double guard;
  double distance(int plane, const Vec4& p) const {
    switch (plane) {
      case 0:
        return p.w() + p.z();  // near
      case 1:
        return p.w() - p.z();  // far
      case 2:
        return guard * p.w() - p.x();
      case 3:
        return guard * p.w() + p.x();
      case 4:
        return guard * p.w() - p.y();
      default:
        return guard * p.w() + p.y();
    }
  }
  // Sets the clipped coordinate so that the point lies exactly on the plane: with huge corners
  // the interpolated coordinate alone would carry their rounding error.
  void putOn(int plane, Vec4& p) const {
    switch (plane) {
      case 0:
        p.z() = -p.w();
        break;
      case 1:
        p.z() = p.w();
        break;
      case 2:
        p.x() = guard * p.w();
        break;
      case 3:
        p.x() = -guard * p.w();
        break;
      case 4:
        p.y() = guard * p.w();
        break;
      default:
        p.y() = -guard * p.w();
        break;
    }
  }
};

using Polygon = std::array<Vec4, 9>;  // a triangle clipped by six planes has at most 9 corners

// Sutherland-Hodgman against one plane. The intersection is always computed from the inside
// corner towards the outside one, so two triangles sharing an edge get the same new corner and
// stay watertight.
int clipAgainst(const ClipPlanes& planes, int plane, const Polygon& in, int n, Polygon& out) {
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const Vec4& a = in[i];
    const Vec4& b = in[i + 1 < n ? i + 1 : 0];
    const double da = planes.distance(plane, a), db = planes.distance(plane, b);
    if (da >= 0.0) out[m++] = a;
    if ((da >= 0.0) != (db >= 0.0)) {
      const bool aInside = da >= 0.0;
      const Vec4& inside = aInside ? a : b;
      const Vec4& outside = aInside ? b : a;
      const double dIn = aInside ? da : db, dOut = aInside ? db : da;
      Vec4 p = inside + (dIn / (dIn - dOut)) * (outside - inside);
      planes.putOn(plane, p);
      out[m++] = p;
    }
  }
  return m;
}

// Twice the polygon's signed area, exact: coordinates below 2^28 make each cross term below 2^57,
// and nine of them stay below 2^61.
std::int64_t twiceArea(const Point* p, int n) {
  std::int64_t sum = 0;
  for (int i = 0; i < n; ++i) {
    const Point& a = p[i];
    const Point& b = p[i + 1 < n ? i + 1 : 0];
    sum += std::int64_t(a.x) * b.y - std::int64_t(b.x) * a.y;
  }
  return sum;
}

std::int64_t floorDiv(std::int64_t a, std::int64_t b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }

// The edge a -> b of a counter-clockwise triangle (window coordinates, y up) owns the pixel
// centres on it when it is a left edge (going down) or a top edge (horizontal, going left).
bool isTopLeft(const Point& a, const Point& b) {
  const std::int32_t dx = b.x - a.x, dy = b.y - a.y;
  return dy < 0 || (dy == 0 && dx < 0);
}

}  // namespace

// Aligned to a cache line: the threads setting up neighbouring chunks would otherwise share one
// (the counters change at every triangle), and two threads set up no faster than one.
struct alignas(64) TiledRaster::Chunk {
  std::vector<SetupTriangle> triangles;
  std::vector<std::vector<std::uint32_t>> tiles;  // per tile, indices into triangles
  DrawnFace* drawn = nullptr;                     // its faces' set-ups, drawnCount of them
  std::size_t drawnCount = 0;
  RasterStats stats;
};

namespace {

class Setup {
 public:
  Setup(int width, int height, int tilesX, const RasterOptions& options)
      : width_(width), height_(height), tilesX_(tilesX), options_(options) {
    planes_.guard = double(1 << 20) / double(std::max(width, height));
  }

  double guard() const { return planes_.guard; }

  // Triangles [begin, end) into `out`. `window`: per vertex, its snapped window position
  // (render/raster_simd.h): a triangle whose three corners lie inside every clip plane needs no
  // clipping, its corners are these points, and most are culled by the sign of their area alone,
  // in this loop; the others are clipped or drawn by functions of their own.
  void triangles(const std::vector<Vec4>& clip, const std::vector<std::int64_t>& window,
                 const std::vector<Triangle>& triangles, std::int64_t begin, std::int64_t end,
                 TiledRaster::Chunk& out) const {
    const auto point = [](std::int64_t w) { return Point{std::int32_t(w), std::int32_t(w >> 32)}; };
    for (std::int64_t f = begin; f < end; ++f) {
      const Triangle& corners = triangles[std::size_t(f)];
      std::array<Point, 9> p;
      p[0] = point(window[std::size_t(corners[0])]), p[1] = point(window[std::size_t(corners[1])]);
      p[2] = point(window[std::size_t(corners[2])]);
      if (p[0].x == kOutsideWindow || p[1].x == kOutsideWindow || p[2].x == kOutsideWindow) {
        clipped(clip, corners, std::int32_t(f), out);
        continue;
      }
      const std::int64_t area = twiceArea(p.data(), 3);
      if (!drawsArea(area)) {
        ++out.stats.culled;
        continue;
      }
      draw(clip, corners, std::int32_t(f), p, 3, area > 0, out);
    }
  }

 private:
  // Whether a polygon of twice this signed area is drawn (not empty, not culled).
  bool drawsArea(std::int64_t area) const {
    if (area == 0) return false;
    const bool front = area > 0;
    return !((options_.cull == Cull::Back && !front) || (options_.cull == Cull::Front && front));
  }

  // A triangle with a corner outside some clip plane: clipped, then drawn or culled.
  __attribute__((noinline)) void clipped(const std::vector<Vec4>& clip, const Triangle& corners, std::int32_t face,
                                         TiledRaster::Chunk& out) const {
    std::array<Point, 9> p;
    const Vec4 &c0 = clip[std::size_t(corners[0])], &c1 = clip[std::size_t(corners[1])], &c2 = clip[std::size_t(corners[2])];
    const int n = clipAndSnap(c0, c1, c2, p);
    if (n < 3) {
      ++out.stats.clipped;
      return;
    }
    const std::int64_t area = twiceArea(p.data(), n);
    if (!drawsArea(area)) {
      ++out.stats.culled;
      return;
    }
    draw(clip, corners, face, p, n, area > 0, out);
  }

  // A visible polygon (n corners, counter-clockwise if front): its face's set-up, and each
  // triangle of its fan with pixels binned into the tiles it overlaps.
  __attribute__((noinline)) void draw(const std::vector<Vec4>& clip, const Triangle& corners, std::int32_t face,
                                      const std::array<Point, 9>& p, int n, bool front, TiledRaster::Chunk& out) const {
    const TriangleInterpolator interpolator(clip[std::size_t(corners[0])], clip[std::size_t(corners[1])],
                                            clip[std::size_t(corners[2])], width_, height_);
    if (!interpolator.valid()) {  // seen edge-on: it covers no area
      ++out.stats.culled;
      return;
    }
    ++out.stats.drawn;
    const DrawnFace* drawn = new (out.drawn + out.drawnCount++) DrawnFace{face, front, interpolator};
    const Vec3 depthPlane = 0.5 * interpolator.ndcDepthPlane() + Vec3(0, 0, 0.5);  // glDepthRange(0, 1)
    for (int i = 1; i + 1 < n; ++i) {  // a fan over the convex polygon
      SetupTriangle t{drawn, face, depthPlane, {}, 0, 0, 0, 0};
      t.v[0] = p[0];
      t.v[1] = front ? p[i] : p[i + 1];
      t.v[2] = front ? p[i + 1] : p[i];
      const std::int64_t subArea = twiceArea(t.v, 3);
      if (subArea <= 0) continue;  // a sliver that snapping collapsed or turned over
      std::int64_t minX = t.v[0].x, maxX = minX, minY = t.v[0].y, maxY = minY;
      for (const Point& q : t.v) {
        minX = std::min<std::int64_t>(minX, q.x), maxX = std::max<std::int64_t>(maxX, q.x);
        minY = std::min<std::int64_t>(minY, q.y), maxY = std::max<std::int64_t>(maxY, q.y);
      }
      // Pixels whose centre i + 1/2 lies in [min, max].
      t.x0 = int(std::max<std::int64_t>(0, floorDiv(minX - kHalfPixel + kSubpixel - 1, kSubpixel)));
      t.x1 = int(std::min<std::int64_t>(width_ - 1, floorDiv(maxX - kHalfPixel, kSubpixel)));
      t.y0 = int(std::max<std::int64_t>(0, floorDiv(minY - kHalfPixel + kSubpixel - 1, kSubpixel)));
      t.y1 = int(std::min<std::int64_t>(height_ - 1, floorDiv(maxY - kHalfPixel, kSubpixel)));
      if (t.x0 > t.x1 || t.y0 > t.y1) continue;
      const auto index = std::uint32_t(out.triangles.size());
      out.triangles.push_back(t);
      for (int ty = t.y0 / kTileSize; ty <= t.y1 / kTileSize; ++ty)
        for (int tx = t.x0 / kTileSize; tx <= t.x1 / kTileSize; ++tx)
          out.tiles[std::size_t(ty) * std::size_t(tilesX_) + std::size_t(tx)].push_back(index);
    }
  }

  // 1/256 pixel steps in window coordinates (y up) of a corner with w > 0.
  Point snap(const Vec4& c) const {
    const std::int64_t w = snapPoint(c, width_, height_);
    return Point{std::int32_t(w), std::int32_t(w >> 32)};
  }

  // The triangle clipped to the planes and snapped: the polygon's corner count, 0 when nothing
  // of it is visible.
  int clipAndSnap(const Vec4& c0, const Vec4& c1, const Vec4& c2, std::array<Point, 9>& p) const {
    Polygon a{c0, c1, c2};
    if (!(c0.allFinite() && c1.allFinite() && c2.allFinite())) return 0;
    Polygon b;
    int n = 3;
    Polygon* in = &a;
    Polygon* outPolygon = &b;
    for (int plane = 0; plane < 6 && n > 0; ++plane) {
      bool allInside = true;
      for (int i = 0; i < n && allInside; ++i) allInside = planes_.distance(plane, (*in)[i]) >= 0.0;
      if (allInside) continue;
      n = clipAgainst(planes_, plane, *in, n, *outPolygon);
      std::swap(in, outPolygon);
    }
    for (int i = 0; i < n; ++i) {
      const Vec4& c = (*in)[i];
      if (!(c.w() > 0.0)) return 0;  // only the degenerate point (0, 0, 0, 0) survives the guard band at w <= 0
      p[std::size_t(i)] = snap(c);
    }
    return n;
  }

  int width_, height_, tilesX_;
  RasterOptions options_;
  ClipPlanes planes_{};
};

// Edge tests and the depth test of one triangle over the pixels of one tile.
void drawInTile(const SetupTriangle& t, TiledRaster::Tile& tile) {
  const int x0 = std::max(t.x0, tile.x0), x1 = std::min(t.x1, tile.x1);
  const int y0 = std::max(t.y0, tile.y0), y1 = std::min(t.y1, tile.y1);
  if (x0 > x1 || y0 > y1) return;
  std::int64_t rowStart[3], stepX[3], stepY[3];
  const std::int64_t px = std::int64_t(x0) * kSubpixel + kHalfPixel, py = std::int64_t(y0) * kSubpixel + kHalfPixel;
  for (int e = 0; e < 3; ++e) {
    const Point& a = t.v[e];
    const Point& b = t.v[(e + 1) % 3];
    // E(p) = (b - a) x (p - a): positive inside a counter-clockwise triangle. A centre on a
    // edge that does not own it is pushed out by one unit.
    const std::int64_t dx = std::int64_t(b.x) - a.x, dy = std::int64_t(b.y) - a.y;
    rowStart[e] = dx * (py - a.y) - dy * (px - a.x) - (isTopLeft(a, b) ? 0 : 1);
    stepX[e] = -dy * kSubpixel;
    stepY[e] = dx * kSubpixel;
  }
  const DrawnFace* face = t.drawn;
  const std::int32_t faceIndex = t.face;
  const Vec3& depthPlane = t.depthPlane;
  for (int y = y0; y <= y1; ++y) {
    std::int64_t e0 = rowStart[0], e1 = rowStart[1], e2 = rowStart[2];
    const std::size_t row = std::size_t(y - tile.y0) * kTileSize;
    for (int x = x0; x <= x1; ++x) {
      if ((e0 | e1 | e2) >= 0) {
        const double z = depthPlane.dot(Vec3(x + 0.5, y + 0.5, 1.0));
        const float depth = float(std::clamp(z, 0.0, 1.0));
        const std::size_t i = row + std::size_t(x - tile.x0);
        if (depth < tile.depth[i]) {
          tile.depth[i] = depth;
          tile.face[i] = face;
          tile.faceIndex[i] = faceIndex;
        }
      }
      e0 += stepX[0], e1 += stepX[1], e2 += stepX[2];
    }
    for (int e = 0; e < 3; ++e) rowStart[e] += stepY[e];
  }
}

}  // namespace

Mat3 inverse3x3(const Mat3& m) {
  // Eigen 3.4, LU/InverseImpl.h (compute_inverse for size 3): the cofactors of column 0, the
  // determinant from them summed in index order, and every cofactor times 1 / determinant.
  const auto cofactor = [&m](int i, int j) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    return m(i1, j1) * m(i2, j2) - m(i1, j2) * m(i2, j1);
  };
  const double c00 = cofactor(0, 0), c10 = cofactor(1, 0), c20 = cofactor(2, 0);
  const double invdet = 1.0 / (c00 * m(0, 0) + c10 * m(1, 0) + c20 * m(2, 0));
  Mat3 r;
  r << c00 * invdet, c10 * invdet, c20 * invdet,                      //
      cofactor(0, 1) * invdet, cofactor(1, 1) * invdet, cofactor(2, 1) * invdet,  //
      cofactor(0, 2) * invdet, cofactor(1, 2) * invdet, cofactor(2, 2) * invdet;
  return r;
}

TriangleInterpolator::TriangleInterpolator(const Vec4& c0, const Vec4& c1, const Vec4& c2, int width, int height) {
  // Spelled out in the order Eigen 3.4 (SSE2) evaluated m.determinant(), the product with the
  // window-to-NDC matrix (rows 0 and 1 as a packet, row 2 unrolled: zero terms kept, they may
  // carry a sign) and z^T K when the images were pinned, without its temporaries.
  Mat3 m;
  m << c0.x(), c1.x(), c2.x(),  //
      c0.y(), c1.y(), c2.y(),   //
      c0.w(), c1.w(), c2.w();
  const double det = (m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0))) +
                     m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
  if (!(det != 0.0) || !std::isfinite(det)) return;
  const double n[3][3] = {{2.0 / width, 0, -1}, {0, 2.0 / height, -1}, {0, 0, 1}};  // X = 2 x / W - 1, Y = 2 y / H - 1
  const Mat3 inverse = inverse3x3(m);
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 2; ++i)
      kFromWindow_(i, j) = (inverse(i, 0) * n[0][j] + inverse(i, 1) * n[1][j]) + inverse(i, 2) * n[2][j];
    kFromWindow_(2, j) = inverse(2, 0) * n[0][j] + (inverse(2, 1) * n[1][j] + inverse(2, 2) * n[2][j]);
  }
  if (!kFromWindow_.allFinite()) return;
  for (int j = 0; j < 3; ++j)
    depthPlane_[j] = (c0.z() * kFromWindow_(0, j) + c1.z() * kFromWindow_(1, j)) + c2.z() * kFromWindow_(2, j);
  valid_ = true;
}

TriangleInterpolator::Barycentrics TriangleInterpolator::at(double x, double y) const {
  // k = M (x, y, 1) and the sums in the order Eigen 3.4 (SSE2) evaluated them when the images were
  // pinned (rows 0 and 1 of the product as one packet, row 2 by its unroller); the vectorised
  // fragments (render/fragment_simd.cpp) repeat it.
  const Eigen::Matrix3d& m = kFromWindow_;
  const Vec3 k((m(0, 0) * x + m(0, 1) * y) + m(0, 2), (m(1, 0) * x + m(1, 1) * y) + m(1, 2),
               m(2, 0) * x + (m(2, 1) * y + m(2, 2)));
  const Vec3 dkdx = m.col(0), dkdy = m.col(1);
  const double s = (k[0] + k[1]) + k[2], dsdx = (dkdx[0] + dkdx[1]) + dkdx[2], dsdy = (dkdy[0] + dkdy[1]) + dkdy[2];
  Barycentrics r;
  r.b = k / s;
  r.dbdx = (dkdx * s - k * dsdx) / (s * s);  // quotient rule on k / s
  r.dbdy = (dkdy * s - k * dsdy) / (s * s);
  return r;
}

TiledRaster::TiledRaster() = default;

TiledRaster::TiledRaster(const std::vector<Vec4>& clip, const std::vector<Triangle>& triangles, int width,
                         int height, const RasterOptions& options) {
  setUp(clip, triangles, width, height, options);
}

void TiledRaster::setUp(const std::vector<Vec4>& clip, const std::vector<Triangle>& triangles, int width, int height,
                        const RasterOptions& options) {
  if (width <= 0 || height <= 0 || width > kMaxViewport || height > kMaxViewport)
    throw UsageError("the image size must lie between 1 x 1 and 16384 x 16384 pixels");
  width_ = width, height_ = height;
  tilesX_ = (width + kTileSize - 1) / kTileSize, tilesY_ = (height + kTileSize - 1) / kTileSize;
  const auto faceCount = std::int64_t(triangles.size());
  UVTK_CHECK(faceCount <= std::numeric_limits<std::int32_t>::max());
  const int threads = threadCount(options.threads);
  const Setup setup(width, height, tilesX_, options);

  if (window_.capacity() < clip.size()) {
    std::vector<std::int64_t>().swap(window_);
    resizeOnHugePages(window_, clip.size());
  }
  window_.resize(clip.size());
  constexpr std::size_t kVertexChunk = std::size_t(1) << 16;
  parallelFor(int((clip.size() + kVertexChunk - 1) / kVertexChunk), threads, [&](int c) {
    const std::size_t begin = std::size_t(c) * kVertexChunk, end = std::min(clip.size(), begin + kVertexChunk);
    snapToWindow(&clip[begin], end - begin, setup.guard(), width, height, &window_[begin]);
  });

  if (drawnCapacity_ < triangles.size()) {
    drawnStorage_.reset(), drawnFaces_ = nullptr;
    drawnStorage_.reset(new std::byte[triangles.size() * sizeof(DrawnFace)]);  // not touched until drawn
    adviseHugePages(drawnStorage_.get(), triangles.size() * sizeof(DrawnFace));
    drawnFaces_ = reinterpret_cast<DrawnFace*>(drawnStorage_.get());
    drawnCapacity_ = triangles.size();
  }

  // Set-up in chunks of consecutive triangles; each chunk bins its own triangles, and tiles read
  // the chunks in order, so the drawing order is the input order whatever the thread count.
  const int chunkCount = int(std::clamp<std::int64_t>(faceCount / 4096, 1, 4 * threads));
  chunks_.resize(static_cast<std::size_t>(chunkCount));
  parallelFor(chunkCount, threads, [&](int c) {
    Chunk& chunk = chunks_[std::size_t(c)];
    chunk.stats = {};
    chunk.drawn = drawnFaces_ + faceCount * c / chunkCount, chunk.drawnCount = 0;
    chunk.tiles.resize(std::size_t(tileCount()));
    for (std::vector<std::uint32_t>& bin : chunk.tiles) bin.clear();
    chunk.triangles.clear();
    const std::int64_t begin = faceCount * c / chunkCount, end = faceCount * (c + 1) / chunkCount;
    const std::size_t expected = std::size_t(end - begin) / 2;  // a closed mesh shows about half its faces
    if (chunk.triangles.capacity() < expected) {
      std::vector<SetupTriangle>().swap(chunk.triangles);
      chunk.triangles.reserve(expected);
      adviseHugePages(chunk.triangles.data(), chunk.triangles.capacity() * sizeof(SetupTriangle));
    }
    setup.triangles(clip, window_, triangles, begin, end, chunk);
  });
  stats_ = {};
  for (const Chunk& chunk : chunks_) {
    stats_.culled += chunk.stats.culled;
    stats_.clipped += chunk.stats.clipped;
    stats_.drawn += chunk.stats.drawn;
  }
}

TiledRaster::~TiledRaster() = default;

void TiledRaster::draw(int tile, Tile& out) const {
  const int tx = tile % tilesX_, ty = tile / tilesX_;
  out.x0 = tx * kTileSize, out.x1 = std::min(width_, out.x0 + kTileSize) - 1;
  out.y0 = ty * kTileSize, out.y1 = std::min(height_, out.y0 + kTileSize) - 1;
  out.face.fill(nullptr);
  out.depth.fill(1.0f);
  for (const Chunk& chunk : chunks_)
    for (std::uint32_t index : chunk.tiles[std::size_t(tile)])
      drawInTile(chunk.triangles[index], out);
}

void clipPositions(const Mesh& mesh, const Mat4& clipFromObject, int threads, std::vector<Vec4>& clip) {
  if (clip.capacity() < mesh.positions.size()) {
    std::vector<Vec4>().swap(clip);
    resizeOnHugePages(clip, mesh.positions.size());
  }
  clip.resize(mesh.positions.size());
  constexpr int kChunk = 1 << 16;
  const int chunks = int((clip.size() + kChunk - 1) / kChunk);
  // Per chunk, the least and the greatest of the vertices' largest finite non-zero |coordinate|.
  std::vector<std::pair<double, double>> range(std::size_t(chunks), {INFINITY, 0.0});
  parallelFor(chunks, threads, [&](int chunk) {
    const std::size_t begin = std::size_t(chunk) * kChunk, end = std::min(clip.size(), begin + kChunk);
    range[std::size_t(chunk)] = transformToClip(clipFromObject, &mesh.positions[begin], &clip[begin], end - begin);
  });
  double least = INFINITY, greatest = 0.0;
  for (const auto& [l, g] : range) least = std::min(least, l), greatest = std::max(greatest, g);
  if (least > 0x1p400 || (greatest > 0.0 && greatest < 0x1p-400)) {
    const double scale = unitPowerOfTwo(greatest);
    parallelFor(chunks, threads, [&](int chunk) {
      const std::size_t end = std::min(clip.size(), std::size_t(chunk + 1) * kChunk);
      for (std::size_t v = std::size_t(chunk) * kChunk; v < end; ++v) clip[v] *= scale;
    });
  }
}

VisibilityBuffer rasterize(const std::vector<Vec4>& clip, const std::vector<Triangle>& triangles, int width, int height,
                           const RasterOptions& options, RasterStats* stats) {
  const TiledRaster raster(clip, triangles, width, height, options);
  VisibilityBuffer buffer;
  buffer.width = width;
  buffer.height = height;
  buffer.face.assign(std::size_t(width) * std::size_t(height), -1);
  buffer.depth.assign(buffer.face.size(), 1.0f);
  Progress progress("rasterizing " + std::to_string(width) + "x" + std::to_string(height),
                    std::uint64_t(raster.tileCount()), "tiles");
  parallelFor(raster.tileCount(), options.threads, [&](int index) {
    const std::unique_ptr<TiledRaster::Tile> tile(new TiledRaster::Tile);  // draw() fills it
    raster.draw(index, *tile);
    for (int y = tile->y0; y <= tile->y1; ++y)
      for (int x = tile->x0; x <= tile->x1; ++x) {
        const std::size_t from = std::size_t(y - tile->y0) * TiledRaster::kTileSize + std::size_t(x - tile->x0);
        const std::size_t to = buffer.index(x, height - 1 - y);
        buffer.face[to] = tile->face[from] ? tile->face[from]->face : -1;
        buffer.depth[to] = tile->depth[from];
      }
    progress.advance();
  });
  if (stats) *stats = raster.stats();
  return buffer;
}

}  // namespace uvtk::render
