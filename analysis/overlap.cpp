#include "analysis/overlap.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include <Eigen/Geometry>

#include "core/error.h"

namespace uvtk::analysis {

namespace {

constexpr std::int64_t kSubpixel = 256;  // corners snap to 1/256 pixel
constexpr std::int64_t kHalfPixel = kSubpixel / 2;

struct Point {
  std::int64_t x, y;
};

// Twice the signed area of the triangle abc: positive when counter-clockwise.
std::int64_t twiceArea(const Point& a, const Point& b, const Point& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The tie rule: of the two directions of an edge exactly one owns the pixel centres on it.
bool ownsCentresOnIt(const Point& a, const Point& b) { return b.y < a.y || (b.y == a.y && b.x > a.x); }

std::int64_t floorDiv(std::int64_t a, std::int64_t b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }

}  // namespace

Eigen::AlignedBox2d measuredUvBounds(const UvMap& uv, const std::vector<FaceDistortion>& faces) {
  Eigen::AlignedBox2d box;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (isMeasured(faces[f].status))
      for (std::size_t corner = 3 * f; corner < 3 * f + 3; ++corner) box.extend(uv.uv[corner]);
  return box;
}

UvGrid uvGridOver(const Eigen::AlignedBox2d& uvBounds, int resolution) {
  UVTK_CHECK(!uvBounds.isEmpty() && uvBounds.min().allFinite() && uvBounds.max().allFinite());
  const double scale = measureUvScale(uvBounds);
  return {Eigen::AlignedBox2d(uvBounds.min() * scale, uvBounds.max() * scale), resolution, scale};
}

void forEachCoveredPixel(const UvMap& uv, const std::vector<FaceDistortion>& faces, const UvGrid& grid,
                         const std::function<void(std::size_t face, int x, int y)>& visit) {
  UVTK_CHECK(uv.uv.size() == 3 * faces.size());
  const int resolution = grid.resolution;
  UVTK_CHECK(resolution >= 1 && resolution <= 65536);
  const Vec2 origin = grid.bounds.min(), size = grid.bounds.sizes();
  UVTK_CHECK(origin.allFinite() && size.allFinite() && size.x() > 0.0 && size.y() > 0.0);
  auto snap = [&](const Vec2& uvPoint) {
    const Vec2 relative = (uvPoint * grid.scale - origin).cwiseQuotient(size);  // in [0, 1] over the grid
    UVTK_CHECK(relative.x() >= -1.0 && relative.x() <= 2.0 && relative.y() >= -1.0 && relative.y() <= 2.0);
    const double scale = static_cast<double>(resolution * kSubpixel);
    return Point{std::llround(relative.x() * scale), std::llround(relative.y() * scale)};
  };

  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (!isMeasured(faces[f].status)) continue;
    Point p[3] = {snap(uv.uv[3 * f]), snap(uv.uv[3 * f + 1]), snap(uv.uv[3 * f + 2])};
    const std::int64_t area = twiceArea(p[0], p[1], p[2]);
    if (area == 0) continue;  // snapping collapsed it: it covers no centre
    if (area < 0) std::swap(p[1], p[2]);
    // Pixels whose centre (i + 1/2) lies within the triangle's snapped bounding box.
    const std::int64_t minX = std::min({p[0].x, p[1].x, p[2].x}), maxX = std::max({p[0].x, p[1].x, p[2].x});
    const std::int64_t minY = std::min({p[0].y, p[1].y, p[2].y}), maxY = std::max({p[0].y, p[1].y, p[2].y});
    const std::int64_t x0 = std::max<std::int64_t>(0, floorDiv(minX - kHalfPixel + kSubpixel - 1, kSubpixel));
    const std::int64_t x1 = std::min<std::int64_t>(resolution - 1, floorDiv(maxX - kHalfPixel, kSubpixel));
    const std::int64_t y0 = std::max<std::int64_t>(0, floorDiv(minY - kHalfPixel + kSubpixel - 1, kSubpixel));
    const std::int64_t y1 = std::min<std::int64_t>(resolution - 1, floorDiv(maxY - kHalfPixel, kSubpixel));
    for (std::int64_t y = y0; y <= y1; ++y)
      for (std::int64_t x = x0; x <= x1; ++x) {
        const Point centre{x * kSubpixel + kHalfPixel, y * kSubpixel + kHalfPixel};
        bool inside = true;
        for (int e = 0; e < 3 && inside; ++e) {
          const Point& a = p[e];
          const Point& b = p[(e + 1) % 3];
          // Edge function (b - a) x (centre - a): positive inside a counter-clockwise triangle.
          const std::int64_t edge = twiceArea(a, b, centre);
          inside = edge > 0 || (edge == 0 && ownsCentresOnIt(a, b));
        }
        if (inside) visit(f, static_cast<int>(x), static_cast<int>(y));
      }
  }
}

std::vector<std::uint8_t> coverageCounts(const UvMap& uv, const std::vector<FaceDistortion>& faces, const UvGrid& grid) {
  const auto n = static_cast<std::size_t>(grid.resolution);
  std::vector<std::uint8_t> counts(n * n, 0);
  forEachCoveredPixel(uv, faces, grid, [&](std::size_t, int x, int y) {
    std::uint8_t& count = counts[static_cast<std::size_t>(y) * n + static_cast<std::size_t>(x)];
    if (count < 255) ++count;
  });
  return counts;
}

Overlap measureOverlap(const UvMap& uv, const std::vector<FaceDistortion>& faces, int resolution) {
  UVTK_CHECK(uv.uv.size() == 3 * faces.size());
  UVTK_CHECK(resolution >= 1 && resolution <= 65536);
  Overlap overlap;
  overlap.resolution = resolution;
  const Eigen::AlignedBox2d bounds = measuredUvBounds(uv, faces);
  if (bounds.isEmpty()) return overlap;
  for (std::uint8_t count : coverageCounts(uv, faces, uvGridOver(bounds, resolution))) {
    overlap.coveredPixels += count >= 1;
    overlap.overlappedPixels += count >= 2;
  }
  return overlap;
}

}  // namespace uvtk::analysis
