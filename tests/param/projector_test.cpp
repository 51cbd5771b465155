// The whole projector pipeline on generated meshes: every surface with every ray mapping,
// placements, seams, poles, caps, the UV transform and the numerical extremes.
#include "param/projector.h"

#include <gtest/gtest.h>

#include "core/seam_edges.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>

#include "core/cancel.h"
#include "core/error.h"
#include "param/surfaces.h"
#include "meshes/generators.h"

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

// Every surface with a formula of a point: a surface added to the list is tested here as it comes.
const std::vector<SurfaceKind> kSurfaces = [] {
  std::vector<SurfaceKind> surfaces;
  std::copy_if(std::begin(param::kSurfaces), std::end(param::kSurfaces), std::back_inserter(surfaces),
               [](SurfaceKind s) { return hasPointFormula(s); });
  return surfaces;
}();
constexpr RayKind kRays[] = {RayKind::SurfaceNormal, RayKind::Centroid, RayKind::ObjectNormal, RayKind::Reflection};

ProjectorOptions optionsFor(SurfaceKind surface, RayKind ray = RayKind::SurfaceNormal) {
  ProjectorOptions o;
  o.surface = surface;
  o.ray = ray;
  if (ray == RayKind::Reflection) o.eye = Vec3(0.3, -0.2, 5.0);
  return o;
}

std::size_t invalidCorners(const UvMap& uv) {
  std::size_t n = 0;
  for (auto c : uv.cornerInvalid) n += c != kCornerValid;
  return n;
}

// The passes of a projection over vertices and faces run in ranges on threads: the same frame,
// UVs, flags and summary on 1, 2 and 3 threads for a mesh of several ranges (65,536 faces each),
// with poles, straddling faces cut or shifted, caps and corners left out of range.
TEST(Project, TheSameBitsOnAnyNumberOfThreads) {
  const Mesh sphere = meshes::latLongSphere(400, 200);
  ASSERT_GT(sphere.faceCount(), 2 * (std::size_t(1) << 16));
  ProjectorOptions cut = optionsFor(SurfaceKind::Sphere), caps = optionsFor(SurfaceKind::Cylinder),
                   behind = optionsFor(SurfaceKind::Camera);
  cut.seam = SeamMode::Cut;
  caps.cylinderCaps = true;
  behind.camera.eye = Vec3(0.1, 0.2, 0.3);  // inside the sphere: half its corners behind the eye
  for (const ProjectorOptions& o : {optionsFor(SurfaceKind::Sphere), cut, caps, behind}) {
    const Projection one = project(sphere, o, 1);
    EXPECT_GT(one.summary.poleVertices + one.summary.invalidVertices + one.summary.capFaces, 0u) << int(o.surface);
    for (const int threads : {2, 3}) {
      const Projection p = project(sphere, o, threads);
      EXPECT_TRUE(p.localFromObject.matrix() == one.localFromObject.matrix());
      ASSERT_EQ(p.uv.uv.size(), one.uv.uv.size());
      EXPECT_TRUE(std::equal(p.uv.uv.begin(), p.uv.uv.end(), one.uv.uv.begin(),
                             [](const Vec2& a, const Vec2& b) { return a.x() == b.x() && a.y() == b.y(); }));
      EXPECT_EQ(p.uv.cornerInvalid, one.uv.cornerInvalid);
      EXPECT_EQ(p.uv.cornerPole, one.uv.cornerPole);
      EXPECT_EQ(p.uv.faceFlags, one.uv.faceFlags);
      EXPECT_EQ(p.summary.poleVertexList, one.summary.poleVertexList);
      EXPECT_EQ(p.summary.poleFaceList, one.summary.poleFaceList);
      EXPECT_EQ(p.summary.invalidVertexList, one.summary.invalidVertexList);
      EXPECT_EQ(p.summary.invalidCorners, one.summary.invalidCorners);
      EXPECT_EQ(p.summary.straddlingFaces, one.summary.straddlingFaces);
      EXPECT_EQ(p.summary.capFaces, one.summary.capFaces);
      EXPECT_EQ(p.summary.addedVertices, one.summary.addedVertices);
      EXPECT_EQ(p.sensible.has_value(), one.sensible.has_value());
      if (p.sensible) EXPECT_TRUE(p.sensible->min() == one.sensible->min() && p.sensible->max() == one.sensible->max());
    }
  }
}

