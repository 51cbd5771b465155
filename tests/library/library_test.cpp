// The installed C++ library (<uvtk/uvtk.h>) through its public interface only: options as structs
// and as command lines, mapping in memory with hand-computed values, the verdict, errors as the
// public exception types, and files written and read back.
#include <gtest/gtest.h>

#include <functional>

#include <filesystem>

#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <tuple>
#include <stdexcept>
#include <string>

#include "scratch_dir.h"
#include "uvtk/uvtk.h"

namespace uvtk::api {
namespace {
namespace UVTK_TEST_FILE {

class LibraryTest : public ScratchDirTest {};

Mesh triangle() {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}};
  mesh.triangles = {{0, 1, 2}};
  return mesh;
}

// An octahedron: its two apexes lie on the sphere projector's axis (poles), its four equator
// vertices at azimuths 0, 90, 180 and 270 degrees.
Mesh octahedron() {
  Mesh mesh;
  mesh.positions = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int i = 0; i < 4; ++i) {
    mesh.triangles.push_back({i, (i + 1) % 4, 4});
    mesh.triangles.push_back({(i + 1) % 4, i, 5});
  }
  return mesh;
}

template <class Work>
std::string messageOf(Work&& work) {
  try {
    work();
  } catch (const std::exception& error) {
    return error.what();
  }
  return "(nothing thrown)";
}

TEST(MapOptions, DefaultsAreTheCommandLinesAndSayNothing) {
  const MapOptions defaults;
  EXPECT_EQ(defaults.projector, "sphere");
  EXPECT_FALSE(defaults.fit.has_value());  // the projector's own: bbox, triplanar none
  EXPECT_EQ(defaults.seam, "shift");
  EXPECT_EQ(defaults.commandLine(), "");
  const MapOptions parsed = MapOptions::parse("");
  EXPECT_EQ(parsed.commandLine(), "");
}

TEST(MapOptions, ParseFillsTheFieldsAndCommandLineGivesThemBack) {
  const MapOptions o = MapOptions::parse(
      "--projector cylinder --fit none --caps --cap-angle 30 --uv-scale 2,0.5 --center 1,2,3 "
      "--fail-on overlap=0.5 --fail-on stretch_p99=4 --seam cut --seam-place auto --flip-v");
  EXPECT_EQ(o.projector, "cylinder");
  EXPECT_EQ(o.fit, "none");
  EXPECT_TRUE(o.caps);
  EXPECT_EQ(o.capAngle, 30.0);
  EXPECT_EQ(o.uvScale, (Vector2{2.0, 0.5}));
  ASSERT_TRUE(o.center.has_value());
  EXPECT_EQ(*o.center, (Vector3{1, 2, 3}));
  EXPECT_EQ(o.failOn, (std::vector<std::string>{"overlap=0.5", "stretch_p99=4"}));
  EXPECT_EQ(o.seam, "cut");
  EXPECT_TRUE(o.seamPlaceAuto);
  EXPECT_FALSE(o.seamPlace.has_value());
  EXPECT_TRUE(o.flipV);
  EXPECT_FALSE(o.flipU);
  EXPECT_EQ(o.commandLine(),
            "--projector cylinder --fit none --center 1,2,3 --caps --cap-angle 30 --seam cut --seam-place auto "
            "--uv-scale 2,0.5 --flip-v --fail-on overlap=0.5 --fail-on stretch_p99=4");
  EXPECT_EQ(MapOptions::parse(o.commandLine()).commandLine(), o.commandLine());
}

TEST(MapOptions, ANumberKeepsEveryBitThroughTheCommandLine) {
  MapOptions o;
  o.poleEps = 0.1 + 0.2;  // 0.30000000000000004
  o.uvOffset = {1.0 / 3.0, -2e-300};
  const MapOptions back = MapOptions::parse(o.commandLine());
  EXPECT_EQ(back.poleEps, o.poleEps);
  EXPECT_EQ(back.uvOffset, o.uvOffset);
}

TEST(MapOptions, BadOptionsThrowInvalidArgumentWithTheCommandLinesMessage) {
  EXPECT_NE(messageOf([] { MapOptions::parse("--projector sphera"); }).find("--projector"), std::string::npos);
  EXPECT_THROW(MapOptions::parse("--projector sphera"), std::invalid_argument);
  EXPECT_THROW(MapOptions::parse("-o out.obj"), std::invalid_argument);  // an output is not a mapping option
  EXPECT_THROW(MapOptions::parse("--fail-on nonsense=1"), std::invalid_argument);
  EXPECT_THROW(MapOptions::parse("--projector 'sphere"), std::invalid_argument);  // unterminated quote
  MapOptions bad;
  bad.omap = "sideways";
  EXPECT_THROW(map(triangle(), bad), std::invalid_argument);
}

