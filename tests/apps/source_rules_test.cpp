// Rules of the source tree that keep the design true (docs/architecture.md): checked on the files
// themselves, so that they stay true.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// The C++ files of the project's own modules (not tests, third-party code or build trees).
std::vector<fs::path> sources() {
  std::vector<fs::path> files;
  const fs::path root = UVTK_SOURCE_DIR;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
    const std::string name = it->path().filename().string();
    if (it->is_directory() && (name.rfind("build", 0) == 0 || name == "third_party" || name == "tests" || name[0] == '.'))
      it.disable_recursion_pending();
    else if (it->is_regular_file() && (it->path().extension() == ".cpp" || it->path().extension() == ".h"))
      files.push_back(fs::relative(it->path(), root));
  }
  return files;
}

std::string textOf(const fs::path& relative) {
  std::ifstream in(fs::path(UVTK_SOURCE_DIR) / relative);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(SourceRules, OnlyParamComparesTheSurfaceEnum) {
  // What a surface is (it wraps, it blends, it has face ids, ...) is asked of param::traitsOf.
  const std::regex comparison(R"((==|!=)\s*(param::)?SurfaceKind::|case\s+(param::)?SurfaceKind::)");
  std::size_t checked = 0;
  for (const fs::path& file : sources()) {
    if (*file.begin() == "param") continue;
    ++checked;
    const std::string text = textOf(file);
    std::smatch found;
    EXPECT_FALSE(std::regex_search(text, found, comparison)) << file << ": " << found.str();
  }
  EXPECT_GT(checked, 100u);  // the walk found the modules
}

TEST(SourceRules, IncludesRunDownTheLayers) {
  // docs/architecture.md: core -> io, param, texgen, analysis, render -> views -> inspect -> options
  // (the command line's parser) -> timing, scene -> apps; library/ and point/ are faces over them.
  // A module includes its own headers and those of the modules below it, never one above.
  const std::map<std::string, std::set<std::string>> below = {
      {"core", {}},
      {"io", {"core"}},
      {"param", {"core"}},
      {"texgen", {"core"}},
      {"analysis", {"core"}},
      {"render", {"core"}},
      {"peers", {"core"}},
      {"meshes", {"core", "io"}},
      {"views", {"core", "analysis", "render"}},
      {"verify", {"core", "render"}},
      {"inspect", {"core", "io", "param", "texgen", "analysis", "render", "verify", "views"}},
      {"options", {"core", "io", "param", "texgen", "analysis", "render", "verify", "views", "inspect"}},
      {"timing", {"core", "io", "param", "views", "inspect", "options", "peers", "meshes"}},
      {"scene", {"core", "io", "param", "analysis", "render", "inspect", "options", "timing"}},
  };
  const std::regex include(R"re(#include "([a-z_]+)/)re");
  for (const fs::path& file : sources()) {
    const std::string module = file.begin()->string();
    const auto allowed = below.find(module);
    if (allowed == below.end()) continue;  // apps/, library/, point/, python/, bench/, fuzz/: the faces
    const std::string text = textOf(file);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), include); it != std::sregex_iterator(); ++it) {
      const std::string target = (*it)[1];
      EXPECT_TRUE(target == module || allowed->second.count(target)) << file << " includes " << target << "/";
    }
  }
}

}  // namespace
