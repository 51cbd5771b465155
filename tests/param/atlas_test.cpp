// The projector atlas (param/atlas.h): hand-computed layouts, and on meshes of every kind a
// recount written apart from the production code: no two UV triangles of the mesh overlap, every
// face keeps its winding, the charts stay within [0, 1]^2 with the gutter met, and the measured
// gutter and seams are what a brute-force count gives.
#include "param/atlas.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.h"
#include "param/projector.h"
#include "param/atlas_meshes.h"

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
double signedArea(const Vec2& a, const Vec2& b, const Vec2& c) { return 0.5 * cross2(b - a, c - a); }

// Whether p lies strictly inside the counter-clockwise triangle (a, b, c), by barycentric signs.
bool strictlyInside(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  const double area = signedArea(a, b, c), tol = 1e-9 * area;
  return signedArea(p, b, c) > tol && signedArea(a, p, c) > tol && signedArea(a, b, p) > tol;
}

// Whether two segments cross at a point inside both (not at an end, not along a shared line).
bool properlyCross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double scale = std::max({(b - a).squaredNorm(), (d - c).squaredNorm()}) * 1e-9;
  const double d1 = cross2(b - a, c - a), d2 = cross2(b - a, d - a), d3 = cross2(d - c, a - c), d4 = cross2(d - c, b - c);
  return ((d1 > scale && d2 < -scale) || (d1 < -scale && d2 > scale)) &&
         ((d3 > scale && d4 < -scale) || (d3 < -scale && d4 > scale));
}

double pointSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double t = ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

struct Recount {
  std::size_t overlappingPairs = 0, clockwiseFaces = 0;
  double smallestGutter = std::numeric_limits<double>::infinity();  // between faces of two charts, texels
  double smallestBorder = std::numeric_limits<double>::infinity();  // from a corner to the texture's border, texels
};

// All pairs of faces: O(F^2), for meshes of a few thousand faces.
Recount recount(const Mesh& mesh, const Atlas& atlas, const std::array<int, 2>& texture) {
  Recount r;
  const std::size_t n = mesh.faceCount();
  std::vector<std::array<Vec2, 3>> t(n);
  std::vector<Eigen::AlignedBox2d> box(n);
  for (std::size_t f = 0; f < n; ++f)
    for (int k = 0; k < 3; ++k) {
      t[f][k] = atlas.uv[3 * f + k].cwiseProduct(Vec2(texture[0], texture[1]));  // in texels
      box[f].extend(t[f][k]);
    }
  const auto area = [&](std::size_t f) { return signedArea(t[f][0], t[f][1], t[f][2]); };
  for (std::size_t f = 0; f < n; ++f)
    for (const Vec2& p : t[f])
      r.smallestBorder = std::min({r.smallestBorder, p.x(), p.y(), texture[0] - p.x(), texture[1] - p.y()});
  for (std::size_t f = 0; f < n; ++f) {
    if (area(f) < 0) ++r.clockwiseFaces;
    for (std::size_t g = f + 1; g < n; ++g) {
      const bool otherChart = atlas.chartOfFace[f] != atlas.chartOfFace[g];
      if (otherChart) {
        if (box[f].exteriorDistance(box[g]) < r.smallestGutter)
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
              r.smallestGutter = std::min(r.smallestGutter, pointSegment(t[f][i], t[g][j], t[g][(j + 1) % 3]));
              r.smallestGutter = std::min(r.smallestGutter, pointSegment(t[g][j], t[f][i], t[f][(i + 1) % 3]));
            }
      }
      if (!box[f].intersects(box[g]) || area(f) <= 1e-9 || area(g) <= 1e-9) continue;
      bool overlap = strictlyInside((t[f][0] + t[f][1] + t[f][2]) / 3, t[g][0], t[g][1], t[g][2]) ||
                     strictlyInside((t[g][0] + t[g][1] + t[g][2]) / 3, t[f][0], t[f][1], t[f][2]);
      for (int i = 0; i < 3 && !overlap; ++i)
        for (int j = 0; j < 3 && !overlap; ++j)
          overlap = properlyCross(t[f][i], t[f][(i + 1) % 3], t[g][j], t[g][(j + 1) % 3]);
      if (overlap) ++r.overlappingPairs;
    }
  }
  return r;
}

