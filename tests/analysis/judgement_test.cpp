// The judgement of a mapping: hand-computed verdicts on small layouts, the thresholds' parsing,
// and, on meshes like real ones under all 20 O x S combinations, that nothing which passes has a
// mirrored face or a UV far outside the projector's range (recounted independently here).
#include "analysis/judgement.h"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "analysis/same_statistics.h"
#include "core/error.h"
#include "layout.h"
#include "meshes/generators.h"
#include "param/projector.h"

namespace uvtk::analysis {
namespace {
namespace UVTK_TEST_FILE {

// n x n unit cells in z = 0, each split in two, mapped by (x, y) / n: an isometry up to scale.
Layout grid(int n) {
  Layout l;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec3 p(i, j, 0);
      const auto uv = [n](const Vec3& q) { return Vec2(q.x() / n, q.y() / n); };
      const Vec3 a = p, b = p + Vec3(1, 0, 0), c = p + Vec3(1, 1, 0), d = p + Vec3(0, 1, 0);
      l.add(a, b, c, uv(a), uv(b), uv(c));
      l.add(a, c, d, uv(a), uv(c), uv(d));
    }
  return l;
}

// A square of side `side` (UV units) at `corner`, mapped from a square of the same side in z = 0:
// two triangles sharing their diagonal's vertices, one chart.
void addSquare(Layout& l, const Vec2& corner, double side) {
  const int base = int(l.mesh.positions.size());
  const Vec2 uv[4] = {corner, corner + Vec2(side, 0), corner + Vec2(side, side), corner + Vec2(0, side)};
  for (const Vec2& p : uv) l.mesh.positions.emplace_back(p.x(), p.y(), 0.0);
  for (const Triangle& t : {Triangle{base, base + 1, base + 2}, Triangle{base, base + 2, base + 3}}) {
    l.mesh.triangles.push_back(t);
    for (int k = 0; k < 3; ++k) l.uv.uv.push_back(uv[t[k] - base]);
    l.uv.faceFlags.push_back(kFaceOk);
    l.uv.cornerInvalid.insert(l.uv.cornerInvalid.end(), 3, 0);
  }
}

// The layout's size in the texture (issue 47, point 3: a layout shrunk into a 1e-6 square passed):
// a square of side s covers s^2 1024^2 texels; under 64 warns, under 16 fails.
TEST(Judgement, ALayoutOfAHandfulOfTexelsDoesNotPass) {
  for (const auto& [side, verdict, text] :
       std::vector<std::tuple<double, Verdict, std::string>>{{1.0 / 128, Verdict::Pass, ""},
                                                              {1.0 / 160, Verdict::Warn, "layout_texels 41 < 64 (2 faces)"},
                                                              {1.0 / 512, Verdict::Fail, "layout_texels 4 < 16 (2 faces)"},
                                                              {1e-6, Verdict::Fail, "layout_texels 1.05e-06 < 16 (2 faces)"}}) {
    Layout l;
    addSquare(l, Vec2(0.25, 0.25), side);
    const Judgement j = judge(l.mesh, l.uv);
    const double texels = side * side * 1024 * 1024;
    EXPECT_NEAR(j.values[std::size_t(Rule::LayoutTexels)], texels, 1e-9 * texels) << side;
    EXPECT_EQ(j.verdict, verdict) << side;
    if (!text.empty()) {
      EXPECT_EQ(j.reasonsText().substr(0, text.size()), text) << side;
    }
  }
}

// Faces far below a texel: n x n cells (2 n^2 faces) over the unit square of a 16 x 16 texture,
// 128 / n^2 texels a face: under 1/16 warns, under 1/256 fails.
TEST(Judgement, FacesFarBelowATexelDoNotPass) {
  JudgementOptions o;
  o.textureSize = {16, 16};
  const std::tuple<int, Verdict, std::string> cases[] = {
      {16, Verdict::Pass, ""},  // half a texel a face
      {64, Verdict::Warn, "texels_per_face 0.0312 < 0.0625 (8192 faces)"},
      {256, Verdict::Fail, "texels_per_face 0.00195 < 0.00391 (131072 faces)"}};
  for (const auto& [n, verdict, text] : cases) {
    const Layout l = grid(n);
    const Judgement j = judge(l.mesh, l.uv, o);
    EXPECT_DOUBLE_EQ(j.values[std::size_t(Rule::TexelsPerFace)], 128.0 / (n * n)) << n;
    EXPECT_EQ(j.verdict, verdict) << n << ": " << j.reasonsText();
    if (!text.empty()) {
      EXPECT_EQ(j.reasonsText(), text) << n;
    }
  }
}

// Charts that must stay apart (an atlas): two 8-texel squares `gap` texels apart at 64 x 64. A gap
// of 8 passes; 1 warns (Unity's two texels); 0 (touching) clashes under bilinear filtering and
// fails. Charts meant to tile (separateCharts false) are not held to it unless a threshold is set.
TEST(Judgement, AnAtlasesChartsMustKeepAGutterAndNotClash) {
  const auto layout = [](double gap) {
    Layout l;
    addSquare(l, Vec2(8, 8) / 64, 8.0 / 64);
    addSquare(l, Vec2(16 + gap, 8) / 64, 8.0 / 64);
    return l;
  };
  JudgementOptions atlas;
  atlas.textureSize = {64, 64};
  atlas.separateCharts = true;
  const Layout apart = layout(8), near = layout(1), touching = layout(0);
  EXPECT_EQ(judge(apart.mesh, apart.uv, atlas).verdict, Verdict::Pass);
  const Judgement n = judge(near.mesh, near.uv, atlas);
  EXPECT_EQ(n.reasonsText(), "gutter 1 < 2");
  EXPECT_EQ(n.values[std::size_t(Rule::TexelClashes)], 0.0);
  const Judgement t = judge(touching.mesh, touching.uv, atlas);
  EXPECT_EQ(t.verdict, Verdict::Fail);
  // The two columns of texels either side of the shared edge, 8 rows: each reads the other chart.
  EXPECT_EQ(t.values[std::size_t(Rule::TexelClashes)], 16.0);
  EXPECT_EQ(t.reasonsText(), "texel_clashes 16 > 0; gutter 0 < 0.5");
  ASSERT_TRUE(t.texels);
  EXPECT_EQ(t.texels->levels.front().clashes, 16u);

  JudgementOptions tiling = atlas;
  tiling.separateCharts = false;
  EXPECT_EQ(judge(touching.mesh, touching.uv, tiling).verdict, Verdict::Pass);
  EXPECT_FALSE(judge(touching.mesh, touching.uv, tiling).texels);
  tiling.thresholds.set("gutter=4", Verdict::Fail, "--fail-on");  // asked for: in force everywhere
  EXPECT_EQ(judge(near.mesh, near.uv, tiling).reasonsText(), "gutter 1 < 4");
  tiling.thresholds.set("gutter=off", Verdict::Fail, "--fail-on");
  EXPECT_EQ(judge(near.mesh, near.uv, tiling).verdict, Verdict::Pass);
}

TEST(Judgement, AnIsometricLayoutPassesWithNoReason) {
  const Layout l = grid(4);
  const Judgement j = judge(l.mesh, l.uv);
  EXPECT_EQ(j.verdict, Verdict::Pass);
  EXPECT_TRUE(j.reasons.empty());
  EXPECT_EQ(j.firstReason(), "no rule triggered");
  EXPECT_DOUBLE_EQ(j.surfaceArea, 16.0);
  EXPECT_EQ(j.statusCount(FaceStatus::Ok), 32u);
  EXPECT_NEAR(j.values[std::size_t(Rule::StretchP99)], 1.0, 1e-12);
  EXPECT_EQ(j.summary.overlap.overlappedPixels, 0u);
}

TEST(Judgement, OneFlippedFaceOf32FailsWithItsAreaShareAndCount) {
  Layout l = grid(4);
  // Mirror face 5 in UV: exchange two corners' UVs.
  std::swap(l.uv.uv[15], l.uv.uv[16]);
  const Judgement j = judge(l.mesh, l.uv);
  ASSERT_EQ(j.statusCount(FaceStatus::Flipped), 1u);
  EXPECT_DOUBLE_EQ(j.values[std::size_t(Rule::FlippedArea)], 0.5 / 16.0);  // half a unit cell of 16
  EXPECT_EQ(j.verdict, Verdict::Fail);
  ASSERT_FALSE(j.reasons.empty());
  const Reason& first = j.reasons.front();
  EXPECT_EQ(first.rule, Rule::FlippedArea);
  EXPECT_EQ(first.severity, Verdict::Fail);
  EXPECT_DOUBLE_EQ(first.threshold, 1e-3);
  EXPECT_EQ(first.faces, 1u);
  EXPECT_EQ(first.text(), "flipped_area 0.0312 > 0.001 (1 face)");
  EXPECT_EQ(j.reasonsText(), "flipped_area 0.0312 > 0.001 (1 face)");
  // Mirrored in place, it still covers only its own cell: the flip alone fails it.
  EXPECT_EQ(j.values[std::size_t(Rule::Overlap)], 0.0);
  EXPECT_EQ(j.overlappedFaces, 0u);
  EXPECT_EQ(j.reasons.size(), 1u);
}

TEST(Judgement, AThresholdTurnsTheSameFlipIntoAWarning) {
  Layout l = grid(4);
  std::swap(l.uv.uv[15], l.uv.uv[16]);
  JudgementOptions options;
  options.thresholds.set("flipped_area=0.05", Verdict::Fail, "--fail-on");
  options.thresholds.set("overlap=off", Verdict::Fail, "--fail-on");
  options.thresholds.set("overlap=off", Verdict::Warn, "--warn-on");
  const Judgement j = judge(l.mesh, l.uv, options);
  EXPECT_EQ(j.verdict, Verdict::Warn);
  ASSERT_EQ(j.reasons.size(), 1u);
  EXPECT_EQ(j.reasons[0].rule, Rule::FlippedArea);
  EXPECT_EQ(j.reasons[0].severity, Verdict::Warn);
  EXPECT_DOUBLE_EQ(j.reasons[0].threshold, 0.0);
  // applyThresholds re-judges without measuring again.
  Judgement strict = j;
  applyThresholds(strict, Thresholds());
  EXPECT_EQ(strict.verdict, Verdict::Fail);
}

// Faces of zero 3D area measure nothing: a mesh of them alone passed every other rule. One of 32
// (3.1 %) warns, 17 of 49 fail only above half, and all of them fail.
TEST(Judgement, FacesOfZeroAreaIn3dWarnAndFailByTheirShareOfTheFaces) {
  const auto withDegenerate = [](int n, int count) {
    Layout l = grid(n);
    for (int k = 0; k < count; ++k)  // three corners on one line, mapped to a proper triangle
      l.add({0, 0, 1}, {1, 0, 1}, {2, 0, 1}, {0, 0}, {0.1, 0}, {0, 0.1});
    return l;
  };
  const Layout one = withDegenerate(4, 1);
  const Judgement j = judge(one.mesh, one.uv);
  ASSERT_EQ(j.statusCount(FaceStatus::ZeroArea3d), 1u);
  EXPECT_DOUBLE_EQ(j.values[std::size_t(Rule::ZeroArea3dFaces)], 1.0 / 33.0);
  EXPECT_EQ(j.verdict, Verdict::Warn);
  EXPECT_EQ(j.reasonsText(), "zero_area_3d_faces 0.0303 > 0.01 (1 face)");

  const Layout third = withDegenerate(4, 16);  // 16 of 48: a third, a warning still
  EXPECT_EQ(judge(third.mesh, third.uv).verdict, Verdict::Warn);
  const Layout most = withDegenerate(4, 33);   // 33 of 65: more than half fails
  const Judgement m = judge(most.mesh, most.uv);
  EXPECT_EQ(m.verdict, Verdict::Fail);
  EXPECT_EQ(m.reasons.at(0).rule, Rule::ZeroArea3dFaces);

  Layout none;  // nothing but degenerate faces: no face is measured, and the verdict says so
  none.add({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 0}, {1, 0}, {0, 1});
  none.add({0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 0}, {1, 0}, {0, 1});
  const Judgement n = judge(none.mesh, none.uv);
  EXPECT_EQ(n.statusCount(FaceStatus::Ok), 0u);
  EXPECT_EQ(n.values[std::size_t(Rule::ZeroArea3dFaces)], 1.0);
  EXPECT_EQ(n.verdict, Verdict::Fail);
  EXPECT_EQ(n.reasonsText(), "zero_area_3d_faces 1 > 0.5 (2 faces)");
}

TEST(Judgement, InvalidAndOutOfRangeCornersFailApartByReason) {
  Layout l = grid(2);
  l.uv.cornerInvalid[0] = kCornerBehind;
  l.uv.cornerInvalid[1] = kCornerBehind;
  l.uv.cornerInvalid[7] = kCornerOutOfRange;
  l.uv.faceFlags[0] |= kFaceInvalid;
  l.uv.faceFlags[2] |= kFaceInvalid;
  const Judgement j = judge(l.mesh, l.uv);
  EXPECT_EQ(j.invalidCorners[kCornerBehind], 2u);
  EXPECT_EQ(j.invalidCorners[kCornerOutOfRange], 1u);
  EXPECT_EQ(j.invalidCorners[kCornerValid], 21u);
  EXPECT_EQ(j.invalidFaces, 2u);
  EXPECT_EQ(j.outOfRangeFaces, 1u);
  EXPECT_EQ(j.verdict, Verdict::Fail);
  ASSERT_GE(j.reasons.size(), 2u);
  EXPECT_EQ(j.reasons[0].rule, Rule::InvalidCorners);
  EXPECT_EQ(j.reasons[0].value, 2.0);
  EXPECT_EQ(j.reasons[0].faces, 1u);
  EXPECT_EQ(j.reasons[1].rule, Rule::OutOfRangeCorners);
  EXPECT_EQ(j.reasons[1].faces, 1u);
  // Warnings after the failures, marked as such: the mirrored face 0 (its invalid corner reads (0, 0)).
  const std::string text = j.reasonsText();
  EXPECT_EQ(text.rfind("invalid_corners 2 > 0 (1 face); out_of_range_corners 1 > 0 (1 face)", 0), 0u) << text;
}

TEST(Judgement, AnUnrepairedSeamFailsWhileARepairedOneIsOnlyReported) {
  const Mesh sphere = meshes::latLongSphere(16, 8);
  param::ProjectorOptions o;
  o.surface = param::SurfaceKind::Sphere;
  JudgementOptions options;
  options.wrapsU = true;
  for (const param::SeamMode mode : {param::SeamMode::Shift, param::SeamMode::None}) {
    o.seam = mode;
    const param::Projection p = param::project(sphere, o);
    const Judgement j = judge(p.mesh, p.uv, options);
    // The seam crosses the faces of one meridian gap (the poles' fans apart).
    EXPECT_EQ(j.straddlingFaces, p.summary.straddlingFaces);
    if (mode == param::SeamMode::Shift) {
      EXPECT_EQ(j.unrepairedSeamFaces, 0u);
      EXPECT_GT(j.summary.seams.wrapEdges, 0u);
      EXPECT_NE(j.verdict, Verdict::Fail) << j.firstReason();
    } else {
      EXPECT_GT(j.unrepairedSeamFaces, 0u);
      EXPECT_EQ(j.verdict, Verdict::Fail);
      bool named = false;
      for (const Reason& r : j.reasons) named |= r.rule == Rule::UnrepairedSeamFaces;
      EXPECT_TRUE(named);
    }
  }
}

TEST(Thresholds, ParseRuleAssignmentsAndRefuseWhatIsNotOne) {
  Thresholds t;
  t.set("stretch_p99=4.5", Verdict::Warn, "--warn-on");
  EXPECT_EQ(t.of(Rule::StretchP99, Verdict::Warn), 4.5);
  t.set("pole_area=off", Verdict::Warn, "--warn-on");
  EXPECT_TRUE(std::isinf(t.of(Rule::PoleArea, Verdict::Warn)));
  EXPECT_FALSE(t == Thresholds());
  for (const char* bad : {"stretch_p99", "stretch=2", "overlap=-1", "overlap=x", "overlap=1x", "=1"}) {
    try {
      t.set(bad, Verdict::Fail, "--fail-on");
      ADD_FAILURE() << bad;
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("--fail-on"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("flipped_area"), std::string::npos) << e.what();
    }
  }
  for (int k = 0; k < kRuleCount; ++k) EXPECT_EQ(parseRule(toString(Rule(k))), Rule(k));
  EXPECT_EQ(parseVerdict("warn"), Verdict::Warn);
  EXPECT_FALSE(parseVerdict("bad"));
}

// Independently of measureFaces: faces whose UV winding is opposite to the 3D-area-weighted
// majority, among faces with a non-zero UV area and no pole flag.
std::size_t mirroredFaces(const Mesh& mesh, const UvMap& uv) {
  std::vector<double> signs(mesh.faceCount());
  double vote = 0.0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    const Vec2 a = uv.uv[3 * f], b = uv.uv[3 * f + 1], c = uv.uv[3 * f + 2];
    const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    const Triangle& t = mesh.triangles[f];
    const double area3 = triangleAreaNormal(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]).norm();
    signs[f] = area > 0 ? 1.0 : area < 0 ? -1.0 : 0.0;
    vote += signs[f] * area3;
  }
  const double majority = vote >= 0 ? 1.0 : -1.0;
  std::size_t mirrored = 0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    mirrored += signs[f] == -majority && !uv.faceHas(f, kFacePole) ? 1 : 0;
  return mirrored;
}

