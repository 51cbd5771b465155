// Ear clipping in the polygon's best-fit plane. Written here rather than taken from CGAL: CGAL's
// polygon triangulation (a constrained Delaunay triangulation) brings heavy headers into a reader
// that is otherwise light, and ear clipping with exact orientation signs is short.
//
// The Newell normal (twice the vector area, exact for a planar polygon and a least-squares-like
// normal for a warped one) gives the plane; the corners are projected to its 2D frame after scaling
// by a power of two to about unit size, so that a polygon of size 1e-200 and one of 1e200 are
// computed alike and no product overflows or underflows. Ear clipping decides with a tolerance of
// the projection's rounding: corners that are collinear in space, but a little left or right once
// projected, are flat, never ears, so no triangle has a zero or rounding-made area of the wrong
// sign. Whether the boundary crosses itself is decided on the projected corners exactly (Shewchuk's
// filter, then an exact expansion).
#include "io/polygon_triangulation.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace uvtk::io {
namespace {

// x + y = a + b exactly (Knuth's two-sum).
void twoSum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bVirtual = x - a;
  const double aVirtual = x - bVirtual;
  y = (a - aVirtual) + (b - bVirtual);
}

// The sign of ax by - ax cy - cx by - ay bx + ay cx + cy bx, the orientation determinant expanded so
// that every term is a product of inputs: each product is split exactly into two doubles (fma) and
// the twelve are summed into a non-overlapping expansion (Shewchuk's grow-expansion), whose sign
// is that of its largest component.
int exactOrientation(double ax, double ay, double bx, double by, double cx, double cy) {
  double expansion[12];
  int length = 0;
  const auto add = [&](double q) {
    for (int i = 0; i < length; ++i) twoSum(q, expansion[i], q, expansion[i]);
    expansion[length++] = q;
  };
  const auto addProduct = [&](double u, double v) {
    const double product = u * v;
    add(product);
    add(std::fma(u, v, -product));
  };
  addProduct(ax, by);
  addProduct(-ax, cy);
  addProduct(-cx, by);
  addProduct(-ay, bx);
  addProduct(ay, cx);
  addProduct(cy, bx);
  for (int i = length - 1; i >= 0; --i)
    if (expansion[i] != 0.0) return expansion[i] > 0.0 ? 1 : -1;
  return 0;
}

// Corners are flat when the cross product of their edges is below this times the edges' lengths
// (1-norms) in the frame scaled to about unit size: above the projection's rounding (a few 1e-16),
// and above the cross product's own, so the sign of what is not flat is exact.
constexpr double kFlat = 1e-13;

// 1 if a, b, c turn left (counter-clockwise), -1 if right, 0 if flat (within rounding of collinear).
int turn(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 ab = b - a, bc = c - b;
  const double cross = ab.x() * bc.y() - ab.y() * bc.x();
  const double tolerance = kFlat * (ab.cwiseAbs().sum() + bc.cwiseAbs().sum());
  return cross > tolerance ? 1 : cross < -tolerance ? -1 : 0;
}

// 1 if a, b, c turn left (counter-clockwise), -1 if right, 0 if collinear; exact.
int orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double left = (a.x() - c.x()) * (b.y() - c.y());
  const double right = (a.y() - c.y()) * (b.x() - c.x());
  const double det = left - right;
  // Shewchuk's ccwerrboundA: beyond it the rounded determinant has the exact one's sign.
  const double bound = 3.3306690738754716e-16 * (std::abs(left) + std::abs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return exactOrientation(a.x(), a.y(), b.x(), b.y(), c.x(), c.y());
}

// Whether q, collinear with a and b, lies on the closed segment ab.
bool onSegment(const Vec2& a, const Vec2& b, const Vec2& q) {
  return std::min(a.x(), b.x()) <= q.x() && q.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= q.y() &&
         q.y() <= std::max(a.y(), b.y());
}

// Whether the closed segments ab and cd have a point in common.
bool segmentsMeet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const int abc = orientation(a, b, c), abd = orientation(a, b, d);
  const int cda = orientation(c, d, a), cdb = orientation(c, d, b);
  if (abc * abd < 0 && cda * cdb < 0) return true;
  return (abc == 0 && onSegment(a, b, c)) || (abd == 0 && onSegment(a, b, d)) || (cda == 0 && onSegment(c, d, a)) ||
         (cdb == 0 && onSegment(c, d, b));
}

}  // namespace

