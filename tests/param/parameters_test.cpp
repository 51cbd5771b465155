// The typed parameters every face fills, and the one place a projector is made from them.
#include "param/parameters.h"

#include <gtest/gtest.h>

#include "param/make_projector.h"
#include "param/surface_traits.h"

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

template <class Work>
std::string messageOf(Work&& work) {
  try {
    work();
  } catch (const std::exception& error) {
    return error.what();
  }
  return "(nothing thrown)";
}

TEST(Parameters, EachFaceSpellsANameItsOwnWay) {
  EXPECT_EQ(spellName(ParameterFace::CommandLine, "cap-angle"), "--cap-angle");
  EXPECT_EQ(spellName(ParameterFace::Scene, "cap-angle"), "cap_angle");
  EXPECT_EQ(spellName(ParameterFace::Keyword, "cap-angle"), "cap_angle");
  EXPECT_EQ(spellName(ParameterFace::Library, "cap-angle"), "capAngle");
  EXPECT_EQ(spellName(ParameterFace::Library, "overlap-resolution"), "overlapResolution");
  EXPECT_EQ(spellName(ParameterFace::Library, "projector"), "projector");
}

TEST(Parameters, AMessageNamesTheParameterWhereItCameFrom) {
  ParameterDictionary p(ParameterFace::Scene);
  p.add("projector", std::string("plane"), "/meshes/0/mappings/2/projector");
  p.add("seam-place", 30.0, "/meshes/0/mappings/2/seam_place");
  EXPECT_EQ(messageOf([&] { makeProjector(p); }),
            "/meshes/0/mappings/2/seam_place: only the wrapping projectors (cylinder, sphere) have a seam to place");
  // A name not given is spelled by the face.
  EXPECT_EQ(p.spelled("cap-angle"), "cap_angle");
  EXPECT_EQ(p.spelledWith("projector", "camera"), "projector camera");
}

TEST(Parameters, TheSameMistakeReadsInEachFacesWords) {
  const auto refusal = [](ParameterFace face) {
    ParameterDictionary p(face);
    p.add("omap", std::string("reflection"));
    return messageOf([&] { makeProjector(p); });
  };
  EXPECT_EQ(refusal(ParameterFace::CommandLine), "--omap reflection: expected --eye x,y,z");
  EXPECT_EQ(refusal(ParameterFace::Keyword), "omap='reflection': expected eye x,y,z");
  EXPECT_EQ(refusal(ParameterFace::Library), "omap \"reflection\": expected eye x,y,z");
}

TEST(Parameters, BooleansAreBooleans) {
  ParameterDictionary p(ParameterFace::Keyword);
  p.add("caps", std::int64_t(0));
  p.add("flip-u", std::int64_t(1));
  p.add("flip-v", std::string("no"));
  p.add("at-infinity", 0.0);
  EXPECT_FALSE(p.getBool("caps", true));  // 0 and 1 are Python's False and True
  EXPECT_TRUE(p.getBool("flip-u", false));
  EXPECT_THROW(p.getBool("flip-v", false), ParameterTypeError);
  EXPECT_EQ(messageOf([&] { p.getBool("flip-v", false); }), "flip_v: expected True or False, got 'no'");
  EXPECT_EQ(messageOf([&] { p.getBool("at-infinity", false); }), "at_infinity: expected True or False, got 0");
  EXPECT_TRUE(p.getBool("not-given", true));
}

TEST(Parameters, NoneIsNotGivenOnlyWhereAParameterIsOptional) {
  ParameterDictionary p(ParameterFace::Keyword);
  p.add("center", std::monostate{});
  p.add("fit", std::monostate{});
  EXPECT_FALSE(p.given("center"));
  EXPECT_FALSE(p.getVector<3>("center").has_value());
  EXPECT_THROW(p.getChoice("fit", kFitNames, Fit::BBox), ParameterTypeError);
  EXPECT_EQ(messageOf([&] { p.getChoice("fit", kFitNames, Fit::BBox); }),
            "fit: expected one of 'none', 'bbox', 'center', 'pca', 'obb', got None");
}

