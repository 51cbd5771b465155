// `uvtk run`, `uvtk run --plan` and `uvtk schema` as a user runs them: the plan holds only what
// the outputs need, a mapping shared by outputs is computed once, an invalid scene is refused with
// its JSON path before anything is written, a failing mesh does not stop the others, and the
// bundled demo scene writes its gallery.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "apps/cli_test.h"
#include "io/image_io.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;
using nlohmann::json;

class SceneCli : public CliTest {
 protected:
  // Writes `scene` as scene.json in the scratch folder and runs `uvtk run` on it with `options`.
  CliRun run(const json& scene, const std::string& options = "") const {
    writeText("scene.json", scene.dump(2));
    return uvtk("run " + path("scene.json") + " " + options);
  }
  json plan(const json& scene) const {
    const CliRun r = run(scene, "--plan --json " + path("plan.json"));
    EXPECT_EQ(r.status, 0) << r.err;
    return json::parse(readText(path("plan.json")));
  }
  json readJson(const std::string& name) const { return json::parse(readText(path(name))); }
  // The stage names of a plan or run report, in order.
  static std::vector<std::string> stages(const json& report) {
    std::vector<std::string> out;
    for (const json& s : report["stages"]) out.push_back(s["stage"]);
    return out;
  }
  static std::set<std::string> computed(const json& report) {
    std::set<std::string> out;
    for (const json& s : report["stages"])
      for (const json& c : s["computes"]) out.insert(c.get<std::string>());
    return out;
  }
  static json sphereMesh(const json& mappings) {
    return {{"name", "sphere"}, {"path", kMeshes + "/sphere_latlong.obj"}, {"mappings", mappings}};
  }
  // Nothing but the scene file (and what a test wrote itself) in the scratch folder.
  std::vector<std::string> written() const {
    std::vector<std::string> out;
    for (const auto& entry : fs::recursive_directory_iterator(dir_))
      if (entry.is_regular_file() && entry.path().filename() != "scene.json" && entry.path().filename() != "stderr.txt")
        out.push_back(entry.path().lexically_relative(dir_).string());
    return out;
  }
};

