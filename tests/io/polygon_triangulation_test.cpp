// Polygon triangulation: hand-computed areas, every triangle turning the polygon's way, the old fan
// for convex polygons, the warnings for polygons that are not simple, and the time it takes.
#include "io/polygon_triangulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <numeric>
#include <random>
#include <vector>

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

constexpr double kPi = 3.14159265358979323846;

struct Triangulation {
  std::vector<PolygonTriangle> triangles;
  bool simple = false;
};

Triangulation triangulate(const std::vector<Vec3>& points) {
  std::vector<int> corners(points.size());
  std::iota(corners.begin(), corners.end(), 0);
  Triangulation t;
  PolygonTriangulator triangulator;
  t.simple = triangulator.triangulate(points, corners, t.triangles);
  return t;
}

std::vector<Vec3> inPlane(const std::vector<Vec2>& xy) {
  std::vector<Vec3> points;
  for (const Vec2& p : xy) points.emplace_back(p.x(), p.y(), 0.0);
  return points;
}

std::vector<PolygonTriangle> fan(int n) {
  std::vector<PolygonTriangle> triangles;
  for (int i = 1; i + 1 < n; ++i) triangles.push_back({0, i, i + 1});
  return triangles;
}

// Twice the polygon's vector area (Newell's normal).
Vec3 doubleVectorArea(const std::vector<Vec3>& p) {
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i < p.size(); ++i) sum += p[i].cross(p[(i + 1) % p.size()]);
  return sum;
}

// The triangles, measured on `points` (which may differ from the points triangulated by a scale):
// n - 2 of them, every one turning the polygon's way with a positive area, and their areas adding up to
// `area`, so none overlaps another.
void expectCovers(const std::vector<Vec3>& points, const std::vector<PolygonTriangle>& triangles, double area) {
  ASSERT_EQ(triangles.size(), points.size() - 2);
  const Vec3 normal = doubleVectorArea(points).normalized();
  double total = 0.0;
  std::vector<int> used(points.size(), 0);
  for (const PolygonTriangle& t : triangles) {
    const Vec3 n = (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]);
    EXPECT_GT(n.dot(normal), 0.0) << "triangle " << t[0] << " " << t[1] << " " << t[2];
    total += 0.5 * n.norm();
    for (int c : t) used[c] = 1;
  }
  EXPECT_NEAR(total, area, 1e-12 * area);
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0) << "every corner is in a triangle";
}

void expectSimpleAndCovers(const std::vector<Vec3>& points, double area) {
  const Triangulation t = triangulate(points);
  EXPECT_TRUE(t.simple);
  expectCovers(points, t.triangles, area);
}

// (0,0) (2,0) (2,2) (1,1) (0,2), started at (2,2): the fan from the first corner folds (its triangles
// add up to 5, one of them turned the wrong way); the polygon's area is 3.
const std::vector<Vec2> kConcavePentagon = {{2, 2}, {1, 1}, {0, 2}, {0, 0}, {2, 0}};
// An L: a 2 x 2 square less its top right quarter, area 3, started at its reflex corner's neighbour.
const std::vector<Vec2> kL = {{2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}, {2, 0}};

// A comb of m teeth: a base 1 high and 2m - 1 wide, and m teeth 1 x 1 on it; 4m corners, area 3m - 1.
std::vector<Vec2> comb(int m) {
  std::vector<Vec2> p = {{0, 0}, {2.0 * m - 1, 0}};
  for (int k = m - 1; k >= 0; --k) {
    p.emplace_back(2.0 * k + 1, 2);
    p.emplace_back(2.0 * k, 2);
    if (k > 0) {
      p.emplace_back(2.0 * k, 1);
      p.emplace_back(2.0 * k - 1, 1);
    }
  }
  return p;  // the last corner, (0, 2), goes down to the first
}

// A star of `points` points between radii r and R: 2 * points corners, area points * R * r * sin(pi / points).
std::vector<Vec2> star(int points, double r, double R) {
  std::vector<Vec2> p;
  for (int i = 0; i < 2 * points; ++i) {
    const double angle = kPi * i / points, radius = i % 2 ? r : R;
    p.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
  }
  return p;
}

