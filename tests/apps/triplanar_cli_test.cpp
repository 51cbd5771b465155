// The triplanar projector (--projector triplanar) as a user runs it: `uvtk eval` gives the three
// projections and their weights (Unity, MaterialX and Godot presets, --tile, --blend), `uvtk map`
// writes each face's dominant projection (a box mapping) and says it is not a blend, bad options
// are usage errors naming the option, and `uvtk render` draws the blend per pixel and measures
// its blend zone.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "apps/cli_test.h"
#include "io/mesh_reader.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

const std::string kCube = std::string(UVTK_MESHES_DIR) + "/cube.obj";

class TriplanarCli : public CliTest {
 protected:
  nlohmann::json readJson(const std::string& name) const { return nlohmann::json::parse(readText(path(name))); }

  // `uvtk eval --projector triplanar` of the point (1, 2, 3) with normal n and the options given.
  nlohmann::json eval(const std::string& normal, const std::string& options = "") const {
    const CliRun r = shell(std::string(UVTK_BINARY) + " eval --projector triplanar --format json --point 1,2,3 " +
                           "--normal " + normal + " " + options + " > " + path("eval.jsonl"));
    EXPECT_EQ(r.status, 0) << options << ": " << r.err;
    const std::string text = readText(path("eval.jsonl"));
    return text.empty() ? nlohmann::json::object() : nlohmann::json::parse(text);
  }
};

void expectPair(const nlohmann::json& pair, double a, double b, const std::string& what) {
  ASSERT_TRUE(pair.is_array()) << what;
  ASSERT_EQ(pair.size(), 2u) << what;
  EXPECT_NEAR(pair[0].get<double>(), a, 1e-15) << what;
  EXPECT_NEAR(pair[1].get<double>(), b, 1e-15) << what;
}

void expectWeights(const nlohmann::json& row, double x, double y, double z, const std::string& what) {
  const nlohmann::json& w = row["weights"];
  ASSERT_TRUE(w.is_array()) << what;
  ASSERT_EQ(w.size(), 3u) << what;
  const double expected[3] = {x, y, z};
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(w[i].is_number()) << what;
    EXPECT_TRUE(std::isfinite(w[i].get<double>())) << what;
    EXPECT_NEAR(w[i].get<double>(), expected[i], 1e-15) << what << " weight " << i;
  }
}

TEST_F(TriplanarCli, EvalGivesTheThreeProjectionsAndTheirWeights) {
  // Unity: x (p.z, p.y), y (p.x, p.z), z (p.x, p.y); weights |n|^1 / sum = (1, 2, 3) / 6.
  nlohmann::json row = eval("1,2,3");
  EXPECT_EQ(row["status"], "ok");
  expectWeights(row, 1.0 / 6, 1.0 / 3, 0.5, "unity");
  expectPair(row["uv_x"], 3, 2, "uv_x");
  expectPair(row["uv_y"], 1, 3, "uv_y");
  expectPair(row["uv_z"], 1, 2, "uv_z");
  EXPECT_EQ(row["u"], 1.0);  // (u, v) is the dominant axis's (z) projection
  EXPECT_EQ(row["v"], 2.0);

  // --tile 2 doubles every projection; the weights do not move.
  row = eval("1,2,3", "--tile 2");
  expectWeights(row, 1.0 / 6, 1.0 / 3, 0.5, "tile 2");
  expectPair(row["uv_x"], 6, 4, "tile uv_x");
  expectPair(row["uv_y"], 2, 6, "tile uv_y");
  expectPair(row["uv_z"], 2, 4, "tile uv_z");
  EXPECT_EQ(row["u"], 2.0);
  EXPECT_EQ(row["v"], 4.0);

  // The exponent: 0 weighs the three alike, 2 squares (1, 4, 9) / 14.
  expectWeights(eval("1,2,3", "--blend 0"), 1.0 / 3, 1.0 / 3, 1.0 / 3, "blend 0");
  expectWeights(eval("1,2,3", "--blend 2"), 1.0 / 14, 4.0 / 14, 9.0 / 14, "blend 2");

  // MaterialX: blend 0.5 is the exponent 1 / 0.5 = 2, (1, 4, 4) / 9; x projects to (p.y, p.z).
  row = eval("1,2,2", "--triplanar-preset materialx --blend 0.5");
  expectWeights(row, 1.0 / 9, 4.0 / 9, 4.0 / 9, "materialx");
  expectPair(row["uv_x"], 2, 3, "materialx uv_x");
  expectPair(row["uv_y"], 1, 3, "materialx uv_y");
  expectPair(row["uv_z"], 1, 2, "materialx uv_z");
  EXPECT_EQ(row["u"], 1.0);  // |n_y| = |n_z|: the tie goes to the lower axis, y
  EXPECT_EQ(row["v"], 3.0);

  // Godot: x (-p.z, -p.y), y (p.x, p.z), z (p.x, -p.y).
  row = eval("1,2,3", "--triplanar-preset godot");
  expectWeights(row, 1.0 / 6, 1.0 / 3, 0.5, "godot");
  expectPair(row["uv_x"], -3, -2, "godot uv_x");
  expectPair(row["uv_y"], 1, 3, "godot uv_y");
  expectPair(row["uv_z"], 1, -2, "godot uv_z");
  EXPECT_EQ(row["u"], 1.0);
  EXPECT_EQ(row["v"], -2.0);
}