TEST(Atlas, AFlatSquareIsOneChartFillingTheTextureLessItsMargins) {
  Mesh square;
  square.positions = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Atlas a = makeAtlas(square, AtlasOptions{});
  ASSERT_EQ(a.charts.size(), 1u);
  // 1024 texels less a margin of 4 on each side: 1016 texels for 2 units.
  EXPECT_NEAR(a.texelsPerUnit, 508.0, 508.0 * 1e-6);
  EXPECT_NEAR(a.occupancy, (1016.0 / 1024) * (1016.0 / 1024), 1e-5);
  for (const Vec2& uv : a.uv) {
    EXPECT_TRUE(std::abs(uv.x() - 4.0 / 1024) < 1e-5 || std::abs(uv.x() - 1020.0 / 1024) < 1e-5) << uv.transpose();
    EXPECT_TRUE(std::abs(uv.y() - 4.0 / 1024) < 1e-5 || std::abs(uv.y() - 1020.0 / 1024) < 1e-5) << uv.transpose();
  }
  EXPECT_GT(signedArea(a.uv[0], a.uv[1], a.uv[2]), 0.0);
  EXPECT_EQ(a.seamEdges, 0u);
}

TEST(Atlas, ACubeIsSixSquaresOfOneDensityWithItsTwelveEdgesAsSeams) {
  Mesh cube = meshes::cube(1);
  const Atlas a = makeAtlas(cube, AtlasOptions{});
  ASSERT_EQ(a.charts.size(), 6u);
  EXPECT_EQ(a.directions, 6u);
  for (const AtlasChart& chart : a.charts) {
    EXPECT_EQ(chart.faces, cube.faceCount() / 6);
    // Each chart's map scales object lengths by the density in texels: its rows have norm D / W.
    EXPECT_NEAR(chart.linear.row(0).norm(), a.texelsPerUnit / 1024, 1e-12);
    EXPECT_NEAR(chart.linear.row(1).norm(), a.texelsPerUnit / 1024, 1e-12);
    EXPECT_NEAR(chart.linear.row(0).dot(chart.linear.row(1)), 0.0, 1e-12);
  }
  Eigen::AlignedBox3d box;
  for (const Vec3& p : cube.positions) box.extend(p);
  EXPECT_EQ(a.seamEdges, 12u);  // cube(1): each edge of the cube is one mesh edge
  EXPECT_NEAR(a.seamLength, 12 * box.sizes().x(), 1e-9);
  const Recount r = recount(cube, a, {1024, 1024});
  EXPECT_EQ(r.overlappingPairs, 0u);
  EXPECT_EQ(r.clockwiseFaces, 0u);
  EXPECT_GE(r.smallestGutter, 4.0 - 1e-6);
}

TEST(Atlas, ARampThatCoversItselfIsSplitIntoChartsThatDoNot) {
  const Mesh ramp = test::spiralRamp(3, 32, 0.5, 1.5, 0.2);
  const Atlas a = makeAtlas(ramp, AtlasOptions{});
  EXPECT_GT(a.splitCharts, 0u);
  EXPECT_GE(a.charts.size(), 3u);  // each turn covers the one below
  const Recount r = recount(ramp, a, {1024, 1024});
  EXPECT_EQ(r.overlappingPairs, 0u);
  EXPECT_EQ(r.clockwiseFaces, 0u);
}

// Every edge (its vertices, lower first) with the faces that have it.
std::map<std::pair<int, int>, std::vector<int>> facesOfEdges(const Mesh& mesh) {
  std::map<std::pair<int, int>, std::vector<int>> faces;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int u = mesh.triangles[f][k], v = mesh.triangles[f][(k + 1) % 3];
      faces[{std::min(u, v), std::max(u, v)}].push_back(int(f));
    }
  return faces;
}

