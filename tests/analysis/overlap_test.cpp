// The overlap raster's spans against a recount written apart from it: every pixel centre tested on
// its own against the three edge functions and the tie rule overlap.h states.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include "analysis/distortion.h"
#include "analysis/overlap.h"
#include "layout.h"
#include "meshes/generators.h"
#include "param/projector.h"

namespace uvtk::analysis {
namespace {
namespace UVTK_TEST_FILE {

constexpr int kResolution = 16;
constexpr int kSubpixels = 256 * kResolution;  // corners on the 1/256-pixel lattice of a 16-pixel grid over [0, 1]^2

struct Corner {
  std::int64_t x, y;  // in 1/256 pixel
};

// Whether pixel centre c is covered by triangle abc (any winding): each edge's function positive,
// or zero on an edge that owns its centres (made counter-clockwise, running downward in v or
// horizontally towards +u).
bool covers(Corner a, Corner b, Corner c, Corner centre) {
  auto cross = [](Corner p, Corner q, Corner r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); };
  if (cross(a, b, c) == 0) return false;
  if (cross(a, b, c) < 0) std::swap(b, c);
  const Corner corners[3] = {a, b, c};
  for (int e = 0; e < 3; ++e) {
    const Corner p = corners[e], q = corners[(e + 1) % 3];
    const std::int64_t edge = cross(p, q, centre);
    const bool owns = q.y < p.y || (q.y == p.y && q.x > p.x);
    if (edge < 0 || (edge == 0 && !owns)) return false;
  }
  return true;
}

// Random triangles with corners on the lattice, many on pixel centres and shared edges, so that the
// tie rule decides many centres; and a few across the whole grid.
Layout randomLayout(std::mt19937& random, int faces) {
  std::uniform_int_distribution<int> lattice(0, kSubpixels), centre(0, kResolution - 1), pick(0, 3);
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  std::vector<Vec2> uvs;
  auto corner = [&]() {
    const int kind = pick(random);
    const int x = kind == 0 ? centre(random) * 256 + 128 : lattice(random);
    const int y = kind == 1 ? centre(random) * 256 + 128 : lattice(random);
    return Vec2(double(x) / kSubpixels, double(y) / kSubpixels);
  };
  for (int f = 0; f < faces; ++f) {
    Vec2 c[3] = {corner(), corner(), corner()};
    if (f > 0 && pick(random) == 0) c[0] = uvs[uvs.size() - 1], c[1] = uvs[uvs.size() - 2];  // the previous face's edge, reversed
    if (f == 0) c[0] = {0, 0}, c[1] = {1, 0}, c[2] = {0, 1};  // the grid spans [0, 1]^2
    for (const Vec2& uv : c) {
      positions.push_back(Vec3(uv.x(), uv.y(), 0.0));
      uvs.push_back(uv);
    }
    triangles.push_back({3 * f, 3 * f + 1, 3 * f + 2});
  }
  return makeLayout(positions, triangles, uvs);
}

TEST(OverlapSpans, CoverExactlyThePixelCentresATestOfEachCentreFinds) {
  std::mt19937 random(20261202);
  for (int round = 0; round < 40; ++round) {
    const Layout l = randomLayout(random, 2 + round);
    const FaceMeasures faces = measureFaces(l.mesh, l.uv);
    const UvGrid grid = uvGridOver(measuredUvBounds(l.uv, faces), kResolution);
    ASSERT_EQ(grid.bounds.min(), Vec2(0, 0));
    ASSERT_EQ(grid.bounds.max(), Vec2(1, 1));

    std::set<std::tuple<std::size_t, int, int>> expected, found;
    std::vector<int> counts(kResolution * kResolution, 0);
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (!isMeasured(faces[f].status)) continue;
      auto at = [&](int k) {
        const Vec2& uv = l.uv.uv[3 * f + std::size_t(k)];
        return Corner{std::int64_t(uv.x() * kSubpixels), std::int64_t(uv.y() * kSubpixels)};
      };
      for (int y = 0; y < kResolution; ++y)
        for (int x = 0; x < kResolution; ++x)
          if (covers(at(0), at(1), at(2), Corner{x * 256 + 128, y * 256 + 128})) {
            expected.insert({f, x, y});
            ++counts[std::size_t(y * kResolution + x)];
          }
    }
    forEachCoveredPixel(l.uv, faces, grid, [&](std::size_t f, int x, int y) {
      EXPECT_TRUE(found.insert({f, x, y}).second) << "pixel visited twice";
    });
    EXPECT_EQ(found, expected) << "round " << round;

    const std::vector<std::uint8_t> coverage = coverageCounts(l.uv, faces, grid);
    std::size_t covered = 0, overlapped = 0;
    for (std::size_t k = 0; k < counts.size(); ++k) {
      EXPECT_EQ(int(coverage[k]), counts[k]);
      covered += counts[k] >= 1, overlapped += counts[k] >= 2;
    }
    std::set<std::size_t> overlappedFaces;
    for (const auto& [f, x, y] : expected)
      if (counts[std::size_t(y * kResolution + x)] >= 2) overlappedFaces.insert(f);
    const Overlap overlap = measureOverlap(l.uv, faces, kResolution);
    EXPECT_EQ(overlap.coveredPixels, covered);
    EXPECT_EQ(overlap.overlappedPixels, overlapped);
    EXPECT_EQ(overlap.overlappedFaces, overlappedFaces.size());
  }
}

// measureOverlap draws a small mesh in bands of rows (32 at 1024), on one thread or shared out to
// several; its figures are those of the whole grid's coverageCounts, which the test above recounts
// centre by centre.
TEST(OverlapSpans, BandsGiveTheFiguresOfTheWholeGrid) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> anywhere(0.0, 1.0);
  for (int round = 0; round < 6; ++round) {
    std::vector<Vec3> positions;
    std::vector<Triangle> triangles;
    std::vector<Vec2> uvs;
    for (int f = 0; f < 30 + 40 * round; ++f) {
      // Small faces (their UV area keeps the raster at 1024), some across bands of 64 rows.
      const Vec2 first(anywhere(random), anywhere(random));
      for (int k = 0; k < 3; ++k) {
        const Vec2 uv = k == 0 ? first : Vec2(first + Vec2(0.2 * anywhere(random) - 0.1, 0.3 * anywhere(random) - 0.15));
        positions.push_back(Vec3(uv.x(), uv.y(), 0.0));
        uvs.push_back(uv);
      }
      triangles.push_back({3 * f, 3 * f + 1, 3 * f + 2});
    }
    const Layout l = makeLayout(positions, triangles, uvs);
    const FaceMeasures faces = measureFaces(l.mesh, l.uv);
    const UvGrid grid = uvGridOver(measuredUvBounds(l.uv, faces), 1024);
    const std::vector<std::uint8_t> counts = coverageCounts(l.uv, faces, grid);
    std::size_t covered = 0, overlapped = 0;
    for (const std::uint8_t count : counts) covered += count >= 1, overlapped += count >= 2;
    std::set<std::size_t> overlappedFaces;
    forEachCoveredPixel(l.uv, faces, grid, [&](std::size_t f, int x, int y) {
      if (counts[std::size_t(y) * 1024 + std::size_t(x)] >= 2) overlappedFaces.insert(f);
    });
    for (int threads : {1, 2, 5}) {
      const Overlap overlap = measureOverlap(l.uv, faces, 1024, threads);
      ASSERT_EQ(overlap.resolution, 1024);
      EXPECT_EQ(overlap.coveredPixels, covered) << round << ", " << threads << " threads";
      EXPECT_EQ(overlap.overlappedPixels, overlapped) << round << ", " << threads << " threads";
      EXPECT_EQ(overlap.overlappedFaces, overlappedFaces.size()) << round << ", " << threads << " threads";
    }
    EXPECT_GT(overlapped, 0u);
  }
}