bool PolygonTriangulator::triangulate(const std::vector<Vec3>& positions, const std::vector<int>& corners,
                                      std::vector<PolygonTriangle>& triangles) {
  const int n = static_cast<int>(corners.size());
  UVTK_CHECK(n >= 3);
  triangles.clear();
  const auto fan = [&] {
    for (int i = 1; i + 1 < n; ++i) triangles.push_back({0, i, i + 1});
  };
  if (n == 3) {
    fan();
    return true;
  }

  // Relative to the first corner and scaled by a power of two to at most 4: then no product
  // overflows or underflows. Halves, because differences of positions may overflow.
  Vec3 lo = positions[corners[0]], hi = lo;
  for (int c : corners) {
    lo = lo.cwiseMin(positions[c]);
    hi = hi.cwiseMax(positions[c]);
  }
  const double halfExtent = (0.5 * hi - 0.5 * lo).maxCoeff();
  if (halfExtent == 0.0) {  // every corner at one point
    fan();
    return false;
  }
  const int exponent = 1 - std::ilogb(halfExtent);
  const auto difference = [exponent](const Vec3& p, const Vec3& q) {
    const Vec3 half = 0.5 * p - 0.5 * q;
    return Vec3(std::ldexp(half.x(), exponent), std::ldexp(half.y(), exponent), std::ldexp(half.z(), exponent));
  };
  relative_.resize(n);
  for (int i = 0; i < n; ++i) relative_[i] = difference(positions[corners[i]], positions[corners[0]]);
  Vec3 normal = Vec3::Zero();  // Newell's: twice the vector area
  for (int i = 0; i + 1 < n; ++i) normal += relative_[i].cross(relative_[i + 1]);
  if (normal.squaredNorm() == 0.0) {  // no area: corners on a line, or a symmetric bowtie
    fan();
    return false;
  }

  // The plane's frame (u, v, normal) is right-handed, so the projected polygon turns counter-clockwise.
  normal.normalize();
  int smallest = 0;
  normal.cwiseAbs().minCoeff(&smallest);
  const Vec3 u = Vec3::Unit(smallest).cross(normal).normalized();
  const Vec3 v = normal.cross(u);
  points_.resize(n);
  double lowest = 0.0, highest = 0.0;
  for (int i = 0; i < n; ++i) {
    points_[i] = Vec2(relative_[i].dot(u), relative_[i].dot(v));
    const double height = relative_[i].dot(normal);
    lowest = std::min(lowest, height);
    highest = std::max(highest, height);
  }
  // The sweeps (blockers of an ear, crossing edges) go along x: make it the axis along which fewer
  // edges overlap on average (their total length over the extent), turning the frame a quarter if
  // need be, so that a comb is swept along its teeth and not across them.
  Vec2 low = points_[0], high = low, length = Vec2::Zero();
  for (int i = 0; i < n; ++i) {
    low = low.cwiseMin(points_[i]);
    high = high.cwiseMax(points_[i]);
    length += (points_[i + 1 == n ? 0 : i + 1] - points_[i]).cwiseAbs();
  }
  if (length.y() * (high.x() - low.x()) < length.x() * (high.y() - low.y()))
    for (Vec2& p : points_) p = Vec2(p.y(), -p.x());
  // Non-planar: a corner farther than the tolerance from the plane halfway between the extreme ones.
  const bool planar = highest - lowest <= 2.0 * kNonPlanarTolerance * difference(hi, lo).norm();

  findEdges();
  if (strictlyConvex()) {  // what ear clipping from corner 1 gives too, in O(n)
    fan();
    return planar;
  }
  if (n > static_cast<int>(kMaxEarClippingCorners)) {
    fan();
    return false;
  }
  const bool clean = earClip(triangles);
  return planar && clean && boundaryIsSimple();
}

void PolygonTriangulator::findEdges() {
  const int n = static_cast<int>(points_.size());
  starts_.clear();
  for (int i = 0; i < n; ++i)
    if (points_[i] != points_[i + 1 == n ? 0 : i + 1]) starts_.push_back(i);
}

// Every turn strictly left, and the edges' direction going round once: it passes the +x direction
// counter-clockwise once (a pentagram turns left everywhere but goes round twice).
bool PolygonTriangulator::strictlyConvex() const {
  const std::size_t m = starts_.size();
  if (m < 3) return false;
  int rounds = 0;
  for (std::size_t j = 0; j < m; ++j) {
    const Vec2& a = points_[starts_[j]];
    const Vec2& b = points_[starts_[(j + 1) % m]];
    const Vec2& c = points_[starts_[(j + 2) % m]];
    if (turn(a, b, c) <= 0) return false;
    if (b.y() < a.y() && c.y() >= b.y()) ++rounds;
  }
  return rounds == 1;
}

bool PolygonTriangulator::isConvex(int b) const {
  return turn(points_[previous_[b]], points_[b], points_[next_[b]]) > 0;
}

