// Texel density as a user meets it: --texture-size W,H on report, compare and render's views, the
// texel_density record, `uvtk map --density D` (then `uvtk report` reads a mean of D), the density
// view, and clear errors with nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "apps/cli_test.h"
#include "io/obj_writer.h"
#include "meshes/generators.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

class DensityCli : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    io::writeObj(path("plane.obj"), meshes::planeGrid(6, 4, 3, 2), nullptr);
    // A height field over [0, 2] x [0, 1]: the plane projector gives it a density that varies.
    std::ofstream out(path("bumps.obj"));
    constexpr int n = 8;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const double x = 2.0 * i / n, y = double(j) / n;
        out << "v " << x << " " << y << " " << 0.4 * std::sin(3 * x) * std::cos(2 * y) << "\n";
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 2, d = a + n + 1;
        out << "f " << a << " " << b << " " << c << "\nf " << a << " " << c << " " << d << "\n";
      }
    std::ofstream(path("segment.obj")) << "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n";  // no face is ok
  }
  nlohmann::json json(const std::string& name) const { return nlohmann::json::parse(readText(path(name))); }
};

TEST_F(DensityCli, ReportWritesTheDensityInTheGivenTexture) {
  // The 3 x 2 plane fitted to the unit square: A_uv / A_3d = 1 / 6 on every face.
  const CliRun r =
      uvtk("report " + path("plane.obj") + " --projector plane --texture-size 512,256 --json " + path("r.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json d = json("r.json")["texel_density"];
  const double expected = std::sqrt(512.0 * 256.0 / 6.0);
  for (const char* key : {"mean", "p10", "p50", "p90", "p99", "min", "max"})
    EXPECT_NEAR(d[key].get<double>(), expected, 1e-12 * expected) << key;
  EXPECT_EQ(d["texture_size"], nlohmann::json::array({512, 256}));
  EXPECT_EQ(d["unit"], "texels per object unit");
  EXPECT_EQ(d["finite"], true);
  EXPECT_NEAR(d["spread"].get<double>(), 1.0, 1e-12);
  EXPECT_TRUE(d["histogram"].contains("edges"));
  EXPECT_EQ(json("r.json")["rule_values"]["density_spread"], d["spread"]);
  EXPECT_EQ(json("r.json")["thresholds"]["warn"]["density_spread"], 2.0);

  // N means N,N; the default is 1024,1024.
  ASSERT_EQ(uvtk("report " + path("plane.obj") + " --projector plane --texture-size 300 --json " + path("n.json")).status, 0);
  EXPECT_EQ(json("n.json")["texel_density"]["texture_size"], nlohmann::json::array({300, 300}));
  EXPECT_NEAR(json("n.json")["texel_density"]["mean"].get<double>(), 300.0 / std::sqrt(6.0), 1e-12 * 300);
  ASSERT_EQ(uvtk("report " + path("plane.obj") + " --projector plane --json " + path("d.json")).status, 0);
  EXPECT_EQ(json("d.json")["texel_density"]["texture_size"], nlohmann::json::array({1024, 1024}));
}

TEST_F(DensityCli, MapDensityScalesTheUvsSoThatReportReadsThatMean) {
  const CliRun m = uvtk("map " + path("bumps.obj") + " --projector plane --texture-size 2048,512 --density 300 -o " +
                        path("m.obj") + " --json " + path("m.json"));
  ASSERT_EQ(m.status, 0) << m.err;
  const nlohmann::json summary = json("m.json");
  EXPECT_EQ(summary["density_scale"]["density"], 300.0);
  const double factor = summary["density_scale"]["factor"].get<double>();
  EXPECT_GT(factor, 0.0);
  EXPECT_NEAR(summary["judgement"]["texel_density"]["mean"].get<double>(), 300.0, 300.0 * 1e-12);
  // The density varies over the bumps: only its mean is 300.
  EXPECT_LT(summary["judgement"]["texel_density"]["min"].get<double>(), 299.0);

  const CliRun r = uvtk("report " + path("m.obj") + " --texture-size 2048,512 --json " + path("r.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(json("r.json")["texel_density"]["mean"].get<double>(), 300.0, 300.0 * 1e-12);

  // Without --density the same mapping's mean is 300 / factor.
  ASSERT_EQ(uvtk("map " + path("bumps.obj") + " --projector plane --texture-size 2048,512 -o " + path("u.obj") +
                 " --json " + path("u.json"))
                .status,
            0);
  const double unscaled = json("u.json")["judgement"]["texel_density"]["mean"].get<double>();
  EXPECT_NEAR(unscaled * factor, 300.0, 300.0 * 1e-12);
  EXPECT_FALSE(json("u.json").contains("density_scale"));
}

TEST_F(DensityCli, BadTextureSizesAndDensitiesAreRefusedWithNothingWritten) {
  for (const char* size : {"abc", "0", "1024,", ",5", "5,5,5", "-4", "20000", "12x12", "1e3"}) {
    SCOPED_TRACE(size);
    const std::string option = std::string(" --texture-size '") + size + "'";
    CliRun r = uvtk("report " + path("plane.obj") + " --projector plane --json " + path("x.json") + option);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--texture-size: expected W,H or N"), std::string::npos) << r.err;
    EXPECT_EQ(uvtk("map " + path("plane.obj") + " --projector plane -o " + path("x.obj") + option).status, 2);
    EXPECT_EQ(uvtk("compare " + path("plane.obj") + " --no-baselines --json " + path("x.json") + option).status, 2);
    EXPECT_EQ(uvtk("render " + path("plane.obj") + " --projector plane --view density -o " + path("x.png") + option).status, 2);
  }
  for (const char* density : {"0", "-3", "inf", "nan"}) {
    SCOPED_TRACE(density);
    const CliRun r = uvtk("map " + path("plane.obj") + " --projector plane -o " + path("x.obj") + " --json " +
                          path("x.json") + " --density " + density);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--density: expected a positive number"), std::string::npos) << r.err;
  }
  // No ok face: nothing to scale (an input error), nothing written.
  const CliRun none = uvtk("map " + path("segment.obj") + " --projector plane -o " + path("x.obj") + " --json " +
                           path("x.json") + " --density 5");
  EXPECT_EQ(none.status, 3);
  EXPECT_NE(none.err.find("no face is ok"), std::string::npos) << none.err;
  EXPECT_FALSE(fs::exists(path("x.obj")));
  EXPECT_FALSE(fs::exists(path("x.json")));
  EXPECT_FALSE(fs::exists(path("x.png")));
}

TEST_F(DensityCli, CompareRecordsAndTheDensityViewReadTheTextureSize) {
  ASSERT_EQ(uvtk("compare " + path("plane.obj") + " --no-baselines --texture-size 256,128 --json " + path("c.json")).status, 0);
  const nlohmann::json compared = json("c.json");  // a range-for over a temporary's member would dangle
  for (const nlohmann::json& record : compared["ranking"])
    EXPECT_EQ(record["texel_density"]["texture_size"], nlohmann::json::array({256, 128})) << record["name"];

  const CliRun r = uvtk("render " + path("plane.obj") + " --projector plane --view density --texture-size 512 -o " +
                        path("d.png") + " --json " + path("d.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("d.png")));
  // The legend in texels per unit: the flat density 512 / sqrt(6) = 209 in the middle of the bar.
  const nlohmann::json legend = json("d.json")["legends"]["density"];
  EXPECT_EQ(legend[0], "Texel density, texels per unit");
  EXPECT_EQ(legend[1], "of a 512 × 512 texture");
  EXPECT_EQ(legend[4], "209");

  const CliRun page = uvtk("report " + path("plane.obj") + " --projector plane --views density,layout --html " +
                           path("p.html") + " --json " + path("p.json"));
  ASSERT_EQ(page.status, 0) << page.err;
  EXPECT_TRUE(fs::exists(path("p.html")));
  EXPECT_EQ(json("p.json")["views"], nlohmann::json::array({"density", "layout"}));
}

TEST_F(DensityCli, TheSpreadRuleIsSetByName) {
  // Two unit squares with their own UVs: one on a UV square of side 1 (1024 texels per unit), one
  // of side 1/4 (256): a spread of 4, above the default warn threshold of 2, and nothing else wrong.
  std::ofstream(path("halves.obj")) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\nv 3 1 0\nv 2 1 0\n"
                                       "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 2 0\nvt 2.25 0\nvt 2.25 0.25\nvt 2 0.25\n"
                                       "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\nf 5/5 6/6 7/7\nf 5/5 7/7 8/8\n";
  const std::string report = "report " + path("halves.obj") + " --json " + path("s.json");
  ASSERT_EQ(uvtk(report).status, 0);
  EXPECT_DOUBLE_EQ(json("s.json")["texel_density"]["spread"].get<double>(), 4.0);
  EXPECT_EQ(json("s.json")["verdict"], "warn");
  ASSERT_EQ(json("s.json")["reasons"].size(), 1u);
  EXPECT_EQ(json("s.json")["reasons"][0]["code"], "density_spread");
  EXPECT_EQ(json("s.json")["reasons"][0]["faces"], 4);
  ASSERT_EQ(uvtk(report + " --warn-on density_spread=off").status, 0);
  EXPECT_EQ(json("s.json")["verdict"], "pass");
  EXPECT_EQ(uvtk(report + " --fail-on density_spread=3.5 --fail-on fail").status, 1);
  EXPECT_EQ(json("s.json")["verdict"], "fail");
  EXPECT_EQ(uvtk(report + " --fail-on density_spread=4 --fail-on fail").status, 0);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