TEST(Parameters, NumbersIntegersAndVectorsAreChecked) {
  ParameterDictionary p(ParameterFace::Library);
  p.add("scale", std::int64_t(2));
  p.add("overlap-resolution", 2048.0);
  p.add("threads", 1.5);
  p.add("texture-size", std::int64_t(0));
  p.add("center", std::vector<double>{1, 2});
  p.add("axis-dir", std::vector<double>{0, 0, std::numeric_limits<double>::infinity()});
  EXPECT_EQ(p.getNumber("scale", 1.0), 2.0);
  EXPECT_EQ(p.getInteger("overlap-resolution", 1024, 1, 16384), 2048);  // an integral number is an integer
  EXPECT_EQ(messageOf([&] { p.getInteger("threads", 0, 0, 1024); }), "threads: expected an integer, got 1.5");
  EXPECT_EQ(messageOf([&] { p.getInteger("texture-size", 1, 1, 16384); }), "textureSize: expected 1 to 16384, got 0");
  EXPECT_EQ(messageOf([&] { p.getVector<3>("center"); }), "center: expected 3 finite numbers, got [1, 2]");
  EXPECT_EQ(messageOf([&] { p.getVector<3>("axis-dir"); }), "axisDir: expected 3 finite numbers, got [0, 0, inf]");
}

TEST(Parameters, AChoiceIsItsNameInAnyCaseWithDidYouMean) {
  ParameterDictionary p(ParameterFace::Keyword);
  p.add("projector", std::string("Cylinder"));
  p.add("omap", std::string("reflexion"));
  EXPECT_EQ(p.getChoice("projector", kSurfaceNames, SurfaceKind::Sphere), SurfaceKind::Cylinder);
  EXPECT_EQ(messageOf([&] { p.getChoice("omap", kRayNames, RayKind::SurfaceNormal); }),
            "omap: 'reflexion' is not one of: isn, centroid, normal, reflection; did you mean 'reflection'?");
}

TEST(Parameters, AParameterNobodyReadIsAnErrorWithTheNearestName) {
  ParameterDictionary p(ParameterFace::Keyword);
  p.add("projector", std::string("cylinder"));
  p.add("cap-angel", 30.0, "cap_angel");
  makeProjector(p);
  EXPECT_EQ(messageOf([&] { p.checkAllRead(projectorParameterNames()); }),
            "cap_angel: not a parameter here; did you mean cap_angle?");
  ParameterDictionary twice(ParameterFace::Keyword);
  twice.add("caps", true);
  EXPECT_EQ(messageOf([&] { twice.add("caps", false); }), "caps: given twice");
}

TEST(MakeProjector, ReadsEachParameterIntoTheTypedProjector) {
  ParameterDictionary p(ParameterFace::Library);
  p.add("projector", std::string("cylinder"));
  p.add("caps", true);
  p.add("cap-angle", std::int64_t(30));
  p.add("fit", std::string("none"));
  p.add("center", std::vector<double>{1, 2, 3});
  p.add("seam-place", std::string("auto"));
  p.add("uv-scale", std::vector<double>{2, 0.5});
  p.add("precision", std::string("float"));
  const ProjectorRequest made = makeProjector(p);
  const ProjectorOptions& o = made.options;
  EXPECT_EQ(o.surface, SurfaceKind::Cylinder);
  EXPECT_TRUE(o.cylinderCaps);
  EXPECT_EQ(o.capAngleDegrees, 30.0);
  EXPECT_EQ(o.placement.fit, Fit::None);
  ASSERT_TRUE(o.placement.frame.has_value());
  EXPECT_EQ(o.placement.frame->center, Vec3(1, 2, 3));
  EXPECT_TRUE(made.seamPlaceAuto);
  EXPECT_EQ(o.uvTransform.scale, Vec2(2, 0.5));
  EXPECT_EQ(o.arithmetic.precision, Precision::Float);
  p.checkAllRead(projectorParameterNames());  // every one was read
}

TEST(MakeProjector, TriplanarIsInObjectSpaceUnlessAFitIsGiven) {
  ParameterDictionary p(ParameterFace::Keyword);
  p.add("projector", std::string("triplanar"));
  EXPECT_EQ(makeProjector(p).options.placement.fit, Fit::None);
  p.add("fit", std::string("bbox"));
  EXPECT_EQ(makeProjector(p).options.placement.fit, Fit::BBox);
  p.add("tile", 2.0);
  EXPECT_EQ(makeProjector(p).options.triplanar.tile, 2.0);
  ParameterDictionary sphere(ParameterFace::Keyword);
  sphere.add("tile", 2.0);
  EXPECT_EQ(messageOf([&] { makeProjector(sphere); }), "tile goes with projector='triplanar' only");
}

