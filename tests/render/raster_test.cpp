#include "render/raster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <algorithm>
#include <limits>
#include <optional>
#include <random>

#include "core/error.h"
#include "core/gl_matrices.h"

namespace uvtk::render {
namespace {
namespace UVTK_TEST_FILE {

// Clip coordinates of window point (x, y) (y up) at depth z_ndc under an identity projection.
Vec4 windowPoint(double x, double y, int width, int height, double z = 0.0) {
  return Vec4(2.0 * x / width - 1.0, 2.0 * y / height - 1.0, z, 1.0);
}

// Rasterizes three clip-space corners per triangle.
VisibilityBuffer rasterizeCorners(const std::vector<Vec4>& corners, int width, int height, const RasterOptions& options,
                                  RasterStats* stats = nullptr) {
  std::vector<Triangle> triangles;
  for (int c = 0; c + 2 < int(corners.size()); c += 3) triangles.push_back({c, c + 1, c + 2});
  return rasterize(corners, triangles, width, height, options, stats);
}

// How many triangles cover each pixel, each triangle rasterized alone.
std::vector<int> coverageCounts(const std::vector<Vec4>& clip, int width, int height, Cull cull = Cull::None) {
  std::vector<int> count(std::size_t(width) * std::size_t(height), 0);
  for (std::size_t f = 0; f < clip.size() / 3; ++f) {
    const std::vector<Vec4> one(clip.begin() + long(3 * f), clip.begin() + long(3 * f + 3));
    const VisibilityBuffer b = rasterizeCorners(one, width, height, {cull, 1});
    for (std::size_t i = 0; i < count.size(); ++i) count[i] += b.face[i] >= 0;
  }
  return count;
}

// A grid of (n x m) quads over the window [x0, x1] x [y0, y1], two triangles each, its inner
// vertices jittered by up to `jitter` pixels, corners counter-clockwise.
std::vector<Vec4> windowGrid(int n, int m, double x0, double x1, double y0, double y1, double jitter, int width,
                             int height, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-jitter, jitter);
  std::vector<Vec2> p(std::size_t((n + 1) * (m + 1)));
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) {
      Vec2 q(x0 + (x1 - x0) * i / n, y0 + (y1 - y0) * j / m);
      if (i > 0 && i < n && j > 0 && j < m) q += Vec2(offset(random), offset(random));
      p[std::size_t(j * (n + 1) + i)] = q;
    }
  std::vector<Vec4> clip;
  auto corner = [&](int i, int j) {
    const Vec2& q = p[std::size_t(j * (n + 1) + i)];
    clip.push_back(windowPoint(q.x(), q.y(), width, height));
  };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      corner(i, j), corner(i + 1, j), corner(i + 1, j + 1);
      corner(i, j), corner(i + 1, j + 1), corner(i, j + 1);
    }
  return clip;
}

TEST(Rasterize, TrianglesTilingTheScreenCoverEveryPixelExactlyOnce) {
  const int width = 40, height = 30;
  // Vertices on pixel centres and pixel edges (every tie of the fill rule), then jittered ones.
  for (const double jitter : {0.0, 0.37}) {
    const std::vector<Vec4> clip = windowGrid(8, 6, 0.0, width, 0.0, height, jitter, width, height, 7);
    const std::vector<Vec4> centres = windowGrid(13, 9, -0.5, width + 0.5, -0.5, height + 0.5, jitter, width, height, 9);
    for (const auto* mesh : {&clip, &centres}) {
      const std::vector<int> count = coverageCounts(*mesh, width, height);
      for (std::size_t i = 0; i < count.size(); ++i) ASSERT_EQ(count[i], 1) << "pixel " << i << ", jitter " << jitter;
    }
  }
}

