// Polygons through the program: a concave pentagon is mapped without folding over itself.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "apps/cli_test.h"
#include "io/mesh_reader.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

class PolygonCli : public CliTest {};

TEST_F(PolygonCli, AConcavePentagonMapsWithItsAreaAndNoFlippedFace) {
  // (0,0) (2,0) (2,2) (1,1) (0,2) started at (2,2), area 3. The fan from the first corner folded: triangles of
  // areas 2, 2 and 1, the last clockwise, so a planar mapping along z flipped a fifth of the area.
  const std::string input = writeText("pentagon.obj", "v 2 2 0\nv 1 1 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\nf 1 2 3 4 5\n");
  const CliRun r = uvtk("map " + input + " --projector plane --axis z -o " + path("out.obj") + " --json " + path("s.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;

  const nlohmann::json summary = nlohmann::json::parse(readText(path("s.json")));
  EXPECT_EQ(summary["input"]["faces"], 3);
  EXPECT_EQ(summary["judgement"]["rule_values"]["flipped_area"], 0.0);
  EXPECT_EQ(summary["verdict"], "pass");

  std::istringstream written(readText(path("out.obj")));
  const Mesh mesh = io::readObj(written, "out.obj").mesh;
  ASSERT_EQ(mesh.faceCount(), 3u);
  double area = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3 n = triangleAreaNormal(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
    EXPECT_GT(n.z(), 0.0) << "every triangle turns the pentagon's way";
    area += 0.5 * n.norm();
  }
  EXPECT_DOUBLE_EQ(area, 3.0);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
