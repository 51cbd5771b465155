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

// Where a weighted percentile lies in the items: sorting would put `item` there, with the items
// left of it no larger and carrying `weightBefore`, those right of it no smaller.
struct Selected {
  WeightedValue* item;
  double weightBefore;
};

// The item of the smallest value v in [first, last) such that `below` plus the weight of the
// items <= v reaches `target` (the lower inverse of the weighted distribution), by selection: each
// round places one item where sorting would put it and keeps the half that holds the answer, O(n)
// on average where sorting is O(n log n). Nothing when even the whole weight stays short of the
// target. `below` is the weight of the items before `first`, all no larger than those after it.
std::optional<Selected> weightedSelect(WeightedValue* first, WeightedValue* last, double below, double target) {
  const auto byValue = [](const WeightedValue& a, const WeightedValue& b) { return a.value < b.value; };
  while (first != last) {
    WeightedValue* middle = first + (last - first) / 2;
    std::nth_element(first, middle, last, byValue);
    double left = below;  // the weight before `middle`
    for (const WeightedValue* w = first; w != middle; ++w) left += w->weight;
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

Statistics weightedStatistics(std::vector<WeightedValue> items, BinSpacing spacing, int bins) {
  UVTK_CHECK(bins >= 1);
  Statistics s;
  s.histogram.spacing = spacing;
  s.histogram.weightFraction.assign(static_cast<std::size_t>(bins), 0.0);
  if (items.empty()) return s;

  const auto byValue = [](const WeightedValue& a, const WeightedValue& b) { return a.value < b.value; };
  const auto [lowest, highest] = std::minmax_element(items.begin(), items.end(), byValue);
  s.min = lowest->value;
  s.max = highest->value;
  UVTK_CHECK(spacing == BinSpacing::Linear || s.min > 0.0);
  double weightedSum = 0.0;
  for (const WeightedValue& item : items) s.totalWeight += item.weight, weightedSum += item.weight * item.value;
  if (s.totalWeight <= 0.0) return s;
  s.mean = weightedSum / s.totalWeight;

  Histogram& h = s.histogram;
  h.lo = s.min;
  h.hi = s.max;
  const double a = binScale(h.lo, spacing), width = binScale(h.hi, spacing) - a;
  for (const WeightedValue& item : items) {
    const double t = width > 0.0 ? (binScale(item.value, spacing) - a) / width : 0.0;
    const int bin = std::clamp(static_cast<int>(t * bins), 0, bins - 1);
    h.weightFraction[static_cast<std::size_t>(bin)] += item.weight / s.totalWeight;
  }

  // Weighted percentiles by selection (which reorders the items).
  const double fractions[4] = {0.10, 0.50, 0.90, 0.99};
  double* const percentiles[4] = {&s.p10, &s.p50, &s.p90, &s.p99};
  Selected from{items.data(), 0.0};  // each percentile lies at or right of the one before
  for (int k = 0; k < 4; ++k) {
    const std::optional<Selected> p =
        weightedSelect(from.item, items.data() + items.size(), from.weightBefore, fractions[k] * s.totalWeight);
    // Rounding may leave the whole weight short of the total: then the largest value.
    *percentiles[k] = p ? p->item->value : s.max;
    if (p) from = *p;
  }
  return s;
}

Statistics weightedStatistics(const std::vector<double>& values, const std::vector<double>& weights,
                              BinSpacing spacing, int bins) {
  UVTK_CHECK(values.size() == weights.size());
  std::vector<WeightedValue> items(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) items[i] = {values[i], weights[i]};
  return weightedStatistics(std::move(items), spacing, bins);
}

}  // namespace uvtk::analysis