TEST(MakeProjector, AConventionOwnsItsParameters) {
  ParameterDictionary p(ParameterFace::CommandLine);
  p.add("projector", std::string("sphere"));
  p.add("convention", std::string("blender"));
  p.add("flip-u", true);
  EXPECT_EQ(messageOf([&] { makeProjector(p); }),
            "--convention blender sets the placement, the seam and the UV transform; --flip-u goes with --convention "
            "uvtk only");
}

TEST(MakeProjector, TheCameraTakesItsOwnNamesWhereTheCommandsCameraHasThePlainOnes) {
  ProjectorContext render;
  render.center = "frame-center";
  render.cameraEye = "proj-eye";
  render.cameraCenter = "proj-center";
  render.cameraOwnsEye = true;
  ParameterDictionary p(ParameterFace::CommandLine);
  p.add("projector", std::string("camera"));
  EXPECT_EQ(messageOf([&] { makeProjector(p, render); }), "--projector camera: expected --proj-eye x,y,z");
  p.add("proj-eye", std::vector<double>{0, 0, 5});
  const ProjectorOptions o = makeProjector(p, render).options;
  EXPECT_EQ(o.camera.eye, Vec3(0, 0, 5));
  EXPECT_EQ(o.camera.center, Vec3::Zero());
  p.add("frame-center", std::vector<double>{0, 0, 0});
  EXPECT_EQ(messageOf([&] { makeProjector(p, render); }),
            "--frame-center goes with the surface projectors, not --projector camera");
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

TEST(SurfaceTraits, EachSurfaceIsAskedInOnePlace) {
  std::vector<std::string> wrapping, perTriangle;
  for (const SurfaceKind surface : kSurfaces) {
    const SurfaceTraits& t = traitsOf(surface);
    if (t.wraps) wrapping.push_back(t.name);
    if (t.choosesPerTriangle) perTriangle.push_back(t.name);
    EXPECT_EQ(nameOf(kSurfaceNames, surface), t.name);  // one spelling
    // u's period starts where the surface says, and only wrapping surfaces have one
    EXPECT_EQ(uPeriodStartOf([&] { ProjectorOptions o; o.surface = surface; return o; }()).has_value(), t.wraps);
  }
  EXPECT_EQ(wrapping, (std::vector<std::string>{"cylinder", "sphere"}));
  EXPECT_EQ(perTriangle, (std::vector<std::string>{"cube", "triplanar", "atlas", "lscm", "arap"}));
  ProjectorOptions seed;
  seed.spherePreset = SpherePreset::Seed004;  // s = atan2(y, x)/(2 pi): u in [-1/2, 1/2)
  EXPECT_EQ(uPeriodStartOf(seed), -0.5);
}

TEST(MakeProjector, TheSeamIsPlacedByDegreesOrAuto) {
  // --seam-place 30 was refused ("expected a text") when the parameters were first typed.
  ParameterDictionary degrees(ParameterFace::CommandLine);
  degrees.add("projector", std::string("cylinder"));
  degrees.add("seam-place", 30.0);
  const ProjectorRequest turned = makeProjector(degrees);
  EXPECT_EQ(turned.options.placement.turnDegrees, 30.0);
  EXPECT_FALSE(turned.seamPlaceAuto);
  ParameterDictionary automatic(ParameterFace::Keyword);
  automatic.add("seam-place", std::string("auto"));
  EXPECT_TRUE(makeProjector(automatic).seamPlaceAuto);
  ParameterDictionary sideways(ParameterFace::Keyword);
  sideways.add("seam-place", std::string("sideways"));
  EXPECT_EQ(messageOf([&] { makeProjector(sideways); }), "seam_place: expected degrees or 'auto', got 'sideways'");
  ParameterDictionary flag(ParameterFace::Keyword);
  flag.add("seam-place", true);
  EXPECT_THROW(makeProjector(flag), ParameterTypeError);
}

TEST(MakeProjector, CapsGoWithTheCylinderOnly) {
  ParameterDictionary p(ParameterFace::Keyword);
  p.add("projector", std::string("sphere"));
  p.add("caps", true);
  EXPECT_EQ(messageOf([&] { makeProjector(p); }), "caps goes with projector='cylinder' only");
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param
