#include "param/atlas_packing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <string>

#include "core/error.h"

namespace uvtk::param {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Bottom-left skyline packing of boxes into a bin: each box goes where its top is lowest, then
// leftmost, upright or turned a quarter, whichever is lower.
class Skyline {
 public:
  Skyline(double width, double height) : width_(width), height_(height), segments_{{0.0, 0.0, width}} {}

  struct Spot {
    double x = 0.0, y = kInfinity;
    std::size_t index = 0;
  };
  // The lowest spot for a box of w x h; y is infinite where none is.
  Spot find(double w, double h) const {
    Spot best;
    for (std::size_t i = 0; i < segments_.size(); ++i) {
      const double x = segments_[i].x;
      if (x + w > width_ + kSlack) break;
      double y = 0.0;
      for (std::size_t j = i; j < segments_.size() && segments_[j].x < x + w - kSlack; ++j) y = std::max(y, segments_[j].y);
      if (y + h <= height_ + kSlack && y < best.y) best = Spot{x, y, i};
    }
    return best;
  }
  void take(const Spot& spot, double w, double h) {
    const double right = spot.x + w;
    std::size_t j = spot.index;
    while (j < segments_.size() && segments_[j].x + segments_[j].w <= right + kSlack) ++j;
    if (j < segments_.size() && segments_[j].x < right) {
      segments_[j].w -= right - segments_[j].x;
      segments_[j].x = right;
    }
    const std::size_t i = spot.index;
    segments_.erase(segments_.begin() + std::ptrdiff_t(i), segments_.begin() + std::ptrdiff_t(j));
    segments_.insert(segments_.begin() + std::ptrdiff_t(i), Segment{spot.x, spot.y + h, w});
    if (i + 1 < segments_.size() && segments_[i + 1].y == segments_[i].y) {
      segments_[i].w += segments_[i + 1].w;
      segments_.erase(segments_.begin() + std::ptrdiff_t(i) + 1);
    }
    if (i > 0 && segments_[i - 1].y == segments_[i].y) {
      segments_[i - 1].w += segments_[i].w;
      segments_.erase(segments_.begin() + std::ptrdiff_t(i));
    }
  }

