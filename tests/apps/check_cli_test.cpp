// `uvtk check` as a user runs it: files written by `uvtk map` and `uvtk texgen` pass against their
// own mapping, a perturbed corner fails and is listed first, conventions, --against, the JSON
// record, the view, and the exit statuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "apps/cli_test.h"
#include "io/image_io.h"
#include "io/mesh_reader.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

using nlohmann::json;

class CheckCli : public CliTest {
 protected:
  // `uvtk ARGUMENTS` with stdout kept in out.txt.
  CliRun check(const std::string& arguments) const {
    return shell(std::string(UVTK_BINARY) + " check " + arguments + " > " + path("out.txt"));
  }
  std::string out() const { return readText(path("out.txt")); }
  json readJson(const std::string& name) const { return json::parse(readText(path(name))); }

  // The icosphere mapped by the sphere projector into A.obj, its summary in map.json.
  std::string mapIcosphere(const std::string& options = "--projector sphere", const std::string& name = "A.obj") {
    const CliRun r = uvtk("map " + kIcosphere + " " + options + " -o " + path(name) + " --json " + path("map.json"));
    EXPECT_EQ(r.status, 0) << r.err;
    return path(name);
  }

  static std::string lastLine(const std::string& text) {
    std::string trimmed = text;
    while (!trimmed.empty() && trimmed.back() == '\n') trimmed.pop_back();
    return trimmed.substr(trimmed.rfind('\n') + 1);
  }
};

// A copy of an OBJ with corner k of face f pointing at a new vt whose u is `du` larger; the corner's
// original (u, v) in `original`.
struct Perturbed {
  std::string text;
  double u = 0.0, v = 0.0;
};

Perturbed perturbCorner(const std::string& obj, std::size_t face, int k, double du) {
  std::istringstream in(obj);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::vector<std::string> vts;
  std::size_t firstFace = lines.size(), faces = 0;
  Perturbed out;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].rfind("vt ", 0) == 0) vts.push_back(lines[i]);
    if (lines[i].rfind("f ", 0) != 0) continue;
    firstFace = std::min(firstFace, i);
    if (faces++ != face) continue;
    std::istringstream tokens(lines[i].substr(2));
    std::vector<std::string> corners;
    for (std::string t; tokens >> t;) corners.push_back(t);
    const std::string& corner = corners.at(std::size_t(k));
    const std::size_t slash = corner.find('/');
    const int vt = std::stoi(corner.substr(slash + 1));
    std::istringstream original(vts.at(std::size_t(vt - 1)).substr(3));
    original >> out.u >> out.v;
    corners[std::size_t(k)] = corner.substr(0, slash) + "/" + std::to_string(vts.size() + 1);
    lines[i] = "f " + corners[0] + " " + corners[1] + " " + corners[2];
  }
  char vt[96];
  std::snprintf(vt, sizeof vt, "vt %.17g %.17g", out.u + du, out.v);
  lines.insert(lines.begin() + std::ptrdiff_t(firstFace), vt);
  for (const std::string& line : lines) out.text += line + "\n";
  return out;
}

TEST_F(CheckCli, AMappedFilePassesAgainstItsOwnMappingWithPolesApart) {
  const std::string a = mapIcosphere();
  const CliRun r = check(a + " --projector sphere --tolerance 1e-12 --json " + path("c.json"));
  ASSERT_EQ(r.status, 0) << r.err << out();
  EXPECT_EQ(lastLine(out()), "uvtk check: PASS") << out();
  EXPECT_NE(out().find("pole corners: "), std::string::npos) << out();
  const json map = readJson("map.json"), c = readJson("c.json");
  EXPECT_EQ(c.at("main").at("max"), 0.0);
  EXPECT_EQ(c.at("pole").at("max"), 0.0);
  EXPECT_EQ(c.at("pole").at("pole_vertices"), map.at("pole_vertex_list"));
  EXPECT_EQ(c.at("pole").at("pole_faces"), map.at("pole_faces"));
  // Every corner at the two pole vertices (6 faces each on this icosphere), and the pole faces' other corners.
  const std::vector<int> poles = map.at("pole_vertex_list");
  const Mesh mesh = io::readMesh(a).mesh;
  std::size_t poleCorners = 0;
  for (const Triangle& t : mesh.triangles)
    for (int v : t) poleCorners += std::count(poles.begin(), poles.end(), v);
  EXPECT_EQ(poleCorners, 12u);
  EXPECT_EQ(c.at("pole").at("pole_vertex_corners"), poleCorners);
  EXPECT_GT(c.at("pole").at("pole_face_corners").get<int>(), 0);
  EXPECT_EQ(c.at("main").at("corners").get<int>() + c.at("pole").at("corners").get<int>(), 3 * 1280);
  EXPECT_EQ(c.at("status"), "pass");
}

