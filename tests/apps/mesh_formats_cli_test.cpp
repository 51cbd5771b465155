// PLY, STL and glTF through the program as a user runs it: a scanned PLY mapped to a GLB whose
// TEXCOORD_0 is the OBJ's (u, 1 - v) corner by corner (read by a GLB parser of this test's own,
// not the toolkit's reader), valid by the Khronos glTF-Validator; a binary STL mapped to PLY that
// `uvtk check` passes against the same mapping; broken files of each format refused with one line
// and nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test.h"
#include "core/mesh.h"
#include "io/mesh_reader.h"
#include "io/mesh_writer.h"
#include "meshes/generators.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;
using json = nlohmann::json;

class MeshFormatsCli : public CliTest {
 protected:
  // Writes a generated mesh in the format its name says.
  std::string generated(const std::string& name, const Mesh& mesh) const {
    io::writeMesh(path(name), mesh, nullptr);
    return path(name);
  }

  // Every file of the scratch folder but stderr.txt.
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_))
      if (entry.path().filename() != "stderr.txt") names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
};

// The per-corner TEXCOORD_0 of a GLB's one triangle primitive, read with nothing but the GLB
// layout (glTF 2.0 §4.4) and the accessor rules: float VEC2 texture coordinates, unsigned indices.
std::vector<std::array<float, 2>> glbCornerTexcoords(const std::string& bytes) {
  const auto u32 = [&](std::size_t at) {
    std::uint32_t v;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
  };
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  EXPECT_EQ(u32(4), 2u);
  EXPECT_EQ(u32(8), bytes.size());
  const std::uint32_t jsonLength = u32(12);
  EXPECT_EQ(u32(16), 0x4E4F534Au);  // "JSON"
  const json gltf = json::parse(bytes.substr(20, jsonLength));
  const std::size_t bin = 20 + jsonLength + 8;
  EXPECT_EQ(u32(20 + jsonLength + 4), 0x004E4942u);  // "BIN\0"
  const json& primitive = gltf["meshes"][0]["primitives"][0];
  const auto bytesOf = [&](int accessorIndex, std::size_t& count) {
    const json& accessor = gltf["accessors"][accessorIndex];
    const json& view = gltf["bufferViews"][accessor["bufferView"].get<int>()];
    count = accessor["count"];
    return bin + view.value("byteOffset", std::size_t{0}) + accessor.value("byteOffset", std::size_t{0});
  };
  std::size_t uvCount = 0, indexCount = 0;
  const json& uvAccessor = gltf["accessors"][primitive["attributes"]["TEXCOORD_0"].get<int>()];
  EXPECT_EQ(uvAccessor["componentType"], 5126);
  EXPECT_EQ(uvAccessor["type"], "VEC2");
  const std::size_t uvAt = bytesOf(primitive["attributes"]["TEXCOORD_0"], uvCount);
  const int indexType = gltf["accessors"][primitive["indices"].get<int>()]["componentType"];
  const std::size_t indexAt = bytesOf(primitive["indices"], indexCount);
  std::vector<std::array<float, 2>> corners;
  for (std::size_t i = 0; i < indexCount; ++i) {
    std::uint32_t index = 0;
    if (indexType == 5123) {
      std::uint16_t small;
      std::memcpy(&small, bytes.data() + indexAt + 2 * i, 2);
      index = small;
    } else {
      EXPECT_EQ(indexType, 5125);
      std::memcpy(&index, bytes.data() + indexAt + 4 * i, 4);
    }
    EXPECT_LT(index, uvCount);
    std::array<float, 2> uv;
    std::memcpy(uv.data(), bytes.data() + uvAt + 8 * std::size_t(index), 8);
    corners.push_back(uv);
  }
  return corners;
}

// The Khronos glTF-Validator (npm gltf-validator, installed by scripts/test.sh) on `file`: its
// summary line, or "" with `skipped` set when it is not installed.
std::string validate(const std::string& file, bool& skipped, int& status) {
  const std::string folder = UVTK_GLTF_VALIDATOR_DIR;
  skipped = !fs::is_directory(folder + "/node_modules/gltf-validator") || std::system("node --version > /dev/null 2>&1");
  if (skipped) return "";
  const std::string out = file + ".validator.txt";
  const int raw = std::system(("node " + folder + "/validate.mjs " + file + " > " + out + " 2>&1").c_str());
  status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream in(out);
  std::stringstream text;
  text << in.rdbuf();
  fs::remove(out);
  return text.str();
}

