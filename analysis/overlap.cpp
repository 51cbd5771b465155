#include "analysis/overlap.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>

#include <Eigen/Geometry>

#include "core/cancel.h"
#include "core/parallel.h"
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

// std::llround (halves away from zero) for |x| < 2^63, inline: the libm call was a quarter of the
// raster's time, six a face and each face snapped up to three times. x - trunc(x) is exact.
std::int64_t roundHalfAway(double x) {
  const std::int64_t whole = static_cast<std::int64_t>(x);  // toward zero
  const double fraction = x - static_cast<double>(whole);
  return whole + (fraction >= 0.5) - (fraction <= -0.5);
}

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

Eigen::AlignedBox2d measuredUvBounds(const UvMap& uv, const FaceMeasures& faces) {
  Bounds2 box;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (isMeasured(faces.status[f]))
      for (std::size_t corner = 3 * f; corner < 3 * f + 3; ++corner) box.extend(uv.uv[corner]);
  return box.box();
}

UvGrid uvGridOver(const Eigen::AlignedBox2d& uvBounds, int resolution) {
  UVTK_CHECK(!uvBounds.isEmpty() && uvBounds.min().allFinite() && uvBounds.max().allFinite());
  const double scale = measureUvScale(uvBounds);
  return {Eigen::AlignedBox2d(uvBounds.min() * scale, uvBounds.max() * scale), resolution, scale};
}

namespace {

// A face's corners snapped to 1/256 pixel of a grid, counter-clockwise, and the box of pixels whose
// centres it can cover, clamped to the grid (empty when x0 > x1 or y0 > y1).
struct SnappedFace {
  Point p[3];
  std::int64_t x0, x1, y0, y1;
};

class GridSnap {
 public:
  explicit GridSnap(const UvGrid& grid)
      : origin_(grid.bounds.min()),
        size_(grid.bounds.sizes()),
        scale_(grid.scale),
        resolution_(grid.resolution),
        subpixels_(static_cast<double>(std::int64_t(grid.resolution) * kSubpixel)) {
    UVTK_CHECK(resolution_ >= 1 && resolution_ <= 65536);
    UVTK_CHECK(origin_.allFinite() && size_.allFinite() && size_.x() > 0.0 && size_.y() > 0.0);
  }

  // Face f's corners, or false when snapping collapsed it (it covers no centre).
  bool snap(const UvMap& uv, std::size_t f, SnappedFace& face) const {
    Point* p = face.p;
    for (int k = 0; k < 3; ++k) p[k] = point(uv.uv[3 * f + std::size_t(k)]);
    const std::int64_t area = twiceArea(p[0], p[1], p[2]);
    if (area == 0) return false;
    if (area < 0) std::swap(p[1], p[2]);
    // Pixels whose centre (i + 1/2) lies within the triangle's snapped bounding box.
    const std::int64_t minX = std::min({p[0].x, p[1].x, p[2].x}), maxX = std::max({p[0].x, p[1].x, p[2].x});
    const std::int64_t minY = std::min({p[0].y, p[1].y, p[2].y}), maxY = std::max({p[0].y, p[1].y, p[2].y});
    face.x0 = std::max<std::int64_t>(0, floorDiv(minX - kHalfPixel + kSubpixel - 1, kSubpixel));
    face.x1 = std::min<std::int64_t>(resolution_ - 1, floorDiv(maxX - kHalfPixel, kSubpixel));
    face.y0 = std::max<std::int64_t>(0, floorDiv(minY - kHalfPixel + kSubpixel - 1, kSubpixel));
    face.y1 = std::min<std::int64_t>(resolution_ - 1, floorDiv(maxY - kHalfPixel, kSubpixel));
    return true;
  }

