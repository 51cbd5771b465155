// `uvtk texgen` with a q that is not 1: an OBJ has no q, so the file holds (s/q, t/q[, r/q]), says
// so on stderr and in the JSON, and a corner with q = 0 is written (0, 0) and counted invalid
// (docs/conventions.md §6).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "apps/cli_test.h"
#include "io/mesh_reader.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

class TexgenQ : public CliTest {
 protected:
  // The texture coordinate of corner k of face f as read back.
  static Vec3 corner(const Mesh& mesh, int f, int k) {
    return mesh.texcoords[std::size_t(mesh.cornerTexcoords[std::size_t(f)][k])];
  }
  static constexpr const char* kPlanes =
      " --s object_linear:1,0,0,0 --t object_linear:0,1,0,0 --q object_linear:0,0,1,2";
};

TEST_F(TexgenQ, AnObjGetsSAndTDividedByQ) {
  // (1, 2, 3): s = 1, t = 2, q = z + 2 = 5: s/q = 1/5, t/q = 2/5. (4, 5, 6): q = 8. (-1, 0, 2): q = 4.
  writeText("tri.obj", "v 1 2 3\nv 4 5 6\nv -1 0 2\nf 1 2 3\n");
  const CliRun r = uvtk("texgen " + path("tri.obj") + kPlanes + " --json " + path("s.json") + " -o " + path("out.obj"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("uvtk texgen: q is not 1 at 3 corners: wrote s/q, t/q ("), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("0 invalid corners"), std::string::npos) << r.err;
  const std::string obj = readText(path("out.obj"));
  EXPECT_NE(obj.find("\nvt 0.2 0.4\n"), std::string::npos) << obj;
  const Mesh back = io::readMesh(path("out.obj")).mesh;
  EXPECT_EQ(corner(back, 0, 0), Vec3(1.0 / 5.0, 2.0 / 5.0, 0));
  EXPECT_EQ(corner(back, 0, 1), Vec3(4.0 / 8.0, 5.0 / 8.0, 0));
  EXPECT_EQ(corner(back, 0, 2), Vec3(-1.0 / 4.0, 0, 0));
  const nlohmann::json j = nlohmann::json::parse(readText(path("s.json")));
  EXPECT_EQ(j.at("q_divided"), true);
  EXPECT_EQ(j.at("q_not_one_corners"), 3);
  EXPECT_EQ(j.at("q_zero_corners"), 0);
  EXPECT_EQ(j.at("invalid_corners"), 0);
  // The JSON keeps the coordinates as generated, q undivided.
  EXPECT_EQ(j.at("texcoords")[0], nlohmann::json::array({1.0, 2.0, 0.0, 5.0}));
}

TEST_F(TexgenQ, RIsDividedTooWhenWritten) {
  writeText("tri.obj", "v 1 2 3\nv 4 5 6\nv -1 0 2\nf 1 2 3\n");
  const CliRun r = uvtk("texgen " + path("tri.obj") + kPlanes + " --r object_linear:0,0,0,1 -o " + path("out.obj"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("wrote s/q, t/q, r/q"), std::string::npos) << r.err;
  const Mesh back = io::readMesh(path("out.obj")).mesh;
  EXPECT_EQ(corner(back, 0, 0), Vec3(1.0 / 5.0, 2.0 / 5.0, 1.0 / 5.0));
}

TEST_F(TexgenQ, ACornerWithQZeroIsWrittenZeroAndCountedInvalid) {
  // (1, 2, -2): q = 0, no texture coordinate; its face is flagged, the other corners divided.
  writeText("q0.obj", "v 1 2 -2\nv 4 5 6\nv -1 0 2\nf 1 2 3\n");
  const CliRun r = uvtk("texgen " + path("q0.obj") + kPlanes + " --json " + path("s.json") + " -o " + path("out.obj"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("q is not 1 at 3 corners: wrote s/q, t/q (1 corners with q = 0 written as 0"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("1 invalid corners"), std::string::npos) << r.err;
  const std::string obj = readText(path("out.obj"));
  EXPECT_EQ(obj.find("nan"), std::string::npos) << obj;
  EXPECT_EQ(obj.find("inf"), std::string::npos) << obj;
  EXPECT_NE(obj.find("vt 0 0\n"), std::string::npos) << obj;
  const Mesh back = io::readMesh(path("out.obj")).mesh;
  EXPECT_EQ(back.cornerTexcoords[0][0], -1);  // its face is listed: read back without a UV
  EXPECT_EQ(corner(back, 0, 1), Vec3(0.5, 0.625, 0));
  const nlohmann::json j = nlohmann::json::parse(readText(path("s.json")));
  EXPECT_EQ(j.at("q_divided"), true);
  EXPECT_EQ(j.at("q_not_one_corners"), 3);
  EXPECT_EQ(j.at("q_zero_corners"), 1);
  EXPECT_EQ(j.at("invalid_corners"), 1);
  EXPECT_EQ(j.at("texcoords")[0], nlohmann::json::array({1.0, 2.0, 0.0, 0.0}));  // as generated
}

TEST_F(TexgenQ, QOneEverywhereChangesNothing) {
  writeText("tri.obj", "v 1 2 3\nv 4 5 6\nv -1 0 2\nf 1 2 3\n");
  const CliRun r = uvtk("texgen " + path("tri.obj") + " --json " + path("s.json") + " -o " + path("out.obj"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("q is not 1"), std::string::npos) << r.err;
  EXPECT_NE(readText(path("out.obj")).find("\nvt 1 2\n"), std::string::npos);
  const nlohmann::json j = nlohmann::json::parse(readText(path("s.json")));
  EXPECT_EQ(j.at("q_divided"), false);
  EXPECT_EQ(j.at("q_not_one_corners"), 0);
  EXPECT_EQ(j.at("q_zero_corners"), 0);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
