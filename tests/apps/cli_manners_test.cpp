// The command line a person expects: --version, a suggestion for a mistyped command or option, the
// accepted names for a bad choice, examples at the end of every --help, and -q everywhere.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "apps/cli_test.h"
#include "apps/uvtk/commands.h"
#include "param/projector_names.h"
#include "options/cli_values.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

class CliManners : public CliTest {
 protected:
  // What `uvtk ARGUMENTS` prints on stdout (and its status), run in the scratch folder.
  CliRun stdoutOf(const std::string& arguments) const { return shell(std::string(UVTK_BINARY) + " " + arguments + " 1>&2"); }

  // The names under "Subcommands:" in `uvtk --help`.
  std::vector<std::string> commands() const {
    const std::string help = stdoutOf("--help").err;
    std::vector<std::string> names;
    std::istringstream in(help.substr(help.find("Subcommands:\n")));
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line) && line.rfind("  ", 0) == 0) names.push_back(line.substr(2, line.find(' ', 2) - 2));
    return names;
  }

  // The command lines under "Examples:" at the end of `help`.
  static std::vector<std::string> examples(const std::string& help) {
    std::vector<std::string> lines;
    const std::size_t at = help.rfind("\nExamples:\n");
    if (at == std::string::npos) return lines;
    std::istringstream in(help.substr(at + 11));
    for (std::string line; std::getline(in, line);)
      if (line.rfind("      ", 0) != 0 && !line.empty()) lines.push_back(line.substr(2));
    return lines;
  }

  std::string sphereMesh() const { return std::string(UVTK_SOURCE_DIR) + "/meshes/sphere_latlong.obj"; }
};

// `uvtk NAME` builds only the command of that name (apps/uvtk/commands.h): each entry of the table
// registers the name it is listed by, and `uvtk --help`, which builds them all, lists the same.
TEST_F(CliManners, EachCommandOfTheTableRegistersTheNameItIsListedBy) {
  std::vector<std::string> names;
  for (const cli::Command& command : cli::kCommands) {
    CLI::App root;
    command.add(root);
    const std::vector<CLI::App*> registered = root.get_subcommands({});
    ASSERT_EQ(registered.size(), 1u) << command.name;
    EXPECT_EQ(registered[0]->get_name(), command.name);
    names.push_back(command.name);
    // Built alone it parses its own options as when every command is built.
    const CliRun help = stdoutOf(std::string(command.name) + " --help");
    EXPECT_EQ(help.status, 0) << command.name;
    EXPECT_NE(help.err.find(std::string("Usage: ")), std::string::npos) << command.name;
  }
  EXPECT_EQ(commands(), names);
}

TEST_F(CliManners, VersionPrintsTheProjectVersion) {
  std::ifstream cmake(std::string(UVTK_SOURCE_DIR) + "/CMakeLists.txt");
  std::stringstream text;
  text << cmake.rdbuf();
  std::smatch version;
  const std::string cmakeText = text.str();
  ASSERT_TRUE(std::regex_search(cmakeText, version, std::regex(R"(project\(uvtk VERSION ([0-9.]+))")));
  const CliRun r = stdoutOf("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.err, "uvtk " + version[1].str() + "\n");
}

// The libraries the dynamic loader initialises for `uvtk ARGUMENTS` (LD_DEBUG=files, on stderr).
TEST_F(CliManners, AMapLoadsNeitherTheBenchPeerNorHighwaysLibrary) {
  const std::string mesh = sphereMesh();
  const CliRun map = shell("LD_DEBUG=files " + std::string(UVTK_BINARY) + " map " + mesh + " -q -o " + path("m.obj"));
  ASSERT_EQ(map.status, 0) << map.err;
  ASSERT_NE(map.err.find("calling init: "), std::string::npos) << "LD_DEBUG said nothing";
  // assimp (and draco, minizip, brotli) start in 4.5 ms, libhwy's timer calibration in 3.3 ms.
  EXPECT_EQ(map.err.find("libassimp"), std::string::npos);
  EXPECT_EQ(map.err.find("libhwy"), std::string::npos);
  // bench's peer opens the plugin, and assimp with it.
  const CliRun bench = shell("LD_DEBUG=files " + std::string(UVTK_BINARY) + " bench --mesh " + mesh +
                             " --projector plane --precision double --math exact --min-time 0.001 --no-end-to-end -q");
  ASSERT_EQ(bench.status, 0) << bench.err.substr(bench.err.size() > 2000 ? bench.err.size() - 2000 : 0);
  EXPECT_NE(bench.err.find("libuvtk_peer_assimp.so"), std::string::npos);
  EXPECT_NE(bench.err.find("libassimp"), std::string::npos);
}

TEST_F(CliManners, AMistypedCommandGetsTheNearestName) {
  const CliRun r = uvtk("mapp x.obj");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "uvtk: error: unknown command 'mapp'; did you mean 'map'?\n");
  EXPECT_EQ(uvtk("merge x.json").err, "uvtk: error: unknown command 'merge'; did you mean 'merge-reports'?\n");
  EXPECT_EQ(uvtk("texgne x.obj").err, "uvtk: error: unknown command 'texgne'; did you mean 'texgen'?\n");
  const CliRun far = uvtk("frobnicate x.obj");
  EXPECT_EQ(far.status, 2);
  EXPECT_EQ(far.err, "uvtk: error: unknown command 'frobnicate'\n");
}

