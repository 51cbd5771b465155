// libFuzzer target: the fits (issue 23) on a small mesh of any finite coordinates. The bytes give
// a few vertices (any finite double, at any exponent, each coordinate optionally copied from the
// first vertex: flat axes, lines, repeated points) and a few triangles; every fit must give a
// finite frame with orthonormal axes and non-zero, finite scales, and a map with each surface kind
// finite UVs (Invalid corners are (0, 0)). Any violation or exception aborts.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>

#include "core/error.h"
#include "param/projector.h"

namespace {

using namespace uvtk;

class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return at_ < size_ ? data_[at_++] : 0; }
  // Any finite double: the raw bits, with an infinity or NaN's exponent cleared (a subnormal).
  double number() {
    std::uint64_t bits = 0;
    for (int k = 0; k < 8; ++k) bits = bits << 8 | byte();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (!std::isfinite(x)) {
      bits &= ~(std::uint64_t(0x7ff) << 52);
      std::memcpy(&x, &bits, sizeof x);
    }
    return x;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_, at_ = 0;
};

void check(bool ok) {
  if (!ok) std::abort();
}

// Rows of length finite and non-zero with finite reciprocals, orthogonal after normalizing.
void checkFrame(const Affine3& frame) {
  check(frame.matrix().allFinite());
  Mat3 axes;
  for (int r = 0; r < 3; ++r) {
    const double length = frame.linear().row(r).stableNorm();
    check(length > 0.0 && std::isfinite(1.0 / length));
    axes.row(r) = frame.linear().row(r) / length;
  }
  check((axes * axes.transpose() - Mat3::Identity()).cwiseAbs().maxCoeff() <= 1e-9);
  check(axes.determinant() > 0.0);
}

void checkAxes(const Mat3& axes) {
  check(axes.allFinite());
  check((axes * axes.transpose() - Mat3::Identity()).cwiseAbs().maxCoeff() <= 1e-9);
}

constexpr param::SurfaceKind kSurfaces[] = {param::SurfaceKind::Plane, param::SurfaceKind::TwoPlane,
                                            param::SurfaceKind::Cylinder, param::SurfaceKind::Sphere,
                                            param::SurfaceKind::Cube};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  const int vertices = 3 + in.byte() % 6;
  const int faces = 1 + in.byte() % 4;
  const std::uint8_t choices = in.byte();
  Mesh mesh;
  for (int v = 0; v < vertices; ++v) {
    const std::uint8_t copy = in.byte();  // bit a: coordinate a as the first vertex's
    Vec3 p;
    for (int a = 0; a < 3; ++a) p[a] = v > 0 && (copy >> a & 1) ? mesh.positions[0][a] : in.number();
    mesh.positions.push_back(p);
  }
  for (int f = 0; f < faces; ++f) {
    Triangle t;
    for (int k = 0; k < 3; ++k) t[k] = in.byte() % vertices;
    mesh.triangles.push_back(t);
  }

  const param::Fit fits[] = {param::Fit::None, param::Fit::BBox, param::Fit::Center, param::Fit::Pca,
                             param::Fit::Obb};
  param::PlacementOptions placement;
  std::optional<Mat3> spreadAxes[5];  // per fit, for the maps below (the oriented box is slow)
  for (int f = 0; f < 5; ++f) {
    const param::Fit fit = fits[f];
    placement.fit = fit;
    placement.spreadAxes.reset();
    if (fit == param::Fit::Pca) placement.spreadAxes = param::principalAxes(mesh.positions);
    if (fit == param::Fit::Obb) placement.spreadAxes = param::orientedBoxAxes(mesh.positions);
    if (placement.spreadAxes) checkAxes(*placement.spreadAxes);
    spreadAxes[f] = placement.spreadAxes;
    for (param::SurfaceKind surface : kSurfaces) checkFrame(param::fitPlacement(mesh.positions, surface, placement));
  }

  // One map per surface kind, with the fit, ray and arithmetic the bytes choose.
  param::ProjectorOptions options;
  options.placement.fit = fits[choices % 5];
  options.placement.spreadAxes = spreadAxes[choices % 5];
  constexpr param::RayKind kRays[] = {param::RayKind::SurfaceNormal, param::RayKind::Centroid,
                                      param::RayKind::ObjectNormal, param::RayKind::Reflection};
  options.ray = kRays[choices / 5 % 4];
  options.eye = Vec3(0.5, -2, 3);
  options.arithmetic.precision = choices & 0x80 ? Precision::Float : Precision::Double;
  for (param::SurfaceKind surface : kSurfaces) {
    options.surface = surface;
    const param::Projection projection = param::project(mesh, options);
    checkFrame(projection.localFromObject);
    for (const Vec2& uv : projection.uv.uv) check(uv.allFinite());
  }
  return 0;
}
