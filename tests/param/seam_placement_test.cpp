// The turn of a projector about its axis (PlacementOptions::turnDegrees) and the automatic seam
// placement that chooses it.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "meshes/generators.h"
#include "param/formulas.h"
#include "param/placement.h"
#include "param/projector.h"

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

// A band about the z axis covering the azimuths [from, to] in `segments` steps, radius 1, z in [-h, h].
Mesh band(double fromDegrees, double toDegrees, int segments, double h = 0.3) {
  Mesh mesh;
  for (int i = 0; i <= segments; ++i) {
    const double a = (fromDegrees + (toDegrees - fromDegrees) * i / segments) * kPi / 180.0;
    mesh.positions.emplace_back(std::cos(a), std::sin(a), -h);
    mesh.positions.emplace_back(std::cos(a), std::sin(a), h);
  }
  for (int i = 0; i < segments; ++i) {
    const int b = 2 * i;
    mesh.triangles.push_back({b, b + 2, b + 3});
    mesh.triangles.push_back({b, b + 3, b + 1});
  }
  return mesh;
}

TEST(SeamPlacement, ATurnMovesTheSeamToThatAzimuth) {
  ProjectorOptions o;
  o.surface = SurfaceKind::Cylinder;
  o.placement.fit = Fit::None;
  o.placement.turnDegrees = 45.0;
  const Projector mapping(o, fitPlacement({}, o.surface, o.placement));
  // The point at azimuth 90 degrees lies an eighth of a turn past the seam at 45 degrees.
  EXPECT_NEAR(mapping.at(Vec3(0, 1, 0.5), Vec3(0, 1, 0)).uv.x(), 0.125, 1e-15);
  EXPECT_NEAR(mapping.at(Vec3(0, 1, 0.5), Vec3(0, 1, 0)).uv.y(), 0.5, 1e-15);
  // Just before 45 degrees the turn is nearly complete.
  const double a = 44.0 * kPi / 180.0;
  EXPECT_NEAR(mapping.at(Vec3(std::cos(a), std::sin(a), 0), Vec3(1, 0, 0)).uv.x(), 359.0 / 360.0, 1e-12);
}

TEST(SeamPlacement, MovesTheSeamOfAHalfBandIntoTheEmptyHalf) {
  // The band spans -90 to 90 degrees: the default seam at 0 degrees cuts through it, a seam
  // anywhere in the empty half crosses nothing; the widest gap is centred on 180 degrees.
  const Mesh mesh = band(-90, 90, 16);
  ProjectorOptions o;
  o.surface = SurfaceKind::Cylinder;
  o.placement.fit = Fit::None;
  const SeamPlacement placement = placeSeam(mesh, o);
  EXPECT_EQ(placement.facesCrossedBefore, 2u);  // the column of two triangles left of the seam vertex
  EXPECT_GT(placement.seamLengthBefore, 0.0);
  EXPECT_EQ(placement.facesCrossed, 0u);
  EXPECT_DOUBLE_EQ(placement.seamLength, 0.0);
  EXPECT_NEAR(std::fabs(placement.turnDegrees), 180.0, 1e-9);

  o.placement.turnDegrees = placement.turnDegrees;
  const Projection turned = project(mesh, o);
  EXPECT_EQ(turned.summary.straddlingFaces, 0u);
  for (const Vec2& uv : turned.uv.uv) {  // one continuous half turn, centred on u = 1/2
    EXPECT_GE(uv.x(), 0.25 - 1e-12);
    EXPECT_LE(uv.x(), 0.75 + 1e-12);
  }
}

TEST(SeamPlacement, FollowsTheClockwiseUOfGluSphere) {
  // gluSphere's s runs clockwise, so the turn that moves its seam has the opposite sign. The band
  // holds the seams of gluSphere (90 degrees) and of the seed's preset (180 degrees).
  const Mesh mesh = band(30, 200, 17);
  for (SpherePreset preset : {SpherePreset::Default, SpherePreset::Glu, SpherePreset::Seed004}) {
    ProjectorOptions o;
    o.surface = SurfaceKind::Sphere;
    o.spherePreset = preset;
    o.placement.fit = Fit::None;
    const SeamPlacement placement = placeSeam(mesh, o);
    o.placement.turnDegrees = placement.turnDegrees;
    EXPECT_EQ(placement.facesCrossedBefore, preset == SpherePreset::Default ? 0u : 2u) << int(preset);
    EXPECT_EQ(placement.facesCrossed, 0u) << int(preset);
    EXPECT_EQ(project(mesh, o).summary.straddlingFaces, 0u) << int(preset);
  }
}

TEST(SeamPlacement, KeepsAPlacementNothingBeats) {
  // A closed lat-long sphere: every seam crosses one column of faces; the one along the vertices
  // at 0 degrees is as good as any, so it stays.
  const Mesh mesh = meshes::latLongSphere(16, 8);
  ProjectorOptions o;
  o.surface = SurfaceKind::Sphere;
  const SeamPlacement placement = placeSeam(mesh, o);
  EXPECT_EQ(placement.turnDegrees, 0.0);
  EXPECT_EQ(placement.facesCrossed, placement.facesCrossedBefore);
  EXPECT_EQ(placement.seamLength, placement.seamLengthBefore);
}

TEST(SeamPlacement, OnlyWrappingSurfacesHaveASeam) {
  ProjectorOptions o;
  o.surface = SurfaceKind::Plane;
  EXPECT_THROW(placeSeam(band(0, 90, 4), o), UsageError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param