TEST_F(CliManners, AMistypedOptionGetsTheNearestNameOfItsCommand) {
  // Before the missing -o: the unknown option is the mistake to fix first.
  const CliRun r = uvtk("map x.obj --projektor sphere");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "uvtk: error: unknown option '--projektor'; did you mean '--projector'?\n");
  EXPECT_EQ(uvtk("map x.obj --projektor=sphere -o o.obj").err,
            "uvtk: error: unknown option '--projektor'; did you mean '--projector'?\n");
  EXPECT_EQ(uvtk("texgen x.obj --texmatrx 1 -o o.obj").err,
            "uvtk: error: unknown option '--texmatrx'; did you mean '--texmatrix'?\n");
  EXPECT_EQ(uvtk("--verison").err, "uvtk: error: unknown option '--verison'; did you mean '--version'?\n");
  const CliRun far = uvtk("map x.obj --colour red -o o.obj");
  EXPECT_EQ(far.status, 2);
  EXPECT_EQ(far.err, "uvtk: error: unknown option '--colour'\n");
  // Other refusals keep CLI11's words, on one line.
  const CliRun missing = uvtk("map x.obj");
  EXPECT_EQ(missing.status, 2);
  EXPECT_EQ(missing.err, "uvtk: error: --output is required\n");
  EXPECT_EQ(uvtk("").status, 2);  // uvtk alone prints its usage (FirstMinutes below)
}

TEST_F(CliManners, ABadChoiceListsTheNames) {
  const std::string map = "map " + sphereMesh() + " -o " + path("o.obj");
  const CliRun r = uvtk(map + " --projector sphera");
  EXPECT_EQ(r.status, 2);
  // Every surface's name, in the order of the one list (param/placement.h).
  std::string surfaces;
  for (const auto& [name, kind] : param::kSurfaceNames) surfaces += (surfaces.empty() ? "" : ", ") + name;
  EXPECT_EQ(surfaces.rfind("plane, two-plane, cylinder, sphere, cube, camera, triplanar, ", 0), 0u) << surfaces;
  EXPECT_EQ(r.err, "uvtk: error: --projector: 'sphera' is not one of: " + surfaces + "; did you mean 'sphere'?\n");
  // The numbers behind the names are not names.
  const CliRun number = uvtk(map + " --projector 3");
  EXPECT_EQ(number.status, 2);
  EXPECT_EQ(number.err, "uvtk: error: --projector: '3' is not one of: " + surfaces + "\n");
  EXPECT_EQ(uvtk(map + " --axis 2").err, "uvtk: error: --axis: '2' is not one of: x, y, z\n");    // an int choice
  EXPECT_EQ(uvtk(map + " --uv-digits 1").err, "uvtk: error: --uv-digits: '1' is not one of: double, float\n");  // a bool
  EXPECT_FALSE(std::filesystem::exists(path("o.obj")));
}

