#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include "core/error.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/stopwatch.h"
#include "core/huge_pages.h"
#include "render/fragment_simd.h"
#include "render/memory.h"
#include "render/raster_simd.h"

namespace uvtk::render {

// What a worker thread shades a tile with: the tile's visibility and a batch of fragments.
struct TileScratch {
  TiledRaster::Tile tile;
  FragmentBatch fragments;
};

namespace {

constexpr int kRowsPerBand = 8;
constexpr int kPrefetchAhead = 4;  // pixels: about the latency of a cache miss in shading time
constexpr std::uint64_t kLargeRenderBytes = std::uint64_t(1) << 30;  // announced on stderr

// Texture coordinates of one fragment, (s, t, r) / q, and their screen-space derivatives.
struct FragmentTexcoords {
  Vec3 str = Vec3::Zero();
  Vec3 dx = Vec3::Zero(), dy = Vec3::Zero();
};

// d(a / q) = (da q - a dq) / q^2, for the interpolated (s, t, r, q) and its derivative.
Vec3 projectedDerivative(const Vec4& tc, const Vec4& dtc) {
  return (dtc.head<3>() * tc.w() - tc.head<3>() * dtc.w()) / (tc.w() * tc.w());
}

// Everything the shading pass reads, computed once per frame.
struct FrameData {
  const Mesh& mesh;
  const TexcoordSource& source;
  const RenderOptions& options;
  std::vector<Vec3> normals;       // object space, per corner: for lighting or the pixel mapping
  std::vector<Vec4> cornerColour;      // lit colour per corner when the environment reads it
  std::vector<Vec4> cornerBackColour;  // the same lit with the normal negated, for back faces (two-sided)
};

// What the texture unit returns for a fragment, and where it looked.
struct TextureLookup {
  Vec4 texel = Vec4::Zero();
  Vec2 st = Vec2::Zero();  // on the selected face for a cube map
  double lambda = 0.0;
  int cubeFace = -1;
};

class Shader {
 public:
  explicit Shader(const FrameData& frame)
      : f_(frame),
        blends_(frame.source.pixelMapping && frame.source.pixelMapping->blendAt),
        quad_(frame.options.derivatives != Derivatives::Analytic && frame.options.seamFix != SeamFix::Grad) {}

  // The pixel (x, row) of a drawn triangle; returns RGB and fills the AOV values.
  Vec3 shade(int x, int row, const DrawnFace& drawn, float* aov) const {
    const RenderOptions& o = f_.options;
    const std::int32_t face = drawn.face;
    const double wx = x + 0.5, wy = o.camera.height - row - 0.5;  // window coordinates, y up
    const TriangleInterpolator::Barycentrics b = drawn.interpolator.at(wx, wy);
    TextureLookup lookup;
    if (blends_) {
      lookup = lookUpBlend(drawn, wx, wy, b);
    } else {
      const FragmentTexcoords tc = quad_                      ? quadTexcoords(drawn, wx, wy)
                                   : f_.source.pixelMapping ? exactTexcoords(face, b)
                                                            : interpolatedTexcoords(face, b);
      lookup = o.cubeTexture ? lookUpCube(tc) : lookUp2d(tc);
    }
    return colourOf(face, drawn.front, b.b, lookup, aov);
  }

  // Whether the vectorised fragments (render/fragment_simd.h) compute what shade() does up to the
  // lookup: a 2D texture read at interpolated corner coordinates with analytic derivatives.
  bool vectorisable() const { return !f_.source.pixelMapping && f_.options.texture && !quad_; }

  // Whether a fragment's colour depends on its face's facing (two-sided lighting).
  bool readsFacing() const { return !f_.cornerBackColour.empty(); }

  // The rest of shade() for a fragment of `face` (`front`: as DrawnFace::front, read only when
  // readsFacing()) at barycentrics b whose 2D lookup at (s, t) and lambda (the bias added) gave
  // `texel`, as the vectors computed them.
  Vec3 shade2d(std::int32_t face, bool front, const Vec3& b, double s, double t, double lambda, const Vec4& texel,
               float* aov) const {
    TextureLookup lookup;
    lookup.st = Vec2(s, t);
    lookup.lambda = lambda;
    lookup.texel = texel;
    return colourOf(face, front, b, lookup, aov);
  }