TEST(Rasterize, AHorizontalSharedEdgeThroughPixelCentresGoesToTheTriangleBelowItsTopEdge) {
  // Two triangles share the horizontal edge y = 2.5 (pixel centres of window row 2). The upper
  // triangle has it as its bottom edge, the lower one as its top edge: the lower one owns it.
  const int width = 8, height = 6;
  const std::vector<Vec4> lower = {windowPoint(0, 0, width, height), windowPoint(8, 2.5, width, height),
                                   windowPoint(0, 2.5, width, height)};
  const std::vector<Vec4> upper = {windowPoint(0, 2.5, width, height), windowPoint(8, 2.5, width, height),
                                   windowPoint(0, 6, width, height)};
  const VisibilityBuffer low = rasterizeCorners(lower, width, height, {Cull::None, 1});
  const VisibilityBuffer up = rasterizeCorners(upper, width, height, {Cull::None, 1});
  const int row = height - 1 - 2;  // window row 2
  EXPECT_EQ(low.face[low.index(0, row)], 0);
  EXPECT_EQ(up.face[up.index(0, row)], -1);
  // The left edge x = 0 passes no pixel centre; the vertical left edge of this one does: x = 0.5.
  const std::vector<Vec4> left = {windowPoint(0.5, 0, width, height), windowPoint(4, 3, width, height),
                                  windowPoint(0.5, 6, width, height)};
  const VisibilityBuffer l = rasterizeCorners(left, width, height, {Cull::None, 1});
  EXPECT_EQ(l.face[l.index(0, height - 1 - 3)], 0);  // centre (0.5, 3.5) on the left edge: owned
}

TEST(Rasterize, CullsByWindowWindingAndKeepsTheNearestFragment) {
  const int width = 4, height = 4;
  const std::vector<Vec4> ccw = {windowPoint(0, 0, width, height, 0.5), windowPoint(4, 0, width, height, 0.5),
                                 windowPoint(0, 4, width, height, 0.5)};
  const std::vector<Vec4> cw = {ccw[0], ccw[2], ccw[1]};
  EXPECT_EQ(rasterizeCorners(ccw, width, height, {Cull::Back, 1}).face[12], 0);
  EXPECT_EQ(rasterizeCorners(cw, width, height, {Cull::Back, 1}).face[12], -1);
  EXPECT_EQ(rasterizeCorners(cw, width, height, {Cull::Front, 1}).face[12], 0);
  EXPECT_EQ(rasterizeCorners(ccw, width, height, {Cull::Front, 1}).face[12], -1);

  // Three full-screen triangles: depth 0.5, 0.0 and 0.0 again. LESS keeps the second.
  std::vector<Vec4> stack;
  for (double z : {0.5, 0.0, 0.0}) {
    stack.push_back(windowPoint(-10, -10, width, height, z));
    stack.push_back(windowPoint(20, -10, width, height, z));
    stack.push_back(windowPoint(-10, 20, width, height, z));
  }
  const VisibilityBuffer b = rasterizeCorners(stack, width, height, {Cull::Back, 1});
  for (std::size_t i = 0; i < b.face.size(); ++i) {
    EXPECT_EQ(b.face[i], 1);
    EXPECT_EQ(b.depth[i], 0.5f);  // window depth = (z_ndc + 1) / 2
  }
}

TEST(Rasterize, TheOutputDoesNotDependOnTheThreadCount) {
  const int width = 300, height = 200;
  std::vector<Vec4> clip = windowGrid(60, 40, -20.0, width + 20.0, -20.0, height + 20.0, 2.0, width, height, 3);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> depth(-0.9, 0.9);
  for (std::size_t c = 0; c < clip.size(); c += 3) {  // overlapping layers in random depth order
    const double z = depth(random);
    for (int k = 0; k < 3; ++k) clip[c + std::size_t(k)].z() = z;
  }
  const std::vector<Vec4> again = clip;
  clip.insert(clip.end(), again.begin(), again.end());
  const VisibilityBuffer one = rasterizeCorners(clip, width, height, {Cull::None, 1});
  const VisibilityBuffer two = rasterizeCorners(clip, width, height, {Cull::None, 2});
  const VisibilityBuffer five = rasterizeCorners(clip, width, height, {Cull::None, 5});
  EXPECT_EQ(one.face, two.face);
  EXPECT_EQ(one.face, five.face);
  EXPECT_EQ(one.depth, two.depth);
}

// The ground plane y = -1 under a camera at the origin looking down -z: a triangle reaching
// behind the eye, a grid of them for watertightness.
struct GroundScene {
  int width = 64, height = 48;
  Mat4 clipFromWorld = perspective(90.0, 64.0 / 48.0, 0.1, 200.0) * lookAt(Vec3::Zero(), Vec3(0, 0, -1), Vec3::UnitY());
  Vec4 clip(const Vec3& p) const { return clipFromWorld * p.homogeneous(); }
  // Where the ray through window point (x, y) meets the ground, if in front of the eye.
  std::optional<Vec3> groundHit(double x, double y) const {
    const double t = std::tan(kPi / 4.0);
    const Vec3 d((2.0 * x / width - 1.0) * t * width / height, (2.0 * y / height - 1.0) * t, -1.0);
    if (!(d.y() < 0.0)) return std::nullopt;
    return d * (-1.0 / d.y());
  }
};