// Whether each chart's faces are joined across shared edges: a chart is one piece.
bool everyChartIsOnePiece(const Mesh& mesh, const Atlas& atlas) {
  std::vector<std::vector<int>> neighbours(mesh.faceCount());
  for (const auto& [edge, faces] : facesOfEdges(mesh))
    for (const int f : faces)
      for (const int g : faces)
        if (f != g && atlas.chartOfFace[f] == atlas.chartOfFace[g]) neighbours[f].push_back(g);
  std::vector<char> reached(mesh.faceCount(), 0), chartSeen(atlas.charts.size(), 0);
  for (std::size_t seed = 0; seed < mesh.faceCount(); ++seed) {
    if (reached[seed]) continue;
    if (chartSeen[atlas.chartOfFace[seed]]) return false;  // a second piece of a chart already met
    chartSeen[atlas.chartOfFace[seed]] = 1;
    std::vector<int> queue{int(seed)};
    reached[seed] = 1;
    for (std::size_t i = 0; i < queue.size(); ++i)
      for (const int g : neighbours[queue[i]])
        if (!reached[g]) reached[g] = 1, queue.push_back(g);
  }
  return true;
}

TEST(Atlas, AStripTooLongForTheTextureIsCutIntoTheFewestPiecesThatFit) {
  // 5 x 1 in 15 x 3 quads. Whole, 5 D + 4 <= 1020 texels: D = 203.2. The charts' area allows
  // D0 = 1020 / sqrt(5) = 456.2, at which the strip is 2281 texels long, more than the 1016 a
  // side holds, and 456 wide, at most half of it: it is cut into ceil(5 / (1016 / 456.2)) = 3 slabs
  // of five columns. Stacked, three 5/3 x 1 pieces fit at 3 (D + 4) <= 1020: D = 336.
  const Mesh strip = meshes::planeGrid(15, 3, 5.0, 1.0);
  const Atlas a = makeAtlas(strip, AtlasOptions{});
  ASSERT_EQ(a.charts.size(), 3u);
  EXPECT_EQ(a.cutCharts, 2u);
  for (const AtlasChart& chart : a.charts) EXPECT_EQ(chart.faces, 30u);
  EXPECT_GE(a.texelsPerUnit, 336.0 * (1 - 1e-3));
  EXPECT_LE(a.texelsPerUnit, 1020.0 / std::sqrt(5.0));
  EXPECT_EQ(a.seamEdges, 6u);  // two cuts across three quads each
  EXPECT_NEAR(a.seamLength, 2.0, 1e-12);
  const auto slabOf = [&](std::size_t f) {  // five whole columns each: by the centroid's x in [0, 5]
    const Triangle& t = strip.triangles[f];
    const double x = (strip.positions[t[0]].x() + strip.positions[t[1]].x() + strip.positions[t[2]].x()) / 3 + 2.5;
    return int(x / (5.0 / 3));
  };
  for (std::size_t f = 0; f < strip.faceCount(); ++f)
    for (std::size_t g = 0; g < strip.faceCount(); ++g) EXPECT_EQ(a.chartOfFace[f] == a.chartOfFace[g], slabOf(f) == slabOf(g));
  const Recount r = recount(strip, a, {1024, 1024});
  EXPECT_EQ(r.overlappingPairs, 0u);
  EXPECT_EQ(r.clockwiseFaces, 0u);
  EXPECT_GE(r.smallestGutter, 4.0 - 1e-6);
}

TEST(Atlas, AStripWhosePiecesWouldPackNoDenserStaysWhole) {
  // 6 x 0.7 on a 32 x 32 texture with 7 texels of margin: 25 texels a side, 18 for a chart. At
  // the area's D0 = 25 / sqrt(4.2) = 12.2 the strip is 73 texels long and 8.5 wide (at most 9): a
  // candidate, cut into 5 slabs of 1.2 x 0.7. But five boxes of (1.2 D + 7) x (0.7 D + 7) fit 25 x 25
  // only below D = 3, and whole it fits at 6 D + 7 <= 25: D = 3 exactly.
  AtlasOptions o;
  o.textureSize = {32, 32};
  o.marginTexels = 7;
  const Atlas a = makeAtlas(meshes::planeGrid(30, 3, 6.0, 0.7), o);
  EXPECT_EQ(a.charts.size(), 1u);
  EXPECT_EQ(a.cutCharts, 0u);
  EXPECT_NEAR(a.texelsPerUnit, 3.0, 1e-9);
}

