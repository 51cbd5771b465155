// `uvtk map`: assign UVs to a mesh with a projector and write an OBJ with per-corner UVs; or do
// so for every mesh of a folder or a list, several meshes at once, into an output folder
// (docs/scale-out.md).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <vector>

#include "options/cli_values.h"
#include "commands.h"
#include "core/error.h"
#include "core/memory.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/stopwatch.h"
#include "io/atomic_file.h"
#include "io/mesh_reader.h"
#include "io/obj_writer.h"
#include "mapped_mesh.h"
#include "param/projector.h"
#include "options/projector_cli.h"
#include "run_report.h"
#include "verdict_cli.h"

namespace uvtk::cli {

namespace {

namespace fs = std::filesystem;

struct MapArguments {
  std::string input, list, output, json;
  bool writeW = false;
  bool floatDigits = false;
  bool quiet = false;
  int jobs = 0;
  ProjectorArguments projector;
  VerdictArguments verdict;
  int overlapResolution = 1024;
};

// Where one mesh is read and written; no JSON summary when `json` is empty.
struct MeshPaths {
  std::string input, output, json;
};

// One mesh's summary line and its verdict.
struct MeshResult {
  std::string numbers;
  analysis::Verdict verdict = analysis::Verdict::Pass;
};

// Memory before work: the peak of a map, measured, is 2.8 bytes per byte of OBJ (3.12 GB for a
// 1.13 GB file of 20 M triangles, docs/robustness.md); a file the machine cannot map that way is
// refused before it is read, and a large one announced.
void checkMapMemory(const std::string& input) {
  constexpr std::uint64_t kBytesPerFileByte = 3;
  constexpr std::uint64_t kLargeMapBytes = std::uint64_t(1) << 30;
  std::error_code error;
  const std::uintmax_t fileBytes = std::filesystem::file_size(input, error);
  if (error) return;  // the reader says what is wrong with the file
  const std::uint64_t needed = kBytesPerFileByte * fileBytes;
  const std::optional<std::uint64_t> available = availableMemory();
  if (available && needed > *available)
    throw InputError(input + ": error: mapping it needs about " + formatBytes(needed) + " of memory, more than the " +
                     formatBytes(*available) + " available");
  if (needed > kLargeMapBytes && progressEnabled())
    printProgressMessage("uvtk map " + input + ": about " + formatBytes(needed) + " of memory" +
                         (available ? " (" + formatBytes(*available) + " available)" : ""));
}

// Reads, maps, judges and writes one mesh (and its JSON summary, published together with it),
// prints the input's notes, and returns its summary line. The stages are shown on a terminal only
// with `showStages`.
MeshResult mapMesh(const MeshPaths& paths, const MapArguments& a, const param::ProjectorOptions& options,
                    bool showStages) {
  StageClock clock("uvtk map", showStages);
  checkMapMemory(paths.input);
  clock.start("reading", paths.input);
  io::ReadMeshResult input = io::readMesh(paths.input);
  const double readMs = clock.stop();
  const nlohmann::json inputSummary = inputJson(paths.input, input);

  clock.start("mapping", std::to_string(input.mesh.faceCount()) + " faces");
  const MappedMesh mapped = mapByProjector(std::move(input.mesh), options, a.projector.seamPlaceAuto());
  const double mapMs = clock.stop();
  const param::MappingSummary& s = mapped.projection->summary;

  clock.start("judging", std::to_string(mapped.mesh.faceCount()) + " faces");
  const analysis::Judgement judgement = mapped.judge(a.verdict.thresholds(), a.overlapResolution);
  const double judgeMs = clock.stop();

  clock.start("writing", paths.output);
  io::ObjWriteOptions write;
  write.writeW = a.writeW;
  write.floatPrecision = a.floatDigits;
  write.header = "uvtk map " + paths.input;
  io::OutputSet outputs;
  io::writeObj(outputs, paths.output, mapped.mesh, &mapped.uv, write);
  const double writeMs = clock.stop();

  if (!paths.json.empty()) {
    nlohmann::json j = mapSummaryJson(mapped, judgement, inputSummary, paths.output);
    j["milliseconds"] = {{"read", readMs}, {"map", mapMs}, {"judge", judgeMs}, {"write", writeMs}};
    outputs.writeText(paths.json, j.dump(2) + "\n");
  }
  outputs.publish();
  printMappingNotes(paths.input, input.warnings, mapped);
  const analysis::Summary& measured = judgement.summary;
  char numbers[256];
  std::snprintf(numbers, sizeof numbers,
                "%zu vertices, %zu faces, %zu seam edges, %zu pole vertices, %zu pole faces, %zu invalid vertices, "
                "%.1f ms; ",
                s.vertices, s.faces, measured.seams.wrapEdges + measured.seams.cutEdges, measured.poleVertices.size(),
                measured.poleFaces, s.invalidVertices, mapMs);
  return {numbers + verdictLine(judgement), judgement.verdict};
}

std::string lowercaseExtension(const fs::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; });
  return extension;
}