// parse() reads the command line's syntax by the fields' kinds (no CLI11 in the library) and hands
// the values to the engine's reader: each message names the option as the command line does.
TEST(Options, ParseReadsTheSyntaxByKindAndTheEngineChecksTheValues) {
  const std::vector<std::pair<std::function<void()>, std::string>> refusals = {
      {[] { MapOptions::parse("--cap-angle abc"); }, "--cap-angle: expected a number, found 'abc'"},
      {[] { MapOptions::parse("--projecter sphere"); }, "--projecter: not an option here; did you mean --projector?"},
      {[] { MapOptions::parse("--projector"); }, "--projector: expected a value"},
      {[] { MapOptions::parse("sphere"); }, "expected an option (--name), found 'sphere'"},
      {[] { MapOptions::parse("--threads 99999"); }, "--threads: expected 0 to 1024, got 99999"},
      {[] { MapOptions::parse("--center 1,2"); }, "--center"},
      {[] { RenderOptions::parse("--aov uv"); }, "--aov: `uvtk render` takes it, the library's options struct does not carry it"},
      {[] { RenderOptions::parse("--camera explicit"); }, "--camera explicit: expected --eye x,y,z"},
      {[] { RenderOptions::parse("--spp 2.5"); }, "--spp: expected an integer, found '2.5'"},
      {[] { CompareOptions::parse("--top 0"); }, "--top: expected at least 1, got 0"},
      {[] { ReportOptions::parse("--size 0x0"); }, "--size"},
  };
  for (const auto& [call, message] : refusals) {
    EXPECT_THROW(call(), std::invalid_argument) << message;
    EXPECT_NE(messageOf(call).find(message), std::string::npos) << messageOf(call);
  }
  // A negative number is a value, not an option; a flag takes no value word; a list repeats.
  const MapOptions o = MapOptions::parse("--caps --projector cylinder --center -1,0,0 --fail-on overlap=0.1 --fail-on flipped_area=0");
  EXPECT_TRUE(o.caps);
  EXPECT_EQ(o.projector, "cylinder");
  EXPECT_EQ(*o.center, (std::array<double, 3>{-1, 0, 0}));
  EXPECT_EQ(o.failOn, (std::vector<std::string>{"overlap=0.1", "flipped_area=0"}));
  EXPECT_FALSE(MapOptions::parse("--projector cylinder --caps=off").caps);
  const RenderOptions r = RenderOptions::parse("--size 64x48 --eye 0,0,5 --ortho=-1,1,-1,1");
  EXPECT_EQ(r.size, "64x48");
  EXPECT_EQ(r.ortho, "-1,1,-1,1");
}

TEST(Map, APlaneInObjectCoordinatesGivesXAndY) {
  MapOptions o;
  o.projector = "plane";
  o.fit = "none";
  const Mapping m = map(triangle(), o);
  ASSERT_EQ(m.uv.size(), 3u);
  EXPECT_EQ(m.uv[0], (Vector2{0, 0}));
  EXPECT_EQ(m.uv[1], (Vector2{2, 0}));
  EXPECT_EQ(m.uv[2], (Vector2{0, 3}));
  EXPECT_EQ(m.source, "projector");
  EXPECT_EQ(m.verdict.status, "pass");
  EXPECT_TRUE(m.verdict.reasons.empty());
  for (const CornerState s : m.state) EXPECT_EQ(s, CornerState::Ok);
  EXPECT_EQ(m.faceFlags, (std::vector<std::uint8_t>{0}));
  EXPECT_NE(m.summaryJson.find("\"verdict\":\"pass\""), std::string::npos);
}

