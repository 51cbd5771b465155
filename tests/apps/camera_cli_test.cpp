// The camera projector (--projector camera) as a user runs it: `uvtk map` writes the divided
// (u, v) = (s/q, t/q) per corner and counts the corners behind the eye, `uvtk eval` gives q, bad
// cameras are usage errors naming the option, and the renderer's projective interpolation of
// (s, t, q) equals the per-pixel evaluation where the divided per-vertex (baked) UVs do not.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "apps/cli_test.h"
#include "core/gl_matrices.h"
#include "inspect/mapped_mesh.h"
#include "io/mesh_reader.h"
#include "param/camera_projector.h"
#include "render/procedural.h"
#include "render/renderer.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

// eye (0, 0, 5) at the origin, fovy 90, aspect 1: u = 0.5 + 0.5 x / (5 - z), v likewise with y.
const std::string kFront = "--projector camera --eye 0,0,5 --fovy 90";

// A triangle in front of the eye and one with a corner behind it (z = 7).
const std::string kMesh =
    "v 1 0 0\n"
    "v 0 1 1\n"
    "v -1 -1 -1\n"
    "v 0 0 7\n"
    "f 1 2 3\n"
    "f 1 2 4\n";

class CameraCli : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    writeText("in.obj", kMesh);
  }
  nlohmann::json readJson(const std::string& name) const { return nlohmann::json::parse(readText(path(name))); }
};

TEST_F(CameraCli, MapWritesTheDividedUvAndCountsTheCornersBehind) {
  const CliRun r = uvtk("map " + path("in.obj") + " " + kFront + " -o " + path("out.obj") + " --json " +
                        path("summary.json"));
  EXPECT_EQ(r.status, 0) << r.err;
  const Mesh out = io::readMesh(path("out.obj")).mesh;
  ASSERT_EQ(out.cornerTexcoords.size(), 2u);
  // Hand-computed: (1,0,0) -> (0.6, 0.5); (0,1,1) -> (0.5, 0.5 + 0.5/4); (-1,-1,-1) -> 0.5 - 0.5/6 twice.
  const Vec2 expected[3] = {{0.6, 0.5}, {0.5, 0.625}, {0.5 - 0.5 / 6.0, 0.5 - 0.5 / 6.0}};
  for (int k = 0; k < 3; ++k) {
    const Vec3 vt = out.texcoords.at(std::size_t(out.cornerTexcoords[0][k]));
    EXPECT_NEAR(vt.x(), expected[k].x(), 1e-15) << k;
    EXPECT_NEAR(vt.y(), expected[k].y(), 1e-15) << k;
  }
  // The corner behind the eye is written as the other projectors write an invalid corner, (0, 0)
  // with its face listed, and so reads back without a UV.
  EXPECT_NE(readText(path("out.obj")).find("1-based face numbers: 2\n"), std::string::npos);
  EXPECT_EQ(out.cornerTexcoords[1][2], -1);
  const nlohmann::json j = readJson("summary.json");
  EXPECT_EQ(j["judgement"]["invalid_corners"]["behind"], 1);
  EXPECT_EQ(j["invalid_vertices"], 1);
  EXPECT_EQ(j["options"]["projector"], "camera");
  EXPECT_EQ(j["options"]["camera"]["eye"], nlohmann::json({0.0, 0.0, 5.0}));
  EXPECT_EQ(j["options"]["camera"]["fovy"], 90.0);
  EXPECT_EQ(j["options"]["camera"]["up"], nlohmann::json({0.0, 1.0, 0.0}));
  // The homogeneous (s, t, q) = ((x_c + w_c)/2, (y_c + w_c)/2, w_c) per corner; (0, 0, 1) behind the eye.
  const double stq[6][3] = {{3, 2.5, 5}, {2, 2.5, 4}, {2.5, 2.5, 6}, {3, 2.5, 5}, {2, 2.5, 4}, {0, 0, 1}};
  const nlohmann::json& homogeneous = j.at("homogeneous_texcoords");
  ASSERT_EQ(homogeneous.size(), 6u);
  for (std::size_t c = 0; c < 6; ++c)
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(homogeneous[c][i].get<double>(), stq[c][i], 1e-14) << c << " " << i;
}

TEST_F(CameraCli, EvalGivesUVAndQ) {
  writeText("points.csv", "1,0,0\n0.5,-1,3\n0,0,6\n");
  const CliRun r = shell(std::string(UVTK_BINARY) + " eval " + kFront + " --format json < " + path("points.csv") +
                         " > " + path("out.jsonl"));
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(path("out.jsonl"));
  std::string line;
  std::vector<nlohmann::json> rows;
  while (std::getline(in, line)) rows.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_NEAR(rows[0]["u"].get<double>(), 0.6, 1e-15);
  EXPECT_NEAR(rows[0]["v"].get<double>(), 0.5, 1e-15);
  EXPECT_EQ(rows[0]["q"], 5.0);
  EXPECT_NEAR(rows[1]["u"].get<double>(), 0.625, 1e-15);  // w_c = 2
  EXPECT_NEAR(rows[1]["v"].get<double>(), 0.25, 1e-15);
  EXPECT_EQ(rows[1]["q"], 2.0);
  EXPECT_EQ(rows[2]["status"], "invalid");
  EXPECT_NE(rows[2]["reason"].get<std::string>().find("behind the camera"), std::string::npos);
}

