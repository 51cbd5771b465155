// Issue 6, numerical extremes of the projector mappings: one row per case, each row stating the
// documented behaviour that its failure messages repeat (docs/extremes.md lists every row). Every
// result is finite or a documented status (Pole, Invalid with uv (0, 0), a UsageError); none is
// NaN. Each row runs in binary64 and binary32 (ProjectorOptions::arithmetic.precision), with libm
// and SLEEF (MathMode Exact and Fast) wherever an arctangent is taken.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "core/error.h"
#include "meshes/generators.h"
#include "param/atlas_meshes.h"
#include "param/formulas.h"
#include "param/projector.h"
#include "param/reference.h"

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

constexpr double kAny = std::numeric_limits<double>::quiet_NaN();  // any finite value
constexpr double kDenormMin = std::numeric_limits<double>::denorm_min();
constexpr double kMax = std::numeric_limits<double>::max();
constexpr long double kPiLong = 3.141592653589793238462643383279502884L;
// The sphere's v at (1, 1, 1): 1 - atan2(sqrt 2, 1)/pi.
const double kV111 = double(1.0L - std::atan2(std::sqrt(2.0L), 1.0L) / kPiLong);
// u at the azimuth of (0.6, 0.8): atan2(0.8, 0.6)/(2 pi).
const double kU0608 = double(std::atan2(0.8L, 0.6L) / (2 * kPiLong));

const char* nameOf(Precision p) { return p == Precision::Double ? "double" : "float"; }
const char* nameOf(MathMode m) { return m == MathMode::Exact ? "exact" : "fast"; }
const char* nameOf(CornerState s) { return s == CornerState::Ok ? "Ok" : s == CornerState::Pole ? "Pole" : "Invalid"; }

// What one precision gives for a row: the state and, unless kAny, u and v within `tolerance`
// relative to max(1, |value|) (0: exactly).
struct Outcome {
  CornerState state;
  double u, v;
  double tolerance = 0.0;
  bool orInvalid = false;  // a miss is documented too: rounding decides a tangent ray
};

Outcome ok(double u, double v, double tolerance = 0.0) { return {CornerState::Ok, u, v, tolerance}; }
Outcome pole(double v) { return {CornerState::Pole, 0.0, v}; }
Outcome invalid() { return {CornerState::Invalid, 0.0, 0.0}; }
Outcome okOrMiss(double u, double v, double tolerance) { return {CornerState::Ok, u, v, tolerance, true}; }

// One vertex through mapVertices (and PointMapping, which must agree bit for bit), local frame =
// object frame unless `frame` is given.
struct PointRow {
  const char* expected;
  SurfaceKind surface;
  RayKind ray;
  Vec3 position;
  Outcome inDouble, inFloat;
  Vec3 normal = Vec3::Zero();  // read by normal and reflection
  Vec3 eye = Vec3(0, 0, 5);    // read by reflection
  std::optional<ExplicitFrame> frame = std::nullopt;
  Vec4 planeV = Vec4(0, 1, 0, 0);  // two-plane: the second plane (the first is x = 0)
};

const Vec3 kNone = Vec3::Zero();
const Vec3 kEye = Vec3(0, 0, 5);
constexpr SurfaceKind kPlane = SurfaceKind::Plane, kTwoPlane = SurfaceKind::TwoPlane, kCylinder = SurfaceKind::Cylinder,
                      kSphere = SurfaceKind::Sphere, kCube = SurfaceKind::Cube;
constexpr RayKind kIsn = RayKind::SurfaceNormal, kCentroid = RayKind::Centroid, kNormal = RayKind::ObjectNormal,
                  kReflection = RayKind::Reflection;

ExplicitFrame frameOf(const Vec3& center, double scale) { return {center, Vec3::UnitZ(), Vec3::UnitX(), scale}; }

PointRow row(const char* expected, SurfaceKind surface, RayKind ray, const Vec3& position, const Outcome& inDouble,
             const Outcome& inFloat, const Vec3& normal = kNone, const Vec3& eye = kEye,
             const std::optional<ExplicitFrame>& frame = std::nullopt, const Vec4& planeV = Vec4(0, 1, 0, 0)) {
  return {expected, surface, ray, position, inDouble, inFloat, normal, eye, frame, planeV};
}

const double kTiny = 1e-11;  // the sine of two nearly parallel planes, above the 1e-12 limit
const Vec4 kNearlyParallelV(std::cos(kTiny), std::sin(kTiny), 0, 0);

