// The verdict as a user meets it: `uvtk map` and `report` with --fail-on and --warn-on, and every
// number in every view's legend read back from `uvtk render --json` and compared with the JSON
// of the same mapping (`uvtk map --json`), on meshes like real ones.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>

#include "apps/cli_test.h"
#include "io/obj_writer.h"
#include "meshes/generators.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

class VerdictCli : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    io::writeObj(path("torus.obj"), meshes::torus(48, 24, 1.0, 0.35), nullptr);
    io::writeObj(path("knot.obj"), meshes::torusKnot(2, 3, 96, 8), nullptr);
    io::writeObj(path("bone.obj"), meshes::bone(40, 12), nullptr);
    io::writeObj(path("blob.obj"), meshes::bumpyBlob(3), nullptr);
    io::writeObj(path("patch.obj"), meshes::scannedPatch(3), nullptr);
  }
  nlohmann::json json(const std::string& name) const { return nlohmann::json::parse(readText(path(name))); }
};

TEST_F(VerdictCli, ACylinderOnATorusFailsAndSaysWhyEverywhere) {
  const CliRun r = uvtk("map " + path("torus.obj") + " --projector cylinder -o " + path("t.obj") + " --json " +
                        path("t.json"));
  ASSERT_EQ(r.status, 0) << r.err;  // the default keeps exit 0
  const nlohmann::json j = json("t.json");
  EXPECT_EQ(j["verdict"], "fail");
  EXPECT_EQ(j["judgement"]["verdict"], "fail");
  ASSERT_FALSE(j["reasons"].empty());
  EXPECT_EQ(j["reasons"][0]["code"], "flipped_area");
  EXPECT_EQ(j["reasons"][0]["severity"], "fail");
  EXPECT_EQ(j["reasons"][0]["faces"], j["judgement"]["status_counts"]["flipped"]);
  EXPECT_NE(r.err.find("verdict fail: flipped_area"), std::string::npos) << r.err;

  const CliRun failing = uvtk("map " + path("torus.obj") + " --projector cylinder -o " + path("t.obj") + " --fail-on fail");
  EXPECT_EQ(failing.status, 1);
  EXPECT_NE(failing.err.find("the verdict is fail (--fail-on fail): exit 1"), std::string::npos) << failing.err;
  // Thresholds: with flips and overlap tolerated the same mapping only warns.
  const CliRun tolerated = uvtk("map " + path("torus.obj") + " --projector cylinder -o " + path("t.obj") +
                                " --fail-on fail --fail-on flipped_area=0.5,overlap=off --json " + path("w.json"));
  EXPECT_EQ(tolerated.status, 0) << tolerated.err;
  EXPECT_EQ(json("w.json")["verdict"], "warn");
  EXPECT_EQ(uvtk("map " + path("torus.obj") + " --projector cylinder -o " + path("t.obj") +
                 " --fail-on fail --fail-on flipped_area=0.5,overlap=off --fail-on warn")
                .status,
            2);
  const CliRun report = uvtk("report " + path("torus.obj") + " --projector cylinder --json " + path("r.json") +
                             " --fail-on warn");
  EXPECT_EQ(report.status, 1);
  EXPECT_EQ(json("r.json")["verdict"], "fail");
  EXPECT_EQ(json("r.json")["reasons"], j["reasons"]);
}

TEST_F(VerdictCli, BadThresholdsAreOneLineUsageErrorsAndWriteNothing) {
  for (const char* option : {"--fail-on flipped=1", "--fail-on overlap=-1", "--warn-on overlap", "--fail-on pass"}) {
    const CliRun r = uvtk("map " + path("torus.obj") + " --projector sphere -o " + path("x.obj") + " " + option);
    EXPECT_EQ(r.status, 2) << option;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(path("x.obj"))) << option;
  }
}

// The overlap raster follows the mesh unless one is asked: a plane projection of a 48 x 24 grid of
// quads fills its box with 2304 faces, at the floor of 256 (sqrt(16 x 2304) = 192), a 100 x 50
// one's 10,000 at sqrt(160000) = 400; --overlap-resolution N gives N.
TEST_F(VerdictCli, TheOverlapRasterFollowsTheMeshUnlessOneIsAsked) {
  io::writeObj(path("grid2k.obj"), meshes::planeGrid(48, 24, 2.0, 1.0), nullptr);
  io::writeObj(path("grid10k.obj"), meshes::planeGrid(100, 50, 2.0, 1.0), nullptr);
  const auto resolution = [&](const std::string& mesh, const std::string& options) {
    const CliRun r = uvtk("map " + path(mesh) + " --projector plane -o " + path("o.obj") + " --json " + path("o.json") +
                          " " + options);
    EXPECT_EQ(r.status, 0) << r.err;
    return json("o.json")["judgement"]["overlap"]["resolution"].get<int>();
  };
  EXPECT_EQ(resolution("grid2k.obj", ""), 256);
  EXPECT_EQ(resolution("grid10k.obj", ""), 400);
  EXPECT_EQ(resolution("grid10k.obj", "--overlap-resolution 1024"), 1024);
  EXPECT_EQ(resolution("grid10k.obj", "--overlap-resolution 100"), 100);
}

// The number after "label: " in a legend line, or -1.
double legendNumber(const std::vector<std::string>& lines, const std::string& label) {
  for (const std::string& line : lines)
    if (line.rfind(label + ": ", 0) == 0) return std::stod(line.substr(label.size() + 2));
  return -1.0;
}

