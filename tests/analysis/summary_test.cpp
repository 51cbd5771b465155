// The mesh-wide report: Sander's normalised stretch, weighted statistics, seams, poles, bounds
// and overlap, on hand-made layouts and on the projectors' output.
#include "analysis/summary.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "analysis/layout.h"
#include "analysis/same_statistics.h"
#include "meshes/generators.h"
#include "param/projector.h"

namespace uvtk::analysis {
namespace {
namespace UVTK_TEST_FILE {

// Separate triangles in the plane z = 0 whose UVs are their (x, y).
Layout flatTriangles(const std::vector<Vec2>& corners) {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  for (const Vec2& c : corners) positions.push_back({c.x(), c.y(), 0.0});
  for (int f = 0; 3 * f < int(corners.size()); ++f) triangles.push_back({3 * f, 3 * f + 1, 3 * f + 2});
  return makeLayout(positions, triangles, corners);
}

Summary summarizeLayout(const Layout& l, int overlapResolution = 1024) {
  return summarize(l.mesh, l.uv, measureFaces(l.mesh, l.uv), overlapResolution);
}

param::Projection projectSphere(int longitudes, int latitudes, param::SeamMode seam, double frameTurn = 0.0) {
  param::ProjectorOptions o;
  o.surface = param::SurfaceKind::Sphere;
  o.seam = seam;
  o.placement.fit = param::Fit::None;
  if (frameTurn != 0.0) {  // the seam half-plane turned about z, off the generator's vertices
    param::ExplicitFrame frame;
    frame.refDir = Vec3(std::cos(frameTurn), std::sin(frameTurn), 0.0);
    o.placement.frame = frame;
  }
  return param::project(meshes::latLongSphere(longitudes, latitudes), o);
}

void expectFinite(const Statistics& s) {
  for (double x : {s.totalWeight, s.mean, s.p50, s.p90, s.p99, s.min, s.max, s.histogram.lo, s.histogram.hi})
    EXPECT_TRUE(std::isfinite(x));
  for (double x : s.histogram.weightFraction) EXPECT_TRUE(std::isfinite(x));
}

// ---- Sander et al.'s mesh-wide stretch ----

// UV = 2 x: every face has L2 = Linf = 1/2, and the normalisation sqrt(sum Auv / sum A3) = 2
// brings the mesh values to 1, as for the isometry.
TEST(Summarize, UniformScaleNormalisesToOne) {
  Layout l = flatTriangles({{0, 0}, {1, 0}, {0, 1}, {1, 0}, {1, 1}, {0, 1}});
  for (Vec2& t : l.uv.uv) t *= 2.0;
  const Summary s = summarizeLayout(l);
  EXPECT_DOUBLE_EQ(s.l2Stretch, 1.0);
  EXPECT_DOUBLE_EQ(s.linfStretch, 1.0);
  EXPECT_DOUBLE_EQ(s.l2Stretches.max, 1.0);
  EXPECT_DOUBLE_EQ(s.areaDistortion.max, 0.0);
}

// Two unit right triangles, one mapped as it is and one scaled by 2: A3 = 1/2 each, Auv = 1/2
// and 2, per-face L2 = 1 and 1/2. L2(M) = sqrt((1/2 + 1/8) / 1) sqrt(5/2) = 5/4;
// Linf(M) = max(1, 1/2) sqrt(5/2). Normalised area ratios r = 0.4 and 1.6.
TEST(Summarize, MeshStretchOfTwoDifferentlyScaledFaces) {
  Layout l = flatTriangles({{0, 0}, {1, 0}, {0, 1}, {2, 0}, {3, 0}, {2, 1}});
  for (int k = 3; k < 6; ++k) l.uv.uv[k] *= 2.0;
  const Summary s = summarizeLayout(l);
  EXPECT_NEAR(s.l2Stretch, 1.25, 1e-15);
  EXPECT_NEAR(s.linfStretch, std::sqrt(2.5), 1e-15);
  EXPECT_NEAR(s.areaDistortion.min, std::log2(0.4), 1e-15);
  EXPECT_NEAR(s.areaDistortion.max, std::log2(1.6), 1e-15);
  EXPECT_NEAR(s.areaDistortion.mean, 0.5 * (std::log2(0.4) + std::log2(1.6)), 1e-15);
  EXPECT_EQ(s.statusCounts[FaceStatus::Ok], 2u);
}

// On a mapped sphere the normalised stretch is at least 1 (Cauchy-Schwarz), and every value of
// the report is finite.
TEST(Summarize, SphereReportIsConsistent) {
  const param::Projection p = projectSphere(32, 16, param::SeamMode::Shift);
  const FaceMeasures faces = measureFaces(p.mesh, p.uv);
  const Summary s = summarize(p.mesh, p.uv, faces);
  EXPECT_EQ(s.statusCounts[FaceStatus::Ok], 2u * 32u * 14u);  // two per quad, 14 quad bands
  EXPECT_EQ(s.statusCounts[FaceStatus::PoleFace], 64u);
  EXPECT_EQ(s.poleFaces, 64u);
  EXPECT_GT(s.l2Stretch, 1.0);
  EXPECT_GE(s.linfStretch, s.l2Stretch);
  for (const Statistics* st : {&s.angleDistortion, &s.areaDistortion, &s.l2Stretches, &s.linfStretches}) {
    expectFinite(*st);
    EXPECT_NEAR(st->totalWeight, okAreaTotals(faces).surface, 1e-12);
    EXPECT_LE(st->min, st->p50);
    EXPECT_LE(st->p50, st->p90);
    EXPECT_LE(st->p90, st->p99);
    EXPECT_LE(st->p99, st->max);
  }
  EXPECT_GE(s.angleDistortion.min, 1.0);
  EXPECT_NEAR(s.linfStretches.max, s.linfStretch, 1e-15);
  EXPECT_EQ(s.uvBounds.min(), Vec2(0, 0));  // the seam's vertices shifted to u = 1; the poles at v = 0, 1
  EXPECT_EQ(s.uvBounds.max(), Vec2(1, 1));
}

// Nothing but degenerate and invalid faces: counts, zeros, no NaN.
TEST(Summarize, NoOkFaceGivesZerosNotNaN) {
  Layout l = makeLayout({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 1, 3}, {0, 1, 3}},
                        {{0, 0}, {1, 0}, {0, 1}, {0, 0}, {1, 1}, {2, 2}, {0, 0}, {1, 0}, {0, 1}});
  l.uv.cornerInvalid[8] = 1;
  const Summary s = summarizeLayout(l);
  EXPECT_EQ(s.statusCounts[FaceStatus::ZeroArea3d], 1u);
  EXPECT_EQ(s.statusCounts[FaceStatus::ZeroAreaUv], 1u);
  EXPECT_EQ(s.statusCounts[FaceStatus::Invalid], 1u);
  EXPECT_EQ(s.statusCounts[FaceStatus::Ok], 0u);
  EXPECT_EQ(s.l2Stretch, 0.0);
  EXPECT_EQ(s.linfStretch, 0.0);
  for (const Statistics* st : {&s.angleDistortion, &s.areaDistortion, &s.l2Stretches, &s.linfStretches}) {
    expectFinite(*st);
    EXPECT_EQ(st->totalWeight, 0.0);
  }
  EXPECT_EQ(s.overlap.coveredPixels, 0u);
  EXPECT_EQ(s.overlap.fraction(), 0.0);
  // The bounds leave out the invalid corner only.
  EXPECT_EQ(s.uvBounds.min(), Vec2(0, 0));
  EXPECT_EQ(s.uvBounds.max(), Vec2(2, 2));
}

TEST(Summarize, UvBoundsSkipInvalidCorners) {
  Layout l = flatTriangles({{0.2, 0.3}, {0.8, 0.3}, {0.2, 0.9}});
  l.uv.uv[0] = Vec2::Zero();  // what a projector writes for a corner without a UV
  l.uv.cornerInvalid[0] = 1;
  const Summary s = summarizeLayout(l);
  EXPECT_EQ(s.uvBounds.min(), Vec2(0.2, 0.3));
  EXPECT_EQ(s.uvBounds.max(), Vec2(0.8, 0.9));
}

// ---- Weighted statistics ----

// Values 1..5 with weights 1, 4, 2, 2.5, 0.5 (total 10): running weights 1, 5, 7, 9.5, 10.
// p50 is the first value whose running weight reaches 5: 2 (reached exactly); p90: 4; p99: 5.
TEST(WeightedStatistics, PercentilesMeanAndHistogramOfAHandMadeSet) {
  const Statistics s = weightedStatistics({4, 2, 5, 1, 3}, {2.5, 4, 0.5, 1, 2}, BinSpacing::Linear, 4);
  EXPECT_DOUBLE_EQ(s.totalWeight, 10.0);
  EXPECT_DOUBLE_EQ(s.mean, 2.75);  // (1 + 8 + 6 + 10 + 2.5) / 10
  EXPECT_EQ(s.p50, 2.0);
  EXPECT_EQ(s.p90, 4.0);
  EXPECT_EQ(s.p99, 5.0);
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 5.0);
  // Bins [1, 2), [2, 3), [3, 4), [4, 5]: the maximum falls into the last.
  const std::vector<double> expected = {0.1, 0.4, 0.2, 0.3};
  ASSERT_EQ(s.histogram.weightFraction.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(s.histogram.weightFraction[i], expected[i], 1e-15);
  for (int i = 0; i <= 4; ++i) EXPECT_DOUBLE_EQ(s.histogram.edge(i), 1.0 + i);
}

// Selection (weightedStatistics) against the definition recounted by sorting: many ties, zero
// weights, integer weights so that every running sum is exact and the answers are unambiguous.
TEST(WeightedStatistics, PercentilesEqualASortedRecountOnLargeSetsWithTies) {
  std::mt19937 random(26);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 1 + int(random() % 5000);
    std::vector<double> values(static_cast<std::size_t>(n)), weights(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      values[std::size_t(i)] = double(random() % (trial % 2 == 0 ? 37 : 100000)) / 8.0;  // ties on even trials
      weights[std::size_t(i)] = double(random() % 4);                                       // a quarter weigh nothing
    }
    std::vector<std::size_t> order(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
    double total = 0.0;
    for (double w : weights) total += w;
    const Statistics s = weightedStatistics(values, weights, BinSpacing::Linear);
    if (total == 0.0) continue;
    const std::pair<double, double> expected[] = {{0.5, s.p50}, {0.9, s.p90}, {0.99, s.p99}};
    for (const auto& [fraction, found] : expected) {
      double running = 0.0, answer = values[order.back()];
      for (std::size_t i : order)
        if ((running += weights[i]) >= fraction * total) {
          answer = values[i];
          break;
        }
      EXPECT_EQ(found, answer) << "trial " << trial << " fraction " << fraction;
    }
  }
}

TEST(WeightedStatistics, EqualWeightsGiveTheLowerMedian) {
  const Statistics s = weightedStatistics({1, 2, 3, 4}, {1, 1, 1, 1}, BinSpacing::Linear);
  EXPECT_EQ(s.p50, 2.0);
  EXPECT_EQ(s.p90, 4.0);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_EQ(s.histogram.weightFraction.size(), 32u);
}

// Log2 spacing over [1, 8] with 3 bins: edges 1, 2, 4, 8.
TEST(WeightedStatistics, Log2SpacedBins) {
  const Statistics s = weightedStatistics({1, 3, 5, 8}, {1, 1, 1, 1}, BinSpacing::Log2, 3);
  EXPECT_DOUBLE_EQ(s.histogram.edge(1), 2.0);
  EXPECT_DOUBLE_EQ(s.histogram.edge(2), 4.0);
  EXPECT_EQ(s.histogram.edge(3), 8.0);
  const std::vector<double> expected = {0.25, 0.25, 0.5};
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_DOUBLE_EQ(s.histogram.weightFraction[i], expected[i]);
}

TEST(WeightedStatistics, OneValueAndNoValue) {
  const Statistics one = weightedStatistics({3, 3}, {1, 2}, BinSpacing::Log2, 4);
  EXPECT_EQ(one.p50, 3.0);
  EXPECT_EQ(one.histogram.weightFraction, (std::vector<double>{1, 0, 0, 0}));
  const Statistics none = weightedStatistics({}, {}, BinSpacing::Linear, 4);
  EXPECT_EQ(none.mean, 0.0);
  EXPECT_EQ(none.histogram.weightFraction, (std::vector<double>(4, 0.0)));
  // No value asked for log2 bins (a mapping without an ok face): linear bins over [0, 0], whose edges
  // are 0, where log2 spacing made them log2(0) and NaN (null in the JSON of `report`).
  const Statistics noRatio = weightedStatistics({}, {}, BinSpacing::Log2, 4);
  EXPECT_EQ(noRatio.histogram.spacing, BinSpacing::Linear);
  for (int i = 0; i <= 4; ++i) EXPECT_EQ(noRatio.histogram.edge(i), 0.0) << i;
}

// An exact running weight for the recount: Shewchuk's expansion (non-overlapping doubles, smallest
// first; "Adaptive Precision Floating-Point Arithmetic", 1997), grown by one double at a time.
struct Expansion {
  std::vector<double> parts;
  void add(double b) {
    std::vector<double> grown;
    for (double a : parts) {  // two-sum: a + b = sum + error exactly
      const double sum = a + b, virtualB = sum - a, error = (a - (sum - virtualB)) + (b - virtualB);
      if (error != 0.0) grown.push_back(error);
      b = sum;
    }
    if (b != 0.0) grown.push_back(b);
    parts = std::move(grown);
  }
  // Whether the sum is at least `target`: the sign of sum - target is that of its largest part.
  bool atLeast(double target) const {
    Expansion difference = *this;
    difference.add(-target);
    return difference.parts.empty() || difference.parts.back() > 0.0;
  }
};

// The definition recounted: sorted by value, the first value whose exact running weight reaches
// the fraction of the total summed in the items' order; the largest value if none does.
double recountedPercentile(const std::vector<double>& values, const std::vector<double>& weights, double fraction) {
  std::vector<std::size_t> order(values.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  double total = 0.0;
  for (double w : weights) total += w;
  Expansion running;
  for (std::size_t i : order) {
    running.add(weights[i]);
    if (running.atLeast(fraction * total)) return values[i];
  }
  return *std::max_element(values.begin(), values.end());
}

void expectPercentilesRecounted(const std::vector<double>& values, const std::vector<double>& weights,
                                const std::string& what) {
  const Statistics s = weightedStatistics(values, weights, BinSpacing::Linear);
  const std::pair<double, double> found[] = {{0.10, s.p10}, {0.50, s.p50}, {0.90, s.p90}, {0.99, s.p99}};
  for (const auto& [fraction, value] : found)
    EXPECT_EQ(value, recountedPercentile(values, weights, fraction)) << what << ", fraction " << fraction;
}

// Random sets against the exact recount: ties, zero weights, weights over 2^-40 .. 2^40 (whose
// rounded running sums go astray), negative values, extremes of the double range, and sets larger
// than one sorted bucket (several passes of the radix selection).
TEST(WeightedStatistics, PercentilesEqualAnExactRecountOnRandomAndAdversarialSets) {
  std::mt19937_64 random(2611);
  const auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
  for (int trial = 0; trial < 60; ++trial) {
    // Two sets larger than one sorted bucket holds (2^17 items): refined in a second pass and more.
    const std::size_t n = trial == 5 || trial == 11 ? 300000 + random() % 100000
                          : trial % 6 == 5          ? 20000 + random() % 30000
                                                    : 1 + random() % 3000;
    std::vector<double> values(n), weights(n);
    for (std::size_t i = 0; i < n; ++i) {
      switch (trial % 6) {
        case 0: values[i] = double(random() % 7); break;                                   // heavy ties
        case 1: values[i] = uniform(-1e3, 1e3); break;                                     // both signs
        case 2: values[i] = std::ldexp(uniform(1.0, 2.0), int(random() % 2000) - 1000); break;  // every scale
        case 3: values[i] = 1.0 + double(random() % 64) * 0x1p-52; break;                  // ties a few ulps apart
        case 4: values[i] = (random() % 3 == 0 ? -1.0 : 1.0) * std::ldexp(1.0, int(random() % 2090) - 1074); break;
        default:  // half the items in the last bits of one bucket: refined pass after pass
          values[i] = random() % 2 ? 1.0 + double(random() % 16) * 0x1p-52 : uniform(1.0, 1e6);
      }
      weights[i] = random() % 5 == 0 ? 0.0 : std::ldexp(uniform(0.5, 1.0), int(random() % 81) - 40);
    }
    expectPercentilesRecounted(values, weights, "trial " + std::to_string(trial));
  }
}

// Items left out by a mask count as if they had never been there: every field equals that of the
// included items gathered into arrays of their own (the summary's statistics read the faces' own
// arrays, skipping the faces that are not ok), whatever the left-out items hold (NaN included),
// through sets small enough to sort and large enough to need several passes.
TEST(WeightedStatistics, MaskedItemsGiveTheStatisticsOfTheIncludedOnesGathered) {
  std::mt19937_64 random(5179);
  const auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
  for (const std::size_t n : {std::size_t(1), std::size_t(7), std::size_t(5000), std::size_t(70000), std::size_t(400000)})
    for (const int keep : {0, 1, 3}) {  // of every 4 items: none, one, three
      std::vector<double> values(n), weights(n), keptValues, keptWeights;
      std::vector<std::uint8_t> included(n);
      for (std::size_t i = 0; i < n; ++i) {
        included[i] = int(random() % 4) < keep;
        values[i] = included[i] ? (random() % 3 == 0 ? 1.0 + double(random() % 8) * 0x1p-52 : uniform(0.5, 1e4))
                                : std::numeric_limits<double>::quiet_NaN();
        weights[i] = included[i] ? std::ldexp(uniform(0.5, 1.0), int(random() % 41) - 20) : -1.0;
        if (included[i]) keptValues.push_back(values[i]), keptWeights.push_back(weights[i]);
      }
      for (const BinSpacing spacing : {BinSpacing::Linear, BinSpacing::Log2}) {
        SCOPED_TRACE(std::to_string(n) + " items, " + std::to_string(keptValues.size()) + " kept");
        const Statistics masked = weightedStatistics(values.data(), weights.data(), included.data(), n, spacing);
        const Statistics gathered = weightedStatistics(keptValues, keptWeights, spacing);
        expectSameStatistics(masked, gathered);
        if (!keptValues.empty()) {
          EXPECT_EQ(masked.p50, recountedPercentile(keptValues, keptWeights, 0.50));
        }
      }
    }
}

// Most items in one bucket of the first digit, which then splits only the exponents (an angle
// distortion from 1 - 2^-52 to 100): that bucket is refined by another pass rather than gathered.
TEST(WeightedStatistics, PercentilesEqualAnExactRecountWhereOneExponentHoldsMostItems) {
  std::mt19937_64 random(4507);
  const auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
  for (const std::size_t n : {300, 3000, 9800, 40000}) {
    std::vector<double> values(n), weights(n);
    for (std::size_t i = 0; i < n; ++i) {
      const int kind = int(random() % 20);
      values[i] = kind == 0 ? 1.0 - 0x1p-52 : kind == 1 ? std::ldexp(uniform(1.0, 2.0), int(random() % 7)) : uniform(1.0, 2.0);
      weights[i] = std::ldexp(uniform(0.5, 1.0), int(random() % 21) - 10);
    }
    expectPercentilesRecounted(values, weights, std::to_string(n) + " items");
  }
}

// Weights whose rounded running sum reaches the target one value early: 0.5 - 2^-54 then 3 2^-56
// round to 0.5, exactly half the total, while their exact sum 0.5 - 2^-56 stays short of it.
TEST(WeightedStatistics, APercentileIsTheExactLowerInverseWhereRoundingWouldTieTheTarget) {
  const std::vector<double> values = {1.0, 2.0, 3.0, 4.0};
  const std::vector<double> weights = {0.5 - 0x1p-54, 3 * 0x1p-56, 0x1p-56, 0.5 - 0x1p-55};
  double rounded = weights[0] + weights[1], total = 0.0;
  for (double w : weights) total += w;
  ASSERT_EQ(total, 1.0);
  ASSERT_EQ(rounded, 0.5);  // a rounded running sum would answer 2
  EXPECT_EQ(weightedStatistics(values, weights, BinSpacing::Linear).p50, 3.0);
  expectPercentilesRecounted(values, weights, "tie");
}

// Many equal values (more than one sorted bucket holds), one value alone, -0 beside +0, and a
// weight at the bottom of the subnormals beside one near the top of the range.
TEST(WeightedStatistics, PercentilesOfEqualValuesSignedZerosAndExtremeWeights) {
  const std::vector<double> same(200000, 2.5), ones(200000, 1.0);
  const Statistics s = weightedStatistics(same, ones, BinSpacing::Log2);
  EXPECT_EQ(s.p10, 2.5);
  EXPECT_EQ(s.p99, 2.5);
  std::vector<double> two(same.size(), 1.0), twoWeights(2 * same.size(), 1.0);
  two.resize(2 * same.size(), 1.0 + 0x1p-52);  // two values a bit apart, each too many to sort
  const Statistics t = weightedStatistics(two, twoWeights, BinSpacing::Linear);
  EXPECT_EQ(t.p50, 1.0);  // reached exactly at the first value
  EXPECT_EQ(t.p90, 1.0 + 0x1p-52);
  EXPECT_EQ(weightedStatistics({7.0}, {0.25}, BinSpacing::Linear).p50, 7.0);
  const Statistics zeros = weightedStatistics({-0.0, 0.0, 1.0}, {1.0, 1.0, 2.0}, BinSpacing::Linear);
  EXPECT_EQ(zeros.p50, 0.0);
  EXPECT_EQ(zeros.p90, 1.0);
  expectPercentilesRecounted({1.0, 2.0, 3.0}, {std::numeric_limits<double>::denorm_min(), 1e300, 1e300}, "extreme weights");
  expectPercentilesRecounted({-1e308, 5e-324, 1e308}, {1.0, 2.0, 1.0}, "extreme values");
  // Their histogram: the span overflows a double, yet each value falls in its bin (0, the middle,
  // the last) and every edge is finite: -1e308, 0 in the middle, 1e308.
  const Histogram h = weightedStatistics({-1e308, 5e-324, 1e308}, {1.0, 2.0, 1.0}, BinSpacing::Linear).histogram;
  ASSERT_EQ(h.weightFraction.size(), 32u);
  EXPECT_EQ(h.weightFraction[0], 0.25);
  EXPECT_EQ(h.weightFraction[16], 0.5);
  EXPECT_EQ(h.weightFraction[31], 0.25);
  EXPECT_EQ(h.edge(0), -1e308);
  EXPECT_EQ(h.edge(16), 0.0);
  EXPECT_EQ(h.edge(32), 1e308);
  for (int i = 0; i <= 32; ++i) EXPECT_TRUE(std::isfinite(h.edge(i))) << i;
}

// ---- Seams and poles ----

// latLongSphere(16, 8) has a vertex on the seam half-plane (y = 0, x > 0) in every ring, so the
// seam runs along the meridian's 8 edges, one per stack, the first and the last ending at a pole.
// Shift moves those vertices to u = 1 in the faces west of the seam: both endpoints of the inner
// 6 edges differ by exactly (1, 0); the 2 polar ones differ so at their ring end and their pole
// end is left out (a fanned pole has a different u in every face). 8 wrap edges, no cut; their
// length is 8 chords of pi/8, the same as the projector reports.
TEST(SeamEdges, ShiftedSphereHasItsMeridianAsWrapSeam) {
  const param::Projection p = projectSphere(16, 8, param::SeamMode::Shift);
  const Summary s = summarize(p.mesh, p.uv, measureFaces(p.mesh, p.uv));
  EXPECT_EQ(s.seams.wrapEdges, 8u);
  EXPECT_EQ(s.seams.cutEdges, 0u);
  EXPECT_NEAR(s.seams.wrapLength, 8 * 2 * std::sin(kPi / 16), 1e-14);
  EXPECT_EQ(s.poleVertices, (std::vector<int>{0, 113}));  // the north pole first, the south pole last
  EXPECT_EQ(s.poleVertices, p.summary.poleVertexList);
}

// Cut splits the straddling triangles along the seam. With the seam turned off the generator's
// vertices, it crosses each of the 7 rings' edges and the 6 quad bands' diagonals: 13 new
// vertices. Each new vertex carries u = 1 on the high side and u = 0 on the low side, which is
// an integer offset: the cut's edges are wrap seams, 2 per quad band and 1 per polar band (from
// the pole): 14 wrap edges, no cut. Without the turn the seam passes through vertices and the
// cut changes nothing.
TEST(SeamEdges, CutSphereHasWrapSeamsAlongTheCut) {
  const param::Projection p = projectSphere(16, 8, param::SeamMode::Cut, 0.1);
  const Summary s = summarize(p.mesh, p.uv, measureFaces(p.mesh, p.uv));
  EXPECT_EQ(p.summary.addedVertices, 13u);
  EXPECT_EQ(s.seams.wrapEdges, 14u);
  EXPECT_EQ(s.seams.cutEdges, 0u);
  EXPECT_EQ(s.uvBounds.max().x(), 1.0);  // the cut layout lies in [0, 1]

  const param::Projection aligned = projectSphere(16, 8, param::SeamMode::Cut);
  const Summary a = summarize(aligned.mesh, aligned.uv, measureFaces(aligned.mesh, aligned.uv));
  EXPECT_EQ(aligned.summary.addedVertices, 0u);
  EXPECT_EQ(a.seams.wrapEdges, 8u);
  EXPECT_EQ(a.seams.cutEdges, 0u);
}

// Two triangles sharing the edge (1, 2) of length sqrt 2; the second face's UVs are the first's
// layout moved by `offset` at the shared vertices.
Layout twoTriangles(const Vec2& offset) {
  return makeLayout({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {{0, 1, 2}, {2, 1, 3}},
                    {{0, 0}, {1, 0}, {0, 1}, Vec2(0, 1) + offset, Vec2(1, 0) + offset, Vec2(1, 1) + offset});
}

TEST(SeamEdges, HandMadeWrapAndCut) {
  const Layout wrap = twoTriangles({1, 0});
  const SeamEdges w = classifySeamEdges(wrap.mesh, wrap.uv);
  EXPECT_EQ(w.wrapEdges, 1u);
  EXPECT_EQ(w.cutEdges, 0u);
  EXPECT_DOUBLE_EQ(w.wrapLength, std::sqrt(2.0));

  for (const Vec2& offset : {Vec2(0.3, 0), Vec2(1, 0.5), Vec2(0, 1)}) {
    const Layout cut = twoTriangles(offset);
    const SeamEdges c = classifySeamEdges(cut.mesh, cut.uv);
    EXPECT_EQ(c.wrapEdges, 0u);
    EXPECT_EQ(c.cutEdges, 1u);
    EXPECT_DOUBLE_EQ(c.cutLength, std::sqrt(2.0));
  }

  const Layout none = twoTriangles({0, 0});  // continuous: no seam; boundary edges never are
  const SeamEdges n = classifySeamEdges(none.mesh, none.uv);
  EXPECT_EQ(n.wrapEdges + n.cutEdges, 0u);

  // Endpoints at different integer offsets, (1, 0) at one and (2, 0) at the other: not a translation.
  Layout twisted = twoTriangles({1, 0});
  twisted.uv.uv[4].x() += 1.0;
  EXPECT_EQ(classifySeamEdges(twisted.mesh, twisted.uv).cutEdges, 1u);

  // A pole endpoint is left out: only the other endpoint's offset decides.
  Layout polar = twoTriangles({1, 0});
  polar.uv.uv[3].x() += 0.25;  // vertex 2 fanned
  EXPECT_EQ(classifySeamEdges(polar.mesh, polar.uv).cutEdges, 1u);
  polar.uv.cornerPole.assign(polar.uv.uv.size(), 0);
  for (std::size_t c = 0; c < polar.uv.uv.size(); ++c) polar.uv.cornerPole[c] = polar.mesh.triangles[c / 3][c % 3] == 2;
  EXPECT_EQ(classifySeamEdges(polar.mesh, polar.uv).wrapEdges, 1u);
}

// The mesh with a vertex per distinct (vertex, u, v) of its corners, as a PLY or glTF file holds
// it (io/split_vertices.h): each copy appended in corner order, the first use keeping the index.
Mesh splitAtUvs(const Mesh& mesh, const UvMap& uv) {
  Mesh split = mesh;
  std::vector<std::vector<std::pair<Vec2, int>>> copies(mesh.positions.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[f][k];
      const Vec2 t = uv.uv[3 * f + std::size_t(k)];
      auto& seen = copies[std::size_t(v)];
      const auto found = std::find_if(seen.begin(), seen.end(), [&](const auto& c) { return c.first == t; });
      int index = v;
      if (found != seen.end()) index = found->second;
      else if (!seen.empty()) index = int(split.positions.size()), split.positions.push_back(mesh.positions[std::size_t(v)]);
      if (found == seen.end()) seen.emplace_back(t, index);
      split.triangles[f][k] = index;
    }
  return split;
}

// Split at its UVs, the shifted sphere's seam edges are edges of one face each in index terms, and
// each pole a vertex per fan face: welded by position, the seams and poles are those of the
// sphere (the same edges, classes and lengths; the poles' stand-ins are the same vertices).
TEST(SeamEdges, AMeshSplitAtItsSeamsHasTheSameSeamsAndPoles) {
  const param::Projection p = projectSphere(16, 8, param::SeamMode::Shift);
  const Mesh split = splitAtUvs(p.mesh, p.uv);
  ASSERT_EQ(split.positions.size(), p.mesh.positions.size() + 7 + 2 * 15);  // the 7 rings' seam vertices; 16 - 1 pole copies each
  EXPECT_EQ(fannedPoleVertices(split, p.uv), (std::vector<int>{0, 113}));
  EXPECT_EQ(poleVerticesOf(p.mesh, p.uv), (std::vector<int>{0, 113}));
  // As a file's UVs: the poles found in them (markFannedPoles) mark the corners of vertices 0 and 113 only.
  UvMap found = p.uv;
  found.cornerPole.clear();
  markFannedPoles(split, found);
  EXPECT_EQ(poleVerticesOf(split, found), (std::vector<int>{0, 113}));
  const std::vector<SeamEdge> whole = seamEdgeList(p.mesh, p.uv), parts = seamEdgeList(split, p.uv);
  EXPECT_EQ(seamEdgeList(split, found).size(), parts.size());
  ASSERT_EQ(parts.size(), 8u);
  ASSERT_EQ(parts.size(), whole.size());
  for (std::size_t i = 0; i < whole.size(); ++i) {
    EXPECT_EQ(parts[i].a, whole[i].a);
    EXPECT_EQ(parts[i].b, whole[i].b);
    EXPECT_EQ(parts[i].wrap, whole[i].wrap);
  }
  const SeamEdges s = classifySeamEdges(split, found);
  EXPECT_EQ(s.wrapEdges, 8u);
  EXPECT_EQ(s.cutEdges, 0u);
  EXPECT_EQ(s.wrapLength, classifySeamEdges(p.mesh, p.uv).wrapLength);

  // Two triangles that share no vertex but meet along an edge at the same positions: one edge, a wrap seam.
  Layout apart = twoTriangles({1, 0});
  apart.mesh.positions.push_back(apart.mesh.positions[2]);
  apart.mesh.positions.push_back(apart.mesh.positions[1]);
  apart.mesh.triangles[1] = {4, 5, 3};
  EXPECT_EQ(classifySeamEdges(apart.mesh, apart.uv).wrapEdges, 1u);
  // Vertices in closed fans are never copies: the sphere twice over at the same positions (two
  // closed shells, as a doubled scan might be) has each shell's seams, where welding every
  // coincident vertex would give every edge four faces and no seam.
  Mesh twice = p.mesh;
  UvMap twiceUv = p.uv;
  const int n = int(p.mesh.positions.size());
  twice.positions.insert(twice.positions.end(), p.mesh.positions.begin(), p.mesh.positions.end());
  for (const Triangle& t : p.mesh.triangles) twice.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  twiceUv.uv.insert(twiceUv.uv.end(), p.uv.uv.begin(), p.uv.uv.end());
  twiceUv.faceFlags.insert(twiceUv.faceFlags.end(), p.uv.faceFlags.begin(), p.uv.faceFlags.end());
  twiceUv.cornerInvalid.insert(twiceUv.cornerInvalid.end(), p.uv.cornerInvalid.begin(), p.uv.cornerInvalid.end());
  twiceUv.cornerPole.insert(twiceUv.cornerPole.end(), p.uv.cornerPole.begin(), p.uv.cornerPole.end());
  EXPECT_EQ(classifySeamEdges(twice, twiceUv).wrapEdges, 16u);
}

// ---- Overlap ----

// Two unit right triangles, the second moved by (1/4, 1/4): they share a right triangle with
// legs 1/2 (area 1/8) of a union of area 7/8, so the overlapped fraction is 1/7.
TEST(Overlap, TwoOverlappingTrianglesMatchTheirAreas) {
  const Layout l = flatTriangles({{0, 0}, {1, 0}, {0, 1}, {0.25, 0.25}, {1.25, 0.25}, {0.25, 1.25}});
  const Overlap o = measureOverlap(l.uv, measureFaces(l.mesh, l.uv));
  EXPECT_EQ(o.resolution, 1024);
  EXPECT_NEAR(o.fraction(), 1.0 / 7.0, 0.01 / 7.0);
  EXPECT_NEAR(double(o.coveredPixels) / (1024.0 * 1024.0), 0.875 / (1.25 * 1.25), 1e-2);
}

// A grid tiling a square: shared edges are covered once. At 10 x 10 pixels over a 4 x 4 grid
// the grid's vertices fall on pixel centres (every 2.5 pixels) and its edges and diagonals run
// through centres, so every centre is covered exactly once only by the tie rule.
TEST(Overlap, ATilingHasNoneExactly) {
  param::ProjectorOptions o;
  o.surface = param::SurfaceKind::Plane;
  o.placement.fit = param::Fit::None;
  for (int n : {4, 7}) {
    const param::Projection p = param::project(meshes::planeGrid(n, n, 1.0, 1.0), o);
    const FaceMeasures faces = measureFaces(p.mesh, p.uv);
    for (int resolution : {10, 1024}) {
      const Overlap overlap = measureOverlap(p.uv, faces, resolution);
      EXPECT_EQ(overlap.overlappedPixels, 0u) << n << " " << resolution;
      EXPECT_EQ(overlap.coveredPixels, std::size_t(resolution) * std::size_t(resolution));
    }
  }
}

// The shifted sphere layout tiles [0, 1]^2 but for the gaps between the fanned pole triangles;
// the planar projection of a closed mesh covers its disk twice, front and back.
TEST(Overlap, SphereLayouts) {
  const param::Projection spherical = projectSphere(32, 16, param::SeamMode::Shift);
  EXPECT_EQ(measureOverlap(spherical.uv, measureFaces(spherical.mesh, spherical.uv)).overlappedPixels, 0u);

  param::ProjectorOptions o;
  o.surface = param::SurfaceKind::Plane;
  const param::Projection planar = param::project(meshes::icosphere(3), o);
  EXPECT_GT(measureOverlap(planar.uv, measureFaces(planar.mesh, planar.uv)).fraction(), 0.99);  // 1 exactly here
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::analysis