const std::vector<PointRow>& pointRows() {
  static const std::vector<PointRow> rows = {
      // ---- on the axis, at a pole: u 0, v exact ----
      row("sphere isn at +z: Pole, u 0, v 1 exactly", kSphere, kIsn, {0, 0, 1}, pole(1), pole(1)),
      row("sphere isn at -z with x = +0, y = -0: Pole, u 0, v 0 exactly", kSphere, kIsn, {0.0, -0.0, -1}, pole(0),
          pole(0)),
      row("sphere isn at (-0, -0, 2): Pole, v 1", kSphere, kIsn, {-0.0, -0.0, 2}, pole(1), pole(1)),
      row("sphere centroid on the axis (radial like isn): Pole, v 0", kSphere, kCentroid, {-0.0, 0.0, -3}, pole(0),
          pole(0)),
      row("sphere isn at the origin (+0, -0, -0): no direction, Invalid (0, 0)", kSphere, kIsn, {0.0, -0.0, -0.0},
          invalid(), invalid()),
      row("cylinder isn on the axis: Pole, u 0, v = z exactly", kCylinder, kIsn, {0, 0, 0.5}, pole(0.5), pole(0.5)),
      row("cylinder isn on the axis, x = y = -0: Pole, v = z", kCylinder, kIsn, {-0.0, -0.0, -0.25}, pole(-0.25),
          pole(-0.25)),
      row("cylinder isn at the origin: Pole, v 0", kCylinder, kIsn, {0, 0, 0}, pole(0), pole(0)),
      row("cylinder centroid on the axis: the ray never meets the side, Invalid", kCylinder, kCentroid, {0.0, -0.0, 1},
          invalid(), invalid()),
      row("sphere normal ray up the axis from inside: hits the pole, Pole, v 1", kSphere, kNormal, {0, 0, 0.5}, pole(1),
          pole(1), {0, 0, 1}),
      row("cylinder normal ray up the axis: parallel to the side, Invalid", kCylinder, kNormal, {0, 0, 0.5}, invalid(),
          invalid(), {0, 0, 1}),
      row("sphere reflection at the pole, eye on the axis: back along the axis, Pole, v 1", kSphere, kReflection,
          {0, 0, 1}, pole(1), pole(1), {0, 0, 1}, kEye),

      // ---- on the seam half-plane: u 0 exactly, never 1 ----
      row("sphere isn on the seam, y = +0: u 0, v 1/2", kSphere, kIsn, {1, 0.0, 0}, ok(0, 0.5), ok(0, 0.5)),
      row("sphere isn on the seam, y = -0: u +0, never 1", kSphere, kIsn, {1, -0.0, 0}, ok(0, 0.5), ok(0, 0.5)),
      row("cylinder isn on the seam, y = -0: u 0, v = z", kCylinder, kIsn, {2, -0.0, 0.3}, ok(0, 0.3), ok(0, 0.3f)),
      row("sphere isn at y = -1e-17: atan2 + 2 pi rounds to a full turn, u 0, not 1", kSphere, kIsn, {1, -1e-17, 0},
          ok(0, 0.5), ok(0, 0.5)),
      row("sphere isn at y = -5e-324 (subnormal): u 0, not 1", kSphere, kIsn, {1, -kDenormMin, 0}, ok(0, 0.5),
          ok(0, 0.5)),
      row("cylinder centroid on the seam, y = -0: u 0, v = z/rho", kCylinder, kCentroid, {1, -0.0, 0.5}, ok(0, 0.5),
          ok(0, 0.5)),
      row("sphere isn on the -x half-plane, y = -0: u 1/2 like y = +0", kSphere, kIsn, {-1, -0.0, 0},
          ok(0.5, 0.5, 1e-15), ok(0.5, 0.5, 1e-7)),

      // ---- tiny, subnormal and huge coordinates (float: documented overflow and underflow) ----
      row("sphere isn at (1e-300)^3: scale-free, as at (1, 1, 1); float flushes to 0: Invalid", kSphere, kIsn,
          {1e-300, 1e-300, 1e-300}, ok(0.125, kV111, 1e-15), invalid()),
      row("sphere isn at (1e300)^3: as at (1, 1, 1); float overflows to inf: Invalid", kSphere, kIsn,
          {1e300, 1e300, 1e300}, ok(0.125, kV111, 1e-15), invalid()),
      row("sphere isn at the subnormal (5e-324, 0, 0): u 0, v 1/2; float: 0, Invalid", kSphere, kIsn,
          {kDenormMin, 0, 0}, ok(0, 0.5), invalid()),
      row("sphere isn at (5e-324)^3: hypot rounds to the subnormal grid, so v = 3/4, not 0.696; float: Invalid",
          kSphere, kIsn, {kDenormMin, kDenormMin, kDenormMin}, ok(0.125, 0.75, 1e-15), invalid()),
      row("sphere isn at (DBL_MAX, DBL_MAX, 0): hypot overflows to inf, still u 1/8, v 1/2; float: Invalid", kSphere,
          kIsn, {kMax, kMax, 0}, ok(0.125, 0.5, 1e-15), invalid()),
      row("cylinder isn at (1e300)^3: u 1/8, v = z = 1e300; float: Invalid", kCylinder, kIsn, {1e300, 1e300, 1e300},
          ok(0.125, 1e300, 1e-15), invalid()),
      row("cylinder isn at (1e-300, 0, 1e-300): u 0, v 1e-300 exactly; float flushes to the axis: Pole, v 0", kCylinder,
          kIsn, {1e-300, 0, 1e-300}, ok(0, 1e-300), pole(0)),
      row("cylinder centroid at (1e-300)^3: u 1/8, v = z/rho = 1/sqrt 2; float: 0, Invalid", kCylinder, kCentroid,
          {1e-300, 1e-300, 1e-300}, ok(0.125, std::sqrt(0.5), 1e-15), invalid()),
      row("cylinder centroid at the subnormal (5e-324, 0, 5e-324): u 0, v 1; float: Invalid", kCylinder, kCentroid,
          {kDenormMin, 0, kDenormMin}, ok(0, 1), invalid()),
      row("plane isn at (1e300, -1e300, 5): (u, v) = (x, y) exactly; float: inf, Invalid", kPlane, kIsn,
          {1e300, -1e300, 5}, ok(1e300, -1e300), invalid()),
      row("plane centroid at (1e-300)^3: (x/z, y/z) = (1, 1); float: z = 0, Invalid", kPlane, kCentroid,
          {1e-300, 1e-300, 1e-300}, ok(1, 1), invalid()),
      row("plane centroid with z = 5e-324: x/z overflows, Invalid", kPlane, kCentroid, {1, 2, kDenormMin}, invalid(),
          invalid()),
      row("plane normal ray from (1e300, 0, 1e300) along -z: meets z = 0 at (1e300, 0); float: Invalid", kPlane,
          kNormal, {1e300, 0, 1e300}, ok(1e300, 0), invalid(), {0, 0, -1}),
      row("two-plane isn at (1e300, -1e300, 0): distances 1e300, -1e300; float: Invalid", kTwoPlane, kIsn,
          {1e300, -1e300, 0}, ok(1e300, -1e300), invalid()),
      row("two-plane isn at (5e-324, -5e-324, 0): subnormal distances exactly; float: 0, Ok", kTwoPlane, kIsn,
          {kDenormMin, -kDenormMin, 0}, ok(kDenormMin, -kDenormMin), ok(0, 0)),

      // ---- explicit frames: the move to the frame (double) rescales before float sees the point ----
      row("sphere, explicit frame of scale 1e-300: (1e-300)^3 is local (1, 1, 1) in both precisions", kSphere, kIsn,
          {1e-300, 1e-300, 1e-300}, ok(0.125, kV111, 1e-15), ok(0.125, kV111, 1e-6), kNone, kEye,
          frameOf(Vec3::Zero(), 1e-300)),
      row("sphere, explicit frame of scale 1e300 at (1e300, 0, 0): (2e300, 1e300, 1e300) is local (1, 1, 1)", kSphere,
          kIsn, {2e300, 1e300, 1e300}, ok(0.125, kV111, 1e-15), ok(0.125, kV111, 1e-6), kNone, kEye,
          frameOf(Vec3(1e300, 0, 0), 1e300)),
      row("sphere, explicit frame of scale 1e-300 at the subnormal (5e-324, 0, 0): local 4.9e-24, u 0, v 1/2", kSphere,
          kIsn, {kDenormMin, 0, 0}, ok(0, 0.5), ok(0, 0.5), kNone, kEye, frameOf(Vec3::Zero(), 1e-300)),

      // ---- tangent and grazing rays: a hit, or a documented miss (Invalid) ----
      row("sphere normal ray tangent at (1, 0, 0) on the surface: hits at t = 0, u 0, v 1/2", kSphere, kNormal,
          {1, 0, 0}, ok(0, 0.5), ok(0, 0.5), {0, 1, 0}),
      row("sphere normal ray grazing from outside, exactly tangent (double root t = 2): hits (1, 0, 0)", kSphere,
          kNormal, {1, -2, 0}, ok(0, 0.5), ok(0, 0.5), {0, 1, 0}),
      row("sphere normal ray passing 1e-9 outside: misses, Invalid; float rounds 1 + 1e-9 to 1: tangent hit", kSphere,
          kNormal, {1 + 1e-9, -2, 0}, invalid(), ok(0, 0.5), {0, 1, 0}),
      row("sphere normal ray grazing (0.6, 0.8, 0) from outside: a tangent hit or a miss (rounding decides), finite",
          kSphere, kNormal, {2.2, -0.4, 0}, okOrMiss(kU0608, 0.5, 1e-7), okOrMiss(kU0608, 0.5, 1e-3), {-0.8, 0.6, 0}),
      row("cylinder normal ray tangent at (1, 0, 0.5) on the side: hits at t = 0, u 0, v 0.5", kCylinder, kNormal,
          {1, 0, 0.5}, ok(0, 0.5), ok(0, 0.5), {0, 1, 0}),
      row("cylinder normal ray grazing from outside, exactly tangent: hits (1, 0, 0.25)", kCylinder, kNormal,
          {1, -2, 0.25}, ok(0, 0.25), ok(0, 0.25), {0, 1, 0}),
      row("sphere reflection, view tangent at (1, 0, 0): the mirror ray leaves along it, hits at t = 0", kSphere,
          kReflection, {1, 0, 0}, ok(0, 0.5), ok(0, 0.5), {1, 0, 0}, {1, -5, 0}),
      row("sphere normal ray from (1e300, 0, 0) along +y (a miss): |p|^2 overflows, Invalid, not a false hit at t = 0",
          kSphere, kNormal, {1e300, 0, 0}, invalid(), invalid(), {0, 1, 0}),
      row("sphere normal ray from (1e300, 0, 0) to the centre: |p|^2 overflows, Invalid (documented), not NaN", kSphere,
          kNormal, {1e300, 0, 0}, invalid(), invalid(), {-1, 0, 0}),
      row("sphere normal ray from (1e20, 0, 0) along +y: a miss; float's |p|^2 overflows: Invalid, not a false hit",
          kSphere, kNormal, {1e20, 0, 0}, invalid(), invalid(), {0, 1, 0}),
      row("cylinder normal ray from (1e20, 0, 0) along +y: a miss; float's rho^2 overflows: Invalid, not a false hit",
          kCylinder, kNormal, {1e20, 0, 0}, invalid(), invalid(), {0, 1, 0}),

      // ---- the centroid O-mapping's centre: vertex at the local origin, centre on the surface ----
      row("sphere centroid at the local origin: no direction, Invalid (0, 0)", kSphere, kCentroid, {0, 0, 0}, invalid(),
          invalid()),
      row("cylinder centroid at the local origin: Invalid (0, 0)", kCylinder, kCentroid, {0, 0, 0}, invalid(),
          invalid()),
      row("plane centroid at the local origin (the centre lies on the plane): Invalid (0, 0)", kPlane, kCentroid,
          {0, 0, 0}, invalid(), invalid()),
      row("plane centroid at z = -0, in the plane through the centre: Invalid", kPlane, kCentroid, {1, 2, -0.0},
          invalid(), invalid()),
      row("two-plane centroid at the object origin (on both planes): Invalid", kTwoPlane, kCentroid, {0, 0, 0},
          invalid(), invalid()),
      row("two-plane centroid in the plane a.x = 0 through the centre: Invalid", kTwoPlane, kCentroid, {1, 2, 0},
          invalid(), invalid()),

      // ---- zero-length normals: no ray, Invalid ----
      row("sphere normal O-mapping, zero normal on the surface: Invalid, not a hit at t = 0", kSphere, kNormal,
          {1, 0, 0}, invalid(), invalid(), kNone),
      row("sphere normal O-mapping, zero normal inside: Invalid", kSphere, kNormal, {0.5, 0, 0}, invalid(), invalid(),
          kNone),
      row("cylinder normal O-mapping, zero normal on the side: Invalid, not a hit at t = 0", kCylinder, kNormal,
          {1, 0, 0.5}, invalid(), invalid(), kNone),
      row("plane normal O-mapping, zero normal: Invalid", kPlane, kNormal, {0.3, 0.4, 1}, invalid(), invalid(), kNone),
      row("two-plane normal O-mapping, zero normal: Invalid", kTwoPlane, kNormal, {0.3, 0.4, 1}, invalid(), invalid(),
          kNone),
      row("sphere reflection, zero normal: no mirror, Invalid (not the unreflected view ray)", kSphere, kReflection,
          {0.5, 0, 0}, invalid(), invalid(), kNone),
      row("cylinder reflection, zero normal: Invalid", kCylinder, kReflection, {0.5, 0, 0.5}, invalid(), invalid(),
          kNone),
      row("plane reflection, zero normal: Invalid", kPlane, kReflection, {0.3, 0.4, 1}, invalid(), invalid(), kNone),
      row("sphere reflection with the eye at the vertex: no view direction, Invalid", kSphere, kReflection, {1, 0, 0},
          invalid(), invalid(), {1, 0, 0}, {1, 0, 0}),

      // ---- nearly parallel two-plane planes (the refused side: NearlyParallelPlanesBelowTheLimitAreRefused) ----
      row("two-plane at a sine of 1e-11 (limit 1e-12): accepted, v = x cos + y sin = 0.5 + 2e-11", kTwoPlane, kIsn,
          {0.5, 2, 0}, ok(0.5, 0.5 + 2e-11, 1e-15), ok(0.5, 0.5, 1e-6), kNone, kEye, std::nullopt, kNearlyParallelV),
      row("two-plane at a sine of 1e-11, centroid: rays meet a.x = 1 with a = +z exactly", kTwoPlane, kCentroid,
          {0.5, 2, 4}, ok(0.125, 0.125 + 5e-12, 1e-15), ok(0.125, 0.125, 1e-6), kNone, kEye, std::nullopt,
          kNearlyParallelV),
      row("two-plane at a sine of 1e-11, normal ray along the planes' line: parallel to a.x = 0, Invalid", kTwoPlane,
          kNormal, {0.5, 2, 4}, invalid(), invalid(), {1, 0, 0}, kEye, std::nullopt, kNearlyParallelV),
  };
  return rows;
}