TEST(Map, TriplanarAndTheCameraAreFieldsLikeEveryOtherOption) {
  MapOptions o;
  o.projector = "triplanar";
  o.tile = 2;
  o.blend = 4;
  EXPECT_EQ(o.commandLine(), "--projector triplanar --tile 2 --blend 4");
  const Mapping box = map(triangle(), o);  // facing +z: the z projection (x, y) T at every corner
  EXPECT_EQ(box.uv, (std::vector<Vector2>{{0, 0}, {4, 0}, {0, 6}}));
  EXPECT_NE(box.summaryJson.find("\"triplanar_faces\":{\"x\":0,\"y\":0,\"z\":1}"), std::string::npos);
  MapOptions camera = MapOptions::parse("--projector camera --eye 0,0,5 --fovy 90 --up 0,1,0");
  EXPECT_EQ(camera.fovy, 90.0);
  ASSERT_TRUE(camera.up.has_value());
  const Mapping view = map(triangle(), camera);  // u = 1/2 + x / (2 (5 - z)), v likewise
  EXPECT_EQ(view.uv, (std::vector<Vector2>{{0.5, 0.5}, {0.7, 0.5}, {0.5, 0.8}}));
  camera.aspect = 2;  // x_c halves
  EXPECT_EQ(map(triangle(), camera).uv[1], (Vector2{0.6, 0.5}));
}

TEST(MapOptions, TheOverlapResolutionTakesWhatTheCommandLineTakes) {
  MapOptions o;
  o.projector = "plane";
  o.overlapResolution = 8;  // refused (16 to 8192) when the library parsed a command line of its own
  EXPECT_NE(map(triangle(), o).summaryJson.find("\"resolution\":8}"), std::string::npos);
  o.overlapResolution = 16385;
  EXPECT_EQ(messageOf([&] { map(triangle(), o); }), "overlapResolution: expected 0 to 16384, got 16385");
  EXPECT_EQ(messageOf([] { MapOptions::parse("--overlap-resolution -1"); }),
            "--overlap-resolution: expected 0 to 16384, got -1");
  // 0, the default, follows the mesh: a triangle at the 256 pixels of the smallest raster.
  o.overlapResolution = 0;
  EXPECT_NE(map(triangle(), o).summaryJson.find("\"resolution\":256}"), std::string::npos);
}

TEST(Map, TypedParametersAreCheckedWhereTheyCameFrom) {
  Parameters p;
  p.face = Parameters::Face::Keyword;
  p.values = {{"projector", std::string("cylinder"), "projector"}, {"caps", std::int64_t(2), "caps"}};
  EXPECT_THROW(map(triangle(), p), ParameterTypeError);
  EXPECT_EQ(messageOf([&] { map(triangle(), p); }), "caps: expected True or False, got 2");
  p.values[1].value = std::int64_t(0);  // Python's 0 is False
  EXPECT_EQ(map(triangle(), p).uv, map(triangle(), MapOptions::parse("--projector cylinder")).uv);
  p.values.push_back({"thread", std::int64_t(1), "thread"});
  EXPECT_EQ(messageOf([&] { map(triangle(), p); }), "thread: not a parameter here; did you mean threads?");
}

TEST(MapOptions, TheSeamPlacedByDegreesTurnsTheProjector) {
  // The sphere's u at the triangle's corners, turned by 90 degrees: a quarter turn less.
  const MapOptions turned = MapOptions::parse("--fit none --seam none --pole none --seam-place 90");
  ASSERT_TRUE(turned.seamPlace.has_value());
  EXPECT_EQ(*turned.seamPlace, 90.0);
  const Mapping a = map(octahedron(), turned), b = map(octahedron(), MapOptions::parse("--fit none --seam none --pole none"));
  for (std::size_t c = 0; c < a.uv.size(); ++c) {
    if (a.state[c] != CornerState::Ok) continue;
    const double d = b.uv[c][0] - a.uv[c][0];
    EXPECT_NEAR(d - std::round(d), 0.25, 1e-12) << c;
    EXPECT_EQ(a.uv[c][1], b.uv[c][1]);
  }
}

TEST(Options, AFlagGivenAsFalseIsOff) {
  // Python's seamless=0 arrives as --seamless=0, which the command line's parser reads as false;
  // the struct took any value of a flag as "given".
  EXPECT_FALSE(RenderOptions::parse("--seamless=0").seamless);
  EXPECT_FALSE(RenderOptions::parse("--two-sided=false").twoSided);
  EXPECT_TRUE(RenderOptions::parse("--two-sided").twoSided);
  EXPECT_TRUE(RenderOptions::parse("--two-sided=1").twoSided);
  EXPECT_TRUE(TexgenOptions::parse("--no-normalize=0").normalize);
  EXPECT_FALSE(TexgenOptions::parse("--no-normalize").normalize);
}

TEST(Mapping, ADefaultMappingIsRefusedNotAnAbort) {
  // report, render and writeMesh of Mapping{} ended the process with a failed check.
  const Mapping empty;
  for (const std::string& message : {messageOf([&] { report(empty); }), messageOf([&] { render(empty); }),
                                     messageOf([&] { writeMesh("never.obj", empty); })})
    EXPECT_NE(message.find(": the mapping is empty (a default Mapping); make one with map(), texgen() or fileUvs()"),
              std::string::npos)
        << message;
  EXPECT_THROW(report(empty), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists("never.obj"));
}

