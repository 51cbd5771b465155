// `uvtk merge-reports` as a user runs it: reports from files and folders, the totals, and an
// invalid report as an input error that writes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "apps/cli_test.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

using MergeReportsCli = CliTest;

nlohmann::json readJson(const std::string& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

TEST_F(MergeReportsCli, MergesMapSummariesAndAFolderWithTotals) {
  const std::string sphere = std::string(UVTK_MESHES_DIR) + "/sphere_latlong.obj";
  const std::string torus = std::string(UVTK_MESHES_DIR) + "/torus.obj";
  ASSERT_EQ(uvtk("map " + sphere + " -o " + path("a.obj") + " --json " + path("a.json")).status, 0);
  ASSERT_EQ(uvtk("map " + torus + " -o " + path("b.obj") + " --json " + path("b.json")).status, 0);
  // A batch of two good meshes and a bad one: its folder holds two summaries and batch.json.
  fs::create_directories(path("in"));
  fs::copy_file(sphere, path("in/sphere.obj"));
  fs::copy_file(torus, path("in/torus.obj"));
  writeText("in/bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n");
  ASSERT_EQ(uvtk("map " + path("in") + " -o " + path("out") + " --json " + path("batch")).status, 3);

  const CliRun r = uvtk("merge-reports -o " + path("merged.json") + " " + path("a.json") + " " + path("b.json") + " " +
                        path("batch"));
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json merged = readJson(path("merged.json"));
  EXPECT_EQ(merged["tool"]["name"], "uvtk");
  const std::vector<std::string> files = {"a.json", "b.json", "batch/batch.json", "batch/sphere.json",
                                          "batch/torus.json"};
  ASSERT_EQ(merged["reports"].size(), files.size()) << merged;
  double read = 0.0, wall = 0.0;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const nlohmann::json& entry = merged["reports"][i];
    EXPECT_EQ(entry["path"], path(files[i]));
    EXPECT_EQ(entry["report"], readJson(path(files[i]))) << files[i];
    read += entry["report"]["milliseconds"].value("read", 0.0);
    wall += entry["report"]["milliseconds"].value("wall", 0.0);
  }
  EXPECT_EQ(merged["totals"]["reports"], 5);
  EXPECT_EQ(merged["totals"]["failed"], 1);  // bad.off, in batch.json
  // The sphere and the torus, twice each (a.json, b.json and the batch's summaries): verdicts recounted.
  std::map<std::string, int> verdicts{{"pass", 0}, {"warn", 0}, {"fail", 0}};
  for (const char* file : {"a.json", "b.json", "batch/sphere.json", "batch/torus.json"})
    ++verdicts[readJson(path(file))["verdict"].get<std::string>()];
  EXPECT_EQ(merged["totals"]["verdicts"], nlohmann::json(verdicts));
  EXPECT_DOUBLE_EQ(merged["totals"]["milliseconds"]["read"].get<double>(), read);
  // A run's whole time is not summed as a stage (runs in parallel overlap): its sum and longest.
  EXPECT_FALSE(merged["totals"]["milliseconds"].contains("wall"));
  EXPECT_FALSE(merged["totals"]["milliseconds"].contains("total"));
  double runs = 0.0, longest = 0.0;
  for (const std::string& file : files) {
    const nlohmann::json ms = readJson(path(file))["milliseconds"];
    const double run = ms.contains("wall") ? ms["wall"].get<double>() : ms["total"].get<double>();
    runs += run, longest = std::max(longest, run);
  }
  EXPECT_DOUBLE_EQ(merged["totals"]["run_milliseconds"]["sum"].get<double>(), runs);
  EXPECT_DOUBLE_EQ(merged["totals"]["run_milliseconds"]["longest"].get<double>(), longest);
  EXPECT_GT(read, 0.0);
  EXPECT_GT(wall, 0.0);
  const CliRun line = shell(std::string(UVTK_BINARY) + " merge-reports -o " + path("merged.json") + " " + path("a.json") +
                            " " + path("b.json") + " " + path("batch") + " > " + path("line.txt"));
  ASSERT_EQ(line.status, 0);
  EXPECT_EQ(readText(path("line.txt")), "uvtk merge-reports: 5 reports merged (" + std::to_string(verdicts["pass"]) +
                                            " pass, " + std::to_string(verdicts["warn"]) + " warn, " +
                                            std::to_string(verdicts["fail"]) + " fail), 1 failed\n");
}

TEST_F(MergeReportsCli, CountsFailedReportsAndSumsMillisecondsPerKey) {
  fs::create_directories(path("reports/deeper"));
  writeText("reports/1.json", R"({"status": "failed", "milliseconds": {"render": 1.5, "total": 2}})");
  writeText("reports/2.json", R"({"status": "ok", "failures": [], "milliseconds": {"render": 2.5}})");
  writeText("reports/deeper/3.json", R"({"failures": [{"scene": "x"}], "milliseconds": {"total": "n/a"}})");
  writeText("reports/notes.txt", "not a report");
  writeText("batch.json", R"({"meshes": [{"status": "ok"}, {"status": "failed"}, {"status": "failed"}],
                              "milliseconds": {"wall": 4}})");
  // The merged file lies in a folder it merges: a second run must not merge it into itself.
  for (int run = 0; run < 2; ++run) {
    const CliRun r =
        uvtk("merge-reports -o " + path("reports/merged.json") + " " + path("reports") + " " + path("batch.json"));
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json totals = readJson(path("reports/merged.json"))["totals"];
    EXPECT_EQ(totals["reports"], 4) << run;
    EXPECT_EQ(totals["failed"], 4) << run;  // 1.json, 3.json and the two failed meshes of batch.json
    EXPECT_EQ(totals["milliseconds"], nlohmann::json({{"render", 4.0}})) << run;
    EXPECT_EQ(totals["run_milliseconds"],
              nlohmann::json({{"sum", 6.0}, {"longest", 4.0}, {"longest_report", path("batch.json")}})) << run;
    EXPECT_EQ(totals["verdicts"], nlohmann::json({{"pass", 0}, {"warn", 0}, {"fail", 0}})) << run;
  }
}

TEST_F(MergeReportsCli, AnInvalidReportIsAnInputErrorNamingItsLineAndColumnAndWritesNothing) {
  writeText("good.json", R"({"status": "ok"})");
  writeText("bad.json", "{\n  \"a\": 1,\n  \"b\": x\n}\n");
  const CliRun r = uvtk("merge-reports -o " + path("merged.json") + " " + path("good.json") + " " + path("bad.json"));
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find(path("bad.json") + ":3:8: error: invalid JSON"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("merged.json")));

  writeText("array.json", "[1, 2]");
  const CliRun notAnObject = uvtk("merge-reports -o " + path("merged.json") + " " + path("array.json"));
  EXPECT_EQ(notAnObject.status, 3);
  EXPECT_NE(notAnObject.err.find("array.json:1:1: error: expected a JSON object, found array"), std::string::npos)
      << notAnObject.err;
  const CliRun missing = uvtk("merge-reports -o " + path("merged.json") + " " + path("missing.json"));
  EXPECT_EQ(missing.status, 3);
  EXPECT_NE(missing.err.find("missing.json: error: cannot open"), std::string::npos) << missing.err;
  EXPECT_FALSE(fs::exists(path("merged.json")));
}

TEST_F(MergeReportsCli, AnUnwritableOutputIsExitStatusFour) {
  writeText("good.json", R"({"status": "ok"})");
  const CliRun r = uvtk("merge-reports -o " + path("no/such/folder/merged.json") + " " + path("good.json"));
  EXPECT_EQ(r.status, 4) << r.err;
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