bool usesArctangent(SurfaceKind s) { return s == kCylinder || s == kSphere; }

ProjectorOptions optionsOf(const PointRow& row, Precision precision, MathMode math) {
  ProjectorOptions o;
  o.surface = row.surface;
  o.ray = row.ray;
  o.eye = row.eye;
  o.planeV = row.planeV;
  o.placement.fit = Fit::None;
  o.placement.frame = row.frame;
  o.arithmetic = {precision, math};
  return o;
}

bool near(double got, double want, double tolerance) {
  return tolerance == 0.0 ? got == want : std::fabs(got - want) <= tolerance * std::max(1.0, std::fabs(want));
}

void expectOutcome(const VertexUv& got, const Outcome& want, bool wraps) {
  ASSERT_TRUE(got.uv.allFinite()) << "uv (" << got.uv.x() << ", " << got.uv.y() << ")";
  const bool missAllowed = want.orInvalid && got.state == CornerState::Invalid;
  EXPECT_TRUE(got.state == want.state || missAllowed)
      << "state " << nameOf(got.state) << ", expected " << nameOf(want.state);
  if (got.state == CornerState::Invalid) {
    EXPECT_EQ(got.uv, Vec2::Zero());
    return;
  }
  if (got.state == CornerState::Pole) {
    EXPECT_EQ(got.uv.x(), 0.0);
  }
  if (!std::isnan(want.u)) {
    EXPECT_TRUE(near(got.uv.x(), want.u, want.tolerance)) << "u " << got.uv.x() << " != " << want.u;
  }
  if (!std::isnan(want.v)) {
    EXPECT_TRUE(near(got.uv.y(), want.v, want.tolerance)) << "v " << got.uv.y() << " != " << want.v;
  }
  if (wraps) {  // u in [0, 1), never -0
    EXPECT_FALSE(std::signbit(got.uv.x())) << "u " << got.uv.x();
    EXPECT_LT(got.uv.x(), 1.0);
  }
}

class PointExtremes : public testing::TestWithParam<std::size_t> {};

