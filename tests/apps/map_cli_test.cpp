// `uvtk map` as a user runs it: exit codes, messages, outputs, and nothing written on failure.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/mesh_reader.h"
#include "io/obj_writer.h"
#include "meshes/generators.h"
#include "param/projector.h"
#include "apps/cli_test.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

using MapCli = CliTest;

TEST_F(MapCli, MapsASphereAndPrintsTheSummaryLine) {
  io::writeObj(path("sphere.obj"), meshes::latLongSphere(16, 8), nullptr);
  const CliRun r = uvtk("map " + path("sphere.obj") + " --projector sphere -o " + path("out.obj"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("uvtk map: 114 vertices, 224 faces, 8 seam edges, 2 pole vertices, 32 pole faces, "
                       "0 invalid vertices"),
            std::string::npos)
      << r.err;
  const std::string obj = readText(path("out.obj"));
  EXPECT_NE(obj.find("\nvt "), std::string::npos);
  EXPECT_NE(obj.find("\nf 1/"), std::string::npos);
}

TEST_F(MapCli, WritesUvsThatRoundTripExactly) {
  const Mesh mesh = meshes::icosphere(2);
  io::writeObj(path("ico.obj"), mesh, nullptr);
  ASSERT_EQ(uvtk("map " + path("ico.obj") + " --projector cylinder --seam cut -o " + path("out.obj")).status, 0);
  param::ProjectorOptions options;
  options.surface = param::SurfaceKind::Cylinder;
  options.seam = param::SeamMode::Cut;
  const param::Projection expected = param::project(io::readMesh(path("ico.obj")).mesh, options);
  const Mesh back = io::readMesh(path("out.obj")).mesh;
  ASSERT_EQ(back.faceCount(), expected.mesh.faceCount());
  ASSERT_EQ(back.vertexCount(), expected.mesh.vertexCount());
  for (std::size_t f = 0; f < back.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Vec3& uvw = back.texcoords[back.cornerTexcoords[f][k]];
      EXPECT_EQ(uvw.head<2>(), expected.uv.uv[3 * f + k]) << f << " " << k;
      EXPECT_EQ(back.triangles[f][k], expected.mesh.triangles[f][k]);
    }
}

TEST_F(MapCli, WritesTheSummaryAsJson) {
  io::writeObj(path("sphere.obj"), meshes::latLongSphere(16, 8), nullptr);
  ASSERT_EQ(uvtk("map " + path("sphere.obj") + " -o " + path("out.obj") + " --json " + path("s.json")).status, 0);
  const std::string json = readText(path("s.json"));
  for (const char* key : {"\"vertices\": 114", "\"faces\": 224", "\"pole_vertices\": 2", "\"pole_faces\": 32",
                          "\"invalid_vertices\": 0", "\"milliseconds\""})
    EXPECT_NE(json.find(key), std::string::npos) << key << "\n" << json;
  // The seams and the verdict are the judgement's: the 8 edges of the seam meridian, pole to pole;
  // the 32 pole faces (2 x 16 of 224, 7.5 % of the area) warn.
  const nlohmann::json j = nlohmann::json::parse(json);
  EXPECT_EQ(j["judgement"]["seams"]["wrap_edges"], 8);
  EXPECT_EQ(j["judgement"]["seams"]["cut_edges"], 0);
  EXPECT_EQ(j["verdict"], "warn");
  ASSERT_EQ(j["reasons"].size(), 1u);
  EXPECT_EQ(j["reasons"][0]["code"], "pole_area");
  EXPECT_EQ(j["reasons"][0]["faces"], 32);
}

// Where nothing can be measured (no face has an area), no number is shown: null in the JSON,
// "—" in compare's table (they were 0, which reads as a perfect stretch).
TEST_F(MapCli, AValueNothingMeasuresIsNullNotZero) {
  writeText("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 3 2\n");
  ASSERT_EQ(uvtk("map " + path("flat.obj") + " -o " + path("out.obj") + " --json " + path("s.json") + " -q").status, 0);
  const nlohmann::json j = nlohmann::json::parse(readText(path("s.json")))["judgement"];
  EXPECT_TRUE(j["stretch_l2"].is_null());
  EXPECT_TRUE(j["stretch_linf"].is_null());
  for (const char* key : {"angle", "area", "stretch_l2_faces", "texel_density"})
    for (const char* value : {"mean", "p50", "max"}) EXPECT_TRUE(j[key][value].is_null()) << key << " " << value;
  EXPECT_TRUE(j["rule_values"]["layout_texels"].is_null());
  const CliRun compare = shell(std::string(UVTK_BINARY) + " compare " + path("flat.obj") + " --no-baselines > " +
                               path("table.md"));
  ASSERT_EQ(compare.status, 0) << compare.err;
  EXPECT_NE(readText(path("table.md")).find("| fail | — | — | — | 0 |"), std::string::npos) << readText(path("table.md"));
}

// A mesh large enough for several reader chunks (4 MB) and judgement chunks (65,536 faces): one
// thread and two write the same bytes and judge alike; the stages are timed in the JSON.
TEST_F(MapCli, ThreadsChangeNothingButTheTime) {
  io::writeObj(path("big.obj"), meshes::latLongSphere(400, 250), nullptr);  // 199,200 faces, ~10 MB
  ASSERT_GT(fs::file_size(path("big.obj")), std::uintmax_t(2 * 4 << 20));
  for (const char* threads : {"1", "2"}) {
    const CliRun r = uvtk("map " + path("big.obj") + " --projector sphere --threads " + threads + " -o " +
                          path(std::string("t") + threads + ".obj") + " --json " + path(std::string("t") + threads + ".json"));
    ASSERT_EQ(r.status, 0) << r.err;
  }
  EXPECT_EQ(readText(path("t1.obj")), readText(path("t2.obj")));
  nlohmann::json one = nlohmann::json::parse(readText(path("t1.json")));
  nlohmann::json two = nlohmann::json::parse(readText(path("t2.json")));
  for (const char* stage : {"read", "map", "seams", "judge", "write", "total"}) {
    EXPECT_TRUE(one["milliseconds"][stage].is_number()) << stage;
    EXPECT_GE(one["milliseconds"]["total"].get<double>(), one["milliseconds"][stage].get<double>()) << stage;
  }
  one.erase("milliseconds"), two.erase("milliseconds");
  one.erase("output"), two.erase("output");
  EXPECT_EQ(one, two);
  EXPECT_EQ(uvtk("map " + path("big.obj") + " --threads -1 -o " + path("x.obj")).status, 2);
}

TEST_F(MapCli, HelpListsEveryOptionWithItsDefault) {
  const std::string help = path("help.txt");
  ASSERT_EQ(std::system((std::string(UVTK_BINARY) + " map --help > " + help).c_str()), 0);
  const std::string text = readText(help);
  for (const char* option : {"--projector", "--omap", "--fit", "--axis", "--center", "--axis-dir", "--ref-dir",
                             "--scale", "--plane-u", "--plane-v", "--caps", "--cap-angle", "--sphere-preset",
                             "--cube-convention", "--cube-layout", "--eye", "--at-infinity", "--seam", "--pole",
                             "--pole-eps", "--uv-scale", "--uv-offset", "--uv-rotate", "--flip-u", "--flip-v",
                             "--json", "--write-w"})
    EXPECT_NE(text.find(option), std::string::npos) << option;
  for (const char* defaults : {"=sphere", "=isn", "=bbox", "=shift", "=fan", "=1e-06", "=45", "=gl",
                              "plane|two-plane|cylinder|sphere|cube", "isn|centroid|normal|reflection"})
    EXPECT_NE(text.find(defaults), std::string::npos) << defaults;
}

TEST_F(MapCli, UnknownOptionsAreUsageErrorsAndWriteNothing) {
  io::writeObj(path("sphere.obj"), meshes::latLongSphere(8, 4), nullptr);
  const CliRun r = uvtk("map " + path("sphere.obj") + " --projektor sphere -o " + path("out.obj"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--projektor"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("out.obj")));
}

TEST_F(MapCli, ReflectionWithoutAnEyeIsAUsageError) {
  io::writeObj(path("sphere.obj"), meshes::latLongSphere(8, 4), nullptr);
  const CliRun r = uvtk("map " + path("sphere.obj") + " --omap reflection -o " + path("out.obj"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--eye"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("out.obj")));
}

TEST_F(MapCli, BadInputNamesFileAndLineAndLeavesAnExistingOutputUntouched) {
  writeText("bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
  writeText("out.obj", "precious");
  const CliRun r = uvtk("map " + path("bad.obj") + " -o " + path("out.obj"));
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("bad.obj:3: error: expected"), std::string::npos) << r.err;
  EXPECT_EQ(readText(path("out.obj")), "precious");
  for (const auto& entry : fs::directory_iterator(dir_))  // no temporary left behind
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
}

TEST_F(MapCli, AnUnwritableOutputIsExitStatusFour) {
  io::writeObj(path("sphere.obj"), meshes::latLongSphere(8, 4), nullptr);
  const CliRun r = uvtk("map " + path("sphere.obj") + " -o " + path("no/such/dir/out.obj"));
  EXPECT_EQ(r.status, 4);
  EXPECT_NE(r.err.find("out.obj"), std::string::npos) << r.err;
}

TEST_F(MapCli, ExplicitPlacementGoesWithFitNoneOnly) {
  io::writeObj(path("sphere.obj"), meshes::latLongSphere(8, 4), nullptr);
  EXPECT_EQ(uvtk("map " + path("sphere.obj") + " --fit bbox --center 0,0,0 -o " + path("o.obj")).status, 2);
  EXPECT_EQ(uvtk("map " + path("sphere.obj") + " --center 0,0,x -o " + path("o.obj")).status, 2);
  EXPECT_EQ(uvtk("map " + path("sphere.obj") + " --center 0,0,1 --scale 2 -o " + path("o.obj")).status, 0);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
