// The camera ("project from view") projector: gluLookAt + gluPerspective, u = s/q, v = t/q, pinned
// to hand-computed points, its invalid corners, and through project(), mapVertices and PointMapping.
#include "param/camera_projector.h"

#include <gtest/gtest.h>

#include "core/seam_edges.h"

#include <cmath>
#include <limits>

#include "core/error.h"
#include "param/projector.h"

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

// eye (0, 0, 5) looking at the origin, fovy 90 (cot 45 = 1), aspect 1: x_c = x, y_c = y, w_c = 5 - z.
CameraProjector frontCamera() {
  CameraProjector c;
  c.eye = Vec3(0, 0, 5);
  c.center = Vec3::Zero();
  c.up = Vec3::UnitY();
  c.fovyDegrees = 90.0;
  c.aspect = 1.0;
  return c;
}

ProjectorOptions cameraOptions(const CameraProjector& camera) {
  ProjectorOptions o;
  o.surface = SurfaceKind::Camera;
  o.camera = camera;
  return o;
}

TEST(CameraProjector, HandComputedPoints) {
  const CameraTransform t(frontCamera());
  // (1, 0, 0): x_c = 1, y_c = 0, w_c = 5: s = 3, t = 2.5, q = 5; u = 0.5 + 0.5 * 1/5 = 0.6.
  const Vec4 h = t.homogeneous(Vec3(1, 0, 0));
  EXPECT_NEAR(h[0], 3.0, 1e-15);
  EXPECT_NEAR(h[1], 2.5, 1e-15);
  EXPECT_EQ(h[2], 0.0);
  EXPECT_NEAR(h[3], 5.0, 1e-15);
  const VertexUv a = cameraVertexUv(t, Vec3(1, 0, 0));
  EXPECT_EQ(a.state, CornerState::Ok);
  EXPECT_NEAR(a.uv.x(), 0.6, 1e-15);
  EXPECT_NEAR(a.uv.y(), 0.5, 1e-15);
  // (0.5, -1, 3): w_c = 2: u = 0.5 + 0.25/2 = 0.625, v = 0.5 - 0.5/2 = 0.25.
  const VertexUv b = cameraVertexUv(t, Vec3(0.5, -1, 3));
  EXPECT_NEAR(b.uv.x(), 0.625, 1e-15);
  EXPECT_NEAR(b.uv.y(), 0.25, 1e-15);
  // The eye's axis maps to the image centre at every depth.
  EXPECT_NEAR(cameraVertexUv(t, Vec3(0, 0, -100)).uv.x(), 0.5, 1e-15);
}

TEST(CameraProjector, FovyScalesBy_cot_half_fovy) {
  CameraProjector c = frontCamera();
  c.fovyDegrees = 60.0;  // cot 30 = sqrt(3)
  const VertexUv a = cameraVertexUv(CameraTransform(c), Vec3(0, 1, 0));
  EXPECT_NEAR(a.uv.x(), 0.5, 1e-15);
  EXPECT_NEAR(a.uv.y(), 0.5 + 0.5 * std::sqrt(3.0) / 5.0, 1e-15);
}

TEST(CameraProjector, AspectTwoHalvesTheSpreadOfU) {
  CameraProjector c = frontCamera();
  c.aspect = 2.0;
  const VertexUv a = cameraVertexUv(CameraTransform(c), Vec3(1, 1, 0));
  EXPECT_NEAR(a.uv.x(), 0.5 + 0.5 * 0.5 / 5.0, 1e-15);  // 0.55
  EXPECT_NEAR(a.uv.y(), 0.6, 1e-15);                    // v keeps its spread
}

TEST(CameraProjector, UpAlongXRotatesTheImage) {
  CameraProjector c = frontCamera();
  c.up = Vec3::UnitX();  // s = f x up = (0, -1, 0), u = s x f = (1, 0, 0)
  const VertexUv a = cameraVertexUv(CameraTransform(c), Vec3(1, 0, 0));
  EXPECT_NEAR(a.uv.x(), 0.5, 1e-15);
  EXPECT_NEAR(a.uv.y(), 0.6, 1e-15);
  const VertexUv b = cameraVertexUv(CameraTransform(c), Vec3(0, 1, 0));
  EXPECT_NEAR(b.uv.x(), 0.4, 1e-15);  // object +y is the picture's -x
  EXPECT_NEAR(b.uv.y(), 0.5, 1e-15);
}

TEST(CameraProjector, BehindOrOnTheEyePlaneIsInvalidBehind) {
  const CameraTransform t(frontCamera());
  for (const Vec3& p : {Vec3(0, 0, 6), Vec3(3, -2, 5), Vec3(0, 0, 5)}) {  // w_c = -1, 0, 0
    const VertexUv a = cameraVertexUv(t, p);
    EXPECT_EQ(a.state, CornerState::Invalid);
    EXPECT_EQ(a.reason, kCornerBehind);
    EXPECT_EQ(a.uv, Vec2::Zero());
  }
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(cameraVertexUv(t, Vec3(inf, 0, 0)).reason, kCornerNotFinite);
}

TEST(CameraProjector, OutsideTheFrustumSidesKeepsItsUv) {
  // (10, 0, 0): x_ndc = 2, u = 1.5; as Blender's Project from View, nothing is clipped.
  const VertexUv a = cameraVertexUv(CameraTransform(frontCamera()), Vec3(10, 0, 0));
  EXPECT_EQ(a.state, CornerState::Ok);
  EXPECT_NEAR(a.uv.x(), 1.5, 1e-15);
}