TEST_F(TriplanarCli, EvalWeightsAtTheEdgesOfTheirRange) {
  // A normal on an axis, of any length and sign: that axis alone.
  nlohmann::json row = eval("0,0,-5");
  expectWeights(row, 0, 0, 1, "on -z");
  EXPECT_EQ(row["u"], 1.0);
  row = eval("0,7,0", "--blend 0.25");
  expectWeights(row, 0, 1, 0, "on +y");
  // A huge exponent keeps the largest components, shared on their tie, and stays finite.
  row = eval("1,1,0.5", "--blend 1e6");
  expectWeights(row, 0.5, 0.5, 0, "blend 1e6");
  EXPECT_EQ(row["u"], 3.0);  // the x-y tie goes to x: (p.z, p.y)
  EXPECT_EQ(row["v"], 2.0);
  // The weights do not depend on the normal's length (within 1e+-150: beyond, the frame's normal
  // squares its length into an overflow or underflow and the point reads as having a zero normal).
  expectWeights(eval("1e-150,2e-150,3e-150"), 1.0 / 6, 1.0 / 3, 0.5, "tiny normal");
  expectWeights(eval("1e150,2e150,3e150"), 1.0 / 6, 1.0 / 3, 0.5, "huge normal");

  // A zero normal has no weights: the point is invalid, and says why.
  row = eval("0,0,0");
  EXPECT_EQ(row["status"], "invalid");
  EXPECT_NE(row["reason"].get<std::string>().find("normal is zero"), std::string::npos) << row.dump();
}

TEST_F(TriplanarCli, EvalCsvHasTheTriplanarColumns) {
  const CliRun r = shell(std::string(UVTK_BINARY) +
                         " eval --projector triplanar --format csv --point 1,2,3 --normal 1,2,3 > " + path("out.csv"));
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(path("out.csv"));
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_NE(header.find(",u,v,w,q,u_x,v_x,u_y,v_y,u_z,v_z,weight_x,weight_y,weight_z,status,reason"),
            std::string::npos)
      << header;
  EXPECT_NE(row.find(",3,2,1,3,1,2,0.16666666666666666,0.33333333333333331,0.5,ok,"), std::string::npos) << row;
}

// The cube's face normal's largest component picks the projection its corners take.
int dominantAxisOf(const Vec3& n) {
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::fabs(n[i]) > std::fabs(n[axis])) axis = i;
  return axis;
}