 private:
  Point point(const Vec2& uvPoint) const {
    const Vec2 relative = (uvPoint * scale_ - origin_).cwiseQuotient(size_);  // in [0, 1] over the grid
    UVTK_CHECK(relative.x() >= -1.0 && relative.x() <= 2.0 && relative.y() >= -1.0 && relative.y() <= 2.0);
    return Point{roundHalfAway(relative.x() * subpixels_), roundHalfAway(relative.y() * subpixels_)};
  }

  Vec2 origin_, size_;
  double scale_;
  int resolution_;
  double subpixels_;
};

// Calls visit(y, x0, x1) for the rows y in [from, to] of `face` with covered centres x0..x1; a
// visit that returns bool ends the walk by returning true.
// Each edge ab keeps the centres c of a row where its edge function (b - a) x (c - a), linear in
// c.x = 256 x + 128, is positive (or zero on an edge that owns them): N - 256 dy x >= 0 with
// N = K - t, solved for x exactly in integers; N grows by 256 dx a row, so each bound
// floor(N / 256 |dy|) steps on without a division. The span is the same set of centres a test of
// each one would keep.
template <class Visit>
void forEachRowSpan(const SnappedFace& face, std::int64_t from, std::int64_t to, Visit&& visit) {
  from = std::max(from, face.y0), to = std::min(to, face.y1);
  if (from > to || face.x0 > face.x1) return;
  EdgeBound bounds[3];
  for (int e = 0; e < 3; ++e) bounds[e] = EdgeBound(face.p[e], face.p[(e + 1) % 3], from * kSubpixel + kHalfPixel);
  for (std::int64_t y = from; y <= to; ++y) {
    std::int64_t x0 = face.x0, x1 = face.x1;
    for (EdgeBound& bound : bounds) {
      bound.limit(x0, x1);
      bound.nextRow();
    }
    if (x0 > x1) continue;
    if constexpr (std::is_same_v<decltype(visit(0, 0, 0)), bool>) {
      if (visit(static_cast<int>(y), static_cast<int>(x0), static_cast<int>(x1))) return;
    } else {
      visit(static_cast<int>(y), static_cast<int>(x0), static_cast<int>(x1));
    }
  }
}

// forEachCoveredSpan with the visit inlined: the raster's loops call it once a row.
template <class Visit>
void forEachSpan(const UvMap& uv, const FaceMeasures& faces, const UvGrid& grid, Visit&& visit) {
  UVTK_CHECK(uv.uv.size() == 3 * faces.size());
  const GridSnap snap(grid);
  SnappedFace face;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (isMeasured(faces.status[f]) && snap.snap(uv, f, face))
      forEachRowSpan(face, 0, grid.resolution - 1, [&](int y, int x0, int x1) { visit(f, y, x0, x1); });
}

// Adds 1 to the counts x0..x1 of a row, saturating at 255.
void countSpan(std::uint8_t* row, int x0, int x1) {
  for (int x = x0; x <= x1; ++x) row[x] = static_cast<std::uint8_t>(row[x] + (row[x] < 255));
}

}  // namespace

void forEachCoveredSpan(const UvMap& uv, const FaceMeasures& faces, const UvGrid& grid,
                        const std::function<void(std::size_t face, int y, int x0, int x1)>& visit) {
  forEachSpan(uv, faces, grid, visit);
}

void forEachCoveredPixel(const UvMap& uv, const FaceMeasures& faces, const UvGrid& grid,
                         const std::function<void(std::size_t face, int x, int y)>& visit) {
  forEachCoveredSpan(uv, faces, grid, [&](std::size_t face, int y, int x0, int x1) {
    for (int x = x0; x <= x1; ++x) visit(face, x, y);
  });
}

std::vector<std::uint8_t> coverageCounts(const UvMap& uv, const FaceMeasures& faces, const UvGrid& grid) {
  const auto n = static_cast<std::size_t>(grid.resolution);
  std::vector<std::uint8_t> counts(n * n, 0);
  forEachSpan(uv, faces, grid,
              [&](std::size_t, int y, int x0, int x1) { countSpan(counts.data() + std::size_t(y) * n, x0, x1); });
  return counts;
}

