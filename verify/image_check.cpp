#include "verify/image_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <string>

#include "core/error.h"
#include "render/raster.h"
#include "render/texture.h"

namespace uvtk::verify {

namespace {

using render::Filter;
using render::LevelChoice;
using render::SamplerState;
using render::TexelLevel;
using render::Texture;
using render::Wrap;

// A set of colours, one interval per channel: what one lookup (one texel, one quad's range of
// weights, one blend of two such) can give. A pixel matches a box when each of its channels does.
struct Box {
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 high = Vec3::Constant(-std::numeric_limits<double>::infinity());

  void add(const Vec3& c) { low = low.cwiseMin(c), high = high.cwiseMax(c); }
  void add(const Box& b) { low = low.cwiseMin(b.low), high = high.cwiseMax(b.high); }
  bool contains(const Vec3& c, double threshold) const {
    return ((c.array() >= low.array() - threshold) && (c.array() <= high.array() + threshold)).all();
  }
};

Vec3 rgb(const render::Rgba& texel) { return texel.head<3>().cast<double>(); }

// The raw texel indices from `first` to `last` that a coordinate interval selects along one axis,
// bounded so that a far coordinate (a huge interval) visits each wrapped texel without visiting
// 2^62 of them: under CLAMP_TO_EDGE the indices beyond [-1, size] repeat the edge's; under REPEAT
// and MIRRORED_REPEAT any 2 size + 1 consecutive indices reach every texel and every pair.
struct IndexRange {
  std::int64_t first, last;
  bool whole;  // the interval was cut: every weight in [0, 1] is possible
};

IndexRange indexRange(std::int64_t first, std::int64_t last, int size, Wrap wrap) {
  if (wrap == Wrap::ClampToEdge) {
    first = std::clamp<std::int64_t>(first, -1, size), last = std::clamp<std::int64_t>(last, -1, size);
    return {first, last, false};
  }
  if (last - first > 2 * std::int64_t(size)) return {first, first + 2 * std::int64_t(size), true};
  return {first, last, false};
}

// The coordinate interval around s allowed at a level `size` texels wide: max(1, |s size|)
// 2^-coordBits texels either side (dEQP's coordBits on the texel-space coordinate).
std::array<double, 2> coordinateInterval(double s, int size, double coordEps) {
  const double e = std::max(1.0, std::abs(s * size)) * coordEps / size;
  return {s - e, s + e};
}

struct Tolerances {
  double coordEps, weightEps, lodEps, colourEps;
};

// NEAREST within one level: each texel the coordinate box can select.
void nearestBoxes(const TexelLevel& level, const SamplerState& sampler, double s, double t, const Tolerances& tol,
                  std::vector<Box>& out) {
  const auto [s0, s1] = coordinateInterval(s, level.width, tol.coordEps);
  const auto [t0, t1] = coordinateInterval(t, level.height, tol.coordEps);
  const IndexRange is = indexRange(render::nearestTexel(s0, level.width), render::nearestTexel(s1, level.width),
                                   level.width, sampler.wrapS);
  const IndexRange js = indexRange(render::nearestTexel(t0, level.height), render::nearestTexel(t1, level.height),
                                   level.height, sampler.wrapT);
  for (std::int64_t j = js.first; j <= js.last; ++j)
    for (std::int64_t i = is.first; i <= is.last; ++i) {
      Box box;
      box.add(rgb(level.at(render::wrapTexel(i, level.width, sampler.wrapS),
                           render::wrapTexel(j, level.height, sampler.wrapT))));
      out.push_back(box);
    }
}

// The weights of one axis's upper texel for the pair whose lower texel is `lower`: the pair's
// share of the coordinate box, widened by the weight rounding.
std::array<double, 2> weightInterval(std::int64_t lower, const render::LinearTap& low, const render::LinearTap& high,
                                     bool whole, double weightEps) {
  const double a0 = !whole && lower == low.lower ? low.alpha : 0.0;
  const double a1 = !whole && lower == high.lower ? high.alpha : 1.0;
  return {std::max(0.0, a0 - weightEps), std::min(1.0, a1 + weightEps)};
}

// LINEAR within one level: per 2 x 2 quad the box touches, the range over its weights. Bilinear
// in (alpha, beta), so each channel's extremes lie at the corners of the weights' rectangle.
void linearBoxes(const TexelLevel& level, const SamplerState& sampler, double s, double t, const Tolerances& tol,
                 std::vector<Box>& out) {
  const auto [s0, s1] = coordinateInterval(s, level.width, tol.coordEps);
  const auto [t0, t1] = coordinateInterval(t, level.height, tol.coordEps);
  const render::LinearTap u0 = render::linearTap(s0, level.width), u1 = render::linearTap(s1, level.width);
  const render::LinearTap v0 = render::linearTap(t0, level.height), v1 = render::linearTap(t1, level.height);
  const IndexRange is = indexRange(u0.lower, u1.lower, level.width, sampler.wrapS);
  const IndexRange js = indexRange(v0.lower, v1.lower, level.height, sampler.wrapT);
  for (std::int64_t j = js.first; j <= js.last; ++j)
    for (std::int64_t i = is.first; i <= is.last; ++i) {
      const int i0 = render::wrapTexel(i, level.width, sampler.wrapS);
      const int i1 = render::wrapTexel(i + 1, level.width, sampler.wrapS);
      const int j0 = render::wrapTexel(j, level.height, sampler.wrapT);
      const int j1 = render::wrapTexel(j + 1, level.height, sampler.wrapT);
      const auto alphas = weightInterval(i, u0, u1, is.whole, tol.weightEps);
      const auto betas = weightInterval(j, v0, v1, js.whole, tol.weightEps);
      Box box;
      for (double a : alphas)
        for (double b : betas)
          box.add(render::bilinear(rgb(level.at(i0, j0)), rgb(level.at(i1, j0)), rgb(level.at(i0, j1)),
                                   rgb(level.at(i1, j1)), a, b));
      out.push_back(box);
    }
}

void levelBoxes(const TexelLevel& level, bool linear, const SamplerState& sampler, double s, double t,
                const Tolerances& tol, std::vector<Box>& out) {
  linear ? linearBoxes(level, sampler, s, t, tol, out) : nearestBoxes(level, sampler, s, t, tol, out);
}

// Every lookup the filter can make at (s, t) for a lambda in [lambdaLow, lambdaHigh]. The range
// is cut at every point where render::chooseLevels may change its levels (the crossover c, the
// halves and the integers); within a piece the levels are fixed and a two-level blend is linear
// in its weight frac(lambda), so its extremes lie at the piece's ends.
std::vector<Box> lookupBoxes(const Texture& texture, const SamplerState& sampler, double s, double t,
                             double lambdaLow, double lambdaHigh, const Tolerances& tol) {
  std::vector<Box> boxes;
  if (!std::isfinite(s) || !std::isfinite(t)) {  // render::sample's texel (0, 0) of level 0
    boxes.emplace_back().add(rgb(texture.level(0).at(0, 0)));
    return boxes;
  }
  const int levelCount = render::needsMipmaps(sampler.minFilter) ? texture.levelCount() : 1;
  // Below -1 every filter magnifies, above levelCount + 1 every one reads the coarsest level.
  const double low = std::clamp(lambdaLow, -1.0, levelCount + 1.0), high = std::clamp(lambdaHigh, -1.0, levelCount + 1.0);
  std::vector<double> cuts{low};
  for (double c = std::floor(low * 2) / 2 + 0.5; c < high; c += 0.5) cuts.push_back(c);
  cuts.push_back(high);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double a = cuts[k], b = cuts[k + 1];
    const LevelChoice choice = render::chooseLevels(sampler, levelCount, (a + b) / 2);
    std::array<std::vector<Box>, 2> perLevel;
    for (int l = 0; l < choice.count; ++l)
      levelBoxes(texture.level(choice.level[std::size_t(l)]), choice.linear, sampler, s, t, tol, perLevel[std::size_t(l)]);
    if (choice.count == 1) {
      boxes.insert(boxes.end(), perLevel[0].begin(), perLevel[0].end());
      continue;
    }
    // GL 4.6 §8.14.3: tau = (1 - f) tau1 + f tau2, f = frac(lambda) = lambda - d1 on this piece.
    const std::array<double, 2> weights{std::max(0.0, a - choice.level[0] - tol.weightEps),
                                        std::min(1.0, b - choice.level[0] + tol.weightEps)};
    for (const Box& first : perLevel[0])
      for (const Box& second : perLevel[1]) {
        Box box;
        for (double f : weights) {
          box.add(Vec3((1 - f) * first.low + f * second.low));
          box.add(Vec3((1 - f) * first.high + f * second.high));
        }
        boxes.push_back(box);
      }
  }
  return boxes;
}

// GL 4.6 §8.14.1 lets an implementation take for rho any f(x, y) with max(m_u, m_v) <= f <= m_u +
// m_v, m_u = max(|du/dx|, |du/dy|) and m_v likewise in texels; Mesa's llvmpipe and softpipe take
// the lower bound. We allow f from that lower bound to the exact rho, not up to the sum: that is
// up to a whole level above (for an isotropic footprint along the texel axes), where a lambda + 1
// fault would hide. The lower bound over the exact rho at pixel (x, row), from the differences of
// its (u, v) to its neighbours on the same face (central, else one-sided), as log2: within
// [-1/2, 0] (max(m_u, m_v) >= rho / sqrt 2), and -1/2 where a difference is missing or rho is 0.
double rhoApproximation(const Image& aovs, int x, int row, int width, int height) {
  constexpr double kLowest = -0.5;
  const auto texels = [&](int px, int py) { return Vec2(aovs.at(px, py, 0) * width, aovs.at(px, py, 1) * height); };
  const auto sameFace = [&](int px, int py) {
    return px >= 0 && py >= 0 && px < aovs.width && py < aovs.height && aovs.at(px, py, 3) == aovs.at(x, row, 3) &&
           texels(px, py).allFinite();
  };
  const auto derivative = [&](int dx, int dy, Vec2& out) {
    const bool before = sameFace(x - dx, row - dy), after = sameFace(x + dx, row + dy);
    if (before && after) out = (texels(x + dx, row + dy) - texels(x - dx, row - dy)) / 2;
    else if (before) out = texels(x, row) - texels(x - dx, row - dy);
    else if (after) out = texels(x + dx, row + dy) - texels(x, row);
    return before || after;
  };
  Vec2 ddx, ddy;
  if (!texels(x, row).allFinite() || !derivative(1, 0, ddx) || !derivative(0, 1, ddy)) return kLowest;
  const double rho = std::max(ddx.norm(), ddy.norm());
  const double mu = std::max(std::abs(ddx.x()), std::abs(ddy.x())), mv = std::max(std::abs(ddx.y()), std::abs(ddy.y()));
  if (!(rho > 0) || !std::isfinite(rho)) return kLowest;
  return std::clamp(std::log2(std::max(mu, mv) / rho), kLowest, 0.0);
}

// Distances from p to a triangle in window coordinates: to its boundary, and to the triangle (0
// inside, either winding).
double segmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double squared = d.squaredNorm();
  const double t = squared > 0.0 ? std::clamp((p - a).dot(d) / squared, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

double boundaryDistance(const Vec2& p, const std::array<Vec2, 3>& t) {
  return std::min({segmentDistance(p, t[0], t[1]), segmentDistance(p, t[1], t[2]), segmentDistance(p, t[2], t[0])});
}

double triangleDistance(const Vec2& p, const std::array<Vec2, 3>& t) {
  const auto side = [&](const Vec2& a, const Vec2& b) { return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x()); };
  const double s0 = side(t[0], t[1]), s1 = side(t[1], t[2]), s2 = side(t[2], t[0]);
  const bool inside = (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
  return inside ? 0.0 : boundaryDistance(p, t);
}

// The faces in front of the eye in window coordinates (y up), binned by their boxes into square
// cells, for the faces near a pixel. A face with a corner on or behind the eye's plane is left out.
struct WindowFaces {
  static constexpr int kCell = 8;  // pixels
  int columns = 0, rows = 0;
  std::vector<std::array<Vec2, 3>> corners;  // per face
  std::vector<char> inFront;                 // per face
  std::vector<std::vector<int>> cells;

  WindowFaces(const Reference& reference, int width, int height, double slack) {
    columns = (width + kCell - 1) / kCell, rows = (height + kCell - 1) / kCell;
    cells.resize(std::size_t(columns) * std::size_t(rows));
    corners.resize(reference.triangles.size());
    inFront.assign(reference.triangles.size(), 0);
    for (std::size_t f = 0; f < reference.triangles.size(); ++f) {
      bool front = true;
      Eigen::AlignedBox2d box;
      for (int k = 0; k < 3; ++k) {
        const Vec4& c = reference.clip[std::size_t(reference.triangles[f][k])];
        front = front && c.w() > 0.0;
        corners[f][std::size_t(k)] = Vec2((c.x() / c.w() + 1.0) * 0.5 * width, (c.y() / c.w() + 1.0) * 0.5 * height);
        box.extend(corners[f][std::size_t(k)]);
      }
      if (!front || !box.min().allFinite() || !box.max().allFinite()) continue;
      inFront[f] = 1;
      const int x0 = std::max(0, int(std::floor((box.min().x() - slack) / kCell)));
      const int x1 = std::min(columns - 1, int(std::floor((box.max().x() + slack) / kCell)));
      const int y0 = std::max(0, int(std::floor((box.min().y() - slack) / kCell)));
      const int y1 = std::min(rows - 1, int(std::floor((box.max().y() + slack) / kCell)));
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) cells[std::size_t(y) * std::size_t(columns) + std::size_t(x)].push_back(int(f));
    }
  }
  const std::vector<int>& near(const Vec2& p) const {
    const int x = std::clamp(int(p.x()) / kCell, 0, columns - 1), y = std::clamp(int(p.y()) / kCell, 0, rows - 1);
    return cells[std::size_t(y) * std::size_t(columns) + std::size_t(x)];
  }
};

void requireSupported(const render::RenderOptions& o) {
  const auto unsupported = [](const std::string& what) {
    throw UsageError("image check: " + what + " is not supported (2D textures with the replace environment only)");
  };
  if (o.cubeTexture) unsupported("a cube-map texture");
  if (!o.texture) unsupported("a rendering without a texture");
  if (o.axisTextures[0] || o.axisTextures[1] || o.axisTextures[2]) unsupported("a blend of textures (triplanar)");
  if (o.env != render::EnvMode::Replace) unsupported("a texture environment other than replace (and lighting)");
  if (o.samplesPerPixel != 1) unsupported("supersampling (" + std::to_string(o.samplesPerPixel) + " samples per pixel)");
  if (render::needsMipmaps(o.sampler.minFilter) && !o.texture->hasMipmaps())
    unsupported("a mipmap filter on a texture without mipmaps");
}

int checkedBits(std::optional<int> bits, int fallback, int maximum, const char* name) {
  const int value = bits.value_or(fallback);
  if (value < 1 || value > maximum)
    throw UsageError(std::string("image check: ") + name + ": expected 1 to " + std::to_string(maximum) +
                     " bits, got " + std::to_string(value));
  return value;
}

}  // namespace

