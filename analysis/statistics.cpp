#include "analysis/statistics.h"

#include <algorithm>
#include <cmath>
#include <optional>

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

namespace {

struct Weighted {
  double value, weight;
};

// Where a weighted percentile lies in the items: sorting would put `item` there, with the items
// left of it no larger and carrying `weightBefore`, those right of it no smaller.
struct Selected {
  Weighted* item;
  double weightBefore;
};

// The item of the smallest value v in [first, last) such that `below` plus the weight of the
// items <= v reaches `target` (the lower inverse of the weighted distribution), by selection: each
// round places one item where sorting would put it and keeps the half that holds the answer, O(n)
// on average where sorting is O(n log n). Nothing when even the whole weight stays short of the
// target. `below` is the weight of the items before `first`, all no larger than those after it.
std::optional<Selected> weightedSelect(Weighted* first, Weighted* last, double below, double target) {
  const auto byValue = [](const Weighted& a, const Weighted& b) { return a.value < b.value; };
  while (first != last) {
    Weighted* middle = first + (last - first) / 2;
    std::nth_element(first, middle, last, byValue);
    double left = below;  // the weight before `middle`
    for (const Weighted* w = first; w != middle; ++w) left += w->weight;
    if (left >= target) {
      last = middle;  // reached before the middle: the answer lies left of it
    } else if (left + middle->weight >= target) {
      return Selected{middle, left};
    } else {
      below = left + middle->weight;
      first = middle + 1;
    }
  }
  return std::nullopt;
}

}  // namespace

Statistics weightedStatistics(const std::vector<double>& values, const std::vector<double>& weights,
                              BinSpacing spacing, int bins) {
  UVTK_CHECK(values.size() == weights.size() && bins >= 1);
  Statistics s;
  s.histogram.spacing = spacing;
  s.histogram.weightFraction.assign(static_cast<std::size_t>(bins), 0.0);
  if (values.empty()) return s;

  const auto [lowest, highest] = std::minmax_element(values.begin(), values.end());
  s.min = *lowest;
  s.max = *highest;
  UVTK_CHECK(spacing == BinSpacing::Linear || s.min > 0.0);
  double weightedSum = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) s.totalWeight += weights[i], weightedSum += weights[i] * values[i];
  if (s.totalWeight <= 0.0) return s;
  s.mean = weightedSum / s.totalWeight;

  // Weighted percentiles by selection.
  std::vector<Weighted> items(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) items[i] = {values[i], weights[i]};
  const double fractions[3] = {0.50, 0.90, 0.99};
  double* const percentiles[3] = {&s.p50, &s.p90, &s.p99};
  Selected from{items.data(), 0.0};  // each percentile lies at or right of the one before
  for (int k = 0; k < 3; ++k) {
    const std::optional<Selected> p =
        weightedSelect(from.item, items.data() + items.size(), from.weightBefore, fractions[k] * s.totalWeight);
    // Rounding may leave the whole weight short of the total: then the largest value.
    *percentiles[k] = p ? p->item->value : s.max;
    if (p) from = *p;
  }

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
