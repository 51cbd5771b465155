// `uvtk bench` and the speed-accuracy options of the mapping commands as a user runs them: every
// configuration measured with the documented keys, errors within their bounds, clear refusals.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "apps/cli_test.h"
#include "io/image_io.h"
#include "io/mesh_reader.h"
#include "io/obj_writer.h"
#include "meshes/generators.h"

namespace uvtk {
namespace {

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
  const nlohmann::json& records = j["records"];
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

TEST_F(BenchCli, RefusesUnknownChoicesBeforeMeasuringAnything) {
  const CliRun run = uvtk("bench --mesh " + path("sphere.obj") + " --precision quad --json " + path("b.json"));
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("--precision: expected a list of double, float, found \"quad\""), std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(path("b.json")));
  EXPECT_EQ(uvtk("bench --projector cube --mesh " + path("sphere.obj")).status, 2);
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

}  // namespace
}  // namespace uvtk