TEST(MapOptions, ANumberBelowTheSmallestDoubleReadsAsTheCommandLineReadsIt) {
  // std::stod's out_of_range escaped parse() (Python: IndexError) where the command line takes it.
  EXPECT_EQ(MapOptions::parse("--pole-eps 1e-400").poleEps, 0.0);
}

TEST(Map, DensityScalesTheUvsToTexelsPerUnitOfTheTextureSize) {
  // The plane in object coordinates maps the triangle isometrically: sqrt(Auv W H / A3) = W = 1024.
  MapOptions o;
  o.projector = "plane";
  o.fit = "none";
  o.density = 256;
  EXPECT_EQ(o.commandLine(), "--projector plane --fit none --density 256");
  EXPECT_EQ(map(triangle(), o).uv, (std::vector<Vector2>{{0, 0}, {0.5, 0}, {0, 0.75}}));  // a quarter
  o.textureSize = {256, 256};  // already 256 texels per unit of a 256 x 256 texture
  EXPECT_EQ(map(triangle(), o).uv, (std::vector<Vector2>{{0, 0}, {2, 0}, {0, 3}}));
  o.density = -1;  // messages name the struct's fields
  EXPECT_EQ(messageOf([&] { map(triangle(), o); }),
            "density: expected a positive number of texels per object unit, found -1");
  o.density.reset();
  o.textureSize = {0, 5};
  EXPECT_EQ(messageOf([&] { map(triangle(), o); }),
            "textureSize: expected W,H or N (N,N) texels with 1 <= W, H <= 16384");
}

TEST(Map, TheSphereOnAnOctahedronGivesTheAzimuthsAndMarksThePoles) {
  MapOptions o;
  o.fit = "none";
  o.seam = "none";
  o.pole = "none";
  const Mapping m = map(octahedron(), o);
  // docs/conventions.md: u = atan2(y, x) / 2 pi wrapped to [0, 1), v = 1/2 + asin(z) / pi.
  const double expectedU[4] = {0.0, 0.25, 0.5, 0.75};
  for (std::size_t f = 0; f < 8; f += 2) {
    const int i = int(f / 2);
    EXPECT_DOUBLE_EQ(m.uv[3 * f][0], expectedU[i]) << "face " << f;
    EXPECT_DOUBLE_EQ(m.uv[3 * f][1], 0.5);
    EXPECT_EQ(m.state[3 * f + 2], CornerState::Pole);  // the apex (0, 0, 1)
    EXPECT_DOUBLE_EQ(m.uv[3 * f + 2][1], 1.0);
    EXPECT_EQ(m.state[3 * f], CornerState::Ok);
    EXPECT_TRUE(m.faceFlags[f] & kFacePole);
  }
}

TEST(Map, ACutSeamGivesTheCutMesh) {
  // Turned by 45 degrees, the octahedron has a face across the seam (from 315 to 45 degrees)
  // above and below the equator.
  Mesh turned = octahedron();
  for (Vector3& p : turned.positions) p = {(p[0] - p[1]) * std::sqrt(0.5), (p[0] + p[1]) * std::sqrt(0.5), p[2]};
  MapOptions o;
  o.fit = "none";
  o.seam = "cut";
  const Mapping m = map(turned, o);
  EXPECT_GT(m.mesh.triangles.size(), 8u);
  EXPECT_EQ(m.uv.size(), 3 * m.mesh.triangles.size());
  for (const Vector2& uv : m.uv) {
    EXPECT_GE(uv[0], 0.0);
    EXPECT_LE(uv[0], 1.0);
  }
}

TEST(Map, AMappingThatFoldsFailsWithItsReasons) {
  // A plane seen edge-on: every face's UV triangle has zero area.
  Mesh wall = triangle();
  for (Vector3& p : wall.positions) p = {p[0], 0.0, p[1]};
  MapOptions o;
  o.projector = "plane";
  o.fit = "none";
  const Mapping m = map(wall, o);
  EXPECT_EQ(m.verdict.status, "fail");
  ASSERT_FALSE(m.verdict.reasons.empty());
  EXPECT_EQ(m.verdict.reasons.front().severity, "fail");
  EXPECT_FALSE(m.verdict.reasons.front().text.empty());
}