// Every S x O combination returns finite UVs; a corner without a valid UV is flagged, never NaN.
TEST(Project, EverySurfaceComposesWithEveryRayMappingOnSphereAndCube) {
  for (const Mesh& mesh : {meshes::latLongSphere(24, 12), meshes::cube(3)}) {
    for (SurfaceKind s : kSurfaces)
      for (RayKind r : kRays)
        for (bool atInfinity : {false, true}) {
          if (atInfinity && r != RayKind::Reflection) continue;
          ProjectorOptions o = optionsFor(s, r);
          o.atInfinity = atInfinity;
          const Projection p = project(mesh, o);
          ASSERT_EQ(p.uv.uv.size(), 3 * p.mesh.faceCount());
          std::size_t flaggedFaces = 0;
          for (std::size_t f = 0; f < p.mesh.faceCount(); ++f) flaggedFaces += p.uv.faceHas(f, kFaceInvalid);
          for (std::size_t i = 0; i < p.uv.uv.size(); ++i) {
            ASSERT_TRUE(p.uv.uv[i].allFinite()) << "surface " << int(s) << " ray " << int(r);
            if (p.uv.cornerInvalid[i]) {
              EXPECT_EQ(p.uv.uv[i], Vec2::Zero());
              EXPECT_TRUE(p.uv.faceHas(i / 3, kFaceInvalid));
            }
          }
          EXPECT_EQ(flaggedFaces, p.summary.invalidFaces);
          // isn and the radial surfaces never miss; the documented invalid cases are
          // central projection behind the plane and rays that miss.
          if (r == RayKind::SurfaceNormal) { EXPECT_EQ(invalidCorners(p.uv), 0u) << int(s); }
          if (s == SurfaceKind::Sphere && r != RayKind::Reflection) { EXPECT_EQ(invalidCorners(p.uv), 0u) << int(r); }
        }
  }
}

// With isn the sphere projector is the closed-form map of the unit sphere.
TEST(Project, SphereIsnOnTheUnitSphereIsTheClosedForm) {
  const Mesh mesh = meshes::latLongSphere(16, 8);
  const Projection p = project(mesh, optionsFor(SurfaceKind::Sphere));
  for (std::size_t f = 0; f < p.mesh.faceCount(); ++f) {
    if (p.uv.faceHas(f, kFacePole)) continue;
    for (int k = 0; k < 3; ++k) {
      const Vec3& q = mesh.positions[mesh.triangles[f][k]];
      const double v = 1.0 - std::atan2(std::hypot(q.x(), q.y()), q.z()) / kPi;
      double u = std::atan2(q.y(), q.x()) / (2 * kPi);
      if (u < 0) u += 1;
      const Vec2 uv = p.uv.uv[3 * f + k];
      EXPECT_NEAR(uv.y(), v, 1e-15);
      EXPECT_NEAR(uv.x() - std::floor(uv.x()), u - std::floor(u), 1e-15);
    }
  }
}

// Normal and reflection rays from a vertex on the fitted sphere hit the sphere at the vertex.
TEST(Project, RaysFromVerticesOnTheSurfaceHitAtTheVertex) {
  const Mesh mesh = meshes::icosphere(2);
  const Projection isn = project(mesh, optionsFor(SurfaceKind::Sphere));
  for (RayKind r : {RayKind::ObjectNormal, RayKind::Reflection}) {
    const Projection p = project(mesh, optionsFor(SurfaceKind::Sphere, r));
    for (std::size_t i = 0; i < p.uv.uv.size(); ++i) EXPECT_TRUE(p.uv.uv[i].isApprox(isn.uv.uv[i], 1e-12)) << i;
  }
}

double maxUSpan(const UvMap& uv, std::size_t f) {
  double lo = INFINITY, hi = -INFINITY;
  for (int k = 0; k < 3; ++k) lo = std::min(lo, uv.uv[3 * f + k].x()), hi = std::max(hi, uv.uv[3 * f + k].x());
  return hi - lo;
}

TEST(Project, ShiftLeavesNoFaceButPoleFacesSpanningMoreThanHalf) {
  for (SurfaceKind s : {SurfaceKind::Sphere, SurfaceKind::Cylinder}) {
    const Mesh mesh = s == SurfaceKind::Sphere ? meshes::icosphere(3) : meshes::cylinder(20, 3, 1, 2, true);
    const Projection p = project(mesh, optionsFor(s));
    EXPECT_GT(p.summary.straddlingFaces, 0u);
    for (std::size_t f = 0; f < p.mesh.faceCount(); ++f) {
      if (!p.uv.faceHas(f, kFacePole)) { EXPECT_LE(maxUSpan(p.uv, f), 0.5) << f; }
      for (int k = 0; k < 3; ++k) {
        EXPECT_GE(p.uv.uv[3 * f + k].x(), 0.0);
        EXPECT_LT(p.uv.uv[3 * f + k].x(), 1.5);
      }
    }
  }
}

