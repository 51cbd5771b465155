// `uvtk report`, `uvtk compare`, `uvtk render --view` and `--seam-place` as a user runs them:
// the JSON keys and values of known layouts, a self-contained HTML page, the ranking, and clear
// errors with nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <nlohmann/json.hpp>
#include <regex>

#include "apps/cli_test.h"
#include "io/image_io.h"
#include "io/obj_writer.h"
#include "meshes/generators.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

class ReportCli : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    io::writeObj(path("plane.obj"), meshes::planeGrid(6, 4, 3, 2), nullptr);
    io::writeObj(path("sphere.obj"), meshes::latLongSphere(24, 12), nullptr);
    io::writeObj(path("tube.obj"), meshes::cylinder(24, 4, 1.0, 2.0, false), nullptr);
  }
  nlohmann::json json(const std::string& name) const { return nlohmann::json::parse(readText(path(name))); }
  // The first line a command prints on stdout.
  static std::string firstLine(const std::string& command) {
    std::FILE* pipe = ::popen(command.c_str(), "r");
    char line[512] = {};
    if (pipe && std::fgets(line, sizeof line, pipe) == nullptr) line[0] = 0;
    if (pipe) ::pclose(pipe);
    return line;
  }
};

TEST_F(ReportCli, APlanarProjectionOfAPlaneIsAnIsometryWithNothingWrong) {
  const CliRun r = uvtk("report " + path("plane.obj") + " --projector plane --json " + path("r.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = json("r.json");
  EXPECT_EQ(j["vertices"], 35);
  EXPECT_EQ(j["faces"], 48);
  // The fit scales x and y differently (3 x 2 to the unit square): a uniform scale would be exact,
  // this one stretches by sqrt(3/2) one way and compresses the other.
  const double a = std::sqrt(1.5);
  EXPECT_NEAR(j["stretch_l2"].get<double>(), std::sqrt((a * a + 1 / (a * a)) / 2), 1e-12);
  EXPECT_NEAR(j["stretch_linf"].get<double>(), a, 1e-12);
  EXPECT_NEAR(j["angle"]["mean"].get<double>(), 1.5, 1e-12);
  EXPECT_NEAR(j["angle"]["p99"].get<double>(), 1.5, 1e-12);
  EXPECT_NEAR(j["area"]["max"].get<double>(), 0.0, 1e-12);
  for (const char* key : {"mean", "p50", "p90", "p99", "max"}) {
    EXPECT_TRUE(j["angle"].contains(key)) << key;
    EXPECT_TRUE(j["area"].contains(key)) << key;
  }
  EXPECT_EQ(j["status_counts"]["ok"], 48);
  for (const char* status : {"zero_area_3d", "zero_area_uv", "flipped", "backfacing", "invalid", "pole_face"})
    EXPECT_EQ(j["status_counts"][status], 0) << status;
  EXPECT_EQ(j["seams"]["wrap_edges"], 0);
  EXPECT_EQ(j["seams"]["cut_edges"], 0);
  EXPECT_EQ(j["seams"]["length"], 0.0);
  EXPECT_EQ(j["poles"]["vertices"], 0);
  EXPECT_EQ(j["poles"]["faces"], 0);
  EXPECT_NEAR(j["uv_bounds"]["min"][0].get<double>(), 0.0, 1e-15);
  EXPECT_NEAR(j["uv_bounds"]["max"][1].get<double>(), 1.0, 1e-15);
  EXPECT_EQ(j["overlap_fraction"], 0.0);
  EXPECT_EQ(j["options"]["projector"], "plane");
  EXPECT_EQ(j["tool"]["name"], "uvtk");
  // The checksum is the file's SHA-256, as sha256sum computes it.
  const std::string sum = firstLine("sha256sum " + path("plane.obj"));
  EXPECT_EQ(j["input"]["sha256"], sum.substr(0, 64));
}

TEST_F(ReportCli, TheFilesOwnUvsMeasureAsTheProjectorThatWroteThem) {
  ASSERT_EQ(uvtk("map " + path("tube.obj") + " --projector cylinder -o " + path("mapped.obj")).status, 0);
  ASSERT_EQ(uvtk("report " + path("mapped.obj") + " --json " + path("file.json")).status, 0);
  ASSERT_EQ(uvtk("report " + path("tube.obj") + " --projector cylinder --json " + path("map.json")).status, 0);
  const nlohmann::json file = json("file.json"), mapped = json("map.json");
  EXPECT_EQ(file["texcoords"], "file");
  EXPECT_EQ(mapped["texcoords"], "projector");
  // An open tube has no poles, so the stored UVs (17 digits) measure as the mapping that wrote them.
  EXPECT_NEAR(file["stretch_l2"].get<double>(), mapped["stretch_l2"].get<double>(), 1e-9);
  EXPECT_NEAR(file["angle"]["p90"].get<double>(), mapped["angle"]["p90"].get<double>(), 1e-9);
  EXPECT_EQ(file["seams"]["wrap_edges"], mapped["seams"]["wrap_edges"]);
  EXPECT_GT(file["seams"]["wrap_edges"].get<int>(), 0);
  EXPECT_EQ(file["status_counts"], mapped["status_counts"]);
}

TEST_F(ReportCli, TheSphereProjectorReportsItsPolesAndWrapSeam) {
  const CliRun r = uvtk("report " + path("sphere.obj") + " --projector sphere --json " + path("r.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = json("r.json");
  EXPECT_EQ(j["poles"]["vertices"], 2);
  EXPECT_EQ(j["poles"]["faces"], 48);  // the two fans of 24 triangles
  EXPECT_EQ(j["status_counts"]["pole_face"], 48);
  EXPECT_EQ(j["seams"]["cut_edges"], 0);
  // The seam meridian from pole to pole: 12 edges (at the two pole edges only the ring end compares).
  EXPECT_EQ(j["seams"]["wrap_edges"], 12);
  EXPECT_NEAR(j["uv_bounds"]["max"][0].get<double>(), 1.0, 1e-12);
  // Compressed towards the poles (r > 1: log2 r > 0), stretched at the equator.
  EXPECT_GT(j["area"]["max"].get<double>(), 0.5);
  EXPECT_LT(j["area"]["min"].get<double>(), 0.0);
}

TEST_F(ReportCli, TheHtmlPageIsSelfContainedWithEveryView) {
  const CliRun r = uvtk("report " + path("sphere.obj") + " --projector sphere --size 64x64 --html " + path("r.html") +
                        " --views checker,stretch,area,seams,uverror,layout");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string html = readText(path("r.html"));
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  for (const char* view : {"checker", "stretch", "area", "seams", "uverror", "layout"})
    EXPECT_NE(html.find("alt=\"" + std::string(view) + " view\""), std::string::npos) << view;
  // Every picture is embedded; nothing is fetched from elsewhere (a plain search: std::regex
  // recurses per character and overflows the stack on a page of megabytes).
  std::size_t pictures = 0;
  for (std::size_t at = html.find("<img "); at != std::string::npos; at = html.find("<img ", at + 1), ++pictures)
    EXPECT_EQ(html.find(" src=\"data:image/png;base64,", at), html.find(" src=\"", at));
  EXPECT_EQ(pictures, 6u);
  EXPECT_EQ(html.find("href=\"http"), std::string::npos);
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_NE(html.find("<svg"), std::string::npos);  // the histograms
  EXPECT_NE(html.find("stretch_l2"), std::string::npos);
  // The 3D view with its scripts inlined; --view3d-faces 0 leaves it out.
  EXPECT_NE(html.find("<div class=\"view3d\">"), std::string::npos);
  EXPECT_NE(html.find("OrbitControls"), std::string::npos);
  ASSERT_EQ(uvtk("report " + path("sphere.obj") + " --projector sphere --size 64x64 --html " + path("r.html") +
                 " --view3d-faces 0").status, 0);
  const std::string without = readText(path("r.html"));
  EXPECT_EQ(without.find("<div class=\"view3d\">"), std::string::npos);
  EXPECT_EQ(without.find("<script"), std::string::npos);
}

TEST_F(ReportCli, BadArgumentsAreClearErrorsAndWriteNothing) {
  // Without --json or --html a report is a summary on stdout (FirstMinutes in cli_manners_test.cpp).
  CliRun r = uvtk("report " + path("sphere.obj") + " --projector sphere");
  EXPECT_EQ(r.status, 0) << r.err;
  r = uvtk("report " + path("sphere.obj") + " --projector sphere --views stretch,wobble --html " + path("r.html"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("wobble"), std::string::npos) << r.err;
  r = uvtk("report " + path("sphere.obj") + " --json " + path("r.json"));  // no vt, no projector
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("no texture coordinates"), std::string::npos) << r.err;
  r = uvtk("report " + path("missing.obj") + " --projector sphere --json " + path("r.json"));
  EXPECT_EQ(r.status, 3);
  EXPECT_FALSE(fs::exists(path("r.json")));
  EXPECT_FALSE(fs::exists(path("r.html")));
}

// A mesh of radius 1.5e308 has no camera (its eye would lie beyond the largest double): every
// command that draws it says so on one line naming the file, as an input error, and writes nothing.
TEST_F(ReportCli, AMeshTooLargeToFrameIsAnInputErrorNamingItsFile) {
  Mesh huge = meshes::latLongSphere(8, 4);
  for (Vec3& p : huge.positions) p *= 1.5e308;
  const std::string mesh = path("huge.obj");
  io::writeObj(mesh, huge, nullptr);
  for (const std::string& command :
       {"report " + mesh + " --projector sphere --html " + path("r.html") + " --json " + path("r.json"),
        "compare " + mesh + " --sheet " + path("c.png") + " --json " + path("c.json") + " --no-baselines",
        "render " + mesh + " --projector sphere -o " + path("v.png")}) {
    const CliRun r = uvtk(command + " -q");
    EXPECT_EQ(r.status, 3) << command << "\n" << r.err;
    EXPECT_EQ(r.err.rfind(mesh + ": error: the mesh (bounding sphere of radius ", 0), 0u) << command << "\n" << r.err;
    EXPECT_NE(r.err.find("too large for a camera to frame"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  for (const char* name : {"r.html", "r.json", "c.png", "c.json", "v.png"}) EXPECT_FALSE(fs::exists(path(name))) << name;
}

TEST_F(ReportCli, SeamPlaceAutoMovesTheSeamOffAnOpenHalfCylinder) {
  // Half a cylinder facing +x: the default seam at +x runs down its middle.
  std::string obj;
  for (int i = 0; i <= 8; ++i) {
    const double a = (-90.0 + 22.5 * i) * M_PI / 180.0;
    obj += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
    obj += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 1\n";
  }
  for (int i = 0; i < 8; ++i) {
    const int b = 2 * i + 1;
    obj += "f " + std::to_string(b) + " " + std::to_string(b + 2) + " " + std::to_string(b + 3) + "\n";
    obj += "f " + std::to_string(b) + " " + std::to_string(b + 3) + " " + std::to_string(b + 1) + "\n";
  }
  writeText("half.obj", obj);
  const CliRun r = uvtk("map " + path("half.obj") + " --projector cylinder --fit none --seam-place auto -o " +
                        path("out.obj") + " --json " + path("m.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = json("m.json");
  EXPECT_EQ(j["seam_placement"]["faces_crossed_before"], 2);
  EXPECT_EQ(j["seam_placement"]["faces_crossed"], 0);
  EXPECT_EQ(j["straddling_faces"], 0);
  EXPECT_NE(r.err.find("seam placed at"), std::string::npos) << r.err;
  EXPECT_EQ(uvtk("map " + path("half.obj") + " --projector plane --seam-place auto -o " + path("p.obj")).status, 2);

  // One seam rule (core/seam_edges.h): the placement's seam length is the judgement's, with and without a cut.
  for (const std::string seam : {"shift", "cut"}) {
    ASSERT_EQ(uvtk("map " + path("sphere.obj") + " --projector cylinder --fit pca --seam-place auto --seam " + seam +
                   " -q -o " + path("s.obj") + " --json " + path("s.json")).status, 0);
    const nlohmann::json s = json("s.json");
    EXPECT_GT(s["judgement"]["seams"]["length"].get<double>(), 0.0) << seam;
    EXPECT_EQ(s["seam_placement"]["seam_length"], s["judgement"]["seams"]["length"]) << seam;
  }
}

TEST_F(ReportCli, CompareRanksAnIsometricProjectionFirstAndIncludesTheBaselines) {
  const CliRun r = uvtk("compare " + path("plane.obj") + " --json " + path("c.json") + " --sheet " + path("c.png") +
                        " --top 3 --tile-size 48");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = json("c.json");
  EXPECT_EQ(j["rank_by"], "stretch_l2");
  const nlohmann::json& ranking = j["ranking"];
  ASSERT_GT(ranking.size(), 40u);
  // A flat grid: the planar projection along z is an isometry up to scale; so are LSCM and ARAP.
  EXPECT_NEAR(ranking[0]["stretch_l2"].get<double>(), 1.0, 1e-9);
  EXPECT_EQ(ranking[0]["verdict"], "pass");
  for (std::size_t i = 1; i < ranking.size(); ++i) {
    if (ranking[i]["verdict"] != "pass") break;
    EXPECT_LE(ranking[i - 1]["stretch_l2"].get<double>(), ranking[i]["stretch_l2"].get<double>()) << i;
  }
  bool lscm = false, arap = false;
  for (const nlohmann::json& c : ranking) {
    lscm = lscm || c["name"] == "lscm";
    arap = arap || c["name"] == "arap";
    if (c["name"] == "lscm") {
      EXPECT_NEAR(c["stretch_l2"].get<double>(), 1.0, 1e-6);  // a flat disk flattens exactly
    }
  }
  EXPECT_TRUE(lscm);
  EXPECT_TRUE(arap);
  // Three candidates, a checker and a stretch picture each, four pictures per row.
  const io::ImageFile sheet = io::readImage(path("c.png"));
  EXPECT_GT(sheet.image.width, 4 * 48);
  EXPECT_GT(sheet.image.height, 2 * 48);
}

TEST_F(ReportCli, CompareRunsTheBaselinesPerChartAndWritesTheBestAsMapWould) {
  // A closed sphere is no disk: LSCM and ARAP run on the atlas's charts and pass, none skipped.
  const CliRun r = uvtk("compare " + path("sphere.obj") + " --json " + path("c.json") + " --write-best " +
                        path("best.obj"));
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = json("c.json");
  EXPECT_TRUE(j["skipped"].empty()) << j["skipped"].dump();
  std::set<std::string> passing;
  for (const nlohmann::json& c : j["ranking"])
    if (c["verdict"] == "pass") passing.insert(c["name"]);
  for (const char* name : {"atlas", "lscm", "arap"}) EXPECT_TRUE(passing.count(name)) << name;
  // The best as written is what uvtk map writes with the options the record gives, less the header.
  const std::string options = j["best"]["map_options"];
  EXPECT_EQ(j["best"]["name"], j["ranking"][0]["name"]);
  EXPECT_NE(r.err.find("wrote " + path("best.obj")), std::string::npos) << r.err;
  ASSERT_EQ(uvtk("map " + path("sphere.obj") + " -o " + path("again.obj") + " " + options).status, 0) << options;
  const auto body = [](const std::string& file) {
    std::ifstream in(file);
    std::string first, rest((std::istreambuf_iterator<char>(std::getline(in, first))), std::istreambuf_iterator<char>());
    return rest;
  };
  EXPECT_EQ(body(path("best.obj")), body(path("again.obj")));
}

TEST_F(ReportCli, RenderDrawsSeveralViewsIntoAContactSheet) {
  CliRun r =
      uvtk("render " + path("sphere.obj") + " --projector sphere --size 80x60 --view stretch -o " + path("s.png"));
  ASSERT_EQ(r.status, 0) << r.err;
  const io::ImageFile single = io::readImage(path("s.png"));
  EXPECT_GE(single.image.width, 80);  // the camera's picture, and the legend below it
  EXPECT_GT(single.image.height, 60);
  r = uvtk("render " + path("sphere.obj") + " --projector sphere --size 80x60 --view checker,seams,uverror -o " +
           path("sheet.png") + " --json " + path("v.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_GT(io::readImage(path("sheet.png")).image.width, 3 * 80);
  const nlohmann::json j = json("v.json");
  EXPECT_GT(j["uverror_texels"]["max"].get<double>(), 0.0);
  // The file's UVs have no exact mapping to compare with.
  ASSERT_EQ(uvtk("map " + path("sphere.obj") + " -o " + path("m.obj")).status, 0);
  r = uvtk("render " + path("m.obj") + " --view uverror -o " + path("e.png"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("uverror"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("e.png")));
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