TEST_F(CheckCli, SeamCutIsAUsageError) {
  const std::string a = mapIcosphere();
  const CliRun r = check(a + " --projector sphere --seam cut");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--seam cut"), std::string::npos) << r.err;
}

TEST_F(CheckCli, APerturbedCornerFailsAndIsListedFirst) {
  const std::string a = mapIcosphere();
  const json map = readJson("map.json");
  const std::vector<int> poleFaces = map.at("pole_face_list");
  std::size_t face = 100;
  while (std::find(poleFaces.begin(), poleFaces.end(), int(face)) != poleFaces.end()) ++face;
  const Perturbed p = perturbCorner(readText(a), face, 1, 0.01);
  writeText("P.obj", p.text);

  const CliRun r = check(path("P.obj") + " --projector sphere --tolerance 1e-3 --json " + path("c.json"));
  EXPECT_EQ(r.status, 1) << r.err << out();
  EXPECT_EQ(lastLine(out()).rfind("uvtk check: FAIL (max error 0.01", 0), 0u) << out();
  EXPECT_NE(out().find("  1. face " + std::to_string(face) + " corner 1 "), std::string::npos) << out();
  const json c = readJson("c.json");
  EXPECT_EQ(c.at("status"), "fail");
  const json& worst = c.at("worst").at(0);
  EXPECT_EQ(worst.at("face"), face);
  EXPECT_EQ(worst.at("corner"), 1);
  EXPECT_EQ(worst.at("expected").at(0).get<double>(), p.u);
  EXPECT_EQ(worst.at("expected").at(1).get<double>(), p.v);
  EXPECT_EQ(worst.at("found").at(0).get<double>(), p.u + 0.01);
  EXPECT_EQ(worst.at("found").at(1).get<double>(), p.v);
  EXPECT_NEAR(worst.at("error").get<double>(), 0.01, 1e-15);
  EXPECT_EQ(c.at("worst").at(1).at("error"), 0.0);  // every other corner is exact
  EXPECT_NEAR(c.at("main").at("max").get<double>(), 0.01, 1e-15);
  EXPECT_EQ(c.at("main").at("p99"), 0.0);  // one corner in 3000 is above the 99th percentile

  // Without a tolerance the same file is only reported.
  ASSERT_EQ(check(path("P.obj") + " --projector sphere").status, 0);
  EXPECT_EQ(lastLine(out()), "uvtk check: no --tolerance given: report only");
}

TEST_F(CheckCli, TexelsAreUvTimesTheTextureSize) {
  const std::string a = mapIcosphere();
  writeText("P.obj", perturbCorner(readText(a), 0, 2, 0.01).text);
  ASSERT_EQ(check(path("P.obj") + " --texture-size 512 --worst 3 --json " + path("c.json")).status, 0) << out();
  const json c = readJson("c.json");
  EXPECT_EQ(c.at("texture_size"), 512);
  const double max = c.at("main").at("max");
  EXPECT_EQ(c.at("main").at("max_texels").get<double>(), max * 512);
  EXPECT_EQ(c.at("worst").at(0).at("error_texels").get<double>(), max * 512);
  EXPECT_EQ(c.at("worst").size(), 3u);
  char line[128];
  std::snprintf(line, sizeof line, "max error:  %.9g UV = %.9g texels", max, max * 512);
  EXPECT_NE(out().find(line), std::string::npos) << out();
}

TEST_F(CheckCli, AgainstAnIdenticalFileIsZeroAndAnotherTopologyIsAnInputError) {
  const std::string a = mapIcosphere();
  const std::string b = mapIcosphere("--projector sphere", "B.obj");
  CliRun r = check(a + " --against " + b + " --tolerance 0 --json " + path("c.json"));
  ASSERT_EQ(r.status, 0) << r.err << out();
  EXPECT_EQ(readJson("c.json").at("main").at("max"), 0.0);
  EXPECT_EQ(readJson("c.json").at("expected").at("source"), "file");
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;

  ASSERT_EQ(uvtk("map " + std::string(UVTK_MESHES_DIR) + "/cube.obj -o " + path("cube.obj")).status, 0);
  r = check(a + " --against " + path("cube.obj"));
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find(path("cube.obj") + ": error: expected the topology of " + a), std::string::npos) << r.err;

  r = check(a + " --against " + b + " --projector sphere");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--projector"), std::string::npos) << r.err;
}