int followingOverlapResolution(std::size_t measuredFaces, double boxShare) {
  if (!(boxShare > 0.0)) return kOverlapMaxFollowingResolution;
  const double side = std::sqrt(kOverlapPixelsPerFace * double(measuredFaces) / boxShare);
  return int(std::clamp(std::round(side), double(kOverlapMinResolution), double(kOverlapMaxFollowingResolution)));
}

int overlapResolution(const UvMap& uv, const FaceMeasures& faces, const UvGrid& unitGrid,
                      int resolution) {
  // The faces' heights and areas as fractions of the grid's box (the grid's own scaling keeps them finite).
  const Vec2 origin = unitGrid.bounds.min(), size = unitGrid.bounds.sizes();
  double height = 0.0, share = 0.0;
  std::size_t measured = 0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (!isMeasured(faces.status[f])) continue;
    ++measured;
    Vec2 p[3];
    for (int k = 0; k < 3; ++k) p[k] = (uv.uv[3 * f + std::size_t(k)] * unitGrid.scale - origin).cwiseQuotient(size);
    height += std::max({p[0].y(), p[1].y(), p[2].y()}) - std::min({p[0].y(), p[1].y(), p[2].y()});
    const Vec2 a = p[1] - p[0], b = p[2] - p[0];
    share += 0.5 * std::fabs(a.x() * b.y() - a.y() * b.x());
  }
  if (resolution == kOverlapFollowsMesh) resolution = followingOverlapResolution(measured, share);
  const double budget = kOverlapWorkBase + kOverlapWorkPerFace * double(measured);
  // The grid's scan, each face's spans twice (counted, then asked), one step per face.
  auto work = [&](double r) { return r * r + 2.0 * height * r + double(measured); };
  while (resolution > 1 && work(double(resolution)) > budget) resolution /= 2;
  return resolution;
}

