#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "core/error.h"
#include "meshes/generators.h"
#include "param/placement.h"
#include "param/projector.h"
#include "param/reference.h"
#include "param/uv_kernel.h"
#include "doubles.h"

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

// The meshes the kernel must agree on: with poles, far out and tiny and huge, with vertices that
// are not finite, on both sides of the local origin.
std::vector<std::pair<std::string, std::vector<Vec3>>> pointSets() {
  std::vector<std::pair<std::string, std::vector<Vec3>>> sets;
  sets.emplace_back("sphere", meshes::latLongSphere(48, 24).positions);
  sets.emplace_back("knot", meshes::torusKnot(2, 3, 96, 12).positions);
  for (double scale : {1e-9, 1e12, 1e-170, 1e160}) {  // the last two take hypot's path in double
    std::vector<Vec3> far = meshes::latLongSphere(16, 8).positions;
    for (Vec3& p : far) p = p * scale + Vec3(1e8, -3e7, 2e6) * scale;
    sets.emplace_back("far*" + std::to_string(scale), far);
  }
  std::vector<Vec3> odd = meshes::bone(8, 6).positions;
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (const Vec3& p : {Vec3(nan, 0, 0), Vec3(0, inf, 1), Vec3(-inf, 0, 0), Vec3(0, 0, 0), Vec3(0, 0, -1),
                        Vec3(0, 0, 1e-30), Vec3(1e300, 1e300, 0), Vec3(1e-30, 0, 0), Vec3(-0.0, -0.0, 2), Vec3(-1, -0.0, 0),
                        Vec3(3e38, 1, 0), Vec3(1e-40, 1e-41, 1e-3), Vec3(0.5, 0.5, 1e-14)})
    odd.push_back(p);
  sets.emplace_back("odd", odd);
  return sets;
}

struct Case {
  SurfaceKind surface;
  RayKind ray;
  SpherePreset preset = SpherePreset::Default;
};

std::vector<Case> cases() {
  std::vector<Case> all;
  for (SurfaceKind surface : {SurfaceKind::Sphere, SurfaceKind::Cylinder, SurfaceKind::Plane, SurfaceKind::TwoPlane})
    for (RayKind ray : {RayKind::SurfaceNormal, RayKind::Centroid, RayKind::ObjectNormal, RayKind::Reflection})
      all.push_back({surface, ray});
  all.push_back({SurfaceKind::Sphere, RayKind::SurfaceNormal, SpherePreset::Glu});
  all.push_back({SurfaceKind::Sphere, RayKind::Centroid, SpherePreset::Seed004});
  return all;
}

ProjectorOptions optionsOf(const Case& c, Precision precision, MathMode math) {
  ProjectorOptions o;
  o.surface = c.surface;
  o.ray = c.ray;
  o.spherePreset = c.preset;
  o.planeU = Vec4(1, 2, -0.5, 0.25);
  o.planeV = Vec4(0, 1, 3, -1);
  if (c.ray == RayKind::Reflection) o.eye = Vec3(0.5, -3, 1);
  o.arithmetic = {precision, math};
  return o;
}

std::vector<Vec3> unitNormals(const std::vector<Vec3>& positions) {
  std::vector<Vec3> normals;
  for (const Vec3& p : positions) normals.push_back(p.allFinite() && p.norm() > 0 ? Vec3(p.normalized()) : Vec3(0, 0, 1));
  return normals;
}