TEST_F(TriplanarCli, MapWritesTheBoxMappingOfTheDominantAxes) {
  const CliRun r = uvtk("map " + kCube + " --projector triplanar --fit none -o " + path("out.obj") + " --json " +
                        path("summary.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("not a triplanar blend"), std::string::npos) << r.err;

  const Mesh out = io::readMesh(path("out.obj")).mesh;
  ASSERT_EQ(out.cornerTexcoords.size(), out.faceCount());
  std::size_t perAxis[3] = {0, 0, 0};
  for (std::size_t f = 0; f < out.faceCount(); ++f) {
    const Triangle& t = out.triangles[f];
    const Vec3 a = out.positions[std::size_t(t[0])], b = out.positions[std::size_t(t[1])],
               c = out.positions[std::size_t(t[2])];
    const int axis = dominantAxisOf((b - a).cross(c - a));
    ++perAxis[axis];
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = out.positions[std::size_t(t[k])];
      // Unity: x (p.z, p.y), y (p.x, p.z), z (p.x, p.y); the cube's coordinates are exact in text.
      const Vec2 expected = axis == 0 ? Vec2(p.z(), p.y()) : axis == 1 ? Vec2(p.x(), p.z()) : Vec2(p.x(), p.y());
      const Vec3 vt = out.texcoords.at(std::size_t(out.cornerTexcoords[f][k]));
      EXPECT_EQ(vt.head<2>(), expected) << "face " << f << " corner " << k;
    }
  }

  const nlohmann::json j = readJson("summary.json");
  const nlohmann::json& faces = j["triplanar_faces"];
  EXPECT_EQ(faces["x"], perAxis[0]);
  EXPECT_EQ(faces["y"], perAxis[1]);
  EXPECT_EQ(faces["z"], perAxis[2]);
  EXPECT_EQ(faces["x"], faces["y"]);
  EXPECT_EQ(faces["y"], faces["z"]);
  EXPECT_EQ(faces["x"].get<std::size_t>() + faces["y"].get<std::size_t>() + faces["z"].get<std::size_t>(),
            out.faceCount());
  EXPECT_EQ(j["faces"], out.faceCount());
  EXPECT_EQ(j["options"]["projector"], "triplanar");
  EXPECT_EQ(j["options"]["triplanar"],
            nlohmann::json({{"preset", "unity"}, {"tile", 1.0}, {"blend", 1.0}, {"exponent", 1.0}}));

  // The mirrored half of the box (Unity mirrors +x, +y and -z) is backfacing, not flipped.
  bool backfacing = false;
  for (const nlohmann::json& reason : j["reasons"]) {
    EXPECT_NE(reason["code"], "flipped") << reason.dump();
    if (reason["code"] == "backfacing_area") {
      backfacing = true;
      EXPECT_EQ(reason["faces"], out.faceCount() / 2);
      EXPECT_NEAR(reason["value"].get<double>(), 0.5, 1e-12);
    }
  }
  EXPECT_TRUE(backfacing) << j["reasons"].dump();

  // MaterialX's exponent is 1 / max(b, 0.03).
  ASSERT_EQ(uvtk("map " + kCube + " --projector triplanar --triplanar-preset materialx --blend 0.01 --tile 3 -o " +
                 path("m.obj") + " --json " + path("m.json"))
                .status,
            0);
  const nlohmann::json m = readJson("m.json")["options"]["triplanar"];
  EXPECT_EQ(m["preset"], "materialx");
  EXPECT_EQ(m["tile"], 3.0);
  EXPECT_NEAR(m["exponent"].get<double>(), 1.0 / 0.03, 1e-12);
}

TEST_F(TriplanarCli, BadOptionsAreUsageErrorsNamingTheOption) {
  const std::string map = "map " + kCube + " -o " + path("out.obj") + " ";
  const struct {
    std::string args, expected;
  } cases[] = {
      {"--projector triplanar --tile 0", "--tile:"},
      {"--projector triplanar --tile nan", "--tile:"},
      {"--projector triplanar --blend -1", "--blend:"},
      {"--projector triplanar --blend inf", "--blend:"},
      {"--projector sphere --tile 2", "--tile goes with --projector triplanar only"},
      {"--projector plane --triplanar-preset godot", "--triplanar-preset goes with --projector triplanar only"},
      {"--projector triplanar --omap normal", "--omap goes with the surface projectors"},
      {"--projector triplanar --seam cut", "--seam goes with the surface projectors"},
  };
  for (const auto& c : cases) {
    const CliRun r = uvtk(map + c.args);
    EXPECT_EQ(r.status, 2) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.args << ": " << r.err;
  }
  EXPECT_FALSE(std::ifstream(path("out.obj")).good());
}

TEST_F(TriplanarCli, RenderDrawsTheBlendPerPixelAndMeasuresItsZone) {
  // A flat quad facing +z: every pixel's weights are (0, 0, 1), no pixel is in the blend zone.
  writeText("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
  const std::string quad = "render " + path("quad.obj") + " --projector triplanar --size 96x96 ";
  CliRun r = uvtk(quad + "--view weights -o " + path("q.png") + " --json " + path("q.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  nlohmann::json zone = readJson("q.json")["blend_zone"];
  EXPECT_GT(zone["covered_pixels"].get<long>(), 0);
  EXPECT_EQ(zone["pixels"], 0);
  EXPECT_EQ(zone["invalid_pixels"], 0);

  // The icosphere's normals turn through every direction: part of it, not all, blends.
  const std::string sphere =
      "render " + std::string(UVTK_MESHES_DIR) + "/icosphere.obj --projector triplanar --size 96x96 ";
  r = uvtk(sphere + "--view weights,blendzone -o " + path("s.png") + " --json " + path("s.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  zone = readJson("s.json")["blend_zone"];
  EXPECT_GT(zone["covered_pixels"].get<long>(), 0);
  EXPECT_GT(zone["pixels"].get<long>(), 0);
  EXPECT_LT(zone["pixels"].get<long>(), zone["covered_pixels"].get<long>());
  EXPECT_EQ(readJson("s.json")["views"], nlohmann::json({"weights", "blendzone"}));

  // The picture: per pixel unless --uv per-vertex asks for the box UVs an OBJ would hold.
  r = uvtk(sphere + "-o " + path("p.png") + " --json " + path("p.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(readJson("p.json")["uv"], "per-pixel");
  r = uvtk(sphere + "--uv per-vertex -o " + path("v.png") + " --json " + path("v.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(readJson("v.json")["uv"], "per-vertex");
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
