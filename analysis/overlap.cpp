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

// One edge ab of a counter-clockwise triangle as a bound on the pixel columns x of a row whose
// centres it keeps: N - 256 dy x >= 0, N = (b - a) x (c - a) at c = (128, centreY) less the tie rule's
// t (0 where the edge owns the centres on it, else 1). A horizontal edge keeps all or none.
class EdgeBound {
 public:
  EdgeBound() = default;
  EdgeBound(const Point& a, const Point& b, std::int64_t centreY)
      : dy_(b.y - a.y),
        step_(kSubpixel * (b.x - a.x)),
        divisor_(kSubpixel * (dy_ < 0 ? -dy_ : dy_)),
        numerator_((b.x - a.x) * (centreY - a.y) - dy_ * (kHalfPixel - a.x) - (ownsCentresOnIt(a, b) ? 0 : 1)) {
    if (dy_ == 0) return;
    quotient_ = floorDiv(numerator_, divisor_);
    remainder_ = numerator_ - quotient_ * divisor_;
    stepQuotient_ = floorDiv(step_, divisor_);
    stepRemainder_ = step_ - stepQuotient_ * divisor_;
  }

  // Narrows [x0, x1] to this row's centres on the kept side.
  void limit(std::int64_t& x0, std::int64_t& x1) const {
    if (dy_ > 0) {
      x1 = std::min(x1, quotient_);  // x <= floor(N / 256 dy)
    } else if (dy_ < 0) {
      x0 = std::max(x0, -quotient_);  // x >= ceil(N / 256 dy) = -floor(N / 256 |dy|)
    } else if (numerator_ < 0) {
      x1 = x0 - 1;
    }
  }

  // The next row up: N += 256 dx, and floor(N / 256 |dy|) with it.
  void nextRow() {
    numerator_ += step_;
    if (dy_ == 0) return;
    quotient_ += stepQuotient_;
    remainder_ += stepRemainder_;
    if (remainder_ >= divisor_) remainder_ -= divisor_, ++quotient_;
  }

 private:
  std::int64_t dy_ = 0, step_ = 0, divisor_ = 1, numerator_ = 0;
  std::int64_t quotient_ = 0, remainder_ = 0, stepQuotient_ = 0, stepRemainder_ = 0;  // 0 <= remainders < divisor
};

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

namespace {

// forEachCoveredSpan with the visit inlined: the raster's loops call it once a row.
template <class Visit>
void forEachSpan(const UvMap& uv, const std::vector<FaceDistortion>& faces, const UvGrid& grid, Visit&& visit) {
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
    const std::int64_t boxX0 = std::max<std::int64_t>(0, floorDiv(minX - kHalfPixel + kSubpixel - 1, kSubpixel));
    const std::int64_t boxX1 = std::min<std::int64_t>(resolution - 1, floorDiv(maxX - kHalfPixel, kSubpixel));
    const std::int64_t y0 = std::max<std::int64_t>(0, floorDiv(minY - kHalfPixel + kSubpixel - 1, kSubpixel));
    const std::int64_t y1 = std::min<std::int64_t>(resolution - 1, floorDiv(maxY - kHalfPixel, kSubpixel));
    // Each edge ab keeps the centres c of a row where its edge function (b - a) x (c - a), linear in
    // c.x = 256 x + 128, is positive (or zero on an edge that owns them): N - 256 dy x >= 0 with
    // N = K - t, solved for x exactly in integers; N grows by 256 dx a row, so each bound
    // floor(N / 256 |dy|) steps on without a division. The span is the same set of centres a test of
    // each one would keep.
    EdgeBound bounds[3];
    for (int e = 0; e < 3; ++e) bounds[e] = EdgeBound(p[e], p[(e + 1) % 3], y0 * kSubpixel + kHalfPixel);
    for (std::int64_t y = y0; y <= y1; ++y) {
      std::int64_t x0 = boxX0, x1 = boxX1;
      for (EdgeBound& bound : bounds) {
        bound.limit(x0, x1);
        bound.nextRow();
      }
      if (x0 <= x1) visit(f, static_cast<int>(y), static_cast<int>(x0), static_cast<int>(x1));
    }
  }
}

}  // namespace

