// `uvtk bench --html` and a scene's bench output as a user runs them: one self-contained page with
// the Pareto chart as SVG and the tables, nothing written on failure, and the run record's chart.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "apps/cli_test.h"
#include "options/bench_cli.h"
#include "timing/bench.h"
#include "io/obj_writer.h"
#include "meshes/generators.h"
#include "scene/scene.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

class BenchHtml : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    io::writeObj(path("sphere.obj"), meshes::latLongSphere(32, 16), nullptr);
  }
  const std::string quick = " --precision double,float --math exact,fast --min-time 0.005 --no-peers --no-end-to-end";
};

TEST_F(BenchHtml, WritesOnePageWithTheChartAsSvgAndTheTables) {
  const CliRun run = uvtk("bench --mesh " + path("sphere.obj") + " --projector plane,sphere" + quick + " --html " +
                          path("b.html") + " --json " + path("b.json"));
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string html = readText(path("b.html"));
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_EQ(count(html, "<svg "), 1u) << "the mapping's chart; no rendering without --render";
  EXPECT_NE(html.find("Mapping: time per vertex against max error"), std::string::npos);
  // Self-contained: no script, no link, no file but itself.
  for (const char* external : {"<script", "<link", "src=", "href="})
    EXPECT_EQ(html.find(external), std::string::npos) << external;
  // One circle per configuration (plane: 2 precisions; sphere: 2 x 2 math modes), titled as the table's rows.
  EXPECT_EQ(count(html, "<circle "), 6u);
  EXPECT_NE(html.find("<title>sphere float fast T1\nns per vertex: "), std::string::npos);
  // The Markdown tables as HTML: the header, one row per configuration.
  EXPECT_NE(html.find("<tr><th>projector</th><th>omap</th><th>precision</th>"), std::string::npos);
  EXPECT_NE(html.find("<tr><td>sphere</td><td>isn</td><td>float</td><td>fast</td><td>1</td>"), std::string::npos);
  EXPECT_EQ(count(html, "<tr><td>"), 6u);
  EXPECT_NE(html.find("Mesh: " + path("sphere.obj") + " (" + std::to_string(32 * 15 + 2) + " vertices)"),
            std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(readText(path("b.json")))["records"].size(), 6u);
}

TEST_F(BenchHtml, WithRenderTheRenderingChartToo) {
  const CliRun run = uvtk("bench --mesh " + path("sphere.obj") +
                          " --projector sphere --precision double --math exact"
                          " --min-time 0.005 --no-peers --no-end-to-end --render --size 32x32 --filters nearest"
                          " --spp 1 --html " +
                          path("b.html"));
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string html = readText(path("b.html"));
  EXPECT_EQ(count(html, "<svg "), 2u);
  EXPECT_NE(html.find("Rendering: time per frame against RMSE to a 64-sample reference"), std::string::npos);
  EXPECT_NE(html.find("<title>nearest 1 spp T1\nms per frame: "), std::string::npos);
}

TEST_F(BenchHtml, AnUnwritablePageFailsWithStatus4AndWritesNothing) {
  const CliRun run = uvtk("bench --mesh " + path("sphere.obj") + " --projector plane" + quick + " --json " +
                          path("b.json") + " --html /dev/full");
  EXPECT_EQ(run.status, 4) << run.err;
  EXPECT_NE(run.err.find("/dev/full: error: cannot write"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(path("b.json"))) << "the outputs are published together or not at all";
  // A missing folder is refused before anything is measured.
  const CliRun missing = uvtk("bench --mesh " + path("sphere.obj") + quick + " --html " + path("no/b.html"));
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("does not exist"), std::string::npos) << missing.err;
  EXPECT_EQ(missing.err.find("timing"), std::string::npos) << "nothing measured";
}

class SceneBench : public BenchHtml {
 protected:
  // A scene of the sphere with a projector and a texgen mapping, and `output` among its outputs.
  std::string scene(const std::string& output) const {
    return writeText("scene.json", R"({"meshes": [{"name": "ball", "path": "sphere.obj", "mappings": [
        {"kind": "projector", "name": "ball-cylinder", "projector": "cylinder"},
        {"kind": "projector", "name": "ball-cube", "projector": "cube"},
        {"kind": "texgen", "name": "ball-texgen", "texgen": "sphere_map"}]}],
      "outputs": [)" + output + R"(, {"kind": "gallery", "path": "index.html"}]})");
  }
};