TEST(Rasterize, ATriangleReachingBehindTheEyeCoversExactlyThePixelsWhoseRaysHitIt) {
  const GroundScene s;
  const Vec3 a(-50, -1, -50), b(50, -1, -50), c(0, -1, 50);  // counter-clockwise in the (x, z) plane
  const std::vector<Vec4> clip = {s.clip(a), s.clip(b), s.clip(c)};
  ASSERT_LT(clip[2].w(), 0.0);  // the third corner is behind the eye
  const VisibilityBuffer buffer = rasterizeCorners(clip, s.width, s.height, {Cull::None, 1});
  int covered = 0;
  for (int row = 0; row < s.height; ++row)
    for (int x = 0; x < s.width; ++x) {
      const double wx = x + 0.5, wy = s.height - row - 0.5;
      const std::optional<Vec3> hit = s.groundHit(wx, wy);
      bool inside = false;
      if (hit) {  // inside the triangle by the signs of the 2D cross products in the xz plane
        const auto side = [&](const Vec3& p, const Vec3& q) {  // times 1 / |q - p|: the distance
          return ((q.x() - p.x()) * (hit->z() - p.z()) - (q.z() - p.z()) * (hit->x() - p.x())) / (q - p).norm();
        };
        const double nearest = std::min({std::abs(side(a, b)), std::abs(side(b, c)), std::abs(side(c, a))});
        if (nearest < 1e-9 * hit->norm()) continue;  // a centre on an edge: the fill rule's business
        inside = side(a, b) > 0 && side(b, c) > 0 && side(c, a) > 0;
      }
      const int face = buffer.face[buffer.index(x, row)];
      EXPECT_EQ(face == 0, inside) << "pixel " << x << ", " << row;
      covered += face == 0;
      if (face == 0) {  // the depth of the hit point, through the projection
        const Vec4 h = s.clip(*hit);
        EXPECT_NEAR(buffer.depth[buffer.index(x, row)], 0.5 * h.z() / h.w() + 0.5, 1e-6);
      }
    }
  EXPECT_GT(covered, 500);
}

TEST(Rasterize, AGroundGridCrossingTheNearPlaneStaysWatertight) {
  const GroundScene s;
  std::vector<Vec4> clip;
  const int n = 12;
  const double size = 8.0;  // the grid spans [-8, 8]^2 around the eye, half of it behind
  auto at = [&](int i, int j) { return s.clip(Vec3(-size + 2 * size * i / n, -1.0, -size + 2 * size * j / n)); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      clip.push_back(at(i, j)), clip.push_back(at(i, j + 1)), clip.push_back(at(i + 1, j + 1));
      clip.push_back(at(i, j)), clip.push_back(at(i + 1, j + 1)), clip.push_back(at(i + 1, j));
    }
  const std::vector<int> count = coverageCounts(clip, s.width, s.height);
  int inside = 0;
  for (int row = 0; row < s.height; ++row)
    for (int x = 0; x < s.width; ++x) {
      const std::optional<Vec3> hit = s.groundHit(x + 0.5, s.height - row - 0.5);
      const bool expected = hit && std::abs(hit->x()) < size && std::abs(hit->z()) < size && -hit->z() > 0.1;
      const int c = count[std::size_t(row * s.width + x)];
      EXPECT_EQ(c, expected ? 1 : 0) << "pixel " << x << ", " << row;
      inside += expected;
    }
  EXPECT_GT(inside, 1000);
}

