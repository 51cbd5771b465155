// Why a corner has no UV (CornerInvalid, docs/conventions.md §1, §4): every O x S combination on
// meshes like real ones keeps its valid UVs within the bound the range rule implies and counts its
// invalid corners per reason; hand-computed misses, rays behind and nearly parallel rays; the
// cylinder's caps decided in object space (§5).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>

#include "meshes/generators.h"
#include "param/atlas_meshes.h"
#include "param/projector.h"
#include "param/surfaces.h"

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

// Every surface with a formula of a point (see projector_test.cpp), as the list grows.
const std::vector<SurfaceKind> kSurfaces = [] {
  std::vector<SurfaceKind> surfaces;
  std::copy_if(std::begin(param::kSurfaces), std::end(param::kSurfaces), std::back_inserter(surfaces),
               [](SurfaceKind s) { return hasPointFormula(s); });
  return surfaces;
}();

using test::NamedMesh;

const std::vector<NamedMesh>& realMeshes() {
  static const std::vector<NamedMesh> meshes = {{"torusKnot", meshes::torusKnot(3, 2, 96, 8)},
                                                {"bone", meshes::bone(24, 12)},
                                                {"bumpyBlob", meshes::bumpyBlob(2)},
                                                {"scannedPatch", meshes::scannedPatch(4)}};
  return meshes;
}

// The O-mappings: isn, centroid, normal, and reflection with an eye 5 bounding radii from the
// mesh's box centre on +z and on +x.
struct Rays {
  const char* name;
  RayKind ray;
  Vec3 eyeDirection = Vec3::Zero();
};
const Rays kRays[] = {{"isn", RayKind::SurfaceNormal},
                      {"centroid", RayKind::Centroid},
                      {"normal", RayKind::ObjectNormal},
                      {"reflection+z", RayKind::Reflection, Vec3::UnitZ()},
                      {"reflection+x", RayKind::Reflection, Vec3::UnitX()}};

ProjectorOptions optionsFor(SurfaceKind surface, const Rays& rays, const Mesh& mesh) {
  ProjectorOptions o;
  o.surface = surface;
  o.ray = rays.ray;
  if (rays.ray == RayKind::Reflection) {
    Eigen::AlignedBox3d box;
    for (const Vec3& p : mesh.positions) box.extend(p);
    o.eye = box.center() + 5.0 * (0.5 * box.diagonal().norm()) * rays.eyeDirection;
  }
  return o;
}

// The bound the range rule implies on a valid corner's (u, v) before the UV transform (§4): every
// valid hit q lies within R = kSensibleRange h of the centre c of the sensible box B (h: B's
// largest half-extent) in each coordinate, so plane |u| <= |c_x| + R, |v| <= |c_y| + R; two-plane
// |u| <= |n.c + d| + |n|_1 R per plane (n, d); cylinder v as the plane's u with c_z, u in
// [0, 1.5); sphere u in [0, 1.5), v in [0, 1]; cube ("faces" layout) |s|, |t| <= (1 + |c|_inf + R)/2.
Vec2 uvBound(const ProjectorOptions& o, const Eigen::AlignedBox3d& box) {
  const Vec3 c = box.center();
  const double reach = kSensibleRange * (0.5 * box.sizes()).maxCoeff();
  const auto planeBound = [&](const Vec4& plane) {
    const Vec3 n = plane.head<3>() / plane.head<3>().norm();
    return std::fabs(n.dot(c) + plane[3] / plane.head<3>().norm()) + n.cwiseAbs().sum() * reach;
  };
  if (o.surface == SurfaceKind::Plane) return {std::fabs(c.x()) + reach, std::fabs(c.y()) + reach};
  if (o.surface == SurfaceKind::TwoPlane) return {planeBound(o.planeU), planeBound(o.planeV)};
  if (o.surface == SurfaceKind::Cylinder) return {1.5, std::fabs(c.z()) + reach};
  if (o.surface == SurfaceKind::Sphere) return {1.5, 1.0};
  if (o.surface == SurfaceKind::Cube) return Vec2::Constant((1.0 + c.cwiseAbs().maxCoeff() + reach) / 2.0);
  // The maps of directions lie in [0, 1]^2 whatever the hit (direction_maps_test.cpp states it).
  return Vec2::Constant(std::numeric_limits<double>::infinity());
}