TEST_P(PointExtremes, FiniteOrTheDocumentedStatus) {
  const PointRow& row = pointRows()[GetParam()];
  for (Precision precision : {Precision::Double, Precision::Float})
    for (MathMode math : {MathMode::Exact, MathMode::Fast}) {
      if (math == MathMode::Fast && !usesArctangent(row.surface)) continue;
      SCOPED_TRACE(std::string(row.expected) + " [" + nameOf(precision) + ", " + nameOf(math) + "]");
      const ProjectorOptions o = optionsOf(row, precision, math);
      const Affine3 frame = fitPlacement({}, row.surface, o.placement);
      std::vector<VertexUv> out;
      Projector(o, frame).mapVertices({row.position}, {row.normal}, out);
      expectOutcome(out[0], precision == Precision::Double ? row.inDouble : row.inFloat, usesArctangent(row.surface));
      const PointUv atPoint = Projector(o, frame).at(row.position, row.normal);
      EXPECT_EQ(atPoint.state, out[0].state) << "PointMapping";
      EXPECT_EQ(atPoint.uv, out[0].uv) << "PointMapping";
    }
}

INSTANTIATE_TEST_SUITE_P(Rows, PointExtremes, testing::Range<std::size_t>(0, pointRows().size()));

// ---- the cube through project(): a face per triangle, ties x before y before z ----

// Per precision: the face id every corner carries (-1: no face) and each corner's (s, t), NaN for
// a corner that is Invalid (written as (0, 0), its face flagged).
struct CubeOutcome {
  int face;
  std::array<Vec2, 3> st;
};

constexpr double kX = kAny;  // an Invalid corner
const CubeOutcome kNoFace{-1, {Vec2(kX, kX), Vec2(kX, kX), Vec2(kX, kX)}};

struct CubeRow {
  const char* expected;
  RayKind ray;
  std::array<Vec3, 3> corners;
  CubeOutcome inDouble, inFloat;
};

CubeRow cubeRow(const char* expected, RayKind ray, const std::array<Vec3, 3>& corners, const CubeOutcome& inDouble,
                const CubeOutcome& inFloat) {
  return {expected, ray, corners, inDouble, inFloat};
}

const std::vector<CubeRow>& cubeRows() {
  const Vec3 a(1, 0, 0), b(0, 1, 0), c(0, 0, 1);
  static const std::vector<CubeRow> rows = {
      cubeRow("isn, normal (1, 1, 1), a corner tie: +X (x before y before z), (s, t) = ((1 - z)/2, (1 - y)/2)", kIsn,
              {a, b, c}, {0, {Vec2(0.5, 0.5), Vec2(0.5, 0), Vec2(0, 0.5)}},
              {0, {Vec2(0.5, 0.5), Vec2(0.5, 0), Vec2(0, 0.5)}}),
      cubeRow("isn, normal (-1, -1, -1), a corner tie: -X, (s, t) = ((1 + z)/2, (1 - y)/2)", kIsn, {a, c, b},
              {1, {Vec2(0.5, 0.5), Vec2(1, 0.5), Vec2(0.5, 0)}}, {1, {Vec2(0.5, 0.5), Vec2(1, 0.5), Vec2(0.5, 0)}}),
      cubeRow("isn, normal (0, 1, 1), an edge tie: +Y (y before z), (s, t) = ((1 + x)/2, (1 + z)/2)", kIsn,
              {c, Vec3(1, 0, 1), b}, {2, {Vec2(0.5, 1), Vec2(1, 1), Vec2(0.5, 0.5)}},
              {2, {Vec2(0.5, 1), Vec2(1, 1), Vec2(0.5, 0.5)}}),
      cubeRow("isn, normal (-1, 0, 1), an edge tie: -X (x before z)", kIsn, {Vec3::Zero(), Vec3(1, 0, 1), b},
              {1, {Vec2(0.5, 0.5), Vec2(1, 0.5), Vec2(0.5, 0)}}, {1, {Vec2(0.5, 0.5), Vec2(1, 0.5), Vec2(0.5, 0)}}),
      cubeRow("isn, a degenerate triangle at (1, 1, 1): no normal, its centroid ties: +X", kIsn,
              {Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1)}, {0, {Vec2(0, 0), Vec2(0, 0), Vec2(0, 0)}},
              {0, {Vec2(0, 0), Vec2(0, 0), Vec2(0, 0)}}),
      cubeRow("isn, a degenerate triangle at the origin: no normal, no centroid direction, every corner Invalid", kIsn,
              {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()}, kNoFace, kNoFace),
      cubeRow("isn, corners at 1e150 (normal 1e300): +X, (s, t) about 5e149; float: inf, Invalid", kIsn,
              {1e150 * a, 1e150 * b, 1e150 * c}, {0, {Vec2(0.5, 0.5), Vec2(0.5, 0.5 - 5e149), Vec2(0.5 - 5e149, 0.5)}},
              kNoFace),
      cubeRow("isn, corners at 1e300: the normal overflows, no face: Invalid in both precisions", kIsn,
              {1e300 * a, 1e300 * b, 1e300 * c}, kNoFace, kNoFace),
      cubeRow("isn, corners at 1e-300: the normal underflows, the centroid ties: +X; float: all 0, Invalid", kIsn,
              {1e-300 * a, 1e-300 * b, 1e-300 * c}, {0, {Vec2(0.5, 0.5), Vec2(0.5, 0.5), Vec2(0.5, 0.5)}}, kNoFace),
      cubeRow("centroid, centroid direction (1, -1, 1), a cube corner: +X, every corner at (s, t) = (0, 1)", kCentroid,
              {Vec3(3, -3, 3), Vec3(6, -6, 6), Vec3(9, -9, 9)}, {0, {Vec2(0, 1), Vec2(0, 1), Vec2(0, 1)}},
              {0, {Vec2(0, 1), Vec2(0, 1), Vec2(0, 1)}}),
      cubeRow("centroid, centroid direction (0, -1, -1), a cube edge: -Y (y before z), (s, t) = (1/2, 1)", kCentroid,
              {Vec3(0, -3, -3), Vec3(0, -6, -6), Vec3(0, -9, -9)}, {3, {Vec2(0.5, 1), Vec2(0.5, 1), Vec2(0.5, 1)}},
              {3, {Vec2(0.5, 1), Vec2(0.5, 1), Vec2(0.5, 1)}}),
      cubeRow("centroid, centroid direction (-1, 1, 0): -X (x before y), (s, t) = (1/2, 0)", kCentroid,
              {Vec3(-3, 3, 0), Vec3(-6, 6, 0), Vec3(-9, 9, 0)}, {1, {Vec2(0.5, 0), Vec2(0.5, 0), Vec2(0.5, 0)}},
              {1, {Vec2(0.5, 0), Vec2(0.5, 0), Vec2(0.5, 0)}}),
      cubeRow("centroid, a corner at the local origin: that corner cannot project, Invalid; the others map on +X",
              kCentroid, {Vec3::Zero(), Vec3(2, 0.5, 1), Vec3(2, -0.5, -1)},
              {0, {Vec2(kX, kX), Vec2(0.25, 0.375), Vec2(0.75, 0.625)}},
              {0, {Vec2(kX, kX), Vec2(0.25, 0.375), Vec2(0.75, 0.625)}}),
      cubeRow("normal O-mapping, zero-length normals (a degenerate triangle): every corner Invalid, not NaN", kNormal,
              {Vec3(0.5, 0, 0), Vec3(0.5, 0, 0), Vec3(0.5, 0, 0)}, kNoFace, kNoFace),
      cubeRow("reflection, zero-length normals (a degenerate triangle): every corner Invalid, not NaN", kReflection,
              {Vec3(0.5, 0, 0), Vec3(0.5, 0, 0), Vec3(0.5, 0, 0)}, kNoFace, kNoFace),
  };
  return rows;
}