std::vector<Vec3> rotated(const std::vector<Vec3>& points, const Vec3& shift) {
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<Vec3> out;
  for (const Vec3& p : points) out.push_back(rotation * p + shift);
  return out;
}

TEST(PolygonTriangulation, TheFanOfTheConcavePentagonFoldsButItsTriangulationDoesNot) {
  const std::vector<Vec3> p = inPlane(kConcavePentagon);
  double fanArea = 0.0;
  for (const PolygonTriangle& t : fan(5)) fanArea += 0.5 * (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).norm();
  EXPECT_DOUBLE_EQ(fanArea, 5.0);
  expectSimpleAndCovers(p, 3.0);
}

TEST(PolygonTriangulation, AnLShapedHexagon) { expectSimpleAndCovers(inPlane(kL), 3.0); }

TEST(PolygonTriangulation, StarsWithFewAndManyPoints) {
  for (int points : {5, 7, 64}) {
    SCOPED_TRACE(points);
    expectSimpleAndCovers(inPlane(star(points, 1.0, 2.5)), points * 2.5 * std::sin(kPi / points));
  }
}

TEST(PolygonTriangulation, ACombWithManyTeeth) {
  ASSERT_EQ(comb(50).size(), 200u);
  expectSimpleAndCovers(inPlane(comb(50)), 149.0);
}

TEST(PolygonTriangulation, CollinearCornersGiveNoZeroAreaTriangle) {
  // A 2 x 2 square with a corner in the middle of every side (convex, but not strictly), and an L whose
  // long sides have two more corners each; expectCovers checks every triangle's area is positive.
  expectSimpleAndCovers(inPlane({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}}), 4.0);
  expectSimpleAndCovers(inPlane({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 1}, {0, 0.5}}), 3.0);
  // Three corners in a row at the first corner, where the fan starts.
  expectSimpleAndCovers(inPlane({{1, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 0}}), 4.0);
}

TEST(PolygonTriangulation, InATiltedPlane) {
  const Vec3 shift(100, -50, 3);
  expectSimpleAndCovers(rotated(inPlane(kConcavePentagon), shift), 3.0);
  expectSimpleAndCovers(rotated(inPlane(comb(20)), shift), 59.0);
  expectSimpleAndCovers(rotated(inPlane(star(9, 0.5, 3)), shift), 9 * 1.5 * std::sin(kPi / 9));
}

TEST(PolygonTriangulation, ClockwiseTrianglesForAClockwisePolygon) {
  std::vector<Vec2> clockwise(kL.rbegin(), kL.rend());
  const std::vector<Vec3> p = inPlane(clockwise);
  const Triangulation t = triangulate(p);
  EXPECT_TRUE(t.simple);
  expectCovers(p, t.triangles, 3.0);
  for (const PolygonTriangle& tri : t.triangles)
    EXPECT_LT((p[tri[1]] - p[tri[0]]).cross(p[tri[2]] - p[tri[0]]).z(), 0.0);
}

TEST(PolygonTriangulation, TinyAndHugePolygonsAreTriangulatedAlike) {
  // Areas of 1e-400 and 1e400 are beyond a double: the triangles are measured on the unscaled comb.
  // 8e306: corners on both sides of the origin, whose differences are beyond a double.
  const std::vector<Vec3> p = rotated(inPlane(comb(10)), Vec3(-9.5, 0.25, 2));
  for (double scale : {1e-200, 1e200, 1e-300, 1e300, 8e306}) {
    SCOPED_TRACE(scale);
    std::vector<Vec3> scaled;
    for (const Vec3& q : p) scaled.push_back(q * scale);
    const Triangulation t = triangulate(scaled);
    EXPECT_TRUE(t.simple);
    expectCovers(p, t.triangles, 29.0);
  }
  // A tiny polygon far from the origin: 1e-280 across, at z = 1e300.
  std::vector<Vec3> far;
  for (const Vec2& q : comb(10)) far.emplace_back(q.x() * 1e-280, q.y() * 1e-280, 1e300);
  const Triangulation t = triangulate(far);
  EXPECT_TRUE(t.simple);
  expectCovers(inPlane(comb(10)), t.triangles, 29.0);
}