TEST(Texgen, ObjectLinearIsThePlaneEquation) {
  const Mapping m = texgen(triangle(), TexgenOptions::parse("--s object_linear:1,0,0,0.5 --t object_linear:0,2,0,0"));
  EXPECT_EQ(m.source, "texgen");
  EXPECT_EQ(m.uv[0], (Vector2{0.5, 0}));
  EXPECT_EQ(m.uv[1], (Vector2{2.5, 0}));
  EXPECT_EQ(m.uv[2], (Vector2{0.5, 6}));
  const TexgenOptions o = TexgenOptions::parse("--s eye_linear:0,1,0,0 --no-normalize --eye 0,0,5");
  EXPECT_EQ(o.s, "eye_linear:0,1,0,0");
  EXPECT_FALSE(o.normalize);
  EXPECT_EQ(o.eye, (Vector3{0, 0, 5}));
  EXPECT_EQ(o.commandLine(), "--s eye_linear:0,1,0,0 --no-normalize --eye 0,0,5");
}

TEST(FileUvs, AMeshWithoutTexcoordsIsRefused) {
  EXPECT_THROW(fileUvs(triangle()), std::invalid_argument);
  Mesh mesh = triangle();
  mesh.texcoords = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.cornerTexcoords = {{0, 1, -1}};
  const Mapping m = fileUvs(mesh);
  EXPECT_EQ(m.uv[1], (Vector2{1, 0}));
  EXPECT_EQ(m.state[2], CornerState::Invalid);
  EXPECT_EQ(m.invalidReason[2], InvalidReason::NoTexcoord);
}

TEST(CheckMesh, AMeshWithoutFacesIsRefusedAsAReaderRefusesTheFile) {
  // A Mesh{} mapped with verdict pass, reported and rendered; writeMesh wrote a 0-byte OBJ that
  // uvtk map refuses, and compare of one vertex ranked a winner.
  const std::string refusal = "mesh: expected at least one face, found none";
  Mesh oneVertex;
  oneVertex.positions = {{0, 0, 0}};
  for (const Mesh& mesh : {Mesh{}, oneVertex}) {
    EXPECT_EQ(messageOf([&] { checkMesh(mesh); }), refusal);
    EXPECT_EQ(messageOf([&] { map(mesh); }), refusal);
    EXPECT_EQ(messageOf([&] { texgen(mesh, TexgenOptions{}); }), refusal);
    EXPECT_EQ(messageOf([&] { compare(mesh); }), refusal);
    EXPECT_EQ(messageOf([&] { writeMesh("never.glb", mesh); }), refusal);
    EXPECT_THROW(writeMesh("never.obj", mesh), std::invalid_argument);
  }
  EXPECT_FALSE(std::filesystem::exists("never.obj"));
  EXPECT_FALSE(std::filesystem::exists("never.glb"));
}

TEST(CheckMesh, NamesTheFirstProblem) {
  Mesh mesh = triangle();
  mesh.triangles[0][2] = 7;
  EXPECT_EQ(messageOf([&] { checkMesh(mesh); }),
            "mesh: the position index of triangle 0, corner 2: index 7 is outside 0..3 - 1");
  EXPECT_THROW(map(mesh), std::invalid_argument);
  mesh = triangle();
  mesh.positions[1][0] = std::nan("");
  EXPECT_EQ(messageOf([&] { checkMesh(mesh); }), "mesh: position 1 is not finite");
  mesh = triangle();
  mesh.cornerTexcoords = {{0, 0, 0}, {0, 0, 0}};
  EXPECT_THROW(checkMesh(mesh), std::invalid_argument);
  mesh = triangle();
  mesh.triangles.push_back({0, 0, 1});
  EXPECT_EQ(checkMesh(mesh).degenerateFaces, 1u);
}

TEST_F(LibraryTest, AMissingFileIsAnInputErrorNamingIt) {
  const std::string missing = path("missing.obj");
  try {
    readMesh(missing);
    FAIL() << "read a missing file";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(missing + ":", 0), 0u) << error.what();
  }
}

TEST_F(LibraryTest, AnUnwritablePathIsAnOutputError) {
  EXPECT_THROW(writeMesh(path("no/such/folder/x.obj"), triangle()), OutputError);
}

