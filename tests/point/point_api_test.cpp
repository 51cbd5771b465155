// The installed point API (uvtk/point.h) through its library target, against values computed by hand
// from docs/conventions.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "uvtk/point.h"
#include "uvtk/testing.h"

namespace {
namespace UVTK_TEST_FILE {

using uvtk::point::Mapping;
using uvtk::point::Result;
using uvtk::point::Status;
using uvtk::point::uvError;
using uvtk::point::Vector3;

constexpr double kPi = 3.14159265358979323846;
constexpr double kTight = 1e-15;

TEST(PointApi, SphereTurnFractionAndPolarAngle) {
  const Mapping sphere("--projector sphere");
  const Result r = sphere.at({0, 1, 0});
  EXPECT_UV_STATUS(r, Status::Ok);
  EXPECT_NEAR(r.u, 0.25, kTight);
  EXPECT_NEAR(r.v, 0.5, kTight);
  EXPECT_STREQ(r.reason, "");
  EXPECT_EQ(r.period[0], 1.0);
  EXPECT_EQ(r.period[1], 0.0);
  EXPECT_EQ(r.position[1], 1.0);
  EXPECT_STREQ(r.mapping, "--projector sphere");
  EXPECT_EQ(sphere.options(), "--projector sphere");
  EXPECT_FALSE(sphere.needsNormal());

  // Any radius: the isn ray is radial. v = 1 - phi/pi, phi = 45 degrees here.
  const Result r2 = sphere.at({-3, 0, 3});
  EXPECT_NEAR(r2.u, 0.5, kTight);
  EXPECT_NEAR(r2.v, 0.75, kTight);
  EXPECT_EQ(r2.w, 0.0);
  EXPECT_EQ(r2.q, 1.0);
}

TEST(PointApi, SphereSeamPoleAndInvalidSayWhy) {
  const Mapping sphere("--projector sphere");
  const Result seam = sphere.at({2, 0, 0.5});
  EXPECT_UV_STATUS(seam, Status::OnSeam);
  EXPECT_EQ(seam.u, 0.0);
  EXPECT_STREQ(seam.reason, "on the seam: u and u + 1 are the same point");

  const Result north = sphere.at({0, 0, 2});
  EXPECT_UV_STATUS(north, Status::Pole);
  EXPECT_EQ(north.u, 0.0);
  EXPECT_EQ(north.v, 1.0);
  EXPECT_STREQ(north.reason, "on the axis: u is undefined there (written as 0), v is exact");
  const Result south = sphere.at({0, 0, -1});
  EXPECT_UV_STATUS(south, Status::Pole);
  EXPECT_EQ(south.v, 0.0);

  const Result centre = sphere.at({0, 0, 0});
  EXPECT_UV_STATUS(centre, Status::Invalid);
  EXPECT_STREQ(centre.reason, "the point is the sphere's centre");
  // The cube's isn ray is undefined there too, and says so of the cube (it named the sphere).
  const Result cubeCentre = Mapping("--projector cube").at({0, 0, 0});
  EXPECT_UV_STATUS(cubeCentre, Status::Invalid);
  EXPECT_STREQ(cubeCentre.reason, "the point is the cube's centre");
  EXPECT_EQ(centre.u, 0.0);
  EXPECT_EQ(centre.v, 0.0);

  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Result notFinite = sphere.at({nan, 0, 0});
  EXPECT_UV_STATUS(notFinite, Status::Invalid);
  EXPECT_STREQ(notFinite.reason, "the position is not finite");

  EXPECT_STREQ(uvtk::point::statusName(Status::Ok), "ok");
  EXPECT_STREQ(uvtk::point::statusName(Status::Pole), "pole");
  EXPECT_STREQ(uvtk::point::statusName(Status::OnSeam), "on-seam");
  EXPECT_STREQ(uvtk::point::statusName(Status::Invalid), "invalid");
}

TEST(PointApi, NormalRayNeedsANormal) {
  const Mapping sphere("--projector sphere --omap normal");
  EXPECT_TRUE(sphere.needsNormal());
  const Result noNormal = sphere.at({0.5, 0, 0});
  EXPECT_UV_STATUS(noNormal, Status::Invalid);
  EXPECT_STREQ(noNormal.reason, "the normal is zero (this mapping reads it)");
  // From (0.5, 0, 0) along +y the unit sphere is met at (0.5, sqrt(3)/2, 0): u = 60 degrees.
  const Result r = sphere.at({0.5, 0, 0}, {0, 2, 0});
  EXPECT_UV_STATUS(r, Status::Ok);
  EXPECT_NEAR(r.u, 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(r.v, 0.5, kTight);
}

TEST(PointApi, CylinderUIsTheTurnAndVTheHeight) {
  const Mapping cylinder("--projector cylinder");
  const Result r = cylinder.at({-2, 0, 0.75});
  EXPECT_NEAR(r.u, 0.5, kTight);
  EXPECT_EQ(r.v, 0.75);
  const Result axis = cylinder.at({0, 0, 3});
  EXPECT_UV_STATUS(axis, Status::Pole);
  EXPECT_EQ(axis.v, 3.0);
}

TEST(PointApi, CubeFaceIdIsW) {
  // +X: sc = -z, tc = -y. The isn O-mapping is the box mapping, s = (sc + 1)/2, t = (tc + 1)/2 of p.
  const Mapping cube("--projector cube --cube-layout faces");
  const Result px = cube.at({2, 0.5, -0.4});
  EXPECT_UV_STATUS(px, Status::Ok);
  EXPECT_EQ(px.w, 0.0);
  EXPECT_NEAR(px.u, (0.4 + 1) / 2, kTight);
  EXPECT_NEAR(px.v, (-0.5 + 1) / 2, kTight);
  EXPECT_EQ(px.period[0], 0.0);  // nothing wraps

  // The central ray divides by the major component: the direct convention's example of
  // docs/conventions.md §3, -Z with (s, t) from (x, y).
  const Mapping direct("--projector cube --cube-convention direct --omap centroid --cube-layout faces");
  const Result nz = direct.at({-0.2, 0.5, -0.84});
  EXPECT_EQ(nz.w, 5.0);
  EXPECT_NEAR(nz.u, (-0.2 / 0.84 + 1) / 2, kTight);
  EXPECT_NEAR(nz.v, (0.5 / 0.84 + 1) / 2, kTight);

  const Vector3 faces[] = {{1, 0.1, 0.2}, {-1, 0.1, 0.2}, {0.1, 1, 0.2}, {0.1, -1, 0.2}, {0.1, 0.2, 1}, {0.1, 0.2, -1}};
  for (int id = 0; id < 6; ++id) EXPECT_EQ(cube.at(faces[id]).w, id) << id;

  const Result edge = cube.at({1, 1, 0.5});
  EXPECT_UV_STATUS(edge, Status::OnSeam);
  EXPECT_EQ(edge.w, 0.0);  // the tie goes to x
  EXPECT_STREQ(edge.reason, "on an edge of the cube: the face follows the tie rule (x before y before z)");
}

TEST(PointApi, TexgenObjectLinearAndQ) {
  const Mapping texgen("--s object_linear:1,0,0,0 --t object_linear:0,1,0,0 --q object_linear:0,0,1,2");
  const Result r = texgen.at({0.25, -0.5, 3});
  EXPECT_UV_STATUS(r, Status::Ok);
  EXPECT_EQ(r.u, 0.25);
  EXPECT_EQ(r.v, -0.5);
  EXPECT_EQ(r.w, 0.0);  // r: GL's default plane (0, 0, 0, 0)
  EXPECT_EQ(r.q, 5.0);  // q = z + 2, not divided out
  EXPECT_EQ(r.period[0], 0.0);
}

TEST(PointApi, TexgenSphereMapAndItsSingularPoint) {
  // Default view: eye at the origin looking down -z, so object = eye coordinates. At (0, 0, -2) with
  // the normal towards the eye, the reflection is (0, 0, 1): m = 4, s = t = 1/2.
  const Mapping sphereMap("--texgen sphere_map");
  EXPECT_TRUE(sphereMap.needsNormal());
  const Result facing = sphereMap.at({0, 0, -2}, {0, 0, 1});
  EXPECT_UV_STATUS(facing, Status::Ok);
  EXPECT_NEAR(facing.u, 0.5, kTight);
  EXPECT_NEAR(facing.v, 0.5, kTight);
  EXPECT_EQ(facing.q, 1.0);
  // u = (0, 0, -1), n = (1, 0, 0): r = (0, 0, -1), m = 0, GL's singular case.
  const Result grazing = sphereMap.at({0, 0, -2}, {1, 0, 0});
  EXPECT_UV_STATUS(grazing, Status::Pole);
  EXPECT_STREQ(grazing.reason, "sphere map: the reflection is (0, 0, -1), where m = 0; s = t = 1/2 as GL leaves it");
  EXPECT_EQ(grazing.u, 0.5);
  EXPECT_EQ(grazing.v, 0.5);
  EXPECT_EQ(grazing.period[0], 0.0);
  // Under a view from (0, 0, 5) towards the origin, the object point (0, 0, 3) facing +z is in front.
  const Mapping viewed("--texgen sphere_map --eye 0,0,5 --center 0,0,0 --up 0,1,0");
  const Result front = viewed.at({0, 0, 3}, {0, 0, 1});
  EXPECT_NEAR(front.u, 0.5, kTight);
  EXPECT_NEAR(front.v, 0.5, kTight);
}

// A mesh whose bounding box runs from (0, 1, 2) to (4, 3, 10): centre c = (2, 2, 6).
const std::vector<Vector3> kBoxMesh = {{0, 1, 2}, {4, 3, 10}, {1, 2, 7}, {3, 1.5, 4}};
const Vector3 kC = {2, 2, 6};

Vector3 offset(double x, double y, double z) { return {kC[0] + x, kC[1] + y, kC[2] + z}; }

TEST(PointApi, BlenderSphereAndCylinder) {
  const Mapping sphere("--projector sphere --convention blender", kBoxMesh);
  EXPECT_NEAR(sphere.at(offset(1, 0, 0)).u, 0.25, 1e-12);
  EXPECT_NEAR(sphere.at(offset(0, 1, 0)).u, 0.5, 1e-12);
  EXPECT_NEAR(sphere.at(offset(-1, 0, 0)).u, 0.75, 1e-12);
  EXPECT_NEAR(sphere.at(offset(-1, 0, 0)).v, 0.5, 1e-12);
  EXPECT_UV_STATUS(sphere.at(offset(0, -1, 0)), Status::OnSeam);  // the seam lies on -y
  EXPECT_UV_STATUS(sphere.at(offset(0, 0, 1)), Status::Pole);

  const Mapping cylinder("--projector cylinder --convention blender", kBoxMesh);
  const Result r = cylinder.at(offset(1, 0, 0.5));
  EXPECT_NEAR(r.u, 0.25, 1e-12);
  EXPECT_NEAR(r.v, (0.5 + 1) / 2, 1e-12);  // v = (z - c_z + 1)/2 in object units
  EXPECT_NEAR(cylinder.at(offset(0, 1, -3)).v, (-3 + 1) / 2.0, 1e-12);
  // The UV transform halves v only: one turn is still (1, 0).
  EXPECT_EQ(r.period[0], 1.0);
  EXPECT_EQ(r.period[1], 0.0);
}

TEST(PointApi, AssimpSphere) {
  const Mapping sphere("--projector sphere --convention assimp", kBoxMesh);
  EXPECT_NEAR(sphere.at(offset(1, 0, 0)).u, 0.75, 1e-12);
  EXPECT_NEAR(sphere.at(offset(0, 0, 1)).u, 0.5, 1e-12);
  // v = (asin(d_y) + pi/2)/pi of the unit direction d from the centre.
  const double dy = 0.5 / std::sqrt(1.25);
  const Result r = sphere.at(offset(1, 0.5, 0));
  EXPECT_NEAR(r.v, (std::asin(dy) + kPi / 2) / kPi, 1e-12);
  EXPECT_NEAR(r.u, 0.75, 1e-12);
}

TEST(PointApi, FittedPlacementNeedsTheMesh) {
  const Mapping fitted("--projector sphere --fit bbox", kBoxMesh);
  // The bbox fit puts the sphere's centre at the box's centre.
  EXPECT_NEAR(fitted.at(offset(0, 1, 0)).u, 0.25, 1e-12);
  try {
    Mapping unfitted("--projector sphere --fit bbox");
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--fit"), std::string::npos) << e.what();
  }
}

// The message of the std::invalid_argument that `options` throws; fails the test if none is thrown.
std::string rejection(const std::string& options) {
  try {
    Mapping m(options);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "Mapping(\"" << options << "\") did not throw";
  return "";
}

TEST(PointApi, InvalidOptionsThrowNamingTheOption) {
  struct Case {
    const char* options;
    const char* named;
  } cases[] = {
      {"--projector banana", "--projector"},
      {"--frobnicate 3", "--frobnicate"},
      {"--projector sphere --omap reflection", "--eye"},
      {"--projector plane --convention blender", "--convention blender"},
      {"--projector sphere --uv-scale 1,2,3", "--uv-scale"},
      {"--texgen sphere_map --omap normal", "--omap"},
      {"--projector sphere --up 0,1,0", "--up"},
      {"--projector sphere --seam-place auto", "--seam-place auto"},
  };
  for (const Case& c : cases) {
    const std::string message = rejection(c.options);
    EXPECT_NE(message.find(c.named), std::string::npos) << c.options << ": " << message;
    EXPECT_EQ(message.rfind(std::string("uvtk::point::Mapping(\"") + c.options + "\")", 0), 0u) << message;
  }
}

// The typed constructor and the option text make the same mapping: the same numbers bit for bit.
TEST(PointApi, TypedParametersMakeTheMappingTheTextMakes) {
  using uvtk::point::Parameter;
  using Numbers = std::vector<double>;
  struct Case {
    const char* text;
    std::vector<Parameter> typed;
  } cases[] = {
      {"--projector sphere --omap normal", {{"projector", std::string("sphere")}, {"omap", std::string("normal")}}},
      {"--projector cylinder --caps --cap-angle 30",
       {{"projector", std::string("cylinder")}, {"caps", true}, {"cap-angle", std::int64_t(30)}}},
      {"--projector triplanar --tile 2.5 --blend 4", {{"projector", std::string("triplanar")}, {"tile", 2.5}, {"blend", 4.0}}},
      {"--projector sphere --omap reflection --eye 0,0,5 --uv-offset -0.25,0",
       {{"projector", std::string("sphere")}, {"omap", std::string("reflection")}, {"eye", Numbers{0, 0, 5}},
        {"uv-offset", Numbers{-0.25, 0}}}},
      {"--texgen sphere_map --eye=0,0,5 --s object_linear:1,0,0,0.5",
       {{"texgen", std::string("sphere_map")}, {"eye", Numbers{0, 0, 5}}, {"s", std::string("object_linear:1,0,0,0.5")}}},
  };
  const std::vector<Vector3> points = {{0.3, 0.2, 1.0}, {-0.7, 0.1, 0.2}, {0.1, -0.9, -0.4}};
  for (const Case& c : cases) {
    const Mapping text(c.text), typed(c.typed);
    for (const Vector3& p : points) {
      const Result a = text.at(p, {p[0], 1, 0.5}), b = typed.at(p, {p[0], 1, 0.5});
      EXPECT_EQ(a.u, b.u) << c.text;
      EXPECT_EQ(a.v, b.v) << c.text;
      EXPECT_EQ(a.w, b.w) << c.text;
      EXPECT_EQ(a.status, b.status) << c.text;
    }
  }
  EXPECT_EQ(Mapping(cases[1].typed).options(), "--projector cylinder --caps --cap-angle 30");
}

// A flag is a flag in either face: --caps=false and caps=false turn caps off, a text is refused as
// the wrong kind (ParameterTypeError, caught across the library's boundary), naming the parameter
// as the face spells it; a misspelt name gets the nearest.
TEST(PointApi, TypedParametersAreCheckedByKind) {
  using uvtk::point::Face;
  using uvtk::point::Parameter;
  using uvtk::point::ParameterTypeError;
  const Vector3 side{0.6, 0.8, 0.95};  // on the cylinder's rim: a cap face's normal
  const Vector3 up{0, 0, 1};
  const Result off = Mapping("--projector cylinder --caps=false").at(side, up);
  const Result on = Mapping("--projector cylinder --caps").at(side, up);
  EXPECT_NE(off.u, on.u);
  EXPECT_EQ(Mapping({{"projector", std::string("cylinder")}, {"caps", false}}).at(side, up).u, off.u);
  EXPECT_EQ(Mapping({{"projector", std::string("cylinder")}, {"caps", std::int64_t(0)}}).at(side, up).u, off.u);
  const auto typeError = [](const std::vector<Parameter>& parameters, Face face) -> std::string {
    try {
      Mapping m(parameters, {}, face);
    } catch (const ParameterTypeError& e) {
      return e.what();
    } catch (const std::exception& e) {
      return std::string("not a ParameterTypeError: ") + e.what();
    }
    return "nothing thrown";
  };
  EXPECT_EQ(typeError({{"projector", std::string("cylinder")}, {"caps", std::string("no")}}, Face::Keyword),
            "uvtk::point::Mapping: caps: expected True or False, got 'no'");
  EXPECT_EQ(typeError({{"projector", std::string("cylinder")}, {"cap-angle", std::string("wide")}}, Face::Library),
            "uvtk::point::Mapping: capAngle: expected a number, got 'wide'");
  try {
    Mapping m({{"projecter", std::string("sphere")}}, {}, Face::Keyword);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean projector?"), std::string::npos) << e.what();
  }
}

TEST(PointApi, MovedMappingStillEvaluates) {
  Mapping a("--projector sphere");
  Mapping b(std::move(a));
  EXPECT_NEAR(b.at({0, 1, 0}).u, 0.25, kTight);
  Mapping c("--projector plane");
  c = std::move(b);
  EXPECT_NEAR(c.at({0, 1, 0}).u, 0.25, kTight);
  EXPECT_STREQ(c.at({0, 1, 0}).mapping, "--projector sphere");
}

TEST(PointApi, OneMappingServesManyThreads) {
  const Mapping sphere("--projector sphere --omap normal");
  std::vector<Vector3> points;
  for (int i = 0; i < 2000; ++i) points.push_back({std::cos(i * 0.1) * 0.5, std::sin(i * 0.1) * 0.5, (i % 7) * 0.1});
  std::vector<Result> serial;
  for (const Vector3& p : points) serial.push_back(sphere.at(p, {p[0], 1, 0.5}));
  std::vector<std::vector<Result>> parallel(4);
  std::vector<std::thread> threads;
  for (std::vector<Result>& out : parallel)
    threads.emplace_back([&] {
      for (const Vector3& p : points) out.push_back(sphere.at(p, {p[0], 1, 0.5}));
    });
  for (std::thread& t : threads) t.join();
  for (const std::vector<Result>& out : parallel)
    for (std::size_t i = 0; i < points.size(); ++i) {
      ASSERT_EQ(out[i].u, serial[i].u) << i;
      ASSERT_EQ(out[i].v, serial[i].v) << i;
      ASSERT_EQ(out[i].status, serial[i].status) << i;
    }
}

TEST(UvError, RemovesWholeTurns) {
  const Mapping sphere("--projector sphere");
  const Result r = sphere.at({0, 1, 0});  // (0.25, 0.5)
  EXPECT_NEAR(uvError(0.25, 0.5, r), 0.0, kTight);
  EXPECT_NEAR(uvError(1.25, 0.5, r), 0.0, kTight);
  EXPECT_NEAR(uvError(-0.75, 0.5, r), 0.0, kTight);
  EXPECT_NEAR(uvError(-2.75, 0.5, r), 0.0, 1e-14);
  EXPECT_NEAR(uvError(0.3, 0.5, r), 0.05, 1e-15);
  EXPECT_NEAR(uvError(1.3, 0.6, r), std::hypot(0.05, 0.1), 1e-15);
  EXPECT_NEAR(uvError(0.7, 0.5, r), 0.45, 1e-15);  // the nearest turn
  // v is not periodic.
  EXPECT_NEAR(uvError(0.25, 1.5, r), 1.0, kTight);
  // A seam point: u = 0 and u = 1 are the same.
  const Result seam = sphere.at({1, 0, 0});
  EXPECT_EQ(uvError(1.0, 0.5, seam), 0.0);
  EXPECT_NEAR(uvError(0.999, 0.5, seam), 0.001, 1e-15);
}

TEST(UvError, IgnoresUAtAPole) {
  const Mapping sphere("--projector sphere");
  const Result pole = sphere.at({0, 0, 1});
  EXPECT_EQ(uvError(0.123, 1.0, pole), 0.0);
  EXPECT_NEAR(uvError(0.123, 0.9, pole), 0.1, 1e-15);
}

TEST(UvError, ComparesDirectlyWhereNothingWraps) {
  const Mapping plane("--projector plane");
  const Result r = plane.at({0.25, 0.5, 7});
  EXPECT_EQ(r.u, 0.25);
  EXPECT_EQ(r.v, 0.5);
  EXPECT_EQ(uvError(1.25, 0.5, r), 1.0);
  // A UV transform that scales u scales the period with it.
  const Mapping scaled("--projector sphere --uv-scale 2,1");
  const Result s = scaled.at({0, 1, 0});
  EXPECT_EQ(s.period[0], 2.0);
  EXPECT_NEAR(s.u, 0.5, kTight);
  EXPECT_NEAR(uvError(2.5, 0.5, s), 0.0, kTight);
  EXPECT_NEAR(uvError(1.5, 0.5, s), 1.0, kTight);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