Overlap measureOverlap(const UvMap& uv, const FaceMeasures& faces, int resolution, int threads) {
  UVTK_CHECK(uv.uv.size() == 3 * faces.size());
  UVTK_CHECK(resolution >= kOverlapFollowsMesh && resolution <= 65536);
  Overlap overlap;
  overlap.resolution = resolution == kOverlapFollowsMesh ? kOverlapMinResolution : resolution;
  const Eigen::AlignedBox2d bounds = measuredUvBounds(uv, faces);
  if (bounds.isEmpty()) return overlap;
  resolution = overlap.resolution = overlapResolution(uv, faces, uvGridOver(bounds, 1), resolution);
  const UvGrid grid = uvGridOver(bounds, resolution);
  const GridSnap snap(grid);
  const std::int64_t n = resolution;

  // The grid in bands of rows whose buffers (256 KiB at 1024) are used again for each band: touching
  // a whole grid's fresh memory would cost more than the counting. Each face is listed for the bands
  // its rows reach (compressed rows: a count per band, then the faces).
  const std::int64_t bandRows = std::max<std::int64_t>(1, 32768 / (n + 1));
  const std::size_t bands = std::size_t((n + bandRows - 1) / bandRows);
  // A face's first and last band (at most 65536 bands: 16 bits each; {1, 0}: none).
  std::vector<std::array<std::uint16_t, 2>> faceBands(faces.size(), {1, 0});
  std::vector<std::uint32_t> bandStart(bands + 1, 0);
  SnappedFace face;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (isMeasured(faces.status[f]) && snap.snap(uv, f, face) && face.x0 <= face.x1 && face.y0 <= face.y1) {
      faceBands[f] = {std::uint16_t(face.y0 / bandRows), std::uint16_t(face.y1 / bandRows)};
      for (std::int32_t band = faceBands[f][0]; band <= faceBands[f][1]; ++band) ++bandStart[std::size_t(band) + 1];
    }
  for (std::size_t band = 0; band < bands; ++band) bandStart[band + 1] += bandStart[band];
  std::vector<std::uint32_t> bandFaces(bandStart.back()), next(bandStart.begin(), bandStart.end() - 1);
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (std::int32_t band = faceBands[f][0]; band <= faceBands[f][1]; ++band)
      bandFaces[next[std::size_t(band)]++] = std::uint32_t(f);

  // Per row, the faces' spans as differences (+1 at x0, -1 after x1: one step a span, not a pixel),
  // then one pass that sums them into counts and keeps the running number of overlapped pixels, so
  // that whether a span holds one is a difference of two of them.
  // The bands are shared out to the threads, each with its own buffers; a face's flag may be set
  // from any of its bands (relaxed atomics: only ever set to 1), the counts are summed per band.
  const std::size_t stride = std::size_t(n) + 1;
  struct Buffers {
    std::vector<std::int32_t> difference, overlappedBefore;
  };
  std::vector<Buffers> buffers(std::size_t(workerCount(int(bands), threads)));
  std::vector<std::atomic<std::uint8_t>> overlapped(faces.size());
  std::vector<std::array<std::size_t, 2>> bandPixels(bands, {0, 0});  // covered, overlapped
  parallelForWorkers(int(bands), threads, [&](int bandIndex, int worker) {
    const std::size_t band = std::size_t(bandIndex);
    std::vector<std::int32_t>& difference = buffers[std::size_t(worker)].difference;
    std::vector<std::int32_t>& overlappedBefore = buffers[std::size_t(worker)].overlappedBefore;
    difference.assign(std::size_t(bandRows) * stride, 0);
    overlappedBefore.resize(std::size_t(bandRows) * stride);
    const std::int64_t from = std::int64_t(band) * bandRows, to = std::min(n - 1, from + bandRows - 1);
    const std::uint32_t* first = bandFaces.data() + bandStart[band];
    const std::uint32_t* last = bandFaces.data() + bandStart[band + 1];
    SnappedFace spanned;
    for (const std::uint32_t* f = first; f != last; ++f)
      if (snap.snap(uv, *f, spanned))
        forEachRowSpan(spanned, from, to, [&](int y, int x0, int x1) {
          std::int32_t* row = &difference[std::size_t(y - from) * stride];
          ++row[x0], --row[x1 + 1];
        });
    std::size_t coveredHere = 0, overlappedHere = 0;
    for (std::int64_t y = from; y <= to; ++y) {
      const std::int32_t* row = &difference[std::size_t(y - from) * stride];
      std::int32_t* before = &overlappedBefore[std::size_t(y - from) * stride];
      std::int32_t count = 0, overlappedSoFar = 0;
      for (std::int64_t x = 0; x < n; ++x) {
        count += row[x];
        before[x] = overlappedSoFar;
        coveredHere += count >= 1;
        overlappedSoFar += count >= 2;
      }
      before[n] = overlappedSoFar;
      overlappedHere += std::size_t(overlappedSoFar);
    }
    bandPixels[band] = {coveredHere, overlappedHere};
    if (overlappedHere == 0) return;
    // The faces that cover a centre another face covers too: a second pass over the band's spans.
    for (const std::uint32_t* f = first; f != last; ++f)
      if (!overlapped[*f].load(std::memory_order_relaxed) && snap.snap(uv, *f, spanned))
        forEachRowSpan(spanned, from, to, [&](int y, int x0, int x1) {
          const std::int32_t* before = &overlappedBefore[std::size_t(y - from) * stride];
          if (before[x1 + 1] == before[x0]) return false;
          overlapped[*f].store(1, std::memory_order_relaxed);
          return true;  // found: its other rows cannot change that
        });
  });
  for (const std::array<std::size_t, 2>& pixels : bandPixels)
    overlap.coveredPixels += pixels[0], overlap.overlappedPixels += pixels[1];
  for (const std::atomic<std::uint8_t>& flag : overlapped) overlap.overlappedFaces += flag.load(std::memory_order_relaxed);
  return overlap;
}

}  // namespace uvtk::analysis