// A flat ring in z = 0 between radii r0 and r1, `segments` quads around, facing +z.
Mesh flatRing(int segments, double r0, double r1) {
  Mesh ring;
  for (int i = 0; i < segments; ++i) {
    const double a = 2 * M_PI * i / segments;
    ring.positions.push_back({r0 * std::cos(a), r0 * std::sin(a), 0.0});
    ring.positions.push_back({r1 * std::cos(a), r1 * std::sin(a), 0.0});
  }
  for (int i = 0; i < segments; ++i) {
    const int a = 2 * i, b = 2 * ((i + 1) % segments);
    ring.triangles.push_back({a, b, b + 1});
    ring.triangles.push_back({a, b + 1, a + 1});
  }
  return ring;
}

TEST(Atlas, AThinRingIsCutIntoArcsThatPackDenser) {
  // Radii 1 and 1.05: its faces cover pi (1.05^2 - 1) / 2.1^2 = 0.073 of its box, under a fifth, so
  // it is halved, and its halves again. Whole, its box is at least 2.1 cos(pi / 256) across: at
  // most 1016 / that texels a unit.
  const Mesh ring = flatRing(256, 1.0, 1.05);
  const Atlas a = makeAtlas(ring, AtlasOptions{});
  const double whole = 1016.0 / (2.1 * std::cos(M_PI / 256));
  EXPECT_GT(a.cutCharts, 0u);
  EXPECT_GE(a.texelsPerUnit, 1.25 * whole);
  EXPECT_LE(a.charts.size(), 64u);  // six halvings at most
  EXPECT_TRUE(everyChartIsOnePiece(ring, a));
  const Recount r = recount(ring, a, {1024, 1024});
  EXPECT_EQ(r.overlappingPairs, 0u);
  EXPECT_EQ(r.clockwiseFaces, 0u);
  EXPECT_GE(r.smallestGutter, 4.0 - 1e-6);
  // Radii 1 and 1.5 cover pi (1.5^2 - 1) / 9 = 0.44 of the box: not hollow, one chart.
  const Atlas thick = makeAtlas(flatRing(256, 1.0, 1.5), AtlasOptions{});
  EXPECT_EQ(thick.charts.size(), 1u);
  EXPECT_EQ(thick.cutCharts, 0u);
}

TEST(Atlas, ATubeMuchLongerThanWideIsCutAcrossItsLengthIntoConnectedPieces) {
  // 80 long, 0.03 in radius, open: whole, each of its strips must span the texture, at most
  // 1016 / 80 = 12.7 texels a unit.
  const Mesh tube = meshes::cylinder(8, 200, 0.03, 80.0, false);
  const Atlas a = makeAtlas(tube, AtlasOptions{});
  EXPECT_GT(a.cutCharts, 0u);
  EXPECT_GT(a.texelsPerUnit, 8 * 1016.0 / 80);
  EXPECT_GT(a.occupancy, 0.3);
  EXPECT_TRUE(everyChartIsOnePiece(tube, a));
  for (std::size_t f = 0; f < tube.faceCount(); ++f) {  // the pieces keep their chart's direction
    const Triangle& t = tube.triangles[f];
    const Vec3 n = (tube.positions[t[1]] - tube.positions[t[0]]).cross(tube.positions[t[2]] - tube.positions[t[0]]).normalized();
    EXPECT_GE(n.dot(a.charts[a.chartOfFace[f]].direction), std::cos(66.0 * M_PI / 180) - 1e-12) << f;
  }
  const Recount r = recount(tube, a, {1024, 1024});
  EXPECT_EQ(r.overlappingPairs, 0u);
  EXPECT_EQ(r.clockwiseFaces, 0u);
  EXPECT_GE(r.smallestGutter, 4.0 - 1e-6);
  EXPECT_GE(r.smallestBorder, 4.0 - 1e-6);
}