TEST_F(LibraryTest, AMappingWrittenAndReadBackHasTheSameTexcoords) {
  MapOptions o;
  o.projector = "cylinder";
  o.seam = "cut";
  const Mapping m = map(octahedron(), o);
  writeMesh(path("m.obj"), m);
  MeshWarnings warnings;
  const Mesh back = readMesh(path("m.obj"), &warnings);
  ASSERT_EQ(back.triangles.size(), m.mesh.triangles.size());
  ASSERT_EQ(back.cornerTexcoords.size(), back.triangles.size());
  for (std::size_t c = 0; c < m.uv.size(); ++c) {
    const Vector3& t = back.texcoords[std::size_t(back.cornerTexcoords[c / 3][c % 3])];
    EXPECT_EQ(t[0], m.uv[c][0]) << c;
    EXPECT_EQ(t[1], m.uv[c][1]) << c;
  }
  EXPECT_EQ(back.positions, m.mesh.positions);
  const Mapping again = fileUvs(back);
  EXPECT_EQ(again.uv, m.uv);
  EXPECT_EQ(warnings.degenerateFaces, 0u);
}

// What Python's signatures are made of: each field's option as `uvtk map --help` shows it.
TEST(MapOptions, DescribeGivesEveryFieldsOptionAsTheHelpShowsIt) {
  const std::vector<OptionDescription> options = MapOptions::describe();
  const auto named = [&](const std::string& name) {
    for (const OptionDescription& o : options)
      if (o.name == name) return o;
    ADD_FAILURE() << name;
    return OptionDescription{};
  };
  EXPECT_EQ(options.front().name, "projector");
  const OptionDescription capAngle = named("cap-angle");
  EXPECT_EQ(capAngle.kind, "float");
  EXPECT_EQ(capAngle.defaultText, "45");
  EXPECT_EQ(capAngle.help, "cylinder: degrees between a cap face's normal and the axis");
  EXPECT_FALSE(capAngle.optional);
  const OptionDescription seam = named("seam");
  EXPECT_EQ(seam.choices, (std::vector<std::string>{"none", "shift", "cut"}));
  EXPECT_EQ(seam.defaultText, "shift");
  EXPECT_EQ(named("caps").kind, "bool");
  EXPECT_EQ(named("center").kind, "float[3]");
  EXPECT_TRUE(named("center").optional);
  EXPECT_EQ(named("seam-place").kind, "float|auto");
  EXPECT_EQ(named("texture-size").kind, "int|int[2]");
  EXPECT_EQ(named("texture-size").defaultText, "1024,1024");
  EXPECT_EQ(named("fail-on").kind, "str[]");
  EXPECT_EQ(named("threads").kind, "int");
  EXPECT_NE(named("threads").help.find("Threads"), std::string::npos);
  for (const OptionDescription& o : options) EXPECT_FALSE(o.help.empty()) << o.name;
  const std::vector<OptionDescription> texgen = TexgenOptions::describe();
  ASSERT_FALSE(texgen.empty());
  EXPECT_EQ(texgen.front().name, "s");
  bool noNormalize = false;
  for (const OptionDescription& o : texgen) noNormalize = noNormalize || (o.name == "no-normalize" && o.kind == "bool");
  EXPECT_TRUE(noNormalize);
}

TEST_F(LibraryTest, ARestoredMappingWritesTheSameBytesAndRefusesReports) {
  MapOptions o;
  o.projector = "cylinder";
  o.seam = "cut";
  const Mapping m = map(octahedron(), o);
  Mapping data = m;
  data.detail = nullptr;  // what a pickle carries: the public fields
  const Mapping restored = restoreMapping(data);
  EXPECT_EQ(restored.uv, m.uv);
  EXPECT_EQ(restored.verdict.status, m.verdict.status);
  writeMesh(path("a.obj"), m);
  writeMesh(path("b.obj"), restored);
  const auto bytes = [](const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(bytes(path("a.obj")), bytes(path("b.obj")));
  EXPECT_THROW(report(restored), std::invalid_argument);
  EXPECT_THROW(render(restored), std::invalid_argument);
  data.uv.pop_back();
  EXPECT_THROW(restoreMapping(data), std::invalid_argument);
}

TEST_F(LibraryTest, AHeaderIsTheCommentLineAtTheTopOfAnObj) {
  WriteOptions options;
  options.header = "uvtk map in.obj";
  writeMesh(path("h.obj"), map(octahedron()), options);
  std::ifstream in(path("h.obj"));
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "# uvtk map in.obj");
}

