// The only translation unit that includes CGAL: principal axes and the oriented bounding box.
#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/linear_least_squares_fitting_3.h>
#include <CGAL/min_quadrilateral_2.h>
#include <CGAL/optimal_bounding_box.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <optional>
#include <tuple>
#include <vector>

#include "core/cancel.h"
#include "core/error.h"
#include "param/placement.h"

namespace uvtk::param {

namespace {

// The positions with every repeat of an earlier one left out, in their order. A fit is of the
// shape, not of how its vertices are split: a glTF or PLY (split at seams) and an STL (a vertex
// per corner until welded) fit as the OBJ they came from. Unchanged when nothing repeats.
std::vector<Vec3> distinctPositions(const std::vector<Vec3>& positions) {
  std::vector<std::size_t> order(positions.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto less = [&](std::size_t a, std::size_t b) {
    const Vec3 &p = positions[a], &q = positions[b];
    return std::tie(p.x(), p.y(), p.z(), a) < std::tie(q.x(), q.y(), q.z(), b);
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<bool> repeat(positions.size(), false);
  bool any = false;
  for (std::size_t i = 1; i < order.size(); ++i)
    if (positions[order[i]] == positions[order[i - 1]]) repeat[order[i]] = any = true;
  if (!any) return positions;
  std::vector<Vec3> distinct;
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (!repeat[i]) distinct.push_back(positions[i]);
  return distinct;
}

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

// Unit-box coordinates below 2^-100 (far below the box's resolution) as 0: the oriented box's
// search multiplies them, and subnormal products made one fit of four points take seconds.
double flush(double x) { return std::fabs(x) < 0x1p-100 ? 0.0 : x; }

std::vector<Point> toCgal(const std::vector<Vec3>& unit) {
  std::vector<Point> points;
  points.reserve(unit.size());
  for (const Vec3& p : unit) points.emplace_back(flush(p.x()), flush(p.y()), flush(p.z()));
  return points;
}

Vec3 toVec(const Kernel::Vector_3& v) { return {v.x(), v.y(), v.z()}; }

// Makes the largest-magnitude component positive, so that fits are reproducible.
Vec3 canonicalSign(const Vec3& v) {
  Eigen::Index i;
  v.cwiseAbs().maxCoeff(&i);
  return v[i] < 0.0 ? Vec3(-v) : v;
}

// The part of `v` orthogonal to the unit vector `e` (all of it when `e` is zero), normalized, or
// nothing when that part is zero, tiny against v or not finite (a degenerate fit's axis).
std::optional<Vec3> unitOrthogonal(const Vec3& v, const Vec3& e) {
  const Vec3 w = v - v.dot(e) * e;
  const double length = w.norm();
  if (!(length > 1e-6 * v.norm()) || !std::isfinite(length)) return std::nullopt;
  return Vec3(w / length);
}

// Rows e0, e1, e2 ordered by decreasing spread, right-handed. An axis a fit leaves zero, NaN or
// parallel to an earlier one is replaced by the first object axis that completes the frame.
Mat3 orderedRows(std::array<Vec3, 3> axes, const std::array<double, 3>& spread) {
  std::array<int, 3> order{0, 1, 2};
  const auto key = [&](int a) { return std::isnan(spread[a]) ? -INFINITY : spread[a]; };  // NaN last
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key(a) > key(b); });
  const Vec3 candidates[] = {axes[order[0]], axes[order[1]], axes[order[2]], Vec3::UnitX(), Vec3::UnitY(),
                             Vec3::UnitZ()};
  Vec3 e0 = Vec3::Zero(), e1 = Vec3::Zero();
  int i = 0;
  for (; i < 6; ++i)
    if (const auto unit = unitOrthogonal(candidates[i], Vec3::Zero())) {
      e0 = canonicalSign(*unit);
      break;
    }
  for (++i; i < 6; ++i)
    if (const auto unit = unitOrthogonal(candidates[i], e0)) {
      e1 = canonicalSign(*unit);
      break;
    }
  Mat3 rows;
  rows.row(0) = e0;
  rows.row(1) = e1;
  rows.row(2) = e0.cross(e1);
  return rows;
}

// The object axes when two or three of them are flat (docs in placement.h): an axis-parallel
// line's direction first, then the others in cyclic order (right-handed); the identity for one
// point. Nothing when a fit is needed.
std::optional<Mat3> flatFrame(const UnitBox& box) {
  const int flat = int(box.flat[0]) + int(box.flat[1]) + int(box.flat[2]);
  if (flat < 2) return std::nullopt;
  if (flat == 3) return Mat3::Identity();
  int line = 0;
  while (line < 2 && box.flat[std::size_t(line)]) ++line;
  Mat3 rows = Mat3::Zero();
  for (int k = 0; k < 3; ++k) rows(k, (line + k) % 3) = 1.0;
  return rows;
}

// A sheet flat along object axis j: e2 is that axis exactly and e0, e1 lie exactly in the sheet,
// so that no rounding of the fit mixes the sheet's (possibly huge) coordinate into the others.
Mat3 keepFlatAxis(const Mat3& rows, const UnitBox& box) {
  const auto it = std::find(box.flat.begin(), box.flat.end(), true);
  if (it == box.flat.end()) return rows;
  const int j = int(it - box.flat.begin());
  Vec3 normal = Vec3::Zero();
  normal[j] = 1.0;
  const Vec3 candidates[] = {rows.row(0), rows.row(1), Vec3::Unit((j + 1) % 3)};
  Vec3 e0 = Vec3::Unit((j + 1) % 3);
  for (Vec3 c : candidates) {
    c[j] = 0.0;
    if (const auto unit = unitOrthogonal(c, Vec3::Zero())) {
      e0 = canonicalSign(*unit);
      break;
    }
  }
  const Vec3 e1 = canonicalSign(normal.cross(e0));  // exact: its j component stays 0
  Mat3 out;
  out.row(0) = e0;
  out.row(1) = e1;
  out.row(2) = std::copysign(1.0, e0.cross(e1)[j]) * normal;
  return out;
}

}  // namespace

Mat3 principalAxes(const std::vector<Vec3>& allPositions) {
  const std::vector<Vec3> positions = distinctPositions(allPositions);
  if (positions.size() < 3) return Mat3::Identity();
  const UnitBox box = toUnitBox(positions);
  if (const auto rows = flatFrame(box)) return *rows;
  const std::vector<Point> points = toCgal(box.unit);
  Kernel::Line_3 line;
  Kernel::Plane_3 plane;
  CGAL::linear_least_squares_fitting_3(points.begin(), points.end(), line, CGAL::Dimension_tag<0>());
  CGAL::linear_least_squares_fitting_3(points.begin(), points.end(), plane, CGAL::Dimension_tag<0>());
  const Vec3 largest = toVec(line.to_vector());
  const Vec3 smallest = toVec(plane.orthogonal_vector());
  return keepFlatAxis(orderedRows({largest, smallest.cross(largest), smallest}, {3.0, 2.0, 1.0}), box);
}

// A sheet's oriented box, flat along object axis j: the smallest rectangle about its points in
// the sheet (rotating calipers on the convex hull, CGAL::min_rectangle_2), exact where the 3D
// search is approximate and, for a flat box, slow (seconds for four points under the sanitizers).
Mat3 sheetBoxAxes(const UnitBox& box, int j) {
  const int a = (j + 1) % 3, b = (j + 2) % 3;
  std::vector<Kernel::Point_2> points, hull, rectangle;
  for (const Vec3& u : box.unit) points.emplace_back(flush(u[a]), flush(u[b]));
  CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull));
  Vec3 along = Vec3::Unit(a), across = Vec3::Unit(b);
  double length = 1.0, width = 0.0;
  if (hull.size() == 2) {  // collinear in the sheet: the line's direction first
    along[a] = hull[1].x() - hull[0].x(), along[b] = hull[1].y() - hull[0].y();
  } else if (hull.size() >= 3) {
    CGAL::min_rectangle_2(hull.begin(), hull.end(), std::back_inserter(rectangle));
    along = across = Vec3::Zero();
    along[a] = rectangle[1].x() - rectangle[0].x(), along[b] = rectangle[1].y() - rectangle[0].y();
    across[a] = rectangle[3].x() - rectangle[0].x(), across[b] = rectangle[3].y() - rectangle[0].y();
    length = along.norm(), width = across.norm();
  }
  Vec3 normal = Vec3::Zero();
  normal[j] = 1.0;
  return keepFlatAxis(orderedRows({along, across, normal}, {length, width, 0.0}), box);
}