// Every .obj and .off file directly in `folder`, sorted by name.
std::vector<std::string> meshesInFolder(const std::string& folder) {
  std::vector<fs::path> found;
  try {
    for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
      const std::string extension = lowercaseExtension(entry.path());
      if (entry.is_regular_file() && (extension == ".obj" || extension == ".off")) found.push_back(entry.path());
    }
  } catch (const fs::filesystem_error& e) {
    throw InputError(folder + ": error: cannot read the folder: " + e.code().message());
  }
  std::sort(found.begin(), found.end(),
            [](const fs::path& x, const fs::path& y) { return x.filename() < y.filename(); });
  std::vector<std::string> meshes;
  for (const fs::path& path : found) meshes.push_back(path.string());
  if (meshes.empty()) throw InputError(folder + ": error: expected .obj or .off files in the folder, found none");
  return meshes;
}

// The paths of a list file, one a line, relative to the list's folder; blank lines and lines whose
// first non-blank character is '#' are skipped (a '#' later on a line belongs to the file name).
std::vector<std::string> meshesInList(const std::string& list) {
  std::error_code ignored;
  std::ifstream in(list);
  if (fs::is_directory(list, ignored) || !in) throw InputError(list + ": error: cannot open the list of meshes");
  const fs::path folder = fs::path(list).parent_path();
  std::vector<std::string> meshes;
  for (std::string line; std::getline(in, line);) {
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const fs::path path = line.substr(first, line.find_last_not_of(" \t\r") + 1 - first);
    meshes.push_back((path.is_absolute() ? path : folder / path).string());
  }
  if (meshes.empty()) throw InputError(list + ": error: expected mesh paths in the list, found none");
  return meshes;
}

// The paths of every mesh of a batch: OUTDIR/STEM.obj and JSONDIR/STEM.json. Throws UsageError
// before any work when two inputs share a stem, when an output would replace an input, or when a
// summary would be named like the batch's own batch.json.
std::vector<MeshPaths> batchPaths(const std::vector<std::string>& inputs, const MapArguments& a) {
  std::map<std::string, std::string> inputOfStem;
  std::set<fs::path> inputFiles;
  std::error_code ignored;
  for (const std::string& input : inputs) inputFiles.insert(fs::weakly_canonical(input, ignored));
  std::vector<MeshPaths> paths;
  for (const std::string& input : inputs) {
    const std::string stem = fs::path(input).stem().string();
    MeshPaths p{input, (fs::path(a.output) / (stem + ".obj")).string(), ""};
    const auto [other, fresh] = inputOfStem.emplace(stem, input);
    if (!fresh) throw UsageError("two meshes would be written to " + p.output + ": " + other->second + " and " + input);
    if (inputFiles.count(fs::weakly_canonical(p.output, ignored)))
      throw UsageError(p.output + " would replace an input mesh: choose another output folder");
    if (!a.json.empty()) {
      if (stem == "batch") throw UsageError(input + ": its summary would replace batch.json in " + a.json);
      p.json = (fs::path(a.json) / (stem + ".json")).string();
    }
    paths.push_back(std::move(p));
  }
  return paths;
}

