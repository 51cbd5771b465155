#include "projector_cli.h"


#include "cli_values.h"
#include "core/error.h"

namespace uvtk::cli {

using namespace uvtk::param;

void addProjectorOptions(CLI::App& app, ProjectorArguments& a, bool cameraOwnsEye) {
  a.app = &app;
  a.cameraOwnsEye = cameraOwnsEye;
  ProjectorOptions& o = a.options;
  addChoice<SurfaceKind>(app, "--projector", o.surface,
                         {{"plane", SurfaceKind::Plane},
                          {"two-plane", SurfaceKind::TwoPlane},
                          {"cylinder", SurfaceKind::Cylinder},
                          {"sphere", SurfaceKind::Sphere},
                          {"cube", SurfaceKind::Cube}},
                         cameraOwnsEye ? "Texture coordinates by this projector (its intermediate surface)"
                                       : "Intermediate surface (S-mapping)")
      ->default_str(cameraOwnsEye ? "" : "sphere");
  addChoice<RayKind>(app, "--omap", o.ray,
                     {{"isn", RayKind::SurfaceNormal},
                      {"centroid", RayKind::Centroid},
                      {"normal", RayKind::ObjectNormal},
                      {"reflection", RayKind::Reflection}},
                     "Ray mapping (O-mapping): isn = along the intermediate surface's own normal")
      ->default_str("isn");
  addChoice<Fit>(app, "--fit", o.placement.fit,
                 {{"none", Fit::None}, {"bbox", Fit::BBox}, {"pca", Fit::Pca}, {"obb", Fit::Obb}},
                 "Placement fitted to the mesh; none = object coordinates")
      ->default_str("bbox");
  addChoice<int>(app, "--axis", o.placement.axis, {{"x", 0}, {"y", 1}, {"z", 2}},
                 "Object axis that becomes the local z of a bbox fit")
      ->default_str("z");
  app.add_option(cameraOwnsEye ? "--frame-center" : "--center", a.center, "Explicit placement: origin x,y,z (replaces the fit)")
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
  addChoice<SpherePreset>(app, "--sphere-preset", o.spherePreset,
                          {{"default", SpherePreset::Default}, {"glu", SpherePreset::Glu}, {"seed004", SpherePreset::Seed004}},
                          "sphere: default (u from +x, v = 1 at +z), glu (gluSphere), seed004")
      ->default_str("default");
  addChoice<CubeConvention>(app, "--cube-convention", o.cubeConvention,
                            {{"gl", CubeConvention::Gl}, {"direct", CubeConvention::Direct}},
                            "cube: gl (OpenGL face table) or direct")
      ->default_str("gl");
  addChoice<CubeLayout>(app, "--cube-layout", o.cubeLayout,
                        {{"faces", CubeLayout::Faces},
                         {"cross", CubeLayout::Cross},
                         {"strip", CubeLayout::Strip},
                         {"3x2", CubeLayout::ThreeByTwo}},
                        "cube: faces (face id as w), cross, strip, 3x2")
      ->default_str("faces");
  if (!cameraOwnsEye)
    app.add_option("--eye", a.eye, "reflection: eye position in object space (required)")->type_name("X,Y,Z");
  app.add_flag("--at-infinity", o.atInfinity, "reflection: look up by the reflected direction only");
  addChoice<SeamMode>(app, "--seam", o.seam,
                      {{"none", SeamMode::None}, {"shift", SeamMode::Shift}, {"cut", SeamMode::Cut}},
                      "Seam repair: none, shift (u in [0,1.5)), cut (u in [0,1])")
      ->default_str("shift");
  addChoice<PoleMode>(app, "--pole", o.pole, {{"none", PoleMode::None}, {"fan", PoleMode::Fan}},
                      "Pole corners: none (u = 0) or fan (mean u of the face's other corners)")
      ->default_str("fan");
  app.add_option("--pole-eps", o.poleEpsilon, "A pole: hypot(x,y) <= eps |q|, eps in [0, 1)")->default_str("1e-06");
  app.add_option("--uv-scale", a.uvScale, "UV transform: scale")->type_name("SU,SV")->default_str(a.uvScale);
  app.add_option("--uv-offset", a.uvOffset, "UV transform: offset")->type_name("OU,OV")->default_str(a.uvOffset);
  app.add_option("--uv-rotate", o.uvTransform.rotateDegrees, "UV transform: degrees about (0.5,0.5)")
      ->default_str("0");
  app.add_flag("--flip-u", o.uvTransform.flipU, "UV transform: u -> 1 - u (first)");
  app.add_flag("--flip-v", o.uvTransform.flipV, "UV transform: v -> 1 - v (first)");
}

ProjectorOptions ProjectorArguments::resolve() const {
  ProjectorOptions o = options;
  const char* centerOption = cameraOwnsEye ? "--frame-center" : "--center";
  const bool explicitFrame = given(app, centerOption) || given(app, "--axis-dir") || given(app, "--ref-dir") ||
                             given(app, "--scale");
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
  o.uvTransform.scale = parseVec2(uvScale, "--uv-scale");
  o.uvTransform.offset = parseVec2(uvOffset, "--uv-offset");
  if (!std::isfinite(o.uvTransform.rotateDegrees)) throw UsageError("--uv-rotate: expected a finite number");
  return o;
}

}  // namespace uvtk::cli
