// `uvtk map`: assign UVs to a mesh with a projector and write an OBJ with per-corner UVs; or do
// so for every mesh of a folder or a list, several meshes at once, into an output folder
// (docs/scale-out.md).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "core/error.h"
#include "core/memory.h"
#include "core/progress.h"
#include "inspect/map_job.h"
#include "inspect/map_parameters.h"
#include "io/mesh_format.h"
#include "io/mesh_writer.h"
#include "options/cli_values.h"
#include "options/projector_cli.h"
#include "options/verdict_cli.h"

namespace uvtk::cli {

namespace {

struct MapArguments {
  std::string input, list, output, json;
  io::MeshWriteOptions write;
  io::MeshFormat batchFormat = io::MeshFormat::obj;
  bool quiet = false;
  int jobs = 0, threads = 0;
  ProjectorArguments projector;
  VerdictArguments verdict;
  int overlapResolution = analysis::kOverlapFollowsMesh;
  std::string textureSize = "1024,1024";
  std::optional<double> density;
};

void runMap(const MapArguments& a) {
  if (a.quiet) setProgressEnabled(false), setQuiet(true);
  if (a.input.empty() == a.list.empty()) throw UsageError("expected a mesh, a folder of meshes or --list FILE");
  // The projector's options and the judgement's, typed by CLI11, read by the engine as every face's.
  param::ParameterDictionary parameters = a.projector.parameters();
  const auto given = [&](const char* name) { return a.projector.app->get_option(name)->count() > 0; };
  if (given("--fail-on")) parameters.add("fail-on", a.verdict.failOn);
  if (given("--warn-on")) parameters.add("warn-on", a.verdict.warnOn);
  if (given("--overlap-resolution")) parameters.add("overlap-resolution", std::int64_t(a.overlapResolution));
  if (given("--texture-size")) {
    const analysis::TextureSize size = parseTextureSize(a.textureSize, "--texture-size");
    parameters.add("texture-size", std::vector<double>{double(size.width), double(size.height)});
  }
  if (a.density) parameters.add("density", *a.density);
  if (given("--threads")) parameters.add("threads", std::int64_t(a.threads));
  inspect::MapJob job;
  job.settings = inspect::readMapSettings(parameters);
  a.verdict.check();
  job.write = a.write;
  job.batchFormat = a.batchFormat;
  std::error_code ignored;
  if (!a.list.empty() || std::filesystem::is_directory(a.input, ignored)) {
    io::checkMeshOutput(std::string("STEM") + io::extensionOf(a.batchFormat), a.write, "--format");
    const std::vector<std::string> inputs = a.list.empty() ? inspect::meshesInFolder(a.input) : inspect::meshesInList(a.list);
    setFreedMemory(freedMemoryForMeshes(largestFile(inputs)));  // one mesh's memory for the next, when they are small
    const inspect::BatchResult batch = inspect::mapBatch(inputs, a.output, a.json, a.jobs, a.quiet, job);
    const std::string line = "uvtk map: " + std::to_string(batch.mapped) + " meshes mapped (" +
                             std::to_string(batch.verdicts[0]) + " pass, " + std::to_string(batch.verdicts[1]) +
                             " warn, " + std::to_string(batch.verdicts[2]) + " fail), " + std::to_string(batch.failed) +
                             " failed";
    if (batch.status != 0) throwWithStatus(batch.status, line);  // main prints the line
    std::fprintf(stderr, "%s\n", line.c_str());  // the last line, even with -q
    return enforceVerdict(a.verdict, batch.worst, "uvtk map");
  }
  io::checkMeshOutput(a.output, a.write);
  const inspect::MeshResult result = inspect::mapMesh({a.input, a.output, a.json}, job, true);
  if (!a.quiet) {
    std::fprintf(stderr, "uvtk map: %s\n", result.numbers.c_str());
    for (const std::string& advice : result.advice) std::fprintf(stderr, "uvtk map: advice: %s\n", advice.c_str());
  }
  if (!a.quiet && io::isGltf(*io::outputFormatOf(a.output)))
    std::fprintf(stderr, "uvtk map: %s: glTF stores positions, normals and UVs as float32 (v as 1 - v)\n",
                 a.output.c_str());
  enforceVerdict(a.verdict, result.verdict, "uvtk map");
}

}  // namespace

void addMapCommand(CLI::App& root) {
  auto arguments = std::make_shared<MapArguments>();
  CLI::App* map = root.add_subcommand("map", "Assign UVs with a projector (Bier & Sloan two-stage mapping)");
  CLI::Option* input = map->add_option(
      "input", arguments->input,
      "Input mesh (.obj, .off, .ply, .stl, .gltf, .glb), or a folder: every mesh in it, into -o's folder");
  map->add_option("--list", arguments->list,
                  "A file of mesh paths, one a line (relative to its folder; # comments), into -o's folder")
      ->excludes(input);
  map->add_option("-o,--output", arguments->output,
                  "Output mesh with per-corner UVs, by extension: .obj, .ply, .glb, .gltf (+ .bin); a folder for many")
      ->required();
  map->add_option("--json", arguments->json,
                  "Also write the summary as JSON (for many meshes: a folder, with STEM.json each and batch.json)");
  map->add_option("-j,--jobs", arguments->jobs, "Meshes mapped at once when there are many; 0: one per hardware thread")
      ->check(CLI::NonNegativeNumber)
      ->default_str("0");
  addMapThreadsOption(*map, arguments->threads);
  map->add_flag("-q,--quiet", arguments->quiet, "No progress and no summary lines; errors are still printed");
  map->add_flag("--write-w", arguments->write.writeW, "Write the third UV component (the cube face id; OBJ only)");
  map->add_flag("--ascii", arguments->write.ascii, "Write a .ply as ASCII text, not binary little endian");
  addChoice<io::MeshFormat>(*map, "--format", arguments->batchFormat,
                            {{"obj", io::MeshFormat::obj},
                             {"ply", io::MeshFormat::ply},
                             {"glb", io::MeshFormat::glb},
                             {"gltf", io::MeshFormat::gltf}},
                            "What a folder or --list of meshes writes: OUTDIR/STEM.obj, .ply, .glb or .gltf")
      ->default_str("obj");
  addChoice<bool>(*map, "--uv-digits", arguments->write.floatDigits, {{"double", false}, {"float", true}},
                  "UV text that round-trips a double (up to 17 digits) or a float (up to 9)")
      ->default_str("double");
  addProjectorOptions(*map, arguments->projector);
  addVerdictOptions(*map, arguments->verdict);
  addMapJudgementOptions(*map, arguments->overlapResolution, arguments->textureSize, arguments->density);
  map->callback([arguments] { runMap(*arguments); });
}

}  // namespace uvtk::cli
