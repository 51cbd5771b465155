// The texels of a layout (analysis/texel_layout.h) against a brute-force recount written apart
// from it: every texel centre tested against every face (closed triangles: a centre on an edge of
// one chart counts once anyway), a level's texels as the union of its whole block of level-0
// texels (not level by level), the conservative count by clipping each triangle to each texel,
// and the gutter by every pair of edges.
#include "analysis/texel_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.h"
#include "layout.h"
#include "meshes/generators.h"
#include "param/projector.h"

namespace uvtk::analysis {
namespace {
namespace UVTK_TEST_FILE {

// Axis-aligned squares of texels (x, y, side) in a W x H texture, two triangles each, each its own chart.
Layout squares(const std::vector<std::array<double, 3>>& list, int width, int height) {
  Layout l;
  for (const auto& [x, y, side] : list) {
    const int base = int(l.mesh.positions.size());
    const Vec2 corners[4] = {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
    for (const Vec2& c : corners) l.mesh.positions.emplace_back(c.x(), c.y(), 0.0);
    for (const Triangle& t : {Triangle{base, base + 1, base + 2}, Triangle{base, base + 2, base + 3}}) {
      l.mesh.triangles.push_back(t);
      for (int k = 0; k < 3; ++k) l.uv.uv.push_back(corners[t[k] - base].cwiseQuotient(Vec2(width, height)));
      l.uv.faceFlags.push_back(kFaceOk);
    }
  }
  l.uv.cornerInvalid.assign(l.uv.uv.size(), kCornerValid);
  return l;
}

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

bool insideClosed(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  const double d1 = cross(b - a, p - a), d2 = cross(c - b, p - b), d3 = cross(a - c, p - c);
  return (d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0);
}

// The area of a triangle clipped to a square (Sutherland-Hodgman).
double clippedArea(std::vector<Vec2> poly, double x0, double y0, double x1, double y1) {
  const auto clip = [&](auto inside, auto cut) {
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec2 &p = poly[i], &q = poly[(i + 1) % poly.size()];
      if (inside(p)) out.push_back(p);
      if (inside(p) != inside(q)) out.push_back(cut(p, q));
    }
    poly = out;
  };
  const auto atX = [](double x) { return [x](const Vec2& p, const Vec2& q) { return Vec2(p + (q - p) * ((x - p.x()) / (q.x() - p.x()))); }; };
  const auto atY = [](double y) { return [y](const Vec2& p, const Vec2& q) { return Vec2(p + (q - p) * ((y - p.y()) / (q.y() - p.y()))); }; };
  clip([&](const Vec2& p) { return p.x() >= x0; }, atX(x0));
  clip([&](const Vec2& p) { return p.x() <= x1; }, atX(x1));
  clip([&](const Vec2& p) { return p.y() >= y0; }, atY(y0));
  clip([&](const Vec2& p) { return p.y() <= y1; }, atY(y1));
  double area = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) area += cross(poly[i], poly[(i + 1) % poly.size()]);
  return std::abs(area) / 2;
}

struct Brute {
  std::vector<TexelLevel> levels;
  double gutter = std::numeric_limits<double>::infinity();
};

Brute bruteForce(const Mesh& mesh, const UvMap& uv, const std::vector<int>& chart, int width, int height) {
  Brute b;
  const std::size_t n = mesh.faceCount();
  std::vector<std::array<Vec2, 3>> t(n);
  for (std::size_t f = 0; f < n; ++f)
    for (int k = 0; k < 3; ++k) t[f][k] = uv.uv[3 * f + k].cwiseProduct(Vec2(width, height));
  std::vector<std::set<int>> base(std::size_t(width * height));
  std::size_t conservative = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      bool met = false;
      for (std::size_t f = 0; f < n; ++f) {
        if (insideClosed(Vec2(x + 0.5, y + 0.5), t[f][0], t[f][1], t[f][2])) base[std::size_t(y * width + x)].insert(chart[f]);
        met = met || clippedArea({t[f][0], t[f][1], t[f][2]}, x, y, x + 1, y + 1) > 1e-12;
      }
      conservative += met;
    }
  for (int level = 0;; ++level) {
    const int w = std::max(1, width >> level), h = std::max(1, height >> level), block = 1 << level;
    std::vector<std::set<int>> held(std::size_t(w * h));
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int by = y * block; by < std::min(height, (y + 1) * block); ++by)
          for (int bx = x * block; bx < std::min(width, (x + 1) * block); ++bx)
            held[std::size_t(y * w + x)].insert(base[std::size_t(by * width + bx)].begin(), base[std::size_t(by * width + bx)].end());
    TexelLevel l;
    l.level = level, l.width = w, l.height = h;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::set<int>& own = held[std::size_t(y * w + x)];
        l.mapped += !own.empty();
        l.overwritten += own.size() >= 2;
        std::set<int> around = own;
        bool near = false;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            if (x + dx < 0 || y + dy < 0 || x + dx >= w || y + dy >= h) continue;
            const std::set<int>& other = held[std::size_t((y + dy) * w + x + dx)];
            near = near || !other.empty();
            around.insert(other.begin(), other.end());
          }
        l.touched += near;
        l.clashes += own.size() >= 2 || (own.size() == 1 && around.size() >= 2);
      }
    l.mappedConservative = level == 0 ? conservative : l.mapped;
    b.levels.push_back(l);
    if (w == 1 && h == 1) break;
  }
  const auto pointSegment = [](const Vec2& p, const Vec2& a, const Vec2& c) {
    const Vec2 ac = c - a;
    const double s = std::clamp((p - a).dot(ac) / ac.squaredNorm(), 0.0, 1.0);
    return (p - (a + s * ac)).norm();
  };
  for (std::size_t f = 0; f < n; ++f)
    for (std::size_t g = 0; g < n; ++g)
      if (chart[f] < chart[g])
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            b.gutter = std::min({b.gutter, pointSegment(t[f][i], t[g][j], t[g][(j + 1) % 3]),
                                 pointSegment(t[g][j], t[f][i], t[f][(i + 1) % 3])});
  return b;
}

