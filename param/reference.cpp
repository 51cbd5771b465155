#include "param/reference.h"

#include "param/sample_evaluator.h"

namespace uvtk::param {

void mapVerticesReference(const ProjectorOptions& o, const Affine3& localFromObject,
                          const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                          std::vector<ReferenceUv>& out) {
  using T = long double;
  if (!(o.poleEpsilon >= 0.0 && o.poleEpsilon < 1.0)) throw UsageError("--pole-eps: expected a number in [0, 1)");
  out.resize(positions.size());
  const LocalFrameT<T> frame(localFromObject);
  visitProjector<T>(o, frame, [&](const auto& s, const auto& m) {
    using S = std::decay_t<decltype(s)>;
    using M = std::decay_t<decltype(m)>;
    if constexpr (std::is_same_v<S, CubeSurfaceT<T>>) {
      throw UsageError("the cube projector chooses a face per triangle: map a mesh with project()");
    } else {
      if (M::kNeedsNormal && normals.size() != positions.size())
        throw UsageError("this O-mapping needs one normal per position");
      const SampleEvaluator<T, S, M, ReferenceUv> evaluate(s, m, frame, PoleTest(o.poleEpsilon), MathMode::Exact);
      evaluate(
          positions.size(), [&](std::size_t i) -> const Vec3& { return positions[i]; },
          [&](std::size_t i) -> const Vec3& { return normals[i]; }, out.data());
    }
  });
}

}  // namespace uvtk::param