TEST(CameraProjector, BadCamerasAreUsageErrorsNamingTheOption) {
  const auto message = [](CameraProjector c, const CameraOptionNames& names = {}) {
    try {
      checkCameraProjector(c, names);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CameraProjector c = frontCamera();
  c.center = c.eye;
  EXPECT_EQ(message(c).rfind("--center:", 0), 0u) << message(c);
  c = frontCamera();
  c.up = Vec3(0, 0, 2);  // along the view direction
  EXPECT_EQ(message(c).rfind("--up:", 0), 0u) << message(c);
  c.up = Vec3::Zero();
  EXPECT_EQ(message(c).rfind("--up:", 0), 0u);
  c = frontCamera();
  for (double fovy : {0.0, 180.0, -10.0, std::nan("")}) {
    c.fovyDegrees = fovy;
    EXPECT_EQ(message(c).rfind("--fovy:", 0), 0u) << fovy;
  }
  c = frontCamera();
  CameraOptionNames render;
  render.aspect = "--proj-aspect";
  for (double aspect : {0.0, -1.0, std::numeric_limits<double>::infinity()}) {
    c.aspect = aspect;
    EXPECT_EQ(message(c, render).rfind("--proj-aspect:", 0), 0u) << aspect;
  }
  c = frontCamera();
  c.eye.x() = std::nan("");
  EXPECT_EQ(message(c).rfind("--eye:", 0), 0u);
  EXPECT_EQ(message(frontCamera()), "no error");
}

// A triangle in front (z = 0), one straddling the eye plane: project() gives per-corner (u, v) =
// (s/q, t/q), the behind corners invalid with their reason and no seam, pole or placement.
TEST(CameraProjector, ProjectMapsEveryCornerByTheFormula) {
  Mesh mesh;
  mesh.positions = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, -1, 0), Vec3(0, 0, 7)};
  mesh.triangles = {{0, 1, 2}, {0, 1, 3}};
  const Projection p = project(mesh, cameraOptions(frontCamera()), 1);
  EXPECT_TRUE(p.localFromObject.matrix().isIdentity());
  const CameraTransform t(frontCamera());
  for (std::size_t f = 0; f < 2; ++f)
    for (int k = 0; k < 3; ++k) {
      const std::size_t c = 3 * f + std::size_t(k);
      const Vec3& x = mesh.positions[mesh.triangles[f][k]];
      if (x.z() > 5) {
        EXPECT_EQ(p.uv.cornerInvalid[c], kCornerBehind);
        continue;
      }
      const Vec4 h = t.homogeneous(x);
      EXPECT_EQ(p.uv.cornerInvalid[c], kCornerValid);
      EXPECT_EQ(p.uv.uv[c], Vec2(h[0] / h[3], h[1] / h[3]));
    }
  EXPECT_NEAR(p.uv.uv[0].x(), 0.6, 1e-15);
  EXPECT_TRUE(p.uv.faceHas(1, kFaceInvalid));
  EXPECT_FALSE(p.uv.faceHas(0, kFaceInvalid));
  EXPECT_EQ(p.summary.invalidCorners[kCornerBehind], 1u);
  EXPECT_EQ(p.summary.invalidVertices, 1u);
  const SeamEdges seams = classifySeamEdges(p.mesh, p.uv);
  EXPECT_EQ(seams.wrapEdges + seams.cutEdges + p.summary.poleVertices + p.summary.straddlingFaces, 0u);
}

TEST(CameraProjector, MapVerticesAndPointMappingAgreeWithProject) {
  const std::vector<Vec3> points = {Vec3(1, 0, 0), Vec3(0.25, -0.5, 2), Vec3(0, 0, 9)};
  std::vector<VertexUv> out;
  ProjectorOptions o = cameraOptions(frontCamera());
  Projector(o, Affine3::Identity()).mapVertices(points, {}, out, 2);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_NEAR(out[0].uv.x(), 0.6, 1e-15);
  EXPECT_NEAR(out[1].uv.x(), 0.5 + 0.125 / 3.0, 1e-15);
  EXPECT_NEAR(out[1].uv.y(), 0.5 - 0.25 / 3.0, 1e-15);
  EXPECT_EQ(out[2].reason, kCornerBehind);
  // Projector adds the UV transform: u -> 1 - u.
  o.uvTransform.flipU = true;
  const Projector mapping(o, Affine3::Identity());
  EXPECT_NEAR(mapping.at(points[0], Vec3::Zero()).uv.x(), 0.4, 1e-15);
  EXPECT_EQ(mapping.at(points[2], Vec3::Zero()).reason, kCornerBehind);
  EXPECT_FALSE(mapping.traits().wraps);
  EXPECT_FALSE(mapping.needsNormal());
  EXPECT_FALSE(sensibleBox(points, o, Affine3::Identity()));
}

TEST(CameraProjector, ProjectRejectsABadCamera) {
  CameraProjector c = frontCamera();
  c.fovyDegrees = 180.0;
  Mesh mesh;
  mesh.positions = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  mesh.triangles = {{0, 1, 2}};
  EXPECT_THROW(project(mesh, cameraOptions(c)), UsageError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param
