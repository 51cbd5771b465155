// The GPU's seam mip line as a user meets it: `uvtk render --derivatives` draws it, `--view mipline`
// counts it in the JSON with where it is, `--seam-fix` removes it, and a report page with the
// mipline view warns with the mip_line rule.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "apps/cli_test.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

const std::string kSphere = std::string(UVTK_MESHES_DIR) + "/sphere_latlong.obj";
// The sphere projector per pixel, seen beside its seam (towards +x) so that the seam crosses quads.
const std::string kSeamView = kSphere + " --projector sphere --uv per-pixel --view-dir 1,0.3,0.2 --size 200x200";

class MipLineCli : public CliTest {
 protected:
  nlohmann::json readJson(const std::string& name) const { return nlohmann::json::parse(readText(path(name))); }
};

TEST_F(MipLineCli, RenderCountsTheLineAndTheFixesRemoveIt) {
  ASSERT_EQ(uvtk("render " + kSeamView + " --view mipline -o " + path("m.png") + " --json " + path("m.json")).status, 0);
  const nlohmann::json line = readJson("m.json")["mip_line"];
  EXPECT_EQ(line["derivatives"], "quad-coarse");
  EXPECT_EQ(line["per_pixel"], true);
  EXPECT_GT(line["where"]["seam"].get<int>(), 30);
  EXPECT_EQ(line["pixels"].get<int>(), line["where"]["seam"].get<int>() + line["where"]["pole"].get<int>() +
                                           line["where"]["cube_edge"].get<int>() + line["where"]["other"].get<int>());
  EXPECT_DOUBLE_EQ(line["share"].get<double>(), line["pixels"].get<double>() / line["covered_pixels"].get<double>());

  for (const std::string fix : {"grad", "tarini"}) {
    ASSERT_EQ(uvtk("render " + kSeamView + " --view mipline --derivatives quad-fine --seam-fix " + fix + " -o " +
                   path("f.png") + " --json " + path("f.json"))
                  .status,
              0);
    const nlohmann::json fixed = readJson("f.json")["mip_line"];
    EXPECT_EQ(fixed["seam_fix"], fix);
    EXPECT_EQ(fixed["derivatives"], "quad-fine");
    EXPECT_EQ(fixed["where"]["seam"], 0) << fix;
  }
}

TEST_F(MipLineCli, RenderWithQuadDerivativesDrawsWhatItRecords) {
  ASSERT_EQ(uvtk("render " + kSeamView + " --texture checker:256:32 --filter linear_mipmap_linear --derivatives "
                 "quad-coarse -o " + path("gpu.png") + " --json " + path("gpu.json"))
                .status,
            0);
  EXPECT_EQ(readJson("gpu.json")["derivatives"], "quad-coarse");
  EXPECT_EQ(readJson("gpu.json")["seam_fix"], "none");
  // Usage errors name the option: Tarini needs a per-pixel mapping; a bad mode.
  const CliRun corners = uvtk("render " + kSphere + " --projector sphere --derivatives quad-coarse --seam-fix tarini -o " + path("t.png"));
  EXPECT_EQ(corners.status, 2);
  EXPECT_NE(corners.err.find("Tarini"), std::string::npos) << corners.err;
  EXPECT_EQ(uvtk("render " + kSeamView + " --derivatives quad -o " + path("q.png")).status, 2);
}

TEST_F(MipLineCli, AReportWithTheMiplineViewWarnsWithTheRule) {
  const std::string report = "report " + kSphere + " --projector sphere --view-dir 1,0.3,0.2 --views checker,mipline ";
  ASSERT_EQ(uvtk(report + "--html " + path("r.html") + " --json " + path("r.json")).status, 0);
  const nlohmann::json r = readJson("r.json");
  ASSERT_TRUE(r.contains("mip_line"));
  EXPECT_GT(r["mip_line"]["where"]["seam"].get<int>(), 0);
  EXPECT_EQ(r["verdict"], "warn");
  bool found = false;
  for (const nlohmann::json& reason : r["reasons"])
    if (reason["code"] == "mip_line") {
      found = true;
      EXPECT_EQ(reason["severity"], "warn");
      EXPECT_DOUBLE_EQ(reason["value"].get<double>(), r["mip_line"]["share"].get<double>());
    }
  EXPECT_TRUE(found) << r["reasons"].dump();
  EXPECT_EQ(r["rule_values"]["mip_line"], r["mip_line"]["share"]);
  // The rule's threshold is the user's: off, the verdict is the mapping's alone; --fail-on warn fails.
  ASSERT_EQ(uvtk(report + "--json " + path("s.json") + " --html " + path("s.html") + " --warn-on mip_line=off").status, 0);
  EXPECT_FALSE(readJson("s.json").contains("reasons") && readJson("s.json")["reasons"].dump().find("mip_line") != std::string::npos);
  EXPECT_EQ(uvtk(report + "--html " + path("w.html") + " --fail-on warn").status, 1);
  // Without the view nothing is measured: no mip_line, the verdict as before.
  ASSERT_EQ(uvtk("report " + kSphere + " --projector sphere --json " + path("n.json")).status, 0);
  EXPECT_FALSE(readJson("n.json").contains("mip_line"));
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
