#include "inspect/merge_reports.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/json_text.h"

namespace uvtk::inspect {

namespace {

namespace fs = std::filesystem;
// Reports keep the order of their keys, and the merged file reads tool, reports, totals.
using Json = nlohmann::ordered_json;

struct Report {
  std::string path;
  Json report;
};

// The report files an input names: the file itself, or every *.json below a folder, sorted.
std::vector<std::string> reportFiles(const std::string& input) {
  std::error_code error;
  if (!fs::is_directory(input, error)) {
    if (!fs::exists(input, error)) throw InputError(input + ": error: cannot open: no such file or folder");
    return {input};
  }
  std::vector<std::string> files;
  try {
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(input))
      if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path().string());
  } catch (const fs::filesystem_error& e) {
    throw InputError(input + ": error: cannot read the folder: " + e.code().message());
  }
  if (files.empty()) throw InputError(input + ": error: expected .json reports in the folder, found none");
  std::sort(files.begin(), files.end());
  return files;
}

// "FILE:LINE:COLUMN: error: invalid JSON: REASON" for a parse error at the 1-based byte `byte`.
InputError jsonError(const std::string& path, const std::string& text, std::size_t byte, const std::string& what) {
  const auto at = text.begin() + std::ptrdiff_t(std::min(text.size(), byte > 0 ? byte - 1 : 0));
  const auto lineStart = std::find(std::make_reverse_iterator(at), text.rend(), '\n').base();
  const std::size_t line = 1 + std::size_t(std::count(text.begin(), at, '\n'));
  const std::size_t column = std::size_t(at - lineStart) + 1;
  // nlohmann's message is "[json.exception.parse_error.N] parse error at line L, column C: REASON".
  const std::size_t colon = what.find(": ");
  const std::string reason = colon == std::string::npos ? what : what.substr(colon + 2);
  return InputError(path + ":" + std::to_string(line) + ":" + std::to_string(column) +
                    ": error: invalid JSON: " + reason);
}

Json readReport(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": error: cannot open");
  std::stringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path + ": error: cannot read");
  const std::string content = text.str();
  Json report;
  try {
    report = Json::parse(content);
  } catch (const Json::parse_error& e) {
    // Names that are not UTF-8 are written as \udcXX (io/json_text.h): read them back as bytes.
    std::string marked = content;
    if (!io::markLoneByteEscapes(marked)) throw jsonError(path, content, e.byte, e.what());
    try {
      report = io::restoredDocument(Json::parse(marked));
    } catch (const Json::parse_error& again) {
      throw jsonError(path, content, again.byte, again.what());
    }
  }
  if (!report.is_object()) throw InputError(path + ":1:1: error: expected a JSON object, found " + report.type_name());
  return report;
}

bool failed(const Json& report) {
  const auto status = report.find("status");
  if (status != report.end() && *status == "failed") return true;
  const auto failures = report.find("failures");
  return failures != report.end() && (failures->is_array() || failures->is_object()) && !failures->empty();
}

// The failed runs a report records (see the file comment).
std::size_t failedRuns(const Json& report) {
  const auto meshes = report.find("meshes");
  if (meshes == report.end() || !meshes->is_array()) return failed(report) ? 1 : 0;
  return std::size_t(
      std::count_if(meshes->begin(), meshes->end(), [](const Json& mesh) { return mesh.is_object() && failed(mesh); }));
}

// The time a report's run took as a whole: its "wall" (a batch), else its "total" (one mesh).
std::optional<double> runMilliseconds(const Json& milliseconds) {
  for (const char* key : {"wall", "total"}) {
    const auto value = milliseconds.find(key);
    if (value != milliseconds.end() && value->is_number()) return value->get<double>();
  }
  return std::nullopt;
}

Json totalsOf(const std::vector<Report>& reports) {
  std::size_t failedCount = 0;
  std::map<std::string, std::size_t> verdicts{{"pass", 0}, {"warn", 0}, {"fail", 0}};
  std::map<std::string, double> stages;  // sorted keys
  double runSum = 0.0, longest = -1.0;
  std::string longestReport;
  for (const Report& r : reports) {
    failedCount += failedRuns(r.report);
    const auto verdict = r.report.find("verdict");
    if (verdict != r.report.end() && verdict->is_string() && verdicts.count(verdict->get<std::string>()))
      ++verdicts[verdict->get<std::string>()];
    const auto ms = r.report.find("milliseconds");
    if (ms == r.report.end() || !ms->is_object()) continue;
    // A run's whole time is not a stage: runs in parallel overlap, so their sum is work, not time.
    for (const auto& [stage, value] : ms->items())
      if (value.is_number() && stage != "total" && stage != "wall") stages[stage] += value.get<double>();
    if (const std::optional<double> run = runMilliseconds(*ms)) {
      runSum += *run;
      if (*run > longest) longest = *run, longestReport = r.path;
    }
  }
  Json sums = Json::object();
  for (const auto& [stage, value] : stages) sums[stage] = value;
  Json runs = {{"sum", runSum}};
  if (longest >= 0) runs["longest"] = longest, runs["longest_report"] = longestReport;
  return {{"reports", reports.size()},
          {"failed", failedCount},
          {"verdicts", {{"pass", verdicts["pass"]}, {"warn", verdicts["warn"]}, {"fail", verdicts["fail"]}}},
          {"milliseconds", std::move(sums)},
          {"run_milliseconds", std::move(runs)}};
}

}  // namespace

std::string mergeReports(const std::vector<std::string>& inputs, const std::string& output) {
  // A merged file written into a folder it merges must not be merged into itself on the next run,
  // and a file named twice (itself and within a folder) is merged once.
  std::error_code ignored;
  std::set<fs::path> seen = {fs::weakly_canonical(output, ignored)};
  std::vector<Report> reports;
  for (const std::string& input : inputs)
    for (const std::string& file : reportFiles(input))
      if (seen.insert(fs::weakly_canonical(file, ignored)).second) reports.push_back({file, readReport(file)});

  Json totals = totalsOf(reports);
  const Json& verdicts = totals["verdicts"];
  const std::string line = std::to_string(reports.size()) + (reports.size() == 1 ? " report" : " reports") + " merged (" +
                           std::to_string(verdicts["pass"].get<std::size_t>()) + " pass, " +
                           std::to_string(verdicts["warn"].get<std::size_t>()) + " warn, " +
                           std::to_string(verdicts["fail"].get<std::size_t>()) + " fail), " +
                           std::to_string(totals["failed"].get<std::size_t>()) + " failed";
  Json list = Json::array();
  for (Report& r : reports) list.push_back({{"path", r.path}, {"report", std::move(r.report)}});
  const Json merged = {{"tool", {{"name", "uvtk"}, {"version", UVTK_VERSION}}},
                       {"reports", std::move(list)},
                       {"totals", std::move(totals)}};
  io::writeFileAtomically(output, io::jsonText(merged, 2) + "\n");
  return line;
}

}  // namespace uvtk::inspect