// OBJ -> glTF -> OBJ: the library writes what it read, by extension; glTF keeps each UV to float
// precision (it stores float32), PLY keeps every bit, and each split vertex is one distinct UV.
TEST_F(LibraryTest, AMappingThroughGltfAndPlyKeepsEveryCornersUv) {
  MapOptions o;
  o.projector = "sphere";
  const Mapping m = map(octahedron(), o);
  writeMesh(path("m.glb"), m);
  writeMesh(path("m.ply"), m);
  const Mesh glb = readMesh(path("m.glb"));
  writeMesh(path("back.obj"), glb);  // the glTF's own UVs, through the library
  const Mesh back = readMesh(path("back.obj"));
  const Mesh ply = readMesh(path("m.ply"));
  ASSERT_EQ(back.triangles.size(), m.mesh.triangles.size());
  ASSERT_EQ(ply.triangles.size(), m.mesh.triangles.size());
  for (std::size_t c = 0; c < m.uv.size(); ++c) {
    const Vector3& t = back.texcoords[std::size_t(back.cornerTexcoords[c / 3][c % 3])];
    // Written as float(1 - v), read as 1 - that: v within one float rounding of 1 - v's.
    EXPECT_EQ(t[0], double(float(m.uv[c][0]))) << c;
    EXPECT_EQ(t[1], 1.0 - double(float(1.0 - m.uv[c][1]))) << c;
    const Vector3& exact = ply.texcoords[std::size_t(ply.cornerTexcoords[c / 3][c % 3])];
    EXPECT_EQ(exact[0], m.uv[c][0]) << c;
    EXPECT_EQ(exact[1], m.uv[c][1]) << c;
  }
  // The octahedron's 6 vertices are split at the seam and at the poles' fans: one vertex per
  // distinct (vertex, uv), the same count in both files.
  std::set<std::tuple<int, double, double>> distinct;
  for (std::size_t c = 0; c < m.uv.size(); ++c)
    distinct.insert({m.mesh.triangles[c / 3][c % 3], m.uv[c][0], m.uv[c][1]});
  EXPECT_EQ(ply.positions.size(), distinct.size());
  EXPECT_EQ(glb.positions.size(), distinct.size());
  EXPECT_GT(distinct.size(), 6u);
}

TEST_F(LibraryTest, TheReportIsTheJsonItWritesAndCarriesTheVerdict) {
  MapOptions o;
  o.projector = "cylinder";
  const Mapping m = map(octahedron(), o);
  ReportOptions options;
  const std::string inMemory = report(m, options);
  EXPECT_NE(inMemory.find("\"verdict\": \"" + m.verdict.status + "\""), std::string::npos);
  options.json = path("r.json");
  const std::string written = report(m, options);
  std::ifstream file(options.json);
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, written + "\n");
  EXPECT_EQ(written, inMemory);
  EXPECT_THROW(report(m, ReportOptions::parse("--views checker,nonsense --html x.html")), std::invalid_argument);
  // The page of a mesh in memory (nlohmann's out_of_range "key 'path' not found" escaped here).
  options.json.clear();
  options.html = path("r.html");
  options.size = "64x64";
  report(m, options);
  std::ifstream page(options.html);
  const std::string html((std::istreambuf_iterator<char>(page)), std::istreambuf_iterator<char>());
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("a mesh in memory"), std::string::npos);
}

TEST(Render, AViewIsTheSizeAskedForAndDrawsTheMesh) {
  const Mapping m = map(octahedron());
  RenderOptions options = RenderOptions::parse("--view checker --size 64x48");
  EXPECT_EQ(options.view, "checker");
  EXPECT_EQ(options.size, "64x48");
  const Image image = render(m, options);
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 48);
  ASSERT_GE(image.channels, 3);
  const std::vector<std::uint8_t> bytes = image.bytes();
  ASSERT_EQ(bytes.size(), image.pixels.size());
  // The octahedron covers the middle of the frame and leaves its corner to the background.
  const std::size_t centre = (std::size_t(24) * 64 + 32) * std::size_t(image.channels);
  const std::size_t corner = 0;
  EXPECT_NE(bytes[centre] + bytes[centre + 1] + bytes[centre + 2], bytes[corner] + bytes[corner + 1] + bytes[corner + 2]);
  EXPECT_THROW(RenderOptions::parse("--view sideways"), std::invalid_argument);

  // A GPU's quad derivatives with textureGrad's fix draw the analytic picture; without it they differ.
  const RenderOptions exact = RenderOptions::parse("--size 64x48 --filter linear_mipmap_linear --view-dir 1,0.3,0.2");
  RenderOptions gpu = RenderOptions::parse("--size 64x48 --filter linear_mipmap_linear --view-dir 1,0.3,0.2 --derivatives quad-fine");
  EXPECT_EQ(gpu.derivatives, "quad-fine");
  EXPECT_EQ(gpu.commandLine(), exact.commandLine() + " --derivatives quad-fine");
  const Image analytic = render(m, exact);
  EXPECT_NE(render(m, gpu).pixels, analytic.pixels);
  gpu.seamFix = "grad";
  EXPECT_EQ(render(m, gpu).pixels, analytic.pixels);
  EXPECT_THROW(RenderOptions::parse("--derivatives quad"), std::invalid_argument);
}

