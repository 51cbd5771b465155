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

#include "cli_values.h"
#include "commands.h"
#include "core/error.h"
#include "core/gl_matrices.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "io/mesh_reader.h"
#include "param/projector.h"
#include "projector_cli.h"
#include "render/procedural.h"
#include "render/renderer.h"
#include "run_report.h"
#include "texgen/texgen.h"
#include "texgen_cli.h"

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
};

std::pair<int, int> parseSize(const std::string& text) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  std::istringstream in(text);
  if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || (in >> extra) || w < 1 || h < 1 || w > 16384 || h > 16384)
    throw UsageError("--size: expected WxH with 1 <= W, H <= 16384, found '" + text + "'");
  return {w, h};
}

render::Camera makeCamera(const RenderArguments& a, const Mesh& mesh, const Mat4& worldFromObject) {
  const auto [width, height] = parseSize(a.size);
  const Vec3 up = parseVec3(a.up, "--up");
  // Explicit when asked for, or when --eye is given without --camera.
  const bool cameraGiven = given(a.projector.app, "--camera");
  const bool manual = cameraGiven ? a.camera == CameraMode::Explicit : !a.eye.empty();
  if (manual && a.eye.empty()) throw UsageError("--camera explicit: expected --eye x,y,z");
  if (manual && a.ortho == "auto") throw UsageError("--ortho auto goes with the automatic camera");
  render::Camera camera;
  if (!manual) {
    std::vector<Vec3> world(mesh.positions.size());
    for (std::size_t v = 0; v < world.size(); ++v) world[v] = (worldFromObject * mesh.positions[v].homogeneous()).head<3>();
    const Vec3 direction = a.eye.empty() ? parseVec3(a.viewDir, "--view-dir")
                                         : Vec3(parseVec3(a.eye, "--eye") - parseVec3(a.center, "--center"));
    camera = render::frameSphere(render::boundingSphere(world), direction, up, {!a.ortho.empty() && a.ortho == "auto", a.fovy},
                                 width, height);
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

void runRender(RenderArguments& a) {
  const bool projectorGiven = given(a.projector.app, "--projector");
  if (projectorGiven && a.texgen.given()) throw UsageError("--projector and texgen options exclude each other");
  const std::vector<std::string> aovs = a.aov.empty() ? std::vector<std::string>() : aovChannels(a.aov);
  if (!a.aov.empty() && a.aovOutput.empty())
    a.aovOutput = std::filesystem::path(a.output).replace_extension(".exr").string();
  if (!a.aov.empty() && a.aovOutput == a.output) throw UsageError("--aov-output must differ from --output");
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
  options.sampler = render::samplerFor(a.filter, a.wrap);
  options.env = a.env;
  options.envColour = parseVec4(a.envColour, "--env-color");
  options.background = parseVec3(a.background, "--background");

  clock.start("texture coordinates", std::to_string(input.mesh.faceCount()) + " faces");
  const bool perPixel = a.uv == UvEvaluation::PerPixel;
  Mesh mesh;
  render::TexcoordSource texcoords;
  std::string source;
  if (projectorGiven) {
    source = "projector";
    const Mat4 objectFromWorld = worldFromObject.inverse();
    a.projector.options.eye = (objectFromWorld * options.camera.eye().homogeneous()).head<3>();
    const param::ProjectorOptions projectorOptions = a.projector.resolve();
    param::Projection projection = param::project(std::move(input.mesh), projectorOptions);
    mesh = std::move(projection.mesh);
    texcoords.corners.resize(projection.uv.uv.size());
    for (std::size_t c = 0; c < texcoords.corners.size(); ++c)
      texcoords.corners[c] = Vec4(projection.uv.uv[c].x(), projection.uv.uv[c].y(), 0.0, 1.0);
    if (perPixel) {
      auto mapping = std::make_shared<param::PointMapping>(projectorOptions, projection.localFromObject);
      auto capFaces = std::make_shared<std::vector<std::uint8_t>>(projection.uv.faceFlags);
      const Mesh* m = &mesh;
      texcoords.pixelMapping = render::PixelMapping{
          [mapping, capFaces, m](const Vec3& p, const Vec3& n, std::int32_t face) -> Vec4 {
            const bool cap = ((*capFaces)[std::size_t(face)] & kFaceCap) != 0;
            Vec3 normal = n;
            if (cap) {  // the cap's side comes from the face, as project() decided it
              const Triangle& t = m->triangles[std::size_t(face)];
              normal = triangleAreaNormal(m->positions[t[0]], m->positions[t[1]], m->positions[t[2]]);
            }
            const param::VertexUv uv = mapping->at(p, normal, cap);
            const double nan = std::numeric_limits<double>::quiet_NaN();
            return uv.state == param::CornerState::Invalid ? Vec4(nan, nan, 0, 1) : Vec4(uv.uv.x(), uv.uv.y(), 0, 1);
          },
          mapping->wrapsU(), mapping->needsNormal()};
    }
  } else if (a.texgen.given()) {
    source = "texgen";
    mesh = std::move(input.mesh);
    const texgen::TexgenOptions texgenOptions = a.texgen.resolve(options.camera.viewFromWorld, worldFromObject);
    if (perPixel) {
      texcoords.pixelMapping = render::PixelMapping{
          [texgenOptions](const Vec3& p, const Vec3& n, std::int32_t) { return texgen::texgenAt(p, n, texgenOptions); },
          false, true};
    } else {
      const texgen::TexgenResult generated = texgen::generateTexcoords(mesh, texgenOptions);
      texcoords.corners.resize(generated.q.size());
      for (std::size_t c = 0; c < generated.q.size(); ++c)
        texcoords.corners[c] = Vec4(generated.uv.uv[c].x(), generated.uv.uv[c].y(), generated.uv.w[c], generated.q[c]);
    }
  } else {
    source = "file";
    mesh = std::move(input.mesh);
    if (perPixel) throw UsageError("--uv per-pixel evaluates a mapping: give --projector or --texgen");
    if (!mesh.hasTexcoords())
      throw UsageError(a.input + " has no texture coordinates (vt): give --projector or --texgen");
    texcoords.corners.resize(3 * mesh.faceCount());
    for (std::size_t f = 0; f < mesh.faceCount(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int t = mesh.cornerTexcoords[f][k];  // a corner without vt keeps GL's current (0, 0, 0, 1)
        const Vec3 uvw = t >= 0 ? mesh.texcoords[std::size_t(t)] : Vec3::Zero();
        texcoords.corners[3 * f + std::size_t(k)] = Vec4(uvw.x(), uvw.y(), uvw.z(), 1.0);
      }
  }
  const double uvMs = clock.stop();

  clock.start("texture", a.texture);
  render::Texture texture = loadTexture(a.texture);
  if (render::needsMipmaps(a.filter)) texture.buildMipmaps();
  options.texture = &texture;
  const double textureMs = clock.stop();

  clock.start("rendering", std::to_string(options.camera.width) + "x" + std::to_string(options.camera.height));
  options.aovs = !a.aov.empty();
  const render::Rendering rendering = render::render(mesh, texcoords, options);
  clock.stop();

  clock.start("writing", a.output);
  io::writeImage(a.output, rendering.colour, io::PixelType::UInt8);
  if (!a.aov.empty()) io::writeImage(a.aovOutput, selectChannels(rendering.aovs, aovs), io::PixelType::Float);
  const double writeMs = clock.stop();

  if (!a.json.empty()) {
    nlohmann::json j = {{"input", inputSummary},
                        {"output", a.output},
                        {"texcoords", source},
                        {"uv", perPixel ? "per-pixel" : "per-vertex"},
                        {"width", options.camera.width},
                        {"height", options.camera.height},
                        {"faces", mesh.faceCount()},
                        {"faces_drawn", rendering.raster.drawn},
                        {"faces_culled", rendering.raster.culled},
                        {"faces_clipped", rendering.raster.clipped},
                        {"covered_pixels", rendering.coveredPixels},
                        {"texture", {{"name", a.texture}, {"width", texture.width()}, {"height", texture.height()},
                                     {"levels", texture.levelCount()}}},
                        {"milliseconds",
                         {{"read", readMs}, {"texcoords", uvMs}, {"texture", textureMs}, {"raster", rendering.rasterMs},
                          {"shade", rendering.shadeMs}, {"write", writeMs}}}};
    if (!a.aov.empty()) j["aov_output"] = a.aovOutput;
    io::writeFileAtomically(a.json, j.dump(2) + "\n");
  }
  printInputWarnings(a.input, input.warnings);
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
  cmd->add_option("-o,--output", a->output, "Output image, 8-bit RGB, format by extension (.png, .tif, .jpg, ...)")->required();
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
  // texture
  cmd->add_option("--texture", a->texture,
                  "checker:N[:C] (N x N texels, C x C squares, white at texel 0,0), uvgrid[:N], or an image file "
                  "(top row at v = 1)")
      ->capture_default_str();
  addChoice<render::Filter>(*cmd, "--filter", a->filter,
                            {{"nearest", render::Filter::Nearest},
                             {"linear", render::Filter::Linear},
                             {"nearest_mipmap_nearest", render::Filter::NearestMipmapNearest},
                             {"linear_mipmap_nearest", render::Filter::LinearMipmapNearest},
                             {"nearest_mipmap_linear", render::Filter::NearestMipmapLinear},
                             {"linear_mipmap_linear", render::Filter::LinearMipmapLinear}},
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
  addChoice<UvEvaluation>(*cmd, "--uv", a->uv, {{"per-vertex", UvEvaluation::PerVertex}, {"per-pixel", UvEvaluation::PerPixel}},
                          "Interpolate per-vertex texture coordinates, or evaluate the mapping at every pixel")
      ->default_str("per-vertex");
  addProjectorOptions(*cmd, a->projector, true);
  addTexgenOptions(*cmd, a->texgen, "--texgen");
  // outputs
  cmd->add_option("--aov", a->aov, "Also write float AOVs: a list of uv, depth, face, lod")->type_name("uv,depth,face,lod");
  cmd->add_option("--aov-output", a->aovOutput, "The AOV file (.exr or .tif; default: the output with .exr)");
  cmd->add_option("--json", a->json, "Also write a summary as JSON");
  cmd->callback([a] { runRender(*a); });
}

}  // namespace uvtk::cli
