// Issue 6, numerical extremes of the distortion measures: slivers with angles of 1e-8, in 3D, in
// UV or both, at unit, tiny and huge scales. One row per case, each row stating the documented
// behaviour that its failure messages repeat (docs/extremes.md lists every row): a status ok (or
// flipped) with finite measures, or zero_area_3d / zero_area_uv with measures 0; never NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "analysis/distortion.h"
#include "analysis/judgement.h"
#include "analysis/layout.h"
#include "meshes/generators.h"
#include "param/projector.h"

namespace uvtk::analysis {
namespace {
namespace UVTK_TEST_FILE {

constexpr double kAngle = 1e-8;
constexpr double kAny = NAN;  // a measure whose value the row does not fix (still finite)

// Expected measures of the row's first face, within `tolerance` relative (0 exactly).
struct Expected {
  FaceStatus status;
  double sigmaMax = kAny, sigmaMin = kAny, l2 = kAny, linf = kAny, angle = kAny, areaRatio = kAny;
  double tolerance = 1e-6;
};

struct SliverRow {
  std::string expected;
  std::vector<Vec3> positions;  // 3 per face
  std::vector<Vec2> uvs;        // 3 per face
  Expected first;
};

SliverRow row(const std::string& expected, const std::vector<Vec3>& positions, const std::vector<Vec2>& uvs,
              const Expected& first) {
  return {expected, positions, uvs, first};
}

std::vector<Vec3> scaled(std::vector<Vec3> points, double s) {
  for (Vec3& p : points) p *= s;
  return points;
}

std::vector<Vec2> planar(const std::vector<Vec3>& points) {
  std::vector<Vec2> uvs;
  for (const Vec3& p : points) uvs.push_back(p.head<2>());
  return uvs;
}

const std::vector<SliverRow>& rows() {
  static const std::vector<SliverRow> table = [] {
    const double c = std::cos(kAngle), s = std::sin(kAngle);
    // A needle: the angle 1e-8 at the first corner between edges of length 1.
    const std::vector<Vec3> needle = {{0, 0, 0}, {1, 0, 0}, {c, s, 0}};
    // A cap: one angle pi - 2e-8, two of 1e-8.
    const std::vector<Vec3> cap = {{0, 0, 0}, {1, 0, 0}, {0.5, 0.5 * std::tan(kAngle), 0}};
    const std::vector<Vec3> right = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<Vec2> rightUv = {{0, 0}, {1, 0}, {0, 1}};
    std::vector<SliverRow> t = {
        row("needle (angle 1e-8) mapped isometrically: ok, s1 = s2 = L2 = Linf = angle = area ratio = 1 within 1e-6",
            needle, planar(needle), {FaceStatus::Ok, 1, 1, 1, 1, 1, 1}),
        row("cap (angle pi - 2e-8) mapped isometrically: ok, every measure 1 within 1e-6", cap, planar(cap),
            {FaceStatus::Ok, 1, 1, 1, 1, 1, 1}),
        row("needle in 3D onto the right UV triangle: ok, s1 = 1.414e8, s2 = 0.7071, L2 = 1, Linf = 1.414, "
            "angle 2e8, area ratio 1e8",
            needle, rightUv,
            {FaceStatus::Ok, std::sqrt(2.0) / s, std::sqrt(0.5), 1.0, std::sqrt(2.0), 2.0 / s, 1.0 / s}),
        row("right triangle onto a UV needle: ok, s1 = 1.414, s2 = 7.07e-9, L2 = 1e8, Linf = 1.414e8, angle 2e8, "
            "area ratio 1e-8",
            right, planar(needle),
            {FaceStatus::Ok, std::sqrt(2.0), s / std::sqrt(2.0), 1.0 / s, std::sqrt(2.0) / s, 2.0 / s, s}),
        row("needle mapped onto itself turned 90 degrees (a rotation): ok, every measure 1 within 1e-6", needle,
            {{0, 0}, {0, 1}, {-s, c}}, {FaceStatus::Ok, 1, 1, 1, 1, 1, 1}),
        row("needle collapsed to a segment in UV: zero_area_uv, measures 0", needle, {{0, 0}, {1, 0}, {2, 0}},
            {FaceStatus::ZeroAreaUv, 0, 0, 0, 0, 0, 0}),
        row("needle whose UV is a point: zero_area_uv, measures 0", needle, {{0.5, 0.5}, {0.5, 0.5}, {0.5, 0.5}},
            {FaceStatus::ZeroAreaUv, 0, 0, 0, 0, 0, 0}),
        row("needle of angle 1e-16 (area below 1e-14 of the longest edge squared): zero_area_3d, measures 0",
            {{0, 0, 0}, {1, 0, 0}, {1, 1e-16, 0}}, rightUv, {FaceStatus::ZeroArea3d, 0, 0, 0, 0, 0, 0}),
        row("needle with edges of 1e-150 (area 5e-309, subnormal) mapped onto the unit needle: ok, s1 = s2 = 1e150, "
            "stretch 1e-150, finite",
            scaled(needle, 1e-150), planar(needle), {FaceStatus::Ok, 1e150, 1e150, 1e-150, 1e-150, 1, 1e300}),
        row("needle with edges of 1e150 (area 5e291) mapped onto the unit needle: ok, s1 = s2 = 1e-150, stretch 1e150",
            scaled(needle, 1e150), planar(needle), {FaceStatus::Ok, 1e-150, 1e-150, 1e150, 1e150, 1, 1e-300}),
        row("right triangle with edges of 1e150 onto a UV needle (G^2 = 2e316 overflows): ok, s1 = 1.414e-150, "
            "s2 = 7.07e-159, L2 = 1e158, Linf = 1.414e158, angle 2e8",
            scaled(right, 1e150), planar(needle),
            {FaceStatus::Ok, std::sqrt(2.0) * 1e-150, s / std::sqrt(2.0) * 1e-150, 1e150 / s, std::sqrt(2.0) * 1e150 / s,
             2.0 / s, kAny}),
        row("needle of angle 1e-10 with edges of 1e-150 (the 3D edges' determinant 1e-310, whose inverse "
            "overflows) onto the right UV triangle of 1e-10: measured at its own scale, ok, s1 = 1.414e150, "
            "s2 = 7.07e139, L2 = 1e-140, Linf = 1.414e-140, angle 2e10, area ratio 1e290",
            scaled({{0, 0, 0}, {1, 0, 0}, {std::cos(1e-10), std::sin(1e-10), 0}}, 1e-150),
            {{0, 0}, {1e-10, 0}, {0, 1e-10}},
            {FaceStatus::Ok, std::sqrt(2.0) * 1e150, std::sqrt(0.5) * 1e140, 1e-140, std::sqrt(2.0) * 1e-140, 2e10,
             1e290}),
        row("needle of angle 1.5e-8 (2^-26, the coordinates' ulp) 1e8 from the origin, isometric: edges are exact "
            "differences, ok, every measure 1 within 1e-6",
            {Vec3(1e8, 1e8, 1e8), Vec3(1e8 + 1, 1e8, 1e8), Vec3(1e8 + 1, 1e8 + 0x1p-26, 1e8)},
            {{0, 0}, {1, 0}, {1, 0x1p-26}}, {FaceStatus::Ok, 1, 1, 1, 1, 1, 1}),
    };
    // A mirrored needle among two ok right triangles: outvoted, so flipped, with finite measures.
    std::vector<Vec3> mixed = {{0, 0, 0}, {1, 0, 0}, {c, s, 0}};
    std::vector<Vec2> mixedUv = {{0, 0}, {1, 0}, {c, -s}};
    for (double dz : {2.0, 4.0}) {
      for (const Vec3& p : right) mixed.push_back(p + Vec3(0, 0, dz));
      for (const Vec2& uv : rightUv) mixedUv.push_back(uv + Vec2(dz, 0));
    }
    t.push_back(row("a mirrored needle among two ok faces: flipped (outvoted), s2 = -1, finite measures", mixed,
                    mixedUv, {FaceStatus::Flipped, 1, -1, 1, 1, 1, 1}));
    return t;
  }();
  return table;
}

bool near(double got, double want, double tolerance) { return std::fabs(got - want) <= tolerance * std::fabs(want); }

class SliverExtremes : public testing::TestWithParam<std::size_t> {};

TEST_P(SliverExtremes, FiniteMeasuresOrAZeroAreaStatus) {
  const SliverRow& row = rows()[GetParam()];
  SCOPED_TRACE(row.expected);
  std::vector<Triangle> triangles;
  for (int f = 0; 3 * f < int(row.positions.size()); ++f) triangles.push_back({3 * f, 3 * f + 1, 3 * f + 2});
  const Layout layout = makeLayout(row.positions, triangles, row.uvs);
  const FaceMeasures faces = measureFaces(layout.mesh, layout.uv);
  const double surfacePerUv = okAreaTotals(faces).surfacePerUv();
  for (const FaceDistortion& f : faces)
    for (double x : {f.area3d, f.areaUv, f.sigmaMax, f.sigmaMin, f.l2Stretch(), f.linfStretch(), f.angleDistortion(),
                     f.areaRatio(), f.areaDistortion(surfacePerUv)})
      ASSERT_TRUE(std::isfinite(x)) << "a measure is " << x;
  const FaceDistortion& f = faces[0];
  const Expected& want = row.first;
  EXPECT_STREQ(toString(f.status), toString(want.status));
  const struct {
    const char* name;
    double got, want;
  } measures[] = {{"s1", f.sigmaMax, want.sigmaMax},
                  {"s2", f.sigmaMin, want.sigmaMin},
                  {"L2", f.l2Stretch(), want.l2},
                  {"Linf", f.linfStretch(), want.linf},
                  {"angle", f.angleDistortion(), want.angle},
                  {"area ratio", f.areaRatio(), want.areaRatio}};
  for (const auto& m : measures) {
    if (std::isnan(m.want)) continue;
    EXPECT_TRUE(near(m.got, m.want, want.tolerance)) << m.name << " " << m.got << " instead of " << m.want;
  }
  if (isMeasured(f.status)) {
    EXPECT_GT(f.sigmaMax, 0.0);
    EXPECT_GT(f.l2Stretch(), 0.0);
  }
  const AreaTotals totals = okAreaTotals(faces);
  EXPECT_TRUE(std::isfinite(totals.surface) && std::isfinite(totals.uv) && std::isfinite(totals.surfacePerUv()));
}

INSTANTIATE_TEST_SUITE_P(Rows, SliverExtremes, testing::Range<std::size_t>(0, rows().size()));

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::analysis

namespace uvtk::analysis {
namespace {
namespace UVTK_TEST_FILE {

// The reasons but those of the layout's size in the texture (layout_texels, texels_per_face): a
// layout scaled by 2^-300 is a handful of texels of a 1024 x 1024 texture, and those rules say so.
std::vector<Reason> shapeReasons(const Judgement& j) {
  std::vector<Reason> out;
  for (const Reason& r : j.reasons)
    if (r.rule != Rule::LayoutTexels && r.rule != Rule::TexelsPerFace) out.push_back(r);
  return out;
}

Verdict worst(const std::vector<Reason>& reasons) {
  Verdict v = Verdict::Pass;
  for (const Reason& r : reasons) v = std::max(v, r.severity);
  return v;
}

// The verdict and reasons of the layout's shape, every face's status and area distortion, and the
// mesh's L2 stretch are those of `reference`.
void expectSameJudgement(const Judgement& j, const Judgement& reference) {
  const std::vector<Reason> reasons = shapeReasons(j), referenceReasons = shapeReasons(reference);
  EXPECT_EQ(worst(reasons), worst(referenceReasons));
  ASSERT_EQ(reasons.size(), referenceReasons.size());
  for (std::size_t r = 0; r < reasons.size(); ++r) {
    EXPECT_EQ(reasons[r].rule, referenceReasons[r].rule);
    EXPECT_EQ(reasons[r].value, referenceReasons[r].value);
    EXPECT_EQ(reasons[r].faces, referenceReasons[r].faces);
  }
  ASSERT_EQ(j.faces.size(), reference.faces.size());
  for (std::size_t f = 0; f < j.faces.size(); ++f) {
    EXPECT_EQ(j.faces[f].status, reference.faces[f].status) << "face " << f;
    EXPECT_EQ(j.faces[f].areaDistortion(j.summary.okTotals.surfacePerUv()),
              reference.faces[f].areaDistortion(reference.summary.okTotals.surfacePerUv()))
        << "face " << f;
  }
  EXPECT_EQ(j.summary.l2Stretch, reference.summary.l2Stretch);
}

// A mesh at 1e-200 or 1e200 gets the verdict it gets at scale 1: its areas would underflow to 0
// (every face zero_area_3d) or overflow to inf (NaN stretches, an internal error in the
// statistics), so they are measured at unit scale (measureLengthScale). Scaling by a power of two
// is exact, so statuses and normalised measures must agree exactly.
TEST(AnalysisExtremes, AJudgementDoesNotDependOnTheMeshScale) {
  const Mesh knot = meshes::torusKnot(2, 3, 64, 8);
  param::ProjectorOptions o;
  o.surface = param::SurfaceKind::Cylinder;
  o.placement.fit = param::Fit::BBox;
  const param::Projection atOne = param::project(knot, o);
  const Judgement reference = judge(knot, atOne.uv);
  ASSERT_GT(reference.reasons.size(), 1u);  // a mapping with flipped faces, overlap and stretch to compare
  EXPECT_EQ(measureLengthScale(knot), 1.0);
  // At 2^+-300 the lengths are measured as they are, but A3 L2^2 would overflow (2^1200) or
  // underflow: the mesh's L2 stretch was null or 0.
  for (const int exponent : {-997, -664, -510, -498, -300, 300, 498, 510, 664, 997}) {
    SCOPED_TRACE("the knot times 2^" + std::to_string(exponent));
    Mesh scaled = knot;
    for (Vec3& p : scaled.positions) p = p.unaryExpr([&](double x) { return std::ldexp(x, exponent); });
    EXPECT_EQ(measureLengthScale(scaled) == 1.0, std::abs(exponent) < 500);
    const Judgement j = judge(scaled, atOne.uv);  // the same UVs: only the 3D lengths scale
    expectSameJudgement(j, reference);
    for (std::size_t f = 0; f < j.faces.size(); ++f)
      EXPECT_TRUE(std::isfinite(j.faces[f].l2Stretch()) && std::isfinite(j.faces[f].area3d)) << "face " << f;
  }
}

// A mesh 1e-149 across (inside the scales measured as they are) with slivers: a sliver's 3D
// determinant (1e-310) overflowed when inverted, its stretches were NaN and `uvtk report` stopped
// with an internal error in the statistics (a torus knot at 1e-150 written as glTF and read back).
// Each such face is measured at its own scale: the judgement is the knot's at unit scale, face by face.
TEST(AnalysisExtremes, SliversOfATinyMeshAreMeasuredAsAtUnitScale) {
  Mesh knot = meshes::torusKnot(2, 3, 64, 8);
  param::ProjectorOptions o;
  o.surface = param::SurfaceKind::Cylinder;
  o.placement.fit = param::Fit::BBox;
  UvMap uv = param::project(knot, o).uv;
  // Slivers beside the knot: needles of angles 1e-10 to 1e-12 onto UV triangles of size 0.01.
  for (const double angle : {1e-10, 1e-11, 1e-12}) {
    const int first = int(knot.positions.size());
    for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(std::cos(angle), std::sin(angle), 0)})
      knot.positions.push_back(p + Vec3(5, 5, 5));
    knot.triangles.push_back({first, first + 1, first + 2});
    uv.uv.insert(uv.uv.end(), {Vec2(0.5, 0.5), Vec2(0.51, 0.5), Vec2(0.5, 0.51)});
    uv.faceFlags.push_back(kFaceOk);
    if (!uv.cornerInvalid.empty()) uv.cornerInvalid.insert(uv.cornerInvalid.end(), 3, 0);
  }
  const Judgement reference = judge(knot, uv);
  Mesh tiny = knot;
  for (Vec3& p : tiny.positions) p = p.unaryExpr([](double x) { return std::ldexp(x, -495); });
  ASSERT_EQ(measureLengthScale(tiny), 1.0);  // measured as it is
  const Judgement j = judge(tiny, uv);
  ASSERT_EQ(j.faces.size(), reference.faces.size());
  for (std::size_t f = 0; f < j.faces.size(); ++f) {
    const FaceDistortion &a = j.faces[f], &b = reference.faces[f];
    ASSERT_EQ(a.status, b.status) << "face " << f;
    const double aArea = a.areaDistortion(j.summary.okTotals.surfacePerUv()),
                 bArea = b.areaDistortion(reference.summary.okTotals.surfacePerUv());
    for (const double x : {a.l2Stretch(), a.linfStretch(), a.angleDistortion(), aArea})
      ASSERT_TRUE(std::isfinite(x)) << "face " << f;
    // The slivers' areas are subnormal at 2^-990: a few digits are lost, no more.
    EXPECT_NEAR(a.angleDistortion(), b.angleDistortion(), 1e-9 * b.angleDistortion()) << "face " << f;
    EXPECT_NEAR(aArea, bArea, 1e-6) << "face " << f;
  }
  EXPECT_EQ(j.verdict, reference.verdict);
  ASSERT_EQ(j.reasons.size(), reference.reasons.size());
  for (std::size_t r = 0; r < j.reasons.size(); ++r) {
    EXPECT_EQ(j.reasons[r].rule, reference.reasons[r].rule);
    EXPECT_EQ(j.reasons[r].faces, reference.reasons[r].faces);
    EXPECT_NEAR(j.reasons[r].value, reference.reasons[r].value, 1e-9 * std::abs(reference.reasons[r].value));
  }
}

// UVs at 1e200 (a planar layout of a mesh at 1e200 spans as much) overflowed the UV areas and the
// Jacobian's determinant: `uvtk map --projector two-plane` of such a mesh stopped with an internal
// error. They are measured at unit scale too (measureUvScale), so the judgement agrees exactly.
TEST(AnalysisExtremes, AJudgementDoesNotDependOnTheUvScale) {
  const Mesh knot = meshes::torusKnot(2, 3, 64, 8);
  param::ProjectorOptions o;
  o.surface = param::SurfaceKind::Cylinder;
  o.placement.fit = param::Fit::BBox;
  const param::Projection atOne = param::project(knot, o);
  const Judgement reference = judge(knot, atOne.uv);
  EXPECT_EQ(measureUvScale(atOne.uv), 1.0);
  for (const int exponent : {-997, -664, -510, -300, 300, 510, 664, 997}) {
    for (const bool meshToo : {false, true}) {
      SCOPED_TRACE("UVs times 2^" + std::to_string(exponent) + (meshToo ? ", mesh too" : ""));
      UvMap uv = atOne.uv;
      for (Vec2& t : uv.uv) t = t.unaryExpr([&](double x) { return std::ldexp(x, exponent); });
      Mesh mesh = knot;
      if (meshToo)
        for (Vec3& p : mesh.positions) p = p.unaryExpr([&](double x) { return std::ldexp(x, exponent); });
      EXPECT_EQ(measureUvScale(uv) == 1.0, std::abs(exponent) < 500);
      const Judgement j = judge(mesh, uv);
      expectSameJudgement(j, reference);
      // The layout in the texture does depend on it: shrunk, it covers less than a texel and fails.
      const std::size_t layoutTexels = std::size_t(Rule::LayoutTexels);
      EXPECT_EQ(j.values[layoutTexels], std::ldexp(reference.values[layoutTexels], 2 * exponent));
      EXPECT_EQ(j.verdict == Verdict::Fail, exponent < 0 || reference.verdict == Verdict::Fail);
      for (std::size_t f = 0; f < j.faces.size(); ++f)
        EXPECT_EQ(j.faces[f].angleDistortion(), reference.faces[f].angleDistortion()) << "face " << f;
    }
  }
}

// Subnormal positions and UVs (1e-320: `uvtk report` of a triangle with such UVs stopped with an
// internal error): their scale, 2^1064 or more, is beyond a double, so they are measured at 2^1023
// times their size. A grid of small whole numbers stays exact at 2^-1064, so the judgement agrees
// exactly with the same grid at unit scale.
TEST(AnalysisExtremes, SubnormalPositionsAndUvsAreJudgedAsAtUnitScale) {
  Mesh grid;
  UvMap unit;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) grid.positions.push_back(Vec3(i, j, (i * j) % 3));
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const int a = 4 * j + i;
      for (const Triangle& t : {Triangle{a, a + 1, a + 5}, Triangle{a, a + 5, a + 4}}) {
        grid.triangles.push_back(t);
        for (const int v : t) unit.uv.push_back(Vec2(v % 4 + (v / 4) % 2, v / 4));  // a sheared layout
      }
    }
  unit.faceFlags.assign(grid.triangles.size(), 0);
  const Judgement reference = judge(grid, unit);
  for (const bool positionsToo : {false, true}) {
    SCOPED_TRACE(positionsToo ? "UVs and positions times 2^-1064" : "UVs times 2^-1064");
    UvMap tiny = unit;
    for (Vec2& t : tiny.uv) t = t.unaryExpr([](double x) { return std::ldexp(x, -1064); });
    Mesh mesh = grid;
    if (positionsToo)
      for (Vec3& p : mesh.positions) p = p.unaryExpr([](double x) { return std::ldexp(x, -1064); });
    EXPECT_EQ(measureUvScale(tiny), 0x1p1023);
    const Judgement j = judge(mesh, tiny);
    expectSameJudgement(j, reference);
    EXPECT_EQ(j.summary.l2Stretches.p50, reference.summary.l2Stretches.p50);
  }
}

// A layout spanning -2^1023 .. 2^1023, whose size overflows a double: the overlap raster stopped
// with an internal error. Its grid is placed at a power of two (uvGridOver), so the overlap and the
// faces overlapping are the same as at unit scale.
TEST(AnalysisExtremes, ALayoutWhoseSizeOverflowsIsRasterisedAsAtUnitScale) {
  const Mesh knot = meshes::torusKnot(2, 3, 64, 8);
  param::ProjectorOptions o;
  o.surface = param::SurfaceKind::Cylinder;
  o.placement.fit = param::Fit::BBox;
  UvMap centred = param::project(knot, o).uv;
  for (Vec2& t : centred.uv) t -= Vec2(0.5, 0.5);
  const Judgement reference = judge(knot, centred);
  ASSERT_GT(reference.summary.overlap.overlappedPixels, 0u);
  UvMap huge = centred;
  for (Vec2& t : huge.uv) t = t.unaryExpr([](double x) { return std::ldexp(x, 1024); });
  const Eigen::AlignedBox2d bounds = validUvBounds(huge);
  ASSERT_TRUE(bounds.min().allFinite() && bounds.max().allFinite() && !bounds.sizes().allFinite());
  const Judgement j = judge(knot, huge);
  expectSameJudgement(j, reference);
  EXPECT_EQ(j.summary.overlap.coveredPixels, reference.summary.overlap.coveredPixels);
  EXPECT_EQ(j.summary.overlap.overlappedPixels, reference.summary.overlap.overlappedPixels);
  EXPECT_EQ(j.overlappedFaces, reference.overlappedFaces);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::analysis
