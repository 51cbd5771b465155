// The only translation unit that includes CGAL: principal axes and the oriented bounding box.
#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/linear_least_squares_fitting_3.h>
#include <CGAL/optimal_bounding_box.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"
#include "param/placement.h"

namespace uvtk::param {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

std::vector<Point> toCgal(const std::vector<Vec3>& positions) {
  std::vector<Point> points;
  points.reserve(positions.size());
  for (const Vec3& p : positions) points.emplace_back(p.x(), p.y(), p.z());
  return points;
}

Vec3 toVec(const Kernel::Vector_3& v) { return {v.x(), v.y(), v.z()}; }

// Makes the largest-magnitude component positive, so that fits are reproducible.
Vec3 canonicalSign(const Vec3& v) {
  Eigen::Index i;
  v.cwiseAbs().maxCoeff(&i);
  return v[i] < 0.0 ? Vec3(-v) : v;
}

// Rows e0, e1, e2 ordered by decreasing spread, right-handed.
Mat3 orderedRows(std::array<Vec3, 3> axes, const std::array<double, 3>& spread) {
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return spread[a] > spread[b]; });
  Mat3 rows;
  const Vec3 e0 = canonicalSign(axes[order[0]].normalized());
  Vec3 e1 = axes[order[1]] - axes[order[1]].dot(e0) * e0;
  e1 = canonicalSign(e1.normalized());
  rows.row(0) = e0;
  rows.row(1) = e1;
  rows.row(2) = e0.cross(e1);
  return rows;
}

}  // namespace

Mat3 principalAxes(const std::vector<Vec3>& positions) {
  if (positions.size() < 3) return Mat3::Identity();
  const std::vector<Point> points = toCgal(positions);
  Kernel::Line_3 line;
  Kernel::Plane_3 plane;
  CGAL::linear_least_squares_fitting_3(points.begin(), points.end(), line, CGAL::Dimension_tag<0>());
  CGAL::linear_least_squares_fitting_3(points.begin(), points.end(), plane, CGAL::Dimension_tag<0>());
  const Vec3 largest = toVec(line.to_vector());
  const Vec3 smallest = toVec(plane.orthogonal_vector());
  if (!(largest.norm() > 0.0) || !(smallest.norm() > 0.0)) return Mat3::Identity();
  const Vec3 middle = smallest.cross(largest);
  return orderedRows({largest, middle, smallest}, {3.0, 2.0, 1.0});
}

Mat3 orientedBoxAxes(const std::vector<Vec3>& positions) {
  if (positions.size() < 4) return Mat3::Identity();
  const std::vector<Point> points = toCgal(positions);
  CGAL::Aff_transformation_3<Kernel> rotation;  // rotates the box to be axis-aligned
  CGAL::oriented_bounding_box(points, rotation, CGAL::parameters::use_convex_hull(true).random_seed(0));
  std::array<Vec3, 3> axes;
  for (int r = 0; r < 3; ++r) axes[r] = Vec3(rotation.m(r, 0), rotation.m(r, 1), rotation.m(r, 2));
  std::array<double, 3> extent{};
  for (int r = 0; r < 3; ++r) {
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec3& p : positions) {
      const double d = axes[r].dot(p);
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
    extent[r] = hi - lo;
  }
  return orderedRows(axes, extent);
}

}  // namespace uvtk::param