// Counts saturate at 255: 300 copies of one triangle over the grid.
TEST(OverlapSpans, CountsSaturateAt255) {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  std::vector<Vec2> uvs;
  for (int f = 0; f < 300; ++f) {
    for (const Vec2& uv : {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}) {
      positions.push_back(Vec3(uv.x(), uv.y(), 0.0));
      uvs.push_back(uv);
    }
    triangles.push_back({3 * f, 3 * f + 1, 3 * f + 2});
  }
  const Layout l = makeLayout(positions, triangles, uvs);
  const FaceMeasures faces = measureFaces(l.mesh, l.uv);
  const std::vector<std::uint8_t> counts =
      coverageCounts(l.uv, faces, UvGrid{Eigen::AlignedBox2d(Vec2(0, 0), Vec2(1, 1)), 4});
  EXPECT_EQ(int(counts[0]), 255);   // centre (1/8, 1/8): inside
  EXPECT_EQ(int(counts[15]), 0);    // centre (7/8, 7/8): outside
  const Overlap overlap = measureOverlap(l.uv, faces, 4);
  // The centres ((x + 1/2) / 4, (y + 1/2) / 4) with x + y < 3: 3 + 2 + 1. Those with x + y = 3 lie on
  // the hypotenuse, which runs upward in v from (1, 0) to (0, 1) and so does not own them.
  EXPECT_EQ(overlap.coveredPixels, 6u);
  EXPECT_EQ(overlap.overlappedPixels, 6u);
  EXPECT_EQ(overlap.overlappedFaces, 300u);
}