TEST_F(SceneBench, RunsTheBenchAndRecordsItsChartForTheGallery) {
  const std::string file = scene(R"({"kind": "bench", "mesh": "ball", "path": "bench/b.html", "json": "bench/b.json",
      "projector": ["plane", "sphere"], "precision": ["float"], "math": ["exact", "fast"], "min_time": 0.005, "no_peers": true})");
  const CliRun run = uvtk("run " + file + " --output-dir " + path("out") + " --json " + path("run.json"));
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string html = readText(path("out/bench/b.html"));
  EXPECT_EQ(count(html, "<circle "), 3u);  // plane float; sphere float exact and fast
  const nlohmann::json records = nlohmann::json::parse(readText(path("out/bench/b.json")))["records"];
  ASSERT_EQ(records.size(), 3u);
  for (const nlohmann::json& r : records) EXPECT_EQ(r["section"], "mapping") << "neither end to end nor peers";
  const nlohmann::json report = nlohmann::json::parse(readText(path("run.json")));
  const nlohmann::json& outputs = report["outputs"];
  const auto bench =
      std::find_if(outputs.begin(), outputs.end(), [](const nlohmann::json& o) { return o["kind"] == "bench"; });
  ASSERT_NE(bench, outputs.end());
  EXPECT_EQ((*bench)["mesh"], "ball");
  EXPECT_EQ((*bench)["configurations"], 3);
  EXPECT_EQ((*bench)["title"], "Mapping: time per vertex against max error");
  EXPECT_EQ((*bench)["files"], nlohmann::json({path("out/bench/b.html"), path("out/bench/b.json")}));
  const std::string svg = (*bench)["svg"];
  EXPECT_EQ(svg.rfind("<svg ", 0), 0u);
  EXPECT_NE(html.find(svg), std::string::npos) << "the page's chart, as the gallery inlines it";
  // Its stage reads the mesh itself: planned after the meshes' stages, nothing else computed for it.
  std::vector<std::string> stages;
  for (const nlohmann::json& s : report["stages"]) stages.push_back(s["stage"]);
  EXPECT_EQ(stages, (std::vector<std::string>{"bench", "gallery"}));
  EXPECT_EQ(report["stages"][0]["computes"][0], "the mapping kernel: 3 configurations, 0.005 s each");
}

TEST_F(SceneBench, AMappingTimesItsOwnProjector) {
  const std::string file = scene(
      R"({"kind": "bench", "mapping": "ball-cylinder", "path": "b.html", "precision": ["double"], "math": ["exact"], "min_time": 0.005})");
  const CliRun run = uvtk("run " + file + " --output-dir " + path("out") + " --json " + path("run.json") + " -q");
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string html = readText(path("out/b.html"));
  EXPECT_EQ(count(html, "<circle "), 1u);
  EXPECT_NE(html.find("<title>cylinder double exact T1\n"), std::string::npos);
  const nlohmann::json report = nlohmann::json::parse(readText(path("run.json")));
  EXPECT_EQ(report["outputs"][0]["mapping"], "ball-cylinder");
}