TEST(Project, ShiftGivesTheTwoSidesOfASeamEdgeUsThatDifferByExactlyOne) {
  const Mesh mesh = meshes::latLongSphere(32, 16);
  const Projection p = project(mesh, optionsFor(SurfaceKind::Sphere));
  // The seam column: vertices with y == 0 and x > 0. Every corner at such a vertex carries
  // u == 0 or u == 1 exactly, and both values occur.
  std::set<double> seamUs;
  for (std::size_t f = 0; f < p.mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Vec3& q = mesh.positions[mesh.triangles[f][k]];
      if (q.y() == 0.0 && q.x() > 0.0) seamUs.insert(p.uv.uv[3 * f + k].x());
    }
  EXPECT_EQ(seamUs, (std::set<double>{0.0, 1.0}));
  // The seam meridian runs over 16 stacks: 16 edges from pole to pole, each 2 sin(pi/32) long.
  const SeamEdges seams = classifySeamEdges(p.mesh, p.uv);
  EXPECT_EQ(seams.wrapEdges, 16u);
  EXPECT_EQ(seams.cutEdges, 0u);
  EXPECT_NEAR(seams.length(), 16 * 2 * std::sin(kPi / 32), 1e-12);
  EXPECT_EQ(p.summary.straddlingFaces, 2u * 15u);
}

double triangleArea(const Mesh& m, std::size_t f) {
  const Triangle& t = m.triangles[f];
  return 0.5 * triangleAreaNormal(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]).norm();
}

TEST(Project, CutKeepsEveryUInsideTheUnitIntervalAndThePiecesTileTheTriangles) {
  const Mesh mesh = meshes::icosphere(2);
  ProjectorOptions o = optionsFor(SurfaceKind::Sphere);
  o.seam = SeamMode::Cut;
  const Projection p = project(mesh, o);
  const Projection shifted = project(mesh, optionsFor(SurfaceKind::Sphere));
  EXPECT_GT(p.summary.addedVertices, 0u);
  EXPECT_EQ(p.mesh.faceCount(), mesh.faceCount() + p.summary.addedFaces);
  EXPECT_EQ(p.mesh.vertexCount(), mesh.vertexCount() + p.summary.addedVertices);
  for (const Vec2& uv : p.uv.uv) {
    EXPECT_GE(uv.x(), 0.0);
    EXPECT_LE(uv.x(), 1.0);
  }
  // Total area unchanged: the pieces tile the triangles they replace.
  double before = 0, after = 0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) before += triangleArea(mesh, f);
  for (std::size_t f = 0; f < p.mesh.faceCount(); ++f) after += triangleArea(p.mesh, f);
  EXPECT_NEAR(after, before, 1e-12 * before);
  // New vertices lie on the seam half-plane y = 0, x > 0.
  for (std::size_t v = mesh.vertexCount(); v < p.mesh.vertexCount(); ++v) {
    EXPECT_NEAR(p.mesh.positions[v].y(), 0.0, 1e-12);
    EXPECT_GT(p.mesh.positions[v].x(), 0.0);
  }
  // The cut's seam is where shift's was: one seam edge per cut triangle edge on the seam.
  EXPECT_EQ(p.summary.straddlingFaces, shifted.summary.straddlingFaces);
  EXPECT_GT(classifySeamEdges(p.mesh, p.uv).wrapEdges, 0u);
}

TEST(Project, FanGivesEachPoleCornerTheMeanUOfTheOtherCorners) {
  const Mesh mesh = meshes::latLongSphere(8, 4);
  const Projection p = project(mesh, optionsFor(SurfaceKind::Sphere));
  EXPECT_EQ(p.summary.poleVertices, 2u);
  EXPECT_EQ(p.summary.poleFaces, 16u);
  std::size_t checked = 0;
  for (std::size_t f = 0; f < p.mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Vec3& q = mesh.positions[mesh.triangles[f][k]];
      if (q.x() != 0.0 || q.y() != 0.0) continue;
      const double mean = (p.uv.uv[3 * f + (k + 1) % 3].x() + p.uv.uv[3 * f + (k + 2) % 3].x()) / 2;
      EXPECT_DOUBLE_EQ(p.uv.uv[3 * f + k].x(), mean);
      EXPECT_EQ(p.uv.uv[3 * f + k].y(), q.z() > 0 ? 1.0 : 0.0);
      ++checked;
    }
  EXPECT_EQ(checked, 16u);
}

TEST(Project, PoleNoneGivesPoleCornersUZero) {
  const Mesh mesh = meshes::latLongSphere(8, 4);
  ProjectorOptions o = optionsFor(SurfaceKind::Sphere);
  o.pole = PoleMode::None;
  const Projection p = project(mesh, o);
  for (std::size_t f = 0; f < p.mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Vec3& q = mesh.positions[mesh.triangles[f][k]];
      if (q.x() == 0.0 && q.y() == 0.0) { EXPECT_EQ(p.uv.uv[3 * f + k].x(), 0.0); }
    }
}