// Projector::mapVertices (which runs on the kernel) and mapUvs against Projector::at, which evaluates each
// point alone through the per-vertex templates: every bit of uv and axial, state and reason.
template <class T>
void expectKernelEqualsPerVertex(Precision precision, MathMode math) {
  std::size_t vectorLanes = 0;
  for (const auto& [name, positions] : pointSets()) {
    const std::vector<Vec3> normals = unitNormals(positions);
    for (const Case& c : cases())
      for (bool fitted : {true, false}) {
        const ProjectorOptions o = optionsOf(c, precision, math);
        std::vector<Vec3> finite;
        for (const Vec3& p : positions)
          if (p.allFinite()) finite.push_back(p);
        const Affine3 frame = fitted ? fitPlacement(finite, c.surface, o.placement) : Affine3::Identity();
        const std::optional<Eigen::AlignedBox3d> box = sensibleBox(finite, o, frame);
        const std::string where = name + " surface " + std::to_string(int(c.surface)) + " ray " +
                                  std::to_string(int(c.ray)) + " preset " + std::to_string(int(c.preset)) +
                                  (fitted ? " fitted" : " identity");
        std::vector<VertexUv> wide;
        Projector(o, frame, box).mapVertices(positions, normals, wide, 1);
        LocalPoints<T> points;
        toLocal(frame, positions, normals, points);
        UvArrays<T> narrow;
        mapUvs(o, frame, points, narrow, 1, box);
        const Projector mapping(o, frame, box);
        std::size_t e = 0;
        for (std::size_t i = 0; i < positions.size(); ++i) {
          const PointUv expected = mapping.at(positions[i], normals[i]);
          const VertexUv& got = wide[i];
          ASSERT_EQ(int(got.state), int(expected.state)) << where << " vertex " << i;
          ASSERT_EQ(int(got.reason), int(expected.reason)) << where << " vertex " << i;
          for (int k = 0; k < 2; ++k) {
            ASSERT_TRUE(sameBits(got.uv[k], expected.uv[k])) << where << " vertex " << i << " uv " << got.uv[k]
                                                             << " expected " << expected.uv[k];
            ASSERT_TRUE(sameBits(got.axial[k], expected.axial[k])) << where << " vertex " << i;
          }
          ASSERT_TRUE(sameBits(double(narrow.u[i]), expected.uv.x())) << where << " vertex " << i;
          ASSERT_TRUE(sameBits(double(narrow.v[i]), expected.uv.y())) << where << " vertex " << i;
          if (expected.state == CornerState::Ok) {
            ++vectorLanes;
            continue;
          }
          ASSERT_LT(e, narrow.exceptions.size()) << where;
          EXPECT_EQ(narrow.exceptions[e].index, i) << where;
          EXPECT_EQ(int(narrow.exceptions[e].state), int(expected.state)) << where;
          EXPECT_EQ(int(narrow.exceptions[e].reason), int(expected.reason)) << where;
          ++e;
        }
        EXPECT_EQ(e, narrow.exceptions.size()) << where;
      }
  }
  EXPECT_GT(vectorLanes, 0u);
}

TEST(UvKernel, DoubleExactEqualsThePerVertexPathBitForBit) { expectKernelEqualsPerVertex<double>(Precision::Double, MathMode::Exact); }
TEST(UvKernel, DoubleFastEqualsThePerVertexPathBitForBit) { expectKernelEqualsPerVertex<double>(Precision::Double, MathMode::Fast); }
TEST(UvKernel, FloatExactEqualsThePerVertexPathBitForBit) { expectKernelEqualsPerVertex<float>(Precision::Float, MathMode::Exact); }
TEST(UvKernel, FloatFastEqualsThePerVertexPathBitForBit) { expectKernelEqualsPerVertex<float>(Precision::Float, MathMode::Fast); }
TEST(UvKernel, FloatFastU10EqualsThePerVertexPathBitForBit) { expectKernelEqualsPerVertex<float>(Precision::Float, MathMode::FastU10); }

TEST(UvKernel, HandComputedSpherePointsAndThePoleInTheSparseList) {
  ProjectorOptions o;  // sphere, isn, default preset: u = turn from +x, v = 1 at +z
  LocalPoints<double> points;
  points.x = {1, 0, -2, 0, 0};
  points.y = {0, 1, 0, 0, 0};
  points.z = {0, 0, 0, 3, 0};
  UvArrays<double> out;
  mapUvs(o, Affine3::Identity(), points, out);
  EXPECT_EQ(out.u[0], 0.0);
  EXPECT_EQ(out.v[0], 0.5);
  EXPECT_EQ(out.u[1], 0.25);
  EXPECT_EQ(out.u[2], 0.5);
  EXPECT_EQ(out.u[3], 0.0);  // the pole: u undefined, given as 0
  EXPECT_EQ(out.v[3], 1.0);
  ASSERT_EQ(out.exceptions.size(), 2u);
  EXPECT_EQ(out.exceptions[0].index, 3u);
  EXPECT_EQ(out.exceptions[0].state, CornerState::Pole);
  EXPECT_EQ(out.exceptions[0].reason, kCornerValid);
  EXPECT_EQ(out.exceptions[1].index, 4u);  // the centre: no direction, a miss
  EXPECT_EQ(out.exceptions[1].state, CornerState::Invalid);
  EXPECT_EQ(out.exceptions[1].reason, kCornerMiss);
  EXPECT_EQ(out.u[4], 0.0);
  EXPECT_EQ(out.v[4], 0.0);
}