TEST_F(MeshFormatsCli, AScannedPlyMapsToAValidGlbWhoseTexcoordsAreTheObjsWithVFlipped) {
  const std::string scan = generated("scan.ply", meshes::scannedPatch(4));
  ASSERT_EQ(uvtk("map " + scan + " --projector plane --fit pca -q -o " + path("scan.glb")).status, 0);
  ASSERT_EQ(uvtk("map " + scan + " --projector plane --fit pca -q -o " + path("scan.obj")).status, 0);
  const io::ReadMeshResult obj = io::readMesh(path("scan.obj"));
  const std::vector<std::array<float, 2>> glb = glbCornerTexcoords(readText(path("scan.glb")));
  ASSERT_EQ(glb.size(), 3 * obj.mesh.faceCount());
  for (std::size_t c = 0; c < glb.size(); ++c) {
    const Vec3& uv = obj.mesh.texcoords[std::size_t(obj.mesh.cornerTexcoords[c / 3][c % 3])];
    ASSERT_EQ(glb[c][0], static_cast<float>(uv.x())) << "corner " << c;
    ASSERT_EQ(glb[c][1], static_cast<float>(1.0 - uv.y())) << "corner " << c;
  }
  bool skipped = false;
  int status = 0;
  const std::string summary = validate(path("scan.glb"), skipped, status);
  if (skipped) GTEST_SKIP() << "glTF-Validator not installed (scripts/test.sh installs it with npm): not run";
  EXPECT_EQ(status, 0) << summary;
  EXPECT_NE(summary.find("errors 0 "), std::string::npos) << summary;
}