TEST_F(VerdictCli, EveryCountInEveryLegendEqualsTheJsonOfTheSameMapping) {
  const std::string views = "stretch,linf,angle,area,seams,layout";
  const std::pair<const char*, const char*> cases[] = {
      {"knot.obj", "--projector cube --omap centroid --cube-layout cross"},
      {"bone.obj", "--projector cylinder --caps"},
      {"blob.obj", "--projector sphere"},
      {"patch.obj", "--projector plane --omap normal"},
      {"torus.obj", "--projector cylinder"},
      {"torus.obj", "--projector sphere --seam none"}};
  for (const auto& [mesh, projector] : cases) {
    SCOPED_TRACE(std::string(mesh) + " " + projector);
    ASSERT_EQ(uvtk("map " + path(mesh) + " " + projector + " -o " + path("m.obj") + " --json " + path("m.json")).status,
              0);
    const CliRun r = uvtk("render " + path(mesh) + " " + projector + " --view " + views + " --size 160x160 -o " +
                          path("v.png") + " --json " + path("v.json"));
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = json("m.json")["judgement"];
    const nlohmann::json legends = json("v.json")["legends"];
    const auto lines = [&](const char* view) { return legends[view].get<std::vector<std::string>>(); };
    const std::vector<std::string> seams = lines("seams");
    EXPECT_EQ(legendNumber(seams, "wrap seam edges"), j["seams"]["wrap_edges"].get<double>());
    EXPECT_EQ(legendNumber(seams, "cut edges"), j["seams"]["cut_edges"].get<double>());
    EXPECT_EQ(legendNumber(seams, "seam-straddling faces"), j["face_flags"]["seam_straddling"].get<double>());
    EXPECT_EQ(legendNumber(seams, "pole vertices"), j["poles"]["vertices"].get<double>());
    EXPECT_EQ(legendNumber(seams, "pole faces"), j["poles"]["faces"].get<double>());
    EXPECT_EQ(legendNumber(seams, "flipped faces"), j["status_counts"]["flipped"].get<double>());
    EXPECT_EQ(legendNumber(seams, "invalid faces"), j["status_counts"]["invalid"].get<double>());
    // The heatmaps list every status other than ok that the mapping has, with its count.
    for (const char* view : {"stretch", "linf", "angle", "area", "layout"}) {
      for (const auto& [status, count] : j["status_counts"].items()) {
        if (status == "ok") continue;
        const double shown = legendNumber(lines(view), status);
        EXPECT_EQ(shown, count.get<double>() > 0 ? count.get<double>() : -1.0) << view << " " << status;
      }
    }
    const std::vector<std::string> layout = lines("layout");
    EXPECT_EQ(legendNumber(layout, "wrap seam edges"), j["seams"]["wrap_edges"].get<double>());
    EXPECT_EQ(legendNumber(layout, "cut edges"), j["seams"]["cut_edges"].get<double>());
    EXPECT_EQ(legendNumber(layout, "faces overlapping"), j["face_flags"]["overlapping"].get<double>());
    std::smatch m;
    bool found = false;
    for (const std::string& line : layout)
      if (std::regex_search(line, m, std::regex(R"(^overlap: (\S+) % of (\d+) covered pixels \((\d+) x)"))) {
        found = true;
        EXPECT_NEAR(std::stod(m[1]), 100.0 * j["overlap_fraction"].get<double>(),
                    5e-3 * std::max(1.0, 100.0 * j["overlap_fraction"].get<double>()));
        EXPECT_EQ(std::stod(m[2]), j["overlap"]["covered_pixels"].get<double>());
        EXPECT_EQ(std::stoi(m[3]), j["overlap"]["resolution"].get<int>());
      }
    EXPECT_TRUE(found);
  }
}

TEST_F(VerdictCli, CompareRanksByVerdictThenByTheMeasureAndRunsBaselinesOnClosedMeshes) {
  for (const char* by : {"stretch_l2", "angle", "seam_length"}) {
    SCOPED_TRACE(by);
    const CliRun r = uvtk(std::string("compare ") + path("knot.obj") + " --by " + by + " --json " + path("c.json"));
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json ranking = json("c.json")["ranking"];
    const std::map<std::string, int> order = {{"pass", 0}, {"warn", 1}, {"fail", 2}};
    const auto key = [&](const nlohmann::json& row) {
      const std::string b = by;
      if (row["status_counts"]["ok"] == 0) return std::numeric_limits<double>::infinity();
      return b == "stretch_l2" ? row["stretch_l2"].get<double>()
             : b == "angle"    ? row["angle"]["mean"].get<double>()
                               : row["seams"]["length"].get<double>();
    };
    bool baselines = false;
    for (std::size_t i = 0; i < ranking.size(); ++i) {
      const nlohmann::json& row = ranking[i];
      baselines |= row["name"].get<std::string>().rfind("arap", 0) == 0;
      // No mapping with flipped faces or out-of-range corners passes.
      if (row["verdict"] == "pass") {
        EXPECT_EQ(row["status_counts"]["flipped"], 0) << row["name"];
        EXPECT_EQ(row["invalid_corners"]["out_of_range"], 0) << row["name"];
      }
      if (i == 0) continue;
      const nlohmann::json& before = ranking[i - 1];
      const int v0 = order.at(before["verdict"]), v1 = order.at(row["verdict"]);
      EXPECT_LE(v0, v1) << row["name"];
      if (v0 == v1) {
        EXPECT_LE(key(before), key(row)) << before["name"] << " before " << row["name"];
      }
    }
    EXPECT_TRUE(baselines);  // the knot is closed and knotted: cut along a cut graph
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
