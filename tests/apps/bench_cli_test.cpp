// `uvtk bench` and the speed-accuracy options of the mapping commands as a user runs them: every
// configuration measured with the documented keys, errors within their bounds, clear refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "apps/cli_test.h"
#include "io/image_io.h"
#include "io/mesh_reader.h"
#include "io/mesh_writer.h"
#include "io/obj_writer.h"
#include "meshes/generators.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

class BenchCli : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    io::writeObj(path("sphere.obj"), meshes::latLongSphere(64, 32), nullptr);
  }
  nlohmann::json readJson(const std::string& name) const { return nlohmann::json::parse(readText(path(name))); }
};

TEST_F(BenchCli, MeasuresEveryProjectorPrecisionAndMathModeWithTheDocumentedKeys) {
  const CliRun run = uvtk("bench --mesh " + path("sphere.obj") +
                          " --projector plane,sphere --precision double,float --math exact,fast --min-time 0.01"
                          " --no-peers --json " +
                          path("b.json") + " --plot " + path("b.png") + " --markdown " + path("b.md"));
  ASSERT_EQ(run.status, 0) << run.err;
  const nlohmann::json j = readJson("b.json");
  std::vector<nlohmann::json> records;  // the mapping's (the end-to-end map has its own)
  for (const nlohmann::json& r : j["records"])
    if (r["section"] == "mapping") records.push_back(r);
  ASSERT_EQ(records.size(), 6u);  // the plane has no arctangent: one math mode per precision
  for (const nlohmann::json& r : records) {
    for (const char* key :
         {"projector", "precision", "math", "vertices", "ns_per_vertex", "max_err_ulp", "max_err_texels"})
      EXPECT_TRUE(r.contains(key)) << key << " " << r;
    EXPECT_EQ(r["vertices"], 64 * 31 + 2);
    EXPECT_GT(r["ns_per_vertex"].get<double>(), 0.0);
    EXPECT_EQ(r["state_mismatches"], 0) << r;
    // Within a few ulps of the result's precision, and far below 1/64 texel at 4096 even in float.
    EXPECT_LE(r["max_err_ulp"].get<double>(), 4.0) << r;
    EXPECT_LT(r["max_err_texels"].get<double>(), r["precision"] == "double" ? 1e-8 : 1.0 / 64) << r;
  }
  const Image chart = io::readImage(path("b.png")).image;
  EXPECT_EQ(chart.width, 960);
  EXPECT_EQ(chart.height, 640);
  EXPECT_NE(readText(path("b.md")).find("| sphere | isn | float | fast | 1 |"), std::string::npos);
}

TEST_F(BenchCli, RendersPerVertexAgainstPerPixelAndFiltersAgainstTheSupersampledReference) {
  const CliRun run = uvtk("bench --mesh " + path("sphere.obj") +
                          " --projector sphere --precision double --math exact --min-time 0.01 --no-peers --render"
                          " --size 64x64 --filters nearest,linear_mipmap_linear --spp 1,4 --json " +
                          path("b.json") + " --plot " + path("b.png"));
  ASSERT_EQ(run.status, 0) << run.err;
  const nlohmann::json j = readJson("b.json");
  std::vector<nlohmann::json> frames;
  for (const nlohmann::json& r : j["records"])
    if (r["section"] == "rendering") frames.push_back(r);
  ASSERT_EQ(frames.size(), 4u);  // per-vertex and per-pixel (linear_mipmap_linear), nearest, 4 samples
  for (const nlohmann::json& r : frames) {
    for (const char* key : {"triangles", "width", "height", "filter", "threads", "ms_per_frame"})
      EXPECT_TRUE(r.contains(key)) << key << " " << r;
    EXPECT_EQ(r["triangles"], 2 * 64 * 31);
    EXPECT_EQ(r["width"], 64);
    EXPECT_GT(r["rmse"].get<double>(), 0.0);  // no single sample per pixel equals 64 of them
    if (r["uv"] == "per-pixel") {
      EXPECT_EQ(r["uv_err_max_texels"], 0.0);
    } else {
      EXPECT_GT(r["uv_err_max_texels"].get<double>(), 0.0);  // interpolating the sphere's UVs is not exact
    }
  }
  // More samples per pixel come closer to the 64-sample reference.
  EXPECT_LT(frames[3]["rmse"].get<double>(), frames[0]["rmse"].get<double>());
  EXPECT_TRUE(fs::exists(path("b-render.png")));
}