TEST(Atlas, AMeshScaledByAPowerOfTwoGetsTheSameChartsAndUvsFrom1eMinus298To1e298) {
  // The atlas works on the mesh scaled to a unit size by a power of two, exactly: the bone (cut
  // into 10 charts at scale 1) gives the same bits at any scale where its coordinates stay normal
  // doubles. Before, its areas squared to 0 or infinity beyond about 1e+-150: every face a chart.
  const Mesh bone = meshes::bone(120, 32);
  const Atlas one = makeAtlas(bone, AtlasOptions{});
  ASSERT_GT(one.cutCharts, 0u);
  for (const int exponent : {-990, -500, -120, 120, 500, 990}) {
    SCOPED_TRACE(exponent);
    Mesh scaled = bone;
    for (Vec3& p : scaled.positions) p *= std::ldexp(1.0, exponent);
    const Atlas a = makeAtlas(scaled, AtlasOptions{});
    ASSERT_EQ(a.charts.size(), one.charts.size());
    EXPECT_EQ(a.chartOfFace, one.chartOfFace);
    EXPECT_EQ(a.uv, one.uv);
    EXPECT_EQ(a.texelsPerUnit, std::ldexp(one.texelsPerUnit, -exponent));
    EXPECT_NEAR(a.seamLength / std::ldexp(one.seamLength, exponent), 1.0, 1e-14);
    EXPECT_EQ(a.occupancy, one.occupancy);
  }
}

TEST(Atlas, OnMeshesOfEveryKindNothingOverlapsNothingMirrorsAndTheGutterIsMet) {
  for (const test::NamedMesh& named : test::atlasMeshes()) {
    if (named.mesh.faceCount() > 12000) continue;  // the recount is quadratic
    SCOPED_TRACE(named.name);
    for (const std::array<int, 2> texture : {std::array<int, 2>{1024, 1024}, std::array<int, 2>{2048, 512}}) {
      AtlasOptions o;
      o.textureSize = texture;
      const Atlas a = makeAtlas(named.mesh, o);
      const Recount r = recount(named.mesh, a, texture);
      EXPECT_EQ(r.overlappingPairs, 0u);
      if (a.degenerateFaces == 0) {
        EXPECT_EQ(r.clockwiseFaces, 0u);
      }
      EXPECT_GE(r.smallestGutter, o.marginTexels - 1e-6);
      EXPECT_GE(r.smallestBorder, o.marginTexels - 1e-6);
      for (const Vec2& uv : a.uv) {
        ASSERT_TRUE(uv.allFinite());
        EXPECT_GE(uv.minCoeff(), 0.0);
        EXPECT_LE(uv.maxCoeff(), 1.0);
      }
      // Square texels: a chart's map has the same scale along u and v once counted in texels.
      for (const AtlasChart& chart : a.charts) {
        const double su = chart.linear.row(0).norm() * texture[0], sv = chart.linear.row(1).norm() * texture[1];
        EXPECT_NEAR(su, a.texelsPerUnit, 1e-9 * a.texelsPerUnit);
        EXPECT_NEAR(sv, a.texelsPerUnit, 1e-9 * a.texelsPerUnit);
      }
    }
  }
}

TEST(Atlas, EveryFaceIsWithinTheAngleLimitOfItsChartsDirection) {
  const Mesh blob = meshes::bumpyBlob(3);
  for (const double limit : {30.0, 66.0, 85.0}) {
    AtlasOptions o;
    o.angleLimitDegrees = limit;
    const Atlas a = makeAtlas(blob, o);
    for (std::size_t f = 0; f < blob.faceCount(); ++f) {
      const Triangle& t = blob.triangles[f];
      const Vec3 n = (blob.positions[t[1]] - blob.positions[t[0]]).cross(blob.positions[t[2]] - blob.positions[t[0]]).normalized();
      EXPECT_GE(n.dot(a.charts[a.chartOfFace[f]].direction), std::cos(limit * M_PI / 180) - 1e-12) << f;
    }
    EXPECT_NEAR(a.stretchBound, 1.0 / std::cos(limit * M_PI / 180), 1e-12);
  }
}