 private:
  // The fragment's colour (lit at the corners, interpolated; a back face's from the back colours
  // where they are computed), the texture environment, the AOVs.
  Vec3 colourOf(std::int32_t face, bool front, const Vec3& b, const TextureLookup& lookup, float* aov) const {
    const RenderOptions& o = f_.options;
    Vec4 fragment = Vec4::Ones();
    if (!f_.cornerColour.empty()) {
      const std::vector<Vec4>& lit = front || f_.cornerBackColour.empty() ? f_.cornerColour : f_.cornerBackColour;
      fragment = Vec4::Zero();
      for (int k = 0; k < 3; ++k) fragment += b[k] * lit[3 * std::size_t(face) + std::size_t(k)];
    }
    const Vec4 colour = textureEnvironment(o.env, fragment, lookup.texel, o.envColour);
    if (aov) {
      aov[0] = float(lookup.st.x());
      aov[1] = float(lookup.st.y());
      aov[4] = std::isfinite(lookup.lambda) ? float(lookup.lambda) : (lookup.lambda > 0 ? 1000.0f : -1000.0f);  // GL's lod clamp
      if (o.cubeTexture) aov[5] = float(lookup.cubeFace);
    }
    return colour.head<3>();
  }

  TextureLookup lookUp2d(const FragmentTexcoords& tc) const {
    const RenderOptions& o = f_.options;
    TextureLookup out;
    out.st = tc.str.head<2>();
    out.lambda = levelOfDetail(o.texture->width(), o.texture->height(), tc.dx.head<2>(), tc.dy.head<2>()) + o.lodBias;
    out.texel = sample(*o.texture, o.sampler, out.st.x(), out.st.y(), out.lambda);
    return out;
  }

  // The face and (s, t) from a direction (s, t, r), or as given with cube face ids; the level of
  // detail from the derivatives of (s, t) on that face.
  TextureLookup lookUpCube(const FragmentTexcoords& tc) const {
    const RenderOptions& o = f_.options;
    TextureLookup out;
    Vec2 dstDx, dstDy;
    CubeFace face = CubeFace::PosX;
    if (f_.source.cubeFaceIds) {
      // Equal ids at the corners interpolate to that id only up to rounding (the barycentrics and
      // the division by q are exact to a few ulp), so an id within 1e-9 of an integer counts.
      const double id = std::round(tc.str.z());
      const bool valid = id >= 0.0 && id < kCubeFaceCount && std::abs(tc.str.z() - id) <= 1e-9;
      face = valid ? CubeFace(int(id)) : CubeFace::PosX;
      out.st = valid ? Vec2(tc.str.head<2>()) : Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
      dstDx = tc.dx.head<2>();
      dstDy = tc.dy.head<2>();
      out.cubeFace = valid ? int(face) : -1;
    } else {
      const CubeCoordinates c = cubeCoordinates(tc.str);
      face = c.face;
      out.st = c.st;
      dstDx = cubeFaceStDerivative(tc.str, tc.dx, face);
      dstDy = cubeFaceStDerivative(tc.str, tc.dy, face);
      out.cubeFace = c.st.allFinite() ? int(face) : -1;
    }
    const int n = o.cubeTexture->size();
    out.lambda = levelOfDetail(n, n, dstDx, dstDy) + o.lodBias;
    out.texel = sampleCube(*o.cubeTexture, o.sampler, face, out.st.x(), out.st.y(), out.lambda, o.seamless);
    return out;
  }