TEST_F(CheckCli, AgainstComparesUModuloOneOnlyWhenAsked) {
  const std::string a = mapIcosphere("--projector sphere --pole none");
  const std::string n = mapIcosphere("--projector sphere --pole none --seam none", "N.obj");
  ASSERT_EQ(check(a + " --against " + n + " --json " + path("c.json")).status, 0);
  EXPECT_NEAR(readJson("c.json").at("main").at("max").get<double>(), 1.0, 1e-15);  // the shifted seam
  ASSERT_EQ(check(a + " --against " + n + " --wrap u --tolerance 1e-15 --json " + path("c.json")).status, 0) << out();
  EXPECT_LE(readJson("c.json").at("main").at("max").get<double>(), 1e-15);
}

TEST_F(CheckCli, AgainstWarnsWhenPositionsDiffer) {
  writeText("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
  writeText("b.obj", "v 0 0 0\nv 1 0 0\nv 0 1.5 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
  const CliRun r = check(path("a.obj") + " --against " + path("b.obj") + " --tolerance 0");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.err.find("warning: " + path("b.obj") + ": 1 vertex positions differ"), std::string::npos) << r.err;
}

TEST_F(CheckCli, JsonHoldsEverySection) {
  const std::string a = mapIcosphere();
  ASSERT_EQ(check(a + " --tolerance 1e-12 --json " + path("c.json")).status, 0);
  const json c = readJson("c.json");
  EXPECT_EQ(c.at("tool").at("name"), "uvtk");
  EXPECT_EQ(c.at("input").at("path"), a);
  EXPECT_EQ(c.at("input").at("faces"), 1280);
  EXPECT_EQ(c.at("expected").at("source"), "projector");
  EXPECT_EQ(c.at("expected").at("options").at("projector"), "sphere");
  EXPECT_EQ(c.at("expected").at("options").at("fit"), "bbox");
  EXPECT_EQ(c.at("period"), json::array({1.0, 0.0}));
  EXPECT_EQ(c.at("texture_size"), 1024);
  EXPECT_EQ(c.at("corners"), 3840);
  EXPECT_EQ(c.at("tolerance"), 1e-12);
  EXPECT_EQ(c.at("worst").size(), 10u);
  for (const char* key : {"face", "corner", "vertex", "position", "expected", "found", "error", "error_texels"})
    EXPECT_TRUE(c.at("worst").at(0).contains(key)) << key;
  for (const char* key : {"corners", "max", "p99", "mean", "max_texels", "p99_texels", "mean_texels"}) {
    EXPECT_TRUE(c.at("main").contains(key)) << key;
    EXPECT_TRUE(c.at("pole").contains(key)) << key;
  }
  EXPECT_EQ(c.at("pole").at("worst").size(), 10u);
  EXPECT_EQ(c.at("invalid").at("corners"), 0);
  EXPECT_EQ(c.at("invalid").at("list"), json::array());
  EXPECT_EQ(c.at("status"), "pass");
}

TEST_F(CheckCli, ViewWritesAPictureOfTheViewportWithTheLegendBelow) {
  const std::string a = mapIcosphere();
  const CliRun r = check(a + " --view " + path("v.png") + " --view-size 512x384");
  ASSERT_EQ(r.status, 0) << r.err;
  const Image image = io::readImage(path("v.png")).image;
  EXPECT_EQ(image.width, 512);  // the legend (a 400-pixel bar) is narrower than the viewport
  EXPECT_GT(image.height, 384);
  EXPECT_LT(image.height, 384 + 200);
  EXPECT_EQ(image.at(0, 0, 0), 0.0f);                                                      // background
  EXPECT_GT(image.at(256, 192, 0) + image.at(256, 192, 1) + image.at(256, 192, 2), 0.1f);  // the sphere

  EXPECT_EQ(check(a + " --view " + path("v.xyz")).status, 2);  // refused before any work
}

TEST_F(CheckCli, BlenderConventionPassesWithItselfAndIsAQuarterTurnOffTheDefault) {
  const std::string b = mapIcosphere("--projector sphere --convention blender", "B.obj");
  CliRun r = check(b + " --projector sphere --convention blender --tolerance 1e-12");
  ASSERT_EQ(r.status, 0) << r.err << out();
  // Blender's frame is ours turned by 270 degrees about z: u = ours + 0.25 modulo 1, v the same
  // (the sphere's angles do not depend on the fit's scale). Every main corner is a quarter turn off.
  r = check(b + " --projector sphere --tolerance 1e-12 --json " + path("c.json"));
  EXPECT_EQ(r.status, 1) << r.err << out();
  const json c = readJson("c.json");
  EXPECT_NEAR(c.at("main").at("max").get<double>(), 0.25, 1e-12);
  EXPECT_NEAR(c.at("main").at("mean").get<double>(), 0.25, 1e-12);
  EXPECT_NEAR(c.at("main").at("p99").get<double>(), 0.25, 1e-12);
  EXPECT_EQ(lastLine(out()).rfind("uvtk check: FAIL (max error 0.25", 0), 0u) << out();
}

TEST_F(CheckCli, TexgenSphereMapPassesAgainstItself) {
  const std::string view = " --eye 0,0,5 --center 0,0,0 --up 0,1,0";
  ASSERT_EQ(uvtk("texgen " + kIcosphere + " --mode sphere_map" + view + " -o " + path("T.obj")).status, 0);
  const CliRun r = check(path("T.obj") + " --texgen sphere_map" + view + " --tolerance 1e-12 --json " + path("c.json"));
  ASSERT_EQ(r.status, 0) << r.err << out();
  const json c = readJson("c.json");
  EXPECT_EQ(c.at("expected").at("source"), "texgen");
  EXPECT_EQ(c.at("period"), json::array({0.0, 0.0}));
  EXPECT_EQ(c.at("main").at("corners"), 3840);
  EXPECT_EQ(c.at("main").at("max"), 0.0);
  // Another eye gives other (s, t).
  EXPECT_EQ(
      check(path("T.obj") + " --texgen sphere_map --eye 0,5,0 --center 0,0,0 --up 0,0,1 --tolerance 1e-12").status, 1);
}

TEST_F(CheckCli, AFileWithoutVtIsAnInputError) {
  const CliRun r = check(kIcosphere);
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(
      r.err.find(kIcosphere + ": error: expected texture coordinates (vt) on every face corner, found none on face 0"),
      std::string::npos)
      << r.err;
}

TEST_F(CheckCli, PartialListsCornersWithoutVtAsInvalid) {
  writeText("q.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\nf 2 4 3\n");
  CliRun r = check(path("q.obj") + " --projector plane");
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("found none on face 1"), std::string::npos) << r.err;
  r = check(path("q.obj") + " --projector plane --partial --tolerance 1e-12 --json " + path("c.json"));
  ASSERT_EQ(r.status, 0) << r.err << out();
  const json c = readJson("c.json");
  EXPECT_EQ(c.at("main").at("corners"), 3);
  EXPECT_EQ(c.at("main").at("max"), 0.0);  // the plane's fit maps the unit square onto itself
  EXPECT_EQ(c.at("invalid").at("corners"), 3);
  EXPECT_EQ(c.at("invalid").at("no_vt"), 3);
  EXPECT_EQ(c.at("invalid").at("list").at(0).at("face"), 1);
  EXPECT_EQ(c.at("invalid").at("list").at(0).at("reason"), "no vt in the file");
}

