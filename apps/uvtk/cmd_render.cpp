// `uvtk render`: draw a mesh with its texture coordinates (from the file, a projector or texgen,
// per vertex or evaluated per pixel) as OpenGL's fixed-function pipeline draws it, into a PNG,
// with optional float AOVs (u, v, depth, face, lod) in an EXR.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>

#include "analysis/summary.h"
#include "arithmetic_cli.h"
#include "cli_values.h"
#include "commands.h"
#include "core/error.h"
#include "core/gl_matrices.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "io/mesh_reader.h"
#include "mapped_mesh.h"
#include "projector_cli.h"
#include "render/procedural.h"
#include "render/renderer.h"
#include "run_report.h"
#include "texgen/texgen.h"
#include "texgen_cli.h"
#include "views/views.h"

namespace uvtk::cli {

namespace {

enum class UvEvaluation { PerVertex, PerPixel };
enum class CameraMode { Auto, Explicit };

struct RenderArguments {
  std::string input, output, json;
  // camera
  std::string eye, center = "0,0,0", up = "0,1,0", viewDir = "0,0,1", ortho, size = "512x512", model;
  CameraMode camera = CameraMode::Auto;
  double fovy = 45.0;
  std::optional<double> zNear, zFar;
  render::Cull cull = render::Cull::Back;
  int threads = 0;
  int samplesPerPixel = 1;
  // texture
  std::string texture = "checker:64:8";
  render::Filter filter = render::Filter::Nearest;
  render::Wrap wrap = render::Wrap::Repeat;
  render::EnvMode env = render::EnvMode::Replace;
  std::string envColour = "0,0,0,0", background = "0,0,0";
  // texture coordinates
  UvEvaluation uv = UvEvaluation::PerVertex;
  ProjectorArguments projector;
  TexgenArguments texgen;
  // outputs
  std::string aov, aovOutput;
  std::string view;  // inspection views instead of the textured picture
  views::View layoutFill = views::View::Stretch;
  int layoutSize = 512;
};

render::Camera makeCamera(const RenderArguments& a, const Mesh& mesh, const Mat4& worldFromObject) {
  const auto [width, height] = parseImageSize(a.size, "--size");
  const Vec3 up = parseVec3(a.up, "--up");
  // Explicit when asked for, or when --eye is given without --camera.
  const bool cameraGiven = given(a.projector.app, "--camera");
  const bool manual = cameraGiven ? a.camera == CameraMode::Explicit : !a.eye.empty();
  if (manual && a.eye.empty()) throw UsageError("--camera explicit: expected --eye x,y,z");
  if (manual && a.ortho == "auto") throw UsageError("--ortho auto goes with the automatic camera");
  render::Camera camera;
  if (!manual) {
    std::vector<Vec3> world(mesh.positions.size());
    for (std::size_t v = 0; v < world.size(); ++v)
      world[v] = (worldFromObject * mesh.positions[v].homogeneous()).head<3>();
    const Vec3 direction = a.eye.empty() ? parseVec3(a.viewDir, "--view-dir")
                                         : Vec3(parseVec3(a.eye, "--eye") - parseVec3(a.center, "--center"));
    camera = render::frameSphere(render::boundingSphere(world), direction, up,
                                 {!a.ortho.empty() && a.ortho == "auto", a.fovy}, width, height);
    if (!a.zNear && !a.zFar) return camera;
  }
  camera.width = width;
  camera.height = height;
  if (manual) camera.viewFromWorld = lookAt(parseVec3(a.eye, "--eye"), parseVec3(a.center, "--center"), up);
  if (!manual && (a.zNear || a.zFar)) throw UsageError("--near and --far go with an explicit camera (--eye)");
  const double zNear = a.zNear.value_or(0.1), zFar = a.zFar.value_or(100.0);
  if (!a.ortho.empty() && a.ortho != "auto") {
    const Vec4 box = parseVec4(a.ortho, "--ortho");
    camera.clipFromView = orthographic(box[0], box[1], box[2], box[3], zNear, zFar);
  } else {
    camera.clipFromView = perspective(a.fovy, double(width) / double(height), zNear, zFar);
  }
  return camera;
}

render::Texture loadTexture(const std::string& name) {
  if (std::optional<render::Texture> procedural = render::proceduralTexture(name)) return std::move(*procedural);
  const io::ImageFile file = io::readImage(name);
  return render::Texture::fromImage(file.image, file.eightBit);
}

// The AOV channels `list` names ("uv,depth,face,lod" in any order and subset), by their names in
// Rendering::aovs; throws UsageError for anything else.
std::vector<std::string> aovChannels(const std::string& list) {
  std::vector<std::string> channels;
  std::stringstream in(list);
  std::string name;
  while (std::getline(in, name, ',')) {
    if (name == "uv") {
      channels.push_back("u"), channels.push_back("v");
    } else if (name == "depth" || name == "face" || name == "lod") {
      channels.push_back(name);
    } else {
      throw UsageError("--aov: expected a list of uv, depth, face, lod, found '" + name + "'");
    }
  }
  return channels;
}

Image selectChannels(const Image& all, const std::vector<std::string>& names) {
  std::vector<int> source;
  for (const std::string& name : names)
    source.push_back(int(std::find(all.channelNames.begin(), all.channelNames.end(), name) - all.channelNames.begin()));
  Image out(all.width, all.height, int(names.size()));
  out.channelNames = names;
  for (int y = 0; y < all.height; ++y)
    for (int x = 0; x < all.width; ++x)
      for (std::size_t k = 0; k < source.size(); ++k) out.at(x, y, int(k)) = all.at(x, y, source[k]);
  return out;
}

// `--view`: the named inspection views (one picture, or a contact sheet of several) instead of the
// textured picture. Distortion is measured only when a view shows it.
void drawViews(const RenderArguments& a, const std::vector<views::View>& list, const MappedMesh& mapped,
               const render::RenderOptions& renderOptions, const nlohmann::json& inputSummary) {
  StageClock clock("uvtk render");
  const auto showsMeasures = [](views::View v) {
    return v != views::View::Checker && v != views::View::Uvgrid && v != views::View::UvError;
  };
  MappedMesh::Measures measures;
  if (std::any_of(list.begin(), list.end(), showsMeasures)) {
    clock.start("measuring", std::to_string(mapped.mesh.faceCount()) + " faces");
    measures = mapped.measure();
    clock.stop();
  }
  const views::ViewInput in = mapped.viewInput(measures);
  views::ViewOptions options;
  options.render = renderOptions;
  options.layoutFill = a.layoutFill;
  options.layoutSize = a.layoutSize;

  nlohmann::json j = {{"input", inputSummary}, {"output", a.output}, {"texcoords", mapped.source}, {"views", {}}};
  std::vector<std::pair<std::string, Image>> tiles;
  for (const views::View view : list) {
    clock.start("drawing", views::toString(view));
    tiles.emplace_back(views::toString(view), views::drawView(view, in, options));
    j["views"].push_back(views::toString(view));
    if (view == views::View::UvError && !a.json.empty()) {
      const views::UvErrorMap error = views::uvErrorMap(in, options);
      j["uverror_texels"] = {
          {"max", error.max}, {"mean", error.mean}, {"pixels", error.pixels}, {"invalid_pixels", error.invalidPixels}};
    }
    clock.stop();
  }
  clock.start("writing", a.output);
  const Image picture =
      tiles.size() == 1 ? tiles.front().second : views::contactSheet(tiles, std::min<int>(3, int(tiles.size())));
  io::writeImage(a.output, picture, io::PixelType::UInt8);
  if (!a.json.empty()) io::writeFileAtomically(a.json, j.dump(2) + "\n");
  clock.stop();
}

void runRender(RenderArguments& a) {
  const bool projectorGiven = given(a.projector.app, "--projector");
  if (projectorGiven && a.texgen.given()) throw UsageError("--projector and texgen options exclude each other");
  const std::vector<std::string> aovs = a.aov.empty() ? std::vector<std::string>() : aovChannels(a.aov);
  if (!a.aov.empty() && a.aovOutput.empty())
    a.aovOutput = std::filesystem::path(a.output).replace_extension(".exr").string();
  if (!a.aov.empty() && a.aovOutput == a.output) throw UsageError("--aov-output must differ from --output");
  const std::vector<views::View> viewList = a.view.empty() ? std::vector<views::View>() : views::parseViewList(a.view);
  if (!viewList.empty() && !a.aov.empty()) throw UsageError("--view and --aov exclude each other");
  if (a.layoutSize < 16 || a.layoutSize > 16384) throw UsageError("--layout-size: expected 16 to 16384 pixels");
  io::checkImageType(a.output, io::PixelType::UInt8);  // nothing is written unless both outputs can be
  if (!a.aov.empty()) io::checkImageType(a.aovOutput, io::PixelType::Float);
  const Mat4 worldFromObject = a.model.empty() ? Mat4::Identity() : parseMatrix(a.model, "--model");

  StageClock clock("uvtk render");
  clock.start("reading", a.input);
  io::ReadMeshResult input = io::readMesh(a.input);
  const double readMs = clock.stop();
  const nlohmann::json inputSummary = inputJson(a.input, input);

  render::RenderOptions options;
  options.camera = makeCamera(a, input.mesh, worldFromObject);
  options.worldFromObject = worldFromObject;
  options.raster = {a.cull, a.threads};
  options.samplesPerPixel = a.samplesPerPixel;
  options.sampler = render::samplerFor(a.filter, a.wrap);
  options.env = a.env;
  options.envColour = parseVec4(a.envColour, "--env-color");
  options.background = parseVec3(a.background, "--background");

  clock.start("texture coordinates", std::to_string(input.mesh.faceCount()) + " faces");
  const bool perPixel = a.uv == UvEvaluation::PerPixel;
  MappedMesh mapped;
  if (projectorGiven) {
    const Mat4 objectFromWorld = worldFromObject.inverse();
    a.projector.options.eye = (objectFromWorld * options.camera.eye().homogeneous()).head<3>();
    mapped = mapByProjector(std::move(input.mesh), a.projector.resolve(), a.projector.seamPlaceAuto());
  } else if (a.texgen.given()) {
    a.texgen.arithmetic = a.projector.options.arithmetic;  // render's --precision serves both
    mapped = mapByTexgen(std::move(input.mesh), a.texgen.resolve(options.camera.viewFromWorld, worldFromObject));
  } else {
    if (perPixel) throw UsageError("--uv per-pixel evaluates a mapping: give --projector or --texgen");
    if (std::any_of(viewList.begin(), viewList.end(), views::needsExactMapping))
      throw UsageError("--view uverror compares with the exact mapping: give --projector or --texgen");
    mapped = withFileUvs(std::move(input.mesh), a.input);
  }
  render::TexcoordSource texcoords;
  if (perPixel) {
    texcoords.pixelMapping = mapped.exact;
  } else {
    texcoords.corners = mapped.corners();
  }
  const double uvMs = clock.stop();

  clock.start("texture", a.texture);
  render::Texture texture = loadTexture(a.texture);
  if (render::needsMipmaps(a.filter)) texture.buildMipmaps();
  options.texture = &texture;
  const double textureMs = clock.stop();

  if (!viewList.empty()) {
    drawViews(a, viewList, mapped, options, inputSummary);
    printMappingNotes(a.input, input.warnings, mapped);
    return;
  }

  clock.start("rendering", std::to_string(options.camera.width) + "x" + std::to_string(options.camera.height));
  options.aovs = !a.aov.empty();
  const render::Rendering rendering = render::render(mapped.mesh, texcoords, options);
  clock.stop();

  clock.start("writing", a.output);
  io::writeImage(a.output, rendering.colour, io::PixelType::UInt8);
  if (!a.aov.empty()) io::writeImage(a.aovOutput, selectChannels(rendering.aovs, aovs), io::PixelType::Float);
  const double writeMs = clock.stop();

  if (!a.json.empty()) {
    nlohmann::json j = {{"input", inputSummary},
                        {"output", a.output},
                        {"texcoords", mapped.source},
                        {"uv", perPixel ? "per-pixel" : "per-vertex"},
                        {"spp", options.samplesPerPixel},
                        {"arithmetic", arithmeticJson(a.projector.options.arithmetic)},
                        {"width", options.camera.width},
                        {"height", options.camera.height},
                        {"faces", mapped.mesh.faceCount()},
                        {"faces_drawn", rendering.raster.drawn},
                        {"faces_culled", rendering.raster.culled},
                        {"faces_clipped", rendering.raster.clipped},
                        {"covered_pixels", rendering.coveredPixels},
                        {"texture",
                         {{"name", a.texture},
                          {"width", texture.width()},
                          {"height", texture.height()},
                          {"levels", texture.levelCount()}}},
                        {"milliseconds",
                         {{"read", readMs},
                          {"texcoords", uvMs},
                          {"texture", textureMs},
                          {"raster", rendering.rasterMs},
                          {"shade", rendering.shadeMs},
                          {"write", writeMs}}}};
    if (!a.aov.empty()) j["aov_output"] = a.aovOutput;
    io::writeFileAtomically(a.json, j.dump(2) + "\n");
  }
  printMappingNotes(a.input, input.warnings, mapped);
  std::fprintf(stderr,
               "uvtk render: %dx%d, %zu faces drawn, %zu culled, %zu clipped, %zu pixels covered, raster %.1f ms, "
               "shade %.1f ms\n",
               options.camera.width, options.camera.height, rendering.raster.drawn, rendering.raster.culled,
               rendering.raster.clipped, rendering.coveredPixels, rendering.rasterMs, rendering.shadeMs);
}

}  // namespace

void addRenderCommand(CLI::App& root) {
  auto a = std::make_shared<RenderArguments>();
  CLI::App* cmd = root.add_subcommand(
      "render", "Render a textured mesh as OpenGL's fixed-function pipeline would (checker, uvgrid or an image)");
  cmd->add_option("input", a->input, "Input mesh (.obj or .off)")->required();
  cmd->add_option("-o,--output", a->output, "Output image, 8-bit RGB, format by extension (.png, .tif, .jpg, ...)")
      ->required();
  // camera
  addChoice<CameraMode>(*cmd, "--camera", a->camera, {{"auto", CameraMode::Auto}, {"explicit", CameraMode::Explicit}},
                        "auto frames the mesh's bounding sphere (along --view-dir, or eye - center when --eye is "
                        "given); explicit uses --eye, --center, --up as given. Default: explicit when --eye is given");
  cmd->add_option("--eye", a->eye, "Camera: gluLookAt eye (x,y,z); without it the camera frames the mesh")
      ->type_name("X,Y,Z");
  cmd->add_option("--center", a->center, "Camera: gluLookAt center")->type_name("X,Y,Z")->capture_default_str();
  cmd->add_option("--up", a->up, "Camera: gluLookAt up")->type_name("X,Y,Z")->capture_default_str();
  cmd->add_option("--view-dir", a->viewDir, "Automatic camera: direction from the mesh to the eye")
      ->type_name("X,Y,Z")
      ->capture_default_str();
  cmd->add_option("--fovy", a->fovy, "Camera: gluPerspective vertical field of view in degrees")->capture_default_str();
  cmd->add_option("--near", a->zNear, "Camera: near plane distance (explicit camera; default 0.1)");
  cmd->add_option("--far", a->zFar, "Camera: far plane distance (explicit camera; default 100)");
  cmd->add_option("--ortho", a->ortho, "Orthographic camera: glOrtho left,right,bottom,top, or auto to frame the mesh")
      ->type_name("L,R,B,T|auto");
  cmd->add_option("--size", a->size, "Image size WxH")->capture_default_str();
  cmd->add_option("--model", a->model, "Model matrix, 16 numbers column-major (default identity)");
  addChoice<render::Cull>(*cmd, "--cull", a->cull,
                          {{"back", render::Cull::Back}, {"front", render::Cull::Front}, {"none", render::Cull::None}},
                          "Face culling; front faces are counter-clockwise")
      ->default_str("back");
  cmd->add_option("--threads", a->threads, "Threads (0: one per hardware thread); the image does not depend on it")
      ->capture_default_str();
  cmd->add_option("--spp", a->samplesPerPixel,
                  "Supersampling: samples per pixel on a regular n x n grid (1, 4, 9, 16, ..., 256), box-filtered")
      ->capture_default_str();
  // texture
  cmd->add_option("--texture", a->texture,
                  "checker:N[:C] (N x N texels, C x C squares, white at texel 0,0), uvgrid[:N], or an image file "
                  "(top row at v = 1)")
      ->capture_default_str();
  addChoice<render::Filter>(*cmd, "--filter", a->filter, kFilterNames,
                            "Minification filter; magnification is nearest for nearest*, else linear")
      ->default_str("nearest");
  addChoice<render::Wrap>(*cmd, "--wrap", a->wrap,
                          {{"repeat", render::Wrap::Repeat},
                           {"clamp_to_edge", render::Wrap::ClampToEdge},
                           {"mirrored_repeat", render::Wrap::MirroredRepeat}},
                          "Wrap mode of s and t")
      ->default_str("repeat");
  addChoice<render::EnvMode>(*cmd, "--env", a->env,
                             {{"replace", render::EnvMode::Replace},
                              {"modulate", render::EnvMode::Modulate},
                              {"decal", render::EnvMode::Decal},
                              {"blend", render::EnvMode::Blend}},
                             "Texture environment; modulate, decal and blend use Blinn-Phong lighting by a head-light")
      ->default_str("replace");
  cmd->add_option("--env-color", a->envColour, "GL_TEXTURE_ENV_COLOR for blend (r,g,b,a)")->capture_default_str();
  cmd->add_option("--background", a->background, "Background colour r,g,b in [0, 1]")->capture_default_str();
  // texture coordinates
  addChoice<UvEvaluation>(*cmd, "--uv", a->uv,
                          {{"per-vertex", UvEvaluation::PerVertex}, {"per-pixel", UvEvaluation::PerPixel}},
                          "Interpolate per-vertex texture coordinates, or evaluate the mapping at every pixel")
      ->default_str("per-vertex");
  addProjectorOptions(*cmd, a->projector, true);
  addTexgenOptions(*cmd, a->texgen, "--texgen");
  // outputs
  cmd->add_option("--aov", a->aov, "Also write float AOVs: a list of uv, depth, face, lod")
      ->type_name("uv,depth,face,lod");
  cmd->add_option("--aov-output", a->aovOutput, "The AOV file (.exr or .tif; default: the output with .exr)");
  cmd->add_option("--view", a->view,
                  "Draw inspection views instead: checker, uvgrid, stretch, linf, angle, area, seams, uverror, layout "
                  "(several: a contact sheet)")
      ->type_name("NAME[,NAME...]");
  addChoice<views::View>(*cmd, "--layout-fill", a->layoutFill,
                         {{"stretch", views::View::Stretch},
                          {"linf", views::View::Linf},
                          {"angle", views::View::Angle},
                          {"area", views::View::Area}},
                         "The measure that fills the triangles of the layout view")
      ->default_str("stretch");
  cmd->add_option("--layout-size", a->layoutSize, "Pixels across the layout view's UV square")->capture_default_str();
  cmd->add_option("--json", a->json, "Also write a summary as JSON");
  cmd->callback([a] { runRender(*a); });
}

}  // namespace uvtk::cli
