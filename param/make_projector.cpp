#include "param/make_projector.h"

#include <cmath>

#include "core/number_text.h"
#include "param/surface_traits.h"

namespace uvtk::param {

namespace {

// Another tool's projector as uvtk's placement, seam turn and UV transform (docs/conventions.md,
// "Other tools"): each is one of our surfaces seen from a frame that tool uses.
void applyConvention(const ParameterDictionary& p, Convention convention, ProjectorOptions& o) {
  const bool wraps = traitsOf(o.surface).wraps;
  const std::string given = p.spelledWith("convention", nameOf(kConventionNames, convention));
  const std::string projector = p.spelled("projector");
  switch (convention) {
    case Convention::Uvtk:
      return;
    case Convention::Blender:
      if (!wraps) throw UsageError(given + ": expected " + projector + " sphere or cylinder");
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
      if (!wraps) throw UsageError(given + ": expected " + projector + " sphere or cylinder");
      // The bounding box fit about object y; u = (atan2(x, z) + pi)/(2 pi) puts the seam on -z, which
      // is local -x of that frame: our turn fraction in the frame turned by 180 degrees.
      o.placement.fit = Fit::BBox;
      o.placement.axis = 1;
      o.placement.turnDegrees = 180.0;
      return;
    case Convention::Notes:
      if (o.surface != SurfaceKind::Cube && o.surface != SurfaceKind::Sphere)
        throw UsageError(given + ": expected " + projector + " cube or sphere");
      // The notes work on a vector in object coordinates: no fit, the object's origin and axes.
      // The cube: the face of the major axis, (s, t) from the remaining coordinates in x, y, z
      // order ("direct"); the sphere: s = atan2(y, x)/(2 pi), t = acos(z)/pi (seed004). The ray
      // (centroid unless --omap is given) and the cube layout (faces by default) are set below.
      o.placement.fit = Fit::None;
      o.cubeConvention = CubeConvention::Direct;
      o.spherePreset = SpherePreset::Seed004;
      return;
  }
}

// The parameters a convention sets; giving one of them as well is a usage error.
const char* const kConventionOwned[] = {"fit",        "axis",      "axis-dir",  "ref-dir",   "scale",  "seam-place",
                                        "sphere-preset", "uv-scale", "uv-offset", "uv-rotate", "flip-u", "flip-v"};

// The surface projectors' own parameters, which neither the camera nor triplanar takes.
const char* const kSurfaceOnly[] = {"omap",           "plane-u",     "plane-v",     "caps",   "cap-angle", "cap-layout",
                                    "sphere-preset",  "cube-convention", "cube-layout", "at-infinity", "seam",
                                    "pole",           "pole-eps",    "seam-place",  "convention"};

// Reads the UV transform (every projector has one).
UvTransform uvTransformOf(const ParameterDictionary& p) {
  UvTransform t;
  t.scale = p.getVector<2>("uv-scale").value_or(Vec2::Ones());
  t.offset = p.getVector<2>("uv-offset").value_or(Vec2::Zero());
  t.rotateDegrees = p.getNumber("uv-rotate", 0.0);
  if (!std::isfinite(t.rotateDegrees)) throw UsageError(p.spelled("uv-rotate") + ": expected a finite number");
  t.flipU = p.getBool("flip-u", false);
  t.flipV = p.getBool("flip-v", false);
  return t;
}

// The atlas's own parameters.
const char* const kAtlasOnly[] = {"angle-limit", "margin", "texels-per-unit"};

}  // namespace

std::optional<std::array<int, 2>> readTextureSize(const ParameterDictionary& p) {
  if (!p.given("texture-size")) return std::nullopt;
  if (p.givenAsText("texture-size")) {
    const auto [width, height] = parseTextureSize(*p.getText("texture-size"), p.spelled("texture-size"));
    return std::array<int, 2>{width, height};
  }
  const std::string range = ": expected W,H or N (N,N) texels with 1 <= W, H <= 16384";
  if (p.givenAsNumbers("texture-size")) {
    const Eigen::Vector2d wh = *p.getVector<2>("texture-size");
    if (wh != wh.array().floor().matrix() || wh.minCoeff() < 1 || wh.maxCoeff() > 16384)
      throw UsageError(p.spelled("texture-size") + range);
    return std::array<int, 2>{int(wh.x()), int(wh.y())};
  }
  const int n = int(p.getInteger("texture-size", 1024, 1, 16384));
  return std::array<int, 2>{n, n};
}

std::vector<std::string> projectorParameterNames(const ProjectorContext& c) {
  std::vector<std::string> names = {"projector", "fit",      "axis",      "axis-dir",          "ref-dir",
                                    "scale",     "tile",     "blend",     "triplanar-preset",  "uv-scale",
                                    "uv-offset", "uv-rotate", "flip-u",   "flip-v",            "precision",
                                    "math",      "eye",      c.center,    c.cameraEye,         c.cameraCenter,
                                    c.cameraUp,  c.cameraFovy, c.cameraAspect};
  names.insert(names.end(), std::begin(kSurfaceOnly), std::end(kSurfaceOnly));
  names.insert(names.end(), std::begin(kAtlasOnly), std::end(kAtlasOnly));
  return names;
}

ProjectorRequest makeProjector(const ParameterDictionary& p, const ProjectorContext& c) {
  ProjectorRequest result;
  ProjectorOptions& o = result.options;
  o.surface = p.getChoice("projector", kSurfaceNames, SurfaceKind::Sphere);
  o.ray = p.getChoice("omap", kRayNames, RayKind::SurfaceNormal);
  o.placement.fit = p.getChoice("fit", kFitNames, c.defaultFit);
  o.placement.axis = p.getChoice("axis", kAxisNames, 2);
  o.cylinderCaps = p.getBool("caps", false);
  o.capAngleDegrees = p.getNumber("cap-angle", 45.0);
  o.capLayout = p.getChoice("cap-layout", kCapLayoutNames, CapLayout::Beside);
  o.spherePreset = p.getChoice("sphere-preset", kSpherePresetNames, SpherePreset::Default);
  o.cubeConvention = p.getChoice("cube-convention", kCubeConventionNames, CubeConvention::Gl);
  o.cubeLayout = p.getChoice("cube-layout", kCubeLayoutNames, CubeLayout::Cross);
  o.atInfinity = p.getBool("at-infinity", false);
  o.seam = p.getChoice("seam", kSeamNames, SeamMode::Shift);
  o.pole = p.getChoice("pole", kPoleNames, PoleMode::Fan);
  o.poleEpsilon = p.getNumber("pole-eps", 1e-6);
  o.triplanar.tile = p.getNumber("tile", 1.0);
  o.triplanar.blend = p.getNumber("blend", 1.0);
  o.triplanar.preset = p.getChoice("triplanar-preset", kTriplanarPresetNames, TriplanarPreset::Unity);
  o.camera.fovyDegrees = p.getNumber(c.cameraFovy, 45.0);
  o.camera.aspect = p.getNumber(c.cameraAspect, 1.0);
  o.arithmetic.precision = p.getChoice("precision", kPrecisionNames, Precision::Double);
  o.arithmetic.math = p.getChoice("math", kMathNames, MathMode::Exact);
  const Convention convention = p.getChoice("convention", kConventionNames, Convention::Uvtk);
  const std::string projector = p.spelled("projector");

  if (o.surface == SurfaceKind::Camera) {  // no surface: none of the surface projectors' options apply
    std::vector<std::string> refused = {"fit", "axis", "axis-dir", "ref-dir", "scale"};
    refused.insert(refused.end(), std::begin(kSurfaceOnly), std::end(kSurfaceOnly));
    if (c.center != c.cameraCenter) refused.push_back(c.center);
    for (const std::string& name : refused)
      if (p.given(name))
        throw UsageError(p.spelled(name) + " goes with the surface projectors, not " +
                         p.spelledWith("projector", "camera"));
    CameraOptionNames names{p.spelled(c.cameraEye), p.spelled(c.cameraCenter), p.spelled(c.cameraUp),
                            p.spelled(c.cameraFovy), p.spelled(c.cameraAspect)};
    const std::optional<Vec3> eye = p.getVector<3>(c.cameraEye);
    if (!eye) throw UsageError(p.spelledWith("projector", "camera") + ": expected " + names.eye + " x,y,z");
    o.camera.eye = *eye;
    o.camera.center = p.getVector<3>(c.cameraCenter).value_or(Vec3::Zero());
    o.camera.up = p.getVector<3>(c.cameraUp).value_or(Vec3::UnitY());
    checkCameraProjector(o.camera, names);
    o.placement = PlacementOptions{};
    o.placement.fit = Fit::None;
    o.uvTransform = uvTransformOf(p);
    return result;
  }
  std::vector<std::string> cameraOnly = {c.cameraUp, c.cameraFovy, c.cameraAspect};
  if (c.cameraOwnsEye) cameraOnly.insert(cameraOnly.end(), {c.cameraEye, c.cameraCenter});
  for (const std::string& name : cameraOnly)
    if (p.given(name)) throw UsageError(p.spelled(name) + " goes with " + p.spelledWith("projector", "camera") + " only");
  const bool atlas = traitsOf(o.surface).chartsFromMesh;
  for (const char* name : kAtlasOnly)
    if (!atlas && p.given(name))
      throw UsageError(p.spelled(name) + " goes with " + p.spelledWith("projector", "atlas") + " only");
  if (atlas) {  // charts placed by the atlas itself: no placement, O-mapping, seam or pole
    std::vector<std::string> refused = {"fit", "axis", "axis-dir", "ref-dir", "scale", "convention", c.center};
    refused.insert(refused.end(), std::begin(kSurfaceOnly), std::end(kSurfaceOnly));
    for (const std::string& name : refused)
      if (p.given(name))
        throw UsageError(p.spelled(name) + " goes with the surface projectors, not " + p.spelledWith("projector", "atlas"));
    o.atlas.angleLimitDegrees = p.getNumber("angle-limit", o.atlas.angleLimitDegrees);
    if (!(o.atlas.angleLimitDegrees >= 1.0 && o.atlas.angleLimitDegrees <= 89.0))
      throw UsageError(p.spelled("angle-limit") + ": expected degrees in [1, 89]");
    o.atlas.marginTexels = p.getNumber("margin", o.atlas.marginTexels);
    if (!(o.atlas.marginTexels >= 0.0 && o.atlas.marginTexels <= 1024.0))
      throw UsageError(p.spelled("margin") + ": expected texels in [0, 1024]");
    o.atlas.textureSize = readTextureSize(p).value_or(o.atlas.textureSize);
    if (2.0 * o.atlas.marginTexels >= double(std::min(o.atlas.textureSize[0], o.atlas.textureSize[1])))
      throw UsageError(p.spelled("margin") + ": two margins must leave room in the texture (" + p.spelled("texture-size") + ")");
    if (p.given("texels-per-unit")) {
      o.atlas.texelsPerUnit = p.getNumber("texels-per-unit", 0.0);
      if (!(*o.atlas.texelsPerUnit > 0.0 && std::isfinite(*o.atlas.texelsPerUnit)))
        throw UsageError(p.spelled("texels-per-unit") + ": expected a finite number above 0");
    }
    o.placement.fit = Fit::None;
    o.uvTransform = uvTransformOf(p);
    return result;
  }
  const bool triplanar = traitsOf(o.surface).blendsProjections;
  for (const char* name : {"tile", "blend", "triplanar-preset"})
    if (!triplanar && p.given(name))
      throw UsageError(p.spelled(name) + " goes with " + p.spelledWith("projector", "triplanar") + " only");
  if (triplanar) {  // three planes and no surface: the O-mapping, seam, pole and surface options do not apply
    for (const char* name : kSurfaceOnly)
      if (p.given(name))
        throw UsageError(p.spelled(name) + " goes with the surface projectors, not " +
                         p.spelledWith("projector", "triplanar"));
    if (!p.given("fit")) o.placement.fit = Fit::None;  // object space, as the engines project
  }
  for (const char* name : {"caps", "cap-angle", "cap-layout"})
    if (o.surface != SurfaceKind::Cylinder && p.given(name))
      throw UsageError(p.spelled(name) + " goes with " + p.spelledWith("projector", "cylinder") + " only");
  if (convention != Convention::Uvtk) {
    std::vector<std::string> owned(std::begin(kConventionOwned), std::end(kConventionOwned));
    if (convention != Convention::Blender) owned.push_back(c.center);  // Blender's pivot may be anywhere
    if (convention == Convention::Notes) owned.push_back("cube-convention");
    for (const std::string& name : owned)
      if (p.given(name))
        throw UsageError(p.spelledWith("convention", nameOf(kConventionNames, convention)) +
                         " sets the placement, the seam and the UV transform; " + p.spelled(name) + " goes with " +
                         p.spelledWith("convention", "uvtk") + " only");
  }
  const std::optional<Vec3> center = p.getVector<3>(c.center);
  const bool explicitFrame = (center && convention == Convention::Uvtk) || p.given("axis-dir") ||
                             p.given("ref-dir") || p.given("scale");
  if (explicitFrame) {
    if (p.given("fit") && o.placement.fit != Fit::None)
      throw UsageError(p.spelled(c.center) + ", " + p.spelled("axis-dir") + ", " + p.spelled("ref-dir") + " and " +
                       p.spelled("scale") + " give the placement; they go with " + p.spelledWith("fit", "none") +
                       " only");
    ExplicitFrame frame;
    if (center) frame.center = *center;
    frame.axisDir = p.getVector<3>("axis-dir").value_or(frame.axisDir);
    frame.refDir = p.getVector<3>("ref-dir").value_or(frame.refDir);
    frame.scale = p.getNumber("scale", 1.0);
    o.placement.frame = frame;
  }
  o.planeU = p.getVector<4>("plane-u").value_or(o.planeU);
  o.planeV = p.getVector<4>("plane-v").value_or(o.planeV);
  o.eye = p.getVector<3>("eye");
  if (o.ray == RayKind::Reflection && !o.eye)
    throw UsageError(p.spelledWith("omap", "reflection") + ": expected " + p.spelled("eye") + " x,y,z");
  if (o.ray != RayKind::Reflection && (o.atInfinity || (!c.cameraOwnsEye && o.eye)))
    throw UsageError(p.spelled("eye") + " and " + p.spelled("at-infinity") + " go with " +
                     p.spelledWith("omap", "reflection") + " only");
  if (p.given("seam-place")) {
    if (!traitsOf(o.surface).wraps)
      throw UsageError(p.spelled("seam-place") +
                       ": only the wrapping projectors (cylinder, sphere) have a seam to place");
    if (p.givenAsText("seam-place")) {  // auto, or degrees as a number
      const std::string text = *p.getText("seam-place");
      if (text != "auto") throw UsageError(p.spelled("seam-place") + ": expected degrees or 'auto', got '" + text + "'");
      result.seamPlaceAuto = true;
    } else {
      o.placement.turnDegrees = p.getNumber("seam-place", 0.0);
      if (!std::isfinite(o.placement.turnDegrees))
        throw UsageError(p.spelled("seam-place") + ": expected a finite number of degrees");
    }
  }
  o.uvTransform = uvTransformOf(p);
  applyConvention(p, convention, o);
  // The notes' vector is a direction from the origin (the cube's worked example selects its face
  // by it): the centroid ray, unless another O-mapping (e.g. reflection) is asked for.
  if (convention == Convention::Notes && !p.given("omap")) o.ray = RayKind::Centroid;
  // Its worked examples give each face's own (s, t): the faces layout, unless another is asked for.
  if (convention == Convention::Notes && !p.given("cube-layout")) o.cubeLayout = CubeLayout::Faces;
  if (convention == Convention::Blender && center) {
    ExplicitFrame pivot;  // the pivot Blender's 3D view used (Median Point: the mean of the face centroids)
    pivot.center = *center;
    o.placement.frame = pivot;
  }
  return result;
}

}  // namespace uvtk::param
