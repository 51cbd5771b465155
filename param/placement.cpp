#include "param/placement.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/huge_pages.h"
#include "core/parallel.h"
#include "param/formulas.h"
#include "param/surface_traits.h"

namespace uvtk::param {

namespace {

// Rows x, y, z of a right-handed frame with z along `axis` and x along `reference`.
Mat3 frameRows(const Vec3& axis, const Vec3& reference) {
  const Vec3 z = axis.normalized();
  const Vec3 x = (reference - reference.dot(z) * z).normalized();
  Mat3 rows;
  rows.row(0) = x;
  rows.row(1) = z.cross(x);
  rows.row(2) = z;
  return rows;
}

// The frame rows of a fit, before scaling: which direction becomes local x, y and z.
Mat3 fittedRotation(const std::vector<Vec3>& positions, SurfaceKind surface, const PlacementOptions& options) {
  if (options.fit == Fit::BBox || options.fit == Fit::Center) {
    // A cyclic permutation keeps the frame right-handed: axis x gives local (y, z, x), etc.
    Mat3 rows = Mat3::Zero();
    for (int k = 0; k < 3; ++k) rows(k, (options.axis + 1 + k) % 3) = 1.0;
    return rows;
  }
  // Spread-ordered axes e0 (largest), e1, e2 (smallest). A plane looks along the smallest spread
  // with x along the largest; the other surfaces put their axis along the largest spread.
  const Mat3 e = options.spreadAxes ? *options.spreadAxes
                 : options.fit == Fit::Pca ? principalAxes(positions)
                                           : orientedBoxAxes(positions);
  if (traitsOf(surface).shape == UnitShape::Plane) return frameRows(e.row(2), e.row(0));
  return frameRows(e.row(0), e.row(1));
}

double positiveOr(double value, double fallback) { return value > 0.0 && std::isfinite(value) ? value : fallback; }

constexpr std::size_t kPositionsPerRange = std::size_t(1) << 16;  // a thread's share at a time

// The largest of distance(i) (i < count), at least 0, in ranges on threads.
template <class Distance>
double largestOf(std::size_t count, int threads, Distance distance) {
  return reduceRanges(
      count, kPositionsPerRange, threads, 0.0,
      [&](double& largest, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) largest = std::max(largest, distance(i));
      },
      [](double& total, double largest) { total = std::max(total, largest); });
}

// The frame of the fit or of the explicit placement, before the turn about its axis.
Affine3 frameBeforeTurn(const std::vector<Vec3>& positions, SurfaceKind surface, const PlacementOptions& options,
                        int threads) {
  Affine3 localFromObject = Affine3::Identity();
  // two-plane works in object space; the camera's own view is its frame
  if (surface == SurfaceKind::TwoPlane || surface == SurfaceKind::Camera || traitsOf(surface).chartsFromMesh)
    return localFromObject;  // the atlas places each chart itself
  if (options.frame) {
    const ExplicitFrame& f = *options.frame;
    if (!(f.axisDir.norm() > 0.0) || !f.axisDir.allFinite())
      throw UsageError("--axis-dir: expected a non-zero direction");
    if (!((f.refDir - f.refDir.dot(f.axisDir.normalized()) * f.axisDir.normalized()).norm() > 1e-12 * f.refDir.norm()))
      throw UsageError("--ref-dir: expected a direction not parallel to --axis-dir");
    if (!(f.scale > 0.0) || !std::isfinite(f.scale)) throw UsageError("--scale: expected a positive number");
    // A subnormal scale's 1/scale overflows: the frame would send every vertex to inf or NaN.
    if (!std::isfinite(1.0 / f.scale))
      throw UsageError("--scale: expected a positive number whose reciprocal is finite");
    localFromObject.linear() = frameRows(f.axisDir, f.refDir) / f.scale;
    localFromObject.translation() = -(localFromObject.linear() * f.center);
    return localFromObject;
  }
  if (options.fit == Fit::None || positions.empty()) return localFromObject;

  // The fit works on the unit box (no overflow or underflow at any scale), then scales back.
  const UnitBox box = toUnitBox(positions, threads);
  const Mat3 rotation = fittedRotation(positions, surface, options);
  const Eigen::AlignedBox3d rotated = boundsInRanges<Eigen::AlignedBox3d>(
      box.unit.size(), threads, [&](Eigen::AlignedBox3d& b, std::size_t i) { b.extend(Vec3(rotation * box.unit[i])); });
  const Vec3 &lo = rotated.min(), &hi = rotated.max();
  const Vec3 extent = hi - lo;
  const Vec3 center = 0.5 * (lo + hi);

  // local = scale (rotation unit - origin), per axis, all in units of the unit box
  Vec3 origin = center, scale = Vec3::Ones();
  switch (options.fit == Fit::Center ? UnitShape::None : traitsOf(surface).shape) {  // Center: no surface-specific fit
    case UnitShape::Plane: {
      const double xy = positiveOr(std::max(extent.x(), extent.y()), 1.0);
      origin = Vec3(lo.x(), lo.y(), center.z());
      scale = Vec3(1.0 / positiveOr(extent.x(), xy), 1.0 / positiveOr(extent.y(), xy), 1.0 / xy);
      break;
    }
    case UnitShape::Cylinder: {
      const double radius = positiveOr(largestOf(box.unit.size(), threads,
                                                 [&](std::size_t i) {
                                                   const Vec3 r = rotation * box.unit[i];
                                                   return radialDistance(r.x() - center.x(), r.y() - center.y());
                                                 }),
                                       1.0);
      origin.z() = lo.z();  // the base of the box: v runs from 0 at the bottom to 1 at the top
      scale = Vec3(1.0 / radius, 1.0 / radius, 1.0 / positiveOr(extent.z(), radius));
      break;
    }
    case UnitShape::Ball: {
      const double radius =
          largestOf(box.unit.size(), threads, [&](std::size_t i) { return (rotation * box.unit[i] - center).norm(); });
      scale = Vec3::Constant(1.0 / positiveOr(radius, 1.0));
      break;
    }
    case UnitShape::Cube: {
      const double largest = positiveOr(0.5 * extent.maxCoeff(), 1.0);
      for (int a = 0; a < 3; ++a) scale[a] = 1.0 / positiveOr(0.5 * extent[a], largest);
      break;
    }
    case UnitShape::Box:
      origin = lo;
      scale = Vec3::Constant(1.0 / positiveOr(extent.maxCoeff(), 1.0));
      break;
    case UnitShape::None:
      break;
  }

  // Back to object units: local = s (rotation p - w), with s = 2^-exponent scale (Center keeps
  // object units) and w = rotation corner + 2^exponent origin, the local origin in rotated object
  // coordinates, summed in long double, whose exponent range no finite double can leave.
  for (int a = 0; a < 3; ++a) {
    double s = options.fit == Fit::Center ? 1.0 : std::ldexp(scale[a], -box.exponent);
    // Kept where it and its reciprocal (the frame's size in object units) are finite; only a mesh
    // wider than about 2^1022, or a mesh or box axis thinner than about 2^-1021, reaches the bounds.
    s = std::clamp(s, 0x1p-1022, 0x1p1022);
    long double w = std::ldexp(static_cast<long double>(origin[a]), box.exponent);
    for (int k = 0; k < 3; ++k) w += static_cast<long double>(rotation(a, k)) * box.corner[k];
    // A sheet 2^1020 times its size from the object origin: a coarser scale keeps the
    // translation finite (and every position's local coordinate, which is constant there).
    const long double t = s * w;
    if (std::fabs(t) > 0x1p1020L) s = std::ldexp(s, 1019 - std::ilogb(t));
    localFromObject.linear().row(a) = s * rotation.row(a);
    localFromObject.translation()[a] = static_cast<double>(-(s * w));
  }
  UVTK_CHECK(localFromObject.matrix().allFinite());
  return localFromObject;
}

}  // namespace

