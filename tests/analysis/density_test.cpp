// Texel density, sqrt(Auv W H / A3) texels per object unit: hand-computed values on rectangles,
// exact powers of two under scaling (also at 1e200, where the areas are measured at scale), the
// spread p90 / p10 of two halves of different densities, and the density_spread rule.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/judgement.h"
#include "analysis/summary.h"
#include "layout.h"

namespace uvtk::analysis {
namespace {
namespace UVTK_TEST_FILE {

// The rectangle [0, w] x [0, h] in z = 0 (two triangles), mapped to [0, s]^2 placed at u0.
Layout rectangle(double w, double h, double s = 1.0, double u0 = 0.0) {
  return makeLayout({{0, 0, 0}, {w, 0, 0}, {w, h, 0}, {0, h, 0}}, {{0, 1, 2}, {0, 2, 3}},
                    {{u0, 0}, {u0 + s, 0}, {u0 + s, s}, {u0, 0}, {u0 + s, s}, {u0, s}});
}

// Appends `b` to `a` (its own vertices).
Layout join(Layout a, const Layout& b) {
  const int first = int(a.mesh.positions.size());
  a.mesh.positions.insert(a.mesh.positions.end(), b.mesh.positions.begin(), b.mesh.positions.end());
  for (const Triangle& t : b.mesh.triangles) a.mesh.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
  a.uv.uv.insert(a.uv.uv.end(), b.uv.uv.begin(), b.uv.uv.end());
  a.uv.faceFlags.insert(a.uv.faceFlags.end(), b.uv.faceFlags.begin(), b.uv.faceFlags.end());
  a.uv.cornerInvalid.insert(a.uv.cornerInvalid.end(), b.uv.cornerInvalid.begin(), b.uv.cornerInvalid.end());
  return a;
}

TexelDensity densityOf(const Layout& l, TextureSize size = {}) {
  JudgementOptions options;
  options.textureSize = size;
  return judge(l.mesh, l.uv, options).summary.density;
}

TEST(TexelDensity, UnitSquareOnTheUnitSquareIsTheTextureWidth) {
  const TexelDensity d = densityOf(rectangle(1, 1));
  ASSERT_TRUE(d.finite);
  for (double x : {d.statistics.mean, d.statistics.p10, d.statistics.p50, d.statistics.p90, d.statistics.p99,
                   d.statistics.min, d.statistics.max})
    EXPECT_DOUBLE_EQ(x, 1024.0);
  EXPECT_EQ(d.textureSize, (TextureSize{1024, 1024}));
  EXPECT_DOUBLE_EQ(d.spread, 1.0);
}

TEST(TexelDensity, NonSquareTextureGivesTheGeometricMean) {
  // sqrt(1 * 2048 * 512 / 1) = 1024; sqrt(1 * 300 * 12 / 1) = 60.
  EXPECT_DOUBLE_EQ(densityOf(rectangle(1, 1), {2048, 512}).statistics.mean, 1024.0);
  EXPECT_DOUBLE_EQ(densityOf(rectangle(1, 1), {300, 12}).statistics.mean, 60.0);
}

TEST(TexelDensity, TwoByOneRectangleOnTheUnitSquare) {
  // A_uv = 1, A_3d = 2: sqrt(W H / 2).
  EXPECT_DOUBLE_EQ(densityOf(rectangle(2, 1), {1024, 1024}).statistics.mean, 1024.0 / std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(densityOf(rectangle(2, 1), {512, 256}).statistics.mean, std::sqrt(512.0 * 256.0 / 2.0));
}

TEST(TexelDensity, ScalingTheMeshByTwoToTheKDividesItExactly) {
  const double unit = densityOf(rectangle(3, 1.5)).statistics.mean;
  for (int k : {-40, -3, 1, 7, 60}) {
    SCOPED_TRACE(k);
    EXPECT_EQ(densityOf(rectangle(std::ldexp(3.0, k), std::ldexp(1.5, k))).statistics.mean, std::ldexp(unit, -k));
  }
}

TEST(TexelDensity, AMeshAt1e200IsMeasuredAtScaleAndUnscaledExactly) {
  const int k = std::ilogb(1e200);  // the mesh spans about 2^k: measured at 2^-k
  const double unit = densityOf(rectangle(1, 1)).statistics.mean;
  const TexelDensity huge = densityOf(rectangle(std::ldexp(1.0, k), std::ldexp(1.0, k)));
  ASSERT_TRUE(huge.finite);
  EXPECT_EQ(huge.statistics.mean, std::ldexp(unit, -k));
  EXPECT_TRUE(std::isnormal(huge.statistics.mean));
  // UVs at 1e200 too: the density is 1024 again, though A_uv and A_3d both overflow a double.
  const TexelDensity both = densityOf(rectangle(std::ldexp(1.0, k), std::ldexp(1.0, k), std::ldexp(1.0, k)));
  EXPECT_EQ(both.statistics.mean, 1024.0);
}

TEST(TexelDensity, BeyondADoubleIsFlaggedNotInfinite) {
  // A mesh at 2^-1020 on the unit UV square: 1024 * 2^1020 = 2^1030 texels per unit overflows.
  // Measured at 2^1021 (its half extent is 2^-1021): the scaled density is 2^1030 / 2^1021 = 512.
  const TexelDensity d = densityOf(rectangle(std::ldexp(1.0, -1020), std::ldexp(1.0, -1020)));
  EXPECT_FALSE(d.finite);
  EXPECT_EQ(d.statistics.mean, 0.0);
  EXPECT_EQ(d.exponent, 1021);
  EXPECT_EQ(d.scaled.mean, 512.0);
  EXPECT_DOUBLE_EQ(d.spread, 1.0);
  // And the opposite: a mesh at 2^1000 on a UV square of 2^-100, 1024 * 2^-1100 = 2^-1090 texels
  // per unit, lies below the normal doubles.
  EXPECT_FALSE(densityOf(rectangle(std::ldexp(1.0, 1000), std::ldexp(1.0, 1000), std::ldexp(1.0, -100))).finite);
}

TEST(TexelDensity, SpreadOfTwoHalvesIsTheirRatio) {
  // Two unit squares side by side (equal 3D areas): one on a UV square of side 1 (density 1024),
  // one of side 1/4 (density 256). Weighted percentiles: p10 = 256, p90 = 1024.
  const Layout l = join(rectangle(1, 1), rectangle(1, 1, 0.25, 2.0));
  const JudgementOptions defaults;
  const Judgement j = judge(l.mesh, l.uv, defaults);
  const TexelDensity& d = j.summary.density;
  EXPECT_DOUBLE_EQ(d.statistics.p10, 256.0);
  EXPECT_DOUBLE_EQ(d.statistics.p90, 1024.0);
  EXPECT_DOUBLE_EQ(d.statistics.mean, 640.0);
  EXPECT_DOUBLE_EQ(d.spread, 4.0);
  // The rule: 4 > 2 warns, and concerns every face (each lies at p10 or p90).
  EXPECT_EQ(j.values[std::size_t(Rule::DensitySpread)], 4.0);
  ASSERT_EQ(j.verdict, Verdict::Warn);
  bool found = false;
  for (const Reason& r : j.reasons)
    if (r.rule == Rule::DensitySpread) {
      found = true;
      EXPECT_EQ(r.faces, 4u);
      EXPECT_EQ(r.threshold, 2.0);
    }
  EXPECT_TRUE(found);

  // Set like any rule: off, or a threshold above 4.
  JudgementOptions options;
  options.thresholds.set("density_spread=4.5", Verdict::Warn, "--warn");
  EXPECT_EQ(judge(l.mesh, l.uv, options).verdict, Verdict::Pass);
  options.thresholds.set("density_spread=3", Verdict::Fail, "--fail");
  EXPECT_EQ(judge(l.mesh, l.uv, options).verdict, Verdict::Fail);
}

TEST(TexelDensity, SpreadAtTheDefaultThresholdPasses) {
  // Halves at 1024 and 512: a spread of exactly 2 does not exceed the default warn threshold.
  const Layout l = join(rectangle(1, 1), rectangle(1, 1, 0.5, 2.0));
  const JudgementOptions defaults;
  const Judgement j = judge(l.mesh, l.uv, defaults);
  EXPECT_DOUBLE_EQ(j.summary.density.spread, 2.0);
  EXPECT_EQ(j.verdict, Verdict::Pass);
}

TEST(TexelDensity, OnlyOkFacesCountAndNoOkFaceGivesZeros) {
  Layout l = join(rectangle(1, 1), rectangle(1, 1, 0.25, 2.0));
  l.uv.faceFlags[2] = l.uv.faceFlags[3] = kFaceInvalid;  // the dense-less half
  const TexelDensity d = densityOf(l);
  EXPECT_DOUBLE_EQ(d.statistics.min, 1024.0);
  EXPECT_DOUBLE_EQ(d.statistics.max, 1024.0);
  Layout none = rectangle(1, 1);
  none.uv.faceFlags.assign(2, kFaceInvalid);
  const TexelDensity z = densityOf(none);
  EXPECT_TRUE(z.finite);
  EXPECT_EQ(z.statistics.mean, 0.0);
  EXPECT_EQ(z.spread, 0.0);
}

TEST(Statistics, P10IsTheLowerInverseAtATenth) {
  // Weights 1, 1, 8 on values 1, 2, 3: the running weight reaches 1 (a tenth of 10) at value 1.
  const Statistics s = weightedStatistics({1.0, 2.0, 3.0}, {1.0, 1.0, 8.0}, BinSpacing::Linear);
  EXPECT_EQ(s.p10, 1.0);
  const Statistics t = weightedStatistics({1.0, 2.0, 3.0}, {0.5, 1.0, 8.5}, BinSpacing::Linear);
  EXPECT_EQ(t.p10, 2.0);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::analysis