namespace {

// Every k-th of the points, k chosen so that at most `limit` remain; all of them within the limit.
std::vector<Point> everyKth(const std::vector<Point>& points, std::size_t limit) {
  if (points.size() <= limit) return points;
  std::vector<Point> chosen;
  chosen.reserve(limit);
  for (std::size_t i = 0; i < limit; ++i) chosen.push_back(points[i * points.size() / limit]);
  return chosen;
}

// The points the oriented box's search runs on: the convex hull's vertices, as CGAL's own
// use_convex_hull takes them (so that a box of up to kSearchPoints hull vertices is the one CGAL
// gives), of at most kHullPoints positions and at most kSearchPoints of them. The search costs about
// 0.17 ms per point (19 s for a 358 k-face sphere, whose every vertex is on the hull) and the hull
// 14 us per point (27 s for 2 M): bounded so, a box takes under half a second on any mesh, and Ctrl-C
// is seen between the steps (docs/conventions.md, "Fit"). The box is still measured on every position.
constexpr std::size_t kHullPoints = 65536, kSearchPoints = 2048;
std::vector<Point> boxSearchPoints(const std::vector<Point>& points) {
  std::vector<Point> hull;
  const CGAL::Convex_hull_traits_3<CGAL::Oriented_bounding_box_traits_3<Kernel>> traits;
  CGAL::extreme_points_3(everyKth(points, kHullPoints), std::back_inserter(hull), traits);
  return everyKth(hull, kSearchPoints);
}

}  // namespace

Mat3 orientedBoxAxes(const std::vector<Vec3>& allPositions) {
  const std::vector<Vec3> positions = distinctPositions(allPositions);
  if (positions.size() < 4) return Mat3::Identity();
  const UnitBox box = toUnitBox(positions);
  if (const auto rows = flatFrame(box)) return *rows;
  const auto flat = std::find(box.flat.begin(), box.flat.end(), true);
  if (flat != box.flat.end()) return sheetBoxAxes(box, int(flat - box.flat.begin()));
  const std::vector<Point> hull = boxSearchPoints(toCgal(box.unit));
  throwIfCancelled();
  CGAL::Aff_transformation_3<Kernel> rotation;  // rotates the box to be axis-aligned
  CGAL::oriented_bounding_box(hull, rotation, CGAL::parameters::use_convex_hull(false).random_seed(0));
  throwIfCancelled();
  std::array<Vec3, 3> axes;
  for (int r = 0; r < 3; ++r) axes[r] = Vec3(rotation.m(r, 0), rotation.m(r, 1), rotation.m(r, 2));
  std::array<double, 3> extent{};
  for (int r = 0; r < 3; ++r) {
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec3& p : box.unit) {
      const double d = axes[r].dot(p);
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
    extent[r] = hi - lo;
  }
  return keepFlatAxis(orderedRows(axes, extent), box);
}

}  // namespace uvtk::param
