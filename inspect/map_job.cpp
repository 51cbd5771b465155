#include "inspect/map_job.h"

#include <algorithm>
#include <atomic>
#include <numeric>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "core/error.h"
#include "core/memory.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/stopwatch.h"
#include "inspect/mapped_mesh.h"
#include "inspect/run_report.h"
#include "inspect/verdict.h"
#include "io/atomic_file.h"
#include "io/gltf_writer.h"
#include "io/mesh_format.h"
#include "io/mesh_reader.h"
#include "io/mesh_format.h"
#include "io/mesh_writer.h"
#include "inspect/projector_json.h"
#include "param/projector_names.h"
#include "io/json_text.h"

namespace uvtk::inspect {

namespace fs = std::filesystem;

// The peak of a map, measured, is 2.8 bytes per byte of OBJ (3.12 GB for a 1.13 GB file of 20 M
// triangles, docs/robustness.md).
// A map needing under 64 MiB is not checked: reading the memory limits (/proc/meminfo, the control
// groups' files) took 0.14 ms, a tenth of a 10 k-face map's work.
void checkMapMemory(const std::string& input) {
  constexpr std::uint64_t kBytesPerFileByte = 3;
  constexpr std::uint64_t kUncheckedMapBytes = std::uint64_t(64) << 20;
  constexpr std::uint64_t kLargeMapBytes = std::uint64_t(1) << 30;
  std::error_code error;
  const std::uintmax_t fileBytes = std::filesystem::file_size(input, error);
  if (error) return;  // the reader says what is wrong with the file
  const std::uint64_t needed = kBytesPerFileByte * fileBytes;
  if (needed < kUncheckedMapBytes) return;
  const std::optional<std::uint64_t> available = availableMemory();
  if (available && needed > *available)
    throw InputError(input + ": error: mapping it needs about " + formatBytes(needed) + " of memory, more than the " +
                     formatBytes(*available) + " available");
  if (needed > kLargeMapBytes && progressEnabled())
    printProgressMessage("uvtk map " + input + ": about " + formatBytes(needed) + " of memory" +
                         (available ? " (" + formatBytes(*available) + " available)" : ""));
}

namespace {

std::string numberText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace

double scaleToTexelDensity(MappedMesh& mapped, const analysis::Judgement& judgement, double density,
                           const std::string& path) {
  UVTK_CHECK(density > 0.0 && std::isfinite(density));
  const analysis::TexelDensity& d = judgement.summary.density;
  const auto refuse = [&](const std::string& why) {
    throw InputError(path + ": error: --density " + numberText(density) + ": " + why);
  };
  if (judgement.statusCount(analysis::FaceStatus::Ok) == 0) refuse("no face is ok, so there is no texel density to scale");
  if (!d.finite || !(d.statistics.mean > 0.0))
    refuse("the mean texel density is not a finite positive number of texels per unit");
  const double factor = density / d.statistics.mean;
  std::vector<Vec2> scaled = mapped.uv.uv;
  for (std::size_t corner = 0; corner < scaled.size(); ++corner) {
    if (!mapped.uv.cornerInvalid.empty() && mapped.uv.cornerInvalid[corner] != kCornerValid) continue;
    scaled[corner] *= factor;
    if (!scaled[corner].allFinite()) refuse("the scaled UVs would not be finite (factor " + numberText(factor) + ")");
  }
  mapped.uv.uv = std::move(scaled);
  mapped.uvScale *= factor;
  return factor;
}

// Below this many faces (one chunk of the judgement's loops) `uvtk map` writes the file while it
// judges the mapping (mapMesh).
constexpr std::size_t kWriteWhileJudgingFaces = analysis::kFacesPerChunk;

MeshResult mapMesh(const MeshPaths& paths, const MapJob& job, bool showStages) {
  const auto start = std::chrono::steady_clock::now();
  StageClock clock("uvtk map", showStages);
  checkMapMemory(paths.input);
  clock.start("reading", paths.input);
  io::ReadMeshResult input = io::readMesh(paths.input, job.settings.threads);
  const double readMs = clock.stop();
  const nlohmann::json inputSummary = inputJson(paths.input, input);

  clock.start("mapping", std::to_string(input.mesh.faceCount()) + " faces");
  const MapSettings& settings = job.settings;
  MappedMesh mapped =
      mapByProjector(std::move(input.mesh), settings.projector.options, settings.projector.seamPlaceAuto, settings.threads);
  const double mapMs = clock.stop();
  const param::MappingSummary& s = mapped.projection->summary;

  io::MeshWriteOptions write = job.write;
  write.header = "uvtk map " + paths.input;
  write.threads = job.settings.threads;
  io::OutputSet outputs;
  double writeMs = 0.0;
  const auto writeOutput = [&] {
    const auto begin = std::chrono::steady_clock::now();
    io::writeMesh(outputs, paths.output, mapped.mesh, &mapped.uv, write);
    writeMs = millisecondsSince(begin);
  };
  // Without --density the file does not depend on the judgement, and both only read `mapped`. A
  // small mesh's judging and writing each run mostly on one thread (their loops share out chunks
  // of kFacesPerChunk faces), so its file is written on another while it is judged: the 10 k-face sphere
  // 13.1 to 11.8 ms. A large mesh's stages already fill every core; together they took as long
  // and 35 MB more (the 4 M-face lat-long sphere, docs/benchmarks.md). WorkAside's destructor
  // waits for the writing, so an exception from the judgement leaves nothing running (and nothing
  // published: `outputs` is published only at the end).
  const bool writeWhileJudging = !settings.density && mapped.mesh.faceCount() < kWriteWhileJudgingFaces;
  if (writeWhileJudging) write.threads = 1;  // beside the judgement, which has the cores
  std::optional<WorkAside<decltype(writeOutput)>> writing;
  if (writeWhileJudging) writing.emplace(writeOutput, true);
  clock.start(writeWhileJudging ? "judging and writing" : "judging", std::to_string(mapped.mesh.faceCount()) + " faces");
  analysis::Judgement judgement = mapped.judge(settings.thresholds, settings.overlapResolution, settings.threads, settings.textureSize);
  double densityFactor = 1.0;
  if (settings.density) {  // judged again: the summary and the verdict are those of the UVs written
    densityFactor = scaleToTexelDensity(mapped, judgement, *settings.density, paths.input);
    judgement = mapped.judge(settings.thresholds, settings.overlapResolution, settings.threads, settings.textureSize);
  }
  const double judgeMs = clock.stop();
  nlohmann::json summary;
  if (!paths.json.empty()) {
    summary = mapSummaryJson(mapped, judgement, inputSummary, paths.output);
    if (settings.density) summary["density_scale"] = {{"density", *settings.density}, {"factor", densityFactor}};
  }
  // The measured faces whose UV triangle glTF's float32 collapses (the others have no area to lose).
  std::size_t collapsedUvFaces = 0;
  const bool gltf = io::isGltf(*io::outputFormatOf(paths.output));
  for (std::size_t f = 0; gltf && f < judgement.faces.size(); ++f)
    collapsedUvFaces += analysis::isMeasured(judgement.faces[f].status) &&
                        io::collapsesInGltfTexcoords(mapped.uv.uv[3 * f], mapped.uv.uv[3 * f + 1], mapped.uv.uv[3 * f + 2]);
  judgement.faces = {};  // every face's measures: not needed while writing

  if (writing) {
    writing->get();
  } else {
    clock.start("writing", paths.output);
    writeOutput();
    clock.stop();
  }
  if (gltf && !paths.json.empty()) summary["output_collapsed_uv_faces"] = collapsedUvFaces;

  if (!paths.json.empty()) {
    // The mapping stage split as the projection measured it: seams (repair and summary) and the
    // rest (placement, both stages, --seam-place auto).
    const double seamsMs = mapped.projection->milliseconds.seams;
    summary["milliseconds"] = {{"read", readMs},   {"map", mapMs - seamsMs}, {"seams", seamsMs},
                               {"judge", judgeMs}, {"write", writeMs},       {"total", millisecondsSince(start)}};
    outputs.writeText(paths.json, io::jsonText(summary, 2) + "\n");
  }
  outputs.publish();
  const double totalMs = millisecondsSince(start);  // what the user waited for, read to published output
  printMappingNotes(paths.input, input.warnings, mapped);
  if (collapsedUvFaces > 0) {
    const Eigen::AlignedBox2d& box = judgement.summary.uvBounds;
    const Vec2 size = box.sizes(), centre = 0.5 * box.min() + 0.5 * box.max();
    // Far from [0, 1] the steps are coarse and placing the layout helps; near it only slivers collapse.
    const bool far = box.min().cwiseAbs().maxCoeff() > 2.0 || box.max().cwiseAbs().maxCoeff() > 2.0;
    printProgressMessage(paths.output + ": warning: " + std::to_string(collapsedUvFaces) +
                         " faces' UVs have zero area as glTF holds them (float32 u, 1 - v): the layout is " +
                         numberText(size.x()) + " x " + numberText(size.y()) + " about (" + numberText(centre.x()) +
                         ", " + numberText(centre.y()) + ")" +
                         (far ? "; --uv-scale, --uv-offset or --fit bring it near [0, 1]"
                              : ": faces finer than float32's steps (2^-24 near 1)"));
  }
  if (param::traitsOf(job.settings.projector.options.surface).blendsProjections && !quiet()) {
    char note[256];
    std::snprintf(note, sizeof note,
                  "uvtk map: %s holds one UV per corner, not a triplanar blend: each face has its dominant axis's "
                  "projection (a box mapping: %zu faces x, %zu y, %zu z); uvtk render shows the blend",
                  paths.output.c_str(), s.triplanarFaces[0], s.triplanarFaces[1], s.triplanarFaces[2]);
    printProgressMessage(note);
  }
  const analysis::Summary& measured = judgement.summary;
  char numbers[256];
  std::snprintf(numbers, sizeof numbers,
                "%zu vertices, %zu faces, %zu seam edges, %zu pole vertices, %zu pole faces, %zu invalid vertices, "
                "%.1f ms; ",
                s.vertices, s.faces, measured.seams.wrapEdges + measured.seams.cutEdges, measured.poleVertices.size(),
                measured.poleFaces, s.invalidVertices, totalMs);
  const std::optional<analysis::Gutters> gutters = mapped.atlasGutters();
  const std::string atlas = gutters ? atlasLine(*mapped.projection->atlas, *gutters) + "; " : "";
  MeshResult result{numbers + atlas + verdictLine(judgement), judgement.verdict, {}};
  for (const analysis::Reason& reason : judgement.reasons) {
    const std::string advice = analysis::adviceOf(reason.rule);
    if (std::find(result.advice.begin(), result.advice.end(), advice) == result.advice.end())
      result.advice.push_back(advice);
  }
  return result;
}

std::vector<std::string> meshesInFolder(const std::string& folder) {
  std::vector<fs::path> found;
  try {
    for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
      if (entry.is_regular_file() && io::meshFormatOf(entry.path().string())) found.push_back(entry.path());
    }
  } catch (const fs::filesystem_error& e) {
    throw InputError(folder + ": error: cannot read the folder: " + e.code().message());
  }
  std::sort(found.begin(), found.end(),
            [](const fs::path& x, const fs::path& y) { return x.filename() < y.filename(); });
  std::vector<std::string> meshes;
  for (const fs::path& path : found) meshes.push_back(path.string());
  if (meshes.empty())
    throw InputError(folder + ": error: expected mesh files (.obj, .off, .ply, .stl, .gltf, .glb) in the folder, found none");
  return meshes;
}

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

namespace {

// The paths of every mesh of a batch: OUTDIR/STEM.EXT (EXT the format asked for) and JSONDIR/STEM.json. Throws UsageError
// before any work when two inputs share a stem, when an output would replace an input, or when a
// summary would be named like the batch's own batch.json.
std::vector<MeshPaths> batchPaths(const std::vector<std::string>& inputs, const std::string& output,
                                  const std::string& json, io::MeshFormat format) {
  std::map<std::string, std::string> inputOfStem;
  std::set<fs::path> inputFiles;
  std::error_code ignored;
  for (const std::string& input : inputs) inputFiles.insert(fs::weakly_canonical(input, ignored));
  std::vector<MeshPaths> paths;
  for (const std::string& input : inputs) {
    const std::string stem = fs::path(input).stem().string();
    MeshPaths p{input, (fs::path(output) / (stem + io::extensionOf(format))).string(), ""};
    const auto [other, fresh] = inputOfStem.emplace(stem, input);
    if (!fresh) throw UsageError("two meshes would be written to " + p.output + ": " + other->second + " and " + input);
    if (inputFiles.count(fs::weakly_canonical(p.output, ignored)))
      throw UsageError(p.output + " would replace an input mesh: choose another output folder");
    if (!json.empty()) {
      if (stem == "batch") throw UsageError(input + ": its summary would replace batch.json in " + json);
      p.json = (fs::path(json) / (stem + ".json")).string();
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
MeshOutcome mapBatchMesh(const MeshPaths& paths, const MapJob& job, bool quiet) {
  const auto start = std::chrono::steady_clock::now();
  MeshOutcome outcome;
  try {
    const MeshResult result = mapMesh(paths, job, false);
    outcome.verdict = result.verdict;
    if (!quiet) printProgressMessage("uvtk map: " + paths.input + ": " + result.numbers);
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
          {"options", inspect::projectorOptionsJson(options)},
          {"jobs", threads},
          {"meshes", std::move(meshes)},
          {"mapped", paths.size() - failed},
          {"failed", failed},
          {"milliseconds", {{"wall", wallMs}}}};
}

}  // namespace

BatchResult mapBatch(const std::vector<std::string>& inputs, const std::string& output, const std::string& json,
                     int jobs, bool quiet, const MapJob& job) {
  // Each mesh's OBJ and summary are published together when it is done, and batch.json at the
  // end: a batch is many independent runs (an interrupted one leaves the meshes done so far, each
  // whole), not one output.
  const std::vector<MeshPaths> paths = batchPaths(inputs, output, json, job.batchFormat);
  createFolder(output);
  if (!json.empty()) createFolder(json);
  const auto start = std::chrono::steady_clock::now();
  const int count = int(paths.size()), threads = std::min(threadCount(jobs), count);
  // Each mesh takes its share of the cores (unless --threads says). The smallest files go first, so
  // that the largest start last; a mesh started with fewer meshes left than workers, and at least
  // 4 times the bytes of each mesh still running, takes the cores the finished workers leave: a
  // folder of small meshes and one large one ends as soon as the large one alone would, and equal
  // meshes never share a core.
  std::vector<std::size_t> order(paths.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::vector<std::uintmax_t> bytes(paths.size());
  for (std::size_t i = 0; i < paths.size(); ++i) {
    std::error_code error;
    bytes[i] = fs::file_size(paths[i].input, error);
    if (error) bytes[i] = 0;  // its read reports the problem
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return bytes[a] < bytes[b]; });
  const int cores = threadCount(0);
  std::vector<MeshOutcome> outcomes(paths.size());
  std::vector<std::atomic<std::uintmax_t>> running(std::size_t(std::max(threads, 1)));  // bytes per worker, 0 idle
  for (auto& r : running) r = 0;
  {
    Progress progress("mapping", paths.size(), "meshes");
    parallelForWorkers(count, threads, [&](int k, int worker) {
      const std::size_t i = order[std::size_t(k)];
      MapJob mine = job;
      if (mine.settings.threads == 0) {
        std::uintmax_t others = 0;
        for (int w = 0; w < int(running.size()); ++w)
          if (w != worker) others = std::max(others, running[std::size_t(w)].load());
        const bool alone = count - k < threads && bytes[i] >= 4 * others;
        mine.settings.threads = std::max(1, cores / (alone ? count - k : threads));
      }
      running[std::size_t(worker)] = std::max<std::uintmax_t>(bytes[i], 1);
      outcomes[i] = mapBatchMesh(paths[i], mine, quiet);
      running[std::size_t(worker)] = 0;
      progress.advance();
    });
  }
  BatchResult result;
  for (const MeshOutcome& o : outcomes) {
    result.status = std::max(result.status, o.status);
    result.failed += o.status != 0;
    if (o.status == 0) result.worst = std::max(result.worst, o.verdict), ++result.verdicts[std::size_t(o.verdict)];
  }
  result.mapped = paths.size() - result.failed;
  if (!json.empty())
    io::writeFileAtomically((fs::path(json) / "batch.json").string(),
                            io::jsonText(batchJson(paths, outcomes, job.settings.projector.options, threads, millisecondsSince(start)), 2) + "\n");
  return result;
}

}  // namespace uvtk::inspect
