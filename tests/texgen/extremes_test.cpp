// Issue 6, numerical extremes of texgen: one row per case, each row stating the documented
// behaviour that its failure messages repeat (docs/extremes.md lists every row). Tiny planes
// (OBJECT_LINEAR and EYE_LINEAR), modelviews with a condition number of 1e12, SPHERE_MAP at and
// near its singular reflection; every row in binary64 and binary32 (TexgenOptions::precision).
// A result is finite, or the documented status: a corner Invalid (written as (0, 0, 0, 0)), a
// sphere-map singular corner (s = t = 1/2, flagged), or a UsageError.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/gl_matrices.h"
#include "texgen/texgen.h"
#include "texgen/texgen_fixtures.h"

namespace uvtk::texgen {
namespace {
namespace UVTK_TEST_FILE {

using LongVec4 = Eigen::Matrix<long double, 4, 1>;
using LongMat4 = Eigen::Matrix<long double, 4, 4>;

constexpr double kDoubleU = 0x1p-53, kFloatU = 0x1p-24;  // unit roundoffs
constexpr double kDenormMin = 4.9406564584124654e-324;

// What one precision gives: (s, t, r, q) within `tolerance` of `value` (absolute, per component),
// or a sphere-map singular corner, or an Invalid corner.
struct Outcome {
  Vec4 value = Vec4::Zero();
  double tolerance = 0.0;
  bool singular = false;
  bool invalid = false;
};

struct TexgenRow {
  std::string expected;
  TexgenOptions options;
  Vec3 position, normal;
  Outcome inDouble, inFloat;
};

TexgenRow row(const std::string& expected, const TexgenOptions& options, const Vec3& position, const Vec3& normal,
              const Outcome& inDouble, const Outcome& inFloat) {
  return {expected, options, position, normal, inDouble, inFloat};
}

TexgenOptions sOnly(TexgenMode mode, const Vec4& plane) {
  TexgenOptions o;
  o.coordinates[0] = {mode, plane};
  return o;
}

TexgenOptions sphereMap() {
  TexgenOptions o;
  o.coordinates[0].mode = o.coordinates[1].mode = TexgenMode::SphereMap;
  return o;
}

// (s, 0, 0, 1): s generated, the other coordinates off (GL's current coordinate).
Outcome sWithin(double s, double tolerance) { return {Vec4(s, 0, 0, 1), tolerance}; }

// An OBJECT_LINEAR row: s = plane . (x, 1); tolerances `ulps` unit roundoffs of sum |p_i x_i|.
TexgenRow objectLinear(const std::string& expected, const Vec4& plane, const Vec3& x, double ulps) {
  const LongVec4 p = plane.cast<long double>(), xh(x.x(), x.y(), x.z(), 1.0L);
  const double exact = double(p.dot(xh)), magnitude = double(p.cwiseAbs().dot(xh.cwiseAbs()));
  return {expected,      sOnly(TexgenMode::ObjectLinear, plane),      x,
          Vec3::UnitZ(), sWithin(exact, ulps * kDoubleU * magnitude), sWithin(exact, ulps * kFloatU * magnitude)};
}

// An EYE_LINEAR row: s = (p M_plane^-1) . (M_draw x), computed in long double (the inverse by LU in
// 64-bit precision, 2^11 times finer than double's); tolerances relative to the terms' magnitude
// sum |p'_i e_i|: `doubleTolerance` of it in double, that plus 8 float unit roundoffs in float.
TexgenRow eyeLinear(const std::string& expected, const Vec4& plane, const Mat4& atPlanes, const Mat4& atDraw,
                    const Vec3& x, double doubleTolerance) {
  TexgenOptions o = sOnly(TexgenMode::EyeLinear, plane);
  o.modelviewAtPlanes = atPlanes;
  o.modelviewAtDraw = atDraw;
  const Eigen::Matrix<long double, 1, 4> p =
      plane.cast<long double>().transpose() * LongMat4(atPlanes.cast<long double>()).inverse();
  const LongVec4 e = atDraw.cast<long double>() * LongVec4(x.x(), x.y(), x.z(), 1.0L);
  const double exact = double(p.dot(e.transpose())), magnitude = double(p.cwiseAbs().dot(e.cwiseAbs().transpose()));
  return {expected,
          o,
          x,
          Vec3::UnitZ(),
          sWithin(exact, doubleTolerance * magnitude),
          sWithin(exact, (doubleTolerance + 8 * kFloatU) * magnitude)};
}

// [[1, 1], [1, 1 + 2^-38]] in the upper left, 1 elsewhere on the diagonal: condition number
// 1.1e12, inverse exactly 2^38 [[1 + 2^-38, -1], [-1, 1]].
Mat4 exactIllConditioned() {
  Mat4 m = Mat4::Identity();
  m(0, 1) = m(1, 0) = 1.0;
  m(1, 1) = 1.0 + 0x1p-38;
  return m;
}

// Condition number 1e12 with no exact structure (the existing Extremes test's matrix).
Mat4 rotatedIllConditioned() { return rotationX(0.7) * Vec4(1e6, 1.0, 1e-6, 1.0).asDiagonal() * rotationX(-0.3); }

const std::vector<TexgenRow>& rows() {
  static const std::vector<TexgenRow> table = [] {
    const Outcome half{Vec4(0.5, 0.5, 0, 1), 0.0, true};  // the singular sphere map: 1/2, flagged
    const Vec4 tinyPlane = 1e-30 * Vec4(1, -2, 3, 0.5);
    const Mat4 view = lookAt(Vec3(1, 2, 3), Vec3::Zero(), Vec3::UnitY());
    const double rimZ = 1e-9;  // a normal 1e-9 off the singular one
    std::vector<TexgenRow> t = {
        // ---- planes of 1e-30: finite; float underflow documented ----
        objectLinear("OBJECT_LINEAR, plane 1e-30 (1, -2, 3, 0.5) at (1, 2, 3): s = 6.5e-30 within 4 u of "
                     "sum |p_i x_i| (float: 1e-30 is a normal float, same bound in float's u)",
                     tinyPlane, Vec3(1, 2, 3), 4),
        row("OBJECT_LINEAR, plane 1e-30 x at x = 3: s = 3e-30 exactly as GL's formula rounds it (the correctly "
            "rounded product); float within an ulp",
            sOnly(TexgenMode::ObjectLinear, Vec4(1e-30, 0, 0, 0)), Vec3(3, 0, 0), Vec3::UnitZ(),
            sWithin(1e-30 * 3.0, 0.0), sWithin(3e-30, kFloatU * 3e-30)),
        row("OBJECT_LINEAR, plane 1e-30 x at x = 1e-20: double s = 1e-50 (the rounded product); float: 1e-50 "
            "underflows below float's subnormals, s = +0 exactly",
            sOnly(TexgenMode::ObjectLinear, Vec4(1e-30, 0, 0, 0)), Vec3(1e-20, 0, 0), Vec3::UnitZ(),
            sWithin(1e-30 * 1e-20, 0.0), sWithin(0.0, 0.0)),
        row("OBJECT_LINEAR, plane 1e-50 x: float rounds the plane to 0 when prepared (finite: no UsageError), s = 0; "
            "double s = 2e-50",
            sOnly(TexgenMode::ObjectLinear, Vec4(1e-50, 0, 0, 0)), Vec3(2, 0, 0), Vec3::UnitZ(),
            sWithin(1e-50 * 2.0, 0.0), sWithin(0.0, 0.0)),
        row("OBJECT_LINEAR, plane 1e-40 x at x = 1: double exact; float keeps 1e-40 as a subnormal, s within 1e-5 "
            "relative (subnormal precision)",
            sOnly(TexgenMode::ObjectLinear, Vec4(1e-40, 0, 0, 0)), Vec3(1, 0, 0), Vec3::UnitZ(), sWithin(1e-40, 0.0),
            sWithin(1e-40, 1e-45)),
        row("OBJECT_LINEAR, plane 1e-30 x at the subnormal x = 5e-324: the product underflows, s = +0 in both",
            sOnly(TexgenMode::ObjectLinear, Vec4(1e-30, 0, 0, 0)), Vec3(kDenormMin, 0, 0), Vec3::UnitZ(),
            sWithin(0.0, 0.0), sWithin(0.0, 0.0)),
        eyeLinear("EYE_LINEAR, plane 1e-30 (1, -2, 3, 0.5) under gluLookAt((1, 2, 3), 0, +y): finite, within "
                  "16 u of sum |p'_i e_i| of the long-double value",
                  tinyPlane, view, view, Vec3(0.3, -0.7, 0.2), 16 * kDoubleU),

        // ---- modelviews of condition number 1e12: accepted, close to the exact value ----
        eyeLinear("EYE_LINEAR, M_plane of condition 1.1e12 with an exact inverse (entries 2^38), at (1, 0, 0): "
                  "accepted; s = 2^38 + 1 within 1e-10 sum |p'_i e_i| (float: + 8 u_f)",
                  Vec4(1, 0, 0, 0), exactIllConditioned(), Mat4::Identity(), Vec3(1, 0, 0), 1e-10),
        eyeLinear("EYE_LINEAR, the same M_plane at (1, 1, 0): the 2^38 terms cancel to s = 1, within 1e-10 "
                  "sum |p'_i e_i| (float: + 8 u_f, an absolute error up to 3e4)",
                  Vec4(1, 0, 0, 0), exactIllConditioned(), Mat4::Identity(), Vec3(1, 1, 0), 1e-10),
        eyeLinear("EYE_LINEAR, M_plane = Rx(0.7) diag(1e6, 1, 1e-6) Rx(-0.3) (condition 1e12), M_draw = I: "
                  "accepted; within 1e-10 sum |p'_i e_i| of the long-double inverse (float: + 8 u_f)",
                  Vec4(1, -2, 3, 0.5), rotatedIllConditioned(), Mat4::Identity(), Vec3(-2, 5, 1), 1e-10),
        eyeLinear("EYE_LINEAR, M_plane = M_draw = that matrix: equals OBJECT_LINEAR p.x = -8.5 within 1e-10 "
                  "sum |p'_i e_i| (float: + 8 u_f)",
                  Vec4(1, -2, 3, 0.5), rotatedIllConditioned(), rotatedIllConditioned(), Vec3(-2, 5, 1), 1e-10),

        // ---- SPHERE_MAP at and near the singular reflection r = (0, 0, -1) ----
        row("SPHERE_MAP, vertex on the view axis, normal (1, 0, 0): r = (0, 0, -1), m = 0: s = t = 1/2, flagged "
            "singular",
            sphereMap(), Vec3(0, 0, -5), Vec3(1, 0, 0), half, half),
        row("SPHERE_MAP, zero normal on the view axis: r = u = (0, 0, -1): singular, s = t = 1/2, flagged", sphereMap(),
            Vec3(0, 0, -5), Vec3::Zero(), half, half),
        row("SPHERE_MAP, normal 1e-9 off the singular one: rz + 1 rounds to 0, m = 4e-9: s = 1 (the rim), t = 1/2, "
            "finite, not flagged",
            sphereMap(), Vec3(0, 0, -5), Vec3(1, 0, rimZ).normalized(), {Vec4(1, 0.5, 0, 1), 1e-12},
            {Vec4(1, 0.5, 0, 1), 1e-6}),
        row("SPHERE_MAP, vertex at the eye: u = 0 (as Mesa), r = 0, m = 2: s = t = 1/2, not flagged", sphereMap(),
            Vec3::Zero(), Vec3(0, 0, 1), {Vec4(0.5, 0.5, 0, 1)}, {Vec4(0.5, 0.5, 0, 1)}),
        row("SPHERE_MAP, vertex at (0, 0, -1e300): u scaled before normalising, singular 1/2; float: the vertex "
            "overflows (0 inf = NaN): Invalid, not singular",
            sphereMap(), Vec3(0, 0, -1e300), Vec3(1, 0, 0), half, {Vec4::Zero(), 0.0, false, true}),
    };
    return t;
  }();
  return table;
}

const char* nameOf(Precision p) { return p == Precision::Double ? "double" : "float"; }

class TexgenExtremes : public testing::TestWithParam<std::size_t> {};

TEST_P(TexgenExtremes, FiniteOrTheDocumentedStatus) {
  const TexgenRow& row = rows()[GetParam()];
  Mesh mesh;  // three corners at the vertex, with the row's normal as the file's
  mesh.positions = {row.position, row.position, row.position};
  mesh.triangles = {{0, 1, 2}};
  mesh.normals = {row.normal};
  mesh.cornerNormals = {{0, 0, 0}};
  for (Precision precision : {Precision::Double, Precision::Float}) {
    SCOPED_TRACE(row.expected + " [" + nameOf(precision) + "]");
    const Outcome& want = precision == Precision::Double ? row.inDouble : row.inFloat;
    TexgenOptions o = row.options;
    o.precision = precision;
    const TexgenResult r = generateTexcoords(mesh, o);
    EXPECT_EQ(r.invalidCorners, want.invalid ? 3u : 0u);
    EXPECT_EQ(r.sphereMapSingular, want.singular ? 3u : 0u);
    EXPECT_EQ(r.uv.faceHas(0, kFaceInvalid), want.invalid);
    EXPECT_EQ(r.uv.faceHas(0, kFaceSphereMapSingular), want.singular);
    for (int k = 0; k < 3; ++k) {
      const Vec4 g(r.uv.uv[k].x(), r.uv.uv[k].y(), r.uv.w[k], r.q[k]);
      ASSERT_TRUE(g.allFinite()) << "corner " << k;
      EXPECT_EQ(r.uv.cornerInvalid[k] != 0, want.invalid) << "corner " << k;
      for (int i = 0; i < 4; ++i)
        EXPECT_LE(std::fabs(g[i] - want.value[i]), want.tolerance)
            << "component " << i << " of corner " << k << ": " << g[i] << " instead of " << want.value[i];
    }
    // The per-point evaluation (the renderer's per-pixel path) gives the same, or no value.
    bool singular = false;
    const Vec4 at = texgenAt(row.position, row.normal, o, &singular);
    EXPECT_EQ(singular, want.singular);
    if (want.invalid) {
      EXPECT_FALSE(at.allFinite()) << "texgenAt: a non-finite value marks 'no value'";
    } else {
      EXPECT_EQ(at, Vec4(r.uv.uv[0].x(), r.uv.uv[0].y(), r.uv.w[0], r.q[0]));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Rows, TexgenExtremes, testing::Range<std::size_t>(0, rows().size()));

TEST(TexgenExtremes, TheIllConditionedMatricesHaveConditionNumber1e12) {
  for (const Mat4& m : {exactIllConditioned(), rotatedIllConditioned()}) {
    const Eigen::JacobiSVD<Mat4> svd(m);
    const double condition = svd.singularValues()[0] / svd.singularValues()[3];
    EXPECT_GT(condition, 0.9e12);
    EXPECT_LT(condition, 1.2e12);
  }
}

// Where the inverse stops existing: rank below 4 at Eigen's threshold (4 eps times the largest
// pivot). Condition 1.1e12 passes (the rows above); 4.5e15 and rank 3 are UsageErrors.
TEST(TexgenExtremes, AModelviewSingularToWorkingPrecisionIsAUsageError) {
  struct Row {
    const char* expected;
    Mat4 atPlanes;
  };
  Mat4 nearlySingular = exactIllConditioned();
  nearlySingular(1, 1) = 1.0 + 0x1p-52;
  const Row table[] = {
      {"M_plane [[1, 1], [1, 1 + 2^-52]] (condition 4.5e15): UsageError 'is singular'", nearlySingular},
      {"M_plane diag(1, 1, 0, 1) (rank 3): UsageError 'is singular'", Vec4(1, 1, 0, 1).asDiagonal()},
  };
  for (const Row& row : table)
    for (Precision precision : {Precision::Double, Precision::Float}) {
      TexgenOptions o = sOnly(TexgenMode::EyeLinear, Vec4(1, 0, 0, 0));
      o.modelviewAtPlanes = row.atPlanes;
      o.precision = precision;
      try {
        texgenAt(Vec3(1, 2, 3), Vec3::UnitZ(), o);
        ADD_FAILURE() << row.expected << " [" << nameOf(precision) << "]: accepted";
      } catch (const UsageError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "texgen: the modelview at the planes is singular, so its inverse does not exist")
            << row.expected << " [" << nameOf(precision) << "]";
      }
    }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::texgen