TEST_F(CliManners, AChoiceSetsTheValueItNamesInAnyCase) {
  // (0.3, 0.4, 0.5) under three projectors with the placement at the origin: the plane's and the
  // cylinder's (u, v) differ, and the name's case does not matter.
  const auto uvs = [&](const std::string& projector) {
    const std::string out = path(projector + ".csv");
    const CliRun r = uvtk("eval --point 0.3,0.4,0.5 --projector " + projector + " -q -o " + out);
    EXPECT_EQ(r.status, 0) << r.err;
    return readText(out);
  };
  const std::string plane = uvs("plane");
  EXPECT_EQ(uvs("PLANE"), plane);
  EXPECT_EQ(uvs("Plane"), plane);
  EXPECT_NE(uvs("cylinder"), plane);
  EXPECT_EQ(uvs("CYLINDER"), uvs("cylinder"));
  EXPECT_EQ(uvtk("map " + sphereMesh() + " --axis Y --uv-digits FLOAT -q -o " + path("o.obj")).status, 0);
}

TEST_F(CliManners, NearestNameIsCloseOrNothing) {
  const std::vector<std::string> projectors = {"plane", "two-plane", "cylinder", "sphere", "cube"};
  EXPECT_EQ(uvtk::nearestName("sphera", projectors), "sphere");  // a substitution
  EXPECT_EQ(uvtk::nearestName("SPHERE", projectors), "sphere");  // case only
  EXPECT_EQ(uvtk::nearestName("two-plnae", projectors), "two-plane");  // neighbours swapped: one edit
  EXPECT_EQ(uvtk::nearestName("cyl", projectors), "cylinder");         // the only name it begins
  EXPECT_EQ(uvtk::nearestName("cub", projectors), "cube");             // one insertion
  EXPECT_EQ(uvtk::nearestName("torus", projectors), "");
  EXPECT_EQ(uvtk::nearestName("x", {"q", "o"}), "");  // one letter for one: not close
  EXPECT_EQ(uvtk::nearestName("pla", {"plane", "planar"}), "");  // begins two: which?
  EXPECT_EQ(uvtk::nearestName("", projectors), "");
  // A third of the longer name: 2 edits in 6 letters are close, 3 are not.
  EXPECT_EQ(uvtk::nearestName("spxxre", {"sphere"}), "sphere");
  EXPECT_EQ(uvtk::nearestName("sxxxre", {"sphere"}), "");
}

TEST_F(CliManners, NameCheckAcceptsExactlyTheNames) {
  const CLI::Validator check = cli::nameCheck({"repeat", "clamp_to_edge", "mirrored_repeat"});
  std::string value = "repeat";
  EXPECT_EQ(check(value), "");
  value = "REPEAT";  // a string option's value is used as typed: no case folding
  EXPECT_EQ(check(value), "'REPEAT' is not one of: repeat, clamp_to_edge, mirrored_repeat; did you mean 'repeat'?");
  value = "clamp";
  EXPECT_EQ(check(value), "'clamp' is not one of: repeat, clamp_to_edge, mirrored_repeat; did you mean 'clamp_to_edge'?");
}

TEST_F(CliManners, EveryHelpEndsWithExamplesThatWork) {
  const std::vector<std::string> names = commands();
  ASSERT_GE(names.size(), 11u);
  // The examples expect the source folder's meshes/ and run in this order (later ones read what
  // earlier ones wrote).
  std::filesystem::copy(std::string(UVTK_SOURCE_DIR) + "/meshes", path("meshes"));
  std::vector<std::string> lines = examples(stdoutOf("--help").err);
  EXPECT_EQ(lines.size(), 2u);
  for (const std::string& name : names) {
    const CliRun help = stdoutOf(name + " --help");
    ASSERT_EQ(help.status, 0) << name;
    const std::vector<std::string> own = examples(help.err);
    EXPECT_TRUE(own.size() == 1 || own.size() == 2) << name << ":\n" << help.err;
    for (const std::string& line : own) {
      EXPECT_NE(line.find("uvtk " + name + " "), std::string::npos) << line;
      lines.push_back(line);
    }
  }
  for (const std::string& line : lines) {
    const std::string command = std::regex_replace(line, std::regex("(^|\\| )uvtk "), "$1" + std::string(UVTK_BINARY) + " ");
    const CliRun r = shell("cd " + dir_.string() + " && " + command);
    EXPECT_EQ(r.status, 0) << line << "\n" << r.err;
  }
  EXPECT_TRUE(std::filesystem::exists(path("demo/obj/sphere_sphere.obj")));
  EXPECT_TRUE(std::filesystem::exists(path("all.json")));
  // The footer that eval had is kept, the examples after it.
  const std::string eval = stdoutOf("eval --help").err;
  EXPECT_LT(eval.find("Exit status: 0 ok"), eval.find("\nExamples:\n"));
  const std::string merge = stdoutOf("merge-reports --help").err;
  EXPECT_EQ(merge.substr(merge.rfind("\nExamples:")),
            "\nExamples:\n"
            "  uvtk merge-reports mapped -o all.json\n"
            "      one report, with totals, of the JSON files that uvtk map wrote into mapped/\n");
}

