// The mapping of single vertices in long double (64-bit significand) with libm's atan2l: the
// reference that `uvtk bench` and the precision tests measure the float and double paths
// against. Its own error is about 2^-11 ulp of a double result, so double errors are measured to
// a thousandth of an ulp.
#pragma once

#include <vector>

#include "param/projector.h"

namespace uvtk::param {

// A VertexUv in long double.
struct ReferenceUv {
  Vec2T<long double> uv = Vec2T<long double>::Zero();
  Vec2T<long double> axial = Vec2T<long double>::Zero();
  CornerState state = CornerState::Invalid;
  CornerInvalid reason = kCornerMiss;
};

// mapVertices in long double, whatever options.arithmetic says; the same contract otherwise.
void mapVerticesReference(const ProjectorOptions& options, const Affine3& localFromObject,
                          const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                          std::vector<ReferenceUv>& out);

// How far a mapping's results lie from the reference, per vertex the larger of the u and v
// errors: u modulo 1 where `wrapsU` (0.9999 and 0.0001 are 2e-4 apart), v alone at poles. In UV
// units, and in ulps of the result's precision at the reference value (ulps of the smallest
// normal number where the value is smaller, so that a tiny value's absolute error of a few
// denormals does not count as millions of ulps). Vertices whose state differs from the
// reference's are counted, not measured.
struct MappingError {
  double maxUv = 0, p99Uv = 0, meanUv = 0;
  double maxUlp = 0, p99Ulp = 0;
  std::size_t compared = 0, stateMismatches = 0;
};

MappingError mappingError(const std::vector<VertexUv>& result, const std::vector<ReferenceUv>& reference,
                          Precision precision, bool wrapsU);

}  // namespace uvtk::param
