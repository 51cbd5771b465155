#include "options/render_cli.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/error.h"
#include "core/gl_matrices.h"
#include "io/image_io.h"
#include "io/mesh_reader.h"
#include "inspect/run_report.h"
#include "options/arithmetic_cli.h"
#include "options/cli_values.h"
#include "render/procedural.h"
#include "io/json_text.h"

namespace uvtk::cli {

const std::vector<std::pair<std::string, render::Filter>> kFilterNames = {
    {"nearest", render::Filter::Nearest},
    {"linear", render::Filter::Linear},
    {"nearest_mipmap_nearest", render::Filter::NearestMipmapNearest},
    {"linear_mipmap_nearest", render::Filter::LinearMipmapNearest},
    {"nearest_mipmap_linear", render::Filter::NearestMipmapLinear},
    {"linear_mipmap_linear", render::Filter::LinearMipmapLinear}};
const std::vector<std::pair<std::string, render::Wrap>> kWrapNames = {
    {"repeat", render::Wrap::Repeat},
    {"clamp_to_edge", render::Wrap::ClampToEdge},
    {"mirrored_repeat", render::Wrap::MirroredRepeat}};
const std::vector<std::pair<std::string, render::EnvMode>> kEnvNames = {{"replace", render::EnvMode::Replace},
                                                                        {"modulate", render::EnvMode::Modulate},
                                                                        {"decal", render::EnvMode::Decal},
                                                                        {"blend", render::EnvMode::Blend}};
const std::vector<std::pair<std::string, render::Cull>> kCullNames = {
    {"back", render::Cull::Back}, {"front", render::Cull::Front}, {"none", render::Cull::None}};

namespace {

// The AOV channels `list` names ("uv,depth,face,lod" in any order and subset), by their names in
// Rendering::aovs; throws UsageError for anything else.
std::vector<std::string> aovChannels(const std::string& list) {
  std::vector<std::string> channels;
  for (const std::string& name : splitList(list)) {
    if (name == "uv") {
      channels.push_back("u"), channels.push_back("v");
    } else if (name == "depth" || name == "face" || name == "lod" || name == "cubeface") {
      channels.push_back(name);
    } else {
      throw UsageError("--aov: expected a list of uv, depth, face, lod, cubeface, found '" + name + "'");
    }
  }
  return channels;
}

}  // namespace

void addCameraOptions(CLI::App& app, CameraArguments& a, bool lookAt) {
  a.app = &app;
  addChoice<CameraArguments::Mode>(
      app, "--camera", a.mode, {{"auto", CameraArguments::Mode::Auto}, {"explicit", CameraArguments::Mode::Explicit}},
      "auto frames the mesh's bounding sphere (along --view-dir, or eye - center when --eye is given); explicit uses "
      "--eye, --center, --up as given. Default: explicit when --eye is given");
  if (lookAt) {
    app.add_option("--eye", a.eye, "Camera: gluLookAt eye (x,y,z); without it the camera frames the mesh")
        ->type_name("X,Y,Z");
    app.add_option("--center", a.center, "Camera: gluLookAt center")->type_name("X,Y,Z")->capture_default_str();
    app.add_option("--up", a.up,
                   "Camera: up; default 0,0,1 along --view-dir (as report's views; 0,1,0 within 18 degrees of z), "
                   "0,1,0 with --eye (gluLookAt's)")
        ->type_name("X,Y,Z");
    app.add_option("--view-dir", a.viewDir, "Automatic camera: direction from the mesh to the eye")
        ->type_name("X,Y,Z")
        ->capture_default_str();
    app.add_option("--fovy", a.fovy, "Camera: gluPerspective vertical field of view in degrees")->capture_default_str();
  }
  app.add_option("--near", a.zNear, "Camera: near plane distance (explicit camera; default 0.1)");
  app.add_option("--far", a.zFar, "Camera: far plane distance (explicit camera; default 100)");
  app.add_option("--ortho", a.ortho, "Orthographic camera: glOrtho left,right,bottom,top, or auto to frame the mesh")
      ->type_name("L,R,B,T|auto");
}

bool CameraArguments::explicitCamera() const {
  // Explicit when asked for, or when --eye is given without --camera.
  return app && given(app, "--camera") ? mode == Mode::Explicit : !eye.empty();
}

void CameraArguments::check() const {
  const bool manual = explicitCamera();
  if (manual && eye.empty()) throw UsageError("--camera explicit: expected --eye x,y,z");
  if (manual && ortho == "auto") throw UsageError("--ortho auto goes with the automatic camera");
  if (!manual && (zNear || zFar)) throw UsageError("--near and --far go with an explicit camera (--eye)");
  if (!up.empty()) parseVec3(up, "--up");
  parseVec3(center, "--center");
  parseVec3(viewDir, "--view-dir");
  if (!eye.empty()) parseVec3(eye, "--eye");
  if (!ortho.empty() && ortho != "auto") parseVec4(ortho, "--ortho");
}

render::Camera CameraArguments::make(const Mesh& mesh, const std::string& meshFile, const Mat4& worldFromObject, int width,
                                     int height) const {
  check();
  const bool manual = explicitCamera();
  const Vec3 direction =
      eye.empty() ? parseVec3(viewDir, "--view-dir") : Vec3(parseVec3(eye, "--eye") - parseVec3(center, "--center"));
  // Not given: z up along a view direction (report's camera), y up with an eye (gluLookAt's) or when
  // looking within 18 degrees of the z axis, where z would point almost out of the picture.
  const bool zUp = eye.empty() && std::fabs(direction.normalized().z()) < 0.95;
  const Vec3 upDir = !up.empty() ? parseVec3(up, "--up") : zUp ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
  render::Camera camera;
  if (!manual) {
    std::vector<Vec3> world(mesh.positions.size());
    for (std::size_t v = 0; v < world.size(); ++v)
      world[v] = (worldFromObject * mesh.positions[v].homogeneous()).head<3>();
    return render::frameSphere(render::boundingSphere(world), direction, upDir, {ortho == "auto", fovy}, width, height,
                               meshFile);
  }
  camera.width = width;
  camera.height = height;
  camera.viewFromWorld = lookAt(parseVec3(eye, "--eye"), parseVec3(center, "--center"), upDir);
  const double n = zNear.value_or(0.1), f = zFar.value_or(100.0);
  if (!ortho.empty()) {
    const Vec4 box = parseVec4(ortho, "--ortho");
    camera.clipFromView = orthographic(box[0], box[1], box[2], box[3], n, f);
  } else {
    camera.clipFromView = perspective(fovy, double(width) / double(height), n, f);
  }
  return camera;
}

void addTextureOptions(CLI::App& app, TextureArguments& a, const std::string& sourceOption) {
  app.add_option(sourceOption, a.source,
                 "checker:N[:C] (N x N texels in squares of C x C texels, white at texel 0,0), uvgrid[:N], spheremap[:N[:K]], or "
                 "an image file (top row at v = 1); cube maps: cube[:N], cubeindex[:N], cubefaces:PX,NX,PY,NY,PZ,NZ, "
                 "cubecross:FILE, cubestrip:FILE, cube3x2:FILE (a face's top row at t = 0), looked up by direction "
                 "(texgen, a file's vt) or by --projector cube --cube-layout faces")
      ->capture_default_str();
  addChoice<render::Filter>(app, "--filter", a.filter, kFilterNames,
                            "Minification filter; magnification is nearest for nearest*, else linear")
      ->default_str("nearest");
  std::vector<std::string> wrapNames;
  for (const auto& [name, wrap] : kWrapNames) wrapNames.push_back(name);
  app.add_option(
         "--wrap", a.wrap,
         "Wrap mode of s and t (default repeat); a cube map's applies to each face, default clamp_to_edge (GL's "
         "REPEAT would filter a face's edge with its opposite edge)")
      ->check(nameCheck(wrapNames))
      ->type_name("repeat|clamp_to_edge|mirrored_repeat");
  app.add_flag("--seamless", a.seamless,
               "Cube maps: filter across face edges (GL's TEXTURE_CUBE_MAP_SEAMLESS; off, as GL's default)");
  addChoice<render::EnvMode>(app, "--env", a.env, kEnvNames,
                             "Texture environment; modulate, decal and blend use Blinn-Phong lighting by a head-light")
      ->default_str("replace");
  app.add_option("--env-color", a.envColour, "GL_TEXTURE_ENV_COLOR for blend (r,g,b,a)")->capture_default_str();
  app.add_flag("--two-sided", a.twoSided,
               "Lighting: back faces lit with their normal negated, as front faces are (GL_LIGHT_MODEL_TWO_SIDE; off, as "
               "GL's default)");
}

bool TextureArguments::cubeMap() const { return inspect::isCubeMapSource(source); }

std::vector<std::string> TextureArguments::files() const { return inspect::textureFiles(source); }

void TextureArguments::resolveFiles(const std::function<std::string(const std::string&)>& resolve) {
  source = inspect::resolveTextureFiles(source, resolve);
}

void TextureArguments::check() const {
  files();
  if (seamless && !cubeMap())
    throw UsageError("--seamless filters cube maps across their edges: '" + source + "' is 2D");
}

render::Wrap TextureArguments::wrapMode() const {
  if (wrap.empty()) return cubeMap() ? render::Wrap::ClampToEdge : render::Wrap::Repeat;
  for (const auto& [name, mode] : kWrapNames)
    if (name == wrap) return mode;
  throw UsageError("--wrap: expected repeat, clamp_to_edge or mirrored_repeat, found '" + wrap + "'");
}

inspect::BoundTexture TextureArguments::load() const {
  check();
  return inspect::loadTexture(source, filter);
}

inspect::TextureOptions TextureArguments::options() const {
  inspect::TextureOptions o;
  o.filter = filter;
  o.wrap = wrapMode();
  o.env = env;
  o.envColour = parseVec4(envColour, "--env-color");
  o.seamless = seamless;
  o.twoSided = twoSided;
  return o;
}

void addFrameSceneOptions(CLI::App& app, FrameArguments& a) {
  app.add_option("--size", a.size, "Image size WxH")->capture_default_str();
  addChoice<render::Cull>(app, "--cull", a.cull, kCullNames, "Face culling; front faces are counter-clockwise")
      ->default_str("back");
  app.add_option("--background", a.background, "Background colour r,g,b in [0, 1]")->capture_default_str();
  addChoice<FrameArguments::Uv>(
      app, "--uv", a.uv,
      {{"per-vertex", FrameArguments::Uv::PerVertex},
       {"per-pixel", FrameArguments::Uv::PerPixel},
       {"baked", FrameArguments::Uv::Baked}},
      "Interpolate per-vertex texture coordinates, or evaluate the mapping at every pixel; baked: the camera "
      "projector's divided per-vertex (u, v), as an OBJ holds them, instead of its (s, t, q); --projector triplanar "
      "defaults to per-pixel, its blend")
      ->default_str("per-vertex");
  addChoice<render::Derivatives>(app, "--derivatives", a.derivatives,
                                 {{"analytic", render::Derivatives::Analytic},
                                  {"quad-coarse", render::Derivatives::QuadCoarse},
                                  {"quad-fine", render::Derivatives::QuadFine}},
                                 "The texture derivatives for the mipmap level: exact, or differences across 2x2 pixel "
                                 "quads as a GPU's dFdxCoarse / dFdxFine (the seam line of per-pixel mappings)")
      ->default_str("analytic");
  addChoice<render::SeamFix>(app, "--seam-fix", a.seamFix,
                             {{"none", render::SeamFix::None}, {"grad", render::SeamFix::Grad}, {"tarini", render::SeamFix::Tarini}},
                             "With quad derivatives: textureGrad with the analytic derivatives (grad), or Tarini's choice "
                             "of fract(u) or fract(u + 1/2) - 1/2 per pixel (tarini; per-pixel sphere and cylinder)")
      ->default_str("none");
}

void addFrameOptions(CLI::App& app, FrameArguments& a) {
  addFrameSceneOptions(app, a);
  app.add_option("--threads", a.threads, "Threads (0: one per hardware thread); the image does not depend on it")
      ->capture_default_str();
  app.add_option("--spp", a.samplesPerPixel,
                 "Supersampling: samples per pixel on a regular n x n grid (1, 4, 9, 16, ..., 256), box-filtered")
      ->capture_default_str();
  app.add_option("--aov", a.aov, "Also write float AOVs: a list of uv, depth, face, lod, cubeface (cube maps)")
      ->type_name("uv,depth,face,lod,cubeface");
  app.add_option("--aov-output", a.aovOutput, "The AOV file (.exr or .tif; default: the output with .exr)");
  app.add_option("--view", a.view,
                 "Draw inspection views instead: checker, uvgrid, stretch, linf, angle, area, seams, uverror, layout, "
                 "density, weights, blendzone, mipline (several: a contact sheet)")
      ->type_name("NAME[,NAME...]");
  addChoice<views::View>(app, "--layout-fill", a.layoutFill,
                         {{"stretch", views::View::Stretch},
                          {"linf", views::View::Linf},
                          {"angle", views::View::Angle},
                          {"area", views::View::Area},
                          {"density", views::View::Density}},
                         "The measure that fills the triangles of the layout view")
      ->default_str("stretch");
  app.add_option("--texture-size", a.textureSize,
                 "Texels W,H (or N: N,N) of the texture the density view counts texel density in")
      ->capture_default_str();
  app.add_option("--layout-size", a.layoutSize, "Pixels across the layout view's UV square")->capture_default_str();
  app.add_option("--bleed-level", a.bleedLevel,
                 "The bleed view's mip level (0: the whole --texture-size; default: the first level where charts mix)");
  app.add_option("--checks", a.checks, "Checks across the unit square in the checker view (1 to 1024)")
      ->capture_default_str();
}

void FrameArguments::check(const std::string& output) {
  imageSize();
  parseVec3(background, "--background");
  if (!aov.empty()) aovChannels(aov);
  if (!aov.empty() && aovOutput.empty()) aovOutput = std::filesystem::path(output).replace_extension(".exr").string();
  if (!aov.empty() && aovOutput == output) throw UsageError("--aov-output must differ from --output");
  if (!view.empty() && !aov.empty()) throw UsageError("--view and --aov exclude each other");
  views();
  densityTexture();
  if (layoutSize < 16 || layoutSize > 16384) throw UsageError("--layout-size: expected 16 to 16384 pixels");
  if (checks < 1 || checks > 1024) throw UsageError("--checks: expected 1 to 1024 checks, got " + std::to_string(checks));
  io::checkImageType(output, io::PixelType::UInt8);
  if (!aov.empty()) io::checkImageType(aovOutput, io::PixelType::Float);
}

std::pair<int, int> FrameArguments::imageSize() const { return parseImageSize(size, "--size"); }

analysis::TextureSize FrameArguments::densityTexture() const { return parseTextureSize(textureSize, "--texture-size"); }

std::vector<views::View> FrameArguments::views() const {
  return view.empty() ? std::vector<views::View>() : views::parseViewList(view);
}

bool FrameArguments::showsMeasures() const {
  inspect::FrameOptions o;
  o.views = views();
  return o.showsMeasures();
}

bool FrameArguments::needsExact() const {
  inspect::FrameOptions o;
  o.views = views();
  o.perPixel = uv == Uv::PerPixel;
  return o.needsExact();
}

inspect::FrameOptions FrameArguments::options() const {
  inspect::FrameOptions o;
  std::tie(o.width, o.height) = imageSize();
  o.cull = cull;
  o.threads = threads;
  o.samplesPerPixel = samplesPerPixel;
  o.background = parseVec3(background, "--background");
  o.perPixel = uv == Uv::PerPixel;
  o.baked = uv == Uv::Baked;
  o.derivatives = derivatives;
  o.seamFix = seamFix;
  if (!aov.empty()) o.aovs = aovChannels(aov);
  o.views = views();
  o.layoutFill = layoutFill;
  o.layoutSize = layoutSize;
  o.bleedLevel = bleedLevel;
  o.checks = checks;
  return o;
}

void checkTextureUse(const FrameArguments& frame, const TextureArguments& texture,
                     const param::ProjectorOptions* projector) {
  const bool cube = texture.cubeMap();
  if (cube && projector && !inspect::writesCubeFaceIds(*projector))
    throw UsageError(
        "a cube-map texture needs directions: --texgen, a file's vt, or --projector cube --cube-layout faces; for "
        "an atlas layout give the layout image as a 2D texture");
  const std::vector<std::string> aovs = frame.aov.empty() ? std::vector<std::string>() : aovChannels(frame.aov);
  if (!cube && std::find(aovs.begin(), aovs.end(), "cubeface") != aovs.end())
    throw UsageError("--aov cubeface: the texture '" + texture.source + "' is 2D, not a cube map");
}

RenderResult renderMeshFile(RenderJob a) {
  using namespace inspect;
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
  const render::Camera camera = a.camera.make(input.mesh, a.input, worldFromObject, width, height);
  clock.start("texture coordinates", std::to_string(input.mesh.faceCount()) + " faces");
  MappedMesh mapped;
  if (projectorGiven) {
    a.projector.options.eye = (worldFromObject.inverse() * camera.eye().homogeneous()).head<3>();
    const param::Projector projector = a.projector.resolve();
    mapped = mapByProjector(std::move(input.mesh), projector.options, projector.seamPlaceAuto);
  } else if (a.texgen.given()) {
    a.texgen.arithmetic = a.projector.options.arithmetic;  // render's --precision serves both
    mapped = mapByTexgen(std::move(input.mesh), a.texgen.resolve(camera.viewFromWorld, worldFromObject));
  } else {
    mapped = withFileUvs(std::move(input.mesh), a.input);
  }
  const double uvMs = clock.stop();

  clock.start("texture", a.texture.source);
  const BoundTexture texture = a.frame.options().samplesTexture() ? a.texture.load() : BoundTexture{};
  const double textureMs = clock.stop();

  clock.start(a.frame.view.empty() ? "rendering" : "drawing", a.frame.size);
  analysis::Judgement judgement;
  const auto measured = [&]() -> const analysis::Judgement& { return judgement = mapped.judge({}, 1024, 0, a.frame.densityTexture()); };
  io::OutputSet outputs;  // the picture, its AOVs and the record, published together
  // A triplanar blend exists per pixel only: drawn so unless --uv asks for the box mapping an OBJ holds.
  if (projectorGiven && param::traitsOf(a.projector.options.surface).blendsProjections && !given(a.projector.app, "--uv"))
    a.frame.uv = FrameArguments::Uv::PerPixel;
  const FrameOptions frame = a.frame.options();
  RenderResult result;
  nlohmann::json& j = result.record;
  j = writeFrame(outputs, frame, a.output, a.frame.aovOutput, mapped,
                 renderOptions(frame, a.texture.options(), texture, camera, worldFromObject), measured);
  clock.stop();

  j["input"] = inputSummary;
  j["arithmetic"] = arithmeticJson(a.projector.options.arithmetic);
  j["texture"]["name"] = a.texture.source;
  j["milliseconds"]["read"] = readMs;
  j["milliseconds"]["texcoords"] = uvMs;
  j["milliseconds"]["texture"] = textureMs;
  if (!a.json.empty()) outputs.writeText(a.json, io::jsonText(j, 2) + "\n");
  outputs.publish();
  printMappingNotes(a.input, input.warnings, mapped);
  if (a.frame.view.empty()) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "%dx%d, %zu faces drawn, %zu culled, %zu clipped, %zu pixels covered, raster %.1f ms, shade %.1f ms",
                  width, height, j["faces_drawn"].get<std::size_t>(), j["faces_culled"].get<std::size_t>(),
                  j["faces_clipped"].get<std::size_t>(), j["covered_pixels"].get<std::size_t>(),
                  j["milliseconds"]["raster"].get<double>(), j["milliseconds"]["shade"].get<double>());
    result.line = line;
  }
  return result;
}

}  // namespace uvtk::cli