// A sphere's seam and poles split vertices; the .gltf and its .bin are written together, and the
// validator accepts them; the float32 note is printed.
TEST_F(MeshFormatsCli, ASphereMapsToAGltfAndItsBufferThatTheValidatorAccepts) {
  const std::string sphere = generated("sphere.obj", meshes::latLongSphere(24, 12));
  const CliRun r = uvtk("map " + sphere + " --projector sphere -o " + path("sphere.gltf"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("glTF stores positions, normals and UVs as float32"), std::string::npos) << r.err;
  EXPECT_EQ(files(), (std::vector<std::string>{"sphere.bin", "sphere.gltf", "sphere.obj"}));
  const json gltf = json::parse(readText(path("sphere.gltf")));
  EXPECT_EQ(gltf["buffers"][0]["uri"], "sphere.bin");
  EXPECT_EQ(gltf["buffers"][0]["byteLength"].get<std::size_t>(), fs::file_size(path("sphere.bin")));
  EXPECT_EQ(gltf["asset"]["generator"].get<std::string>().rfind("uvtk ", 0), 0u);
  const io::ReadMeshResult back = io::readMesh(path("sphere.gltf"));
  EXPECT_EQ(back.mesh.faceCount(), meshes::latLongSphere(24, 12).faceCount());
  // The seam's column and the poles' fans are split: more vertices than the sphere has.
  EXPECT_GT(back.mesh.vertexCount(), meshes::latLongSphere(24, 12).vertexCount());
  bool skipped = false;
  int status = 0;
  const std::string summary = validate(path("sphere.gltf"), skipped, status);
  if (skipped) GTEST_SKIP() << "glTF-Validator not installed (scripts/test.sh installs it with npm): not run";
  EXPECT_EQ(status, 0) << summary;
}

TEST_F(MeshFormatsCli, ABinaryStlMapsToAPlyThatCheckPassesAgainstTheSameMapping) {
  const std::string stl = generated("bone.stl", meshes::bone(60, 16));
  const std::string mapping = "--projector cylinder --fit pca --omap normal";
  const CliRun map = uvtk("map " + stl + " " + mapping + " -o " + path("bone.ply"));
  ASSERT_EQ(map.status, 0) << map.err;
  const io::ReadMeshResult ply = io::readMesh(path("bone.ply"));
  EXPECT_TRUE(ply.mesh.hasTexcoords());
  EXPECT_TRUE(ply.mesh.hasNormals());  // the rays' normals, so that a mapping of the PLY casts the same rays
  const CliRun check = uvtk("check " + path("bone.ply") + " " + mapping + " --tolerance 1e-12");
  EXPECT_EQ(check.status, 0) << check.err;
  // An ASCII PLY holds the same numbers.
  ASSERT_EQ(uvtk("map " + stl + " " + mapping + " --ascii -q -o " + path("bone_ascii.ply")).status, 0);
  const io::ReadMeshResult ascii = io::readMesh(path("bone_ascii.ply"));
  EXPECT_EQ(readText(path("bone_ascii.ply")).substr(0, 27), "ply\nformat ascii 1.0\ncommen");
  EXPECT_EQ(ascii.mesh.texcoords, ply.mesh.texcoords);
  EXPECT_EQ(ascii.mesh.positions, ply.mesh.positions);
}

TEST_F(MeshFormatsCli, OutputsAFormatCannotHoldAreUsageErrorsBeforeAnyWork) {
  const std::string sphere = generated("sphere.obj", meshes::latLongSphere(8, 4));
  const CliRun stl = uvtk("map " + sphere + " -o " + path("out.stl"));
  EXPECT_EQ(stl.status, 2);
  EXPECT_NE(stl.err.find("-o: expected a .obj, .ply, .gltf or .glb extension, found '.stl'"), std::string::npos)
      << stl.err;
  EXPECT_EQ(uvtk("map " + sphere + " --ascii -o " + path("out.glb")).status, 2);
  EXPECT_EQ(uvtk("map " + sphere + " --write-w -o " + path("out.ply")).status, 2);
  EXPECT_EQ(files(), (std::vector<std::string>{"sphere.obj"}));
}

// The classics of each new format: exit 3, one line naming the file and the place, nothing written.
TEST_F(MeshFormatsCli, BrokenFilesOfEachFormatAreRefusedWithOneLineAndNothingWritten) {
  generated("good.ply", meshes::icosphere(1));
  generated("good.stl", meshes::icosphere(1));
  generated("good.glb", meshes::icosphere(1));
  const std::string ply = readText(path("good.ply")), stl = readText(path("good.stl")), glb = readText(path("good.glb"));
  const std::vector<std::pair<std::string, std::string>> broken = {
      {"truncated.ply", ply.substr(0, ply.size() - 7)},
      {"counts.ply", std::string(ply).replace(ply.find("element face 80"), 15, "element face 99")},
      {"truncated.stl", stl.substr(0, stl.size() - 10)},
      {"truncated.glb", glb.substr(0, glb.size() - 12)},
      {"notjson.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": ["},
      {"missing_buffer.gltf",
       R"({"asset":{"version":"2.0"},"buffers":[{"uri":"nowhere.bin","byteLength":36}],)"
       R"("bufferViews":[{"buffer":0,"byteLength":36}],)"
       R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],)"
       R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]})"},
  };
  ASSERT_NE(ply.find("element face 80"), std::string::npos);
  for (const auto& [name, bytes] : broken) {
    writeText(name, bytes);
    const CliRun r = uvtk("map " + path(name) + " -o " + path("out.glb") + " --json " + path("out.json"));
    EXPECT_EQ(r.status, 3) << name << ": " << r.err;
    EXPECT_EQ(r.err.find(path(name) + ":"), 0u) << name << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << name << ": " << r.err;
    EXPECT_FALSE(fs::exists(path("out.glb"))) << name;
    EXPECT_FALSE(fs::exists(path("out.json"))) << name;
  }
}

// Every command that reads a mesh reads the new formats.
TEST_F(MeshFormatsCli, EveryCommandThatReadsAMeshReadsPlyStlAndGlb) {
  const Mesh knot = meshes::torusKnot(2, 3, 60, 8);
  for (const std::string name : {"knot.ply", "knot.stl", "knot.glb"}) {
    const std::string mesh = generated(name, knot);
    EXPECT_EQ(uvtk("texgen " + mesh + " --mode sphere_map -q -o " + path(name + ".obj")).status, 0) << name;
    EXPECT_EQ(uvtk("report " + mesh + " --projector sphere -q --json " + path(name + ".report.json")).status, 0)
        << name;
    EXPECT_EQ(uvtk("compare " + mesh + " -q --json " + path(name + ".compare.json")).status, 0) << name;
    EXPECT_EQ(uvtk("render " + mesh + " --projector sphere --size 64x64 -q -o " + path(name + ".png")).status, 0)
        << name;
    EXPECT_EQ(uvtk("eval --projector sphere --mesh " + mesh + " --fit bbox --point 0,0,1 -q").status, 0) << name;
    const json report = json::parse(readText(path(name + ".report.json")));
    EXPECT_EQ(report["input"]["faces"], knot.faceCount()) << name;
  }
}