  // The three lookups of a blend, each as lookUp2d reads an exact mapping, and their weighted
  // sum; u, v and lambda of the heaviest. Without a value, what lookUp2d shows for a non-finite
  // (s, t): its derivatives are 0, so lambda = -inf, and the texel is the bound texture's (0, 0).
  TextureLookup lookUpBlend(const DrawnFace& drawn, double wx, double wy,
                            const TriangleInterpolator::Barycentrics& b) const {
    constexpr double h = 1e-3;  // as exactTexcoords
    const RenderOptions& o = f_.options;
    const std::int32_t face = drawn.face;
    const TexcoordBlend at = blendAt(face, b.b);
    const Vec3& w = at.weights;
    bool valid = w.allFinite();
    for (int i = 0; i < 3 && valid; ++i) valid = !(w[i] > 0.0) || at.st[std::size_t(i)].allFinite();
    TextureLookup out;
    if (!valid) {
      out.st = Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
      out.lambda = -std::numeric_limits<double>::infinity();
      out.texel = sample(*o.texture, o.sampler, out.st.x(), out.st.y(), out.lambda);
      return out;
    }
    // Per lookup, d(st)/dx and d(st)/dy as the columns of two 2 x 3 matrices.
    using Coordinates = Eigen::Matrix<double, 2, 3>;
    const auto columns = [](const TexcoordBlend& blend) {
      Coordinates c;
      for (int i = 0; i < 3; ++i) c.col(i) = blend.st[std::size_t(i)];
      return c;
    };
    Coordinates dx, dy;
    if (quad_) {
      std::tie(dx, dy) = quadDifferences(
          [&](double px, double py) { return columns(blendAt(face, drawn.interpolator.at(px, py).b)); }, wx, wy);
    } else {
      const Coordinates xPlus = columns(blendAt(face, b.b + h * b.dbdx)), xMinus = columns(blendAt(face, b.b - h * b.dbdx));
      const Coordinates yPlus = columns(blendAt(face, b.b + h * b.dbdy)), yMinus = columns(blendAt(face, b.b - h * b.dbdy));
      for (int i = 0; i < 3; ++i) {
        dx.col(i) = difference(Vec2(xPlus.col(i)), Vec2(xMinus.col(i))) / (2 * h);
        dy.col(i) = difference(Vec2(yPlus.col(i)), Vec2(yMinus.col(i))) / (2 * h);
      }
    }
    int heaviest = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      if (!(w[int(i)] > 0.0)) continue;
      const Texture& texture = o.axisTextures[i] ? *o.axisTextures[i] : *o.texture;
      const double lambda =
          levelOfDetail(texture.width(), texture.height(), dx.col(int(i)), dy.col(int(i))) + o.lodBias;
      out.texel += w[int(i)] * sample(texture, o.sampler, at.st[i].x(), at.st[i].y(), lambda);
      if (w[int(i)] > w[heaviest]) heaviest = int(i);
      if (int(i) == heaviest) out.st = at.st[i], out.lambda = lambda;
    }
    return out;
  }

  // The differences of f(window x, window y) across the fragment's 2 x 2 quad, as {dFdx, dFdy}:
  // coarse from the quad's bottom-left pixel, fine along the fragment's own row and column.
  template <typename F, typename Value = std::decay_t<std::invoke_result_t<const F&, double, double>>>
  std::pair<Value, Value> quadDifferences(const F& f, double wx, double wy) const {
    const double x0 = 2.0 * std::floor(wx / 2.0) + 0.5, y0 = 2.0 * std::floor(wy / 2.0) + 0.5;
    const double x1 = x0 + 1.0, y1 = y0 + 1.0;
    if (f_.options.derivatives == Derivatives::QuadCoarse) {
      const Value v00 = f(x0, y0);
      return {f(x1, y0) - v00, f(x0, y1) - v00};
    }
    return {f(x1, wy) - f(x0, wy), f(wx, y1) - f(wx, y0)};
  }

  // (s, t, r) / q at window (x, y) on the drawn triangle's plane, inside it or not.
  Vec3 texcoordsAt(const DrawnFace& drawn, double wx, double wy) const {
    const Vec3 b = drawn.interpolator.at(wx, wy).b;
    if (f_.source.pixelMapping) return exactAt(drawn.face, b);
    const Vec4* corners = &f_.source.corners[3 * std::size_t(drawn.face)];
    const Vec4 tc = b[0] * corners[0] + b[1] * corners[1] + b[2] * corners[2];
    return tc.head<3>() / tc.w();
  }

  // The fragment's coordinates, their derivatives taken across its quad (RenderOptions::derivatives),
  // with Tarini's choice of s when asked for.
  FragmentTexcoords quadTexcoords(const DrawnFace& drawn, double wx, double wy) const {
    FragmentTexcoords out;
    out.str = texcoordsAt(drawn, wx, wy);
    if (f_.options.seamFix != SeamFix::Tarini) {
      std::tie(out.dx, out.dy) = quadDifferences([&](double px, double py) { return texcoordsAt(drawn, px, py); }, wx, wy);
      return out;
    }
    // (fract(s), fract(s + 1/2) - 1/2, t, r): the two candidates for s beside t and r.
    const auto candidates = [&](double px, double py) {
      const Vec3 str = texcoordsAt(drawn, px, py);
      const double shifted = str.x() + 0.5;
      return Vec4(str.x() - std::floor(str.x()), shifted - std::floor(shifted) - 0.5, str.y(), str.z());
    };
    const auto [dx, dy] = quadDifferences(candidates, wx, wy);
    const int s = std::fabs(dx[0]) + std::fabs(dy[0]) <= std::fabs(dx[1]) + std::fabs(dy[1]) ? 0 : 1;
    out.dx = Vec3(dx[s], dx[2], dx[3]);
    out.dy = Vec3(dy[s], dy[2], dy[3]);
    return out;
  }

