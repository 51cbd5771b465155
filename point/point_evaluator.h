// The evaluation behind uvtk::point::Mapping and `uvtk eval`: one resolved mapping (a projector
// and its placement, or texgen), each point's value with its status and the reason for it.
#pragma once

#include <optional>
#include <string>

#include "core/math.h"
#include "inspect/mapping_parameters.h"
#include "param/projector.h"
#include "uvtk/point.h"

namespace uvtk::point {

class PointEvaluator {
 public:
  // `localFromObject` is the projector's placement (fitPlacement); texgen ignores it. `description`
  // names the mapping in every Result (Result::mapping). `sensible` (param::sensibleBox of the mesh)
  // enables the range rule: hits beyond it are invalid; without it there is no range check.
  // Throws UsageError like project().
  PointEvaluator(const inspect::ResolvedMapping& mapping, const Affine3& localFromObject, std::string description,
                 const std::optional<Eigen::AlignedBox3d>& sensible = std::nullopt);

  Result at(const Vector3& position, const Vector3& normal) const noexcept;
  bool needsNormal() const { return needsNormal_; }
  const std::string& description() const { return description_; }

 private:
  Result projectorAt(const Vec3& p, const Vec3& n, Result out) const;
  Result texgenAt(const Vec3& p, const Vec3& n, Result out) const;
  Result triplanarAt(const Vec3& p, const Vec3& n, Result out) const;

  std::optional<param::Projector> projector_;
  std::optional<param::CameraTransform> camera_;  // --projector camera: its q
  std::optional<texgen::TexgenOptions> texgen_;
  std::string description_;
  bool needsNormal_ = false;
};

// The placement of a projector over `positions`, as `uvtk map` fits it; throws UsageError when the
// placement is fitted and there are no positions.
Affine3 placementFor(const param::ProjectorOptions& options, const std::vector<Vec3>& positions);

}  // namespace uvtk::point