// The root mean square and the largest difference of two images' channel values.
std::pair<double, double> differences(const Image& a, const Image& b) {
  EXPECT_EQ(a.pixels.size(), b.pixels.size());
  double sum = 0, largest = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const double d = std::fabs(double(a.pixels[i]) - double(b.pixels[i]));
    sum += d * d;
    largest = std::max(largest, d);
  }
  return {std::sqrt(sum / double(a.pixels.size())), largest};
}

TEST_F(BenchCli, RenderTakesRendersSceneOptionsAndTimesThePictureItDraws) {
  // A 16 x 16 image texture whose edges differ (clamping is not repeating).
  Image texture(16, 16, 3, 0.0f);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      texture.at(x, y, 0) = float((x * 7 + y * 3) % 16) / 15.0f;
      texture.at(x, y, 1) = float(y) / 15.0f;
      texture.at(x, y, 2) = float(x) / 15.0f;
    }
  io::writeImage(path("tex.png"), texture, io::PixelType::UInt8);
  const std::string scene = " --eye 0.5,-3,1.5 --center 0,0,0.2 --up 0,0,1 --texture " + path("tex.png") +
                            " --wrap clamp_to_edge --cull none --background 0.2,0.3,0.4 --size 48x40";
  const CliRun run = uvtk("bench --mesh " + path("sphere.obj") +
                          " --projector sphere --precision double --math exact --min-time 0.01 --no-peers"
                          " --no-end-to-end --render --filter linear --spp 1 --json " +
                          path("b.json") + " --markdown " + path("b.md") + scene);
  ASSERT_EQ(run.status, 0) << run.err;
  const nlohmann::json j = readJson("b.json");
  std::vector<nlohmann::json> frames;
  for (const nlohmann::json& r : j["records"])
    if (r["section"] == "rendering") frames.push_back(r);
  ASSERT_EQ(frames.size(), 2u);  // --filter linear alone: per-vertex and per-pixel UVs
  for (const nlohmann::json& r : frames) {
    EXPECT_EQ(r["filter"], "linear");
    EXPECT_EQ(r["camera"], "explicit");
    EXPECT_EQ(r["projection"], "perspective");
    for (int i = 0; i < 3; ++i)  // the made camera's, from its view matrix
      EXPECT_NEAR(r["eye"][i].get<double>(), (std::array<double, 3>{0.5, -3.0, 1.5}[i]), 1e-12);
    EXPECT_EQ(r["texture"], path("tex.png"));
    EXPECT_EQ(r["wrap"], "clamp_to_edge");
    EXPECT_EQ(r["env"], "replace");
    EXPECT_EQ(r["seamless"], false);
    EXPECT_EQ(r["cull"], "none");
    EXPECT_EQ(r["background"], nlohmann::json::array({0.2, 0.3, 0.4}));
    EXPECT_EQ(r["width"], 48);
    EXPECT_EQ(r["height"], 40);
  }
  EXPECT_EQ(frames[0]["uv"], "per-vertex");
  EXPECT_EQ(frames[1]["uv"], "per-pixel");
  EXPECT_NE(readText(path("b.md")).find("Scene: camera explicit (perspective), texture " + path("tex.png") +
                                        ", wrap clamp_to_edge, env replace, cull none."),
            std::string::npos);

  // `uvtk render` with the same options draws the frame bench timed, and the reference bench
  // compares it with (64 samples, per-pixel UVs, linear_mipmap_linear): their RMSE and largest
  // difference are bench's, up to the PNGs' rounding (each value within half a level of 255).
  // (With --wrap repeat bench measures 0.024 and 0.48 here, against 0.029 and 0.58.)
  const std::string render = "render " + path("sphere.obj") + " --projector sphere" + scene;
  ASSERT_EQ(uvtk(render + " --filter linear -o " + path("frame.png")).status, 0);
  ASSERT_EQ(uvtk(render + " --filter linear_mipmap_linear --spp 64 --uv per-pixel -o " + path("ref.png")).status, 0);
  const auto [rmse, largest] =
      differences(io::readImage(path("frame.png")).image, io::readImage(path("ref.png")).image);
  EXPECT_GT(rmse, 0.01);  // the comparison is not of two blank frames
  EXPECT_NEAR(frames[0]["rmse"].get<double>(), rmse, 1.0 / 255);
  EXPECT_NEAR(frames[0]["max_err"].get<double>(), largest, 1.0 / 255);
}

