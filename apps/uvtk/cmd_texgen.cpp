// `uvtk texgen`: OpenGL fixed-function texture-coordinate generation on a mesh, written as an
// OBJ with per-corner `vt s t` (or `vt s t r`), and optionally every (s, t, r, q) as JSON.
#include <cstdio>
#include <memory>
#include <string>

#include "commands.h"
#include "core/progress.h"
#include "inspect/run_report.h"
#include "inspect/texgen_job.h"
#include "options/cli_values.h"
#include "options/texgen_cli.h"

namespace uvtk::cli {

namespace {

struct TexgenCommandArguments {
  std::string input, output, json;
  std::string eye = "0,0,0", center = "0,0,-1", up = "0,1,0";
  std::string model;
  TexgenArguments texgen;
  io::MeshWriteOptions write;
};

void runTexgen(const TexgenCommandArguments& a) {
  const Mat4 view = lookAt(parseVec3(a.eye, "--eye"), parseVec3(a.center, "--center"), parseVec3(a.up, "--up"));
  const Mat4 model = a.model.empty() ? Mat4::Identity() : parseMatrix(a.model, "--model");
  const inspect::TexgenRun r = inspect::texgenMesh(a.input, a.output, a.json, a.texgen.resolve(view, model), a.write);
  inspect::printInputWarnings(a.input, r.warnings);
  if (r.qDivided)
    std::fprintf(stderr, "uvtk texgen: q is not 1 at %zu corners: wrote s/q, t/q%s (%zu corners with q = 0 written as 0 and counted invalid)\n",
                 r.qNotOneCorners, r.writesR ? ", r/q" : "", r.qZeroCorners);
  if (r.dropsR)
    std::fprintf(stderr, "uvtk texgen: %s holds two texture coordinates: r is not written (an OBJ output keeps it)\n",
                 a.output.c_str());
  if (!quiet())
    std::fprintf(stderr, "uvtk texgen: %zu vertices, %zu faces, %zu sphere-map singular corners, %zu invalid corners, %.1f ms\n",
               r.vertices, r.faces, r.sphereMapSingular, r.invalidCorners, r.texgenMs);
}

}  // namespace

void addTexgenCommand(CLI::App& root) {
  auto arguments = std::make_shared<TexgenCommandArguments>();
  CLI::App* cmd = root.add_subcommand(
      "texgen", "OpenGL fixed-function texture-coordinate generation (glTexGen, GL 4.6 compatibility §12.1.3)");
  cmd->add_option("input", arguments->input, "Input mesh (.obj, .off, .ply, .stl, .gltf, .glb)")->required();
  cmd->add_option("-o,--output", arguments->output,
                  "Output mesh by extension (.obj: vt s t, or s t r when r is generated; .ply, .glb, .gltf: s t), "
                  "divided by q where q is not 1")
      ->required();
  cmd->add_flag("--ascii", arguments->write.ascii, "Write a .ply as ASCII text, not binary little endian");
  addTexgenOptions(*cmd, arguments->texgen, "--mode");
  addTexgenViewOptions(*cmd, arguments->eye, arguments->center, arguments->up, arguments->model);
  addTexgenThreadsOption(*cmd, arguments->write.threads);
  cmd->add_option("--json", arguments->json, "Also write the summary and every corner's [s, t, r, q] (undivided) as JSON");
  cmd->callback([arguments] { runTexgen(*arguments); });
}

}  // namespace uvtk::cli