TEST(Atlas, SeamsAreTheEdgesBetweenCharts) {
  const Mesh torus = meshes::torus(32, 16, 1.0, 0.4);
  const Atlas a = makeAtlas(torus, AtlasOptions{});
  const std::map<std::pair<int, int>, std::vector<int>> faces = facesOfEdges(torus);
  std::size_t seams = 0;
  double length = 0.0;
  for (const auto& [edge, list] : faces) {
    ASSERT_EQ(list.size(), 2u);
    if (a.chartOfFace[list[0]] == a.chartOfFace[list[1]]) continue;
    ++seams;
    length += (torus.positions[edge.first] - torus.positions[edge.second]).norm();
  }
  EXPECT_EQ(a.seamEdges, seams);
  EXPECT_NEAR(a.seamLength, length, 1e-9 * length);
}

TEST(Atlas, AFixedDensityGoesOnToFurtherTilesInUdimOrder) {
  Mesh bone = meshes::cube(4);
  Eigen::AlignedBox3d box;
  for (const Vec3& p : bone.positions) box.extend(p);
  const double side = box.sizes().x();
  AtlasOptions o;
  o.texelsPerUnit = 800.0 / side;  // a face of the cube: 800 x 800 texels, one to a 1024^2 tile
  const Atlas a = makeAtlas(bone, o);
  EXPECT_DOUBLE_EQ(a.texelsPerUnit, 800.0 / side);
  ASSERT_EQ(a.tiles, 6);
  for (std::size_t f = 0; f < bone.faceCount(); ++f) {
    const int tile = a.charts[a.chartOfFace[f]].tile;
    for (int k = 0; k < 3; ++k) {
      const Vec2 uv = a.uv[3 * f + k];
      EXPECT_GE(uv.x(), tile % 10);
      EXPECT_LE(uv.x(), tile % 10 + 1);
      EXPECT_GE(uv.y(), tile / 10);
      EXPECT_LE(uv.y(), tile / 10 + 1);
    }
  }
  o.texelsPerUnit = 1e6;  // one chart alone exceeds a texture
  EXPECT_THROW(makeAtlas(bone, o), UsageError);
}

TEST(Atlas, MoreChartsThanMarginsFitIsAUsageError) {
  AtlasOptions o;
  o.textureSize = {64, 64};
  o.marginTexels = 16;
  EXPECT_THROW(makeAtlas(test::manyComponents(30), o), UsageError);
}

TEST(Atlas, ValuesNoTypeRulesOutAreRefused) {
  const Mesh cube = meshes::cube(1);
  for (const double angle : {0.0, 90.0, -5.0, std::nan("")}) {
    AtlasOptions o;
    o.angleLimitDegrees = angle;
    EXPECT_THROW(makeAtlas(cube, o), UsageError) << angle;
  }
  AtlasOptions o;
  o.marginTexels = 600;  // two margins fill a 1024 texture
  EXPECT_THROW(makeAtlas(cube, o), UsageError);
  o = AtlasOptions{};
  o.texelsPerUnit = 0.0;
  EXPECT_THROW(makeAtlas(cube, o), UsageError);
}

TEST(Atlas, TheSameBitsWhateverTheThreads) {
  ProjectorOptions o;
  o.surface = SurfaceKind::Atlas;
  const Mesh knot = meshes::torusKnot(2, 3, 200, 12);
  const Projection one = project(knot, o, 1), two = project(knot, o, 2), eight = project(knot, o, 8);
  EXPECT_EQ(one.uv.uv, two.uv.uv);
  EXPECT_EQ(one.uv.uv, eight.uv.uv);
}

TEST(Atlas, AProjectorOfAPointAloneIsRefused) {
  ProjectorOptions o;
  o.surface = SurfaceKind::Atlas;
  EXPECT_THROW(Projector(o, Affine3::Identity()), UsageError);
  std::vector<VertexUv> out;
  EXPECT_THROW(Projector(o, Affine3::Identity()).mapVertices({Vec3::Zero()}, {}, out), UsageError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param
