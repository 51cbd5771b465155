// `uvtk map` over many meshes (a folder or a list) as a user runs it: outputs, per-mesh failures,
// exit statuses, batch.json, usage errors before any work, and --quiet.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "apps/cli_test.h"
#include "io/obj_writer.h"
#include "meshes/generators.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

class MapBatchCli : public CliTest {
 protected:
  // A bundled mesh copied to `to` (relative to the scratch folder), whose folders are created.
  std::string copyMesh(const std::string& name, const std::string& to) const {
    fs::create_directories(fs::path(path(to)).parent_path());
    fs::copy_file(fs::path(UVTK_MESHES_DIR) / name, path(to));
    return path(to);
  }
  // Three good meshes and one with a malformed coordinate on line 3, in the folder "in".
  void makeFolderWithABadMesh() const {
    copyMesh("sphere_latlong.obj", "in/sphere.obj");
    copyMesh("torus.obj", "in/torus.obj");
    copyMesh("cube.obj", "in/cube.obj");
    writeText("in/bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 x\nf 1 2 3\n");
  }
  std::vector<std::string> filesIn(const std::string& folder) const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(path(folder))) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
};

TEST_F(MapBatchCli, AFolderWithAMalformedMeshMapsTheOthersAndExitsThree) {
  makeFolderWithABadMesh();
  const CliRun r = uvtk("map " + path("in") + " -o " + path("out") + " --json " + path("reports"));
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_EQ(filesIn("out"), (std::vector<std::string>{"cube.obj", "sphere.obj", "torus.obj"}));
  EXPECT_NE(r.err.find(path("in/bad.obj") + ":3: error: expected a number, found 'x'\n"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("uvtk map: " + path("in/sphere.obj") + ": 482 vertices, 960 faces"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("uvtk map: 3 meshes mapped (1 pass, 1 warn, 1 fail), 1 failed\n"), std::string::npos) << r.err;

  EXPECT_EQ(filesIn("reports"), (std::vector<std::string>{"batch.json", "cube.json", "sphere.json", "torus.json"}));
  const nlohmann::json batch = nlohmann::json::parse(readText(path("reports/batch.json")));
  ASSERT_EQ(batch["meshes"].size(), 4u) << batch;
  EXPECT_EQ(batch["mapped"], 3);
  EXPECT_EQ(batch["failed"], 1);
  const std::vector<std::string> sorted = {"bad", "cube", "sphere", "torus"};
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    const nlohmann::json& mesh = batch["meshes"][i];
    EXPECT_EQ(mesh["input"], path("in/" + sorted[i] + ".obj"));
    EXPECT_EQ(mesh["status"], i == 0 ? "failed" : "ok") << mesh;
    EXPECT_TRUE(mesh["milliseconds"].is_number()) << mesh;
  }
  EXPECT_NE(batch["meshes"][0]["error"].get<std::string>().find("bad.obj:3: error:"), std::string::npos);
  EXPECT_EQ(batch["meshes"][1]["summary"], path("reports/cube.json"));
  const nlohmann::json sphere = nlohmann::json::parse(readText(path("reports/sphere.json")));
  EXPECT_EQ(sphere["vertices"], 482);
  EXPECT_EQ(sphere["output"], path("out/sphere.obj"));
}

TEST_F(MapBatchCli, TheOutputsAreThoseOfSingleRunsWhateverTheJobs) {
  makeFolderWithABadMesh();
  fs::remove(path("in/bad.obj"));
  ASSERT_EQ(uvtk("map " + path("in") + " -o " + path("one") + " --jobs 1").status, 0);
  ASSERT_EQ(uvtk("map " + path("in") + " -o " + path("two") + " --jobs 2").status, 0);
  ASSERT_EQ(uvtk("map " + path("in/torus.obj") + " -o " + path("torus.obj")).status, 0);
  for (const char* name : {"cube.obj", "sphere.obj", "torus.obj"})
    EXPECT_EQ(readText(path("one/") + name), readText(path("two/") + name)) << name;
  EXPECT_EQ(readText(path("one/torus.obj")), readText(path("torus.obj")));
}

TEST_F(MapBatchCli, AListSkipsCommentsAndReportsAMissingMeshAsAFailure) {
  copyMesh("sphere_latlong.obj", "meshes/sphere.obj");
  copyMesh("torus.obj", "meshes/sub/torus.obj");
  writeText("meshes/list.txt", "# the meshes of this test\n\nsphere.obj\n  sub/torus.obj  \n#cube.obj\nmissing.obj\n");
  const CliRun r = uvtk("map --list " + path("meshes/list.txt") + " -o " + path("out"));
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_EQ(filesIn("out"), (std::vector<std::string>{"sphere.obj", "torus.obj"}));
  EXPECT_NE(r.err.find(path("meshes/missing.obj") + ": error: cannot open"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("uvtk map: 2 meshes mapped (1 pass, 0 warn, 1 fail), 1 failed"), std::string::npos) << r.err;

  const CliRun noList = uvtk("map --list " + path("no-list.txt") + " -o " + path("out2"));
  EXPECT_EQ(noList.status, 3);
  EXPECT_NE(noList.err.find("no-list.txt: error: cannot open"), std::string::npos) << noList.err;
}

TEST_F(MapBatchCli, TwoMeshesWithOneStemAreAUsageErrorBeforeAnyWork) {
  copyMesh("sphere_latlong.obj", "in/a.obj");
  writeText("in/a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const CliRun r = uvtk("map " + path("in") + " -o " + path("out") + " --json " + path("reports"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(path("in/a.obj")), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(path("in/a.off")), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("out")));
  EXPECT_FALSE(fs::exists(path("reports")));

  // Nor may an output replace its input.
  fs::remove(path("in/a.off"));
  const std::string before = readText(path("in/a.obj"));
  EXPECT_EQ(uvtk("map " + path("in") + " -o " + path("in")).status, 2);
  EXPECT_EQ(readText(path("in/a.obj")), before);
}

TEST_F(MapBatchCli, AnOutputFolderThatCannotBeCreatedIsExitStatusFour) {
  copyMesh("sphere_latlong.obj", "in/sphere.obj");
  writeText("out", "a file, not a folder");
  const CliRun r = uvtk("map " + path("in") + " -o " + path("out"));
  EXPECT_EQ(r.status, 4) << r.err;
  EXPECT_NE(r.err.find(path("out") + ": error: cannot create the folder"), std::string::npos) << r.err;
}

TEST_F(MapBatchCli, AnOutputFailureWinsOverAnInputFailureAndTheOthersStillRun) {
  makeFolderWithABadMesh();
  fs::create_directories(path("out/torus.obj"));  // a folder where the torus's output goes
  const CliRun r = uvtk("map " + path("in") + " -o " + path("out"));
  EXPECT_EQ(r.status, 4) << r.err;
  EXPECT_NE(r.err.find("bad.obj:3: error:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("torus.obj"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("uvtk map: 2 meshes mapped (1 pass, 1 warn, 0 fail), 2 failed"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_regular_file(path("out/sphere.obj")));
  EXPECT_TRUE(fs::is_regular_file(path("out/cube.obj")));
}

TEST_F(MapBatchCli, QuietPrintsNoProgressAndNoSummaryLinesButTheLastLine) {
  makeFolderWithABadMesh();
  fs::remove(path("in/bad.obj"));
  const CliRun r = uvtk("map " + path("in") + " -o " + path("out") + " --quiet");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.err, "uvtk map: 3 meshes mapped (1 pass, 1 warn, 1 fail), 0 failed\n");

  // On a terminal (script(1) gives the program one) the bar is drawn once the work has lasted
  // 0.1 s, which a mesh of 260000 faces after the others makes sure of; unless --quiet.
  if (std::system("command -v script > /dev/null") != 0) GTEST_SKIP() << "script(1) is not installed";
  io::writeObj(path("in/zz_large.obj"), meshes::latLongSphere(512, 256), nullptr);
  const auto onTerminal = [&](const std::string& options) {
    const std::string command =
        std::string(UVTK_BINARY) + " map " + path("in") + " -o " + path("out") + " --jobs 1" + options;
    EXPECT_EQ(std::system(("script -qec '" + command + "' /dev/null > " + path("tty.txt")).c_str()), 0);
    return readText(path("tty.txt"));
  };
  EXPECT_NE(onTerminal("").find("mapping ["), std::string::npos);
  const std::string quiet = onTerminal(" --quiet");
  EXPECT_EQ(quiet.find("mapping ["), std::string::npos) << quiet;
  EXPECT_EQ(quiet.find("482 vertices"), std::string::npos) << quiet;
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
