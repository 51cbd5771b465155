// The comparison behind `uvtk check`: the per-corner error with whole periods removed, pole corners
// compared across the period only, nearest-rank statistics, the worst corners, and whole meshes
// mapped twice with different seam repairs.
#include "analysis/uv_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/seam_edges.h"
#include "meshes/generators.h"
#include "param/projector.h"

namespace uvtk::analysis {
namespace {
namespace UVTK_TEST_FILE {

const Vec2 kTurn(1, 0), kNoPeriod(0, 0);

// Per-corner UVs of `faces` faces, no face flagged, every corner valid.
UvMap uvMap(std::vector<Vec2> uv) {
  UvMap m;
  m.faceFlags.assign(uv.size() / 3, kFaceOk);
  m.cornerInvalid.assign(uv.size(), 0);
  m.uv = std::move(uv);
  return m;
}

// ---- the error of one corner ----

TEST(WrappedUvError, WholeTurnsDoNotCountOnAWrappingSurface) {
  EXPECT_EQ(wrappedUvError(Vec2(1.02, 0.5), Vec2(0.02, 0.5), kTurn, false), 0.0);
  EXPECT_EQ(wrappedUvError(Vec2(0.02, 0.5), Vec2(1.02, 0.5), kTurn, false), 0.0);
  EXPECT_EQ(wrappedUvError(Vec2(-2.0, 0.5), Vec2(1.0, 0.5), kTurn, false), 0.0);
}

TEST(WrappedUvError, OnAPlaneTheTurnIsAnError) {
  EXPECT_EQ(wrappedUvError(Vec2(1.02, 0.5), Vec2(0.02, 0.5), kNoPeriod, false), 1.0);
  EXPECT_DOUBLE_EQ(wrappedUvError(Vec2(0.3, 0.9), Vec2(0.0, 0.5), kNoPeriod, false), 0.5);  // 3-4-5
}

TEST(WrappedUvError, TheNearestTurnIsRemovedAndTheRestIsEuclidean) {
  // u differs by 0.9 = one turn less 0.1; v by 0.2: sqrt(0.1^2 + 0.2^2).
  EXPECT_NEAR(wrappedUvError(Vec2(0.95, 0.7), Vec2(0.05, 0.5), kTurn, false), std::hypot(0.1, 0.2), 1e-15);
  // A quarter turn stays a quarter turn, whichever side.
  EXPECT_NEAR(wrappedUvError(Vec2(0.35, 0.5), Vec2(0.1, 0.5), kTurn, false), 0.25, 1e-15);
  EXPECT_NEAR(wrappedUvError(Vec2(0.1, 0.5), Vec2(0.85, 0.5), kTurn, false), 0.25, 1e-15);
}

TEST(WrappedUvError, APoleCornersUIsIgnored) {
  EXPECT_EQ(wrappedUvError(Vec2(0.7, 1.0), Vec2(0.0, 1.0), kTurn, true), 0.0);
  EXPECT_EQ(wrappedUvError(Vec2(0.123, 0.25), Vec2(0.9, 0.2), kTurn, true), std::hypot(0.0, 0.25 - 0.2));
  // Not at a pole, the same u difference counts.
  EXPECT_NEAR(wrappedUvError(Vec2(0.7, 1.0), Vec2(0.0, 1.0), kTurn, false), 0.3, 1e-15);
}

TEST(WrappedUvError, AScaledPeriodRemovesItsOwnTurns) {
  const Vec2 period(2, 0);  // --uv-scale 2,1: T(1, 0) - T(0, 0)
  EXPECT_EQ(wrappedUvError(Vec2(2.04, 0.5), Vec2(0.04, 0.5), period, false), 0.0);
  EXPECT_EQ(wrappedUvError(Vec2(1.02, 0.5), Vec2(0.02, 0.5), period, false), 1.0);  // half a turn: not removed
  EXPECT_EQ(wrappedUvError(Vec2(4.5, 0.5), Vec2(0.5, 0.5), period, false), 0.0);
  // A period along v (--uv-rotate 90: T(1, 0) - T(0, 0) = (0, 1)).
  EXPECT_EQ(wrappedUvError(Vec2(0.3, 1.75), Vec2(0.3, 0.75), Vec2(0, 1), false), 0.0);
  EXPECT_EQ(wrappedUvError(Vec2(0.9, 1.75), Vec2(0.3, 0.25), Vec2(0, 1), true), 0.9 - 0.3);  // pole: v ignored
}

// ---- statistics ----

TEST(ErrorStatistics, MaxP99ByNearestRankAndMean) {
  const ErrorStatistics s = errorStatistics({0.3, 0.1, 0.4, 0.2});
  EXPECT_EQ(s.count, 4u);
  EXPECT_EQ(s.max, 0.4);
  EXPECT_EQ(s.p99, 0.4);  // rank ceil(3.96) = 4
  EXPECT_DOUBLE_EQ(s.mean, 0.25);
  // Errors near the largest double: their sum overflows, their mean does not (it was inf).
  const double big = 0x1.8p1023;  // 1.35e308
  EXPECT_EQ(errorStatistics({big, big, big}).mean, big);
  EXPECT_EQ(errorStatistics({big, 0.0}).mean, 0.5 * big);
  EXPECT_EQ(errorStatistics({big, HUGE_VAL}).mean, HUGE_VAL);  // an infinite error stays infinite
}

TEST(ErrorStatistics, P99IsTheValueOfRankCeil99PercentOfN) {
  std::vector<double> values;
  for (int i = 100; i >= 0; --i) values.push_back(i);  // 0..100, in any order
  ErrorStatistics s = errorStatistics(values);
  EXPECT_EQ(s.max, 100.0);
  EXPECT_EQ(s.p99, 99.0);  // n = 101: rank ceil(99.99) = 100, the 100th smallest
  EXPECT_EQ(s.mean, 50.0);
  values.assign(100, 0.0);
  values[0] = 7.0;  // n = 100: rank 99 leaves the one large value out
  s = errorStatistics(values);
  EXPECT_EQ(s.max, 7.0);
  EXPECT_EQ(s.p99, 0.0);
  values[1] = 5.0;  // two large values: rank 99 is the smaller of them
  EXPECT_EQ(errorStatistics(values).p99, 5.0);
  std::vector<double> ramp;
  for (int i = 1; i <= 200; ++i) ramp.push_back(i);
  EXPECT_EQ(errorStatistics(ramp).p99, 198.0);  // rank ceil(198) = 198, exactly
}

TEST(ErrorStatistics, NoValuesGiveZeros) {
  const ErrorStatistics s = errorStatistics({});
  EXPECT_EQ(s.count, 0u);
  EXPECT_EQ(s.max, 0.0);
  EXPECT_EQ(s.p99, 0.0);
  EXPECT_EQ(s.mean, 0.0);
}

// ---- the worst corners ----

TEST(WorstCorners, LargestFirstAndTiesInCornerOrder) {
  const std::vector<double> error = {0.5, 0.1, 0.5, 0.9, 0.1, 0.0};
  const std::vector<CornerClass> classes(6, CornerClass::Main);
  const std::vector<CornerError> worst = worstCorners(error, classes, CornerClass::Main, 4);
  ASSERT_EQ(worst.size(), 4u);
  EXPECT_EQ(worst[0].corner, 3u);
  EXPECT_EQ(worst[0].error, 0.9);
  EXPECT_EQ(worst[1].corner, 0u);
  EXPECT_EQ(worst[2].corner, 2u);
  EXPECT_EQ(worst[3].corner, 1u);
  EXPECT_EQ(worstCorners(error, classes, CornerClass::Main, 100).size(), 6u);
  EXPECT_TRUE(worstCorners(error, classes, CornerClass::Main, 0).empty());
}

TEST(WorstCorners, OnlyTheClassAskedFor) {
  const std::vector<double> error = {0.5, 0.9, 0.7, 0.8};
  const std::vector<CornerClass> classes = {CornerClass::Main, CornerClass::Pole, CornerClass::PoleFace,
                                            CornerClass::Main};
  const std::vector<CornerError> main = worstCorners(error, classes, CornerClass::Main, 10);
  ASSERT_EQ(main.size(), 2u);
  EXPECT_EQ(main[0].corner, 3u);
  EXPECT_EQ(main[1].corner, 0u);
  const std::vector<CornerError> pole = worstCorners(error, classes, CornerClass::Pole, 10);  // with PoleFace
  ASSERT_EQ(pole.size(), 2u);
  EXPECT_EQ(pole[0].corner, 1u);
  EXPECT_EQ(pole[1].corner, 2u);
}

// ---- whole fields ----

TEST(CheckUvs, ClassifiesCornersAndKeepsPolesAndInvalidCornersOutOfTheMainStatistics) {
  // Face 0: ordinary, its corner 1 a whole turn off (no error) and corner 2 off by 0.01 in v.
  // Face 1: a pole face; corner 3 at the pole vertex with a different u (no error), corner 4 off by 0.2.
  // Face 2: corner 6 without a value in the mapping, corner 7 without one in the file; corner 8 off by 0.5.
  UvMap expected = uvMap({{0.1, 0.5},
                          {0.2, 0.5},
                          {0.3, 0.5},  //
                          {0.0, 1.0},
                          {0.4, 0.9},
                          {0.6, 0.9},  //
                          {0.0, 0.0},
                          {0.5, 0.5},
                          {0.5, 0.2}});
  UvMap found = uvMap({{0.1, 0.5},
                       {1.2, 0.5},
                       {0.3, 0.51},  //
                       {0.5, 1.0},
                       {0.6, 0.9},
                       {0.6, 0.9},  //
                       {0.7, 0.7},
                       {0.0, 0.0},
                       {0.5, 0.7}});
  expected.faceFlags[1] = kFacePole;
  expected.cornerInvalid[6] = 1;
  found.cornerInvalid[7] = 1;
  UvCheckOptions options;
  options.period = kTurn;
  options.poleCorners = {0, 0, 0, 1, 0, 0, 0, 0, 0};
  const UvCheck check = checkUvs(expected, found, options);

  EXPECT_EQ(check.cornerClass[0], CornerClass::Main);
  EXPECT_EQ(check.cornerClass[3], CornerClass::Pole);
  EXPECT_EQ(check.cornerClass[4], CornerClass::PoleFace);
  EXPECT_EQ(check.cornerClass[6], CornerClass::Invalid);
  EXPECT_EQ(check.cornerClass[7], CornerClass::Invalid);
  EXPECT_EQ(check.cornerClass[8], CornerClass::Main);
  EXPECT_EQ(check.error[1], 0.0);
  EXPECT_EQ(check.error[3], 0.0);
  EXPECT_TRUE(std::isnan(check.error[6]));

  EXPECT_EQ(check.main.count, 4u);  // corners 0, 1, 2, 8
  EXPECT_NEAR(check.main.max, 0.5, 1e-15);
  EXPECT_NEAR(check.main.mean, (0.01 + 0.5) / 4, 1e-15);
  EXPECT_EQ(check.pole.count, 3u);
  EXPECT_EQ(check.poleCorners, 1u);
  EXPECT_EQ(check.poleFaceCorners, 2u);
  EXPECT_EQ(check.poleFaces, 1u);
  EXPECT_NEAR(check.pole.max, 0.2, 1e-15);
  EXPECT_EQ(check.invalidCorners, (std::vector<std::size_t>{6, 7}));
  EXPECT_EQ(check.noExpected, 1u);
  EXPECT_EQ(check.noFound, 1u);
  ASSERT_EQ(check.worst.size(), 4u);
  EXPECT_EQ(check.worst[0].corner, 8u);
  EXPECT_EQ(check.worst[1].corner, 2u);
  EXPECT_EQ(check.worst[2].corner, 0u);  // 0 and 1 tie at 0: corner order
  EXPECT_EQ(check.worst[3].corner, 1u);
  ASSERT_EQ(check.worstPole.size(), 3u);
  EXPECT_EQ(check.worstPole[0].corner, 4u);
}

TEST(CheckUvs, CapFacesAndPlanesDoNotWrap) {
  UvMap expected = uvMap({{0.1, 0.5}, {0.2, 0.5}, {0.3, 0.5}, {0.1, 0.5}, {0.2, 0.5}, {0.3, 0.5}});
  const UvMap found = uvMap({{1.1, 0.5}, {0.2, 0.5}, {0.3, 0.5}, {1.1, 0.5}, {0.2, 0.5}, {0.3, 0.5}});
  expected.faceFlags[1] = kFaceCap;
  UvCheckOptions options;
  options.period = kTurn;
  UvCheck check = checkUvs(expected, found, options);
  EXPECT_EQ(check.error[0], 0.0);
  EXPECT_NEAR(check.error[3], 1.0, 1e-15);
  options.period = kNoPeriod;
  check = checkUvs(expected, found, options);
  EXPECT_NEAR(check.error[0], 1.0, 1e-15);
}

// The projector marks its pole corners as it marks invalid ones: exactly the corners on the axis
// (x = y = 0 for the sphere at the origin), and poleVerticesOf lists the summary's pole vertices.
TEST(CheckUvs, TheProjectorMarksExactlyTheCornersOnItsAxis) {
  const Mesh sphere = meshes::latLongSphere(16, 9);
  param::ProjectorOptions o;
  o.surface = param::SurfaceKind::Sphere;
  o.placement.fit = param::Fit::None;
  const param::Projection p = param::project(sphere, o);
  ASSERT_EQ(p.uv.cornerPole.size(), p.uv.uv.size());
  std::size_t onAxis = 0;
  for (std::size_t c = 0; c < p.uv.uv.size(); ++c) {
    const Vec3& q = p.mesh.positions[std::size_t(p.mesh.triangles[c / 3][c % 3])];
    const bool axis = q.x() == 0.0 && q.y() == 0.0;
    onAxis += axis;
    EXPECT_EQ(p.uv.cornerAtPole(c), axis) << "corner " << c;
  }
  EXPECT_EQ(onAxis, 2u * 16u);  // one fan of 16 triangles at each pole
  EXPECT_EQ(poleVerticesOf(p.mesh, p.uv), p.summary.poleVertexList);
  EXPECT_EQ(p.summary.poleVertexList.size(), 2u);
}

// A sphere mapped with the seam shifted and with the raw u, and with a scaled UV transform: the
// corners differ by whole periods only, and checkUvs sees no error anywhere.
TEST(CheckUvs, SeamRepairsDifferByWholePeriodsOnly) {
  const Mesh sphere = meshes::latLongSphere(16, 9);
  for (const Vec2& scale : {Vec2(1, 1), Vec2(2, 1)}) {
    param::ProjectorOptions o;
    o.surface = param::SurfaceKind::Sphere;
    o.uvTransform.scale = scale;
    o.seam = param::SeamMode::Shift;
    const param::Projection shifted = param::project(sphere, o);
    o.seam = param::SeamMode::None;
    const param::Projection raw = param::project(sphere, o);
    ASSERT_GT(shifted.summary.straddlingFaces, 0u);
    UvCheckOptions options;
    options.period = o.uvTransform.apply(Vec2(1, 0)) - o.uvTransform.apply(Vec2(0, 0));
    EXPECT_EQ(options.period, Vec2(scale.x(), 0));
    options.poleCorners = shifted.uv.cornerPole;
    const UvCheck check = checkUvs(raw.uv, shifted.uv, options);
    EXPECT_EQ(check.main.max, 0.0) << "scale " << scale.x();
    EXPECT_EQ(check.pole.max, 0.0);
    EXPECT_GT(check.poleCorners, 0u);
    // Without the period the seam's corners are whole turns off.
    options.period = kNoPeriod;
    EXPECT_NEAR(checkUvs(raw.uv, shifted.uv, options).main.max, scale.x(), 1e-12);
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::analysis