void createFolder(const std::string& folder) {
  std::error_code error;
  fs::create_directories(folder, error);
  if (error || !fs::is_directory(folder))
    throw OutputError(folder + ": error: cannot create the folder: " +
                      (error ? error.message() : std::string("a file has that name")));
}

// How one mesh of a batch ended: its exit status (0, or that of its error's class as main maps
// them), the error's one-line message, and its time.
struct MeshOutcome {
  int status = 0;
  std::string error;
  double milliseconds = 0.0;
  analysis::Verdict verdict = analysis::Verdict::Pass;
};

// Maps one mesh of a batch; a failure is recorded and printed, never thrown.
MeshOutcome mapBatchMesh(const MeshPaths& paths, const MapArguments& a, const param::ProjectorOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  MeshOutcome outcome;
  try {
    const MeshResult result = mapMesh(paths, a, options, false);
    outcome.verdict = result.verdict;
    if (!a.quiet) printProgressMessage("uvtk map: " + paths.input + ": " + result.numbers);
  } catch (const std::exception& e) {
    // A usage error here is a check of the options that only mapping the mesh makes.
    const int status = exitStatus(e);
    outcome = {status, status == 3 || status == 4
                           ? std::string(e.what())
                           : paths.input + (status == 2 ? ": error: " : ": internal error: ") + e.what()};
  }
  if (outcome.status != 0) printProgressMessage(outcome.error);
  outcome.milliseconds = millisecondsSince(start);
  return outcome;
}

// The record of a batch: every mesh with its status, error and time (the per-mesh numbers are in
// the summaries beside it, so that merging the folder whole counts each once).
nlohmann::json batchJson(const std::vector<MeshPaths>& paths, const std::vector<MeshOutcome>& outcomes,
                         const param::ProjectorOptions& options, int threads, double wallMs) {
  nlohmann::json meshes = nlohmann::json::array();
  std::size_t failed = 0;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const bool ok = outcomes[i].status == 0;
    nlohmann::json mesh = {{"input", paths[i].input},
                           {"output", paths[i].output},
                           {"status", ok ? "ok" : "failed"},
                           {"milliseconds", outcomes[i].milliseconds}};
    if (ok) {
      mesh["summary"] = paths[i].json;
      mesh["verdict"] = analysis::toString(outcomes[i].verdict);
    } else
      mesh["error"] = outcomes[i].error;
    failed += !ok;
    meshes.push_back(std::move(mesh));
  }
  return {{"tool", {{"name", "uvtk"}, {"version", UVTK_VERSION}}},
          {"options", projectorOptionsJson(options)},
          {"jobs", threads},
          {"meshes", std::move(meshes)},
          {"mapped", paths.size() - failed},
          {"failed", failed},
          {"milliseconds", {{"wall", wallMs}}}};
}

