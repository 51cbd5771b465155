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
                      {"cap_layout", nameOf(kCapLayoutNames, o.capLayout)},
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

namespace {

nlohmann::json finiteOrNull(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

}  // namespace

nlohmann::json texelStatisticsJson(const analysis::TexelStatistics& s) {
  nlohmann::json levels = nlohmann::json::array();
  for (const analysis::TexelLevel& l : s.levels)
    levels.push_back({{"level", l.level},
                      {"size", {l.width, l.height}},
                      {"mapped", l.mapped},
                      {"mapped_conservative", l.mappedConservative},
                      {"touched", l.touched},
                      {"overwritten", l.overwritten},
                      {"clashes", l.clashes},
                      {"gutter_texels", finiteOrNull(l.gutterTexels)}});
  return {{"charts", s.charts},
          {"gutter_texels", finiteOrNull(s.gutters.betweenCharts)},
          {"border_texels", finiteOrNull(s.gutters.toBorder)},
          {"first_bleed_level", s.firstBleedLevel ? nlohmann::json(*s.firstBleedLevel) : nlohmann::json()},
          {"levels", levels}};
}

nlohmann::json atlasJson(const Atlas& a, const analysis::Gutters& gutters) {
  return {{"charts", a.charts.size()},
          {"directions", a.directions},
          {"split_charts", a.splitCharts},
          {"merged_charts", a.mergedCharts},
          {"cut_charts", a.cutCharts},
          {"degenerate_faces", a.degenerateFaces},
          {"texels_per_unit", a.texelsPerUnit},
          {"tiles", a.tiles},
          {"occupancy", a.occupancy},
          {"gutter_texels", finiteOrNull(gutters.betweenCharts)},
          {"border_texels", finiteOrNull(gutters.toBorder)},
          {"seam_edges", a.seamEdges},
          {"seam_length", a.seamLength},
          {"stretch_bound", a.stretchBound},
          {"fallback_charts", a.fallbackCharts},
          {"fallback_reasons", a.fallbackReasons}};
}

std::string atlasLine(const Atlas& a, const analysis::Gutters& gutters) {
  char gutter[48] = "no second chart";
  if (std::isfinite(gutters.betweenCharts)) std::snprintf(gutter, sizeof gutter, "gutter %.3g texels", gutters.betweenCharts);
  char line[200];
  std::snprintf(line, sizeof line, "%zu charts, occupancy %.3f, %s, %.4g texels per unit%s", a.charts.size(),
                a.occupancy, gutter, a.texelsPerUnit,
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
