// OpenGL texgen (GL 4.6 compatibility §12.1.3): values worked by hand for every mode, the
// plane and modelview semantics, the two-plane projector, extremes and gluLookAt.
#include "texgen/texgen.h"

#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.h"
#include "meshes/generators.h"
#include "param/projector.h"
#include "texgen/texgen_fixtures.h"

namespace uvtk::texgen {
namespace {
namespace UVTK_TEST_FILE {

constexpr double kTight = 1e-15;

Mat4 translation(double x, double y, double z) {
  Mat4 m = Mat4::Identity();
  m.block<3, 1>(0, 3) = Vec3(x, y, z);
  return m;
}

Mat4 scaling(double x, double y, double z) { return Vec4(x, y, z, 1.0).asDiagonal(); }

// A quarter turn about z, exact: (x, y, z) -> (-y, x, z).
Mat4 quarterTurnZ() {
  Mat4 m = Mat4::Zero();
  m(0, 1) = -1.0;
  m(1, 0) = 1.0;
  m(2, 2) = 1.0;
  m(3, 3) = 1.0;
  return m;
}

// Whether every component of `actual` is within `tolerance` of `expected`; says which is not.
::testing::AssertionResult isNear(const Vec4& actual, const Vec4& expected, double tolerance) {
  for (int i = 0; i < 4; ++i)
    if (!(std::abs(actual[i] - expected[i]) <= tolerance))
      return ::testing::AssertionFailure() << "component " << i << ": " << actual[i] << " instead of " << expected[i];
  return ::testing::AssertionSuccess();
}

TEST(TexgenDefaults, GlInitialStateIsEveryCoordinateOffWithPlanesSAndT) {
  const TexgenOptions o;
  for (const TexgenCoordinate& c : o.coordinates) EXPECT_EQ(c.mode, TexgenMode::Off);
  EXPECT_EQ(o.coordinates[0].plane, Vec4(1, 0, 0, 0));
  EXPECT_EQ(o.coordinates[1].plane, Vec4(0, 1, 0, 0));
  EXPECT_EQ(o.coordinates[2].plane, Vec4::Zero());
  EXPECT_EQ(o.coordinates[3].plane, Vec4::Zero());
  EXPECT_EQ(texgenAt(Vec3(3, 4, 5), Vec3::UnitZ(), o), Vec4(0, 0, 0, 1));  // the current texcoord
}

TEST(ObjectLinear, EvaluatesTheUnnormalisedPlaneOnObjectCoordinates) {
  TexgenOptions o = withModes(TexgenMode::ObjectLinear, TexgenMode::ObjectLinear);
  o.coordinates[0].plane = Vec4(2, -3, 0.5, 4);               // 2 - 6 + 1.5 + 4 at (1, 2, 3)
  o.modelviewAtDraw = quarterTurnZ() * translation(7, 8, 9);  // ignored by object linear
  const Vec4 g = texgenAt(Vec3(1, 2, 3), Vec3::UnitZ(), o);
  EXPECT_EQ(g, Vec4(1.5, 2.0, 0.0, 1.0));  // t: default plane (0,1,0,0); r, q off
}

TEST(EyeLinear, TransformsThePlaneByTheInverseOfTheModelviewAtPlaneTime) {
  TexgenOptions o = withModes(TexgenMode::EyeLinear, TexgenMode::Off);
  o.coordinates[0].plane = Vec4(1, 0, 0, 0);
  // M_plane = T(1,2,3) Rz(90): p' = (1,0,0,0) Rz^-1 T(-1,-2,-3) = (0, 1, 0, -2), g = ye - 2.
  o.modelviewAtPlanes = translation(1, 2, 3) * quarterTurnZ();
  EXPECT_EQ(texgenAt(Vec3(5, 7, 1), Vec3::UnitZ(), o)[0], 5.0);
  o.modelviewAtDraw = scaling(2, 2, 2);  // eye (10, 14, 2)
  EXPECT_EQ(texgenAt(Vec3(5, 7, 1), Vec3::UnitZ(), o)[0], 12.0);
}

TEST(EyeLinear, EqualsObjectLinearWhenViewAndModelAreIdentity) {
  const Mesh mesh = meshes::icosphere(2);
  TexgenOptions eye =
      withModes(TexgenMode::EyeLinear, TexgenMode::EyeLinear, TexgenMode::EyeLinear, TexgenMode::EyeLinear);
  const Vec4 planes[4] = {{0.3, -2, 5, 1}, {1, 1, 1, -0.5}, {0, 0, 7, 2}, {0.1, 0.2, 0.3, 4}};
  for (int i = 0; i < 4; ++i) eye.coordinates[i].plane = planes[i];
  TexgenOptions object = eye;
  for (auto& c : object.coordinates) c.mode = TexgenMode::ObjectLinear;
  const TexgenResult a = generateTexcoords(mesh, eye), b = generateTexcoords(mesh, object);
  ASSERT_EQ(a.uv.uv.size(), 3 * mesh.faceCount());
  for (std::size_t c = 0; c < a.uv.uv.size(); ++c) {
    EXPECT_DOUBLE_EQ(a.uv.uv[c].x(), b.uv.uv[c].x());
    EXPECT_DOUBLE_EQ(a.uv.uv[c].y(), b.uv.uv[c].y());
    EXPECT_DOUBLE_EQ(a.uv.w[c], b.uv.w[c]);
    EXPECT_DOUBLE_EQ(a.q[c], b.q[c]);
  }
}

TEST(EyeLinear, EqualsObjectLinearWhenThePlaneIsGivenAndDrawnUnderTheSameModelview) {
  const Mesh mesh = meshes::icosphere(2);
  TexgenOptions eye = withModes(TexgenMode::EyeLinear, TexgenMode::EyeLinear);
  eye.coordinates[0].plane = Vec4(0.3, -2, 5, 1);
  eye.coordinates[1].plane = Vec4(1, 1, 1, -0.5);
  const Mat4 view = lookAt(Vec3(2, 3, 4), Vec3(0.5, 0, -1), Vec3(0, 1, 0.2));
  eye.modelviewAtPlanes = view;
  eye.modelviewAtDraw = view;
  TexgenOptions object = eye;
  for (auto& c : object.coordinates) c.mode = c.mode == TexgenMode::Off ? TexgenMode::Off : TexgenMode::ObjectLinear;
  const TexgenResult a = generateTexcoords(mesh, eye), b = generateTexcoords(mesh, object);
  for (std::size_t c = 0; c < a.uv.uv.size(); ++c) EXPECT_NEAR((a.uv.uv[c] - b.uv.uv[c]).norm(), 0.0, 1e-13) << c;

  eye.modelviewAtDraw = view * rotationX(0.4);  // the model turned after the planes were given
  const TexgenResult turned = generateTexcoords(mesh, eye);
  double largest = 0.0;
  for (std::size_t c = 0; c < a.uv.uv.size(); ++c) largest = std::max(largest, (turned.uv.uv[c] - b.uv.uv[c]).norm());
  EXPECT_GT(largest, 0.1);
}

// The Swedish lecture notes on distance-controlled texture generation: a plane y = 0 given in
// object space follows the model; given in eye space it stays fixed while the model turns.
TEST(LectureNotesExample, ObjectLinearPlaneFollowsTheRotatingModel) {
  TexgenOptions o = withModes(TexgenMode::ObjectLinear, TexgenMode::Off);
  o.coordinates[0].plane = Vec4(0, 1, 0, 0);
  const Vec3 vertex(0.2, 0.7, -0.4);
  const double still = texgenAt(vertex, Vec3::UnitY(), o)[0];
  EXPECT_EQ(still, 0.7);
  for (double angle : {0.3, 1.0, 2.5}) {
    o.modelviewAtDraw = rotationX(angle);
    EXPECT_EQ(texgenAt(vertex, Vec3::UnitY(), o)[0], still) << angle;
  }
}

TEST(LectureNotesExample, EyeLinearPlaneStaysFixedInViewSpace) {
  TexgenOptions o = withModes(TexgenMode::EyeLinear, TexgenMode::Off);
  o.coordinates[0].plane = Vec4(0, 1, 0, 0);
  const Vec3 vertex(0.2, 0.7, -0.4);
  for (double angle : {0.3, 1.5, 2.5}) {
    o.modelviewAtDraw = rotationX(angle);
    const Vec4 eyePosition = o.modelviewAtDraw * Vec4(vertex.x(), vertex.y(), vertex.z(), 1.0);
    const double s = texgenAt(vertex, Vec3::UnitY(), o)[0];
    EXPECT_NEAR(s, eyePosition.y(), kTight) << angle;
    EXPECT_GT(std::abs(s - 0.7), 0.05) << angle;  // changed by the model's rotation
  }
}

TEST(SphereMap, MatchesHandWorkedEyePositionsAndNormals) {
  const TexgenOptions o = withModes(TexgenMode::SphereMap, TexgenMode::SphereMap);
  // Facing the viewer: u = (0,0,-1), n = (0,0,1), r = (0,0,1), m = 4.
  EXPECT_TRUE(isNear(texgenAt(Vec3(0, 0, -5), Vec3(0, 0, 1), o), Vec4(0.5, 0.5, 0, 1), kTight));
  // n = (1,0,1)/sqrt2: r = (1,0,0), m = 2 sqrt2, s = 1/(2 sqrt2) + 1/2.
  EXPECT_TRUE(isNear(texgenAt(Vec3(0, 0, -5), Vec3(1, 0, 1) / std::sqrt(2.0), o),
                     Vec4(0.5 + 1.0 / (2.0 * std::sqrt(2.0)), 0.5, 0, 1), kTight));
  // u = (0.6, 0, -0.8), n = (0,0,1): r = (0.6, 0, 0.8), m = 2 sqrt(3.6), s = 1/2 + 1/sqrt(40).
  EXPECT_TRUE(isNear(texgenAt(Vec3(3, 0, -4), Vec3(0, 0, 1), o), Vec4(0.5 + 1.0 / std::sqrt(40.0), 0.5, 0, 1), kTight));
  // u = (0, 0.8, -0.6), n = (0,1,0): r = (0, -0.8, -0.6), m = 2 sqrt(0.8), t = 1/2 - sqrt(0.8)/2.
  EXPECT_TRUE(isNear(texgenAt(Vec3(0, 4, -3), Vec3(0, 1, 0), o), Vec4(0.5, 0.5 - std::sqrt(0.8) / 2.0, 0, 1), kTight));
}

// In both precisions: r = (0,0,-1) is exact in float too.
TEST(SphereMap, ReflectionStraightAwayGivesOneHalfAndReportsTheSingularity) {
  for (Precision precision : {Precision::Double, Precision::Float}) {
    TexgenOptions o = withModes(TexgenMode::SphereMap, TexgenMode::SphereMap);
    o.precision = precision;
    bool singular = false;
    // n perpendicular to u = (0,0,-1): r = (0,0,-1), m = 0.
    const Vec4 g = texgenAt(Vec3(0, 0, -5), Vec3(1, 0, 0), o, &singular);
    EXPECT_EQ(g, Vec4(0.5, 0.5, 0, 1));
    EXPECT_TRUE(singular);
    texgenAt(Vec3(0, 0, -5), Vec3(0, 0, 1), o, &singular);
    EXPECT_FALSE(singular);
  }
}

TEST(SphereMap, FlagsFacesAndCountsCornersWhereMIsZero) {
  Mesh mesh;  // in the plane x = 0, normal (-1,0,0): the corners on the view axis reflect to (0,0,-1)
  mesh.positions = {Vec3(0, 0, -5), Vec3(0, 1, -5), Vec3(0, 0, -6)};
  mesh.triangles = {{0, 1, 2}};
  for (Precision precision : {Precision::Double, Precision::Float}) {
    TexgenOptions o = withModes(TexgenMode::SphereMap, TexgenMode::SphereMap);
    o.precision = precision;
    const TexgenResult r = generateTexcoords(mesh, o);
    EXPECT_EQ(r.sphereMapSingular, 2u);
    EXPECT_TRUE(r.uv.faceHas(0, kFaceSphereMapSingular));
    EXPECT_EQ(r.uv.uv[0], Vec2(0.5, 0.5));
    EXPECT_EQ(r.uv.uv[2], Vec2(0.5, 0.5));
    EXPECT_TRUE(r.uv.uv.at(1).allFinite());
    EXPECT_EQ(r.invalidCorners, 0u);
  }
}

TEST(NormalMap, GivesTheEyeNormal) {
  TexgenOptions o = withModes(TexgenMode::NormalMap, TexgenMode::NormalMap, TexgenMode::NormalMap);
  EXPECT_TRUE(isNear(texgenAt(Vec3(1, 2, 3), Vec3(0.6, 0, 0.8), o), Vec4(0.6, 0, 0.8, 1), kTight));
  o.modelviewAtDraw = translation(4, 5, 6) * quarterTurnZ();  // (x,y,z) -> (-y,x,z), translation ignored
  EXPECT_TRUE(isNear(texgenAt(Vec3(1, 2, 3), Vec3(1, 0, 0), o), Vec4(0, 1, 0, 1), kTight));
}

TEST(NormalMap, RenormalisesAfterTheInverseTransposeUnlessNormalizeIsOff) {
  TexgenOptions o = withModes(TexgenMode::NormalMap, TexgenMode::NormalMap, TexgenMode::NormalMap);
  o.modelviewAtDraw = scaling(2, 1, 1);  // inverse transpose diag(1/2, 1, 1)
  const Vec3 n = Vec3(1, 1, 0) / std::sqrt(2.0);
  const Vec4 normalized = texgenAt(Vec3::Zero(), n, o);
  EXPECT_TRUE(isNear(normalized, Vec4(1 / std::sqrt(5.0), 2 / std::sqrt(5.0), 0, 1), kTight));  // (1,2,0)/sqrt5
  o.normalize = false;  // GL's default state: the transformed normal keeps its length
  const Vec4 raw = texgenAt(Vec3::Zero(), n, o);
  EXPECT_TRUE(isNear(raw, Vec4(0.5 / std::sqrt(2.0), 1 / std::sqrt(2.0), 0, 1), kTight));
  EXPECT_NEAR(raw.head<3>().norm(), std::sqrt(0.625), kTight);
  // A non-unit input normal is used as given when not normalising.
  EXPECT_EQ(texgenAt(Vec3::Zero(), Vec3(4, 0, 0), o).head<3>(), Vec3(2, 0, 0));
  o.normalize = true;
  EXPECT_EQ(texgenAt(Vec3::Zero(), Vec3(4, 0, 0), o).head<3>(), Vec3(1, 0, 0));
}

TEST(ReflectionMap, GivesTheReflectedViewVector) {
  const TexgenOptions o = withModes(TexgenMode::ReflectionMap, TexgenMode::ReflectionMap, TexgenMode::ReflectionMap);
  // u = (0.6, 0, -0.8), n = (0,0,1): r = u - 2 n (n.u) = (0.6, 0, 0.8).
  EXPECT_TRUE(isNear(texgenAt(Vec3(3, 0, -4), Vec3(0, 0, 1), o), Vec4(0.6, 0, 0.8, 1), kTight));
  // u = (0,0,-1), n = (1,0,1)/sqrt2: r = (1,0,0).
  EXPECT_TRUE(isNear(texgenAt(Vec3(0, 0, -5), Vec3(1, 0, 1) / std::sqrt(2.0), o), Vec4(1, 0, 0, 1), 4 * kTight));
}

TEST(TextureMatrix, IsAppliedAfterGeneration) {
  TexgenOptions o = withModes(TexgenMode::ObjectLinear, TexgenMode::ObjectLinear);
  o.textureMatrix = translation(0.5, 0.25, 0) * scaling(2, 3, 1);
  EXPECT_EQ(texgenAt(Vec3(1, 2, 3), Vec3::UnitZ(), o), Vec4(2.5, 6.25, 0, 1));
}

TEST(TextureMatrix, KeepsAProjectiveQWithoutDividing) {
  TexgenOptions o = withModes(TexgenMode::ObjectLinear, TexgenMode::ObjectLinear, TexgenMode::ObjectLinear);
  o.coordinates[2].plane = Vec4(0, 0, 1, 0);
  o.textureMatrix = Mat4::Identity();
  o.textureMatrix.row(3) = Eigen::RowVector4d(0, 0, 0.5, 2);  // q = r/2 + 2 q
  EXPECT_EQ(texgenAt(Vec3(1, 2, 3), Vec3::UnitZ(), o), Vec4(1, 2, 3, 3.5));
}

TEST(TwoPlaneProjector, EqualsObjectLinearWithNormalisedPlanes) {
  const Mesh mesh = meshes::icosphere(2);
  const std::pair<Vec4, Vec4> planes[] = {
      {Vec4(1, 0, 0, 0), Vec4(0, 1, 0, 0)},
      {Vec4(2, 0, 1, -0.5), Vec4(0, 3, -4, 1.25)},
      {Vec4(0.1, 0.2, 0.3, 7), Vec4(-5, 1, 2, -3)},
  };
  for (const auto& [u, v] : planes) {
    param::ProjectorOptions p;
    p.surface = param::SurfaceKind::TwoPlane;
    p.ray = param::RayKind::SurfaceNormal;
    p.planeU = u;
    p.planeV = v;
    const param::Projection projection = param::project(mesh, p);
    TexgenOptions o = withModes(TexgenMode::ObjectLinear, TexgenMode::ObjectLinear);
    o.coordinates[0].plane = u / u.head<3>().norm();
    o.coordinates[1].plane = v / v.head<3>().norm();
    const TexgenResult r = generateTexcoords(mesh, o);
    ASSERT_EQ(r.uv.uv.size(), projection.uv.uv.size());
    for (std::size_t c = 0; c < r.uv.uv.size(); ++c)
      for (int i = 0; i < 2; ++i) {
        const double a = r.uv.uv[c][i], b = projection.uv.uv[c][i];
        EXPECT_LE(std::abs(a - b), 1e-15 * std::max(std::abs(b), 1.0)) << c << " " << i << " " << a << " " << b;
      }
  }
}

TEST(Extremes, TinyAndHugePlaneCoefficientsGiveFiniteValues) {
  const Mesh mesh = meshes::icosphere(1);
  for (double scale : {1e-30, 1e30}) {
    TexgenOptions o =
        withModes(TexgenMode::ObjectLinear, TexgenMode::EyeLinear, TexgenMode::ObjectLinear, TexgenMode::EyeLinear);
    for (auto& c : o.coordinates) c.plane = scale * Vec4(1, -2, 3, 0.5);
    o.modelviewAtPlanes = lookAt(Vec3(1, 2, 3), Vec3::Zero(), Vec3::UnitY());
    const TexgenResult r = generateTexcoords(mesh, o);
    EXPECT_EQ(r.invalidCorners, 0u);
    for (std::size_t c = 0; c < r.q.size(); ++c) {
      EXPECT_TRUE(r.uv.uv[c].allFinite() && std::isfinite(r.uv.w[c]) && std::isfinite(r.q[c])) << c;
      EXPECT_NE(r.q[c], 0.0);
    }
  }
}

TEST(Extremes, AnEyeAMillionUnitsAwayGivesFiniteSphereAndReflectionMaps) {
  const Mesh mesh = meshes::icosphere(2);
  for (TexgenMode mode : {TexgenMode::SphereMap, TexgenMode::ReflectionMap, TexgenMode::EyeLinear}) {
    TexgenOptions o = withModes(mode, mode);
    const Mat4 view = lookAt(Vec3(0, 1e6, 1e6), Vec3::Zero(), Vec3::UnitY());
    o.modelviewAtPlanes = view;
    o.modelviewAtDraw = view;
    const TexgenResult r = generateTexcoords(mesh, o);
    EXPECT_EQ(r.invalidCorners, 0u);
    for (const Vec2& uv : r.uv.uv) EXPECT_TRUE(uv.allFinite());
    if (mode == TexgenMode::SphereMap) {
      for (const Vec2& uv : r.uv.uv) EXPECT_TRUE(uv.minCoeff() >= 0.0 && uv.maxCoeff() <= 1.0) << uv.transpose();
    }
  }
}

TEST(Extremes, AModelviewWithConditionNumberOneE12StillGivesFiniteValues) {
  const Mesh mesh = meshes::icosphere(2);
  const Mat4 illConditioned = rotationX(0.7) * scaling(1e6, 1.0, 1e-6) * rotationX(-0.3);
  const Eigen::JacobiSVD<Mat3> svd(illConditioned.topLeftCorner<3, 3>());
  EXPECT_NEAR(svd.singularValues()[0] / svd.singularValues()[2], 1e12, 1e-2 * 1e12);
  for (TexgenMode mode :
       {TexgenMode::EyeLinear, TexgenMode::SphereMap, TexgenMode::NormalMap, TexgenMode::ReflectionMap}) {
    for (bool normalize : {true, false}) {
      TexgenOptions o = withModes(mode, mode);
      o.modelviewAtPlanes = illConditioned;
      o.modelviewAtDraw = illConditioned;
      o.normalize = normalize;
      const TexgenResult r = generateTexcoords(mesh, o);
      EXPECT_EQ(r.invalidCorners, 0u);
      for (const Vec2& uv : r.uv.uv) EXPECT_TRUE(uv.allFinite());
    }
  }
}

TEST(Extremes, ASingularModelviewIsAUsageErrorWhereItsInverseIsNeeded) {
  const Mat4 flat = scaling(1, 1, 0);
  TexgenOptions eye = withModes(TexgenMode::EyeLinear, TexgenMode::EyeLinear);
  eye.modelviewAtPlanes = flat;
  EXPECT_THROW(texgenAt(Vec3(1, 2, 3), Vec3::UnitZ(), eye), UsageError);
  TexgenOptions normal = withModes(TexgenMode::NormalMap, TexgenMode::NormalMap);
  normal.modelviewAtDraw = flat;
  EXPECT_THROW(generateTexcoords(meshes::icosphere(1), normal), UsageError);
  TexgenOptions object = withModes(TexgenMode::ObjectLinear, TexgenMode::EyeLinear);
  object.modelviewAtDraw = flat;  // drawn flattened: no inverse needed
  EXPECT_EQ(texgenAt(Vec3(1, 2, 3), Vec3::UnitZ(), object), Vec4(1, 2, 0, 1));
}

TEST(Modes, SphereMapOnROrQAndNormalOrReflectionOnQAreUsageErrors) {
  EXPECT_THROW(
      texgenAt(Vec3::Zero(), Vec3::UnitZ(), withModes(TexgenMode::Off, TexgenMode::Off, TexgenMode::SphereMap)),
      UsageError);
  EXPECT_THROW(texgenAt(Vec3::Zero(), Vec3::UnitZ(),
                        withModes(TexgenMode::Off, TexgenMode::Off, TexgenMode::Off, TexgenMode::SphereMap)),
               UsageError);
  EXPECT_THROW(texgenAt(Vec3::Zero(), Vec3::UnitZ(),
                        withModes(TexgenMode::Off, TexgenMode::Off, TexgenMode::Off, TexgenMode::NormalMap)),
               UsageError);
  EXPECT_THROW(texgenAt(Vec3::Zero(), Vec3::UnitZ(),
                        withModes(TexgenMode::Off, TexgenMode::Off, TexgenMode::Off, TexgenMode::ReflectionMap)),
               UsageError);
  EXPECT_NO_THROW(texgenAt(Vec3(0, 0, -1), Vec3::UnitZ(),
                           withModes(TexgenMode::NormalMap, TexgenMode::ReflectionMap, TexgenMode::ReflectionMap)));
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::texgen