TEST_F(SceneCli, AnObjOnlySceneReadsMapsAndWritesAndComputesNothingElse) {
  const json scene = {{"meshes",
                       {sphereMesh({{{"kind", "projector"}, {"name", "s"}, {"projector", "sphere"}},
                                    {{"kind", "projector"}, {"name", "unused"}, {"projector", "cube"}}}),
                        {{"name", "torus"}, {"path", kMeshes + "/torus.obj"}}}},
                      {"outputs", {{{"kind", "obj"}, {"mapping", "s"}, {"path", "out/s.obj"}}}}};
  const json p = plan(scene);
  // The OBJ's summary is `uvtk map --json`'s, verdict included: one judgement, nothing else.
  EXPECT_EQ(stages(p), (std::vector<std::string>{"read", "map", "measure", "obj"}));
  EXPECT_EQ(computed(p), (std::set<std::string>{"distortion", "overlap on a raster that follows the mesh", "verdict"}));
  EXPECT_TRUE(written() == std::vector<std::string>{"plan.json"}) << "--plan runs nothing";

  const CliRun r = run(scene, "--json " + path("run.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  const json report = readJson("run.json");
  EXPECT_EQ(stages(report), stages(p));
  for (const json& s : report["stages"]) EXPECT_EQ(s["status"], "ok");
  EXPECT_TRUE(fs::exists(path("out/s.obj")));
  EXPECT_GT(report["outputs"][0]["summary"]["judgement"]["seams"]["wrap_edges"].get<int>(), 0);
  EXPECT_EQ(report["outputs"][0]["verdict"], report["outputs"][0]["summary"]["verdict"]);
}

TEST_F(SceneCli, SharedMappingIsComputedOnceAndOnlyRequiredExtrasArePlanned) {
  const json scene = {
      {"meshes", {sphereMesh({{{"kind", "projector"}, {"name", "n"}, {"projector", "sphere"}, {"omap", "normal"}}})}},
      {"textures",
       {{{"name", "mip"}, {"source", "checker:64"}, {"filter", "linear_mipmap_linear"}},
        {{"name", "unused"}, {"source", "uvgrid"}}}},
      {"outputs",
       {{{"kind", "obj"}, {"mapping", "n"}, {"path", "n.obj"}},
        {{"kind", "render"}, {"mapping", "n"}, {"texture", "mip"}, {"size", "64x48"}, {"path", "n.png"}},
        {{"kind", "render"}, {"mapping", "n"}, {"view", {"stretch"}}, {"size", "64x48"}, {"path", "v.png"}},
        {{"kind", "report"}, {"mapping", "n"}, {"json", "r.json"}}}}};
  const json p = plan(scene);
  // The mipmapped texture and the default one (for the views); one read, one map; the views' and
  // the report's measures share the overlap resolution, so one measure.
  EXPECT_EQ(stages(p), (std::vector<std::string>{"texture", "texture", "read", "map", "measure", "obj", "render",
                                                 "render", "report"}));
  EXPECT_EQ(p["stages"][0]["computes"], json({"mipmaps"}));
  EXPECT_EQ(p["stages"][1]["computes"], json::array());
  EXPECT_EQ(p["stages"][3]["computes"], json({"vertex normals"}));
  const CliRun r = run(scene, "--json " + path("run.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* file : {"n.obj", "n.png", "v.png", "r.json"}) EXPECT_TRUE(fs::exists(path(file))) << file;
  EXPECT_EQ(io::readImage(path("n.png")).image.width, 64);
  EXPECT_EQ(io::readImage(path("n.png")).image.height, 48);
}

// A scene's texture takes the cube-map sources and seamless filtering as `uvtk render` does, its
// files relative to the scene; the seamless frame differs from the per-face one only near edges.
TEST_F(SceneCli, CubeMapTexturesRenderWithAndWithoutSeamlessFiltering) {
  const int n = 4;
  Image strip(6 * n, n, 3);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < 6 * n; ++x)
      for (int c = 0; c < 3; ++c) strip.at(x, y, c) = float((x * 53 + y * 29 + c * 71) % 256) / 255.0f;
  io::writeImage(path("strip.png"), strip, io::PixelType::UInt8);
  const json scene = {
      {"meshes", {sphereMesh({{{"kind", "texgen"}, {"name", "r"}, {"texgen", "reflection_map"}}})}},
      {"textures",
       {{{"name", "edges"}, {"source", "cubestrip:strip.png"}, {"filter", "linear"}},
        {{"name", "seamless"}, {"source", "cubestrip:strip.png"}, {"filter", "linear"}, {"seamless", true}}}},
      {"outputs",
       {{{"kind", "render"}, {"mapping", "r"}, {"texture", "edges"}, {"size", "64x64"}, {"path", "a.png"}},
        {{"kind", "render"}, {"mapping", "r"}, {"texture", "seamless"}, {"size", "64x64"}, {"path", "b.png"}}}}};
  const CliRun r = run(scene);
  ASSERT_EQ(r.status, 0) << r.err;
  const Image a = io::readImage(path("a.png")).image, b = io::readImage(path("b.png")).image;
  std::size_t differ = 0;
  for (std::size_t k = 0; k < a.pixels.size(); ++k) differ += a.pixels[k] != b.pixels[k];
  EXPECT_GT(differ, 0u);                   // 4 x 4 faces: much of the sphere is near an edge
  EXPECT_LT(differ, a.pixels.size() / 2);  // but not everywhere

  json flat = scene;
  flat["textures"][1]["source"] = "checker:8";
  const CliRun refused = run(flat);
  EXPECT_NE(refused.status, 0);
  EXPECT_NE(refused.err.find("/textures/1"), std::string::npos) << refused.err;
}

struct BadScene {
  const char* what;
  json scene;
  const char* message;
};

TEST_F(SceneCli, InvalidScenesAreRefusedWithTheirJsonPathAndNothingIsWritten) {
  const json good = {{"kind", "projector"}, {"name", "s"}};
  const json obj = {{"kind", "obj"}, {"mapping", "s"}, {"path", "out/s.obj"}};
  const auto scene = [&](const json& mapping, const json& output) {
    return json{{"meshes", {{{"name", "a"}, {"path", kMeshes + "/cube.obj"}}, sphereMesh(json::array({mapping}))}},
                {"outputs", {obj, output}}};
  };
  json withAxis = good, withEye = good, withRef = obj, spp = {{"kind", "render"}, {"mapping", "s"}, {"path", "x.png"}};
  withAxis["axis"] = "w";
  withEye["omap"] = "reflection";
  withRef["mapping"] = "nope";
  json sppZero = spp, unknown = obj, sameFile = obj, badPixel = spp, missing = spp;
  sppZero["spp"] = 0;
  unknown["colour"] = 1;
  badPixel["uv"] = "per-pixel";
  missing["texture"] = "grid";
  json fileMapping = {{"kind", "file"}, {"name", "s"}};
  json missingMesh = scene(good, spp);
  missingMesh["meshes"][0]["path"] = "no/such.obj";
  json duplicate = scene(good, spp);
  duplicate["meshes"][0]["name"] = "sphere";
  json missingImage = scene(good, spp);
  missingImage["textures"] = {{{"name", "t"}, {"source", "none.png"}}};
  json cubeOutput = spp;
  cubeOutput["texture"] = "env";
  json cubeOnSphere = scene(good, cubeOutput), missingFace = scene(good, cubeOutput);
  cubeOnSphere["textures"] = {{{"name", "env"}, {"source", "cube:8"}}};
  missingFace["textures"] = {{{"name", "env"}, {"source", "cubestrip:none.png"}}};
  const std::vector<BadScene> cases = {
      {"enum", scene(withAxis, spp), "/meshes/1/mappings/0/axis: expected one of x, y, z, found \"w\""},
      {"reference", scene(good, withRef), "/outputs/1/mapping: no mapping named \"nope\"; the scene has: s"},
      {"range", scene(good, sppZero), "/outputs/1/spp: expected an integer >= 1, found 0"},
      {"unknown key", scene(good, unknown), "/outputs/1/colour: unknown key \"colour\"; expected one of: ascii, json, kind"},
      {"same file", scene(good, sameFile), "/outputs/1: writes \""},
      {"option check", scene(withEye, spp), "/meshes/1/mappings/0: omap reflection: expected eye x,y,z"},
      {"per-pixel file UVs", scene(fileMapping, badPixel), "/outputs/1: uv per-pixel evaluates the mapping"},
      {"undefined texture", scene(good, missing),
       "/outputs/1/texture: no texture named \"grid\"; the scene defines none"},
      {"missing mesh", missingMesh, "/meshes/0/path: no such file"},
      {"duplicate", duplicate, "/meshes/1/name: duplicate mesh name \"sphere\" (also at /meshes/0)"},
      {"missing image", missingImage, "/textures/0/source: no such file"},
      {"cube map on a sphere", cubeOnSphere, "/outputs/1: a cube-map texture needs directions"},
      {"missing cube map file", missingFace, "/textures/0/source: no such file"},
  };
  for (const BadScene& c : cases) {
    SCOPED_TRACE(c.what);
    const CliRun r = run(c.scene, "--json " + path("run.json"));
    EXPECT_EQ(r.status, 3);
    EXPECT_NE(r.err.find(path("scene.json") + ": " + c.message), std::string::npos) << r.err;
    EXPECT_TRUE(written().empty()) << written().front();
  }
  writeText("scene.json", "{\"meshes\": [], \"meshes\": []}");
  const CliRun r = uvtk("run " + path("scene.json"));
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find(path("scene.json") + ":1:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("duplicate key \"meshes\""), std::string::npos) << r.err;
}

TEST_F(SceneCli, AFailingMeshDoesNotStopTheOthers) {
  writeText("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  const json scene = {{"meshes",
                       {{{"name", "bad"}, {"path", "bad.obj"}, {"mappings", {{{"kind", "projector"}, {"name", "b"}}}}},
                        sphereMesh({{{"kind", "projector"}, {"name", "s"}}, {{"kind", "file"}, {"name", "own"}}})}},
                      {"outputs",
                       {{{"kind", "obj"}, {"mapping", "b"}, {"path", "b.obj"}},
                        {{"kind", "obj"}, {"mapping", "s"}, {"path", "s.obj"}},
                        {{"kind", "obj"}, {"mapping", "own"}, {"path", "own.obj"}}}}};
  const CliRun r = run(scene, "--jobs 2 --json " + path("run.json"));
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find(path("bad.obj") + ":4:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("/meshes/1/mappings/1: "), std::string::npos) << "the file's UVs are missing: " << r.err;
  EXPECT_TRUE(fs::exists(path("s.obj")));
  EXPECT_FALSE(fs::exists(path("b.obj")));
  EXPECT_FALSE(fs::exists(path("own.obj")));
  const json report = readJson("run.json");
  EXPECT_EQ(report["status"], "failed");
  EXPECT_EQ(report["failures"].size(), 2u);
  std::map<std::string, std::string> statuses;
  for (const json& s : report["stages"]) statuses[s["subject"]] = s["status"];
  EXPECT_EQ(statuses[path("b.obj")], "skipped");
  EXPECT_EQ(statuses[path("s.obj")], "ok");
}

TEST_F(SceneCli, SchemaCommandPrintsTheShippedSchema) {
  const std::string printed = path("schema.json");
  ASSERT_EQ(std::system((std::string(UVTK_BINARY) + " schema > " + printed).c_str()), 0);
  EXPECT_EQ(json::parse(readText(printed)),
            json::parse(readText(std::string(UVTK_SOURCE_DIR) + "/schema/scene.schema.json")));
}

// The README's main job: the bundled demo scene writes its gallery; every picture exists at its
// size, and the page refers only to files that exist.
TEST_F(SceneCli, DemoSceneWritesAGalleryThatRefersOnlyToFilesThatExist) {
  const CliRun r = uvtk("run " + kMeshes + "/demo.json --quiet -o " + path("out") + " --json " + path("out/run.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  const json report = readJson("out/run.json");
  EXPECT_EQ(report["status"], "ok");
  const json scene = json::parse(readText(kMeshes + "/demo.json"));
  int pictures = 0;
  for (const json& output : scene["outputs"]) {
    if (output["kind"] != "render") continue;
    const Image image = io::readImage(path("out/" + output["path"].get<std::string>())).image;
    const std::string size = output.value("size", "512x512");
    if (output.value("view", json::array()).size() > 1) {  // a contact sheet of labelled tiles
      const int tile = std::stoi(size);
      EXPECT_GE(image.width, 3 * tile) << output["path"];
      EXPECT_GE(image.height, tile) << output["path"];
    } else {
      EXPECT_EQ(std::to_string(image.width) + "x" + std::to_string(image.height), size) << output["path"];
    }
    ++pictures;
  }
  EXPECT_GE(pictures, 5);
  const std::string html = readText(path("out/index.html"));
  const std::regex reference("(src|href)=\"([^\"]+)\"");
  int references = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), reference); it != std::sregex_iterator(); ++it) {
    EXPECT_TRUE(fs::is_regular_file(path("out/" + (*it)[2].str()))) << (*it)[2];
    ++references;
  }
  EXPECT_GE(references, 20);

  // Every row of the mappings table opens its report page, shows every reason of its report, and
  // states overlap as the report does (a percentage).
  const std::size_t begin = html.find("<h2>Mappings</h2>"), end = html.find("</table>", begin);
  ASSERT_NE(begin, std::string::npos);
  const std::string table = html.substr(begin, end - begin);
  const std::regex row("<tr><td>[^<]*</td><td>([^<]*)</td><td>(.*?)</td>(?:<td class=\"num\">[^<]*</td>){4}"
                       "<td class=\"num\">([^<]*)</td>");
  int rows = 0;
  for (auto it = std::sregex_iterator(table.begin(), table.end(), row); it != std::sregex_iterator(); ++it, ++rows) {
    const std::string mapping = (*it)[1], verdict = (*it)[2];
    std::smatch link;
    ASSERT_TRUE(std::regex_search(verdict, link, std::regex("<a href=\"(reports/[^\"]+\\.html)\" title=\"open the report\">")))
        << mapping;
    const std::string page = link[1];
    const json judged = readJson("out/" + page.substr(0, page.size() - 4) + "json");
    std::size_t badges = 0;
    for (std::size_t at = verdict.find("class=\"verdict "); at != std::string::npos;
         at = verdict.find("class=\"verdict ", at + 1))
      ++badges;
    EXPECT_EQ(badges, 1 + judged["reasons"].size()) << mapping;
    for (const json& reason : judged["reasons"]) {
      const std::string text = std::regex_replace(reason["text"].get<std::string>(), std::regex(">"), "&gt;");
      EXPECT_NE(verdict.find(text), std::string::npos) << mapping << ": " << text;
    }
    EXPECT_EQ((*it)[3].str().substr((*it)[3].str().size() - 2), " %") << mapping;
  }
  EXPECT_EQ(rows, 4);
}

// Memory before work: the render stage refuses a frame the process cannot hold, naming the
// estimate, before allocating it (a 16384 x 16384 frame took 5.4 GB and 70 s with no word before).
TEST_F(SceneCli, ARenderTheProcessCannotHoldIsRefusedBeforeItsBuffersAreAllocated) {
  if (kAddressSanitized) GTEST_SKIP() << "the sanitizers reserve terabytes of address space, which ulimit -v forbids";
  const json scene = {{"meshes", {sphereMesh({{{"kind", "projector"}, {"name", "s"}, {"projector", "sphere"}}})}},
                      {"outputs",
                       {{{"kind", "render"}, {"mapping", "s"}, {"path", "big.png"}, {"size", "16384x16384"}}}}};
  writeText("scene.json", scene.dump(2));
  const CliRun r = shell("ulimit -v 3000000; " + std::string(UVTK_BINARY) + " run " + path("scene.json") + " -q");
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_EQ(r.err.find(path("scene.json") +
                       ": /outputs/0: rendering 16384x16384 needs about 3.0 GiB of memory for its buffers, more than "
                       "the "),
            0u)
      << r.err;
  EXPECT_TRUE(written().empty());
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