TEST(CornerReason, EveryCombinationKeepsValidUvsWithinTheRangeBoundAndCountsItsInvalidCornersPerReason) {
  for (const NamedMesh& named : realMeshes())
    for (SurfaceKind surface : kSurfaces)
      for (const Rays& rays : kRays) {
        const ProjectorOptions o = optionsFor(surface, rays, named.mesh);
        SCOPED_TRACE(std::string(named.name) + ", surface " + std::to_string(int(surface)) + ", " + rays.name);
        const Projection p = project(named.mesh, o);
        const std::optional<Eigen::AlignedBox3d> box = sensibleBox(named.mesh.positions, o, p.localFromObject);
        ASSERT_TRUE(box);
        const Vec2 bound = uvBound(o, *box);
        std::array<std::size_t, kCornerInvalidCount> counted{};
        for (std::size_t i = 0; i < p.uv.uv.size(); ++i) {
          const std::uint8_t reason = p.uv.cornerInvalid[i];
          ASSERT_LT(reason, kCornerNoTexcoord) << "corner " << i;  // a projector's corner always has a value or a reason
          ++counted[reason];
          if (reason != kCornerValid) {
            EXPECT_EQ(p.uv.uv[i], Vec2::Zero());
            EXPECT_TRUE(p.uv.faceHas(i / 3, kFaceInvalid));
            continue;
          }
          ASSERT_LE(std::fabs(p.uv.uv[i].x()), bound.x()) << "corner " << i;
          ASSERT_LE(std::fabs(p.uv.uv[i].y()), bound.y()) << "corner " << i;
        }
        EXPECT_EQ(p.summary.invalidCorners, counted);
        std::size_t flagged = 0;
        for (int reason = 1; reason < kCornerInvalidCount; ++reason) flagged += p.summary.invalidCorners[reason];
        EXPECT_EQ(flagged, p.uv.uv.size() - counted[kCornerValid]);
        // isn never misses a fitted surface; the sphere's hits are on the unit sphere, inside B.
        if (rays.ray == RayKind::SurfaceNormal) {
          EXPECT_EQ(flagged, 0u);
        }
        if (surface == SurfaceKind::Sphere) {
          EXPECT_EQ(p.summary.invalidCorners[kCornerOutOfRange], 0u);
        }
        // Only rays from the vertex (normal, reflection) can have their plane behind them.
        if (rays.ray != RayKind::ObjectNormal && rays.ray != RayKind::Reflection) {
          EXPECT_EQ(p.summary.invalidCorners[kCornerBehind], 0u);
        }
      }
}

// A closed mesh's outward normals point away from the plane through its middle, above it up and
// below it down: their lines meet the plane only behind the vertex, except where bumps turn them.
TEST(CornerReason, NormalRaysOfAClosedMeshAwayFromThePlaneAreBehind) {
  const Mesh mesh = meshes::bumpyBlob(2);
  for (SurfaceKind surface : {SurfaceKind::Plane, SurfaceKind::TwoPlane}) {
    ProjectorOptions o;
    o.surface = surface;
    o.ray = RayKind::ObjectNormal;
    const Projection p = project(mesh, o);
    const std::size_t corners = p.uv.uv.size();
    EXPECT_GT(p.summary.invalidCorners[kCornerBehind], corners / 2) << int(surface);
  }
}

ProjectorOptions unplaced(SurfaceKind surface, RayKind ray) {
  ProjectorOptions o;
  o.surface = surface;
  o.ray = ray;
  o.placement.fit = Fit::None;
  return o;
}

// One point through mapVertices and Projector (which must agree), with the sensible box of
// `mesh` (fit none: local = object).
VertexUv mapOne(const ProjectorOptions& o, const std::vector<Vec3>& mesh, const Vec3& position, const Vec3& normal) {
  const std::optional<Eigen::AlignedBox3d> box = sensibleBox(mesh, o, Affine3::Identity());
  std::vector<VertexUv> out;
  Projector(o, Affine3::Identity(), box).mapVertices({position}, {normal}, out, 1);
  const PointUv atPoint = Projector(o, Affine3::Identity(), box).at(position, normal);
  EXPECT_EQ(atPoint.state, out[0].state);
  EXPECT_EQ(atPoint.reason, out[0].reason);
  EXPECT_EQ(atPoint.uv, out[0].uv);
  EXPECT_EQ(out[0].state == CornerState::Invalid, out[0].reason != kCornerValid);
  return out[0];
}

