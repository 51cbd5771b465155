// A scene's outputs stay inside --output-dir and name files a file system can hold: every refusal
// is exit 3 at check time, one line naming the JSON pointer, and nothing is written, neither in the
// output folder nor beside it. `--allow-outside` lets outputs leave the folder. Inputs may be anywhere.
#include <gtest/gtest.h>

#include <climits>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "apps/cli_test.h"
#include "core/error.h"
#include "scene/scene.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;
using nlohmann::json;

class ScenePaths : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    out_ = dir_ / "work" / "out";
    fs::create_directories(out_);
  }

  // A scene mapping the cube whose only output is an OBJ, with `extra` merged into that output.
  static json scene(const json& extra) {
    json output = {{"kind", "obj"}, {"mapping", "m"}, {"path", "ok.obj"}};
    output.update(extra);
    return {{"meshes",
             {{{"name", "cube"},
               {"path", kMeshes + "/cube.obj"},
               {"mappings", {{{"kind", "projector"}, {"name", "m"}, {"projector", "cube"}}}}}}},
            {"outputs", {output}}};
  }

  CliRun run(const json& s, const std::string& options = "") const {
    writeText("scene.json", s.dump(2));
    return uvtk("run " + path("scene.json") + " --output-dir " + out_.string() + " " + options);
  }

  // Every file under the scratch folder (the output folder, its parent and beyond) but the scene
  // and the captured stderr.
  std::vector<std::string> written() const {
    std::vector<std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(dir_))
      if (!entry.is_directory() && !entry.is_symlink() && entry.path() != path("scene.json") &&
          entry.path() != path("stderr.txt"))
        files.push_back(entry.path().lexically_relative(dir_).string());
    return files;
  }

  // Runs `s`, expecting the one-line refusal at `pointer` that contains `problem`, and no file.
  void expectRefused(const json& s, const std::string& pointer, const std::string& problem) const {
    const CliRun r = run(s);
    EXPECT_EQ(r.status, 3) << r.err;
    const std::string prefix = path("scene.json") + ": " + pointer + ": ";
    EXPECT_EQ(r.err.compare(0, prefix.size(), prefix), 0) << r.err;
    EXPECT_NE(r.err.find(problem), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(written(), std::vector<std::string>{}) << "nothing may be written anywhere";
  }

  fs::path out_;
};

TEST_F(ScenePaths, AValidSceneWritesInsideTheOutputFolder) {
  const CliRun r = run(scene({{"path", "sub/../a/x.obj"}}));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(written(), std::vector<std::string>{"work/out/a/x.obj"});
}

TEST_F(ScenePaths, PathsLeavingTheOutputFolderAreRefused) {
  expectRefused(scene({{"path", "../../x.obj"}}), "/outputs/0/path",
                "\"../../x.obj\" leads outside the output folder \"" + out_.string() +
                    "\" (uvtk run --allow-outside lets outputs leave it)");
  expectRefused(scene({{"path", path("abs/x.obj")}}), "/outputs/0/path",
                "\"" + path("abs/x.obj") + "\" is an absolute path, outside the output folder");
  expectRefused(scene({{"json", "sub/../../x.json"}}), "/outputs/0/json", "\"sub/../../x.json\" leads outside");
}

TEST_F(ScenePaths, AllowOutsideLetsThemLeave) {
  const CliRun r = run(scene({{"path", "../x.obj"}}), "--allow-outside");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(written(), std::vector<std::string>{"work/x.obj"});
}

TEST_F(ScenePaths, NamesNoFileSystemCanHoldAreRefused) {
  const std::string longName = std::string(296, 'a') + ".obj";
  expectRefused(scene({{"path", longName}}), "/outputs/0/path",
                "\"" + longName + "\": a component of 300 bytes, more than the 255 a file name can have");
  // The NUL shows escaped, and the message goes on past it.
  expectRefused(scene({{"path", std::string("a\0b.obj", 7)}}), "/outputs/0/path",
                "\"a\\u0000b.obj\": a file name cannot hold a NUL byte");
  std::string deep;
  for (int i = 0; i < 20; ++i) deep += std::string(250, 'd') + "/";
  expectRefused(scene({{"path", deep + "x.obj"}}), "/outputs/0/path", "a path can have");
}