  FragmentTexcoords interpolatedTexcoords(std::int32_t face, const TriangleInterpolator::Barycentrics& b) const {
    const Vec4* corners = &f_.source.corners[3 * std::size_t(face)];
    Vec4 tc = Vec4::Zero(), dx = Vec4::Zero(), dy = Vec4::Zero();
    for (int k = 0; k < 3; ++k) {
      tc += b.b[k] * corners[k];
      dx += b.dbdx[k] * corners[k];
      dy += b.dbdy[k] * corners[k];
    }
    FragmentTexcoords out;
    if (!f_.options.cubeTexture) {  // a 2D texture reads (s, t) alone: r stays 0, two divisions fewer
      const double q = tc.w(), q2 = q * q;
      out.str.head<2>() = tc.head<2>() / q;
      out.dx.head<2>() = (dx.head<2>() * q - tc.head<2>() * dx.w()) / q2;  // as projectedDerivative
      out.dy.head<2>() = (dy.head<2>() * q - tc.head<2>() * dy.w()) / q2;
      return out;
    }
    out.str = tc.head<3>() / tc.w();
    out.dx = projectedDerivative(tc, dx);
    out.dy = projectedDerivative(tc, dy);
    return out;
  }

  // The mapping at the fragment, and its derivatives by central differences a thousandth of a
  // pixel to either side on the triangle's plane; across the seam of a wrapping mapping the
  // nearest difference, so no line of the coarsest level appears along the seam.
  FragmentTexcoords exactTexcoords(std::int32_t face, const TriangleInterpolator::Barycentrics& b) const {
    constexpr double h = 1e-3;
    FragmentTexcoords out;
    out.str = exactAt(face, b.b);
    out.dx = difference(exactAt(face, b.b + h * b.dbdx), exactAt(face, b.b - h * b.dbdx)) / (2 * h);
    out.dy = difference(exactAt(face, b.b + h * b.dbdy), exactAt(face, b.b - h * b.dbdy)) / (2 * h);
    return out;
  }

  template <typename V>
  V difference(const V& a, const V& b) const {
    V d = a - b;
    if (!d.allFinite()) return V::Zero();
    if (f_.source.pixelMapping->wrapsS) d.x() -= std::round(d.x());
    return d;
  }

  // The fragment's object-space position and unit normal (0 without normals) at barycentrics b.
  struct SurfacePoint {
    Vec3 position, normal;
  };
  SurfacePoint surfaceAt(std::int32_t face, const Vec3& b) const {
    const Triangle& t = f_.mesh.triangles[std::size_t(face)];
    SurfacePoint p;
    p.position = b[0] * f_.mesh.positions[t[0]] + b[1] * f_.mesh.positions[t[1]] + b[2] * f_.mesh.positions[t[2]];
    p.normal = Vec3::Zero();
    if (!f_.normals.empty()) {
      for (int k = 0; k < 3; ++k) p.normal += b[k] * f_.normals[3 * std::size_t(face) + std::size_t(k)];
      const double length = p.normal.norm();
      p.normal = length > 0.0 ? Vec3(p.normal / length) : Vec3::Zero();
    }
    return p;
  }

  Vec3 exactAt(std::int32_t face, const Vec3& b) const {
    const SurfacePoint p = surfaceAt(face, b);
    const Vec4 tc = f_.source.pixelMapping->texcoordAt(p.position, p.normal, face);
    return tc.head<3>() / tc.w();
  }

  TexcoordBlend blendAt(std::int32_t face, const Vec3& b) const {
    const SurfacePoint p = surfaceAt(face, b);
    return f_.source.pixelMapping->blendAt(p.position, p.normal, face);
  }

