// Area-weighted statistics of a per-face measure: mean, percentiles, extremes and a histogram,
// each face counting with its 3D area.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace uvtk::analysis {

enum class BinSpacing {
  Linear,  // equal widths over [lo, hi]
  Log2,    // equal widths of log2(value): for ratios such as stretch and angle distortion
};

struct Histogram {
  double lo = 0.0, hi = 0.0;  // the smallest and the largest value
  BinSpacing spacing = BinSpacing::Linear;
  std::vector<double> weightFraction;  // per bin, its fraction of the total weight; sums to 1

  // Bin i holds [edge(i), edge(i + 1)), the last bin also hi; edge(bins) = hi.
  double edge(int i) const;
};

struct Statistics {
  double totalWeight = 0.0;
  double mean = 0.0;  // weighted mean
  // Weighted percentiles: the smallest value v such that the values <= v carry at least that
  // fraction of the total weight (the lower inverse of the weighted distribution; no interpolation).
  double p10 = 0.0, p50 = 0.0, p90 = 0.0, p99 = 0.0;
  double min = 0.0, max = 0.0;
  Histogram histogram;  // `bins` bins over [min, max]; all the weight in bin 0 when min = max
};

// Statistics of values[i] with weights[i] >= 0 over the items i < size with included[i] != 0 (null:
// every item), in any order (read, not reordered): finite values, entries of zero weight counting
// for min and max; the items left out count as if the others had been gathered in their order into
// arrays of their own (a caller whose values and weights lie in per-face arrays skips the faces
// that do not enter without copying the others): their weights are not read, their values may be
// any doubles, NaN too (a log2 histogram takes their logarithms along, a block at a time, unused). No items give zeros and empty bins.
// Precondition: bins >= 1. Log2 spacing where every value is > 0, else linear (the histogram's
// spacing says which). The mean, the total and the histogram are summed in the items' order; the
// percentiles are exact (their running weights summed without rounding).
Statistics weightedStatistics(const double* values, const double* weights, const std::uint8_t* included,
                              std::size_t size, BinSpacing spacing, int bins = 32);

// The same for every values[i] with weights[i]. Precondition: equal sizes.
Statistics weightedStatistics(const std::vector<double>& values, const std::vector<double>& weights,
                              BinSpacing spacing, int bins = 32);

}  // namespace uvtk::analysis