TEST(Rasterize, TrianglesBehindTheEyeOrWithHugeOrNonFiniteCoordinatesDrawNothingWrong) {
  const GroundScene s;
  // Wholly behind the eye.
  const std::vector<Vec4> behind = {s.clip(Vec3(-1, -1, 1)), s.clip(Vec3(1, -1, 1)), s.clip(Vec3(0, 1, 1))};
  RasterStats stats;
  const VisibilityBuffer b = rasterizeCorners(behind, s.width, s.height, {Cull::None, 1}, &stats);
  EXPECT_EQ(std::count(b.face.begin(), b.face.end(), -1), long(b.face.size()));
  EXPECT_EQ(stats.clipped, 1u);
  // Enormous but finite: a screen-covering triangle, clipped by the guard band, covers every pixel.
  const std::vector<Vec4> huge = {Vec4(-1e30, -1e30, 0, 1), Vec4(1e30, -1e30, 0, 1), Vec4(0, 1e30, 0, 1)};
  const VisibilityBuffer h = rasterizeCorners(huge, s.width, s.height, {Cull::None, 1});
  EXPECT_EQ(std::count(h.face.begin(), h.face.end(), 0), long(h.face.size()));
  // Non-finite corners are dropped.
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<Vec4> bad = {Vec4(0, 0, 0, 1), Vec4(inf, 0, 0, 1), Vec4(0, 1, 0, 1)};
  const VisibilityBuffer n = rasterizeCorners(bad, s.width, s.height, {Cull::None, 1});
  EXPECT_EQ(std::count(n.face.begin(), n.face.end(), -1), long(n.face.size()));
  EXPECT_THROW(rasterizeCorners(bad, 0, 10, {}), UsageError);
  EXPECT_THROW(rasterizeCorners(bad, 16385, 10, {}), UsageError);
}

TEST(TriangleInterpolator, GivesTheBarycentricsOfThePointWhereThePixelRayMeetsTheTriangle) {
  const GroundScene s;
  const Vec3 a(-3, -1, -2), b(4, -1, -9), c(-1, -1, -20);
  const TriangleInterpolator interpolator(s.clip(a), s.clip(b), s.clip(c), s.width, s.height);
  ASSERT_TRUE(interpolator.valid());
  const double x = 30.5, y = 10.5;
  const Vec3 hit = *s.groundHit(x, y);
  // Barycentrics of the hit point in the xz plane, solved directly.
  Eigen::Matrix2d m;
  m << a.x() - c.x(), b.x() - c.x(), a.z() - c.z(), b.z() - c.z();
  const Eigen::Vector2d l = m.inverse() * Eigen::Vector2d(hit.x() - c.x(), hit.z() - c.z());
  const TriangleInterpolator::Barycentrics r = interpolator.at(x, y);
  EXPECT_LT((r.b - Vec3(l[0], l[1], 1 - l[0] - l[1])).norm(), 1e-12);
  // Analytic derivatives against central differences of the same closed form.
  const double h = 1e-5;
  const Vec3 dx = (interpolator.at(x + h, y).b - interpolator.at(x - h, y).b) / (2 * h);
  const Vec3 dy = (interpolator.at(x, y + h).b - interpolator.at(x, y - h).b) / (2 * h);
  EXPECT_LT((r.dbdx - dx).norm(), 1e-8);
  EXPECT_LT((r.dbdy - dy).norm(), 1e-8);
  // A triangle seen edge-on (its plane passes through the eye) is not valid.
  EXPECT_FALSE(TriangleInterpolator(s.clip(Vec3(0, 0, -1)), s.clip(Vec3(0, 1, -2)), s.clip(Vec3(0, -1, -3)), s.width,
                                    s.height)
                   .valid());
}

TEST(Inverse3x3, IsBitForBitEigensInverse) {
  // Hand-computed: a diagonal scale and shear whose inverse is exact.
  Mat3 m;
  m << 2, 0, 4,  //
      0, 4, 0,   //
      0, 0, 0.5;
  Mat3 expected;
  expected << 0.5, 0, -4,  //
      0, 0.25, 0,          //
      0, 0, 2;
  EXPECT_EQ(inverse3x3(m), expected);
  // Clip-space corners as the rasterizer meets them: every scale, signs, near-singular ones.
  std::mt19937_64 random(26);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 30);
  int compared = 0;
  for (int n = 0; n < 200000; ++n) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m(i, j) = std::ldexp(unit(random), exponent(random) * (n % 2));
    if (n % 7 == 0) m.col(2) = m.col(0) * 3.0 + m.col(1) * std::ldexp(unit(random), -40);  // nearly singular
    if (!(m.determinant() != 0.0)) continue;
    const Mat3 ours = inverse3x3(m), eigen = m.inverse();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double a = ours(i, j), b = eigen(i, j);
        ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0) << n << " (" << i << ", " << j << "): " << a << " vs " << b;
      }
    ++compared;
  }
  EXPECT_GT(compared, 190000);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::render