TEST_F(BenchCli, RenderTakesACubeMapSeamlessAndPerPixelUvsForEveryRow) {
  const CliRun run = uvtk("bench --mesh " + path("sphere.obj") +
                          " --projector sphere --precision double --math exact --min-time 0.01 --no-peers"
                          " --no-end-to-end --render --render-projector cube --texture cube:16 --seamless"
                          " --uv per-pixel --filters nearest,linear --spp 1,4 --size 32x32 --json " +
                          path("b.json"));
  ASSERT_EQ(run.status, 0) << run.err;
  const nlohmann::json j = readJson("b.json");
  std::vector<nlohmann::json> frames;
  for (const nlohmann::json& r : j["records"])
    if (r["section"] == "rendering") frames.push_back(r);
  // linear_mipmap_linear (the UV and sample-count rows' filter), nearest, linear, and 4 samples: all
  // per pixel, so none has an interpolation error.
  ASSERT_EQ(frames.size(), 4u);
  for (const nlohmann::json& r : frames) {
    EXPECT_EQ(r["uv"], "per-pixel");
    EXPECT_EQ(r["uv_err_max_texels"], 0.0);
    EXPECT_EQ(r["projector"], "cube");
    EXPECT_EQ(r["texture"], "cube:16");
    EXPECT_EQ(r["seamless"], true);
    EXPECT_EQ(r["wrap"], "clamp_to_edge");  // a cube map's default, as in `uvtk render`
    EXPECT_EQ(r["camera"], "auto");
  }
  EXPECT_EQ(frames[1]["filter"], "nearest");
  EXPECT_EQ(frames[3]["spp"], 4);
  EXPECT_LT(frames[3]["rmse"].get<double>(), frames[0]["rmse"].get<double>());
}

TEST_F(BenchCli, RenderRefusesWhatUvtkRenderRefusesWithItsMessage) {
  const std::string bench = "bench --mesh " + path("sphere.obj") +
                            " --projector sphere --precision double --math exact --min-time 0.01 --no-peers"
                            " --no-end-to-end --render --render-projector sphere --json " +
                            path("b.json");
  const std::string render = "render " + path("sphere.obj") + " --projector sphere -o " + path("r.png");
  for (const char* bad : {" --eye 1,2", " --filter bogus", " --seamless", " --texture cube:8", " --wrap twice",
                          " --cull sideways", " --size 0x5", " --background red", " --ortho auto --eye 0,0,3",
                          " --texture none.png"}) {
    const CliRun b = uvtk(bench + bad), r = uvtk(render + bad);
    EXPECT_EQ(b.status, r.status) << bad << "\n" << b.err << r.err;
    EXPECT_NE(b.status, 0) << bad;
    EXPECT_EQ(b.err, r.err) << bad;
    EXPECT_FALSE(fs::exists(path("b.json"))) << bad;
  }
  const CliRun both = uvtk(bench + " --filter linear --filters nearest,linear");
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("--filter and --filters exclude each other"), std::string::npos) << both.err;
}

