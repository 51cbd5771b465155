#include "options/projector_cli.h"

#include "core/error.h"
#include "options/arithmetic_cli.h"
#include "options/cli_values.h"
#include "options/option_names.h"

namespace uvtk::cli {

using namespace uvtk::param;

namespace {

const std::vector<std::pair<std::string, Convention>> kConventionNames = {
    {"uvtk", Convention::Uvtk},
    {"blender", Convention::Blender},
    {"assimp", Convention::Assimp},
    {"notes", Convention::Notes}};

// The options a convention sets; giving one of them as well is a usage error.
const char* const kConventionOwnedOptions[] = {"--fit",       "--axis",       "--axis-dir",      "--ref-dir",
                                               "--scale",     "--seam-place", "--sphere-preset", "--uv-scale",
                                               "--uv-offset", "--uv-rotate",  "--flip-u",        "--flip-v"};

// Another tool's projector as uvtk's placement, seam turn and UV transform (docs/conventions.md,
// "Other tools"): each is one of our surfaces seen from a frame that tool uses.
void applyConvention(Convention convention, ProjectorOptions& o) {
  const bool wraps = o.surface == SurfaceKind::Sphere || o.surface == SurfaceKind::Cylinder;
  switch (convention) {
    case Convention::Uvtk:
      return;
    case Convention::Blender:
      if (!wraps) throw UsageError("--convention blender: expected --projector sphere or cylinder");
      // Origin at the bounding box's centre (a script's pivot; --center gives another), object axes
      // and units; u = (1 - atan2(x, y)/pi)/2 puts the seam on -y and u = 0.25 on +x: our turn
      // fraction in the frame turned by 270 degrees.
      o.placement.fit = Fit::Center;
      o.placement.axis = 2;
      o.placement.turnDegrees = 270.0;
      if (o.surface == SurfaceKind::Cylinder) {  // v = (z + 1)/2 of the centred object z
        o.uvTransform.scale = Vec2(1.0, 0.5);
        o.uvTransform.offset = Vec2(0.0, 0.5);
      }
      return;
    case Convention::Assimp:
      if (!wraps) throw UsageError("--convention assimp: expected --projector sphere or cylinder");
      // The bounding box fit about object y; u = (atan2(x, z) + pi)/(2 pi) puts the seam on -z, which
      // is local -x of that frame: our turn fraction in the frame turned by 180 degrees.
      o.placement.fit = Fit::BBox;
      o.placement.axis = 1;
      o.placement.turnDegrees = 180.0;
      return;
    case Convention::Notes:
      if (o.surface != SurfaceKind::Cube && o.surface != SurfaceKind::Sphere)
        throw UsageError("--convention notes: expected --projector cube or sphere");
      // The notes work on a vector in object coordinates: no fit, the object's origin and axes.
      // The cube: the face of the major axis, (s, t) from the remaining coordinates in x, y, z
      // order ("direct"); the sphere: s = atan2(y, x)/(2 pi), t = acos(z)/pi (seed004). The ray
      // (centroid unless --omap is given) and the cube layout (faces by default) are set by the caller.
      o.placement.fit = Fit::None;
      o.cubeConvention = CubeConvention::Direct;
      o.spherePreset = SpherePreset::Seed004;
      return;
  }
}

}  // namespace

void addProjectorOptions(CLI::App& app, ProjectorArguments& a, bool cameraOwnsEye) {
  a.app = &app;
  a.cameraOwnsEye = cameraOwnsEye;
  ProjectorOptions& o = a.options;
  addChoice<SurfaceKind>(app, "--projector", o.surface, kSurfaceNames,
                         cameraOwnsEye ? "Texture coordinates by this projector (its intermediate surface)"
                                       : "Intermediate surface (S-mapping)")
      ->default_str(cameraOwnsEye ? "" : "sphere");
  addChoice<RayKind>(app, "--omap", o.ray, kRayNames,
                     "Ray mapping (O-mapping): isn = along the intermediate surface's own normal")
      ->default_str("isn");
  addChoice<Fit>(app, "--fit", o.placement.fit, kFitNames,
                 "Placement fitted to the mesh; none = object coordinates, center = the box's centre in object axes "
                 "and units")
      ->default_str("bbox");
  addChoice<int>(app, "--axis", o.placement.axis, kAxisNames, "Object axis that becomes the local z of a bbox fit")
      ->default_str("z");
  app.add_option(cameraOwnsEye ? "--frame-center" : "--center", a.center,
                 cameraOwnsEye ? "Explicit placement: origin x,y,z (replaces the fit)"
                               : "Explicit placement: origin x,y,z (replaces the fit); camera: gluLookAt centre "
                                 "(default 0,0,0)")
      ->type_name("X,Y,Z");
  app.add_option("--axis-dir", a.axisDir, "Explicit placement: local z direction")
      ->type_name("X,Y,Z")
      ->default_str("0,0,1");
  app.add_option("--ref-dir", a.refDir, "Explicit placement: local x reference direction")
      ->type_name("X,Y,Z")
      ->default_str("1,0,0");
  app.add_option("--scale", a.scale, "Explicit placement: object units per local unit")->default_str("1");
  app.add_option("--plane-u", a.planeU, "two-plane: plane a,b,c,d whose signed distance is u")
      ->type_name("A,B,C,D")
      ->default_str(a.planeU);
  app.add_option("--plane-v", a.planeV, "two-plane: plane a,b,c,d whose signed distance is v")
      ->type_name("A,B,C,D")
      ->default_str(a.planeV);
  app.add_flag("--caps", o.cylinderCaps, "cylinder: planar caps on faces facing along the axis");
  app.add_option("--cap-angle", o.capAngleDegrees, "cylinder: degrees between a cap face's normal and the axis")
      ->default_str("45");
  addChoice<SpherePreset>(app, "--sphere-preset", o.spherePreset, kSpherePresetNames,
                          "sphere: default (u from +x, v = 1 at +z), glu (gluSphere), seed004")
      ->default_str("default");
  addChoice<CubeConvention>(app, "--cube-convention", o.cubeConvention, kCubeConventionNames,
                            "cube: gl (OpenGL face table) or direct")
      ->default_str("gl");
  addChoice<CubeLayout>(app, "--cube-layout", o.cubeLayout, kCubeLayoutNames,
                        "cube: faces (face id as w), cross, strip, 3x2")
      ->default_str("faces");
  if (!cameraOwnsEye)
    app.add_option("--eye", a.eye, "reflection: eye position in object space (required); camera: gluLookAt eye (required)")
        ->type_name("X,Y,Z");
  app.add_flag("--at-infinity", o.atInfinity, "reflection: look up by the reflected direction only");
  addChoice<SeamMode>(app, "--seam", o.seam, kSeamNames, "Seam repair: none, shift (u in [0,1.5)), cut (u in [0,1])")
      ->default_str("shift");
  addChoice<PoleMode>(app, "--pole", o.pole, kPoleNames,
                      "Pole corners: none (u = 0) or fan (mean u of the face's other corners)")
      ->default_str("fan");
  app.add_option("--pole-eps", o.poleEpsilon, "A pole: hypot(x,y) <= eps |q|, eps in [0, 1)")->default_str("1e-06");
  app.add_option("--seam-place", a.seamPlace,
                 "cylinder, sphere: turn the projector about its axis to put the seam at this azimuth in degrees, or "
                 "auto: where it crosses the fewest faces")
      ->type_name("DEGREES|auto");
  app.add_option("--uv-scale", a.uvScale, "UV transform: scale")->type_name("SU,SV")->default_str(a.uvScale);
  app.add_option("--uv-offset", a.uvOffset, "UV transform: offset")->type_name("OU,OV")->default_str(a.uvOffset);
  app.add_option("--uv-rotate", o.uvTransform.rotateDegrees, "UV transform: degrees about (0.5,0.5)")->default_str("0");
  app.add_flag("--flip-u", o.uvTransform.flipU, "UV transform: u -> 1 - u (first)");
  app.add_flag("--flip-v", o.uvTransform.flipV, "UV transform: v -> 1 - v (first)");
  app.add_option("--tile", o.triplanar.tile, "triplanar: UV units per unit of the projector's frame (T)")
      ->default_str("1");
  app.add_option("--blend", o.triplanar.blend,
                 "triplanar: the weights' exponent B, w = |n|^B / sum (materialx: its blend b, exponent 1/max(b, 0.03))")
      ->default_str("1");
  addChoice<TriplanarPreset>(app, "--triplanar-preset", o.triplanar.preset, kTriplanarPresetNames,
                             "triplanar: unity (Shader Graph's Triplanar node), materialx (triplanarprojection, "
                             "upaxis Z), godot (BaseMaterial3D's triplanar)")
      ->default_str("unity");
  // The camera projector's own, in their own names where the command's camera has the plain ones.
  const auto freeName = [&](const char* name) {
    return cameraOwnsEye || app.get_option_no_throw(std::string("--") + name) ? std::string("--proj-") + name
                                                                               : std::string("--") + name;
  };
  param::CameraOptionNames& names = a.cameraNames;
  if (cameraOwnsEye) {
    names.eye = "--proj-eye";
    names.center = "--proj-center";
    app.add_option(names.eye, a.projEye, "camera: gluLookAt eye of the camera projector (required)")
        ->type_name("X,Y,Z");
    app.add_option(names.center, a.projCenter, "camera: gluLookAt centre of the camera projector")
        ->type_name("X,Y,Z")
        ->default_str("0,0,0");
  }
  names.up = freeName("up");
  names.fovy = freeName("fovy");
  names.aspect = freeName("aspect");
  app.add_option(names.up, a.up, "camera: gluLookAt up")->type_name("X,Y,Z")->default_str("0,1,0");
  app.add_option(names.fovy, o.camera.fovyDegrees, "camera: gluPerspective field of view in y, degrees in (0, 180)")
      ->default_str("45");
  app.add_option(names.aspect, o.camera.aspect, "camera: gluPerspective aspect, width / height")->default_str("1");
  addArithmeticOptions(app, o.arithmetic);
  addChoice<Convention>(
      app, "--convention", a.convention, kConventionNames,
      "Another tool's sphere or cylinder projector: blender (uv.sphere_project, cylinder_project, "
      "align to object), assimp (aiProcess_GenUVCoords); or notes: the lecture notes' cube (direct convention) "
      "and sphere (seed004) in object coordinates with the centroid ray; it sets the placement, seam and UV "
      "transform")
      ->default_str("uvtk");
}

ProjectorOptions ProjectorArguments::resolve() const {
  ProjectorOptions o = options;
  if (o.surface == SurfaceKind::Camera) {  // no surface: none of the surface projectors' options apply
    for (const char* name : {"--omap", "--fit", "--axis", "--axis-dir", "--ref-dir", "--scale", "--plane-u",
                             "--plane-v", "--caps", "--cap-angle", "--sphere-preset", "--cube-convention",
                             "--cube-layout", "--at-infinity", "--seam", "--pole", "--pole-eps", "--seam-place",
                             "--convention", "--frame-center"})
      if (app->get_option_no_throw(name) && given(app, name))
        throw UsageError(std::string(name) + " goes with the surface projectors, not --projector camera");
    const std::string& eyeText = cameraOwnsEye ? projEye : eye;
    const std::string& centerText = cameraOwnsEye ? projCenter : center;
    const param::CameraOptionNames& names = cameraNames;
    if (eyeText.empty()) throw UsageError("--projector camera: expected " + names.eye + " x,y,z");
    o.camera.eye = parseVec3(eyeText, names.eye.c_str());
    o.camera.center = centerText.empty() ? Vec3::Zero() : parseVec3(centerText, names.center.c_str());
    o.camera.up = up.empty() ? Vec3::UnitY() : parseVec3(up, names.up.c_str());
    checkCameraProjector(o.camera, names);
    if (!cameraOwnsEye) o.eye.reset();  // --eye was the camera's, not a reflection's
    o.placement = PlacementOptions{};
    o.placement.fit = Fit::None;
    o.uvTransform.scale = parseVec2(uvScale, "--uv-scale");
    o.uvTransform.offset = parseVec2(uvOffset, "--uv-offset");
    if (!std::isfinite(o.uvTransform.rotateDegrees)) throw UsageError("--uv-rotate: expected a finite number");
    return o;
  }
  std::vector<std::string> cameraOnly = {cameraNames.up, cameraNames.fovy, cameraNames.aspect};
  if (cameraOwnsEye) cameraOnly.insert(cameraOnly.end(), {cameraNames.eye, cameraNames.center});
  for (const std::string& name : cameraOnly)
    if (given(app, name.c_str())) throw UsageError(name + " goes with --projector camera only");
  const bool triplanar = o.surface == SurfaceKind::Triplanar;
  for (const char* name : {"--tile", "--blend", "--triplanar-preset"})
    if (!triplanar && given(app, name)) throw UsageError(std::string(name) + " goes with --projector triplanar only");
  if (triplanar) {  // three planes and no surface: the O-mapping, seam, pole and surface options do not apply
    for (const char* name : {"--omap", "--plane-u", "--plane-v", "--caps", "--cap-angle", "--sphere-preset",
                             "--cube-convention", "--cube-layout", "--at-infinity", "--seam", "--pole", "--pole-eps",
                             "--seam-place", "--convention"})
      if (app->get_option_no_throw(name) && given(app, name))
        throw UsageError(std::string(name) + " goes with the surface projectors, not --projector triplanar");
    if (!given(app, "--fit")) o.placement.fit = Fit::None;  // object space, as the engines project
  }
  const char* centerOption = cameraOwnsEye ? "--frame-center" : "--center";
  if (convention != Convention::Uvtk) {
    std::vector<const char*> owned(std::begin(kConventionOwnedOptions), std::end(kConventionOwnedOptions));
    if (convention != Convention::Blender) owned.push_back(centerOption);  // Blender's pivot may be anywhere
    if (convention == Convention::Notes) owned.push_back("--cube-convention");
    for (const char* name : owned)
      if (given(app, name))
        throw UsageError("--convention " + conventionName(convention) +
                         " sets the placement, the seam and the UV "
                         "transform; " +
                         name + " goes with --convention uvtk only");
  }
  const bool explicitFrame = (given(app, centerOption) && convention == Convention::Uvtk) || given(app, "--axis-dir") ||
                             given(app, "--ref-dir") || given(app, "--scale");
  if (explicitFrame) {
    if (given(app, "--fit") && o.placement.fit != Fit::None)
      throw UsageError(std::string(centerOption) +
                       ", --axis-dir, --ref-dir and --scale give the placement; they go with --fit none only");
    ExplicitFrame frame;
    if (!center.empty()) frame.center = parseVec3(center, centerOption);
    if (!axisDir.empty()) frame.axisDir = parseVec3(axisDir, "--axis-dir");
    if (!refDir.empty()) frame.refDir = parseVec3(refDir, "--ref-dir");
    frame.scale = scale;
    o.placement.frame = frame;
  }
  o.planeU = parseVec4(planeU, "--plane-u");
  o.planeV = parseVec4(planeV, "--plane-v");
  if (!eye.empty()) o.eye = parseVec3(eye, "--eye");
  if (o.ray == RayKind::Reflection && !o.eye) throw UsageError("--omap reflection: expected --eye x,y,z");
  if (o.ray != RayKind::Reflection && (o.atInfinity || (!cameraOwnsEye && o.eye)))
    throw UsageError("--eye and --at-infinity go with --omap reflection only");
  if (!seamPlace.empty()) {
    if (o.surface != SurfaceKind::Cylinder && o.surface != SurfaceKind::Sphere)
      throw UsageError("--seam-place: only the wrapping projectors (cylinder, sphere) have a seam to place");
    if (!seamPlaceAuto()) o.placement.turnDegrees = parseNumbers(seamPlace, 1, "--seam-place")[0];
  }
  o.uvTransform.scale = parseVec2(uvScale, "--uv-scale");
  o.uvTransform.offset = parseVec2(uvOffset, "--uv-offset");
  if (!std::isfinite(o.uvTransform.rotateDegrees)) throw UsageError("--uv-rotate: expected a finite number");
  applyConvention(convention, o);
  // The notes' vector is a direction from the origin (the cube's worked example selects its face
  // by it): the centroid ray, unless another O-mapping (e.g. reflection) is asked for.
  if (convention == Convention::Notes && !given(app, "--omap")) o.ray = RayKind::Centroid;
  if (convention == Convention::Blender && given(app, centerOption)) {
    ExplicitFrame pivot;  // the pivot Blender's 3D view used (Median Point: the mean of the face centroids)
    pivot.center = parseVec3(center, centerOption);
    o.placement.frame = pivot;
  }
  return o;
}

const std::string& conventionName(Convention convention) { return nameOf(kConventionNames, convention); }

ProjectorOptions projectorNamed(const std::string& projector, const std::string& omap) {
  ProjectorOptions o;
  o.surface = parseNameList(projector, kSurfaceNames, "--projector").at(0);
  o.ray = parseNameList(omap, kRayNames, "--omap").at(0);
  return o;
}

}  // namespace uvtk::cli