TEST(PolygonTriangulation, ConvexPolygonsGiveTheFanFromTheFirstCorner) {
  EXPECT_EQ(triangulate(inPlane({{0, 0}, {1, 0}, {1, 1}, {0, 1}})).triangles, fan(4));
  std::vector<Vec2> polygon;
  for (int i = 0; i < 12; ++i) polygon.emplace_back(std::cos(2 * kPi * i / 12 + 0.1), 0.5 * std::sin(2 * kPi * i / 12 + 0.1));
  const Triangulation t = triangulate(rotated(inPlane(polygon), Vec3(1, 2, 3)));
  EXPECT_TRUE(t.simple);
  EXPECT_EQ(t.triangles, fan(12));
  // Clockwise, and with a repeated corner (f 1 2 3 3): the fan too, as before.
  EXPECT_EQ(triangulate(inPlane({{0, 0}, {0, 1}, {1, 1}, {1, 0}})).triangles, fan(4));
  const Triangulation repeated = triangulate(inPlane({{0, 0}, {1, 0}, {0, 1}, {0, 1}}));
  EXPECT_TRUE(repeated.simple);
  EXPECT_EQ(repeated.triangles, fan(4));
}

TEST(PolygonTriangulation, AMillionCornerConvexFaceIsFanned) {
  const int n = 1'000'000;
  std::vector<Vec3> points;
  for (int i = 0; i < n; ++i) points.emplace_back(std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n), 1.0);
  const auto start = std::chrono::steady_clock::now();
  const Triangulation t = triangulate(points);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(t.simple);
  EXPECT_EQ(t.triangles, fan(n));
  EXPECT_LT(seconds, 2.0);
  std::cout << "a convex face of " << n << " corners: " << seconds << " s\n";
}

TEST(PolygonTriangulation, ATwentyThousandCornerCombFinishes) {
  const std::vector<Vec3> p = inPlane(comb(5000));
  ASSERT_EQ(p.size(), 20000u);
  const auto start = std::chrono::steady_clock::now();
  const Triangulation t = triangulate(p);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(t.simple);
  expectCovers(p, t.triangles, 14999.0);
  EXPECT_LT(seconds, 30.0);
  std::cout << "a comb of 20000 corners: " << seconds << " s\n";
}

TEST(PolygonTriangulation, RandomStarShapedPolygonsInRandomPlanes) {
  // Corners at increasing angles and random radii around the origin: always simple, often concave.
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 4 + trial % 40;
    std::vector<double> angles;
    for (int i = 0; i < n; ++i) angles.push_back(2 * kPi * (i + 0.9 * unit(random)) / n);
    std::vector<Vec2> polygon;
    double area = 0.0;
    for (int i = 0; i < n; ++i) polygon.emplace_back(angles[i], 0.1 + unit(random));
    for (int i = 0; i < n; ++i) {  // exact area of a star-shaped polygon: its triangles from the centre
      const Vec2 a = polygon[i], b = polygon[(i + 1) % n];
      area += 0.5 * a.y() * b.y() * std::sin(b.x() - a.x() + (i + 1 == n ? 2 * kPi : 0.0));
    }
    for (Vec2& p : polygon) p = Vec2(p.y() * std::cos(p.x()), p.y() * std::sin(p.x()));
    std::rotate(polygon.begin(), polygon.begin() + trial % n, polygon.end());
    SCOPED_TRACE(trial);
    expectSimpleAndCovers(rotated(inPlane(polygon), Vec3(unit(random), -7, 30)), area);
  }
}

