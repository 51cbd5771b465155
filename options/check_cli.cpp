#include "options/check_cli.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "io/image_io.h"
#include "io/mesh_reader.h"
#include "options/cli_values.h"

namespace uvtk::cli {

inspect::CheckOptions CheckArguments::resolve() const {
  for (const std::string& name : imageOptions)
    if (given(app, name.c_str())) throw UsageError(name + " goes with --image");
  if (textureSize < 1) throw UsageError("--texture-size: expected a positive number of texels");
  if (worst < 0) throw UsageError("--worst: expected a count of corners, 0 or more");
  if (tolerance && !(std::isfinite(*tolerance) && *tolerance >= 0.0))
    throw UsageError("--tolerance: expected a finite number of UV units, 0 or more");
  if (wrap != "none" && wrap != "u") throw UsageError("--wrap: expected none or u, found \"" + wrap + "\"");
  inspect::CheckOptions o;
  if (!against.empty()) {
    for (const std::string& name : mappingOptions)
      if (given(mapping.app, name.c_str()))
        throw UsageError("--against compares two files: " + name + " (a mapping option) does not go with it");
  } else {
    if (given(mapping.app, "--wrap"))
      throw UsageError("--wrap goes with --against only: a mapping knows its own period");
    const ResolvedMapping resolved = resolveMapping(mapping);
    if (resolved.projector && resolved.projector->seam == param::SeamMode::Cut)
      throw UsageError(
          "--seam cut changes the triangles, and uvtk check compares corner by corner: use --seam shift or none (u "
          "is compared modulo its period, so the seam's side does not matter)");
    o.projector = resolved.projector;
    o.texgen = resolved.texgen;
    o.seamPlaceAuto = resolved.seamPlaceAuto;
  }
  if (!view.empty()) {
    std::tie(o.viewWidth, o.viewHeight) = parseImageSize(viewSize, "--view-size");
    o.viewDir = parseVec3(viewDir, "--view-dir");
    o.viewUp = parseVec3(viewUp, "--view-up");
    io::checkImageType(view, io::PixelType::UInt8);
  }
  o.input = input, o.against = against, o.wrapU = wrap == "u", o.partial = partial;
  o.textureSize = textureSize, o.worst = std::size_t(worst), o.tolerance = tolerance;
  o.thresholds = verdict.thresholds();
  o.json = json, o.view = view;
  return o;
}

void addImageCheckOptions(CLI::App& app, CheckArguments& a) {
  a.app = &app;
  std::vector<std::string> before;
  for (const CLI::Option* option : app.get_options()) before.push_back(option->get_name());
  app.add_option("--image", a.image,
                 "Check this picture of the mesh, made by another renderer (a GPU, a shader), against uvtk's "
                 "rendering with the options of `uvtk render` (2D texture, replace)");
  app.add_option("--error-mask", a.errorMask, "--image: write the invalid pixels in red over the shot at a third (PNG)");
  app.add_option("--coord-bits", a.precision.coordBits,
                 "--image: a texel coordinate c may be off by max(1, |c|) 2^-N")
      ->capture_default_str();
  app.add_option("--weight-bits", a.precision.weightBits, "--image: each filter weight may be off by 2^-N")
      ->capture_default_str();
  app.add_option("--lod-bits", a.precision.lodBits,
                 "--image: lambda may be off by 2^-N beyond its neighbours' (default 6)");
  app.add_option("--color-bits", a.precision.colorBits,
                 "--image: each colour channel may be off by 2^-N (default 7, 6 for the *_mipmap_linear filters)");
  // `uvtk render`'s camera, texture and frame options that check has not under the same name
  // (--eye, --center, --up, --fovy, --view-dir and --wrap are shared; see CheckArguments).
  addCameraOptions(app, a.camera, false);
  app.add_option("--texture", a.texture.source,
                 "--image: checker:N[:C], uvgrid[:N], spheremap[:N[:K]] or an image file (top row at v = 1)")
      ->capture_default_str();
  addChoice<render::Filter>(app, "--filter", a.texture.filter, kFilterNames,
                            "--image: minification filter; magnification is nearest for nearest*, else linear")
      ->default_str("nearest");
  addFrameSceneOptions(app, a.frame);
  for (const CLI::Option* option : app.get_options())
    if (std::find(before.begin(), before.end(), option->get_name()) == before.end())
      a.imageOptions.push_back(option->get_name());
  a.imageOptions.erase(std::find(a.imageOptions.begin(), a.imageOptions.end(), "--image"));
}

inspect::ImageCheckRun checkImageFile(CheckArguments a) {
  CLI::App* app = a.app;
  for (const std::string& name : a.uvOptions)
    if (given(app, name.c_str())) throw UsageError(name + " goes with the UV comparison, not --image");
  for (const char* name : {"--derivatives", "--seam-fix"})  // `uvtk render`'s, when the frame's options have them
    if (app->get_option_no_throw(name) && given(app, name))
      throw UsageError(std::string(name) +
                       " does not go with --image: the reference has the exact derivatives, a GPU's quad differences "
                       "are allowed by the tolerances, and a seam line is what the check reports");
  ProjectorArguments& projector = a.mapping.projector;
  const bool projectorGiven = given(app, "--projector");
  if (projectorGiven && a.mapping.isTexgen()) throw UsageError("--projector and texgen options exclude each other");
  if (projectorGiven && param::traitsOf(projector.options.surface).isPerspective)
    throw UsageError("--image: --eye, --center and --up are the camera's; --projector camera is not supported");
  inspect::FrameSettings frameSettings = a.frame.settings();
  inspect::FrameOptions& frame = frameSettings.frame;
  // A triplanar blend exists per pixel only: drawn so unless --uv asks for the box mapping, as `uvtk render` does.
  if (projectorGiven && param::traitsOf(projector.options.surface).blendsProjections && !frameSettings.uvGiven)
    frame.perPixel = true;
  if (!projectorGiven && !a.mapping.isTexgen() && frame.perPixel)
    throw UsageError("--uv per-pixel evaluates a mapping: give --projector or --texgen");
  // The shared options are the camera's, as in `uvtk render`: taken, and cleared, so that the
  // projector reads no placement origin, reflection eye or camera projector's up and fovy from them.
  a.camera.eye = projector.eye;
  if (given(app, "--center")) a.camera.center = projector.center;
  if (given(app, "--up")) a.camera.up = projector.up;
  if (given(app, "--fovy")) a.camera.fovy = projector.options.camera.fovyDegrees;
  a.camera.viewDir = a.viewDir;
  for (const char* name : {"--eye", "--center", "--up", "--fovy"}) app->get_option(name)->clear();
  projector.eye.clear(), projector.center.clear(), projector.up.clear();
  a.texture.wrap = given(app, "--wrap") ? a.wrap : "";
  const inspect::CameraSettings camera = a.camera.settings();
  const inspect::TextureSettings texture = a.texture.settings();
  inspect::checkTextureUse(frame, texture, projectorGiven ? &projector.options : nullptr);
  if (!a.errorMask.empty()) io::checkImageType(a.errorMask, io::PixelType::UInt8);
  verify::resolvePrecision(a.precision, render::samplerFor(texture.filter, texture.wrapMode()), false);
  const Mat4 worldFromObject = a.mapping.model.empty() ? Mat4::Identity() : parseMatrix(a.mapping.model, "--model");

  io::ReadMeshResult input = io::readMesh(a.input);
  const render::Camera view = camera.make(input.mesh, a.input, worldFromObject, frame.width, frame.height);
  inspect::MappedMesh mapped;
  if (projectorGiven) {  // the reflection O-mapping sees from the camera's eye, as in `uvtk render`
    if (projector.options.ray == param::RayKind::Reflection)
      projector.options.eye = (worldFromObject.inverse() * view.eye().homogeneous()).head<3>();
    const param::ProjectorRequest resolved = projector.resolve();
    mapped = inspect::mapByProjector(std::move(input.mesh), resolved.options, resolved.seamPlaceAuto);
  } else if (a.mapping.isTexgen()) {
    a.mapping.texgen.arithmetic = projector.options.arithmetic;
    mapped = inspect::mapByTexgen(std::move(input.mesh), a.mapping.texgen.resolve(view.viewFromWorld, worldFromObject));
  } else {
    mapped = inspect::withFileUvs(std::move(input.mesh), a.input);
  }
  const inspect::BoundTexture bound = texture.load();
  inspect::ImageCheckOptions o;
  o.input = a.input, o.image = a.image, o.errorMask = a.errorMask, o.json = a.json, o.precision = a.precision;
  const inspect::ImageCheckRun run = inspect::checkImageShot(
      o, mapped, frame, inspect::renderOptions(frame, texture.options(), bound, view, worldFromObject));
  inspect::printMappingNotes(a.input, input.warnings, mapped);
  return run;
}

}  // namespace uvtk::cli