 private:
  static constexpr double kSlack = 1e-9;
  struct Segment {
    double x, y, w;
  };
  double width_, height_;
  std::vector<Segment> segments_;
};

// Places a box of w x h upright or turned, whichever sits lower (then further left, then upright).
bool placeBox(Skyline& skyline, double w, double h, bool mayTurn, Placement& out) {
  const Skyline::Spot upright = skyline.find(w, h), turned = mayTurn ? skyline.find(h, w) : Skyline::Spot{};
  const bool turn = turned.y + w < upright.y + h || (turned.y + w == upright.y + h && turned.x < upright.x);
  const Skyline::Spot& spot = turn ? turned : upright;
  if (spot.y == kInfinity) return false;
  skyline.take(spot, turn ? h : w, turn ? w : h);
  out.at = Vec2(spot.x, spot.y);
  out.turned = turn;
  return true;
}

// How the packer goes about it: the order it takes the boxes in, and whether it may turn them.
struct PackingStrategy {
  std::vector<int> order;
  bool mayTurn = true;
};

// Packs boxes of size * density + margin (texels) in `order` into tiles of W x H less the margin
// along the left and bottom border. With one tile only, false when they do not all fit.
bool pack(const std::vector<Vec2>& sizes, const PackingStrategy& strategy, double density, double margin,
          const std::array<int, 2>& texture, bool manyTiles, std::vector<Placement>& out) {
  out.assign(sizes.size(), Placement{Vec2::Zero(), 0, false});
  const double binW = double(texture[0]) - margin, binH = double(texture[1]) - margin;
  Skyline skyline(binW, binH);
  int tile = 0;
  for (const int c : strategy.order) {
    const double w = sizes[std::size_t(c)].x() * density + margin, h = sizes[std::size_t(c)].y() * density + margin;
    Placement& p = out[std::size_t(c)];
    if (!placeBox(skyline, w, h, strategy.mayTurn, p)) {
      if (!manyTiles) return false;
      skyline = Skyline(binW, binH);
      ++tile;
      if (!placeBox(skyline, w, h, strategy.mayTurn, p)) return false;
    }
    p.at += Vec2(margin, margin);
    p.tile = tile;
  }
  return true;
}

std::string numberText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

Vec2 chartRoom(const AtlasOptions& options) {
  const double margin = options.marginTexels;
  return Vec2(double(options.textureSize[0]) - margin - margin, double(options.textureSize[1]) - margin - margin);
}

double areaDensity(const std::vector<Vec2>& sizes, const AtlasOptions& options) {
  const double binW = double(options.textureSize[0]) - options.marginTexels;
  const double binH = double(options.textureSize[1]) - options.marginTexels;
  double area = 0.0;
  for (const Vec2& s : sizes) area += s.x() * s.y();
  return area > 0.0 ? std::sqrt(binW * binH / area) : kInfinity;
}

Packing packCharts(const std::vector<Vec2>& size, const std::vector<AtlasChart>& charts, const AtlasOptions& options,
                   double scale) {
  const std::size_t chartCount = size.size();
  std::vector<PackingStrategy> strategies;
  const int keys = chartCount <= 2000 ? 3 : 1;
  for (int key = 0; key < keys; ++key) {
    const auto measure = [&](int c) {
      const Vec2& s = size[std::size_t(c)];
      return key == 0 ? s.y() : key == 1 ? s.x() * s.y() : std::max(s.x(), s.y());
    };
    std::vector<int> order(chartCount);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return measure(a) > measure(b); });
    strategies.push_back({order, true});
    if (chartCount <= 2000) strategies.push_back({order, false});
  }
  const double margin = options.marginTexels;
  const double binW = double(options.textureSize[0]) - margin, binH = double(options.textureSize[1]) - margin;
  Packing result;
  if (options.texelsPerUnit) {
    result.density = *options.texelsPerUnit * scale;
    for (std::size_t c = 0; c < chartCount; ++c)
      if (size[c].x() * result.density + margin > binW || size[c].y() * result.density + margin > binH)
        throw UsageError("--texels-per-unit " + numberText(*options.texelsPerUnit) + ": a chart of " +
                         std::to_string(charts[c].faces) + " faces needs " +
                         std::to_string(int(std::ceil(size[c].x() * result.density))) + " x " +
                         std::to_string(int(std::ceil(size[c].y() * result.density))) +
                         " texels, more than one texture less its margins holds");
    result.fits = pack(size, strategies.front(), result.density, margin, options.textureSize, true, result.placements);
    return result;
  }
  result.fits = pack(size, strategies.front(), 0.0, margin, options.textureSize, false, result.placements);
  if (!result.fits) return result;
  double high = kInfinity;
  const Vec2 room = chartRoom(options);
  for (std::size_t c = 0; c < chartCount; ++c) {
    if (size[c].x() > 0.0) high = std::min(high, room.x() / size[c].x());
    if (size[c].y() > 0.0) high = std::min(high, room.y() / size[c].y());
  }
  high = std::min(high, areaDensity(size, options));
  if (!std::isfinite(high)) high = 1.0;  // nothing has extent: any density will do
  // Packing is not monotone in the density (a box that no longer fits beside another may fit
  // below it), so each strategy's search steps down from the area bound by 3 % until the charts
  // fit (below 0.4 of the bound by 30 %), then bisects between that and the step above; it
  // stops where it could no longer beat the best so far.
  std::size_t best = 0;
  double density = 0.0;
  std::vector<Placement> trial;
  for (std::size_t k = 0; k < strategies.size(); ++k) {
    const PackingStrategy& strategy = strategies[k];
    double fits = 0.0, failed = high;
    for (double d = high, step = 0.97; d > 1e-12 * high && d > density; d *= step, step = d < 0.4 * high ? 0.7 : step) {
      if (pack(size, strategy, d, margin, options.textureSize, false, trial)) {
        fits = d;
        break;
      }
      failed = d;
    }
    if (fits == 0.0) continue;
    for (int step = 0; step < 12 && fits < failed; ++step) {
      const double mid = 0.5 * (fits + failed);
      (pack(size, strategy, mid, margin, options.textureSize, false, trial) ? fits : failed) = mid;
    }
    if (fits > density) density = fits, best = k;
  }
  pack(size, strategies[best], density, margin, options.textureSize, false, result.placements);
  result.density = density;
  return result;
}

void throwChartsDoNotFit(std::size_t charts, const AtlasOptions& options) {
  throw UsageError(std::to_string(charts) + " charts with " + numberText(options.marginTexels) +
                   " texels of margin each do not fit a " + std::to_string(options.textureSize[0]) + " x " +
                   std::to_string(options.textureSize[1]) +
                   " texture even at no size: give a larger --texture-size or a smaller --margin");
}

}  // namespace uvtk::param