const std::vector<Vec3> kUnitSquare = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

TEST(CornerReason, APlaneNormalRayFacingAwayFromThePlaneIsBehind) {
  const ProjectorOptions o = unplaced(SurfaceKind::Plane, RayKind::ObjectNormal);
  // (0.5, 0.5, 0.5) facing +z: the line meets z = 0 at t = -0.5
  EXPECT_EQ(mapOne(o, kUnitSquare, Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 1)).reason, kCornerBehind);
  // facing -z: t = 0.5, the foot (0.5, 0.5)
  const VertexUv front = mapOne(o, kUnitSquare, Vec3(0.5, 0.5, 0.5), Vec3(0, 0, -1));
  EXPECT_EQ(front.reason, kCornerValid);
  EXPECT_EQ(front.uv, Vec2(0.5, 0.5));
  // a reflected view that leaves the plane behind: eye below, point above, normal +z mirrors it up
  ProjectorOptions reflection = unplaced(SurfaceKind::Plane, RayKind::Reflection);
  reflection.eye = Vec3(0.5, 0.5, 5);
  EXPECT_EQ(mapOne(reflection, kUnitSquare, Vec3(0.5, 0.5, 0.5), Vec3(0, 0, -1)).reason, kCornerBehind);
}

TEST(CornerReason, ANearlyParallelRayIsOutOfRange) {
  const ProjectorOptions o = unplaced(SurfaceKind::Plane, RayKind::ObjectNormal);
  // B = [0,1]^2 x {0} (the square united with the plane's unit shape): centre (0.5, 0.5, 0),
  // half-extent 0.5, reach 1: hits with x or y outside [-0.5, 1.5] are out of range.
  // From z = 0.1 along (1, 0, -1e-6): t = 1e5, x = 1e5.
  const Vec3 grazing = Vec3(1, 0, -1e-6).normalized();
  EXPECT_EQ(mapOne(o, kUnitSquare, Vec3(0.5, 0.5, 0.1), grazing).reason, kCornerOutOfRange);
  // Along (1, 0, -0.1): x = 0.5 + 1 = 1.5, on the edge of the range: valid.
  const VertexUv edge = mapOne(o, kUnitSquare, Vec3(0.5, 0.5, 0.1), Vec3(1, 0, -0.1).normalized());
  EXPECT_EQ(edge.reason, kCornerValid);
  EXPECT_NEAR(edge.uv.x(), 1.5, 1e-15);
  // Without a box there is no range check: the far hit is valid.
  std::vector<VertexUv> out;
  Projector(o, Affine3::Identity()).mapVertices({Vec3(0.5, 0.5, 0.1)}, {grazing}, out);
  EXPECT_EQ(out[0].reason, kCornerValid);
  EXPECT_NEAR(out[0].uv.x(), 0.5 + 1e5, 1e-5);
}

TEST(CornerReason, ARayThatMissesTheSphereIsAMiss) {
  const ProjectorOptions o = unplaced(SurfaceKind::Sphere, RayKind::ObjectNormal);
  const std::vector<Vec3> mesh = {{-1, -1, -1}, {1, 1, 1}};
  // from (0, -3, 0) along +x: the closest approach is 3 from the centre
  EXPECT_EQ(mapOne(o, mesh, Vec3(0, -3, 0), Vec3(1, 0, 0)).reason, kCornerMiss);
  // heading away: its line meets the sphere only behind the point, which for a sphere is a miss (§4)
  EXPECT_EQ(mapOne(o, mesh, Vec3(0, -3, 0), Vec3(0, -1, 0)).reason, kCornerMiss);
}

