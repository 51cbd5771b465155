// The box UVs of a triplanar projection measured: each face is stretched by 1/|n_d| across its
// slope (n its unit normal, d its dominant axis), and the faces a projection mirrors by design are
// backfacing, not flipped (docs/conventions.md, "Triplanar projection").
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/distortion.h"
#include "meshes/generators.h"
#include "param/projector.h"

namespace uvtk::analysis {
namespace {
namespace UVTK_TEST_FILE {

TEST(TriplanarStretch, AFaceIsStretchedByOneOverItsDominantNormalComponent) {
  Mesh mesh = meshes::icosphere(2);
  param::ProjectorOptions o;
  o.surface = param::SurfaceKind::Triplanar;
  o.placement.fit = param::Fit::None;
  const param::Projection projection = param::project(mesh, o, 1);
  ProjectionDirections options;
  for (int f = 0; f < int(mesh.faceCount()); ++f) {
    const Vec3 facing = param::triplanarFacing(o.triplanar, projection.triplanarAxis[std::size_t(f)]);
    options.faceProjectionDirections.push_back(facing);
  }
  UvMap marked = projection.uv;
  markTurnedAwayFaces(mesh, options, marked, 1);
  const FaceMeasures faces = measureFaces(mesh, marked, 1);
  std::size_t backfacing = 0, mirroredByDesign = 0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3 n = (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]).normalized();
    const int axis = projection.triplanarAxis[f];
    // An orthographic projection of the face's plane onto the axis plane: singular values 1 and |n_d|.
    EXPECT_NEAR(faces[f].angleDistortion(), 1.0 / std::fabs(n[axis]), 1e-9) << "face " << f;
    EXPECT_LE(faces[f].angleDistortion(), std::sqrt(3.0) + 1e-9);
    EXPECT_NE(faces[f].status, FaceStatus::Flipped) << "face " << f;
    backfacing += faces[f].status == FaceStatus::Backfacing;
    mirroredByDesign += n.dot(param::triplanarFacing(o.triplanar, axis)) < 0.0;
  }
  EXPECT_EQ(backfacing, mirroredByDesign);  // an independent recount: the faces turned from their projection
  EXPECT_GT(backfacing, 0u);
  // Without the per-face directions the same faces are flipped: the directions are what decide it.
  const FaceMeasures plain = measureFaces(mesh, projection.uv, 1);
  std::size_t flipped = 0;
  for (const FaceDistortion& face : plain) flipped += face.status == FaceStatus::Flipped;
  EXPECT_EQ(flipped, std::min(backfacing, mesh.faceCount() - backfacing));
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::analysis