TEST(Judgement, NothingThatPassesOnRealLookingMeshesHasAMirroredFaceOrAFarUv) {
  const std::pair<const char*, Mesh> meshes[] = {{"torus knot", meshes::torusKnot(2, 3, 96, 8)},
                                                 {"bone", meshes::bone(40, 12)},
                                                 {"bumpy blob", meshes::bumpyBlob(2)},
                                                 {"scanned patch", meshes::scannedPatch(3)}};
  using param::RayKind;
  using param::SurfaceKind;
  int passed = 0, judged = 0;
  for (const auto& [name, mesh] : meshes)
    for (const SurfaceKind surface :
         {SurfaceKind::Plane, SurfaceKind::TwoPlane, SurfaceKind::Cylinder, SurfaceKind::Sphere, SurfaceKind::Cube})
      for (const RayKind ray : {RayKind::SurfaceNormal, RayKind::Centroid, RayKind::ObjectNormal, RayKind::Reflection}) {
        param::ProjectorOptions o;
        o.surface = surface;
        o.ray = ray;
        o.cubeLayout = CubeLayout::Cross;
        o.eye = Vec3(3, -20, 8);
        const param::Projection p = param::project(mesh, o);
        JudgementOptions options;
        options.wrapsU = surface == SurfaceKind::Cylinder || surface == SurfaceKind::Sphere;
        options.overlapResolution = 256;
        const Judgement j = judge(p.mesh, p.uv, options);
        ++judged;
        // Every count the verdict reads agrees with the projector's own.
        EXPECT_EQ(j.invalidFaces, p.summary.invalidFaces) << name;
        if (j.verdict != Verdict::Pass) continue;
        ++passed;
        const std::string what = std::string(name) + " " + std::to_string(int(surface)) + "/" + std::to_string(int(ray));
        EXPECT_EQ(mirroredFaces(p.mesh, p.uv), 0u) << what;
        for (std::size_t corner = 0; corner < p.uv.uv.size(); ++corner) {
          EXPECT_EQ(p.uv.cornerInvalid[corner], kCornerValid) << what;
          EXPECT_LE(p.uv.uv[corner].cwiseAbs().maxCoeff(), 8.0) << what << " corner " << corner;
        }
      }
  EXPECT_EQ(judged, 80);
  // The classic projectors do pass somewhere (a judgement that fails everything is no judgement).
  EXPECT_GT(passed, 0);
}