// Every mesh of `inputs`, `--jobs` at a time, each mapped on one thread; a failing mesh does not
// stop the others. The exit status is the highest of the failures'. Each mesh's OBJ and summary
// are published together when it is done, and batch.json at the end: a batch is many independent
// runs (an interrupted one leaves the meshes done so far, each whole), not one output.
void mapBatch(const std::vector<std::string>& inputs, const MapArguments& a, const param::ProjectorOptions& options) {
  const std::vector<MeshPaths> paths = batchPaths(inputs, a);
  createFolder(a.output);
  if (!a.json.empty()) createFolder(a.json);
  const auto start = std::chrono::steady_clock::now();
  const int threads = std::min(threadCount(a.jobs), int(paths.size()));
  std::vector<MeshOutcome> outcomes(paths.size());
  {
    Progress progress("mapping", paths.size(), "meshes");
    parallelFor(int(paths.size()), threads, [&](int i) {
      outcomes[std::size_t(i)] = mapBatchMesh(paths[std::size_t(i)], a, options);
      progress.advance();
    });
  }
  int status = 0;
  std::size_t failed = 0;
  analysis::Verdict worst = analysis::Verdict::Pass;
  for (const MeshOutcome& o : outcomes) {
    status = std::max(status, o.status);
    failed += o.status != 0;
    if (o.status == 0) worst = std::max(worst, o.verdict);
  }
  if (!a.json.empty())
    io::writeFileAtomically((fs::path(a.json) / "batch.json").string(),
                            batchJson(paths, outcomes, options, threads, millisecondsSince(start)).dump(2) + "\n");
  const std::string line =
      "uvtk map: " + std::to_string(paths.size() - failed) + " meshes mapped, " + std::to_string(failed) + " failed";
  if (status != 0) throwWithStatus(status, line);  // main prints the line
  std::fprintf(stderr, "%s\n", line.c_str());
  enforceVerdict(a.verdict, worst, "uvtk map");
}

void runMap(const MapArguments& a) {
  if (a.quiet) setProgressEnabled(false);
  if (a.input.empty() == a.list.empty()) throw UsageError("expected a mesh, a folder of meshes or --list FILE");
  const param::ProjectorOptions options = a.projector.resolve();
  a.verdict.check();
  if (a.overlapResolution < 1 || a.overlapResolution > 16384)
    throw UsageError("--overlap-resolution: expected 1 to 16384 pixels");
  std::error_code ignored;
  if (!a.list.empty()) return mapBatch(meshesInList(a.list), a, options);
  if (fs::is_directory(a.input, ignored)) return mapBatch(meshesInFolder(a.input), a, options);
  const MeshResult result = mapMesh({a.input, a.output, a.json}, a, options, true);
  if (!a.quiet) std::fprintf(stderr, "uvtk map: %s\n", result.numbers.c_str());
  enforceVerdict(a.verdict, result.verdict, "uvtk map");
}

}  // namespace

void addMapCommand(CLI::App& root) {
  auto arguments = std::make_shared<MapArguments>();
  CLI::App* map = root.add_subcommand("map", "Assign UVs with a projector (Bier & Sloan two-stage mapping)");
  CLI::Option* input = map->add_option(
      "input", arguments->input, "Input mesh (.obj or .off), or a folder: every .obj and .off in it, into -o's folder");
  map->add_option("--list", arguments->list,
                  "A file of mesh paths, one a line (relative to its folder; # comments), into -o's folder")
      ->excludes(input);
  map->add_option("-o,--output", arguments->output, "Output OBJ with per-corner UVs (a folder for many meshes)")
      ->required();
  map->add_option("--json", arguments->json,
                  "Also write the summary as JSON (for many meshes: a folder, with STEM.json each and batch.json)");
  map->add_option("-j,--jobs", arguments->jobs, "Meshes mapped at once when there are many; 0: one per hardware thread")
      ->check(CLI::NonNegativeNumber)
      ->default_str("0");
  map->add_flag("-q,--quiet", arguments->quiet, "No progress and no summary lines; errors are still printed");
  map->add_flag("--write-w", arguments->writeW, "Write the third UV component (the cube face id)");
  addChoice<bool>(*map, "--uv-digits", arguments->floatDigits, {{"double", false}, {"float", true}},
                  "UV text that round-trips a double (up to 17 digits) or a float (up to 9)")
      ->default_str("double");
  addProjectorOptions(*map, arguments->projector);
  addVerdictOptions(*map, arguments->verdict);
  map->add_option("--overlap-resolution", arguments->overlapResolution,
                  "Pixels across the layout raster that measures overlap for the verdict")
      ->capture_default_str();
  map->callback([arguments] { runMap(*arguments); });
}

}  // namespace uvtk::cli