TEST(UvKernel, TwoThreadsGiveTheSameArraysAndListAsOne) {
  const Mesh mesh = meshes::latLongSphere(256, 128);  // 32,514 vertices: many blocks per thread
  for (SurfaceKind surface : {SurfaceKind::Sphere, SurfaceKind::Cylinder})
    for (MathMode math : {MathMode::Exact, MathMode::Fast}) {
      ProjectorOptions o;
      o.surface = surface;
      o.arithmetic = {Precision::Float, math};
      const Affine3 frame = fitPlacement(mesh.positions, surface, o.placement);
      LocalPoints<float> points;
      toLocal(frame, mesh.positions, {}, points, 2);
      UvArrays<float> one, two;
      mapUvs(o, frame, points, one, 1);
      mapUvs(o, frame, points, two, 2);
      EXPECT_EQ(std::memcmp(one.u.data(), two.u.data(), one.u.size() * sizeof(float)), 0);
      EXPECT_EQ(std::memcmp(one.v.data(), two.v.data(), one.v.size() * sizeof(float)), 0);
      ASSERT_EQ(one.exceptions.size(), two.exceptions.size());
      EXPECT_EQ(one.exceptions.size(), 2u);  // the sphere's and the cylinder's two pole vertices
      for (std::size_t i = 0; i < one.exceptions.size(); ++i) EXPECT_EQ(one.exceptions[i].index, two.exceptions[i].index);
      std::vector<VertexUv> wide1, wide2;
      Projector(o, frame).mapVertices(mesh.positions, {}, wide1, 1);
      Projector(o, frame).mapVertices(mesh.positions, {}, wide2, 2);
      ASSERT_EQ(wide1.size(), wide2.size());
      for (std::size_t i = 0; i < wide1.size(); ++i) {
        ASSERT_TRUE(sameBits(wide1[i].uv.x(), wide2[i].uv.x()) && sameBits(wide1[i].uv.y(), wide2[i].uv.y())) << i;
        ASSERT_EQ(wide1[i].state, wide2[i].state);
      }
    }
}

TEST(UvKernel, FastFloatStaysWithinASixtyFourthOfATexelAt4096) {
  const Mesh mesh = meshes::latLongSphere(512, 256);
  for (SurfaceKind surface : {SurfaceKind::Sphere, SurfaceKind::Cylinder})
    for (MathMode math : {MathMode::Fast, MathMode::FastU10}) {
      ProjectorOptions o;
      o.surface = surface;
      const Affine3 frame = fitPlacement(mesh.positions, surface, o.placement);
      std::vector<ReferenceUv> reference;
      mapVerticesReference(o, frame, mesh.positions, {}, reference);
      o.arithmetic = {Precision::Float, math};
      std::vector<VertexUv> out;
      Projector(o, frame).mapVertices(mesh.positions, {}, out, 2);
      const MappingError error = mappingError(out, reference, Precision::Float, true);
      EXPECT_EQ(error.stateMismatches, 0u);
      EXPECT_EQ(error.compared, mesh.positions.size());
      EXPECT_LE(error.maxUv * 4096, 1.0 / 64);
      EXPECT_LE(error.maxUlp, 3.5);  // SLEEF's bound, plus the float rounding of the result
    }
}

TEST(UvKernel, RefusesTheCubeAndMissingNormals) {
  ProjectorOptions o;
  o.surface = SurfaceKind::Cube;
  LocalPoints<double> points;
  points.x = points.y = points.z = {1};
  UvArrays<double> out;
  EXPECT_THROW(mapUvs(o, Affine3::Identity(), points, out), UsageError);
  o.surface = SurfaceKind::Sphere;
  o.ray = RayKind::ObjectNormal;
  EXPECT_THROW(mapUvs(o, Affine3::Identity(), points, out), UsageError);  // no normals in points
  EXPECT_THROW(toLocal(Affine3::Identity(), {Vec3(1, 0, 0)}, {Vec3(1, 0, 0), Vec3(0, 1, 0)}, points), UsageError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param