TEST(Project, SeamNoneKeepsTheRawStraddlingFaces) {
  ProjectorOptions o = optionsFor(SurfaceKind::Sphere);
  o.seam = SeamMode::None;
  const Projection p = project(meshes::latLongSphere(16, 8), o);
  EXPECT_EQ(p.summary.straddlingFaces, 2u * 7u);
  EXPECT_EQ(classifySeamEdges(p.mesh, p.uv).length(), 0.0);
  for (const Vec2& uv : p.uv.uv) EXPECT_LT(uv.x(), 1.0);
}

TEST(Project, PoleFacesIncludeFacesEnclosingTheAxisWithoutAPoleVertex) {
  // One triangle around the z axis, no vertex on it.
  Mesh mesh;
  mesh.positions = {{1, 0, 0.5}, {-0.5, 0.8, 0.5}, {-0.5, -0.8, 0.5}};
  mesh.triangles = {{0, 1, 2}};
  ProjectorOptions o = optionsFor(SurfaceKind::Sphere);
  o.placement.fit = Fit::None;
  const Projection p = project(mesh, o);
  EXPECT_TRUE(p.uv.faceHas(0, kFacePole));
  EXPECT_EQ(p.summary.poleVertices, 0u);
  EXPECT_EQ(p.summary.poleFaces, 1u);
}

TEST(Project, CylinderCapsAreMappedPlanarAndFlagged) {
  const Mesh mesh = meshes::cylinder(16, 2, 1.0, 2.0, true);  // radius 1, z in [0, 2]: the fit moves z to [0, 1]
  ProjectorOptions o = optionsFor(SurfaceKind::Cylinder);
  o.cylinderCaps = true;
  const Projection beside = project(mesh, o);
  o.capLayout = CapLayout::Stacked;
  const Projection stacked = project(mesh, o);
  for (const Projection* p : {&beside, &stacked}) {
    EXPECT_EQ(p->summary.capFaces, 32u);
    EXPECT_EQ(p->summary.poleFaces, 0u);
  }
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Vec3& q = mesh.positions[mesh.triangles[f][k]];
      const Vec2 b = beside.uv.uv[3 * f + k], s = stacked.uv.uv[3 * f + k];
      if (!beside.uv.faceHas(f, kFaceCap)) {  // the side: v = z / 2 beside the caps, z stacked
        EXPECT_NEAR(s.y(), q.z() / 2, 1e-15);
        EXPECT_NEAR(b.y(), q.z() / 4, 1e-15);
        EXPECT_EQ(b.x(), s.x());
        continue;
      }
      const bool top = q.z() > 1.0;
      const double mirror = top ? 1.0 : -1.0;  // the bottom cap reads unmirrored from below
      EXPECT_NEAR(s.x(), (mirror * q.x() + 1) / 2, 1e-15);
      EXPECT_NEAR(s.y(), (q.y() + 1) / 2, 1e-15);
      // Beside: the top cap in [0, 1/2] x [1/2, 1], the bottom cap in [1/2, 1] x [1/2, 1].
      EXPECT_NEAR(b.x(), (top ? 0.0 : 0.5) + (mirror * q.x() + 1) / 4, 1e-15);
      EXPECT_NEAR(b.y(), 0.5 + (q.y() + 1) / 4, 1e-15);
    }
  // Without caps the cap centres are poles.
  EXPECT_EQ(project(mesh, optionsFor(SurfaceKind::Cylinder)).summary.poleVertices, 2u);
}

TEST(Project, CylinderFitGivesRadiusOneAndHeightToTheUnitInterval) {
  Mesh mesh = meshes::cylinder(12, 3, 2.0, 5.0, false);
  for (Vec3& p : mesh.positions) p += Vec3(10, -3, 7);
  const Projection p = project(mesh, optionsFor(SurfaceKind::Cylinder));
  double vMin = INFINITY, vMax = -INFINITY;
  for (const Vec2& uv : p.uv.uv) vMin = std::min(vMin, uv.y()), vMax = std::max(vMax, uv.y());
  EXPECT_NEAR(vMin, 0.0, 1e-15);
  EXPECT_NEAR(vMax, 1.0, 1e-15);
  for (const Vec3& q : mesh.positions) EXPECT_NEAR((p.localFromObject * q).head<2>().norm(), 1.0, 1e-12);
}