// PLY and glTF split vertices where their corners' UVs differ, so a seam's two sides share no
// vertex in the file: `report` of each written file finds the seams `report` finds in the OBJ
// (edge counts exactly; lengths to the float positions of glTF), on a sphere (a wrap seam, and its
// fanned poles, cuts in a file) and a knot mapped by the cube (cuts between the cube's faces).
TEST_F(MeshFormatsCli, SeamsSurviveARoundTripThroughEachFormat) {
  generated("sphere.obj", meshes::latLongSphere(32, 16));
  generated("knot.obj", meshes::torusKnot(2, 3, 120, 12));
  for (const auto& [input, projector] : std::vector<std::pair<std::string, std::string>>{
           {"sphere.obj", "sphere"}, {"knot.obj", "cube"}}) {
    // The seams map found; the sphere's pole fans are listed in every file, so they are not cut edges there either.
    const std::string mapJson = path(input + ".map.json");
    ASSERT_EQ(uvtk("map " + path(input) + " --projector " + projector + " -q -o " + path("map.obj") + " --json " + mapJson).status, 0);
    const json expected = json::parse(readText(mapJson))["judgement"]["seams"];
    EXPECT_GT(expected["wrap_edges"].get<int>() + expected["cut_edges"].get<int>(), 0) << input;
    for (const std::string format : {"obj", "ply", "gltf", "glb"}) {
      const std::string mapped = path(input + ".mapped." + format), report = path(input + "." + format + ".json");
      ASSERT_EQ(uvtk("map " + path(input) + " --projector " + projector + " -q -o " + mapped).status, 0) << format;
      ASSERT_EQ(uvtk("report " + mapped + " -q --json " + report).status, 0) << format;
      const json seams = json::parse(readText(report))["seams"];
      EXPECT_EQ(seams["wrap_edges"], expected["wrap_edges"]) << input << " " << format;
      EXPECT_EQ(seams["cut_edges"], expected["cut_edges"]) << input << " " << format;
      const double tolerance = format == "obj" || format == "ply" ? 0.0 : 1e-6 * expected["length"].get<double>();
      EXPECT_NEAR(seams["length"].get<double>(), expected["length"].get<double>(), tolerance) << input << " " << format;
    }
  }
}

// A map whose normal rays miss the cylinder on the torus's inner side: every format lists the faces
// with corners without a valid UV, so `report` of each file judges what `map` judged, not the (0, 0)
// those corners hold (which read as valid gave other stretch, overlap and zero-area-UV reasons).
TEST_F(MeshFormatsCli, ReportOfAWrittenMapJudgesItsInvalidCornersAsTheMapDid) {
  generated("torus.obj", meshes::torus(48, 24, 1.0, 0.3));
  const std::string input = path("torus.obj");
  ASSERT_EQ(uvtk("map " + input + " --projector cylinder --omap normal -q -o " + path("m.obj") + " --json " +
                 path("m.json")).status, 0);
  const json mapped = json::parse(readText(path("m.json")));
  const int invalidFaces = mapped["invalid_faces"].get<int>();
  ASSERT_GT(invalidFaces, 0);
  for (const std::string format : {"obj", "ply", "glb", "gltf"}) {
    const std::string file = path("t." + format), report = path("t." + format + ".json");
    ASSERT_EQ(uvtk("map " + input + " --projector cylinder --omap normal -q -o " + file).status, 0) << format;
    const CliRun result = uvtk("report " + file + " --json " + report);
    ASSERT_EQ(result.status, 0) << format;
    EXPECT_NE(result.err.find(std::to_string(invalidFaces) + " faces listed by uvtk as having corners without a valid UV"),
              std::string::npos) << result.err;
    const json judged = json::parse(readText(report));
    EXPECT_EQ(judged["input"]["listed_invalid_uv_faces"], invalidFaces) << format;
    EXPECT_EQ(judged["status_counts"]["invalid"], invalidFaces) << format;
    // And `check` takes the listed faces as without a value, not as a file missing its vt.
    const CliRun check = uvtk("check " + file + " --projector cylinder --omap normal --tolerance 1e-6");
    EXPECT_EQ(check.status, 0) << format << ": " << check.err;
    EXPECT_EQ(judged["invalid_corners"]["no_texcoord"].get<double>(), mapped["reasons"][0]["value"].get<double>()) << format;
    // The same reasons: the map's out_of_range_corners is the file's invalid_corners (the file keeps no why).
    ASSERT_EQ(judged["reasons"].size(), mapped["reasons"].size()) << format;
    for (std::size_t i = 0; i < mapped["reasons"].size(); ++i) {
      const json &a = mapped["reasons"][i], &b = judged["reasons"][i];
      EXPECT_EQ(b["code"], i == 0 ? json("invalid_corners") : a["code"]) << format << " " << i;
      EXPECT_EQ(b["faces"], a["faces"]) << format << " " << i;
      const double tolerance = format == "obj" || format == "ply" ? 0.0 : 1e-6 * std::abs(a["value"].get<double>());
      EXPECT_NEAR(b["value"].get<double>(), a["value"].get<double>(), tolerance) << format << " " << i;
    }
  }
}