// Every part of a judgement is the same whatever the thread count: the faces, counted and summed in
// fixed chunks; the bounds and the ok mask, in chunks on threads; the seams beside the faces and the
// summary's six tasks, run side by side. The knot has 3 chunks of faces, flipped and stretched faces, seams.
TEST(Judgement, DoesNotDependOnTheThreadCount) {
  const Mesh knot = meshes::torusKnot(2, 3, 1200, 60);
  ASSERT_GT(knot.faceCount(), std::size_t(2) << 16);
  param::ProjectorOptions o;
  o.surface = param::SurfaceKind::Cylinder;
  o.placement.fit = param::Fit::BBox;
  const param::Projection p = param::project(knot, o);
  JudgementOptions options;
  options.wrapsU = true;
  options.threads = 1;
  const Judgement one = judge(knot, p.uv, options);
  ASSERT_EQ(one.verdict, Verdict::Fail);
  ASSERT_GT(one.statusCount(FaceStatus::Flipped), 0u);
  ASSERT_GT(one.summary.seams.wrapEdges + one.summary.seams.cutEdges, 0u);
  for (const int threads : {2, 3, 0}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    options.threads = threads;
    const Judgement j = judge(knot, p.uv, options);
    ASSERT_EQ(j.faces.size(), one.faces.size());
    std::size_t differentFaces = 0;
    for (std::size_t f = 0; f < j.faces.size(); ++f) {
      const FaceDistortion &a = j.faces[f], &b = one.faces[f];
      differentFaces += a.status != b.status || a.area3d != b.area3d || a.areaUv != b.areaUv ||
                        a.sigmaMax != b.sigmaMax || a.sigmaMin != b.sigmaMin;
    }
    EXPECT_EQ(differentFaces, 0u);
    EXPECT_EQ(j.summary.statusCounts.faces, one.summary.statusCounts.faces);
    EXPECT_EQ(j.summary.okTotals.surface, one.summary.okTotals.surface);
    EXPECT_EQ(j.summary.okTotals.uv, one.summary.okTotals.uv);
    EXPECT_EQ(j.summary.l2Stretch, one.summary.l2Stretch);
    EXPECT_EQ(j.summary.linfStretch, one.summary.linfStretch);
    expectSameStatistics(j.summary.angleDistortion, one.summary.angleDistortion);
    expectSameStatistics(j.summary.areaDistortion, one.summary.areaDistortion);
    expectSameStatistics(j.summary.l2Stretches, one.summary.l2Stretches);
    expectSameStatistics(j.summary.linfStretches, one.summary.linfStretches);
    expectSameStatistics(j.summary.density.scaled, one.summary.density.scaled);
    EXPECT_EQ(j.summary.seams.wrapEdges, one.summary.seams.wrapEdges);
    EXPECT_EQ(j.summary.seams.cutEdges, one.summary.seams.cutEdges);
    EXPECT_EQ(j.summary.seams.length(), one.summary.seams.length());
    EXPECT_EQ(j.summary.overlap.overlappedPixels, one.summary.overlap.overlappedPixels);
    EXPECT_EQ(j.summary.uvBounds.min(), one.summary.uvBounds.min());
    EXPECT_EQ(j.summary.uvBounds.max(), one.summary.uvBounds.max());
    EXPECT_EQ(j.values, one.values);
    EXPECT_EQ(j.ruleFaces, one.ruleFaces);
    EXPECT_EQ(j.reasonsText(), one.reasonsText());
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::analysis