TEST_F(CameraCli, BadCamerasAreUsageErrorsNamingTheOption) {
  const std::string map = "map " + path("in.obj") + " -o " + path("out.obj") + " ";
  const struct {
    std::string args, expected;
  } cases[] = {
      {"--projector camera", "--eye"},
      {"--projector camera --eye 1,2,3 --center 1,2,3", "--center:"},
      {"--projector camera --eye 0,0,5 --up 0,0,1", "--up:"},
      {"--projector camera --eye 0,0,5 --fovy 180", "--fovy:"},
      {"--projector camera --eye 0,0,5 --fovy 0", "--fovy:"},
      {"--projector camera --eye 0,0,5 --aspect 0", "--aspect:"},
      {"--projector camera --eye 0,0,5 --aspect inf", "--aspect"},
      {"--projector camera --eye 0,0,nan", "--eye"},
      {"--projector camera --eye 0,0,5 --fit obb", "--fit goes with the surface projectors"},
      {"--projector camera --eye 0,0,5 --omap centroid", "--omap goes with the surface projectors"},
      {"--projector sphere --fovy 30", "--fovy goes with --projector camera only"},
      {"--projector plane --up 0,0,1", "--up goes with --projector camera only"},
  };
  for (const auto& c : cases) {
    const CliRun r = uvtk(map + c.args);
    EXPECT_EQ(r.status, 2) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.args << ": " << r.err;
  }
  EXPECT_FALSE(std::ifstream(path("out.obj")).good());
}

// Where the command's own camera owns a name (render: --eye, --center, --up, --fovy; report: --up),
// the camera projector's option is --proj-NAME.
TEST_F(CameraCli, RenderTakesTheProjectorCameraAsProjOptions) {
  const std::string render = "render " + path("in.obj") + " -o " + path("out.png") + " --size 64x64 ";
  CliRun r = uvtk(render + "--projector camera --proj-eye 0,0,5 --proj-fovy 90");
  EXPECT_EQ(r.status, 0) << r.err;
  r = uvtk(render + "--projector camera --proj-eye 0,0,5 --proj-up 0,0,1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--proj-up:"), std::string::npos) << r.err;
  r = uvtk(render + "--projector camera");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--proj-eye"), std::string::npos) << r.err;
  // `uvtk report`: --up is the views' camera, the projector's is --proj-up.
  r = uvtk("report " + path("in.obj") + " --json " + path("r.json") + " " + kFront + " --proj-up 0,0,1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--proj-up:"), std::string::npos) << r.err;
}

// The AOV (u, v) of every covered pixel: per-vertex projective and baked against per pixel.
struct UvDifference {
  double max = 0.0;
  std::size_t pixels = 0;
};

UvDifference compareUv(const render::Rendering& a, const render::Rendering& b) {
  UvDifference d;
  for (int y = 0; y < a.aovs.height; ++y)
    for (int x = 0; x < a.aovs.width; ++x) {
      if (a.aovs.at(x, y, 3) < 0 || b.aovs.at(x, y, 3) < 0) continue;  // background
      ++d.pixels;
      d.max = std::max({d.max, std::fabs(double(a.aovs.at(x, y, 0)) - b.aovs.at(x, y, 0)),
                        std::fabs(double(a.aovs.at(x, y, 1)) - b.aovs.at(x, y, 1))});
    }
  return d;
}

TEST(CameraRender, ProjectiveInterpolationIsExactWhereBakedUvsSwim) {
  // A big quad in z = 0 seen by the projector from an oblique eye, so that q varies by 2.5x over it.
  Mesh quad;
  quad.positions = {Vec3(-2, -2, 0), Vec3(2, -2, 0), Vec3(2, 2, 0), Vec3(-2, 2, 0)};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  param::ProjectorOptions options;
  options.surface = param::SurfaceKind::Camera;
  options.camera.eye = Vec3(3, 1, 2.5);
  options.camera.fovyDegrees = 100.0;
  const inspect::MappedMesh mapped = inspect::mapByProjector(quad, options, false, 1);
  ASSERT_EQ(mapped.cameraQ.size(), 6u);
  // The corners carry (u q, v q, 0, q), q = w_c; baked: (u, v, 0, 1).
  const param::CameraTransform camera(options.camera);
  const std::vector<Vec4> projective = mapped.corners(), baked = mapped.corners(true);
  for (std::size_t c = 0; c < 6; ++c) {
    const Vec4 h = camera.homogeneous(quad.positions[quad.triangles[c / 3][c % 3]]);
    EXPECT_NEAR(projective[c][3], h[3], 1e-12);
    EXPECT_NEAR(projective[c][0], h[0], 1e-12);
    EXPECT_NEAR(projective[c][1], h[1], 1e-12);
    EXPECT_EQ(baked[c][3], 1.0);
    EXPECT_EQ(baked[c].head<2>(), mapped.uv.uv[c]);
  }

  render::RenderOptions ro;
  ro.camera.viewFromWorld = lookAt(Vec3(0, -1, 6), Vec3::Zero(), Vec3::UnitY());
  ro.camera.clipFromView = perspective(60.0, 1.0, 0.5, 20.0);
  ro.camera.width = ro.camera.height = 256;
  ro.raster.cull = render::Cull::None;
  const render::Texture texture = render::checkerTexture(64, 8);
  ro.texture = &texture;
  ro.aovs = true;
  const auto draw = [&](bool perPixel, bool bake) {
    return render::render(mapped.mesh, mapped.texcoordSource(perPixel, bake), ro);
  };
  const render::Rendering exact = draw(true, false), perVertex = draw(false, false), bakedFrame = draw(false, true);
  const UvDifference projectiveError = compareUv(perVertex, exact), bakedError = compareUv(bakedFrame, exact);
  EXPECT_GT(projectiveError.pixels, 10000u);
  EXPECT_LT(projectiveError.max, 2e-6);  // float AOVs: rounding only (measured: 0 on 21056 pixels)
  EXPECT_GT(bakedError.max, 0.05) << "measured " << bakedError.max;  // measured: 0.112 in UV units
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
