// Per-face distortion: hand-computed triangles, the statuses, and closed forms of the sphere,
// cylinder and plane projectors.
#include "analysis/distortion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "analysis/layout.h"
#include "meshes/generators.h"
#include "param/projector.h"

namespace uvtk::analysis {
namespace {
namespace UVTK_TEST_FILE {

// The unit right triangle, its UVs the images of (0, 0), (1, 0), (0, 1) under `map`.
template <class Map>
Layout rightTriangle(Map map) {
  return makeLayout({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}},
                    {map(Vec2(0, 0)), map(Vec2(1, 0)), map(Vec2(0, 1))});
}

void expectFinite(const FaceDistortion& f, double surfacePerUv) {
  for (double x : {f.area3d, f.areaUv, f.sigmaMax, f.sigmaMin, f.l2Stretch(), f.linfStretch(), f.angleDistortion(),
                   f.areaRatio(), f.areaDistortion(surfacePerUv)})
    EXPECT_TRUE(std::isfinite(x));
}

// UVs of planeGrid's vertices: (x, y), the plane projector's map with Fit::None.
Layout planeLayout(int nx, int ny) {
  const Mesh plane = meshes::planeGrid(nx, ny, double(nx), double(ny));
  std::vector<Vec2> uvs;
  for (const Triangle& t : plane.triangles)
    for (int v : t) uvs.push_back(plane.positions[v].head<2>());
  return makeLayout(plane.positions, plane.triangles, uvs);
}

TEST(MeasureFaces, IdentityIsIsometric) {
  const Layout l = rightTriangle([](const Vec2& p) { return p; });
  const FaceDistortion f = measureFaces(l.mesh, l.uv)[0];
  EXPECT_EQ(f.status, FaceStatus::Ok);
  EXPECT_DOUBLE_EQ(f.area3d, 0.5);
  EXPECT_DOUBLE_EQ(f.areaUv, 0.5);
  EXPECT_DOUBLE_EQ(f.sigmaMax, 1.0);
  EXPECT_DOUBLE_EQ(f.sigmaMin, 1.0);
  EXPECT_DOUBLE_EQ(f.l2Stretch(), 1.0);
  EXPECT_DOUBLE_EQ(f.linfStretch(), 1.0);
  EXPECT_DOUBLE_EQ(f.angleDistortion(), 1.0);
  EXPECT_DOUBLE_EQ(f.areaRatio(), 1.0);
  EXPECT_EQ(f.areaDistortion(1.0), 0.0);  // sum(A3) / sum(Auv) = 1
}

// The frame of the triangle's plane makes the measures independent of its placement in space.
TEST(MeasureFaces, IdentityOnATiltedTriangle) {
  const Mat3 rotation = Eigen::AngleAxisd(0.7, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
  Layout l = rightTriangle([](const Vec2& p) { return p; });
  for (Vec3& p : l.mesh.positions) p = rotation * p + Vec3(3, -1, 2);
  const FaceDistortion f = measureFaces(l.mesh, l.uv)[0];
  EXPECT_NEAR(f.sigmaMax, 1.0, 1e-14);
  EXPECT_NEAR(f.sigmaMin, 1.0, 1e-14);
  EXPECT_NEAR(f.angleDistortion(), 1.0, 1e-14);
  EXPECT_NEAR(f.areaRatio(), 1.0, 1e-14);
}

// UV = 2 x: s1 = s2 = 2, so G = g = 1/2 and L2 = Linf = 1/2; the area grows 4 times.
TEST(MeasureFaces, UniformScaleByTwo) {
  const Layout l = rightTriangle([](const Vec2& p) { return Vec2(2.0 * p); });
  const FaceDistortion f = measureFaces(l.mesh, l.uv)[0];
  EXPECT_EQ(f.status, FaceStatus::Ok);
  EXPECT_DOUBLE_EQ(f.sigmaMax, 2.0);
  EXPECT_DOUBLE_EQ(f.sigmaMin, 2.0);
  EXPECT_DOUBLE_EQ(f.l2Stretch(), 0.5);
  EXPECT_DOUBLE_EQ(f.linfStretch(), 0.5);
  EXPECT_DOUBLE_EQ(f.angleDistortion(), 1.0);
  EXPECT_DOUBLE_EQ(f.areaRatio(), 4.0);
  EXPECT_EQ(f.areaDistortion(0.25), 0.0);  // normalised by the mesh's own totals, sum(A3) / sum(Auv) = 1/4
  EXPECT_EQ(f.areaDistortion(1.0), 2.0);   // log2 of the area ratio itself
}

// UV = (x + y, y): J = [[1, 1], [0, 1]], singular values phi = (1 + sqrt 5)/2 and 1/phi.
TEST(MeasureFaces, ShearHasTheGoldenRatioAsSingularValues) {
  const Layout l = rightTriangle([](const Vec2& p) { return Vec2(p.x() + p.y(), p.y()); });
  const FaceDistortion f = measureFaces(l.mesh, l.uv)[0];
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  EXPECT_EQ(f.status, FaceStatus::Ok);
  EXPECT_NEAR(f.sigmaMax, phi, 1e-15);
  EXPECT_NEAR(f.sigmaMin, (std::sqrt(5.0) - 1.0) / 2.0, 1e-15);
  EXPECT_NEAR(f.angleDistortion(), phi * phi, 1e-14);
  EXPECT_NEAR(f.linfStretch(), phi, 1e-15);                // G = 1/s2 = phi
  EXPECT_NEAR(f.l2Stretch(), std::sqrt(1.5), 1e-15);       // (phi^2 + phi^-2)/2 = 3/2
  EXPECT_NEAR(f.areaRatio(), 1.0, 1e-15);                  // det J = 1: a shear keeps area
}

// One face of a 3 x 3 grid mirrored in u: the majority winding makes it the flipped one.
TEST(MeasureFaces, AMirroredFaceAmongUnmirroredOnesIsFlipped) {
  Layout l = planeLayout(3, 3);
  const std::size_t mirrored = 7;
  for (int k = 0; k < 3; ++k) l.uv.uv[3 * mirrored + k].x() *= -1.0;
  const FaceMeasures faces = measureFaces(l.mesh, l.uv);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    expectFinite(faces[f], okAreaTotals(faces).surfacePerUv());
    EXPECT_EQ(faces[f].status, f == mirrored ? FaceStatus::Flipped : FaceStatus::Ok);
    EXPECT_NEAR(faces[f].sigmaMin, f == mirrored ? -1.0 : 1.0, 1e-15);  // a mirror is an isometry
    EXPECT_NEAR(faces[f].angleDistortion(), 1.0, 1e-15);
    EXPECT_NEAR(faces[f].l2Stretch(), 1.0, 1e-15);
  }
}

// Degenerate and invalid faces get a status, their areas, and zeros, never NaN.
TEST(MeasureFaces, DegenerateAndInvalidFacesAreCountedApart) {
  Layout l = makeLayout({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {3, 0, 0}},
                        {{0, 1, 2}, {0, 1, 3}, {0, 1, 2}, {0, 1, 2}, {0, 1, 4}},
                        {{0, 0}, {1, 0}, {0, 1},          // ok
                         {0, 0}, {1, 0}, {0, 1},          // collinear positions: zero 3D area
                         {0, 0}, {1, 1}, {2, 2},          // collinear UVs: zero UV area
                         {0, 0}, {1, 0}, {0, 1},          // an invalid corner
                         {0, 0}, {1, 0}, {1, 1}});        // zero 3D area and a pole flag: zero area wins
  l.uv.cornerInvalid[3 * 3 + 1] = 1;
  l.uv.faceFlags[4] = kFacePole;
  const FaceMeasures faces = measureFaces(l.mesh, l.uv);
  const FaceStatus expected[] = {FaceStatus::Ok, FaceStatus::ZeroArea3d, FaceStatus::ZeroAreaUv, FaceStatus::Invalid,
                                 FaceStatus::ZeroArea3d};
  for (std::size_t f = 0; f < faces.size(); ++f) {
    EXPECT_EQ(faces[f].status, expected[f]) << f << ": " << toString(faces[f].status);
    expectFinite(faces[f], okAreaTotals(faces).surfacePerUv());
    if (f == 0) continue;
    EXPECT_EQ(faces[f].sigmaMax, 0.0);
    EXPECT_EQ(faces[f].l2Stretch(), 0.0);
    EXPECT_EQ(faces[f].angleDistortion(), 0.0);
  }
  EXPECT_EQ(faces[1].area3d, 0.0);
  EXPECT_DOUBLE_EQ(faces[1].areaUv, 0.5);
  EXPECT_DOUBLE_EQ(faces[2].area3d, 0.5);
  EXPECT_EQ(faces[2].areaUv, 0.0);
  EXPECT_EQ(faces[3].areaUv, 0.0);  // its UVs are placeholders

  // The face flag alone makes a face invalid, before any zero area.
  l.uv.cornerInvalid.assign(l.uv.uv.size(), 0);
  l.uv.faceFlags[1] = kFaceInvalid;
  EXPECT_EQ(measureFaces(l.mesh, l.uv)[1].status, FaceStatus::Invalid);
}

TEST(MeasureFaces, StatusNames) {
  EXPECT_STREQ(toString(FaceStatus::Ok), "ok");
  EXPECT_STREQ(toString(FaceStatus::ZeroArea3d), "zero_area_3d");
  EXPECT_STREQ(toString(FaceStatus::ZeroAreaUv), "zero_area_uv");
  EXPECT_STREQ(toString(FaceStatus::Flipped), "flipped");
  EXPECT_STREQ(toString(FaceStatus::Backfacing), "backfacing");
  EXPECT_STREQ(toString(FaceStatus::Invalid), "invalid");
  EXPECT_STREQ(toString(FaceStatus::PoleFace), "pole_face");
}

// The plane projector mirrors the far side of a closed mesh by design: given the direction it
// looks along, those faces are backfacing; without it they are flipped.
TEST(MeasureFaces, PlanarProjectionOfASphereMirrorsItsBackFaces) {
  param::ProjectorOptions o;
  o.surface = param::SurfaceKind::Plane;
  const param::Projection p = param::project(meshes::icosphere(2), o);
  const Vec3 direction = p.localFromObject.inverse().linear().col(2);
  auto count = [](const FaceMeasures& faces, FaceStatus status) {
    std::size_t n = 0;
    for (const FaceDistortion& f : faces) n += f.status == status;
    return n;
  };
  UvMap marked = p.uv;
  markTurnedAwayFaces(p.mesh, {direction, {}}, marked);
  const FaceMeasures seen = measureFaces(p.mesh, marked);
  const FaceMeasures blind = measureFaces(p.mesh, p.uv);
  EXPECT_EQ(count(seen, FaceStatus::Flipped), 0u);
  EXPECT_EQ(count(blind, FaceStatus::Backfacing), 0u);
  EXPECT_GT(count(seen, FaceStatus::Backfacing), p.mesh.faceCount() / 3);
  EXPECT_EQ(count(seen, FaceStatus::Backfacing) + count(seen, FaceStatus::Ok),
            count(blind, FaceStatus::Flipped) + count(blind, FaceStatus::Ok));
  for (std::size_t f = 0; f < seen.size(); ++f) {
    if (seen[f].status != FaceStatus::Backfacing) continue;
    const Triangle& t = p.mesh.triangles[f];
    const Vec3 n = triangleAreaNormal(p.mesh.positions[t[0]], p.mesh.positions[t[1]], p.mesh.positions[t[2]]);
    EXPECT_LT(n.dot(direction), 0.0);
    EXPECT_LT(seen[f].sigmaMin, 0.0);
  }
}

// The default sphere preset u = theta / 2 pi, v = 1 - phi / pi (docs/conventions.md §3) takes
// the area element sin(phi) dphi dtheta to du dv = dphi dtheta / (2 pi^2), so
// Auv / A3 -> 1 / (2 pi^2 sin phi); its singular values are 1 / (2 pi sin phi) along the
// parallel and 1 / pi along the meridian, so the angle distortion is max(2 sin phi, 1/(2 sin phi)).
// Each ok face (the pole faces are excluded) is compared with these at its centroid's polar angle.
// A face is half a quad of height h = pi / latitudes: its area follows the ring its base lies on,
// while its centroid lies h/3 from that ring, so the relative error is first order,
// (h/3) |cot phi|, whose area-weighted mean over the sphere is h/3. Measured (area ratio, angle):
//   16 x 8: 0.0885, 0.102;  32 x 16: 0.0538, 0.0554;  64 x 32: 0.0297, 0.0299;
//   128 x 64: 0.0156, 0.0156 (h/3 = 0.0164).
TEST(MeasureFaces, UnitSphereConvergesToTheClosedForm) {
  double previousArea = 1.0, previousAngle = 1.0, h = 0.0;
  for (int n : {16, 32, 64, 128}) {
    param::ProjectorOptions o;
    o.surface = param::SurfaceKind::Sphere;
    o.placement.fit = param::Fit::None;
    const param::Projection p = param::project(meshes::latLongSphere(n, n / 2), o);
    const FaceMeasures faces = measureFaces(p.mesh, p.uv);
    double weight = 0.0, areaError = 0.0, angleError = 0.0;
    std::size_t ok = 0, poles = 0;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      poles += faces[f].status == FaceStatus::PoleFace;
      if (faces[f].status != FaceStatus::Ok) continue;
      ++ok;
      const Triangle& t = p.mesh.triangles[f];
      const Vec3 c = (p.mesh.positions[t[0]] + p.mesh.positions[t[1]] + p.mesh.positions[t[2]]) / 3.0;
      const double sinPhi = std::sin(std::atan2(std::hypot(c.x(), c.y()), c.z()));
      const double area = 1.0 / (2.0 * kPi * kPi * sinPhi);
      const double angle = std::max(2.0 * sinPhi, 1.0 / (2.0 * sinPhi));
      weight += faces[f].area3d;
      areaError += faces[f].area3d * std::fabs(faces[f].areaRatio() / area - 1.0);
      angleError += faces[f].area3d * std::fabs(faces[f].angleDistortion() / angle - 1.0);
    }
    EXPECT_EQ(poles, std::size_t(2 * n));  // the fans around the two pole vertices
    EXPECT_EQ(ok, faces.size() - poles);
    areaError /= weight;
    angleError /= weight;
    std::printf("sphere %d x %d: mean relative error, area ratio %.3g, angle distortion %.3g\n", n, n / 2,
                areaError, angleError);
    EXPECT_LT(areaError, previousArea / 1.5);  // first order: about halved by each refinement
    EXPECT_LT(angleError, previousAngle / 1.5);
    previousArea = areaError;
    previousAngle = angleError;
    h = kPi / (n / 2);
  }
  EXPECT_NEAR(previousArea, h / 3, 0.1 * h / 3);
  EXPECT_NEAR(previousAngle, h / 3, 0.1 * h / 3);
}

// The open cylinder under the cylindrical projector (bbox fit: radius 1, height to v in [0, 1]):
// each quad of the 16-gon prism is a flat rectangle, chord 2 R sin(pi/16) wide and H/stacks
// high, mapped to a rectangle (1/16) x (1/stacks) wide and high. The scales are exactly
// su = (1/16) / (2 R sin(pi/16)) along the ring and sv = 1/H along the axis, the angle
// distortion their ratio; with H = 16 chords (the polygon's perimeter) the map is an isometry
// up to a uniform scale.
TEST(MeasureFaces, CylinderIsIsometricUpToTheFittedScales) {
  const int segments = 16;
  const double radius = 0.75, chord = 2.0 * radius * std::sin(kPi / segments);
  param::ProjectorOptions o;
  o.surface = param::SurfaceKind::Cylinder;
  for (double height : {2.0, segments * chord}) {  // the second: su = sv, angle distortion 1
    const param::Projection p = param::project(meshes::cylinder(segments, 3, radius, height, false), o);
    const double su = (1.0 / segments) / chord, sv = 1.0 / height;
    const FaceMeasures faces = measureFaces(p.mesh, p.uv);
    const double surfacePerUv = okAreaTotals(faces).surfacePerUv();
    for (const FaceDistortion& f : faces) {
      ASSERT_EQ(f.status, FaceStatus::Ok);
      EXPECT_NEAR(f.sigmaMax, std::max(su, sv), 1e-12);
      EXPECT_NEAR(f.sigmaMin, std::min(su, sv), 1e-12);
      EXPECT_NEAR(f.angleDistortion(), std::max(su, sv) / std::min(su, sv), 1e-12);
      EXPECT_NEAR(f.areaDistortion(surfacePerUv), 0.0, 1e-12);  // every face has the same area ratio
    }
  }
}

// planeGrid under the plane projector with Fit::None: UV = (x, y), an exact isometry.
TEST(MeasureFaces, PlaneProjectionWithoutFitIsExactlyIsometric) {
  param::ProjectorOptions o;
  o.surface = param::SurfaceKind::Plane;
  o.placement.fit = param::Fit::None;
  const param::Projection p = param::project(meshes::planeGrid(7, 5, 2.5, 1.5), o);
  const FaceMeasures faces = measureFaces(p.mesh, p.uv);
  const double surfacePerUv = okAreaTotals(faces).surfacePerUv();
  for (const FaceDistortion& f : faces) {
    ASSERT_EQ(f.status, FaceStatus::Ok);
    EXPECT_NEAR(f.sigmaMax, 1.0, 1e-12);
    EXPECT_NEAR(f.sigmaMin, 1.0, 1e-12);
    EXPECT_NEAR(f.l2Stretch(), 1.0, 1e-12);
    EXPECT_NEAR(f.linfStretch(), 1.0, 1e-12);
    EXPECT_NEAR(f.angleDistortion(), 1.0, 1e-12);
    EXPECT_NEAR(f.areaDistortion(surfacePerUv), 0.0, 1e-12);
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::analysis