// Pole faces and the faces a planar or triplanar projection sees from behind (mirrored by design)
// are listed in every file as invalid faces are, so `report` of the file gives map's verdict: the
// same statuses, reasons and values (read back as valid, such faces counted as flipped).
TEST_F(MeshFormatsCli, ReportOfAWrittenMapGivesTheMapsVerdictWithItsPoleAndTurnedAwayFaces) {
  generated("sphere.obj", meshes::latLongSphere(24, 12));
  generated("knot.obj", meshes::torusKnot(2, 3, 96, 10));
  for (const auto& [input, projector] : std::vector<std::pair<std::string, std::string>>{
           {"sphere.obj", "sphere"}, {"sphere.obj", "plane"}, {"knot.obj", "triplanar"}, {"knot.obj", "plane --fit obb"}}) {
    const std::string mapJson = path("map.json");
    ASSERT_EQ(uvtk("map " + path(input) + " --projector " + projector + " -q -o " + path("map.obj") + " --json " + mapJson).status, 0);
    const json mapped = json::parse(readText(mapJson))["judgement"];
    const json& counts = mapped["status_counts"];
    EXPECT_GT(counts["pole_face"].get<int>() + counts["backfacing"].get<int>(), 0) << projector;
    for (const std::string format : {"obj", "ply", "glb"}) {
      const std::string file = path("m." + format), report = path("m." + format + ".json");
      ASSERT_EQ(uvtk("map " + path(input) + " --projector " + projector + " -q -o " + file).status, 0) << format;
      ASSERT_EQ(uvtk("report " + file + " -q --json " + report).status, 0) << format;
      const json judged = json::parse(readText(report));
      const std::string what = input + " " + projector + " " + format;
      EXPECT_EQ(judged["status_counts"], counts) << what;
      EXPECT_EQ(judged["verdict"], mapped["verdict"]) << what;
      ASSERT_EQ(judged["reasons"].size(), mapped["reasons"].size()) << what;
      for (std::size_t i = 0; i < mapped["reasons"].size(); ++i) {
        const json &a = mapped["reasons"][i], &b = judged["reasons"][i];
        EXPECT_EQ(b["code"], a["code"]) << what << " " << i;
        if (format == "glb") continue;  // float32 moves a few faces across a percentile's threshold
        EXPECT_EQ(b["faces"], a["faces"]) << what << " " << i;
        EXPECT_EQ(b["value"], a["value"]) << what << " " << i;
      }
    }
  }
}