TEST(Project, PlaneBoxFitMapsTheExtentToTheUnitSquare) {
  Mesh mesh = meshes::planeGrid(4, 4, 3.0, 1.5);
  for (Vec3& p : mesh.positions) p += Vec3(-7, 2, 1);
  const Projection p = project(mesh, optionsFor(SurfaceKind::Plane));
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Vec3& q = mesh.positions[mesh.triangles[f][k]];
      EXPECT_NEAR(p.uv.uv[3 * f + k].x(), (q.x() + 8.5) / 3.0, 1e-15);
      EXPECT_NEAR(p.uv.uv[3 * f + k].y(), (q.y() - 1.25) / 1.5, 1e-15);
    }
}

TEST(Project, BoxFitAxisChoosesWhichObjectAxisBecomesLocalZ) {
  Mesh mesh = meshes::planeGrid(2, 2, 2.0, 2.0);  // in z = 0
  for (Vec3& p : mesh.positions) p = Vec3(p.z(), p.x(), p.y());  // now in x = 0: y = old x, z = old y
  ProjectorOptions o = optionsFor(SurfaceKind::Plane);
  o.placement.axis = 0;  // project along x: local (x, y, z) = object (y, z, x)
  const Projection p = project(mesh, o);
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Vec3& q = mesh.positions[mesh.triangles[f][k]];
      EXPECT_NEAR(p.uv.uv[3 * f + k].x(), (q.y() + 1) / 2, 1e-15);
      EXPECT_NEAR(p.uv.uv[3 * f + k].y(), (q.z() + 1) / 2, 1e-15);
    }
}

TEST(Project, SphereFitPutsTheFarthestVertexAtRadiusOne) {
  Mesh mesh = meshes::icosphere(1, 3.0);
  for (Vec3& p : mesh.positions) p += Vec3(1, 2, 3);
  const Projection p = project(mesh, optionsFor(SurfaceKind::Sphere));
  double largest = 0;
  for (const Vec3& q : mesh.positions) largest = std::max(largest, (p.localFromObject * q).norm());
  EXPECT_NEAR(largest, 1.0, 1e-15);
}

TEST(Project, CubeFitMapsTheBoxToMinusOneOne) {
  Mesh mesh = meshes::cube(2);
  for (Vec3& p : mesh.positions) p = Vec3(3 * p.x() + 1, 0.5 * p.y(), 2 * p.z() - 4);
  const Projection p = project(mesh, optionsFor(SurfaceKind::Cube));
  for (const Vec3& q : mesh.positions) EXPECT_LE((p.localFromObject * q).cwiseAbs().maxCoeff(), 1.0 + 1e-15);
  for (const Vec2& uv : p.uv.uv) {
    EXPECT_GE(uv.minCoeff(), -1e-15);
    EXPECT_LE(uv.maxCoeff(), 1.0 + 1e-15);
  }
  // Box mapping of the unit cube: each face's vertices land on its own face; w is the face id.
  EXPECT_EQ(p.uv.w.size(), p.uv.uv.size());
}

TEST(Project, PcaAndObbFitsFindTheLongAxisOfARotatedCylinder) {
  Mesh mesh = meshes::cylinder(24, 6, 0.5, 6.0, true);
  const Mat3 rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
  for (Vec3& p : mesh.positions) p = rotation * p + Vec3(4, 5, 6);
  const Vec3 axis = rotation * Vec3::UnitZ();
  for (Fit fit : {Fit::Pca, Fit::Obb}) {
    ProjectorOptions o = optionsFor(SurfaceKind::Cylinder);
    o.placement.fit = fit;
    const Projection p = project(mesh, o);
    const Vec3 localZ = p.localFromObject.linear().row(2).normalized();
    EXPECT_NEAR(std::fabs(localZ.dot(axis)), 1.0, 1e-6) << int(fit);
    // The side maps to the cylinder: v spans [0, 1] along the axis.
    double vMin = INFINITY, vMax = -INFINITY;
    for (const Vec2& uv : p.uv.uv) vMin = std::min(vMin, uv.y()), vMax = std::max(vMax, uv.y());
    EXPECT_NEAR(vMin, 0.0, 1e-9);
    EXPECT_NEAR(vMax, 1.0, 1e-9);
  }
}

// A lat-long ellipsoid of 3, 2, 1 whose every vertex (about 180 k) is on the convex hull: the oriented
// box is searched on at most 2048 of the hull's vertices (placement_cgal.cpp), and still finds the
// rotated axes; once searched on all of them it took 19 s. A cancellation request stops it.
TEST(Placement, ObbOfAMeshWithAHugeHullFindsItsAxes) {
  Mesh mesh = meshes::latLongSphere(600, 300);
  const Mat3 rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
  for (Vec3& p : mesh.positions) p = rotation * Vec3(3 * p.x(), 2 * p.y(), p.z()) + Vec3(4, 5, 6);
  const Mat3 axes = orientedBoxAxes(mesh.positions);
  for (int r = 0; r < 3; ++r)  // rows by decreasing extent: the 3, the 2, the 1 axis
    EXPECT_NEAR(std::fabs(axes.row(r).dot(rotation.col(r))), 1.0, 1e-3) << r;
  requestCancel();
  EXPECT_THROW(orientedBoxAxes(mesh.positions), Cancelled);
  clearCancel();
}

