#include "point/point_evaluator.h"

#include <cmath>
#include <exception>

#include "core/error.h"
#include "param/formulas.h"
#include "param/surfaces.h"
#include "texgen/texgen.h"

namespace uvtk::point {

using param::CornerState;
using param::SurfaceKind;

namespace {

Vec3 toVec3(const Vector3& v) { return {v[0], v[1], v[2]}; }

Result invalid(Result out, const char* reason) {
  out.u = out.v = out.w = 0.0;
  out.q = 1.0;
  out.status = Status::Invalid;
  out.reason = reason;
  return out;
}

}  // namespace

Affine3 placementFor(const param::ProjectorOptions& o, const std::vector<Vec3>& positions) {
  if (inspect::fitsToMesh(o) && positions.empty())
    throw UsageError(
        "the placement is fitted to a mesh (--fit or --convention), and no mesh was given: name one, or "
        "use --fit none");
  return param::fitPlacement(positions, o.surface, o.placement);
}

PointEvaluator::PointEvaluator(const inspect::ResolvedMapping& mapping, const Affine3& localFromObject,
                               std::string description, const std::optional<Eigen::AlignedBox3d>& sensible)
    : description_(std::move(description)) {
  if (mapping.texgen) {
    texgen_ = mapping.texgen;
    for (const texgen::TexgenCoordinate& c : texgen_->coordinates)
      needsNormal_ = needsNormal_ || c.mode == texgen::TexgenMode::SphereMap ||
                     c.mode == texgen::TexgenMode::NormalMap || c.mode == texgen::TexgenMode::ReflectionMap;
    texgen::texgenAt(Vec3::Zero(), Vec3::UnitZ(), *texgen_);  // throws now for what would fail at every point
    return;
  }
  projector_.emplace(*mapping.projector, localFromObject, sensible);
  if (projector_->traits().isPerspective) camera_.emplace(mapping.projector->camera);
  // A cylinder's caps are chosen by the normal given with the point.
  needsNormal_ = projector_->needsNormal() || mapping.projector->cylinderCaps;
}

Result PointEvaluator::at(const Vector3& position, const Vector3& normal) const noexcept {
  Result out;
  out.position = position;
  out.mapping = description_.c_str();
  const Vec3 p = toVec3(position), n = toVec3(normal);
  if (!p.allFinite()) return invalid(out, "the position is not finite");
  if (needsNormal_ && !n.allFinite()) return invalid(out, "the normal is not finite");
  if (needsNormal_ && n == Vec3::Zero()) return invalid(out, "the normal is zero (this mapping reads it)");
  try {
    return texgen_ ? texgenAt(p, n, out) : projectorAt(p, n, out);
  } catch (const std::exception&) {  // only a texgen matrix beyond float range, checked at construction
    return invalid(out, "the mapping failed at this point");
  }
}

Result PointEvaluator::projectorAt(const Vec3& p, const Vec3& n, Result out) const {
  const param::Projector& projector = *projector_;
  const param::ProjectorOptions& o = projector.options();
  if (projector.traits().blendsProjections) return triplanarAt(p, n, out);
  const bool cap = o.cylinderCaps && projector.isCap(n);  // as project() decides it
  const param::PointUv mapped = projector.at(p, n, cap);
  if (mapped.state == CornerState::Invalid) return invalid(out, param::invalidReasonText(o, mapped.reason));
  const bool wraps = projector.traits().wraps;
  out.status = Status::Ok;
  if (camera_) out.q = camera_->homogeneous(p).w();  // (u, v) are s/q, t/q: q is w_c, the divisor
  if (mapped.state == CornerState::Pole) {
    out.status = Status::Pole;
    out.reason = wraps ? "on the axis: u is undefined there (written as 0), v is exact"
                       : "at the singular point: (u, v) is undefined there (written at azimuth 0)";
  } else if (wraps && !cap) {
    const double start = *param::uPeriodStartOf(o);
    if (mapped.unplaced.x() == start || mapped.unplaced.x() == start + 1.0) {
      out.status = Status::OnSeam;
      out.reason = "on the seam: u and u + 1 are the same point";
    }
  } else if (mapped.cubeFace) {
    const Vec2& st = mapped.unplaced;
    if (st.x() == 0.0 || st.x() == 1.0 || st.y() == 0.0 || st.y() == 1.0) {
      out.status = Status::OnSeam;
      out.reason = "on an edge of the cube: the face follows the tie rule (x before y before z)";
    }
    if (o.cubeLayout == CubeLayout::Faces) out.w = static_cast<double>(*mapped.cubeFace);
  }
  out.u = mapped.uv.x();
  out.v = mapped.uv.y();
  const Vec2 period = cap ? Vec2::Zero() : projector.period();
  out.period = {period.x(), period.y()};
  return out;
}

Result PointEvaluator::triplanarAt(const Vec3& p, const Vec3& n, Result out) const {
  const param::TriplanarSample s = projector_->blendAt(p, n);
  if (!s.weights.allFinite()) return invalid(out, "the normal is zero: the weights need its direction");
  for (const Vec2& uv : s.uv)
    if (!uv.allFinite()) return invalid(out, "the result is not finite");
  const std::size_t axis = std::size_t(s.dominant);
  out.u = s.uv[axis].x();
  out.v = s.uv[axis].y();
  for (std::size_t i = 0; i < 3; ++i) {
    out.triplanarUv[i] = {s.uv[i].x(), s.uv[i].y()};
    out.triplanarWeights[i] = s.weights[int(i)];
  }
  out.status = Status::Ok;
  return out;
}

Result PointEvaluator::texgenAt(const Vec3& p, const Vec3& n, Result out) const {
  bool singular = false;
  const Vec4 stq = texgen::texgenAt(p, n, *texgen_, &singular);
  if (!stq.allFinite()) return invalid(out, "the result is not finite");
  out.u = stq[0], out.v = stq[1], out.w = stq[2], out.q = stq[3];
  out.status = singular ? Status::Pole : Status::Ok;
  if (singular) out.reason = "sphere map: the reflection is (0, 0, -1), where m = 0; s = t = 1/2 as GL leaves it";
  return out;
}

}  // namespace uvtk::point