TEST_F(CheckCli, CornersWhereTheMappingHasNoValueAreListedApart) {
  // Central rays onto the plane miss it from the lower half of the sphere.
  const std::string a = mapIcosphere("--projector plane --omap centroid");
  const std::size_t invalidVertices = readJson("map.json").at("invalid_vertices");
  ASSERT_GT(invalidVertices, 0u);
  const CliRun r = check(a + " --projector plane --omap centroid --tolerance 1e-12 --json " + path("c.json") +
                         " --view " + path("v.png"));
  ASSERT_EQ(r.status, 0) << r.err << out();
  const json c = readJson("c.json");
  const std::size_t invalid = c.at("invalid").at("corners");
  EXPECT_GT(invalid, 0u);
  EXPECT_EQ(c.at("invalid").at("no_reference_value"), invalid);
  EXPECT_EQ(c.at("invalid").at("list").size(), invalid);
  EXPECT_EQ(c.at("main").at("corners").get<std::size_t>() + invalid, 3840u);
  EXPECT_EQ(c.at("main").at("max"), 0.0);
  EXPECT_NE(out().find("invalid corners: " + std::to_string(invalid)), std::string::npos) << out();
}

TEST_F(CheckCli, OptionsAreCheckedBeforeAnyWork) {
  const std::string a = mapIcosphere();
  EXPECT_EQ(check(a + " --tolerance -1").status, 2);
  EXPECT_EQ(check(a + " --texture-size 0").status, 2);
  EXPECT_EQ(check(a + " --wrap u").status, 2);  // --wrap goes with --against
  EXPECT_EQ(check(a + " --against " + a + " --wrap v").status, 2);
  EXPECT_EQ(check(path("missing.obj") + " --projector sphere").status, 3);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
