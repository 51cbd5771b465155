#include "inspect/projector_json.h"

#include <cmath>
#include <cstdio>

#include "param/projector_names.h"

namespace uvtk::inspect {

using namespace uvtk::param;

nlohmann::json projectorOptionsJson(const ProjectorOptions& o) {
  nlohmann::json j = {{"projector", nameOf(kSurfaceNames, o.surface)},
                      {"omap", nameOf(kRayNames, o.ray)},
                      {"fit", nameOf(kFitNames, o.placement.fit)},
                      {"axis", nameOf(kAxisNames, o.placement.axis)},
                      {"turn_degrees", o.placement.turnDegrees},
                      {"seam", nameOf(kSeamNames, o.seam)},
                      {"pole", nameOf(kPoleNames, o.pole)},
                      {"pole_eps", o.poleEpsilon},
                      {"sphere_preset", nameOf(kSpherePresetNames, o.spherePreset)},
                      {"cube_convention", nameOf(kCubeConventionNames, o.cubeConvention)},
                      {"cube_layout", nameOf(kCubeLayoutNames, o.cubeLayout)},
                      {"caps", o.cylinderCaps},
                      {"cap_angle", o.capAngleDegrees},
                      {"plane_u", {o.planeU[0], o.planeU[1], o.planeU[2], o.planeU[3]}},
                      {"plane_v", {o.planeV[0], o.planeV[1], o.planeV[2], o.planeV[3]}},
                      {"uv_scale", {o.uvTransform.scale.x(), o.uvTransform.scale.y()}},
                      {"uv_offset", {o.uvTransform.offset.x(), o.uvTransform.offset.y()}},
                      {"uv_rotate", o.uvTransform.rotateDegrees},
                      {"flip_u", o.uvTransform.flipU},
                      {"flip_v", o.uvTransform.flipV},
                      {"precision", precisionName(o.arithmetic.precision)},
                      {"math", mathName(o.arithmetic.math)}};
  if (const auto& f = o.placement.frame)
    j["frame"] = {{"center", {f->center.x(), f->center.y(), f->center.z()}},
                  {"axis_dir", {f->axisDir.x(), f->axisDir.y(), f->axisDir.z()}},
                  {"ref_dir", {f->refDir.x(), f->refDir.y(), f->refDir.z()}},
                  {"scale", f->scale}};
  if (o.eye) j["eye"] = {o.eye->x(), o.eye->y(), o.eye->z()};
  if (traitsOf(o.surface).isPerspective) {
    const CameraProjector& c = o.camera;
    j["camera"] = {{"eye", {c.eye.x(), c.eye.y(), c.eye.z()}},
                   {"center", {c.center.x(), c.center.y(), c.center.z()}},
                   {"up", {c.up.x(), c.up.y(), c.up.z()}},
                   {"fovy", c.fovyDegrees},
                   {"aspect", c.aspect}};
  }
  if (traitsOf(o.surface).blendsProjections)
    j["triplanar"] = {{"preset", nameOf(kTriplanarPresetNames, o.triplanar.preset)},
                      {"tile", o.triplanar.tile},
                      {"blend", o.triplanar.blend},
                      {"exponent", triplanarExponent(o.triplanar)}};
  if (traitsOf(o.surface).chartsFromMesh) {
    const AtlasOptions& a = o.atlas;
    j["atlas"] = {{"angle_limit", a.angleLimitDegrees},
                  {"margin", a.marginTexels},
                  {"texture_size", {a.textureSize[0], a.textureSize[1]}},
                  {"texels_per_unit", a.texelsPerUnit ? nlohmann::json(*a.texelsPerUnit) : nlohmann::json()}};
  }
  if (o.ray == RayKind::Reflection) j["at_infinity"] = o.atInfinity;
  return j;
}

nlohmann::json atlasJson(const Atlas& a) {
  const auto finiteOrNull = [](double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); };
  return {{"charts", a.charts.size()},
          {"directions", a.directions},
          {"split_charts", a.splitCharts},
          {"merged_charts", a.mergedCharts},
          {"degenerate_faces", a.degenerateFaces},
          {"texels_per_unit", a.texelsPerUnit},
          {"tiles", a.tiles},
          {"occupancy", a.occupancy},
          {"gutter_texels", finiteOrNull(a.gutterTexels)},
          {"border_texels", finiteOrNull(a.borderTexels)},
          {"seam_edges", a.seamEdges},
          {"seam_length", a.seamLength},
          {"stretch_bound", a.stretchBound},
          {"fallback_charts", a.fallbackCharts},
          {"fallback_reasons", a.fallbackReasons}};
}

std::string atlasLine(const Atlas& a) {
  char line[200];
  std::snprintf(line, sizeof line, "%zu charts, occupancy %.3f, gutter %.3g texels, %.4g texels per unit%s",
                a.charts.size(), a.occupancy, a.gutterTexels, a.texelsPerUnit,
                a.tiles > 1 ? (", " + std::to_string(a.tiles) + " tiles").c_str() : "");
  return line;
}

nlohmann::json seamPlacementJson(const SeamPlacement& p) {
  return {{"turn_degrees", p.turnDegrees},
          {"faces_crossed", p.facesCrossed},
          {"faces_crossed_before", p.facesCrossedBefore},
          {"seam_length", p.seamLength},
          {"seam_length_before", p.seamLengthBefore}};
}

}  // namespace uvtk::inspect
