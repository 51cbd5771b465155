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

namespace {

std::vector<double> numbers(const Eigen::VectorXd& vector) { return {vector.data(), vector.data() + vector.size()}; }

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

void CameraArguments::addTo(param::ParameterDictionary& p) const {
  if (app && given(app, "--camera")) p.add("camera", std::string(mode == Mode::Explicit ? "explicit" : "auto"));
  if (!eye.empty()) p.add("eye", numbers(parseVec3(eye, "--eye")));
  p.add("center", numbers(parseVec3(center, "--center")));
  if (!up.empty()) p.add("up", numbers(parseVec3(up, "--up")));
  p.add("view-dir", numbers(parseVec3(viewDir, "--view-dir")));
  p.add("fovy", fovy);
  if (zNear) p.add("near", *zNear);
  if (zFar) p.add("far", *zFar);
  if (!ortho.empty()) p.add("ortho", ortho);
}

inspect::CameraSettings CameraArguments::settings() const {
  param::ParameterDictionary p(param::ParameterFace::CommandLine);
  addTo(p);
  return inspect::readCameraSettings(p);
}

void addTextureOptions(CLI::App& app, TextureArguments& a, const std::string& sourceOption) {
  a.app = &app;
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

void TextureArguments::addTo(param::ParameterDictionary& p) const {
  p.add("texture", source);
  if (!app || given(app, "--filter")) p.add("filter", nameOf(kFilterNames, filter));
  if (!wrap.empty()) p.add("wrap", wrap);
  p.add("env", nameOf(kEnvNames, env));
  p.add("env-color", numbers(parseVec4(envColour, "--env-color")));
  p.add("seamless", seamless);
  p.add("two-sided", twoSided);
}

inspect::TextureSettings TextureArguments::settings() const {
  param::ParameterDictionary p(param::ParameterFace::CommandLine);
  addTo(p);
  return inspect::readTextureSettings(p, "texture");
}

void addFrameSceneOptions(CLI::App& app, FrameArguments& a) {
  a.app = &app;
  app.add_option("--size", a.size, "Image size WxH")->capture_default_str();
  addChoice<render::Cull>(app, "--cull", a.cull, kCullNames, "Face culling; front faces are counter-clockwise")
      ->default_str("back");
  app.add_option("--background", a.background, "Background colour r,g,b in [0, 1]")->capture_default_str();
  addChoice<FrameArguments::Uv>(
      app, "--uv", a.uv, inspect::kUvNames,
      "Interpolate per-vertex texture coordinates, or evaluate the mapping at every pixel; baked: the camera "
      "projector's divided per-vertex (u, v), as an OBJ holds them, instead of its (s, t, q); --projector triplanar "
      "defaults to per-pixel, its blend")
      ->default_str("per-vertex");
  addChoice<render::Derivatives>(app, "--derivatives", a.derivatives, inspect::kDerivativeNames,
                                 "The texture derivatives for the mipmap level: exact, or differences across 2x2 pixel "
                                 "quads as a GPU's dFdxCoarse / dFdxFine (the seam line of per-pixel mappings)")
      ->default_str("analytic");
  addChoice<render::SeamFix>(app, "--seam-fix", a.seamFix, inspect::kSeamFixNames,
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
  addChoice<views::View>(app, "--layout-fill", a.layoutFill, inspect::kLayoutFillNames,
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

void FrameArguments::addSceneTo(param::ParameterDictionary& p) const {
  p.add("size", size);
  p.add("cull", nameOf(kCullNames, cull));
  p.add("background", numbers(parseVec3(background, "--background")));
  if (app && given(app, "--uv"))
    p.add("uv", nameOf(inspect::kUvNames, uv));
  p.add("derivatives", nameOf(inspect::kDerivativeNames, derivatives));
  p.add("seam-fix", nameOf(inspect::kSeamFixNames, seamFix));
}

inspect::FrameSettings FrameArguments::settings() const {
  param::ParameterDictionary p(param::ParameterFace::CommandLine);
  addSceneTo(p);
  p.add("threads", std::int64_t(threads));
  p.add("spp", std::int64_t(samplesPerPixel));
  if (!aov.empty()) p.add("aov", splitList(aov));
  if (!aovOutput.empty()) p.add("aov-output", aovOutput);
  if (!view.empty()) p.add("view", view);
  p.add("layout-fill", nameOf(inspect::kLayoutFillNames, layoutFill));
  p.add("layout-size", std::int64_t(layoutSize));
  if (bleedLevel) p.add("bleed-level", std::int64_t(*bleedLevel));
  p.add("checks", std::int64_t(checks));
  p.add("texture-size", textureSize);
  return inspect::readFrameSettings(p);
}

RenderResult renderMeshFile(RenderJob a) {
  using namespace inspect;
  const bool projectorGiven = given(a.projector.app, "--projector");
  if (projectorGiven && a.texgen.given()) throw UsageError("--projector and texgen options exclude each other");
  FrameSettings frameSettings = a.frame.settings();
  checkFrameOutputs(frameSettings, a.output);  // nothing is written unless every output can be
  FrameOptions& frame = frameSettings.frame;
  if (!projectorGiven && !a.texgen.given() && frame.needsExact())
    throw UsageError(frame.perPixel ? "--uv per-pixel evaluates a mapping: give --projector or --texgen"
                                    : "--view uverror compares with the exact mapping: give --projector or --texgen");
  const CameraSettings cameraSettings = a.camera.settings();
  const TextureSettings textureSettings = a.texture.settings();
  checkTextureUse(frame, textureSettings, projectorGiven ? &a.projector.options : nullptr);
  const Mat4 worldFromObject = a.model.empty() ? Mat4::Identity() : parseMatrix(a.model, "--model");

  StageClock clock("uvtk render");
  clock.start("reading", a.input);
  io::ReadMeshResult input = io::readMesh(a.input);
  const double readMs = clock.stop();
  const nlohmann::json inputSummary = inputJson(a.input, input);

  const int width = frame.width, height = frame.height;
  const render::Camera camera = cameraSettings.make(input.mesh, a.input, worldFromObject, width, height);
  clock.start("texture coordinates", std::to_string(input.mesh.faceCount()) + " faces");
  MappedMesh mapped;
  if (projectorGiven) {
    a.projector.options.eye = (worldFromObject.inverse() * camera.eye().homogeneous()).head<3>();
    const param::ProjectorRequest projector = a.projector.resolve();
    mapped = mapByProjector(std::move(input.mesh), projector.options, projector.seamPlaceAuto);
  } else if (a.texgen.given()) {
    a.texgen.arithmetic = a.projector.options.arithmetic;  // render's --precision serves both
    mapped = mapByTexgen(std::move(input.mesh), a.texgen.resolve(camera.viewFromWorld, worldFromObject));
  } else {
    mapped = withFileUvs(std::move(input.mesh), a.input);
  }
  const double uvMs = clock.stop();

  clock.start("texture", a.texture.source);
  const BoundTexture texture = frame.samplesTexture() ? textureSettings.load() : BoundTexture{};
  const double textureMs = clock.stop();

  clock.start(a.frame.view.empty() ? "rendering" : "drawing", a.frame.size);
  analysis::Judgement judgement;
  const auto measured = [&]() -> const analysis::Judgement& { 
    return judgement = mapped.judge({}, analysis::kOverlapFollowsMesh, 0, frameSettings.densityTexture);
  };
  io::OutputSet outputs;  // the picture, its AOVs and the record, published together
  // A triplanar blend exists per pixel only: drawn so unless --uv asks for the box mapping an OBJ holds.
  if (projectorGiven && param::traitsOf(a.projector.options.surface).blendsProjections && !frameSettings.uvGiven)
    frame.perPixel = true;
  RenderResult result;
  nlohmann::json& j = result.record;
  j = writeFrame(outputs, frame, a.output, frameSettings.aovOutput, mapped,
                 renderOptions(frame, textureSettings.options(), texture, camera, worldFromObject), measured);
  clock.stop();

  j["input"] = inputSummary;
  j["arithmetic"] = arithmeticJson(a.projector.options.arithmetic);
  j["texture"]["name"] = textureSettings.source;
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
