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
};

// mapVertices in long double, whatever options.arithmetic says; the same contract otherwise.
void mapVerticesReference(const ProjectorOptions& options, const Affine3& localFromObject,
                          const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                          std::vector<ReferenceUv>& out);

}  // namespace uvtk::param