class CubeExtremes : public testing::TestWithParam<std::size_t> {};

TEST_P(CubeExtremes, FaceAndCornersAsDocumented) {
  const CubeRow& row = cubeRows()[GetParam()];
  Mesh mesh;
  mesh.positions = {row.corners.begin(), row.corners.end()};
  mesh.triangles = {{0, 1, 2}};
  for (Precision precision : {Precision::Double, Precision::Float}) {
    SCOPED_TRACE(std::string(row.expected) + " [" + nameOf(precision) + "]");
    const CubeOutcome& want = precision == Precision::Double ? row.inDouble : row.inFloat;
    ProjectorOptions o;
    o.surface = kCube;
    o.cubeLayout = CubeLayout::Faces;  // each face's own (s, t), the face id as w
    o.ray = row.ray;
    o.eye = kEye;
    o.placement.fit = Fit::None;
    o.arithmetic.precision = precision;
    const Projection p = project(mesh, o);
    std::size_t invalid = 0;
    for (int k = 0; k < 3; ++k) {
      const Vec2& uv = p.uv.uv[std::size_t(k)];
      ASSERT_TRUE(uv.allFinite()) << "corner " << k;
      if (std::isnan(want.st[k].x())) {
        EXPECT_TRUE(p.uv.cornerInvalid[std::size_t(k)]) << "corner " << k << " should be Invalid";
        EXPECT_EQ(uv, Vec2::Zero()) << "corner " << k;
        ++invalid;
        continue;
      }
      EXPECT_FALSE(p.uv.cornerInvalid[std::size_t(k)]) << "corner " << k;
      EXPECT_EQ(p.uv.w[std::size_t(k)], double(want.face)) << "corner " << k;
      const double tolerance = precision == Precision::Double ? 1e-15 : 1e-6;
      EXPECT_TRUE(near(uv.x(), want.st[k].x(), tolerance) && near(uv.y(), want.st[k].y(), tolerance))
          << "corner " << k << " (" << uv.x() << ", " << uv.y() << ")";
    }
    EXPECT_EQ(p.uv.faceHas(0, kFaceInvalid), invalid > 0);
    EXPECT_EQ(p.summary.invalidFaces, invalid > 0 ? 1u : 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(Rows, CubeExtremes, testing::Range<std::size_t>(0, cubeRows().size()));

// majorAxisFace itself: project() never asks it about a zero vector (that is Invalid), but the rule
// for signed zeros is part of the contract (§3).
struct MajorAxisRow {
  const char* expected;
  Vec3 direction;
  CubeFace face;
};

TEST(CubeExtremes, MajorAxisTiesGoXBeforeYBeforeZAndTheSignBitPicksTheFace) {
  const MajorAxisRow rows[] = {
      {"(+0, +0, +0): x first, +0 picks +X", Vec3(0.0, 0.0, 0.0), CubeFace::PosX},
      {"(-0, +0, +0): -0 picks -X", Vec3(-0.0, 0.0, 0.0), CubeFace::NegX},
      {"(+0, -0, -0): +X", Vec3(0.0, -0.0, -0.0), CubeFace::PosX},
      {"(1, 1, 1): +X", Vec3(1, 1, 1), CubeFace::PosX},
      {"(-1, 1, 1): -X", Vec3(-1, 1, 1), CubeFace::NegX},
      {"(-0, -1, 1): -Y (y before z)", Vec3(-0.0, -1, 1), CubeFace::NegY},
      {"(0, 1, -1): +Y", Vec3(0, 1, -1), CubeFace::PosY},
      {"(-0, -0, 1): +Z", Vec3(-0.0, -0.0, 1), CubeFace::PosZ},
      {"(+0, +0, -1): -Z", Vec3(0.0, 0.0, -1), CubeFace::NegZ},
      {"(5e-324, -5e-324, 5e-324): subnormal tie, +X (float: +0, -0, +0: +X)",
       Vec3(kDenormMin, -kDenormMin, kDenormMin), CubeFace::PosX},
      {"(-inf, inf, inf): infinite tie, -X", Vec3(-INFINITY, INFINITY, INFINITY), CubeFace::NegX},
  };
  for (const MajorAxisRow& row : rows) {
    EXPECT_EQ(majorAxisFace(row.direction), row.face) << row.expected << " [double]";
    EXPECT_EQ(majorAxisFace(Vec3T<float>(row.direction.cast<float>())), row.face) << row.expected << " [float]";
  }
}

// ---- limits of the options ----

TEST(ParamExtremes, NearlyParallelPlanesBelowTheLimitAreRefused) {
  struct Row {
    const char* expected;
    double sine;
    bool accepted;
  };
  const Row rows[] = {
      {"sine 1e-11: accepted", 1e-11, true},
      {"sine 2e-12: accepted", 2e-12, true},
      {"sine 1e-13: UsageError 'the planes are parallel'", 1e-13, false},
      {"sine 0 (the same plane twice): UsageError 'the planes are parallel'", 0.0, false},
  };
  for (const Row& row : rows)
    for (Precision precision : {Precision::Double, Precision::Float}) {
      SCOPED_TRACE(std::string(row.expected) + " [" + nameOf(precision) + "]");
      ProjectorOptions o;
      o.surface = kTwoPlane;
      o.planeU = Vec4(1, 0, 0, 0);
      o.planeV = Vec4(std::sqrt(1 - row.sine * row.sine), row.sine, 0, 0);
      o.arithmetic.precision = precision;
      std::vector<VertexUv> out;
      if (row.accepted) {
        Projector(o, Affine3::Identity()).mapVertices({Vec3(1, 2, 3)}, {}, out);
        EXPECT_EQ(out[0].state, CornerState::Ok);
        EXPECT_TRUE(out[0].uv.allFinite());
        continue;
      }
      try {
        Projector(o, Affine3::Identity()).mapVertices({Vec3(1, 2, 3)}, {}, out);
        ADD_FAILURE() << "accepted";
      } catch (const UsageError& e) {
        EXPECT_EQ(std::string(e.what()), "two-plane: the planes are parallel (the sine of their angle is below 1e-12)");
      }
    }
}

TEST(ParamExtremes, AnExplicitScaleWhoseReciprocalOverflowsIsAUsageError) {
  for (double scale : {kDenormMin, 1e-310}) {
    PlacementOptions placement;
    placement.fit = Fit::None;
    placement.frame = frameOf(Vec3::Zero(), scale);
    try {
      fitPlacement({Vec3(1, 0, 0)}, kSphere, placement);
      ADD_FAILURE() << "scale " << scale << " accepted: its frame is not finite";
    } catch (const UsageError& e) {
      EXPECT_EQ(std::string(e.what()), "--scale: expected a positive number whose reciprocal is finite") << scale;
    }
  }
  // The smallest normal scale still has a finite frame.
  PlacementOptions placement;
  placement.frame = frameOf(Vec3::Zero(), std::numeric_limits<double>::min());
  EXPECT_TRUE(fitPlacement({}, kSphere, placement).matrix().allFinite());
}

// ---- a unit mesh 1e8 from the object origin, fitted placement: the local origin keeps the digits ----

struct FarRow {
  const char* expected;
  SurfaceKind surface;
  RayKind ray;
};

// The largest difference from the long-double reference: u to the nearest period (a seam may round
// to the other side), v; u is skipped at poles (it is 0 by definition). States must agree.
template <class Out>
double worstDifference(const std::vector<Out>& got, const std::vector<ReferenceUv>& reference, bool wraps) {
  double worst = 0.0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].state, reference[i].state) << "vertex " << i;
    EXPECT_TRUE(got[i].uv.allFinite()) << "vertex " << i;
    if (got[i].state != reference[i].state || got[i].state == CornerState::Invalid) continue;
    double du = std::fabs(got[i].uv.x() - double(reference[i].uv.x()));
    if (wraps) du = std::min(du, 1.0 - du);
    if (got[i].state == CornerState::Pole) du = 0.0;
    worst = std::max({worst, du, std::fabs(got[i].uv.y() - double(reference[i].uv.y()))});
  }
  return worst;
}

