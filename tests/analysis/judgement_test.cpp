// The judgement of a mapping: hand-computed verdicts on small layouts, the thresholds' parsing,
// and, on meshes like real ones under all 20 O x S combinations, that nothing which passes has a
// mirrored face or a UV far outside the projector's range (recounted independently here).
#include "analysis/judgement.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "meshes/generators.h"
#include "param/projector.h"

namespace uvtk::analysis {
namespace {

// Two triangles of the unit square, mapped by (x, y), plus optional extra faces.
struct Layout {
  Mesh mesh;
  UvMap uv;
  void add(const Vec3& a, const Vec3& b, const Vec3& c, const Vec2& ua, const Vec2& ub, const Vec2& uc) {
    const int first = int(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, b, c});
    mesh.triangles.push_back({first, first + 1, first + 2});
    uv.uv.insert(uv.uv.end(), {ua, ub, uc});
    uv.faceFlags.push_back(kFaceOk);
    uv.cornerInvalid.insert(uv.cornerInvalid.end(), {0, 0, 0});
  }
};

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
    options.poleVertices = p.summary.poleVertexList;
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
        options.poleVertices = p.summary.poleVertexList;
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
// fixed chunks; the bounds and the ok faces' areas, gathered in chunks on threads; the summary's
// seven tasks, run side by side. The knot has 3 chunks of faces, flipped and stretched faces, seams.
void expectSameStatistics(const Statistics& a, const Statistics& b) {
  EXPECT_EQ(a.totalWeight, b.totalWeight);
  EXPECT_EQ(a.mean, b.mean);
  EXPECT_EQ(a.p10, b.p10);
  EXPECT_EQ(a.p50, b.p50);
  EXPECT_EQ(a.p90, b.p90);
  EXPECT_EQ(a.p99, b.p99);
  EXPECT_EQ(a.min, b.min);
  EXPECT_EQ(a.max, b.max);
  EXPECT_EQ(a.histogram.weightFraction, b.histogram.weightFraction);
}

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
                        a.sigmaMax != b.sigmaMax || a.sigmaMin != b.sigmaMin || a.areaDistortion != b.areaDistortion;
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

}  // namespace
}  // namespace uvtk::analysis