TEST_F(SceneBench, RefusesWhatItCannotTimeBeforeAnyWork) {
  const auto refusal = [&](const std::string& output) {
    const CliRun run = uvtk("run " + scene(output) + " --output-dir " + path("out"));
    EXPECT_EQ(run.status, 3) << output;
    EXPECT_FALSE(fs::exists(path("out/index.html"))) << output;
    return run.err;
  };
  EXPECT_NE(refusal(R"({"kind": "bench", "path": "b.html"})").find("/outputs/0: expected mesh or mapping, one of them"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"kind": "bench", "mesh": "ball", "mapping": "ball-cylinder", "path": "b.html"})")
                .find("expected mesh or mapping"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"kind": "bench", "mapping": "ball-texgen", "path": "b.html"})")
                .find("/outputs/0/mapping: mapping \"ball-texgen\" is not a projector"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"kind": "bench", "mapping": "ball-cube", "path": "b.html"})").find("chooses a projection per triangle"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"kind": "bench", "mapping": "ball-cylinder", "projector": ["plane"], "path": "b.html"})")
                .find("/outputs/0/projector: projector and mapping exclude each other"),
            std::string::npos);
  // The schema: rendering and the end-to-end map are not a scene's; choices as the command line's.
  EXPECT_NE(refusal(R"({"kind": "bench", "mesh": "ball", "path": "b.html", "render": true})").find("render"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"kind": "bench", "mesh": "ball", "path": "b.html", "projector": ["cube"]})").find("cube"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"kind": "bench", "mesh": "ball", "path": "b.html", "min_time": 0})").find("min_time"),
            std::string::npos);
  EXPECT_NE(
      refusal(R"({"kind": "bench", "mesh": "ball", "path": "../b.html"})").find("leads outside the output folder"),
      std::string::npos);
  EXPECT_NE(refusal(R"({"kind": "bench", "mesh": "ball", "path": "b.html", "json": "b.html"})").find("names too"),
            std::string::npos);
}

// The schema's bench output has the bench parser's options but those a scene leaves out, with the
// same choices: a scene is parsed by that very parser.
TEST(SceneBenchSchema, HasTheBenchOptionsButRenderingAndTheEndToEndMap) {
  CLI::App app;
  cli::BenchArguments arguments;
  cli::addBenchOptions(app, arguments);
  std::map<std::string, const CLI::Option*> options;
  for (const CLI::Option* option : app.get_options()) {
    if (option->get_lnames().empty() || option->get_lnames().front() == "help") continue;
    std::string key = option->get_lnames().front();
    std::replace(key.begin(), key.end(), '-', '_');
    options[key] = option;
  }
  const nlohmann::json properties =
      nlohmann::json::parse(scene::sceneSchemaText())["$defs"]["benchOutput"]["properties"];
  std::set<std::string> schemaKeys;
  for (const auto& [key, value] : properties.items()) {
    if (key == "kind" || key == "mesh" || key == "mapping" || key == "path") continue;
    schemaKeys.insert(key);
    ASSERT_TRUE(options.count(key)) << key << " is no option of uvtk bench";
    std::string parameter = key;
    std::replace(parameter.begin(), parameter.end(), '_', '-');
    const std::vector<std::string> read = timing::benchParameterNames();
    EXPECT_NE(std::find(read.begin(), read.end(), parameter), read.end()) << key << " is no parameter the bench reads";
    const nlohmann::json& choices = value.contains("items") ? value["items"] : value;
    if (!choices.contains("enum")) continue;
    std::set<std::string> names;
    for (const nlohmann::json& name : choices["enum"]) names.insert(name);
    // The option's help names its choices (lists take names, not CLI11 sets).
    for (const std::string& name : names)
      EXPECT_NE(options[key]->get_description().find(name), std::string::npos) << key << ": " << name;
  }
  std::set<std::string> left;
  for (const auto& [key, option] : options)
    if (!schemaKeys.count(key)) left.insert(key);
  // --mesh is the scene's mesh, --html its path; the rest renders or maps end to end.
  const std::set<std::string> rendering = {
      "mesh", "html", "map_projector", "no_end_to_end", "render", "render_projector", "filters", "spp"};
  for (const std::string& key : rendering) EXPECT_TRUE(left.count(key)) << key;
  for (const std::string& key : left) {
    if (rendering.count(key)) continue;
    EXPECT_TRUE(key == "camera" || key == "eye" || key == "center" || key == "up" || key == "view_dir" ||
                key == "fovy" || key == "near" || key == "far" || key == "ortho" || key == "texture" ||
                key == "filter" || key == "wrap" || key == "seamless" || key == "two_sided" || key == "env" || key == "env_color" ||
                key == "size" || key == "cull" || key == "background" || key == "uv" ||
                key == "derivatives" || key == "seam_fix")
        << key << ": a bench option the scene neither takes nor leaves out on purpose";
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