TEST(Project, ExplicitFrameSetsCenterAxisReferenceAndScale) {
  Mesh mesh;
  mesh.positions = {{5, 2, 0}, {3, 4, 0}, {3, 2, 2}};
  mesh.triangles = {{0, 1, 2}};
  ProjectorOptions o = optionsFor(SurfaceKind::Plane);
  o.placement.frame = ExplicitFrame{Vec3(3, 2, 0), Vec3(0, 0, 1), Vec3(0, 1, 0), 2.0};
  // local x = object y, local y = z x x = -object x, scaled by 1/2 about (3, 2, 0)
  const Projection p = project(mesh, o);
  EXPECT_TRUE(p.uv.uv[0].isApprox(Vec2(0, -1)));
  EXPECT_TRUE(p.uv.uv[1].isApprox(Vec2(1, 0)));
  EXPECT_TRUE(p.uv.uv[2].isApprox(Vec2(0, 0)));
  o.placement.frame->refDir = Vec3(0, 0, 3);
  EXPECT_THROW(project(mesh, o), UsageError);
  o.placement.frame->refDir = Vec3(1, 0, 0);
  o.placement.frame->scale = 0;
  EXPECT_THROW(project(mesh, o), UsageError);
}

TEST(Project, ReflectionWithoutAnEyeIsAUsageError) {
  ProjectorOptions o = optionsFor(SurfaceKind::Sphere, RayKind::Reflection);
  o.eye.reset();
  EXPECT_THROW(project(meshes::icosphere(0), o), UsageError);
}

TEST(UvTransform, FlipsThenScalesThenRotatesAboutTheCentreThenOffsets) {
  UvTransform t;
  t.flipU = true;
  t.scale = Vec2(2, 1);
  t.rotateDegrees = 90;
  t.offset = Vec2(10, 20);
  // (0.25, 0) -> flip (0.75, 0) -> scale (1.5, 0) -> about (0.5,0.5): d = (1, -0.5),
  // rotated 90 degrees: (0.5, 1) -> (1, 1.5) -> offset (11, 21.5)
  EXPECT_TRUE(t.apply(Vec2(0.25, 0)).isApprox(Vec2(11, 21.5), 1e-15));
  EXPECT_TRUE(UvTransform{}.isIdentity());
}

TEST(Project, AppliesTheUvTransformAfterTheSeamRepair) {
  ProjectorOptions o = optionsFor(SurfaceKind::Sphere);
  o.uvTransform.offset = Vec2(3, 0);
  const Mesh mesh = meshes::latLongSphere(8, 4);
  const Projection plain = project(mesh, optionsFor(SurfaceKind::Sphere));
  const Projection moved = project(mesh, o);
  for (std::size_t i = 0; i < plain.uv.uv.size(); ++i) EXPECT_EQ(moved.uv.uv[i], plain.uv.uv[i] + Vec2(3, 0));
}

TEST(Project, AUvTransformThatOverflowsFlagsTheCornersInvalidInsteadOfWritingInfinity) {
  ProjectorOptions o = optionsFor(SurfaceKind::Plane);
  o.placement.fit = Fit::None;
  o.uvTransform.scale = Vec2(1e308, 1);
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {100, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}};
  const Projection p = project(mesh, o);
  EXPECT_EQ(p.uv.uv[1], Vec2::Zero());
  EXPECT_EQ(p.uv.cornerInvalid[1], kCornerNotFinite);
  EXPECT_EQ(p.summary.invalidCorners[kCornerNotFinite], 1u);
  EXPECT_TRUE(p.uv.faceHas(0, kFaceInvalid));
  EXPECT_EQ(p.summary.invalidVertexList, std::vector<int>{1});
  EXPECT_EQ(p.uv.uv[2], Vec2(0, 1));
}

TEST(Project, GluPresetPutsTheSeamOnPlusY) {
  ProjectorOptions o = optionsFor(SurfaceKind::Sphere);
  o.spherePreset = SpherePreset::Glu;
  o.placement.fit = Fit::None;
  Mesh mesh;
  mesh.positions = {{0, 1, 0}, {1, 0, 0}, {0, -1, 0}, {-1, 0, 0}, {0, 0, 1}};
  mesh.triangles = {{1, 0, 4}, {2, 1, 4}, {3, 2, 4}, {0, 3, 4}};
  const Projection p = project(mesh, o);
  EXPECT_EQ(p.uv.uv[3 * 1 + 1].x(), 0.25);  // +x
  EXPECT_EQ(p.uv.uv[3 * 1 + 0].x(), 0.5);   // -y
  // The face from -x to +y straddles the seam: +y carries u = 1 there.
  EXPECT_EQ(p.uv.uv[3 * 3 + 0].x(), 1.0);
  EXPECT_EQ(p.uv.uv[3 * 3 + 1].x(), 0.75);
}

