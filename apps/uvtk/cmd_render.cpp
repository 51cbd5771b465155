// `uvtk render`: draw a mesh with its texture coordinates (from the file, a projector or texgen,
// per vertex or evaluated per pixel) as OpenGL's fixed-function pipeline draws it, into a PNG,
// with optional float AOVs (u, v, depth, face, lod, and cubeface with a cube map) in an EXR.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "commands.h"
#include "core/progress.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "io/mesh_reader.h"
#include "inspect/mapped_mesh.h"
#include "options/arithmetic_cli.h"
#include "options/cli_values.h"
#include "options/projector_cli.h"
#include "options/texgen_cli.h"
#include "options/render_cli.h"
#include "inspect/run_report.h"

namespace uvtk::cli {

using namespace uvtk::inspect;

namespace {

struct RenderArguments {
  std::string input, output, json, model;
  CameraArguments camera;
  TextureArguments texture;
  FrameArguments frame;
  ProjectorArguments projector;
  TexgenArguments texgen;
};

void runRender(RenderArguments& a) {
  const bool projectorGiven = given(a.projector.app, "--projector");
  if (projectorGiven && a.texgen.given()) throw UsageError("--projector and texgen options exclude each other");
  a.frame.check(a.output);  // nothing is written unless every output can be
  if (!projectorGiven && !a.texgen.given() && a.frame.needsExact())
    throw UsageError(a.frame.uv == FrameArguments::Uv::PerPixel
                         ? "--uv per-pixel evaluates a mapping: give --projector or --texgen"
                         : "--view uverror compares with the exact mapping: give --projector or --texgen");
  a.camera.check();
  a.texture.check();
  checkTextureUse(a.frame, a.texture, projectorGiven ? &a.projector.options : nullptr);
  const Mat4 worldFromObject = a.model.empty() ? Mat4::Identity() : parseMatrix(a.model, "--model");

  StageClock clock("uvtk render");
  clock.start("reading", a.input);
  io::ReadMeshResult input = io::readMesh(a.input);
  const double readMs = clock.stop();
  const nlohmann::json inputSummary = inputJson(a.input, input);

  const auto [width, height] = a.frame.imageSize();
  const render::Camera camera = a.camera.make(input.mesh, worldFromObject, width, height);
  clock.start("texture coordinates", std::to_string(input.mesh.faceCount()) + " faces");
  MappedMesh mapped;
  if (projectorGiven) {
    a.projector.options.eye = (worldFromObject.inverse() * camera.eye().homogeneous()).head<3>();
    mapped = mapByProjector(std::move(input.mesh), a.projector.resolve(), a.projector.seamPlaceAuto());
  } else if (a.texgen.given()) {
    a.texgen.arithmetic = a.projector.options.arithmetic;  // render's --precision serves both
    mapped = mapByTexgen(std::move(input.mesh), a.texgen.resolve(camera.viewFromWorld, worldFromObject));
  } else {
    mapped = withFileUvs(std::move(input.mesh), a.input);
  }
  const double uvMs = clock.stop();

  clock.start("texture", a.texture.source);
  const BoundTexture texture = a.texture.load();
  const double textureMs = clock.stop();

  clock.start(a.frame.view.empty() ? "rendering" : "drawing", a.frame.size);
  analysis::Judgement judgement;
  const auto measured = [&]() -> const analysis::Judgement& { return judgement = mapped.judge(); };
  io::OutputSet outputs;  // the picture, its AOVs and the record, published together
  const FrameOptions frame = a.frame.options();
  nlohmann::json j = writeFrame(outputs, frame, a.output, a.frame.aovOutput, mapped,
                                renderOptions(frame, a.texture.options(), texture, camera, worldFromObject), measured);
  clock.stop();

  if (!a.json.empty()) {
    j["input"] = inputSummary;
    j["arithmetic"] = arithmeticJson(a.projector.options.arithmetic);
    j["texture"]["name"] = a.texture.source;
    j["milliseconds"]["read"] = readMs;
    j["milliseconds"]["texcoords"] = uvMs;
    j["milliseconds"]["texture"] = textureMs;
    outputs.writeText(a.json, j.dump(2) + "\n");
  }
  outputs.publish();
  printMappingNotes(a.input, input.warnings, mapped);
  if (a.frame.view.empty() && !quiet())
    std::fprintf(stderr,
                 "uvtk render: %dx%d, %zu faces drawn, %zu culled, %zu clipped, %zu pixels covered, raster %.1f ms, "
                 "shade %.1f ms\n",
                 width, height, j["faces_drawn"].get<std::size_t>(), j["faces_culled"].get<std::size_t>(),
                 j["faces_clipped"].get<std::size_t>(), j["covered_pixels"].get<std::size_t>(),
                 j["milliseconds"]["raster"].get<double>(), j["milliseconds"]["shade"].get<double>());
}

}  // namespace

void addRenderCommand(CLI::App& root) {
  auto a = std::make_shared<RenderArguments>();
  CLI::App* cmd = root.add_subcommand(
      "render", "Render a textured mesh as OpenGL's fixed-function pipeline would (2D textures and cube maps)");
  cmd->add_option("input", a->input, "Input mesh (.obj or .off)")->required();
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