ImagePrecision resolvePrecision(const ImagePrecision& precision, const SamplerState& sampler, bool projective) {
  const bool trilinear =
      sampler.minFilter == Filter::NearestMipmapLinear || sampler.minFilter == Filter::LinearMipmapLinear;
  ImagePrecision out;
  out.coordBits = checkedBits(precision.coordBits, 20, 30, "coord-bits");
  out.weightBits = checkedBits(precision.weightBits, 16, 30, "weight-bits");
  out.lodBits = checkedBits(precision.lodBits, 6, 30, "lod-bits");
  out.colorBits = checkedBits(precision.colorBits, trilinear ? 8 - 2 : 8 - 1, 16, "color-bits");
  return out;
}

Reference drawReference(const Mesh& mesh, const render::TexcoordSource& texcoords, const render::RenderOptions& options) {
  requireSupported(options);
  if (texcoords.pixelMapping && texcoords.pixelMapping->blendAt)
    throw UsageError("image check: a blend of lookups (triplanar) is not supported (2D textures with the replace "
                     "environment only)");
  render::RenderOptions o = options;
  o.aovs = true;
  o.derivatives = render::Derivatives::Analytic;
  Reference reference{render::render(mesh, texcoords, o), {}, {}, {}, {}};
  if (!texcoords.pixelMapping) {
    render::clipPositions(mesh, o.camera.clipFromView * o.camera.viewFromWorld * o.worldFromObject, o.raster.threads,
                          reference.clip);
    reference.triangles = mesh.triangles;
    reference.corners = texcoords.corners;
  }
  o.seamFix = texcoords.pixelMapping && texcoords.pixelMapping->wrapsS ? render::SeamFix::Tarini : render::SeamFix::None;
  o.derivatives = render::Derivatives::QuadFine;
  reference.quadAovs.push_back(render::render(mesh, texcoords, o).aovs);
  o.derivatives = render::Derivatives::QuadCoarse;
  for (int mirror = 0; mirror < 4; ++mirror) {  // bit 0: x mirrored, bit 1: y mirrored
    render::RenderOptions q = o;
    Mat4 flip = Mat4::Identity();
    if (mirror & 1) flip(0, 0) = -1;
    if (mirror & 2) flip(1, 1) = -1;
    q.camera.clipFromView = flip * o.camera.clipFromView;
    if (mirror == 1 || mirror == 2)  // one mirror turns counter-clockwise triangles clockwise
      q.raster.cull = o.raster.cull == render::Cull::Back    ? render::Cull::Front
                      : o.raster.cull == render::Cull::Front ? render::Cull::Back
                                                             : render::Cull::None;
    const Image drawn = render::render(mesh, texcoords, q).aovs;
    Image aovs = drawn;
    for (int row = 0; row < drawn.height; ++row)
      for (int x = 0; x < drawn.width; ++x)
        for (int c = 0; c < drawn.channels; ++c)
          aovs.at(x, row, c) = drawn.at(mirror & 1 ? drawn.width - 1 - x : x, mirror & 2 ? drawn.height - 1 - row : row, c);
    reference.quadAovs.push_back(std::move(aovs));
  }
  return reference;
}

