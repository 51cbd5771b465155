#include "inspect/projector_json.h"

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
  if (o.ray == RayKind::Reflection) j["at_infinity"] = o.atInfinity;
  return j;
}

nlohmann::json seamPlacementJson(const SeamPlacement& p) {
  return {{"turn_degrees", p.turnDegrees},
          {"faces_crossed", p.facesCrossed},
          {"faces_crossed_before", p.facesCrossedBefore},
          {"seam_length", p.seamLength},
          {"seam_length_before", p.seamLengthBefore}};
}

}  // namespace uvtk::inspect
