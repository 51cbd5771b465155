// `uvtk run SCENE.json`: one file describes the job (schema/scene.schema.json); only the stages
// its outputs need run. `--plan` prints them without running anything.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "core/error.h"
#include "core/memory.h"
#include "core/progress.h"
#include "io/atomic_file.h"
#include "scene/scene.h"
#include "scene/scene_run.h"
#include "io/json_text.h"

namespace uvtk::cli {

using namespace uvtk::scene;

namespace {

struct RunArguments {
  std::string scene, outputDir, json;
  bool plan = false, quiet = false, allowOutside = false;
  int jobs = 0;
};

// Fails with the worst failure's status once every mesh has had its turn.
void runRun(const RunArguments& a) {
  if (a.quiet) setProgressEnabled(false), setQuiet(true);
  const Scene scene = loadScene(a.scene, a.outputDir, a.allowOutside);
  const std::vector<Stage> plan = planScene(scene);
  if (a.plan) {
    std::fputs(planText(scene, plan).c_str(), stdout);
    if (!a.json.empty()) io::writeFileAtomically(a.json, io::jsonText(planJson(scene, plan), 2) + "\n");
    return;
  }
  if (scene.meshes.size() > 1) {  // one mesh's memory for the next, when they are small
    std::vector<std::string> paths;
    for (const SceneMesh& mesh : scene.meshes) paths.push_back(mesh.path);
    setFreedMemory(freedMemoryForMeshes(largestFile(paths)));
  }
  const RunResult result = runScene(scene, plan, {a.jobs});
  if (!a.json.empty()) io::writeFileAtomically(a.json, io::jsonText(result.report, 2) + "\n");
  const std::size_t failed = result.report["failures"].size();
  if (!a.quiet || failed)
    std::fprintf(stderr, "uvtk run: %zu stages, %zu outputs, %zu failed, %.1f ms\n", plan.size(), scene.outputs.size(),
                 failed, result.report["milliseconds"]["total"].get<double>());
  const std::string summary = "uvtk run: " + std::to_string(failed) + " stages failed (see above)";
  if (result.status != 0) throwWithStatus(result.status, summary);
}

}  // namespace

void addRunCommand(CLI::App& root) {
  auto a = std::make_shared<RunArguments>();
  CLI::App* cmd = root.add_subcommand(
      "run",
      "Run a scene file: meshes, mappings, cameras, textures and outputs; only what the outputs need is computed");
  cmd->add_option("scene", a->scene, "Scene file (JSON; `uvtk schema` prints its schema)")->required();
  cmd->add_flag("--plan", a->plan, "Print the stages the outputs need, and run nothing");
  cmd->add_option("-o,--output-dir", a->outputDir,
                  "Folder the scene's output paths are relative to (default: the scene file's folder)");
  cmd->add_flag("--allow-outside", a->allowOutside,
               "Let the scene's outputs leave the output folder (absolute paths, .., symbolic links to folders "
               "outside it)");
  cmd->add_option("--json", a->json, "Write the run report (with --plan: the plan) as JSON");
  cmd->add_option("--jobs", a->jobs, "Meshes worked on at once (0: one per hardware thread)")->capture_default_str();
  cmd->add_flag("-q,--quiet", a->quiet, "No progress and no summary line (failures are still printed)");
  cmd->callback([a] { runRun(*a); });
}

}  // namespace uvtk::cli