// A scan far from the origin (at 1e6, -2e6, 3e5, 2 units across) mapped to a GLB: glTF's float32
// would round its coordinates to 1/8 of a unit, a twentieth of the mesh, so the writer stores them
// relative to the node's translation. `report` of the far GLB judges it as it judges the same scan
// written at the origin (every face's status, every reason's faces and value to float32's
// precision), and the validator accepts the file.
TEST_F(MeshFormatsCli, AScanFarFromTheOriginMapsToAGlbThatReportsAsAtTheOrigin) {
  const auto reported = [&](const std::string& name, const Vec3& offset) {
    Mesh scan = meshes::scannedPatch(4);
    for (Vec3& p : scan.positions) p += offset;
    const std::string input = generated(name + ".ply", scan);
    const CliRun map = uvtk("map " + input + " --projector cylinder -q -o " + path(name + ".glb"));
    EXPECT_EQ(map.status, 0) << map.err;
    const CliRun report = uvtk("report " + path(name + ".glb") + " -q --json " + path(name + ".json"));
    EXPECT_EQ(report.status, 0) << report.err;
    return json::parse(readText(path(name + ".json")));
  };
  const json near = reported("near", Vec3::Zero()), far = reported("far", Vec3(1e6, -2e6, 3e5));
  EXPECT_EQ(far["status_counts"], near["status_counts"]);
  ASSERT_EQ(far["reasons"].size(), near["reasons"].size());
  for (std::size_t i = 0; i < near["reasons"].size(); ++i) {
    EXPECT_EQ(far["reasons"][i]["code"], near["reasons"][i]["code"]) << i;
    EXPECT_EQ(far["reasons"][i]["faces"], near["reasons"][i]["faces"]) << i;
    EXPECT_NEAR(far["reasons"][i]["value"].get<double>(), near["reasons"][i]["value"].get<double>(),
                1e-5 * std::abs(near["reasons"][i]["value"].get<double>())) << i;
  }
  EXPECT_NEAR(far["stretch_l2"].get<double>(), near["stretch_l2"].get<double>(), 1e-5);
  bool skipped = false;
  int status = 0;
  const std::string summary = validate(path("far.glb"), skipped, status);
  if (skipped) GTEST_SKIP() << "glTF-Validator not installed (scripts/test.sh installs it with npm): not run";
  EXPECT_EQ(status, 0) << summary;
  EXPECT_NE(summary.find("errors 0 "), std::string::npos) << summary;
  EXPECT_NE(summary.find("warnings 0 "), std::string::npos) << summary;
}


// A two-plane map writes UVs in object units: a bone at x = 1e15 has u near 1e15, where float32's
// steps are 2^26 wide. The GLB is written, `map` warns with the count of faces whose UVs float32
// collapsed, and the JSON has the same count: an independent recount over the GLB read back against
// the OBJ of the same mapping (doubles) finds exactly those faces.
TEST_F(MeshFormatsCli, AMapWarnsOfTheFacesWhoseUvsGltfsFloat32Collapses) {
  Mesh bone = meshes::bone(40, 12);
  for (Vec3& p : bone.positions) p.x() += 1e15;
  const std::string input = generated("far_bone.obj", bone);
  const CliRun glb = uvtk("map " + input + " --projector two-plane -q -o " + path("b.glb") + " --json " + path("b.json"));
  ASSERT_EQ(glb.status, 0) << glb.err;
  ASSERT_EQ(uvtk("map " + input + " --projector two-plane -q -o " + path("b.obj")).status, 0);
  const std::size_t counted = json::parse(readText(path("b.json")))["output_collapsed_uv_faces"].get<std::size_t>();
  const Mesh exact = io::readMesh(path("b.obj")).mesh, stored = io::readMesh(path("b.glb")).mesh;
  ASSERT_EQ(exact.faceCount(), stored.faceCount());
  const auto zeroArea = [](const Mesh& m, std::size_t f) {
    const auto t = [&](int k) { return m.texcoords[std::size_t(m.cornerTexcoords[f][k])]; };
    const Vec3 a = t(0), b = t(1), c = t(2);
    return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x()) == 0.0;
  };
  std::size_t recounted = 0;
  for (std::size_t f = 0; f < exact.faceCount(); ++f) recounted += !zeroArea(exact, f) && zeroArea(stored, f) ? 1 : 0;
  EXPECT_GT(recounted, exact.faceCount() / 4);
  EXPECT_EQ(counted, recounted);
  EXPECT_NE(glb.err.find("b.glb: warning: " + std::to_string(counted) +
                         " faces' UVs have zero area as glTF holds them (float32 u, 1 - v)"),
            std::string::npos) << glb.err;
  // Brought near [0, 1], nothing collapses and nothing is said.
  const CliRun near = uvtk("map " + input + " --projector two-plane --uv-offset -1e15,0 -q -o " + path("n.glb") +
                           " --json " + path("n.json"));
  ASSERT_EQ(near.status, 0) << near.err;
  EXPECT_EQ(json::parse(readText(path("n.json")))["output_collapsed_uv_faces"], 0);
  EXPECT_EQ(near.err.find("warning"), std::string::npos) << near.err;
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
