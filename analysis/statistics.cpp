#include "analysis/statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.h"

namespace uvtk::analysis {

namespace {

// The scale on which bins have equal widths.
double binScale(double value, BinSpacing spacing) { return spacing == BinSpacing::Log2 ? std::log2(value) : value; }

}  // namespace

double Histogram::edge(int i) const {
  const int bins = static_cast<int>(weightFraction.size());
  if (i >= bins) return hi;
  const double a = binScale(lo, spacing), b = binScale(hi, spacing);
  const double x = a + (b - a) * static_cast<double>(i) / static_cast<double>(bins);
  return spacing == BinSpacing::Log2 ? std::exp2(x) : x;
}

Statistics weightedStatistics(const std::vector<double>& values, const std::vector<double>& weights,
                              BinSpacing spacing, int bins) {
  UVTK_CHECK(values.size() == weights.size() && bins >= 1);
  Statistics s;
  s.histogram.spacing = spacing;
  s.histogram.weightFraction.assign(static_cast<std::size_t>(bins), 0.0);
  if (values.empty()) return s;

  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  s.min = values[order.front()];
  s.max = values[order.back()];
  UVTK_CHECK(spacing == BinSpacing::Linear || s.min > 0.0);
  double weightedSum = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) s.totalWeight += weights[i], weightedSum += weights[i] * values[i];
  if (s.totalWeight <= 0.0) return s;
  s.mean = weightedSum / s.totalWeight;

  // Weighted percentile: the first value, in ascending order, at which the running weight
  // reaches fraction * total.
  const double fractions[3] = {0.50, 0.90, 0.99};
  double* const percentiles[3] = {&s.p50, &s.p90, &s.p99};
  double running = 0.0;
  int next = 0;
  for (std::size_t i = 0; i < order.size() && next < 3; ++i) {
    running += weights[order[i]];
    while (next < 3 && running >= fractions[next] * s.totalWeight) *percentiles[next++] = values[order[i]];
  }
  while (next < 3) *percentiles[next++] = s.max;  // rounding left the running sum short of the total

  Histogram& h = s.histogram;
  h.lo = s.min;
  h.hi = s.max;
  const double a = binScale(h.lo, spacing), width = binScale(h.hi, spacing) - a;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double t = width > 0.0 ? (binScale(values[i], spacing) - a) / width : 0.0;
    const int bin = std::clamp(static_cast<int>(t * bins), 0, bins - 1);
    h.weightFraction[static_cast<std::size_t>(bin)] += weights[i] / s.totalWeight;
  }
  return s;
}

}  // namespace uvtk::analysis