TEST_F(ScenePaths, FoldersAreRefused) {
  expectRefused(scene({{"path", "."}}), "/outputs/0/path", "\".\" names a folder, not a file");
  expectRefused(scene({{"path", ".."}}), "/outputs/0/path", "\"..\" names a folder, not a file");
  expectRefused(scene({{"path", "sub/"}}), "/outputs/0/path", "\"sub/\" names a folder, not a file");
  fs::create_directory(out_ / "existing");
  expectRefused(scene({{"path", "existing"}}), "/outputs/0/path",
                "\"existing\": \"" + (out_ / "existing").string() + "\" is an existing folder");
}

TEST_F(ScenePaths, TwoOutputsOfOneFileAreRefused) {
  json s = scene({{"path", "a.obj"}});
  s["outputs"].push_back({{"kind", "obj"}, {"mapping", "m"}, {"path", "sub/../a.obj"}});
  expectRefused(s, "/outputs/1", "writes \"" + (out_ / "a.obj").string() + "\", which /outputs/0 names too");
}

TEST_F(ScenePaths, SymbolicLinksToFoldersOutsideAreRefusedUnlessAllowed) {
  fs::create_directory(dir_ / "elsewhere");
  fs::create_directory_symlink(dir_ / "elsewhere", out_ / "link");
  expectRefused(scene({{"path", "link/x.obj"}}), "/outputs/0/path",
                "\"link/x.obj\" leads outside the output folder \"" + out_.string() +
                    "\" through a symbolic link, to \"" + (dir_ / "elsewhere" / "x.obj").string() + "\"");
  const CliRun r = run(scene({{"path", "link/x.obj"}}), "--allow-outside");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir_ / "elsewhere" / "x.obj"));
}

TEST_F(ScenePaths, AnOutputThatIsASymbolicLinkOutsideIsRefused) {
  // An output that is a link is written where it leads (docs/robustness.md), so the link counts.
  fs::create_symlink(dir_ / "victim.obj", out_ / "x.obj");
  expectRefused(scene({{"path", "x.obj"}}), "/outputs/0/path",
                "\"x.obj\" leads outside the output folder \"" + out_.string() + "\" through a symbolic link, to \"" +
                    (dir_ / "victim.obj").string() + "\"");
  EXPECT_TRUE(fs::is_symlink(out_ / "x.obj"));
}

TEST_F(ScenePaths, InputsMayBeAnywhereButHoldNoNul) {
  json s = scene(json::object());
  s["meshes"][0]["path"] = fs::relative(kMeshes + "/cube.obj", dir_).string();  // "../.." from the scene's folder
  ASSERT_EQ(run(s).status, 0);
  s["meshes"][0]["path"] = kMeshes + std::string("/cube.obj\0.txt", 14);
  const CliRun r = run(s);
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("/meshes/0/path: \"" + kMeshes + "/cube.obj\\u0000.txt\": a file name cannot hold a NUL byte"),
            std::string::npos)
      << r.err;
}

// The check itself, as the fuzz target calls it.
TEST(CheckOutputPath, ResolvesInsideAndRefusesTheRest) {
  EXPECT_EQ(scene::checkOutputPath("a/./b/../c.obj", "/o", false), "/o/a/c.obj");
  EXPECT_EQ(scene::checkOutputPath("c.obj", "", false), "c.obj");
  EXPECT_EQ(scene::checkOutputPath("../c.obj", "/o/p", true), "/o/c.obj");
  EXPECT_EQ(scene::checkOutputPath("/x/c.obj", "/o", true), "/x/c.obj");
  EXPECT_EQ(scene::checkOutputPath(std::string(255, 'n'), "/o", false), "/o/" + std::string(255, 'n'));
  // A relative output folder that does not exist yet (`uvtk run -o demo`) holds its outputs.
  EXPECT_EQ(scene::checkOutputPath("obj/c.obj", "uvtk-no-such-folder/demo", false), "uvtk-no-such-folder/demo/obj/c.obj");
  EXPECT_EQ(scene::checkOutputPath("c.obj", "uvtk-no-such-folder", false), "uvtk-no-such-folder/c.obj");
  EXPECT_THROW(scene::checkOutputPath("../../c.obj", "uvtk-no-such-folder/demo", false), InputError);
  const std::vector<std::string> bad = {"", "..", ".", "a/", "a/..", "../c", "a/../../c", "/c", std::string("\0", 1),
                                       std::string(256, 'n'), "a/" + std::string(256, 'n') + "/b"};
  for (const std::string& path : bad)
    EXPECT_THROW(scene::checkOutputPath(path, "/o", false), InputError) << quotedName(path);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
