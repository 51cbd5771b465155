// OpenGL texgen in binary32 (TexgenOptions::precision = Float): agreement with double within a few
// float ulps for every mode, float rounding of the result, EYE_LINEAR = OBJECT_LINEAR under
// identity, the sphere-map singular case, and overflow to infinity flagged as invalid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "core/gl_matrices.h"
#include "meshes/generators.h"
#include "texgen/texgen.h"
#include "texgen/texgen_fixtures.h"

namespace uvtk::texgen {
namespace {
namespace UVTK_TEST_FILE {

constexpr double kUnitRoundoff = 0x1p-24;  // binary32: half an ulp of 1

TexgenOptions inFloat(TexgenOptions o) {
  o.precision = Precision::Float;
  return o;
}

struct Vertex {
  Vec3 position, normal;
};

// In front of the camera below, normals towards it: every eye reflection has rz >= 0, so m >= 2
// (checked in the test), far from the sphere map's singular m = 0.
const std::vector<Vertex>& vertices() {
  static const std::vector<Vertex> v = {
      {Vec3(0.3, -0.7, 0.2), Vec3(0, 0, 1)},       {Vec3(1.0 / 3, 2.0 / 3, -1.0 / 7), Vec3(0.6, 0, 0.8)},
      {Vec3(-1.25, 0.5, 0.75), Vec3(1, 2, 2) / 3}, {Vec3(0.1, 0.2, 0.3), Vec3(-0.48, 0.6, 0.64)},
      {Vec3(2.5, -1.5, 1.0), Vec3(0.2, 0.4, 0.9)},
  };
  return v;
}

const Mat4& view() {
  static const Mat4 m = lookAt(Vec3(1, 2, 5), Vec3::Zero(), Vec3::UnitY());
  return m;
}

// The scale a float evaluation errs relative to: the value with every term's absolute value.
// OBJECT_LINEAR |p| |x|; EYE_LINEAR |p'| |M_draw| |x| (p' = p M_plane^-1); NORMAL_MAP 1 (a unit
// vector); REFLECTION_MAP 1 + 2 |n . u| (r = u - 2 (n . u) n); SPHERE_MAP 1 (s = rx/m + 1/2, m >= 2).
double magnitude(const TexgenOptions& o, int i, const Vertex& v) {
  const Vec4 xh(v.position.x(), v.position.y(), v.position.z(), 1.0);
  const Vec4 plane = o.coordinates[i].plane;
  switch (o.coordinates[i].mode) {
    case TexgenMode::ObjectLinear:
      return plane.cwiseAbs().dot(xh.cwiseAbs());
    case TexgenMode::EyeLinear:
      return (o.modelviewAtPlanes.inverse().transpose() * plane)
          .cwiseAbs()
          .dot(o.modelviewAtDraw.cwiseAbs() * xh.cwiseAbs());
    case TexgenMode::ReflectionMap: {
      const Vec3 u = (o.modelviewAtDraw * xh).head<3>().normalized();
      const Vec3 n = (o.modelviewAtDraw.topLeftCorner<3, 3>().inverse().transpose() * v.normal).normalized();
      return 1.0 + 2.0 * std::abs(n.dot(u));
    }
    default:
      return 1.0;
  }
}

TEST(TexgenFloat, DefaultsToDouble) { EXPECT_EQ(TexgenOptions().precision, Precision::Double); }

TEST(TexgenFloat, AgreesWithDoubleWithinFourFloatUlpsOfTheInputsInEveryMode) {
  std::vector<TexgenOptions> cases;
  TexgenOptions linear =
      withModes(TexgenMode::ObjectLinear, TexgenMode::ObjectLinear, TexgenMode::EyeLinear, TexgenMode::EyeLinear);
  linear.coordinates[0].plane = Vec4(0.3, -2, 5, 1);
  linear.coordinates[1].plane = Vec4(1, 1, 1, -0.5);
  linear.coordinates[2].plane = Vec4(0.1, 0.2, 0.3, 4);
  linear.coordinates[3].plane = Vec4(-7, 0.25, 1.0 / 3, 2);
  linear.modelviewAtPlanes = lookAt(Vec3(-2, 1, 3), Vec3(0.5, 0, -1), Vec3(0, 1, 0.2));
  linear.modelviewAtDraw = view();
  cases.push_back(linear);
  for (int i = 0; i < 4; ++i)  // the other way round: eye on s, t and object on r, q
    linear.coordinates[i].mode = i < 2 ? TexgenMode::EyeLinear : TexgenMode::ObjectLinear;
  cases.push_back(linear);
  cases.push_back(withModes(TexgenMode::SphereMap, TexgenMode::SphereMap));
  cases.push_back(withModes(TexgenMode::NormalMap, TexgenMode::NormalMap, TexgenMode::NormalMap));
  cases.push_back(withModes(TexgenMode::ReflectionMap, TexgenMode::ReflectionMap, TexgenMode::ReflectionMap));
  for (std::size_t k = 2; k < cases.size(); ++k) cases[k].modelviewAtDraw = view();
  for (const Vertex& v : vertices()) ASSERT_GE(texgenAt(v.position, v.normal, cases.back())[2], 0.0);

  for (std::size_t k = 0; k < cases.size(); ++k) {
    const TexgenOptions& d = cases[k];
    const TexgenOptions f = inFloat(d);
    for (const Vertex& v : vertices()) {
      bool singularD = true, singularF = true;
      const Vec4 gd = texgenAt(v.position, v.normal, d, &singularD);
      const Vec4 gf = texgenAt(v.position, v.normal, f, &singularF);
      EXPECT_FALSE(singularD || singularF);
      for (int i = 0; i < 4; ++i) {
        EXPECT_LE(std::abs(gf[i] - gd[i]), 4 * kUnitRoundoff * magnitude(d, i, v))
            << "case " << k << ", coordinate " << i << ": float " << gf[i] << ", double " << gd[i];
      }
    }
  }
}

TEST(TexgenFloat, TheTextureMatrixIsAppliedInFloatToo) {
  TexgenOptions o = withModes(TexgenMode::ObjectLinear, TexgenMode::ObjectLinear, TexgenMode::ObjectLinear);
  o.coordinates[2].plane = Vec4(0, 0, 1, 0);
  o.textureMatrix = Mat4::Identity();
  o.textureMatrix(0, 1) = 0.1;  // s' = s + 0.1 t
  const double x = 1.0 / 3, y = 2.0 / 7;
  const Vec4 g = texgenAt(Vec3(x, y, 0), Vec3::UnitZ(), inFloat(o));
  // s' = 1 s + 0.1 t + 0 r + 0 q in float; the zero terms add nothing, in any order.
  const float fx = static_cast<float>(x), fy = static_cast<float>(y);
  const float s = fx + static_cast<float>(0.1) * fy;
  EXPECT_EQ(g[0], static_cast<double>(s));
  EXPECT_NE(g[0], x + 0.1 * y);
  EXPECT_EQ(g[1], static_cast<double>(fy));
}

TEST(TexgenFloat, ObjectLinearIsTheFloatComputationNotTheDoubleOne) {
  TexgenOptions o = withModes(TexgenMode::ObjectLinear, TexgenMode::ObjectLinear);
  o.coordinates[0].plane = Vec4(0.1, 0, 0, 0);
  o.coordinates[1].plane = Vec4(0.1, 0.2, 0.3, 0.4);
  const Vec3 x(1.0 / 3, 2.0 / 3, 1.0 / 7);
  const Vec4 g = texgenAt(x, Vec3::UnitZ(), inFloat(o));
  const Vec4 d = texgenAt(x, Vec3::UnitZ(), o);

  // s = 0.1 x: both factors rounded to float, then one float product (the zero terms add nothing).
  const float s = static_cast<float>(0.1) * static_cast<float>(1.0 / 3);
  EXPECT_EQ(g[0], static_cast<double>(s));
  EXPECT_EQ(d[0], 0.1 * (1.0 / 3));
  EXPECT_NE(g[0], d[0]);
  EXPECT_GT(std::abs(g[0] - d[0]), 1e-10);  // a float error (~1e-9 here), far above double's ~1e-18

  // t = p1 x + p2 y + p3 z + p4, summed left to right in float.
  const float fx = static_cast<float>(x.x()), fy = static_cast<float>(x.y()), fz = static_cast<float>(x.z());
  const float t = static_cast<float>(0.1) * fx + static_cast<float>(0.2) * fy + static_cast<float>(0.3) * fz +
                  static_cast<float>(0.4) * 1.0f;
  EXPECT_EQ(g[1], static_cast<double>(t));
  EXPECT_NE(g[1], d[1]);
  EXPECT_EQ(g[2], 0.0);  // r and q off: GL's current texture coordinate
  EXPECT_EQ(g[3], 1.0);
}

TEST(TexgenFloat, EyeLinearEqualsObjectLinearUnderIdentityModelview) {
  const Mesh mesh = meshes::icosphere(2);
  TexgenOptions eye =
      inFloat(withModes(TexgenMode::EyeLinear, TexgenMode::EyeLinear, TexgenMode::EyeLinear, TexgenMode::EyeLinear));
  const Vec4 planes[4] = {{0.3, -2, 5, 1}, {1, 1, 1, -0.5}, {0, 0, 7, 2}, {0.1, 0.2, 0.3, 4}};
  for (int i = 0; i < 4; ++i) eye.coordinates[i].plane = planes[i];
  TexgenOptions object = eye;
  for (auto& c : object.coordinates) c.mode = TexgenMode::ObjectLinear;
  const TexgenResult a = generateTexcoords(mesh, eye), b = generateTexcoords(mesh, object);
  TexgenOptions objectDouble = object;
  objectDouble.precision = Precision::Double;
  const TexgenResult d = generateTexcoords(mesh, objectDouble);
  ASSERT_EQ(a.uv.uv.size(), 3 * mesh.faceCount());
  std::size_t differsFromDouble = 0;
  for (std::size_t c = 0; c < a.uv.uv.size(); ++c) {
    // Identity: 1 x + 0 y + 0 z + 0 w = x exactly in float, so the same float plane sum.
    EXPECT_EQ(a.uv.uv[c], b.uv.uv[c]) << c;
    EXPECT_EQ(a.uv.w[c], b.uv.w[c]) << c;
    EXPECT_EQ(a.q[c], b.q[c]) << c;
    differsFromDouble += a.uv.uv[c] != d.uv.uv[c];
  }
  EXPECT_GT(differsFromDouble, a.uv.uv.size() / 2);  // the float path was taken
}

TEST(TexgenFloat, OverflowToInfinityIsAnInvalidCornerWrittenAsZero) {
  Mesh mesh;
  mesh.positions = {Vec3(1e10, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  mesh.triangles = {{0, 1, 2}};
  TexgenOptions o = withModes(TexgenMode::ObjectLinear, TexgenMode::ObjectLinear);
  o.coordinates[0].plane = Vec4(1e30, 0, 0, 0);  // s = 1e40 at corner 0: above FLT_MAX ~3.4e38

  const TexgenResult d = generateTexcoords(mesh, o);
  EXPECT_EQ(d.invalidCorners, 0u);
  EXPECT_EQ(d.uv.uv[0].x(), 1e30 * 1e10);
  EXPECT_FALSE(d.uv.faceHas(0, kFaceInvalid));

  const TexgenResult f = generateTexcoords(mesh, inFloat(o));
  EXPECT_EQ(f.invalidCorners, 1u);
  EXPECT_EQ(f.uv.cornerInvalid[0], 1);
  EXPECT_TRUE(f.uv.faceHas(0, kFaceInvalid));
  EXPECT_EQ(f.uv.uv[0], Vec2(0, 0));  // the whole corner written as (0, 0, 0, 0)
  EXPECT_EQ(f.uv.w[0], 0.0);
  EXPECT_EQ(f.q[0], 0.0);
  EXPECT_EQ(f.uv.cornerInvalid[1], 0);  // s = 1e30 * 0 = 0, t = y
  EXPECT_EQ(f.uv.uv[1], Vec2(0, 1));
  EXPECT_EQ(f.uv.uv[2], Vec2(0, 0));
  EXPECT_EQ(f.q[2], 1.0);
}

TEST(TexgenFloat, APlaneBeyondFloatRangeIsAUsageError) {
  TexgenOptions o = withModes(TexgenMode::ObjectLinear, TexgenMode::ObjectLinear);
  o.coordinates[0].plane = Vec4(1e39, 0, 0, 0);  // finite in double, infinite in float
  EXPECT_EQ(texgenAt(Vec3(1, 2, 3), Vec3::UnitZ(), o)[0], 1e39);
  EXPECT_THROW(texgenAt(Vec3(1, 2, 3), Vec3::UnitZ(), inFloat(o)), UsageError);
  o.coordinates[0].mode = TexgenMode::Off;  // a plane no mode reads is not checked
  EXPECT_EQ(texgenAt(Vec3(1, 2, 3), Vec3::UnitZ(), inFloat(o)), Vec4(0, 2, 0, 1));
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::texgen