TEST(ParamExtremes, AUnitMesh1e8AwayKeepsItsDigitsInTheLocalFrame) {
  const FarRow rows[] = {
      {"plane isn, bbox fit, 1e8 away: double within 1e-9 of the reference, float within 1e-6", kPlane, kIsn},
      {"cylinder isn, bbox fit, 1e8 away: double within 1e-9, float within 1e-6", kCylinder, kIsn},
      {"cylinder centroid, bbox fit, 1e8 away: double within 1e-9, float within 1e-6", kCylinder, kCentroid},
      {"sphere isn, bbox fit, 1e8 away: double within 1e-9, float within 1e-6", kSphere, kIsn},
      {"sphere centroid, bbox fit, 1e8 away: double within 1e-9, float within 1e-6", kSphere, kCentroid},
  };
  const Vec3 offset(1e8, -1e8, 1e8);
  for (const FarRow& row : rows) {
    Mesh mesh = row.surface == kPlane      ? meshes::planeGrid(8, 8, 1.0, 1.0)
                : row.surface == kCylinder ? meshes::cylinder(32, 4, 0.5, 1.0, false)
                                           : meshes::latLongSphere(32, 16, 0.5);
    for (Vec3& p : mesh.positions) p += offset;
    ProjectorOptions o;
    o.surface = row.surface;
    o.ray = row.ray;
    const Affine3 frame = fitPlacement(mesh.positions, row.surface, o.placement);
    std::vector<ReferenceUv> reference;
    mapVerticesReference(o, frame, mesh.positions, {}, reference);
    for (Precision precision : {Precision::Double, Precision::Float})
      for (MathMode math : {MathMode::Exact, MathMode::Fast}) {
        if (math == MathMode::Fast && !usesArctangent(row.surface)) continue;
        SCOPED_TRACE(std::string(row.expected) + " [" + nameOf(precision) + ", " + nameOf(math) + "]");
        o.arithmetic = {precision, math};
        std::vector<VertexUv> out;
        Projector(o, frame).mapVertices(mesh.positions, {}, out);
        EXPECT_LE(worstDifference(out, reference, usesArctangent(row.surface)),
                  precision == Precision::Double ? 1e-9 : 1e-6);
      }
  }
}

// ---- a random cloud against the long-double reference: the documented bounds ----

TEST(ParamExtremes, ARandomCloudStaysWithinTheDocumentedBoundsOfTheReference) {
  std::mt19937_64 random(6);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::vector<Vec3> cloud(10000);
  for (Vec3& p : cloud) p = Vec3(coordinate(random), coordinate(random), coordinate(random));
  for (SurfaceKind surface : {kCylinder, kSphere}) {
    ProjectorOptions o;
    o.surface = surface;
    std::vector<ReferenceUv> reference;
    mapVerticesReference(o, Affine3::Identity(), cloud, {}, reference);
    for (Precision precision : {Precision::Double, Precision::Float})
      for (MathMode math : {MathMode::Exact, MathMode::Fast}) {
        const double bound = precision == Precision::Double ? 1e-13 : 2e-6;
        SCOPED_TRACE(std::string(surface == kCylinder ? "cylinder" : "sphere") + " isn, 10^4 random points: within " +
                     (precision == Precision::Double ? "1e-13" : "2e-6") + " of the reference [" + nameOf(precision) +
                     ", " + nameOf(math) + "]");
        o.arithmetic = {precision, math};
        std::vector<VertexUv> out;
        Projector(o, Affine3::Identity()).mapVertices(cloud, {}, out);
        EXPECT_LE(worstDifference(out, reference, true), bound);
      }
  }
}

// ---- zero-length normals through project(): every surface, both ray O-mappings ----

TEST(ParamExtremes, ZeroLengthNormalsGiveInvalidCornersThroughProject) {
  Mesh mesh;  // a triangle of zero area on the unit sphere and cylinder: its vertex normals are zero
  mesh.positions = {Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0)};
  mesh.triangles = {{0, 1, 2}};
  for (SurfaceKind surface : {kPlane, kTwoPlane, kCylinder, kSphere, kCube})
    for (RayKind ray : {kNormal, kReflection})
      for (Precision precision : {Precision::Double, Precision::Float}) {
        SCOPED_TRACE(std::string("zero-length normals: 3 Invalid corners (0, 0), face flagged [surface ") +
                     std::to_string(int(surface)) + ", ray " + std::to_string(int(ray)) + ", " + nameOf(precision) +
                     "]");
        ProjectorOptions o;
        o.surface = surface;
        o.ray = ray;
        o.eye = kEye;
        o.placement.fit = Fit::None;
        o.arithmetic.precision = precision;
        const Projection p = project(mesh, o);
        for (std::size_t i = 0; i < 3; ++i) {
          EXPECT_TRUE(p.uv.cornerInvalid[i]);
          EXPECT_EQ(p.uv.uv[i], Vec2::Zero());
        }
        EXPECT_TRUE(p.uv.faceHas(0, kFaceInvalid));
        EXPECT_EQ(p.summary.invalidVertices, 3u);
      }
}

// ---- issue 23: every fit on any finite input ----
// The fits work on the mesh moved to a unit box by a power of two (placement.h, UnitBox), so a
// mesh times 2^n has the same frame after it and the same UVs. The sample meshes are snapped to
// multiples of 2^-32 first: then every coordinate times 2^n (|n| <= 1000) is exact, subnormals
// included, and the scaled mesh is the same mesh, not a rounded one.

constexpr Fit kEveryFit[] = {Fit::None, Fit::BBox, Fit::Center, Fit::Pca, Fit::Obb};
constexpr Fit kScaleFreeFits[] = {Fit::BBox, Fit::Pca, Fit::Obb};  // none and center keep object units
constexpr SurfaceKind kEverySurface[] = {kPlane, kTwoPlane, kCylinder, kSphere, kCube};

const char* nameOf(Fit f) {
  return f == Fit::None ? "none" : f == Fit::BBox ? "bbox" : f == Fit::Center ? "center" : f == Fit::Pca ? "pca" : "obb";
}
const char* nameOf(SurfaceKind s) {
  return s == kPlane ? "plane" : s == kTwoPlane ? "two-plane" : s == kCylinder ? "cylinder" : s == kSphere ? "sphere" : "cube";
}

