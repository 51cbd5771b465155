// The camera of the renderer: a view (gluLookAt) and a projection (gluPerspective or glOrtho)
// onto a width x height viewport, and the camera that frames a mesh's bounding sphere.
#pragma once

#include <string>
#include <vector>

#include "core/math.h"

namespace uvtk::render {

struct Camera {
  Mat4 viewFromWorld = Mat4::Identity();
  Mat4 clipFromView = Mat4::Identity();
  int width = 512, height = 512;

  // The eye in world space (where the view puts the origin).
  Vec3 eye() const;
};

struct BoundingSphere {
  Vec3 center = Vec3::Zero();
  double radius = 0.0;
};

// The sphere about the centre of the points' bounding box through the farthest point.
BoundingSphere boundingSphere(const std::vector<Vec3>& points);

struct Projection {
  bool orthographic = false;
  double fovyDegrees = 45.0;  // perspective
};

// A camera on the ray from the sphere's centre along `eyeDirection` (world space), looking at the
// centre with `up`, far enough that the sphere fills 90% of the smaller field of view; near and
// far enclose the sphere with a margin. Orthographic: the view volume is the sphere's box with a
// 5% margin in the smaller image dimension. Throws UsageError for a zero direction, an up parallel
// to it, or an empty viewport; InputError for a sphere so large (beyond about 1e307) that the eye
// or the far plane would lie beyond the largest double, its message starting "MESHFILE: error: "
// when `meshFile` is given.
Camera frameSphere(const BoundingSphere& sphere, const Vec3& eyeDirection, const Vec3& up, const Projection& projection,
                   int width, int height, const std::string& meshFile = {});

}  // namespace uvtk::render
