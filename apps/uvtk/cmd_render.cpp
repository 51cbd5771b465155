// `uvtk render`: draw a mesh with its texture coordinates (from the file, a projector or texgen,
// per vertex or evaluated per pixel) as OpenGL's fixed-function pipeline draws it, into a PNG,
// with optional float AOVs (u, v, depth, face, lod, and cubeface with a cube map) in an EXR.
#include <cstdio>
#include <memory>
#include <string>

#include "commands.h"
#include "core/progress.h"
#include "options/projector_cli.h"
#include "options/render_cli.h"
#include "options/texgen_cli.h"

namespace uvtk::cli {

namespace {

void runRender(const RenderJob& job) {
  const RenderResult result = renderMeshFile(job);
  if (!result.line.empty() && !quiet()) std::fprintf(stderr, "uvtk render: %s\n", result.line.c_str());
}

}  // namespace

void addRenderCommand(CLI::App& root) {
  auto a = std::make_shared<RenderJob>();
  CLI::App* cmd = root.add_subcommand(
      "render", "Render a textured mesh as OpenGL's fixed-function pipeline would (2D textures and cube maps)");
  cmd->add_option("input", a->input, "Input mesh (.obj, .off, .ply, .stl, .gltf, .glb)")->required();
  cmd->add_option("-o,--output", a->output, "Output image, 8-bit RGB, format by extension (.png, .tif, .jpg, ...)")
      ->required();
  addCameraOptions(*cmd, a->camera);
  cmd->add_option("--model", a->model, "Model matrix, 16 numbers column-major (default identity)");
  addFrameOptions(*cmd, a->frame);
  addTextureOptions(*cmd, a->texture, "--texture");
  addProjectorOptions(*cmd, a->projector, true);
  addTexgenOptions(*cmd, a->texgen, "--texgen");
  cmd->add_option("--json", a->json, "Also write a summary as JSON");
  cmd->callback([a] { runRender(*a); });
}

}  // namespace uvtk::cli