// Clips ears from corner 1 on, each time going on with the corner after the one clipped: for a
// convex polygon, the fan from corner 0. Returns false when a full round found no ear (a polygon
// that is not simple): a convex corner, or any, was clipped anyway so that the loop ends, after at
// most n rounds of n tests.
bool PolygonTriangulator::earClip(std::vector<PolygonTriangle>& triangles) {
  const int n = static_cast<int>(points_.size());
  previous_.resize(n);
  next_.resize(n);
  convex_.resize(n);
  alive_.assign(n, 1);
  listed_.assign(n, 0);
  reflex_.clear();
  lateReflex_.clear();
  for (int i = 0; i < n; ++i) {
    previous_[i] = i == 0 ? n - 1 : i - 1;
    next_[i] = i + 1 == n ? 0 : i + 1;
  }
  for (int i = 0; i < n; ++i) {
    convex_[i] = isConvex(i);
    if (!convex_[i]) reflex_.push_back(i), listed_[i] = 1;
  }
  std::sort(reflex_.begin(), reflex_.end(), [&](int i, int j) { return points_[i].x() < points_[j].x(); });
  // Clipping only makes corners more convex, but for a polygon that is not simple.
  const auto update = [&](int k) {
    convex_[k] = isConvex(k);
    if (!convex_[k] && !listed_[k]) lateReflex_.push_back(k), listed_[k] = 1;
  };
  bool clean = true;
  int b = 1, failures = 0;
  for (int remaining = n; remaining > 3; --remaining) {
    while (!isEar(b)) {
      b = next_[b];
      if (++failures < remaining) continue;
      clean = false;
      for (int i = 0; i < remaining && !convex_[b]; ++i) b = next_[b];
      break;
    }
    const int a = previous_[b], c = next_[b];
    triangles.push_back({a, b, c});
    next_[a] = c;
    previous_[c] = a;
    alive_[b] = 0;
    update(a);
    update(c);
    b = c;
    failures = 0;
  }
  triangles.push_back({previous_[b], b, next_[b]});
  return clean;
}

// A strictly convex corner whose triangle holds no other corner, inside or on its boundary (corners
// at the same point as its neighbours excepted). Only corners that are not strictly convex can be
// inside, and only those between the triangle's extreme x are looked at.
bool PolygonTriangulator::isEar(int b) {
  if (!convex_[b]) return false;
  const int a = previous_[b], c = next_[b];
  const Vec2 &pa = points_[a], &pb = points_[b], &pc = points_[c];
  const double minX = std::min({pa.x(), pb.x(), pc.x()}), maxX = std::max({pa.x(), pb.x(), pc.x()});
  const double minY = std::min({pa.y(), pb.y(), pc.y()}), maxY = std::max({pa.y(), pb.y(), pc.y()});
  const auto blocks = [&](int r) {
    const Vec2& p = points_[r];
    return alive_[r] && !convex_[r] && r != a && r != c && minY <= p.y() && p.y() <= maxY && p != pa && p != pc &&
           turn(pa, pb, p) >= 0 && turn(pb, pc, p) >= 0 && turn(pc, pa, p) >= 0;
  };
  const auto first = std::lower_bound(reflex_.begin(), reflex_.end(), minX,
                                      [&](int r, double x) { return points_[r].x() < x; });
  for (auto r = first; r != reflex_.end() && points_[*r].x() <= maxX; ++r)
    if (blocks(*r)) return false;
  for (int r : lateReflex_)
    if (minX <= points_[r].x() && points_[r].x() <= maxX && blocks(r)) return false;
  return true;
}

// Whether the boundary touches itself nowhere but where consecutive edges meet: no edge doubles
// back along the one before, and no two other edges meet (a sweep over x; quadratic at worst).
bool PolygonTriangulator::boundaryIsSimple() {
  const std::size_t m = starts_.size();
  if (m < 3) return false;
  const auto point = [&](std::size_t j) -> const Vec2& { return points_[starts_[j % m]]; };
  for (std::size_t j = 0; j < m; ++j) {
    const Vec2 &a = point(j), &b = point(j + 1), &c = point(j + 2);
    if (turn(a, b, c) != 0) continue;
    const bool doublesBack = a.x() != b.x() ? (a.x() < b.x()) == (c.x() < b.x()) : (a.y() < b.y()) == (c.y() < b.y());
    if (doublesBack) return false;
  }
  const auto minX = [&](int j) { return std::min(point(j).x(), point(j + 1).x()); };
  const auto maxX = [&](int j) { return std::max(point(j).x(), point(j + 1).x()); };
  order_.resize(m);
  for (std::size_t j = 0; j < m; ++j) order_[j] = static_cast<int>(j);
  std::sort(order_.begin(), order_.end(), [&](int j, int k) { return minX(j) < minX(k); });
  for (std::size_t s = 0; s < m; ++s) {
    const int j = order_[s];
    const double right = maxX(j);
    const double bottom = std::min(point(j).y(), point(j + 1).y()), top = std::max(point(j).y(), point(j + 1).y());
    for (std::size_t t = s + 1; t < m && minX(order_[t]) <= right; ++t) {
      const int k = order_[t];
      const std::size_t gap = static_cast<std::size_t>(std::abs(j - k));
      if (gap == 1 || gap == m - 1) continue;  // consecutive edges
      if (std::max(point(k).y(), point(k + 1).y()) < bottom || std::min(point(k).y(), point(k + 1).y()) > top) continue;
      if (segmentsMeet(point(j), point(j + 1), point(k), point(k + 1))) return false;
    }
  }
  return true;
}

}  // namespace uvtk::io