// ---- Numerical extremes ----

TEST(Project, PlusAndMinusZeroOnTheSeamGetTheSameU) {
  Mesh mesh;
  mesh.positions = {{1, 0.0, 0.1}, {1, -0.0, -0.1}, {0.5, 0.5, 0}, {0.5, -0.5, 0}};
  mesh.triangles = {{0, 2, 1}, {1, 3, 0}};
  ProjectorOptions o = optionsFor(SurfaceKind::Sphere);
  o.placement.fit = Fit::None;
  const Projection p = project(mesh, o);
  for (int corner : {0, 2}) EXPECT_EQ(p.uv.uv[corner].x(), 0.0);  // face 0 touches only u >= 0
  for (const Vec2& uv : p.uv.uv) EXPECT_FALSE(std::signbit(uv.x()));
}

TEST(Project, StaysFiniteForTinyAndHugeCoordinates) {
  for (double scale : {1e-30, 1e30, 1e-300, 1e300}) {
    Mesh mesh = meshes::latLongSphere(12, 6);
    for (Vec3& p : mesh.positions) p *= scale;
    for (SurfaceKind s : kSurfaces) {
      ProjectorOptions o = optionsFor(s);
      o.placement.fit = Fit::None;  // no rescaling: the formulas themselves see the extremes
      const Projection p = project(mesh, o);
      for (std::size_t i = 0; i < p.uv.uv.size(); ++i) {
        ASSERT_TRUE(p.uv.uv[i].allFinite()) << scale << " " << int(s);
        if (s == SurfaceKind::Sphere || s == SurfaceKind::Cylinder) {
          EXPECT_GE(p.uv.uv[i].x(), 0.0);
          EXPECT_LT(p.uv.uv[i].x(), 1.5);
        }
      }
      if (s == SurfaceKind::Sphere) { EXPECT_EQ(p.summary.poleVertices, 2u) << scale; }
    }
  }
}

long double turnFractionLong(long double y, long double x) {
  long double theta = std::atan2(y, x);
  if (theta < 0) theta += 2 * 3.141592653589793238462643383279502884L;
  return theta / (2 * 3.141592653589793238462643383279502884L);
}

TEST(Project, AgreesWithALongDoubleEvaluationFarFromTheProjectorCentre) {
  // A unit sphere 1e6 away from an explicit projector centre: well conditioned, since the
  // formulas see the difference, which is exact in double here.
  Mesh mesh = meshes::latLongSphere(16, 8);
  const Vec3 offset(1e6, -1e6, 5e5);
  for (Vec3& p : mesh.positions) p += offset;
  ProjectorOptions o = optionsFor(SurfaceKind::Sphere);
  o.placement.frame = ExplicitFrame{offset, Vec3::UnitZ(), Vec3::UnitX(), 1.0};
  const Projection p = project(mesh, o);
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    if (p.uv.faceHas(f, kFacePole)) continue;
    for (int k = 0; k < 3; ++k) {
      const Vec3& q = mesh.positions[mesh.triangles[f][k]];
      const long double x = (long double)q.x() - (long double)offset.x();
      const long double y = (long double)q.y() - (long double)offset.y();
      const long double z = (long double)q.z() - (long double)offset.z();
      const long double u = turnFractionLong(y, x);
      const long double v = 1.0L - std::atan2(std::hypot(x, y), z) / 3.141592653589793238462643383279502884L;
      const Vec2 uv = p.uv.uv[3 * f + k];
      const double wrapped = uv.x() >= 1.0 ? uv.x() - 1.0 : uv.x();
      EXPECT_NEAR(wrapped, (double)(u >= 1.0L ? u - 1.0L : u), 1e-12);
      EXPECT_NEAR(uv.y(), (double)v, 1e-12);
    }
  }
}

TEST(Project, ProjectorCentreFarFromAUnitMeshGivesFiniteUvs) {
  const Mesh mesh = meshes::icosphere(2);
  for (SurfaceKind s : kSurfaces)
    for (RayKind r : kRays) {
      ProjectorOptions o = optionsFor(s, r);
      o.placement.frame = ExplicitFrame{Vec3(1e6, 0, 0), Vec3::UnitZ(), Vec3::UnitX(), 1.0};
      const Projection p = project(mesh, o);
      for (const Vec2& uv : p.uv.uv) ASSERT_TRUE(uv.allFinite());
    }
}