ImageCheckResult checkImage(const Image& shot, const Reference& reference, const render::RenderOptions& options,
                            bool projective, const ImagePrecision& precision) {
  requireSupported(options);
  const Image& aovs = reference.analytic.aovs;
  const int width = aovs.width, height = aovs.height;
  const auto hasAovs = [&](const Image& image) { return image.channels >= 5 && image.width == width && image.height == height; };
  if (!hasAovs(aovs) || !std::all_of(reference.quadAovs.begin(), reference.quadAovs.end(), hasAovs))
    throw UsageError("image check: a reference drawn without AOVs (RenderOptions::aovs) or of another size");
  if (shot.width != width || shot.height != height)
    throw UsageError("image check: the shot is " + std::to_string(shot.width) + " x " + std::to_string(shot.height) +
                     " pixels, the reference " + std::to_string(width) + " x " + std::to_string(height));
  if (shot.channels < 1 || shot.channels > 4)
    throw UsageError("image check: expected a shot of 1 to 4 channels, got " + std::to_string(shot.channels));

  ImageCheckResult result;
  result.precision = resolvePrecision(precision, options.sampler, projective);
  const Tolerances tol{std::exp2(-result.precision.coordBits), std::exp2(-result.precision.weightBits),
                       std::exp2(-*result.precision.lodBits), std::exp2(-*result.precision.colorBits)};
  const auto face = [&](int x, int row) { return int(aovs.at(x, row, 3)); };
  const auto shotColour = [&](int x, int row) {
    if (shot.channels < 3) return Vec3::Constant(shot.at(x, row, 0)).eval();  // grey (and alpha)
    return Vec3(shot.at(x, row, 0), shot.at(x, row, 1), shot.at(x, row, 2));
  };

  // The colours pixel (x, row) may show by its own surface: the background, or every lookup for
  // its (u, v) over its lambda widened to that of its 3 x 3 neighbours on the same face (a GPU's
  // derivatives are differences across its 2 x 2 quad) and, where that neighbourhood holds another
  // face or the background, to the quad renderings' lambda (the quad extrapolates the triangle
  // there); lowered by GL's approximation of rho, then widened by 2^-lodBits.
  const auto ownBoxes = [&](int x, int row) {
    const int f = face(x, row);
    if (f < 0) {
      std::vector<Box> boxes(1);
      boxes[0].add(options.background);
      return boxes;
    }
    double low = aovs.at(x, row, 4), high = low;
    const auto widen = [&](double lambda) { low = std::min(low, lambda), high = std::max(high, lambda); };
    for (int ny = std::max(0, row - 1); ny <= std::min(height - 1, row + 1); ++ny)
      for (int nx = std::max(0, x - 1); nx <= std::min(width - 1, x + 1); ++nx)
        if (face(nx, ny) == f) widen(aovs.at(nx, ny, 4));
    for (const Image& quad : reference.quadAovs)
      if (quad.at(x, row, 3) == f) widen(quad.at(x, row, 4));
    low += rhoApproximation(aovs, x, row, options.texture->width(), options.texture->height());
    return lookupBoxes(*options.texture, options.sampler, aovs.at(x, row, 0), aovs.at(x, row, 1), low - tol.lodEps,
                       high + tol.lodEps, tol);
  };
  const auto matches = [&](const std::vector<Box>& boxes, const Vec3& colour) {
    return std::any_of(boxes.begin(), boxes.end(), [&](const Box& b) { return b.contains(colour, tol.colourEps); });
  };
  // The colours pixel (x, row) may show if face g, not the reference's face there, is drawn at it
  // (an edge a GPU places elsewhere, by its own snapping and depth precision: at grazing angles and
  // silhouettes that may be a face the reference shows only diagonally beside it): g's coordinates
  // extrapolated to the pixel's centre, its lambda over the pixel's 3 x 3 neighbourhood extrapolated
  // likewise (dEQP widens the level-of-detail bounds over the +-1 pixel neighbourhood), lowered by
  // GL's approximation of rho (at most 1/2) and widened by 2^-lodBits.
  const Texture& texture = *options.texture;
  const auto extrapolatedBoxes = [&](int g, int x, int row) {
    std::vector<Box> boxes;
    const Triangle& t = reference.triangles[std::size_t(g)];
    const render::TriangleInterpolator triangle(reference.clip[std::size_t(t[0])], reference.clip[std::size_t(t[1])],
                                                reference.clip[std::size_t(t[2])], width, height);
    if (!triangle.valid()) return boxes;
    const Vec4* corners = &reference.corners[3 * std::size_t(g)];
    const auto at = [&](double wx, double wy, Vec2& st) {  // as the renderer interpolates them
      const render::TriangleInterpolator::Barycentrics b = triangle.at(wx, wy);
      Vec4 tc = Vec4::Zero(), dx = Vec4::Zero(), dy = Vec4::Zero();
      for (int k = 0; k < 3; ++k) tc += b.b[k] * corners[k], dx += b.dbdx[k] * corners[k], dy += b.dbdy[k] * corners[k];
      const double q = tc.w();
      st = tc.head<2>() / q;
      const Vec2 dstDx = (dx.head<2>() * q - tc.head<2>() * dx.w()) / (q * q);
      const Vec2 dstDy = (dy.head<2>() * q - tc.head<2>() * dy.w()) / (q * q);
      return render::levelOfDetail(texture.width(), texture.height(), dstDx, dstDy) + options.lodBias;
    };
    const double cx = x + 0.5, cy = height - row - 0.5;  // window coordinates, y up
    Vec2 st;
    double low = at(cx, cy, st), high = low;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        Vec2 ignored;
        const double lambda = at(cx + dx, cy + dy, ignored);
        if (!std::isnan(lambda)) low = std::min(low, lambda), high = std::max(high, lambda);
      }
    if (!st.allFinite() || std::isnan(low) || std::isnan(high)) return boxes;
    return lookupBoxes(texture, options.sampler, st.x(), st.y(), low - 0.5 - tol.lodEps, high + tol.lodEps, tol);
  };

  // The edge rule's second step, for a pixel still invalid: a face whose triangle reaches within
  // kEdgeSlack of its centre may be the one drawn there, if it lies in front (within the depth one
  // pixel's snapping moves the shown face) or the shown face's own edge passes that near (a GPU
  // may leave the centre out of it and show what lies behind). These are faces no neighbour's
  // centre shows: slivers at silhouettes, a face behind a near edge, two faces at one depth.
  constexpr double kEdgeSlack = 1.0 / 8.0;  // pixels: twice dEQP's 1/16
  std::optional<WindowFaces> windowFaces;
  const auto nearFaceMatches = [&](int x, int row, const Vec3& colour) {
    if (!windowFaces) windowFaces.emplace(reference, width, height, kEdgeSlack);
    const Vec2 centre(x + 0.5, height - row - 0.5);
    const int f = face(x, row);
    const auto depthAt = [&](int g) {
      const Triangle& t = reference.triangles[std::size_t(g)];
      const render::TriangleInterpolator triangle(reference.clip[std::size_t(t[0])], reference.clip[std::size_t(t[1])],
                                                  reference.clip[std::size_t(t[2])], width, height);
      const Vec3& plane = triangle.ndcDepthPlane();
      return std::pair<double, double>(plane.x() * centre.x() + plane.y() * centre.y() + plane.z(),
                                       std::abs(plane.x()) + std::abs(plane.y()));
    };
    const bool shownEdgeNear =
        f < 0 || !windowFaces->inFront[std::size_t(f)] || boundaryDistance(centre, windowFaces->corners[std::size_t(f)]) <= kEdgeSlack;
    const auto [shownDepth, shownSlope] = f >= 0 ? depthAt(f) : std::pair<double, double>(0.0, 0.0);
    for (const int g : windowFaces->near(centre)) {
      if (g == f || triangleDistance(centre, windowFaces->corners[std::size_t(g)]) > kEdgeSlack) continue;
      if (!shownEdgeNear) {
        const auto [depth, slope] = depthAt(g);
        if (depth > shownDepth + (shownSlope + slope) * kEdgeSlack + 1e-6) continue;
      }
      if (matches(extrapolatedBoxes(g, x, row), colour)) return true;
    }
    return false;
  };

  result.errorMask = Image(width, height, 3);
  for (int row = 0; row < height; ++row)
    for (int x = 0; x < width; ++x) {
      const Vec3 colour = shotColour(x, row);
      const std::vector<Box> own = ownBoxes(x, row);
      bool valid = matches(own, colour);
      // Next to another face or the background a GPU may place the edge elsewhere (dEQP allows
      // 1/16 pixel): the pixel may show the background or any face of its 3 x 3 neighbourhood,
      // extrapolated to it; for a per-pixel mapping (no corners to extrapolate), what its
      // 4-neighbour across the edge shows.
      const bool extrapolate = !reference.corners.empty();
      for (int ny = std::max(0, row - 1); !valid && ny <= std::min(height - 1, row + 1); ++ny)
        for (int nx = std::max(0, x - 1); !valid && nx <= std::min(width - 1, x + 1); ++nx) {
          const int g = face(nx, ny);
          if (g == face(x, row) || (!extrapolate && std::abs(nx - x) + std::abs(ny - row) != 1)) continue;
          valid = extrapolate && g >= 0 ? matches(extrapolatedBoxes(g, x, row), colour) : matches(ownBoxes(nx, ny), colour);
        }
      if (!valid && extrapolate) valid = nearFaceMatches(x, row, colour);
      const Vec3 shown = valid ? Vec3(colour / 3.0) : Vec3(1, 0, 0);
      for (int c = 0; c < 3; ++c) result.errorMask.at(x, row, c) = float(shown[c]);
      if (valid) continue;
      ++result.invalid;
      if (result.firstInvalid.size() < kFirstInvalid) {
        Box hull;
        for (const Box& b : own) hull.add(b);
        result.firstInvalid.push_back({x, row, colour, (hull.low.array() - tol.colourEps).cwiseMax(0.0),
                                       (hull.high.array() + tol.colourEps).cwiseMin(1.0)});
      }
    }
  result.checked = std::size_t(width) * std::size_t(height);
  result.invalidShare = result.checked ? double(result.invalid) / double(result.checked) : 0.0;
  result.pass = result.invalid == 0;
  return result;
}

}  // namespace uvtk::verify
