// `uvtk texgen` as a user runs it: the written texture coordinates, JSON, exit codes, help.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "io/mesh_reader.h"
#include "apps/cli_test.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

class TexgenCli : public CliTest {
 protected:
  std::string triangle() const { return writeText("tri.obj", "v 1 2 3\nv 4 5 6\nv -1 0 2\nf 1 2 3\n"); }
  // The texture coordinate of corner k of face 0 as read back.
  static Vec3 corner(const Mesh& mesh, int k) { return mesh.texcoords[mesh.cornerTexcoords[0][k]]; }
};

TEST_F(TexgenCli, ObjectLinearWritesVtSAndTOfTheGivenPlanes) {
  const CliRun r = uvtk("texgen " + triangle() + " --s object_linear:1,0,0,0.5 --t object_linear:0,2,0,0 -o " +
                        path("out.obj"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("uvtk texgen: 3 vertices, 1 faces, 0 sphere-map singular corners"), std::string::npos) << r.err;
  const std::string obj = readText(path("out.obj"));
  EXPECT_NE(obj.find("\nvt 1.5 4\n"), std::string::npos) << obj;  // two components: r is not generated
  const Mesh back = io::readMesh(path("out.obj")).mesh;
  EXPECT_EQ(corner(back, 0), Vec3(1.5, 4, 0));
  EXPECT_EQ(corner(back, 1), Vec3(4.5, 10, 0));
  EXPECT_EQ(corner(back, 2), Vec3(-0.5, 0, 0));
}

TEST_F(TexgenCli, WithoutCoordinateOptionsSAndTAreObjectLinearWithGlDefaultPlanes) {
  ASSERT_EQ(uvtk("texgen " + triangle() + " -o " + path("out.obj")).status, 0);
  const Mesh back = io::readMesh(path("out.obj")).mesh;
  EXPECT_EQ(corner(back, 0), Vec3(1, 2, 0));
  EXPECT_EQ(corner(back, 2), Vec3(-1, 0, 0));
}

TEST_F(TexgenCli, NormalMapWritesVtSTR) {
  writeText("flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const CliRun r = uvtk("texgen " + path("flat.obj") + " --mode normal_map -o " + path("out.obj"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(readText(path("out.obj")).find("\nvt 0 0 1\n"), std::string::npos) << readText(path("out.obj"));
}

TEST_F(TexgenCli, NoNormalizeKeepsTheLengthOfTheTransformedNormal) {
  writeText("n.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0.6 0.8 0\nf 1//1 2//1 3//1\n");
  const std::string model = " --model \"2 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1\"";
  ASSERT_EQ(uvtk("texgen " + path("n.obj") + " --mode normal_map" + model + " -o " + path("a.obj")).status, 0);
  ASSERT_EQ(uvtk("texgen " + path("n.obj") + " --mode normal_map --no-normalize" + model + " -o " + path("b.obj"))
                .status,
            0);
  const Vec3 normalized = corner(io::readMesh(path("a.obj")).mesh, 0);
  const Vec3 raw = corner(io::readMesh(path("b.obj")).mesh, 0);
  EXPECT_NEAR((raw - Vec3(0.3, 0.8, 0)).norm(), 0.0, 1e-15);  // inverse transpose of diag(2,1,1)
  EXPECT_NEAR((normalized - Vec3(0.3, 0.8, 0) / std::sqrt(0.73)).norm(), 0.0, 1e-15);
}

TEST_F(TexgenCli, JsonHoldsEveryCornersSTRQ) {
  const CliRun r = uvtk("texgen " + triangle() + " --q object_linear:0,0,0,2 --s object_linear --json " +
                        path("s.json") + " -o " + path("out.obj"));
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(readText(path("s.json")));
  EXPECT_EQ(j.at("faces"), 1);
  EXPECT_EQ(j.at("sphere_map_singular_corners"), 0);
  ASSERT_EQ(j.at("texcoords").size(), 3u);
  EXPECT_EQ(j.at("texcoords")[1], nlohmann::json::array({4.0, 0.0, 0.0, 2.0}));  // t, r off: 0; q = 2
}

TEST_F(TexgenCli, SphereMapOnRIsAUsageError) {
  const CliRun r = uvtk("texgen " + triangle() + " --r sphere_map -o " + path("out.obj"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--r"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("out.obj")));
  EXPECT_EQ(uvtk("texgen " + triangle() + " --q normal_map -o " + path("out.obj")).status, 2);
  EXPECT_EQ(uvtk("texgen " + triangle() + " --s cube_map -o " + path("out.obj")).status, 2);
  EXPECT_EQ(uvtk("texgen " + triangle() + " --texgen-mode x -o " + path("out.obj")).status, 2);
}

TEST_F(TexgenCli, ABadInputFileIsExitStatusThreeWithFileAndLine) {
  writeText("bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
  const CliRun r = uvtk("texgen " + path("bad.obj") + " -o " + path("out.obj"));
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("bad.obj:3: error: expected"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("out.obj")));
}

TEST_F(TexgenCli, HelpListsEveryOption) {
  const std::string help = path("help.txt");
  ASSERT_EQ(std::system((std::string(UVTK_BINARY) + " texgen --help > " + help).c_str()), 0);
  const std::string text = readText(help);
  for (const char* option : {"--s", "--t", "--r", "--q", "--mode", "--eye", "--center", "--up", "--model",
                             "--texmatrix", "--no-normalize", "--json", "--output", "=0,0,-1", "=0,1,0",
                             "object_linear|eye_linear|sphere_map|normal_map|reflection_map|off"})
    EXPECT_NE(text.find(option), std::string::npos) << option;
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