TEST(Render, CarriesTheCameraAndTextureOptionsAndRefusesWhatItCannot) {
  const Mapping m = map(octahedron());
  const std::string line =
      "--size 64x48 --eye 0.5,2,3 --center 0,0.1,0 --fovy 30 --near 0.5 --far 20 --wrap mirrored_repeat "
      "--env blend --env-color 1,0.5,0.25,1 --two-sided";
  const RenderOptions o = RenderOptions::parse(line);
  EXPECT_EQ(o.eye, (std::optional<Vector3>{Vector3{0.5, 2, 3}}));
  EXPECT_EQ(o.center, (Vector3{0, 0.1, 0}));
  EXPECT_EQ(o.fovy, 30.0);
  EXPECT_EQ(o.zNear, 0.5);
  EXPECT_EQ(o.zFar, 20.0);
  EXPECT_EQ(o.wrap, "mirrored_repeat");
  EXPECT_EQ(o.env, "blend");
  EXPECT_EQ(o.envColor, (std::array<double, 4>{1, 0.5, 0.25, 1}));
  EXPECT_TRUE(o.twoSided);
  EXPECT_EQ(o.commandLine(), line);
  // Each reaches the picture: another eye, another environment, another lighting of the back faces.
  const Image picture = render(m, o);
  RenderOptions other = o;
  other.eye = Vector3{-2, 1, 1};
  EXPECT_NE(render(m, other).pixels, picture.pixels);
  other = o;
  other.env = "replace";
  EXPECT_NE(render(m, other).pixels, picture.pixels);
  other = o;
  other.cull = "front";  // only back faces are drawn: one-sided leaves them in the ambient term
  RenderOptions oneSided = other;
  oneSided.twoSided = false;
  EXPECT_NE(render(m, other).pixels, render(m, oneSided).pixels);
  // What `uvtk render` takes but the picture in memory has no place for is refused, not dropped.
  EXPECT_THROW(RenderOptions::parse("--aov uv"), std::invalid_argument);
  EXPECT_NE(messageOf([] { RenderOptions::parse("--size 64x48 --aov-output a.exr"); }).find("--aov-output"),
            std::string::npos);
}

TEST(ImageBytes, RoundAsAPngStores) {
  Image image;
  image.width = 5, image.height = 1, image.channels = 1;
  image.pixels = {-1.0f, 0.5f, 1.0f / 255.0f * 0.5f, 2.0f, std::nanf("")};
  EXPECT_EQ(image.bytes(), (std::vector<std::uint8_t>{0, 128, 1, 255, 0}));
}

TEST(Compare, RanksEveryProjectorAndNamesTheBest) {
  CompareOptions options;
  options.baselines = false;
  const Comparison c = compare(octahedron(), options);
  EXPECT_FALSE(c.best.empty());
  EXPECT_NE(c.table.find(c.best), std::string::npos);
  EXPECT_NE(c.json.find("\"ranking\""), std::string::npos);
  EXPECT_EQ(CompareOptions::parse("--by angle --no-baselines").commandLine(), "--by angle --no-baselines");
}

// The README's "Library" program is examples/map_verdict/map_verdict.cpp, which the test command
// builds against the installed package.
TEST(Readme, TheLibraryProgramIsTheExampleBuiltAgainstTheInstall) {
  const auto read = [](const std::string& file) {
    std::ifstream in(std::string(UVTK_SOURCE_DIR) + "/" + file);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  const std::string readme = read("README.md"), program = read("examples/map_verdict/map_verdict.cpp");
  ASSERT_FALSE(program.empty());
  const std::size_t section = readme.find("\n## Library\n");
  ASSERT_NE(section, std::string::npos);
  const std::size_t start = readme.find("```cpp\n", section);
  ASSERT_NE(start, std::string::npos);
  EXPECT_EQ(readme.substr(start + 7, program.size()), program);
  EXPECT_EQ(readme.substr(start + 7 + program.size(), 4), "```\n");
}

TEST(Version, IsTheProjects) { EXPECT_EQ(version(), UVTK_VERSION); }

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::api