// A usual layout keeps the asked resolution; so does a stack of a thousand copies of one triangle (its
// spans cost a step each, not their pixels); five thousand are measured at the largest halving whose
// work fits the budget, and are still wholly overlapped.
TEST(OverlapSpans, AStackOfFacesIsMeasuredAtAResolutionItsFaceCountPays) {
  const Layout tiling = makeLayout({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}},
                                   {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}});
  const Overlap square = measureOverlap(tiling.uv, measureFaces(tiling.mesh, tiling.uv));
  EXPECT_EQ(square.resolution, 1024);
  EXPECT_EQ(square.coveredPixels, 1024u * 1024u);
  EXPECT_EQ(square.overlappedPixels, 0u);

  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  std::vector<Vec2> uvs;
  const int copies = 5000;
  for (int f = 0; f < copies; ++f) {
    for (const Vec2& uv : {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}) {
      positions.push_back(Vec3(uv.x(), uv.y(), 0.0));
      uvs.push_back(uv);
    }
    triangles.push_back({3 * f, 3 * f + 1, 3 * f + 2});
  }
  const Layout stack = makeLayout(positions, triangles, uvs);
  const FaceMeasures measured = measureFaces(stack.mesh, stack.uv);
  // The centres ((x + 1/2) / R, (y + 1/2) / R) with x + y <= R - 2: (R - 1) R / 2 of them (those on
  // the hypotenuse are not the triangle's, as above).
  std::vector<FaceDistortion> thousand;
  for (std::size_t f = 0; f < 1000; ++f) thousand.push_back(measured[f]);
  UvMap firstThousand = stack.uv;
  firstThousand.uv.resize(3000);
  const Overlap o1000 = measureOverlap(firstThousand, thousand);
  EXPECT_EQ(o1000.resolution, 1024);  // work R^2 + 2 (1000 R) + 1000 = 3.1e6 within 2^23 + 256 000
  EXPECT_EQ(o1000.coveredPixels, 1023u * 1024u / 2u);
  EXPECT_EQ(o1000.overlappedPixels, o1000.coveredPixels);
  EXPECT_EQ(o1000.overlappedFaces, 1000u);
  const Overlap o = measureOverlap(stack.uv, measured);
  // 5000: at 1024 the work is 1.1e7 > 2^23 + 1.28e6 = 9.7e6; at 512 5.4e6.
  EXPECT_EQ(o.resolution, 512);
  EXPECT_EQ(o.coveredPixels, 511u * 512u / 2u);
  EXPECT_EQ(o.overlappedPixels, o.coveredPixels);
  EXPECT_EQ(o.overlappedFaces, std::size_t(copies));
}

// By default the judgement's raster follows the mesh: sixteen pixels for the mean face, from the
// faces' count and the share of the layout's box they cover; 256 to 1024 a side.
TEST(OverlapSpans, TheJudgementsRasterFollowsTheMeasuredFacesAndTheirShareOfTheBox) {
  EXPECT_EQ(followingOverlapResolution(0, 0.0), 1024);
  EXPECT_EQ(followingOverlapResolution(2, 1.0), 256);        // sqrt(32), up to the floor
  EXPECT_EQ(followingOverlapResolution(4096, 1.0), 256);     // sqrt(16 x 4096) = 256
  EXPECT_EQ(followingOverlapResolution(4097, 1.0), 256);     // 256.03, rounded
  EXPECT_EQ(followingOverlapResolution(7680, 1.0), 351);     // sqrt(122880) = 350.5
  EXPECT_EQ(followingOverlapResolution(10000, 1.0), 400);
  EXPECT_EQ(followingOverlapResolution(10000, 0.25), 800);   // a quarter of the box: twice as fine
  EXPECT_EQ(followingOverlapResolution(10000, 0.01), 1024);  // at most 1024
  EXPECT_EQ(followingOverlapResolution(65536, 1.0), 1024);

  // On layouts: a 100 x 50 grid of quads fills its box (10,000 faces: 400); the same grid in a
  // quarter of a box that one small far triangle widens: 800; a resolution asked for is kept.
  param::ProjectorOptions o;
  o.surface = param::SurfaceKind::Plane;
  o.placement.fit = param::Fit::None;
  const param::Projection grid = param::project(meshes::planeGrid(100, 50, 1.0, 1.0), o);
  const FaceMeasures faces = measureFaces(grid.mesh, grid.uv);
  EXPECT_EQ(measureOverlap(grid.uv, faces, kOverlapFollowsMesh).resolution, 400);
  EXPECT_EQ(measureOverlap(grid.uv, faces, 8).resolution, 8);
  std::vector<Vec3> positions = grid.mesh.positions;
  std::vector<Triangle> triangles = grid.mesh.triangles;
  std::vector<Vec2> uvs;
  const Vec2 low = measuredUvBounds(grid.uv, faces).min(), size = measuredUvBounds(grid.uv, faces).sizes();
  for (const Vec2& uv : grid.uv.uv) uvs.push_back(low + 0.5 * (uv - low));
  const int n = int(positions.size());
  positions.insert(positions.end(), {{5, 5, 0}, {5.001, 5, 0}, {5, 5.001, 0}});
  triangles.push_back({n, n + 1, n + 2});
  for (const Vec2& corner : {Vec2(0, 0), Vec2(1e-6, 0), Vec2(0, 1e-6)}) uvs.push_back(low + size - Vec2(1e-6, 1e-6) + corner);
  const Layout sparse = makeLayout(positions, triangles, uvs);
  EXPECT_EQ(measureOverlap(sparse.uv, measureFaces(sparse.mesh, sparse.uv), kOverlapFollowsMesh).resolution, 800);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::analysis
