// The scene schema and the command line agree: every option group a scene mirrors has exactly the
// schema's keys (besides the scene's own), with the same choices, so that a scene can say all the
// command line can and nothing it cannot.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "options/arithmetic_cli.h"
#include "options/compare_cli.h"
#include "options/projector_cli.h"
#include "options/render_cli.h"
#include "options/report_cli.h"
#include "scene/scene.h"
#include "options/texgen_cli.h"

namespace uvtk::cli {
namespace {
namespace UVTK_TEST_FILE {

using nlohmann::json;
using scene::sceneSchemaText;

const json& schema() {
  static const json parsed = json::parse(sceneSchemaText());
  return parsed;
}

std::set<std::string> names(const std::string& text, char separator) {
  std::set<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, separator);) out.insert(item);
  return out;
}

// The options of `app` as scene keys ("--axis-dir" is "axis_dir").
std::map<std::string, const CLI::Option*> keysOf(const CLI::App& app) {
  std::map<std::string, const CLI::Option*> out;
  for (const CLI::Option* option : app.get_options()) {
    if (option->get_lnames().empty() || option->get_lnames().front() == "help") continue;
    std::string key = option->get_lnames().front();
    std::replace(key.begin(), key.end(), '-', '_');
    out[key] = option;
  }
  return out;
}

void expectSameOptions(const std::string& definition, const CLI::App& app, const std::set<std::string>& sceneKeys) {
  SCOPED_TRACE(definition);
  const json& properties = schema().at("$defs").at(definition).at("properties");
  const std::map<std::string, const CLI::Option*> options = keysOf(app);
  std::set<std::string> schemaKeys, optionKeys;
  for (const auto& [key, value] : properties.items())
    if (!sceneKeys.count(key)) schemaKeys.insert(key);
  for (const auto& [key, option] : options) optionKeys.insert(key);
  EXPECT_EQ(schemaKeys, optionKeys);
  for (const auto& [key, value] : properties.items()) {
    if (!value.contains("enum") || !options.count(key)) continue;
    SCOPED_TRACE(key);
    const std::set<std::string> choices = value["enum"].get<std::set<std::string>>();
    EXPECT_EQ(names(options.at(key)->get_type_name(), '|'), choices);
  }
}

TEST(SceneSchema, ProjectorMappingHasEveryMapOption) {
  CLI::App app;
  ProjectorArguments arguments;
  addProjectorOptions(app, arguments);
  ASSERT_TRUE(keysOf(app).count("seam_place"));
  expectSameOptions("projectorMapping", app, {"kind", "name"});
}

TEST(SceneSchema, TexgenMappingHasEveryTexgenOption) {
  CLI::App app;
  TexgenArguments arguments;
  addTexgenOptions(app, arguments, "--texgen");
  addArithmeticOptions(app, arguments.arithmetic, false);
  ASSERT_TRUE(keysOf(app).count("no_normalize"));
  expectSameOptions("texgenMapping", app, {"kind", "name", "camera", "eye", "center", "up"});
}

TEST(SceneSchema, CameraTextureAndOutputsHaveTheRenderReportAndCompareOptions) {
  CLI::App camera, texture, frame, report, compare;
  CameraArguments cameraArguments;
  TextureArguments textureArguments;
  FrameArguments frameArguments;
  ReportArguments reportArguments;
  CompareArguments compareArguments;
  addCameraOptions(camera, cameraArguments);
  addTextureOptions(texture, textureArguments, "--source");
  addFrameOptions(frame, frameArguments);
  addReportOptions(report, reportArguments);
  addCompareOptions(compare, compareArguments);
  ASSERT_TRUE(keysOf(compare).count("no_baselines")) << "a negated flag is named as typed";
  expectSameOptions("camera", camera, {"name"});
  expectSameOptions("texture", texture, {"name"});
  expectSameOptions("renderOutput", frame, {"kind", "mapping", "camera", "texture", "path", "json"});
  expectSameOptions("reportOutput", report, {"kind", "mapping"});
  expectSameOptions("compareOutput", compare, {"kind", "mesh"});
}

// Every key of the scene's camera, texture and render output is a parameter their readers take.
TEST(SceneSchema, CameraTextureAndRenderKeysAreTheReadersParameters) {
  const nlohmann::json defs = nlohmann::json::parse(scene::sceneSchemaText())["$defs"];
  const auto expectRead = [&](const char* def, const std::vector<std::string>& read, std::set<std::string> sceneKeys) {
    for (const auto& [key, value] : defs[def]["properties"].items()) {
      if (sceneKeys.count(key)) continue;
      std::string name = key;
      std::replace(name.begin(), name.end(), '_', '-');
      EXPECT_NE(std::find(read.begin(), read.end(), name), read.end()) << def << ": " << key;
    }
  };
  expectRead("camera", inspect::cameraParameterNames(), {"name"});
  expectRead("texture", inspect::textureParameterNames("source"), {"name"});
  expectRead("renderOutput", inspect::frameParameterNames(), {"kind", "mapping", "camera", "texture", "path", "json"});
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::cli