TEST(CornerReason, TheCubeFlagsACornerWhoseRayLeavesTheTrianglesFacePlaneBehind) {
  ProjectorOptions o = unplaced(SurfaceKind::Cube, RayKind::ObjectNormal);
  Mesh mesh;
  // A triangle inside the cube: two corners' normals point to +z (the mean ray exits through +Z),
  // the third's points to -z, so its line meets z = 1 only behind it.
  mesh.positions = {{0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}};
  mesh.triangles = {{0, 1, 2}};
  mesh.normals = {Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3(0, 0, -1)};
  mesh.cornerNormals = {{0, 1, 2}};
  const Projection p = project(mesh, o);
  EXPECT_EQ(p.uv.w[0], double(CubeFace::PosZ));
  EXPECT_EQ(p.uv.cornerInvalid[0], kCornerValid);
  EXPECT_EQ(p.uv.cornerInvalid[1], kCornerValid);
  EXPECT_EQ(p.uv.cornerInvalid[2], kCornerBehind);
  EXPECT_EQ(p.summary.invalidCorners[kCornerBehind], 1u);
  EXPECT_TRUE(p.uv.faceHas(0, kFaceInvalid));
}

// ---- caps in object space (§5) ----

// The faces whose object-space normal lies within `degrees` of the object's z axis, counted here
// from the positions alone.
std::size_t capsInObjectSpace(const Mesh& mesh, double degrees) {
  std::size_t n = 0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3 normal = (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
    const double angle = std::acos(std::min(1.0, std::fabs(normal.z()) / normal.norm())) * 180.0 / kPi;
    n += angle <= degrees;
  }
  return n;
}

TEST(CornerReason, CylinderCapsAreDecidedInObjectSpaceOnAnElongatedMesh) {
  ProjectorOptions o;
  o.surface = SurfaceKind::Cylinder;
  o.cylinderCaps = true;  // --fit bbox --axis z --caps, cap angle 45 degrees
  // A cylinder of height 10 and radius 0.5: exactly its two fans of 24 triangles are caps. The fit
  // divides z by 10 and x, y by 0.5; the side's normals stay horizontal, the caps' vertical.
  const Mesh tube = meshes::cylinder(24, 10, 0.5, 10.0, true);
  EXPECT_EQ(project(tube, o).summary.capFaces, 48u);
  // The bone's knobby ends slope: the count is the object-space count, far below what the squeezed
  // local frame (z divided by 10, x and y by about 0.5: slopes 20 times steeper) would take.
  const Mesh bone = meshes::bone(48, 16, 10.0);
  const Projection p = project(bone, o);
  const std::size_t expected = capsInObjectSpace(bone, 45.0);
  EXPECT_EQ(p.summary.capFaces, expected);
  std::size_t inLocalFrame = 0;  // the old test: the normal of the triangle's local corners
  for (const Triangle& t : bone.triangles) {
    const Vec3 a = p.localFromObject * bone.positions[t[0]], b = p.localFromObject * bone.positions[t[1]],
               c = p.localFromObject * bone.positions[t[2]];
    const Vec3 normal = (b - a).cross(c - a);
    inLocalFrame += std::fabs(normal.z()) >= std::cos(kPi / 4) * normal.norm();
  }
  EXPECT_GT(inLocalFrame, 3 * expected) << expected << " caps in object space";
  for (std::size_t f = 0; f < bone.faceCount(); ++f) {
    const Triangle& t = bone.triangles[f];
    const Vec3 normal = (bone.positions[t[1]] - bone.positions[t[0]]).cross(bone.positions[t[2]] - bone.positions[t[0]]);
    const bool cap = std::fabs(normal.z()) >= std::cos(kPi / 4) * normal.norm();
    EXPECT_EQ(p.uv.faceHas(f, kFaceCap), cap) << "face " << f;
  }
  // The same test decides per point (Projector::isCap, point::PointEvaluator), and the sign of the
  // normal along the axis picks the cap: beside the side band, the top's square has u in [0, 1/2].
  const Projector caps(o, p.localFromObject);
  EXPECT_TRUE(caps.isCap(Vec3(0, 0.9, 1)));   // 42 degrees from +z
  EXPECT_FALSE(caps.isCap(Vec3(0, 1.1, 1)));  // 48 degrees
  EXPECT_LT(caps.at(bone.positions[0], Vec3(0, 0.9, 1), true).uv.x(), 0.5);
  EXPECT_GE(caps.at(bone.positions[0], Vec3(0, 0.9, -1), true).uv.x(), 0.5);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param