void forEachCoveredSpan(const UvMap& uv, const std::vector<FaceDistortion>& faces, const UvGrid& grid,
                        const std::function<void(std::size_t face, int y, int x0, int x1)>& visit) {
  forEachSpan(uv, faces, grid, visit);
}

void forEachCoveredPixel(const UvMap& uv, const std::vector<FaceDistortion>& faces, const UvGrid& grid,
                         const std::function<void(std::size_t face, int x, int y)>& visit) {
  forEachCoveredSpan(uv, faces, grid, [&](std::size_t face, int y, int x0, int x1) {
    for (int x = x0; x <= x1; ++x) visit(face, x, y);
  });
}

std::vector<std::uint8_t> coverageCounts(const UvMap& uv, const std::vector<FaceDistortion>& faces, const UvGrid& grid) {
  const auto n = static_cast<std::size_t>(grid.resolution);
  std::vector<std::uint8_t> counts(n * n, 0);
  forEachSpan(uv, faces, grid, [&](std::size_t, int y, int x0, int x1) {
    std::uint8_t* row = counts.data() + static_cast<std::size_t>(y) * n;
    for (int x = x0; x <= x1; ++x) row[x] = static_cast<std::uint8_t>(row[x] + (row[x] < 255));  // saturating
  });
  return counts;
}

int overlapResolution(const UvMap& uv, const std::vector<FaceDistortion>& faces, const UvGrid& unitGrid,
                      int resolution) {
  // The faces' UV area and height as fractions of the grid's box (the grid's own scaling keeps them finite).
  const Vec2 origin = unitGrid.bounds.min(), size = unitGrid.bounds.sizes();
  double area = 0.0, height = 0.0;
  std::size_t measured = 0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (!isMeasured(faces[f].status)) continue;
    ++measured;
    Vec2 p[3];
    for (int k = 0; k < 3; ++k) p[k] = (uv.uv[3 * f + std::size_t(k)] * unitGrid.scale - origin).cwiseQuotient(size);
    const Vec2 e1 = p[1] - p[0], e2 = p[2] - p[0];
    area += 0.5 * std::fabs(e1.x() * e2.y() - e1.y() * e2.x());
    height += std::max({p[0].y(), p[1].y(), p[2].y()}) - std::min({p[0].y(), p[1].y(), p[2].y()});
  }
  const double budget = kOverlapWorkBase + kOverlapWorkPerFace * double(measured);
  auto work = [&](double r) { return area * r * r + height * r + double(measured); };
  while (resolution > 1 && work(double(resolution)) > budget) resolution /= 2;
  return resolution;
}

Overlap measureOverlap(const UvMap& uv, const std::vector<FaceDistortion>& faces, int resolution) {
  UVTK_CHECK(uv.uv.size() == 3 * faces.size());
  UVTK_CHECK(resolution >= 1 && resolution <= 65536);
  Overlap overlap;
  overlap.resolution = resolution;
  const Eigen::AlignedBox2d bounds = measuredUvBounds(uv, faces);
  if (bounds.isEmpty()) return overlap;
  resolution = overlap.resolution = overlapResolution(uv, faces, uvGridOver(bounds, 1), resolution);
  const UvGrid grid = uvGridOver(bounds, resolution);
  const std::vector<std::uint8_t> counts = coverageCounts(uv, faces, grid);
  for (std::uint8_t count : counts) {
    overlap.coveredPixels += count >= 1;
    overlap.overlappedPixels += count >= 2;
  }
  if (overlap.overlappedPixels == 0) return overlap;
  // The faces that cover a centre another face covers too: a second pass over the same spans.
  std::vector<std::uint8_t> overlapped(faces.size(), 0);
  const auto n = static_cast<std::size_t>(resolution);
  forEachSpan(uv, faces, grid, [&](std::size_t face, int y, int x0, int x1) {
    if (overlapped[face]) return;
    const std::uint8_t* row = counts.data() + static_cast<std::size_t>(y) * n;
    overlapped[face] = std::any_of(row + x0, row + x1 + 1, [](std::uint8_t count) { return count >= 2; });
  });
  overlap.overlappedFaces = static_cast<std::size_t>(std::count(overlapped.begin(), overlapped.end(), std::uint8_t(1)));
  return overlap;
}

}  // namespace uvtk::analysis