UnitBox toUnitBox(const std::vector<Vec3>& positions, int threads) {
  UnitBox box;
  if (positions.empty()) return box;
  const Eigen::AlignedBox3d bounds =
      boundsInRanges<Eigen::AlignedBox3d>(positions.size(), threads, [&](Eigen::AlignedBox3d& b, std::size_t i) {
        UVTK_CHECK(positions[i].allFinite());  // the readers refuse non-finite coordinates
        b.extend(positions[i]);
      });
  const Vec3 &lo = bounds.min(), &hi = bounds.max();
  // The box's low corner, not its centre: the centre of a mesh far from the object origin rounds,
  // while p - corner is exact there (Sterbenz), so the fit is the same as the mesh's at the origin.
  box.corner = lo;
  const double half = (0.5 * hi - 0.5 * lo).maxCoeff();  // halves: hi - lo overflows near the largest double
  box.exponent = half > 0.0 ? std::ilogb(half) + 1 : 0;
  const bool overflows = !(hi - lo).allFinite();
  for (int a = 0; a < 3; ++a) box.flat[std::size_t(a)] = lo[a] == hi[a];
  // Times 2^shift: a product where that power is a double (the same correctly rounded value as ldexp's).
  const int shift = overflows ? 1 - box.exponent : -box.exponent;
  const bool product = shift >= -1074 && shift <= 1023;
  const double factor = product ? std::ldexp(1.0, shift) : 0.0;
  resizeFaultedIn(box.unit, positions.size(), threads);
  parallelForRanges(positions.size(), kPositionsPerRange, threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      for (int a = 0; a < 3; ++a) {
        const double offset = overflows ? 0.5 * positions[i][a] - 0.5 * lo[a] : positions[i][a] - lo[a];
        box.unit[i][a] = product ? offset * factor : std::ldexp(offset, shift);
      }
  });
  return box;
}

Affine3 fitPlacement(const std::vector<Vec3>& positions, SurfaceKind surface, const PlacementOptions& options,
                     int threads) {
  const Affine3 frame = frameBeforeTurn(positions, surface, options, threads);
  if (options.turnDegrees == 0.0 || surface == SurfaceKind::TwoPlane || surface == SurfaceKind::Camera ||
      traitsOf(surface).chartsFromMesh)
    return frame;
  if (!std::isfinite(options.turnDegrees)) throw UsageError("--seam-place: expected a finite angle in degrees");
  // Turning the frame by +a puts the point at old azimuth a on the new local +x axis. Quarter
  // turns are exact: a seam moved to -y (Blender's) must not leave 6e-17 of x in local y.
  const double degrees = std::fmod(options.turnDegrees, 360.0);
  double c = 0.0, s = 0.0;
  if (degrees == std::trunc(degrees) && std::fmod(degrees, 90.0) == 0.0) {
    static constexpr double kQuarterCos[4] = {1, 0, -1, 0}, kQuarterSin[4] = {0, 1, 0, -1};
    const int quarter = (static_cast<int>(degrees / 90.0) + 4) % 4;
    c = kQuarterCos[quarter], s = kQuarterSin[quarter];
  } else {
    c = std::cos(degrees * (kPi / 180.0)), s = std::sin(degrees * (kPi / 180.0));
  }
  Mat3 turn;  // rotation by -a about z
  turn << c, s, 0, -s, c, 0, 0, 0, 1;
  return Affine3(turn) * frame;
}

}  // namespace uvtk::param