TEST_F(BenchCli, RefusesUnknownChoicesBeforeMeasuringAnything) {
  const CliRun run = uvtk("bench --mesh " + path("sphere.obj") + " --precision quad --json " + path("b.json"));
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("--precision: expected a list of double, float, found \"quad\""), std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(path("b.json")));
  EXPECT_EQ(uvtk("bench --projector cube --mesh " + path("sphere.obj")).status, 2);
}

// Round-trip digits for the hand-written OFF file.
std::string offNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// The end-to-end row maps every input format; OFF and STL hold no UVs, so their map is written as OBJ.
TEST_F(BenchCli, TheEndToEndMapTakesEveryInputFormat) {
  for (const char* format : {"off", "stl", "ply"}) {
    const std::string mesh = path(std::string("sphere.") + format);
    const Mesh sphere = meshes::latLongSphere(64, 32);
    if (std::string(format) == "ply") {
      ASSERT_EQ(uvtk("map " + path("sphere.obj") + " --projector plane -o " + mesh).status, 0);
    } else if (std::string(format) == "stl") {
      io::writeMesh(mesh, sphere, nullptr);
    } else {
      std::string off = "OFF\n" + std::to_string(sphere.positions.size()) + " " + std::to_string(sphere.faceCount()) + " 0\n";
      for (const Vec3& p : sphere.positions) off += offNumber(p.x()) + " " + offNumber(p.y()) + " " + offNumber(p.z()) + "\n";
      for (const Triangle& t : sphere.triangles)
        off += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
      writeText(std::string("sphere.") + format, off);
    }
    const CliRun run = uvtk("bench --mesh " + mesh + " --projector plane --precision double --math exact" +
                            " --min-time 0.01 --no-peers --threads 1 --json " + path("b.json"));
    ASSERT_EQ(run.status, 0) << format << ": " << run.err;
    std::size_t rows = 0;
    const nlohmann::json b = readJson("b.json");
    for (const nlohmann::json& r : b["records"])
      if (r["section"] == "end-to-end") {
        ++rows;
        EXPECT_EQ(r["mesh"], mesh);
      }
    EXPECT_EQ(rows, 1u) << format;
  }
}

TEST_F(BenchCli, MapInFloatWithFastMathStaysWithinTheBoundOfTheDoubleResult) {
  ASSERT_EQ(uvtk("map " + path("sphere.obj") + " -o " + path("d.obj")).status, 0);
  ASSERT_EQ(uvtk("map " + path("sphere.obj") + " --precision float --math fast -o " + path("f.obj") + " --json " +
                 path("f.json") + "")
                .status,
            0);
  const Mesh d = io::readMesh(path("d.obj")).mesh, f = io::readMesh(path("f.obj")).mesh;
  ASSERT_EQ(d.texcoords.size(), f.texcoords.size());
  double worst = 0.0, differing = 0;
  for (std::size_t i = 0; i < d.texcoords.size(); ++i) {
    worst = std::max(worst, (d.texcoords[i] - f.texcoords[i]).cwiseAbs().maxCoeff());
    differing += d.texcoords[i] != f.texcoords[i];
  }
  EXPECT_LT(worst, 4 * 0x1p-24);  // a few float ulps of values in [0, 1]
  EXPECT_GT(differing, 0);        // the float path really ran
  const nlohmann::json j = readJson("f.json");
  EXPECT_EQ(j["options"]["precision"], "float");
  EXPECT_EQ(j["options"]["math"], "fast");
}

TEST_F(BenchCli, RenderTakesSamplesPerPixelAndRefusesNonSquares) {
  const CliRun ok = uvtk("render " + path("sphere.obj") + " --projector sphere --size 32x32 --spp 4 -o " +
                         path("r.png") + " --json " + path("r.json"));
  ASSERT_EQ(ok.status, 0) << ok.err;
  EXPECT_EQ(readJson("r.json")["spp"], 4);
  const CliRun bad = uvtk("render " + path("sphere.obj") + " --projector sphere --spp 5 -o " + path("s.png"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--spp: expected a square number"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(path("s.png")));
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