  const FrameData& f_;
  const bool blends_;  // the pixel mapping is a blend of three lookups
  const bool quad_;    // derivatives across the pixel quad
};

// `image` as width x height x channels, its pixels kept when it has that size already (every pixel
// is written by the frame), else allocated on huge pages.
void shapeImage(Image& image, int width, int height, int channels) {
  const std::size_t size = std::size_t(width) * std::size_t(height) * std::size_t(channels);
  if (image.pixels.size() != size) {
    std::vector<float>().swap(image.pixels);
    resizeOnHugePages(image.pixels, size);
  }
  image.width = width, image.height = height, image.channels = channels;
}

// One sample at the centre of each pixel of the camera's viewport, into `out`, whose images are
// reused, as are the raster's bins and each worker's scratch. Each tile is shaded right after its visibility is drawn, while both are in cache.
// `sampleCovered`, when given, receives per pixel (row 0 at the top) whether a triangle covers
// it. The arguments are valid.
void renderFrame(const Mesh& mesh, const TexcoordSource& source, const RenderOptions& o, std::vector<Vec4>& clip,
                 TiledRaster& raster, std::vector<std::unique_ptr<TileScratch>>& scratch, Rendering& out,
                 std::vector<std::uint8_t>* sampleCovered) {
  const int width = o.camera.width, height = o.camera.height;

  const auto rasterStart = std::chrono::steady_clock::now();
  const Mat4 eyeFromObject = o.camera.viewFromWorld * o.worldFromObject;
  clipPositions(mesh, o.camera.clipFromView * eyeFromObject, o.raster.threads, clip);
  raster.setUp(clip, mesh.triangles, width, height, o.raster);
  out.raster = raster.stats();
  out.rasterMs = millisecondsSince(rasterStart);
  out.coveredPixels = 0;

  const auto shadeStart = std::chrono::steady_clock::now();
  FrameData frame{mesh, source, o, {}, {}, {}};
  // Normals and lighting only when something reads them.
  const bool lit = readsFragmentColour(o.env);
  if (lit || (source.pixelMapping && source.pixelMapping->needsNormal)) frame.normals = cornerNormals(mesh);
  if (lit) {
    const Mat3 normalMatrix = eyeFromObject.topLeftCorner<3, 3>().inverse().transpose();
    frame.cornerColour.resize(frame.normals.size());
    if (o.lighting.twoSided) frame.cornerBackColour.resize(frame.normals.size());
    for (std::size_t c = 0; c < frame.normals.size(); ++c) {
      const Vec3 n = normalMatrix * frame.normals[c];
      const double length = n.norm();
      const Vec3 unit = length > 0.0 ? Vec3(n / length) : Vec3::Zero();
      frame.cornerColour[c] = headlightColour(o.lighting, unit);
      if (o.lighting.twoSided) frame.cornerBackColour[c] = headlightColour(o.lighting, -unit);
    }
  }

  shapeImage(out.colour, width, height, 3);
  if (o.aovs) {
    shapeImage(out.aovs, width, height, o.cubeTexture ? 6 : 5);
    out.aovs.channelNames = {"u", "v", "depth", "face", "lod"};
    if (o.cubeTexture) out.aovs.channelNames.push_back("cubeface");
  } else {
    out.aovs = Image();
  }
  if (sampleCovered) sampleCovered->assign(std::size_t(width) * std::size_t(height), 0);
  std::vector<std::size_t> covered(std::size_t(raster.tileCount()), 0);
  Progress progress("rendering " + std::to_string(width) + "x" + std::to_string(height),
                    std::uint64_t(raster.tileCount()), "tiles");
  const Shader shader(frame);
  const bool vectorised = shader.vectorisable() && fragmentsVectorised();
  FragmentFrame fragmentFrame;
  std::optional<FragmentTexture> fragmentTexture;  // the texels sampled on vectors too
  if (vectorised) {
    fragmentTexture = vectorisedTexture(*o.texture, o.sampler, o.env == EnvMode::Decal);  // DECAL alone reads alpha
    fragmentFrame.drawnFaces = raster.drawnFaces();
    fragmentFrame.corners = source.corners.data()->data();
    fragmentFrame.textureWidth = o.texture->width(), fragmentFrame.textureHeight = o.texture->height();
    fragmentFrame.lodBias = o.lodBias;
  }
  const int workers = workerCount(raster.tileCount(), o.raster.threads);
  while (int(scratch.size()) < workers) scratch.push_back(std::make_unique<TileScratch>());
  parallelForWorkers(raster.tileCount(), o.raster.threads, [&](int index, int worker) {
    TiledRaster::Tile* tile = &scratch[std::size_t(worker)]->tile;  // draw() fills it
    FragmentBatch* batch = &scratch[std::size_t(worker)]->fragments;
    raster.draw(index, *tile);
    std::size_t tileCovered = 0;  // stored once: neighbouring tiles' counts share a cache line
    // A drawn pixel's (face >= 0) colour, AOVs and coverage; an empty one's (face -1) background.
    const auto write = [&](int x, int y, std::int32_t face, const Vec3& rgb, float* aov) {
      const int row = height - 1 - y;
      if (face >= 0) {
        ++tileCovered;
        if (sampleCovered) (*sampleCovered)[std::size_t(row) * std::size_t(width) + std::size_t(x)] = 1;
      } else if (aov) {
        aov[0] = aov[1] = aov[4] = 0.0f;
        if (o.cubeTexture) aov[5] = -1.0f;
      }
      if (aov) {
        aov[2] = tile->depth[std::size_t(y - tile->y0) * TiledRaster::kTileSize + std::size_t(x - tile->x0)];
        aov[3] = float(face);
      }
      for (int c = 0; c < 3; ++c) out.colour.at(x, row, c) = float(rgb[c]);
    };
    const auto aovAt = [&](int x, int y) { return o.aovs ? &out.aovs.pixels[out.aovs.index(x, height - 1 - y)] : nullptr; };
    if (vectorised) {
      // The tile's fragments in batches: up to the lookup on vectors, the rest one by one.
      batch->count = 0;
      std::array<std::uint16_t, FragmentBatch::kSize> pixel;  // (y - y0) * kTileSize + x - x0
      const auto flush = [&] {
        const std::size_t n = batch->count;
        for (std::size_t j = n; j % 16 != 0; ++j)  // whole vectors read valid indices
          batch->x[j] = batch->x[n - 1], batch->y[j] = batch->y[n - 1], batch->drawn[j] = batch->drawn[n - 1],
          batch->corners[j] = batch->corners[n - 1];
        shadeFragments(fragmentFrame, *batch);
        for (std::size_t k = 0; k < batch->undecidedCount; ++k) {
          const auto j = std::size_t(batch->undecided[k]);
          batch->lambda[j] = levelOfDetail(o.texture->width(), o.texture->height(), Vec2(batch->dsdx[j], batch->dtdx[j]),
                                           Vec2(batch->dsdy[j], batch->dtdy[j])) + o.lodBias;
        }
        const auto texelOf = [&](std::size_t j) { return sample(*o.texture, o.sampler, batch->s[j], batch->t[j], batch->lambda[j]); };
        if (fragmentTexture) {
          sampleTexels(*fragmentTexture, *batch);
          for (std::size_t k = 0; k < batch->unsampledCount; ++k) {
            const auto j = std::size_t(batch->unsampled[k]);
            const Vec4 texel = texelOf(j);
            batch->red[j] = texel[0], batch->green[j] = texel[1], batch->blue[j] = texel[2], batch->alpha[j] = texel[3];
          }
        }
        for (std::size_t j = 0; j < n; ++j) {
          const int x = tile->x0 + pixel[j] % TiledRaster::kTileSize, y = tile->y0 + pixel[j] / TiledRaster::kTileSize;
          const std::int32_t face = tile->faceIndex[pixel[j]];
          float* aov = aovAt(x, y);
          const Vec3 b(batch->b0[j], batch->b1[j], batch->b2[j]);
          const Vec4 texel =
              fragmentTexture ? Vec4(batch->red[j], batch->green[j], batch->blue[j], batch->alpha[j]) : texelOf(j);
          const bool front = !shader.readsFacing() || fragmentFrame.drawnFaces[batch->drawn[j]].front;
          write(x, y, face, shader.shade2d(face, front, b, batch->s[j], batch->t[j], batch->lambda[j], texel, aov), aov);
        }
        batch->count = 0;
      };
      const DrawnFace* previous = nullptr;
      for (int y = tile->y0; y <= tile->y1; ++y)
        for (int x = tile->x0; x <= tile->x1; ++x) {
          const auto i = std::uint16_t((y - tile->y0) * TiledRaster::kTileSize + (x - tile->x0));
          const DrawnFace* drawn = tile->face[i];
          if (!drawn) {
            write(x, y, -1, o.background, aovAt(x, y));
            continue;
          }
          const std::int32_t face = tile->faceIndex[i];  // drawn->face, without reading the record
          if (drawn != previous) {
            // The set-up and corners the vectors gather lie anywhere in memory: asked for now, they
            // are in cache when the batch is shaded. (Inline: GCC drops a call to a function that
            // only prefetches, as it has no effect.)
            const auto* record = reinterpret_cast<const char*>(drawn);
            const auto* corners = reinterpret_cast<const char*>(&source.corners[3 * std::size_t(face)]);
            __builtin_prefetch(record), __builtin_prefetch(record + sizeof(DrawnFace) - 1);
            __builtin_prefetch(corners), __builtin_prefetch(corners + 64), __builtin_prefetch(corners + 3 * sizeof(Vec4) - 1);
            previous = drawn;
          }
          const std::size_t j = batch->count++;
          pixel[j] = i;
          batch->x[j] = x + 0.5, batch->y[j] = y + 0.5;
          batch->drawn[j] = drawn - fragmentFrame.drawnFaces;
          batch->corners[j] = 12 * std::int64_t(face);
          if (batch->count == FragmentBatch::kSize) flush();
        }
      if (batch->count > 0) flush();
    } else {
      for (int y = tile->y0; y <= tile->y1; ++y) {
        const int row = height - 1 - y;
        for (int x = tile->x0; x <= tile->x1; ++x) {
          const std::size_t i = std::size_t(y - tile->y0) * TiledRaster::kTileSize + std::size_t(x - tile->x0);
          const DrawnFace* drawn = tile->face[i];
          // The set-up and texture coordinates of the face a few pixels ahead lie anywhere in memory:
          // asked for now, they are in cache when that pixel is shaded. (Inline: GCC drops a call
          // to a function that only prefetches, as it has no effect.)
          const DrawnFace* ahead = x + kPrefetchAhead <= tile->x1 ? tile->face[i + kPrefetchAhead] : nullptr;
          if (ahead) {
            __builtin_prefetch(&ahead->interpolator);
            if (!source.pixelMapping) {
              const auto* corners = reinterpret_cast<const char*>(&source.corners[3 * std::size_t(ahead->face)]);
              __builtin_prefetch(corners);
              __builtin_prefetch(corners + 64);
              __builtin_prefetch(corners + 3 * sizeof(Vec4) - 1);
            }
          }
          float* aov = aovAt(x, y);
          write(x, y, drawn ? tile->faceIndex[i] : -1, drawn ? shader.shade(x, row, *drawn, aov) : o.background, aov);
        }
      }
    }
    covered[std::size_t(index)] = tileCovered;
    progress.advance();
  });
  for (std::size_t n : covered) out.coveredPixels += n;
  out.shadeMs = millisecondsSince(shadeStart);
}

// n for n x n samples per pixel.
int sampleGridSize(int samplesPerPixel) {
  const int n = int(std::lround(std::sqrt(double(std::clamp(samplesPerPixel, 1, 256)))));
  if (samplesPerPixel < 1 || samplesPerPixel > 256 || n * n != samplesPerPixel)
    throw UsageError("--spp: expected a square number of samples per pixel in [1, 256] (1, 4, 9, 16, 64, ...), found " +
                     std::to_string(samplesPerPixel));
  return n;
}

// The supersampled frame down to width x height, into `out`: each n x n block's mean colour (in
// double, so that a block of equal samples keeps their value exactly), its sample (n/2, n/2)'s
// AOVs, covered when any of its samples is.
void resolve(const Rendering& samples, const std::vector<std::uint8_t>& sampleCovered, int n, int width, int height,
             int threads, Rendering& out) {
  shapeImage(out.colour, width, height, 3);
  const bool aovs = !samples.aovs.pixels.empty();
  if (aovs) {
    shapeImage(out.aovs, width, height, samples.aovs.channels);
    out.aovs.channelNames = samples.aovs.channelNames;
  } else {
    out.aovs = Image();
  }
  out.coveredPixels = 0;
  const int bands = (height + kRowsPerBand - 1) / kRowsPerBand;
  std::vector<std::size_t> covered(std::size_t(bands), 0);
  parallelFor(bands, threads, [&](int band) {
    for (int row = band * kRowsPerBand; row < std::min(height, (band + 1) * kRowsPerBand); ++row)
      for (int x = 0; x < width; ++x) {
        double sum[3] = {0.0, 0.0, 0.0};
        bool any = false;
        for (int j = row * n; j < (row + 1) * n; ++j)
          for (int i = x * n; i < (x + 1) * n; ++i) {
            for (int c = 0; c < 3; ++c) sum[c] += samples.colour.at(i, j, c);
            any = any || sampleCovered[std::size_t(j) * std::size_t(samples.colour.width) + std::size_t(i)];
          }
        for (int c = 0; c < 3; ++c) out.colour.at(x, row, c) = float(sum[c] / double(n * n));
        covered[std::size_t(band)] += any;
        if (aovs)
          for (int c = 0; c < out.aovs.channels; ++c)
            out.aovs.at(x, row, c) = samples.aovs.at(x * n + n / 2, row * n + n / 2, c);
      }
  });
  for (std::size_t b : covered) out.coveredPixels += b;
  out.raster = samples.raster;
  out.rasterMs = samples.rasterMs;
  out.shadeMs = samples.shadeMs;
}

// Memory before work: a frame the machine cannot hold is refused before any buffer is allocated,
// and a large one is announced beside the progress (the bar shows no memory).
void checkFrameMemory(const Mesh& mesh, const TexcoordSource& source, const RenderOptions& o) {
  const int width = o.camera.width, height = o.camera.height;
  if (width <= 0 || height <= 0 || width > kMaxViewport || height > kMaxViewport) return;  // rasterize refuses
  const MemoryEstimate estimate = estimateMemory(mesh, source, o);
  std::string what = "rendering " + std::to_string(width) + "x" + std::to_string(height);
  if (o.samplesPerPixel > 1) what += " at " + std::to_string(o.samplesPerPixel) + " samples per pixel";
  const std::optional<std::uint64_t> available = availableMemory();
  if (available) checkMemory(estimate, *available, what);
  if (estimate.total() > kLargeRenderBytes && progressEnabled())
    printProgressMessage(what + ": about " + formatBytes(estimate.total()) + " of memory" +
                         (available ? " (" + formatBytes(*available) + " available)" : ""));
}

}  // namespace