Mesh snapped(Mesh mesh) {
  for (Vec3& p : mesh.positions)
    for (int a = 0; a < 3; ++a) p[a] = std::ldexp(std::nearbyint(std::ldexp(p[a], 32)), -32);
  return mesh;
}

// The mesh times 2^exponent, then moved by `offset` (rounded where the offset is large).
Mesh placed(Mesh mesh, int exponent, const Vec3& offset = Vec3::Zero()) {
  for (Vec3& p : mesh.positions)
    for (int a = 0; a < 3; ++a) p[a] = std::ldexp(p[a], exponent) + offset[a];
  return mesh;
}

using test::NamedMesh;

const std::vector<NamedMesh>& sampleMeshes() {
  static const std::vector<NamedMesh> meshes = {
      {"torusKnot(2, 3)", snapped(meshes::torusKnot(2, 3, 48, 8))},
      {"bone", snapped(meshes::bone(12, 8))},
      {"bumpyBlob(1)", snapped(meshes::bumpyBlob(1))},
      {"scannedPatch(2)", snapped(meshes::scannedPatch(2))},
  };
  return meshes;
}

// The contract of every placement: finite, and its rows (the local axes in object space times
// their scales) orthogonal with finite, non-zero lengths whose reciprocals (the scales in object
// units) are finite too. Two-plane's identity passes.
void expectValidPlacement(const Affine3& frame) {
  ASSERT_TRUE(frame.matrix().allFinite()) << frame.matrix();
  Mat3 axes;
  for (int r = 0; r < 3; ++r) {
    const double length = frame.linear().row(r).stableNorm();  // norm() squares 1e300 to inf
    ASSERT_TRUE(length > 0.0 && std::isfinite(1.0 / length)) << "row " << r << " of\n" << frame.matrix();
    axes.row(r) = frame.linear().row(r) / length;
  }
  EXPECT_LE((axes * axes.transpose() - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-12) << frame.matrix();
  EXPECT_GT(axes.determinant(), 0.0) << "left-handed:\n" << frame.matrix();
}

// The largest difference between two mappings of the same mesh, u to the nearest period on the
// wrapping surfaces; corners must agree in validity. UVs must be finite.
double worstUvDifference(const Projection& got, const Projection& want, bool wraps) {
  EXPECT_EQ(got.uv.uv.size(), want.uv.uv.size());
  double worst = 0.0;
  for (std::size_t c = 0; c < std::min(got.uv.uv.size(), want.uv.uv.size()); ++c) {
    EXPECT_TRUE(got.uv.uv[c].allFinite()) << "corner " << c;
    EXPECT_EQ(got.uv.cornerInvalid[c] != 0, want.uv.cornerInvalid[c] != 0) << "corner " << c;
    double du = std::fabs(got.uv.uv[c].x() - want.uv.uv[c].x());
    if (wraps) du = std::fabs(du - std::nearbyint(du));
    worst = std::max({worst, du, std::fabs(got.uv.uv[c].y() - want.uv.uv[c].y())});
  }
  return worst;
}

TEST(FitExtremes, EveryFitIsScaleInvariantFrom1eMinus300To1e300) {
  // 2^-997 ~ 1e-300, 2^-498 ~ 1e-150, 1, 2^498 ~ 1e150, 2^997 ~ 1e300: powers of two, so each
  // scaled mesh is exactly the sample mesh (1e300 itself would round it, and the oriented box's
  // randomized search may then take another path to another, equally small box).
  const int exponents[] = {-997, -498, 0, 498, 997};
  // Tolerance: the frame is the scale-1 frame times 2^-n exactly (checked first), so the local
  // coordinates differ only in how LocalFrameT rounds them (its inverse is taken at unit scale, so
  // the same path at every scale): a few ulps of coordinates of order 1, 1e-15. The
  // arctangents amplify that by 1/(2 pi rho) for a vertex at distance rho from the axis, above
  // the pole limit 1e-6: at most 2e-10, so 1e-9.
  constexpr double kTolerance = 1e-9;
  double measured = 0.0;
  for (const NamedMesh& sample : sampleMeshes())
    for (Fit fit : kScaleFreeFits)
      for (SurfaceKind surface : {kPlane, kCylinder, kSphere, kCube}) {
        ProjectorOptions o;
        o.surface = surface;
        o.placement.fit = fit;
        const Projection atOne = project(sample.mesh, o);
        for (int exponent : exponents) {
          SCOPED_TRACE(std::string(sample.name) + " times 2^" + std::to_string(exponent) + ", --fit " + nameOf(fit) +
                       ", " + nameOf(surface) + " isn: the same frame and UVs as at scale 1");
          const Mesh mesh = placed(sample.mesh, exponent);
          const Affine3 frame = fitPlacement(mesh.positions, surface, o.placement);
          expectValidPlacement(frame);
          EXPECT_EQ(frame.translation(), atOne.localFromObject.translation());
          const Mat3 back = frame.linear().unaryExpr([&](double x) { return std::ldexp(x, exponent); });
          EXPECT_LE((back - atOne.localFromObject.linear()).cwiseAbs().maxCoeff(),
                    1e-15 * atOne.localFromObject.linear().cwiseAbs().maxCoeff());
          // Normal and reflection rays need the frame's inverse (the normal matrix), which at 2^+-498
          // and beyond over- or underflowed until it was taken at unit scale; the eye scales with the mesh.
          for (RayKind ray : {kIsn, kCentroid, kNormal, kReflection}) {
            o.ray = ray;
            o.eye = ray == kReflection ? std::optional<Vec3>(Vec3(0.5, -3.0, 2.0)) : std::nullopt;
            const Projection reference = ray == kIsn ? atOne : project(sample.mesh, o);
            if (o.eye) o.eye = o.eye->unaryExpr([&](double x) { return std::ldexp(x, exponent); });
            const Projection p = project(mesh, o);
            const double worst = worstUvDifference(p, reference, usesArctangent(surface));
            EXPECT_LE(worst, kTolerance) << "ray " << int(ray);
            measured = std::max(measured, worst);
          }
          o.ray = kIsn;
          o.eye.reset();
        }
      }
  std::printf("scale invariance: largest UV difference %.3g\n", measured);
}

TEST(FitExtremes, AMeshFarFromTheOriginFitsAsAtTheOrigin) {
  struct Offset {
    const char* expected;
    int exponent;  // the mesh's scale, 2^exponent
    Vec3 offset;
    double tolerance;
  };
  // The offset mesh p = 2^n m + o is rounded; the reference is that rounded mesh moved back,
  // 2^-n (p - o), exact (Sterbenz): the same mesh at scale 1. The fit sees identical unit
  // positions (p - corner is exact too), so only the frame's translation differs: about
  // r = |o| / 2^n times the mesh's local size, rounded to double (an Affine3 holds no more), an
  // error of r 2^-53 in the local coordinates, amplified by the arctangents (1/(2 pi rho); these
  // meshes' vertices keep it below 1000): tolerance 1000 r 2^-53. Measured: 1.6e-5 at r = 1e10,
  // 2.6e-11 at r = 1e5, 2.5e-8 at r = 1e8.
  const Offset offsets[] = {
      {"centred at 1e300, extent 1e290 (2^963)", 963, Vec3(1e300, -1e300, 1e300), 1e3 * 1e10 * 0x1p-53},
      {"centred at -1e150, extent 1e145 (2^482)", 482, Vec3(-1e150, 3e149, 0.0), 1e3 * 1e5 * 0x1p-53},
      {"centred at 1e-290, extent 1e-300 (2^-997)", -997, Vec3(1e-290, 1e-290, -1e-290), 1e3 * 1e10 * 0x1p-53},
      {"centred at 1e8, extent 1", 0, Vec3(1e8, 1e8, 1e8), 1e3 * 1e8 * 0x1p-53},
  };
  double measured[std::size(offsets)] = {};
  for (const Offset& row : offsets)
    for (const NamedMesh& sample : sampleMeshes())
      for (Fit fit : kScaleFreeFits)
        for (SurfaceKind surface : {kPlane, kCylinder, kSphere, kCube}) {
          SCOPED_TRACE(std::string(sample.name) + " " + row.expected + ", --fit " + nameOf(fit) + ", " +
                       nameOf(surface) + ": the UVs of the mesh at the origin");
          const Mesh far = placed(sample.mesh, row.exponent, row.offset);
          Mesh reference = far;
          for (Vec3& p : reference.positions)
            for (int a = 0; a < 3; ++a) p[a] = std::ldexp(p[a] - row.offset[a], -row.exponent);
          ProjectorOptions o;
          o.surface = surface;
          o.placement.fit = fit;
          const Projection p = project(far, o);
          expectValidPlacement(p.localFromObject);
          const double worst = worstUvDifference(p, project(reference, o), usesArctangent(surface));
          EXPECT_LE(worst, row.tolerance);
          measured[&row - offsets] = std::max(measured[&row - offsets], worst);
        }
  for (const Offset& row : offsets) std::printf("%s: largest UV difference %.3g\n", row.expected, measured[&row - offsets]);
}

// Zero extent along one, two or three object axes, at any scale and far from the origin: every
// fit, every surface gives a valid frame and finite UVs; a flat axis is kept exactly.
TEST(FitExtremes, FlatLinearAndSinglePointMeshesGetAValidFrameAtEveryScale) {
  const Mesh grid = snapped(meshes::planeGrid(6, 4, 2.0, 1.0));  // z = 0
  Mesh line = grid;                                               // along x: y = z = 0
  for (Vec3& p : line.positions) p.y() = 0.0;
  Mesh point = grid;  // every vertex at (0.5, -0.25, 2)
  for (Vec3& p : point.positions) p = Vec3(0.5, -0.25, 2.0);
  Mesh slanted = grid;  // a line along (1, 1, 1): no object axis is flat
  for (Vec3& p : slanted.positions) p = Vec3::Constant(p.x());
  const NamedMesh shapes[] = {{"flat sheet", grid}, {"line", line}, {"single point", point}, {"slanted line", slanted}};
  const int exponents[] = {-997, -498, 0, 498, 997};
  const Vec3 offsets[] = {Vec3::Zero(), Vec3(1e300, -1e300, 1e300), Vec3(0.0, 0.0, -1e300)};
  for (const NamedMesh& shape : shapes)
    for (int exponent : exponents)
      for (const Vec3& offset : offsets)
        for (Fit fit : kEveryFit)
          for (SurfaceKind surface : kEverySurface)
            for (RayKind ray : {kIsn, kCentroid, kNormal}) {
              SCOPED_TRACE(std::string(shape.name) + " times 2^" + std::to_string(exponent) + " at (" +
                           std::to_string(offset.x()) + ", ...), --fit " + nameOf(fit) + ", " + nameOf(surface) +
                           ", ray " + std::to_string(int(ray)) + ": a valid frame, finite UVs");
              const Mesh mesh = placed(shape.mesh, exponent, offset);
              ProjectorOptions o;
              o.surface = surface;
              o.ray = ray;
              o.placement.fit = fit;
              const Projection p = project(mesh, o);
              expectValidPlacement(p.localFromObject);
              for (const Vec2& uv : p.uv.uv) ASSERT_TRUE(uv.allFinite());
              // A sheet's normal is its flat object axis, exactly, in every fitted frame (unless
              // the offset rounded the sheet to a line or a point).
              const std::array<bool, 3> sheet{false, false, true};
              if (toUnitBox(mesh.positions).flat == sheet && (fit == Fit::Pca || fit == Fit::Obb) &&
                  surface == kPlane) {
                const Vec3 z = p.localFromObject.linear().row(2);
                EXPECT_EQ(z.x(), 0.0);
                EXPECT_EQ(z.y(), 0.0);
              }
            }
}

TEST(FitExtremes, TheUnitBoxIsExactAndFlatAxesAreFound) {
  // Hand-computed: box [1e300, 1e300 + 3 2^944] x {-7} x [0, 2^-1000]; half extent 1.5 2^944, so
  // the unit is 2^945 and the corner (1e300, -7, 0).
  const double ulp = std::ldexp(1.0, 944);  // the spacing of doubles at 1e300
  const UnitBox box = toUnitBox({Vec3(1e300, -7, 0), Vec3(1e300 + 3 * ulp, -7, 0x1p-1000), Vec3(1e300 + ulp, -7, 0)});
  EXPECT_EQ(box.exponent, 945);
  EXPECT_EQ(box.corner, Vec3(1e300, -7, 0));
  EXPECT_EQ(box.unit[1], Vec3(1.5, 0, 0));  // 2^-1000 / 2^945 underflows to 0
  EXPECT_EQ(box.unit[2], Vec3(0.5, 0, 0));
  EXPECT_EQ(box.flat, (std::array<bool, 3>{false, true, false}));
  // The largest doubles: hi - lo overflows, the halves do not.
  const UnitBox wide = toUnitBox({Vec3(-kMax, 0, 0), Vec3(kMax, 0, 0)});
  EXPECT_EQ(wide.exponent, 1024);
  EXPECT_EQ(wide.unit[1], Vec3(std::ldexp(kMax, -1023), 0, 0));  // (kMax/2 + kMax/2) 2^-1023
  EXPECT_EQ(wide.flat, (std::array<bool, 3>{false, true, true}));
  // One point: unit 1.
  const UnitBox single = toUnitBox({Vec3(kDenormMin, 0, 0)});
  EXPECT_EQ(single.exponent, 0);
  EXPECT_EQ(single.unit[0], Vec3::Zero());
}

TEST(FitExtremes, CoordinatesNear1e103DoNotTrapInTheOrientedBox) {
  // Issue 23: 1e103 cubed overflows in CGAL's predicates, which died of SIGFPE (1e102 worked).
  for (double size : {1e102, 1e103, 1e200, 1e300, kMax / 4}) {
    SCOPED_TRACE(size);
    Mesh mesh = meshes::torusKnot(2, 3, 48, 8);
    for (Vec3& p : mesh.positions) p *= size / 4;
    for (Fit fit : {Fit::Pca, Fit::Obb}) {
      const Mat3 axes = fit == Fit::Pca ? principalAxes(mesh.positions) : orientedBoxAxes(mesh.positions);
      ASSERT_TRUE(axes.allFinite());
      EXPECT_LE((axes * axes.transpose() - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-12);
    }
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param