void expectSame(const TexelStatistics& s, const Brute& b) {
  ASSERT_EQ(s.levels.size(), b.levels.size());
  for (std::size_t i = 0; i < b.levels.size(); ++i) {
    SCOPED_TRACE("level " + std::to_string(i));
    const TexelLevel &x = s.levels[i], &y = b.levels[i];
    EXPECT_EQ(x.width, y.width);
    EXPECT_EQ(x.height, y.height);
    EXPECT_EQ(x.mapped, y.mapped);
    EXPECT_EQ(x.mappedConservative, y.mappedConservative);
    EXPECT_EQ(x.touched, y.touched);
    EXPECT_EQ(x.overwritten, y.overwritten);
    EXPECT_EQ(x.clashes, y.clashes);
  }
  if (std::isfinite(b.gutter)) {
    EXPECT_NEAR(s.gutters.betweenCharts, b.gutter, 1e-9 * (1 + b.gutter));
  }
}

TEST(TexelLayout, TwoSquaresBleedAtTheLevelWhereTheirGutterCloses) {
  // Two 8-texel squares d texels apart at 64^2: they first mix at the level where a texel spans the gap.
  for (const auto& [gap, firstBleed] : {std::pair{0, 0}, {1, 1}, {2, 2}, {8, 4}}) {
    SCOPED_TRACE("gap " + std::to_string(gap));
    const Layout l = squares({{8, 8, 8}, {16.0 + gap, 8, 8}}, 64, 64);
    const TexelStatistics s = texelStatistics(l.mesh, l.uv, 64, 64);
    EXPECT_EQ(s.charts, 2u);
    EXPECT_EQ(s.levels.size(), 7u);  // 64, 32, ..., 1
    EXPECT_EQ(s.levels[0].mapped, 128u);
    EXPECT_EQ(s.levels[0].mappedConservative, 128u);
    EXPECT_NEAR(s.gutters.betweenCharts, gap, 1e-12);
    EXPECT_NEAR(s.levels[2].gutterTexels, gap / 4.0, 1e-12);
    EXPECT_NEAR(s.gutters.toBorder, 8.0, 1e-12);
    ASSERT_TRUE(s.firstBleedLevel);
    EXPECT_EQ(*s.firstBleedLevel, firstBleed);
    expectSame(s, bruteForce(l.mesh, l.uv, uvCharts(l.mesh, l.uv), 64, 64));
  }
}

TEST(TexelLayout, AChartOnTheBorderHasNoBorderGutterAndOneChartNeverBleeds) {
  const Layout l = squares({{0, 0, 10.25}}, 32, 16);
  const TexelStatistics s = texelStatistics(l.mesh, l.uv, 32, 16);
  EXPECT_EQ(s.charts, 1u);
  EXPECT_EQ(s.gutters.toBorder, 0.0);
  EXPECT_TRUE(std::isinf(s.gutters.betweenCharts));
  EXPECT_FALSE(s.firstBleedLevel);
  EXPECT_EQ(s.levels[0].mapped, 100u);              // centres 0.5 .. 9.5 in x and y
  EXPECT_EQ(s.levels[0].mappedConservative, 121u);  // squares 0 .. 10 meet [0, 10.25]
  EXPECT_EQ(s.levels.back().width, 1);
  expectSame(s, bruteForce(l.mesh, l.uv, uvCharts(l.mesh, l.uv), 32, 16));
}

TEST(TexelLayout, GeneratedMeshesUnderTheAtlasAndASphereAgreeWithTheRecount) {
  for (const param::SurfaceKind surface : {param::SurfaceKind::Atlas, param::SurfaceKind::Sphere}) {
    param::ProjectorOptions o;
    o.surface = surface;
    o.atlas.textureSize = {96, 64};
    o.atlas.marginTexels = 2;
    const param::Projection p = param::project(meshes::icosphere(2), o);
    const std::vector<int> chart = uvCharts(p.mesh, p.uv);
    const TexelStatistics s = texelStatistics(p.mesh, p.uv, 96, 64);
    SCOPED_TRACE(int(surface));
    expectSame(s, bruteForce(p.mesh, p.uv, chart, 96, 64));
    if (surface == param::SurfaceKind::Atlas) {
      EXPECT_EQ(s.charts, p.atlas->charts.size());  // the atlas's charts are the layout's
      EXPECT_GE(s.gutters.betweenCharts, 2.0 - 1e-9);
      EXPECT_GE(s.gutters.toBorder, 2.0 - 1e-9);
      EXPECT_EQ(s.levels[0].overwritten, 0u);
      EXPECT_EQ(s.levels[0].clashes, 0u);  // two texels apart: no bilinear lookup mixes them at level 0
    }
  }
}

TEST(TexelLayout, ChartsAreFacesJoinedAtEqualUvs) {
  const Layout l = squares({{0, 0, 4}, {4, 0, 4}}, 16, 16);  // touching, but each its own vertices
  EXPECT_EQ(uvCharts(l.mesh, l.uv), (std::vector<int>{0, 0, 1, 1}));
  EXPECT_THROW(texelStatistics(l.mesh, l.uv, 9000, 16), UsageError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::analysis
