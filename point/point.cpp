// The installed point API (uvtk/point.h): options parsed as `uvtk eval` parses them, then the
// PointEvaluator that `uvtk eval` uses.
#include "uvtk/point.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <stdexcept>

#include "core/error.h"
#include "core/uv_map.h"
#include "point/point_evaluator.h"

namespace uvtk::point {

struct Mapping::Impl {
  PointEvaluator evaluator;
};

namespace {

PointEvaluator prepare(const std::string& options, const std::vector<Vector3>& meshPositions) {
  CLI::App app{"uvtk::point::Mapping"};
  cli::MappingArguments arguments;
  cli::addMappingOptions(app, arguments, param::Fit::None);
  try {
    app.parse(options, false);
  } catch (const CLI::ParseError& e) {
    throw std::invalid_argument("uvtk::point::Mapping(\"" + options + "\"): " + e.what());
  }
  try {
    const cli::ResolvedMapping mapping = cli::resolveMapping(arguments);
    if (mapping.seamPlaceAuto)
      throw UsageError("--seam-place auto needs a mesh's faces; give the angle it chose (uvtk map prints it)");
    Affine3 frame = Affine3::Identity();
    std::optional<Eigen::AlignedBox3d> sensible;  // the range rule needs the mesh (docs/conventions.md §4)
    if (mapping.projector) {
      std::vector<Vec3> positions;
      positions.reserve(meshPositions.size());
      for (const Vector3& p : meshPositions) positions.emplace_back(p[0], p[1], p[2]);
      frame = placementFor(*mapping.projector, positions);
      if (!positions.empty()) sensible = param::sensibleBox(positions, *mapping.projector, frame);
    }
    return PointEvaluator(mapping, frame, options, sensible);
  } catch (const UsageError& e) {
    throw std::invalid_argument("uvtk::point::Mapping(\"" + options + "\"): " + e.what());
  }
}

}  // namespace

Mapping::Mapping(const std::string& options, const std::vector<Vector3>& meshPositions)
    : impl_(new Impl{prepare(options, meshPositions)}) {}
Mapping::~Mapping() = default;
Mapping::Mapping(Mapping&&) noexcept = default;
Mapping& Mapping::operator=(Mapping&&) noexcept = default;

Result Mapping::at(const Vector3& position, const Vector3& normal) const noexcept {
  return impl_->evaluator.at(position, normal);
}

bool Mapping::needsNormal() const { return impl_->evaluator.needsNormal(); }
const std::string& Mapping::options() const { return impl_->evaluator.description(); }

double uvError(double u, double v, const Result& expected) {
  return wrappedUvError(Vec2(u, v), Vec2(expected.u, expected.v), Vec2(expected.period[0], expected.period[1]),
                        expected.status == Status::Pole);
}

}  // namespace uvtk::point