TEST_F(CliManners, EveryCommandTakesQ) {
  for (const std::string& name : commands()) {
    const std::string help = stdoutOf(name + " --help").err;
    EXPECT_NE(help.find("\n  -q,--quiet "), std::string::npos) << name << ":\n" << help;
  }
  // texgen's -q (quiet) and --q (the q coordinate) are two options.
  const CliRun texgen = uvtk("texgen " + sphereMesh() + " --q object_linear:0,0,0,1 -q -o " + path("t.obj"));
  EXPECT_EQ(texgen.status, 0) << texgen.err;
  EXPECT_EQ(uvtk("schema -q").status, 0);
  // map brings its own: no summary line.
  const CliRun map = uvtk("map " + sphereMesh() + " -q -o " + path("m.obj"));
  EXPECT_EQ(map.status, 0);
  EXPECT_EQ(map.err, "");
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

// The first ten minutes (issue "newcomer", point 3): a command line that says what to do next.
class FirstMinutes : public CliTest {
 protected:
  static std::string bundled(const std::string& name) { return std::string(UVTK_SOURCE_DIR) + "/meshes/" + name; }
};

TEST_F(FirstMinutes, UvtkAlonePrintsItsUsage) {
  const CliRun r = uvtk("");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("Subcommands:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("map"), std::string::npos) << r.err;
}

TEST_F(FirstMinutes, AFailingVerdictSaysWhatWouldAddressIt) {
  // A cylinder seen along its axis folds a torus over itself: flipped and overlapping faces.
  const CliRun r = uvtk("map " + bundled("torus.obj") + " -o " + path("t.obj") + " --projector cylinder --json " +
                        path("t.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("verdict fail"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("uvtk map: advice: one projection cannot cover a closed or curved shape without folding: "
                       "--projector atlas"),
            std::string::npos)
      << r.err;
  std::ifstream in(path("t.json"));
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_FALSE(j["reasons"].empty());
  for (const nlohmann::json& reason : j["reasons"]) EXPECT_FALSE(reason["advice"].get<std::string>().empty()) << reason;
  // The advice taken: the atlas passes.
  const CliRun atlas = uvtk("map " + bundled("torus.obj") + " -o " + path("a.obj") + " --projector atlas");
  EXPECT_NE(atlas.err.find("verdict pass"), std::string::npos) << atlas.err;
  EXPECT_EQ(atlas.err.find("advice"), std::string::npos) << atlas.err;
}

TEST_F(FirstMinutes, AReportWithoutOutputsPrintsASummary) {
  const CliRun r = shell(std::string(UVTK_BINARY) + " report " + bundled("torus.obj") +
                         " --projector cylinder > " + path("out.txt"));
  EXPECT_EQ(r.status, 0) << r.err;
  std::ifstream in(path("out.txt"));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* expected : {"1152 vertices, 2304 faces; UVs from the projector", "verdict fail", "  fail: overlap",
                               "    advice: ", "stretch: L2 ", "seams: ", "overlap: ", "texels at 1024 x 1024: "})
    EXPECT_NE(text.find(expected), std::string::npos) << expected << "\n" << text;
}

TEST_F(FirstMinutes, ABatchCountsItsVerdicts) {
  fs::create_directories(path("in"));
  for (const char* name : {"sphere_latlong.obj", "torus.obj", "cube.obj"}) fs::copy_file(bundled(name), path(std::string("in/") + name));
  const CliRun r = uvtk("map " + path("in") + " -o " + path("out") + " --projector atlas -q");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "uvtk map: 3 meshes mapped (3 pass, 0 warn, 0 fail), 0 failed\n");
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
