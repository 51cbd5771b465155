#include "options/projector_cli.h"

#include "core/error.h"
#include "options/arithmetic_cli.h"
#include "options/cli_values.h"

namespace uvtk::cli {

using namespace uvtk::param;

void addProjectorOptions(CLI::App& app, ProjectorArguments& a, bool cameraOwnsEye) {
  a.app = &app;
  a.context.cameraOwnsEye = cameraOwnsEye;
  if (cameraOwnsEye) a.context.center = "frame-center";
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
      ->default_str("1,0,0,0");
  app.add_option("--plane-v", a.planeV, "two-plane: plane a,b,c,d whose signed distance is v")
      ->type_name("A,B,C,D")
      ->default_str("0,1,0,0");
  app.add_flag("--caps", o.cylinderCaps, "cylinder: planar caps on faces facing along the axis");
  app.add_option("--cap-angle", o.capAngleDegrees, "cylinder: degrees between a cap face's normal and the axis")
      ->default_str("45");
  addChoice<CapLayout>(app, "--cap-layout", o.capLayout, kCapLayoutNames,
                       "cylinder caps: beside (side band below, caps side by side above) or stacked (all over the "
                       "unit square)")
      ->default_str("beside");
  addChoice<SpherePreset>(app, "--sphere-preset", o.spherePreset, kSpherePresetNames,
                          "sphere: default (u from +x, v = 1 at +z), glu (gluSphere), seed004")
      ->default_str("default");
  addChoice<CubeConvention>(app, "--cube-convention", o.cubeConvention, kCubeConventionNames,
                            "cube: gl (OpenGL face table) or direct")
      ->default_str("gl");
  addChoice<CubeLayout>(app, "--cube-layout", o.cubeLayout, kCubeLayoutNames,
                        "cube: cross (a 4x3 cross, no overlap), strip, 3x2, or faces (each face over the unit "
                        "square, its id as w: for cube-map textures)")
      ->default_str("cross");
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
  app.add_option("--uv-scale", a.uvScale, "UV transform: scale")->type_name("SU,SV")->default_str("1,1");
  app.add_option("--uv-offset", a.uvOffset, "UV transform: offset")->type_name("OU,OV")->default_str("0,0");
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
  app.add_option("--angle-limit", o.atlas.angleLimitDegrees,
                 "atlas: a face joins a projection direction within this many degrees of its normal")
      ->default_str("66");
  app.add_option("--margin", o.atlas.marginTexels, "atlas: texels of gutter between charts and from the border")
      ->default_str("4");
  app.add_option("--texels-per-unit", a.texelsPerUnit,
                 "atlas: texels per object unit for every chart (default: the most that fit one texture)");
  // The camera projector's own, in their own names where the command's camera has the plain ones.
  const auto freeName = [&](const char* name) {
    return cameraOwnsEye || app.get_option_no_throw(std::string("--") + name) ? std::string("proj-") + name
                                                                               : std::string(name);
  };
  param::ProjectorContext& names = a.context;
  if (cameraOwnsEye) {
    names.cameraEye = "proj-eye";
    names.cameraCenter = "proj-center";
    app.add_option("--proj-eye", a.projEye, "camera: gluLookAt eye of the camera projector (required)")
        ->type_name("X,Y,Z");
    app.add_option("--proj-center", a.projCenter, "camera: gluLookAt centre of the camera projector")
        ->type_name("X,Y,Z")
        ->default_str("0,0,0");
  }
  names.cameraUp = freeName("up");
  names.cameraFovy = freeName("fovy");
  names.cameraAspect = freeName("aspect");
  app.add_option("--" + names.cameraUp, a.up, "camera: gluLookAt up")->type_name("X,Y,Z")->default_str("0,1,0");
  app.add_option("--" + names.cameraFovy, o.camera.fovyDegrees,
                 "camera: gluPerspective field of view in y, degrees in (0, 180)")
      ->default_str("45");
  app.add_option("--" + names.cameraAspect, o.camera.aspect, "camera: gluPerspective aspect, width / height")
      ->default_str("1");
  addArithmeticOptions(app, o.arithmetic);
  addChoice<param::Convention>(
      app, "--convention", a.convention, kConventionNames,
      "Another tool's sphere or cylinder projector: blender (uv.sphere_project, cylinder_project, "
      "align to object), assimp (aiProcess_GenUVCoords); or notes: the lecture notes' cube (direct convention) "
      "and sphere (seed004) in object coordinates with the centroid ray; it sets the placement, seam and UV "
      "transform")
      ->default_str("uvtk");
}

ParameterDictionary ProjectorArguments::parameters() const {
  ParameterDictionary p(ParameterFace::CommandLine);
  const ProjectorOptions& o = options;
  const auto has = [&](const std::string& name) {
    const CLI::Option* option = app->get_option_no_throw("--" + name);
    return option && option->count() > 0;
  };
  const auto choice = [&](const char* name, const auto& table, auto value) {
    if (has(name)) p.add(name, nameOf(table, value));
  };
  const auto flag = [&](const char* name, bool value) {
    if (has(name)) p.add(name, value);
  };
  const auto number = [&](const std::string& name, double value) {
    if (has(name)) p.add(name, value);
  };
  const auto numbers = [&](const std::string& name, const std::string& text, int n) {
    if (!has(name)) return;
    const Eigen::VectorXd values = parseNumbers(text, n, "--" + name);
    p.add(name, std::vector<double>(values.data(), values.data() + n));
  };
  choice("projector", kSurfaceNames, o.surface);
  choice("omap", kRayNames, o.ray);
  choice("fit", kFitNames, o.placement.fit);
  choice("axis", kAxisNames, o.placement.axis);
  numbers(context.center, center, 3);
  numbers("axis-dir", axisDir, 3);
  numbers("ref-dir", refDir, 3);
  number("scale", scale);
  numbers("plane-u", planeU, 4);
  numbers("plane-v", planeV, 4);
  flag("caps", o.cylinderCaps);
  number("cap-angle", o.capAngleDegrees);
  choice("cap-layout", kCapLayoutNames, o.capLayout);
  choice("sphere-preset", kSpherePresetNames, o.spherePreset);
  choice("cube-convention", kCubeConventionNames, o.cubeConvention);
  choice("cube-layout", kCubeLayoutNames, o.cubeLayout);
  if (context.cameraOwnsEye) {
    numbers(context.cameraEye, projEye, 3);
    numbers(context.cameraCenter, projCenter, 3);
  }
  if (!eye.empty() && !context.cameraOwnsEye) {  // given, or set by `uvtk eval` from a row's own eye
    const Vec3 given = parseVec3(eye, "--eye");
    p.add("eye", std::vector<double>(given.data(), given.data() + 3));
  } else if (o.eye) {  // the reflection's eye, set by a command from its camera's (render, check --image)
    p.add("eye", std::vector<double>(o.eye->data(), o.eye->data() + 3));
  }
  flag("at-infinity", o.atInfinity);
  choice("seam", kSeamNames, o.seam);
  choice("pole", kPoleNames, o.pole);
  number("pole-eps", o.poleEpsilon);
  if (has("seam-place")) {
    if (seamPlace == "auto") p.add("seam-place", seamPlace);
    else p.add("seam-place", parseNumbers(seamPlace, 1, "--seam-place")[0]);
  }
  numbers("uv-scale", uvScale, 2);
  numbers("uv-offset", uvOffset, 2);
  number("uv-rotate", o.uvTransform.rotateDegrees);
  flag("flip-u", o.uvTransform.flipU);
  flag("flip-v", o.uvTransform.flipV);
  number("tile", o.triplanar.tile);
  number("blend", o.triplanar.blend);
  choice("triplanar-preset", kTriplanarPresetNames, o.triplanar.preset);
  number("angle-limit", o.atlas.angleLimitDegrees);
  number("margin", o.atlas.marginTexels);
  number("texels-per-unit", texelsPerUnit);
  numbers(context.cameraUp, up, 3);
  number(context.cameraFovy, o.camera.fovyDegrees);
  number(context.cameraAspect, o.camera.aspect);
  choice("precision", kPrecisionNames, o.arithmetic.precision);
  choice("math", kMathNames, o.arithmetic.math);
  choice("convention", kConventionNames, convention);
  return p;
}

param::ProjectorRequest ProjectorArguments::resolve() const { return makeProjector(parameters(), context); }

ProjectorOptions projectorNamed(const std::string& projector, const std::string& omap) {
  ProjectorOptions o;
  o.surface = parseNameList(projector, kSurfaceNames, "--projector").at(0);
  o.ray = parseNameList(omap, kRayNames, "--omap").at(0);
  return o;
}

}  // namespace uvtk::cli