const char* toString(Derivatives derivatives) {
  switch (derivatives) {
    case Derivatives::Analytic: return "analytic";
    case Derivatives::QuadCoarse: return "quad-coarse";
    case Derivatives::QuadFine: return "quad-fine";
  }
  return "?";
}

const char* toString(SeamFix fix) {
  switch (fix) {
    case SeamFix::None: return "none";
    case SeamFix::Grad: return "grad";
    case SeamFix::Tarini: return "tarini";
  }
  return "?";
}

Renderer::Renderer() = default;
Renderer::~Renderer() = default;

const Rendering& Renderer::render(const Mesh& mesh, const TexcoordSource& source, const RenderOptions& o) {
  if (!o.texture == !o.cubeTexture) throw UsageError("render: expected one texture, 2D or cube map, to be bound");
  if (!source.pixelMapping && source.corners.size() != 3 * mesh.triangles.size())
    throw UsageError("render: expected 3 texture coordinates per triangle");
  UVTK_CHECK(!needsMipmaps(o.sampler.minFilter) || (o.texture ? o.texture->hasMipmaps() : o.cubeTexture->hasMipmaps()));
  if (source.pixelMapping) {
    const PixelMapping& m = *source.pixelMapping;
    UVTK_CHECK(!m.texcoordAt != !m.blendAt);
    if (m.blendAt && o.cubeTexture) throw UsageError("render: a triplanar blend reads 2D textures");
    if (o.seamFix == SeamFix::Tarini && m.blendAt) throw UsageError("render: Tarini's seam fix applies to one lookup, not a blend");
    if (m.blendAt)
      for (const Texture* t : o.axisTextures) UVTK_CHECK(!t || !needsMipmaps(o.sampler.minFilter) || t->hasMipmaps());
  }
  if (o.seamFix == SeamFix::Tarini && (!source.pixelMapping || !source.pixelMapping->wrapsS))
    throw UsageError("render: Tarini's seam fix needs a per-pixel mapping that wraps in u (sphere, cylinder)");
  const int n = sampleGridSize(o.samplesPerPixel);
  const int width = o.camera.width, height = o.camera.height;
  if (n > 1 && (std::int64_t(width) * n > kMaxViewport || std::int64_t(height) * n > kMaxViewport))
    throw UsageError("--spp: " + std::to_string(o.samplesPerPixel) + " samples per pixel need a " +
                     std::to_string(std::int64_t(width) * n) + " x " + std::to_string(std::int64_t(height) * n) +
                     " frame, larger than the rasterizer's " + std::to_string(kMaxViewport) + " pixels a side");
  checkFrameMemory(mesh, source, o);
  if (n == 1) {
    renderFrame(mesh, source, o, clip_, raster_, scratch_, frame_, nullptr);
    return frame_;
  }

  // The same projection onto an n times larger viewport puts each sample at a pixel centre.
  RenderOptions big = o;
  big.camera.width = width * n;
  big.camera.height = height * n;
  renderFrame(mesh, source, big, clip_, raster_, scratch_, samples_, &sampleCovered_);
  const auto resolveStart = std::chrono::steady_clock::now();
  resolve(samples_, sampleCovered_, n, width, height, o.raster.threads, frame_);
  frame_.shadeMs += millisecondsSince(resolveStart);
  return frame_;
}

Rendering render(const Mesh& mesh, const TexcoordSource& source, const RenderOptions& o) {
  Renderer renderer;
  renderer.render(mesh, source, o);
  return renderer.take();
}

}  // namespace uvtk::render