TEST(Project, PointsOnTheAxisArePolesNotNaN) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0.5}, {0.0, -0.0, -0.5}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 2, 3}, {1, 3, 2}};
  for (SurfaceKind s : {SurfaceKind::Sphere, SurfaceKind::Cylinder}) {
    ProjectorOptions o = optionsFor(s);
    o.placement.fit = Fit::None;
    const Projection p = project(mesh, o);
    EXPECT_EQ(p.summary.poleVertices, 2u);
    for (const Vec2& uv : p.uv.uv) EXPECT_TRUE(uv.allFinite());
  }
}

TEST(Project, TheOriginUnderARadialProjectionIsInvalidNotNaN) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}};
  ProjectorOptions o = optionsFor(SurfaceKind::Sphere);
  o.placement.fit = Fit::None;
  const Projection p = project(mesh, o);
  EXPECT_EQ(p.summary.invalidVertices, 1u);
  EXPECT_EQ(p.summary.invalidVertexList, std::vector<int>{0});
  EXPECT_TRUE(p.uv.faceHas(0, kFaceInvalid));
  EXPECT_EQ(p.uv.uv[0], Vec2::Zero());
}

TEST(Placement, GivenSpreadAxesFitAsTheComputedOnes) {
  Mesh mesh = meshes::torus(24, 12, 2.0, 0.5);
  for (Vec3& p : mesh.positions) p = Vec3(p.x() + 0.3 * p.z(), 1.5 * p.y(), p.z() - 0.2 * p.x());
  for (Fit fit : {Fit::Pca, Fit::Obb})
    for (SurfaceKind surface : {SurfaceKind::Plane, SurfaceKind::Cylinder, SurfaceKind::Sphere, SurfaceKind::Cube}) {
      PlacementOptions computed;
      computed.fit = fit;
      PlacementOptions given = computed;
      given.spreadAxes = fit == Fit::Pca ? principalAxes(mesh.positions) : orientedBoxAxes(mesh.positions);
      EXPECT_TRUE(fitPlacement(mesh.positions, surface, given).isApprox(fitPlacement(mesh.positions, surface, computed), 0.0))
          << int(fit) << " " << int(surface);
    }
  // Axes given are used as given: with the identity, object x (the "largest spread") becomes the
  // sphere's axis, whatever the points' own spread.
  PlacementOptions identity;
  identity.fit = Fit::Pca;
  identity.spreadAxes = Mat3::Identity();
  const Vec3 x = fitPlacement(mesh.positions, SurfaceKind::Sphere, identity).linear() * Vec3::UnitX();
  EXPECT_EQ(x.head<2>(), Vec2::Zero());
  EXPECT_GT(x.z(), 0.0);
}

TEST(Placement, CenterFitMovesTheBoxCentreToTheOriginAndKeepsAxesAndUnits) {
  const std::vector<Vec3> positions = {{-1, -2, 0}, {3, 2, 4}};
  PlacementOptions o;
  o.fit = Fit::Center;
  for (SurfaceKind surface : {SurfaceKind::Plane, SurfaceKind::Cylinder, SurfaceKind::Sphere, SurfaceKind::Cube}) {
    const Affine3 frame = fitPlacement(positions, surface, o);
    EXPECT_EQ(frame.linear(), Mat3::Identity());
    EXPECT_EQ(frame * Vec3(1, 0, 2), Vec3::Zero());
  }
  o.axis = 1;  // object y becomes local z, by the bbox fit's cyclic permutation
  EXPECT_EQ(fitPlacement(positions, SurfaceKind::Sphere, o) * Vec3(1, 5, 2), Vec3(0, 0, 5));
}

TEST(Placement, QuarterTurnsAreExact) {
  PlacementOptions o;
  o.fit = Fit::None;
  // A turn by a puts the point at azimuth a on local +x; no 6e-17 residue in the other components.
  const std::pair<double, Vec3> turns[] = {{90, Vec3(0, 1, 0)},  {180, Vec3(-1, 0, 0)}, {270, Vec3(0, -1, 0)},
                                           {-90, Vec3(0, -1, 0)}, {450, Vec3(0, 1, 0)},  {-360, Vec3(1, 0, 0)}};
  for (const auto& [degrees, direction] : turns) {
    o.turnDegrees = degrees;
    EXPECT_EQ(fitPlacement({}, SurfaceKind::Sphere, o) * direction, Vec3(1, 0, 0)) << degrees;
  }
  o.turnDegrees = 45;
  EXPECT_TRUE((fitPlacement({}, SurfaceKind::Sphere, o) * Vec3(1, 1, 0).normalized()).isApprox(Vec3(1, 0, 0), 1e-15));
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param