TEST(PolygonTriangulation, SelfIntersectingPolygonsAreTriangulatedAndReported) {
  for (const std::vector<Vec2>& polygon : std::vector<std::vector<Vec2>>{
           {{0, 0}, {1, 1}, {1, 0}, {0, 1}},            // a bowtie: no area
           {{0, 0}, {2, 2}, {2, 0}, {0, 1}},            // a bowtie with unequal halves
           star(5, 2.0, 2.0),                           // a decagon...
           {{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {2, 3}, {0, 2}},  // a spike doubling back
           {{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}},                  // touching itself at (2, 0)
           {{0, 0}, {2, 0}, {2, 2}, {1, 2}, {1, -1}, {0, -1}},        // crossing an earlier edge
       }) {
    const Triangulation t = triangulate(inPlane(polygon));
    EXPECT_EQ(t.triangles.size(), polygon.size() - 2);
    if (polygon.size() == 10) {
      EXPECT_TRUE(t.simple);  // ... is simple, only a pentagram is not:
      continue;
    }
    EXPECT_FALSE(t.simple) << polygon[1].transpose();
  }
  std::vector<Vec2> pentagram;
  for (int i = 0; i < 5; ++i) pentagram.emplace_back(std::cos(4 * kPi * i / 5), std::sin(4 * kPi * i / 5));
  const Triangulation t = triangulate(inPlane(pentagram));
  EXPECT_FALSE(t.simple);
  EXPECT_EQ(t.triangles.size(), 3u);
}

TEST(PolygonTriangulation, NonPlanarMeansACornerOnePercentOfTheSizeOffThePlane) {
  // A unit square with one corner lifted by h: the corners are h / 4 off the mean plane, the diagonal is
  // about sqrt(2): non-planar from h = 4 * 0.01 * sqrt(2) = 0.057.
  const auto lifted = [](double h) { return triangulate({{0, 0, 0}, {1, 0, 0}, {1, 1, h}, {0, 1, 0}}); };
  EXPECT_TRUE(lifted(0.05).simple);
  EXPECT_FALSE(lifted(0.06).simple);
  EXPECT_EQ(lifted(0.5).triangles, fan(4));
}

TEST(PolygonTriangulation, DegeneratePolygonsAreFannedAndReported) {
  const Triangulation line = triangulate(inPlane({{0, 0}, {1, 0}, {2, 0}, {3, 0}}));
  EXPECT_FALSE(line.simple);
  EXPECT_EQ(line.triangles, fan(4));
  const Triangulation point = triangulate(inPlane({{1, 1}, {1, 1}, {1, 1}, {1, 1}, {1, 1}}));
  EXPECT_FALSE(point.simple);
  EXPECT_EQ(point.triangles, fan(5));
  // A triangle is returned as it is, even a degenerate one (the mesh check counts those).
  const Triangulation triangle = triangulate(inPlane({{0, 0}, {1, 0}, {2, 0}}));
  EXPECT_TRUE(triangle.simple);
  EXPECT_EQ(triangle.triangles, fan(3));
}

TEST(PolygonTriangulation, ANonConvexPolygonTooLargeToEarClipIsFannedAndReported) {
  std::vector<Vec2> zigzag;
  const int n = static_cast<int>(kMaxEarClippingCorners) + 2;
  for (int i = 0; i + 1 < n; ++i) zigzag.emplace_back(i, i % 2);
  zigzag.emplace_back(0, -1);
  const Triangulation t = triangulate(inPlane(zigzag));
  EXPECT_FALSE(t.simple);
  EXPECT_EQ(t.triangles, fan(n));
}

TEST(PolygonTriangulation, ReusesItsScratchSpaceAcrossPolygons) {
  PolygonTriangulator triangulator;
  std::vector<PolygonTriangle> triangles;
  const std::vector<Vec3> comb20 = inPlane(comb(20)), square = inPlane({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  std::vector<int> combCorners(comb20.size()), squareCorners = {0, 1, 2, 3};
  std::iota(combCorners.begin(), combCorners.end(), 0);
  EXPECT_TRUE(triangulator.triangulate(comb20, combCorners, triangles));
  EXPECT_TRUE(triangulator.triangulate(square, squareCorners, triangles));
  EXPECT_EQ(triangles, fan(4));
  EXPECT_TRUE(triangulator.triangulate(comb20, combCorners, triangles));
  expectCovers(comb20, triangles, 59.0);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
