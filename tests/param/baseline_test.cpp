// The reference parametrizations: mesh topology, cutting along UV seams, and CGAL's LSCM and
// ARAP on planar and curved disks and on meshes that are not disks.
#include "param/baseline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "meshes/generators.h"
#include "param/projector.h"

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

constexpr Baseline kBaselines[] = {Baseline::Lscm, Baseline::Arap};

// The upper half (z >= 0) of a lat-long sphere with 2 `stacks`: a curved disk bounded by the equator.
Mesh hemisphere(int longitudes, int stacks) {
  const Mesh sphere = meshes::latLongSphere(longitudes, 2 * stacks);
  Mesh half;
  std::vector<int> index(sphere.vertexCount(), -1);
  for (Triangle t : sphere.triangles) {
    if (!std::all_of(t.begin(), t.end(), [&](int v) { return sphere.positions[v].z() >= 0.0; })) continue;
    for (int& v : t) {
      if (index[v] < 0) {
        index[v] = static_cast<int>(half.positions.size());
        half.positions.push_back(sphere.positions[v]);
      }
      v = index[v];
    }
    half.triangles.push_back(t);
  }
  return half;
}

// A lat-long sphere cut along the seams of the sphere projector (seam Shift, poles Fan).
CutMesh cutSphere(int longitudes, int latitudes) {
  const Projection p = project(meshes::latLongSphere(longitudes, latitudes), ProjectorOptions{});
  return cutAlongUvSeams(p.mesh, p.uv);
}

// UVs equal to each corner's x and y: no seams at all.
UvMap planarUvs(const Mesh& mesh) {
  UvMap uv;
  for (const Triangle& t : mesh.triangles)
    for (int v : t) uv.uv.push_back(mesh.positions[v].head<2>());
  uv.faceFlags.assign(mesh.faceCount(), kFaceOk);
  uv.cornerInvalid.assign(3 * mesh.faceCount(), 0);
  return uv;
}

double signedAreaUv(const UvMap& uv, std::size_t f) {
  const Vec2 a = uv.uv[3 * f + 1] - uv.uv[3 * f], b = uv.uv[3 * f + 2] - uv.uv[3 * f];
  return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

double area3d(const Mesh& mesh, std::size_t f) {
  const Triangle& t = mesh.triangles[f];
  return 0.5 * triangleAreaNormal(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]).norm();
}

double angleAt(const Vec3& apex, const Vec3& b, const Vec3& c) {
  return std::acos((b - apex).normalized().dot((c - apex).normalized()));
}

// The largest over the smallest ratio of UV area to 3D area: 1 for an area-preserving map.
double areaRatioSpread(const Mesh& mesh, const UvMap& uv) {
  double lo = INFINITY, hi = 0.0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    const double ratio = signedAreaUv(uv, f) / area3d(mesh, f);
    lo = std::min(lo, ratio);
    hi = std::max(hi, ratio);
  }
  return hi / lo;
}

// The contract every result meets: finite UVs, no face flags, the bounding box at (0, 0) with
// its longer side 1, and every triangle counter-clockwise in UV as it is seen from the front.
// Whether `uv` is a baseline's output for `mesh`: one finite UV per corner, no flags, the bounding
// box from (0, 0) with its longer side 1, and every triangle counter-clockwise.
::testing::AssertionResult normalisedAndUnflipped(const Mesh& mesh, const UvMap& uv, Baseline baseline) {
  const auto failure = [&] { return ::testing::AssertionFailure() << toString(baseline) << ": "; };
  if (uv.uv.size() != 3 * mesh.faceCount()) return failure() << uv.uv.size() << " UVs";
  if (uv.faceFlags != std::vector<std::uint8_t>(mesh.faceCount(), kFaceOk)) return failure() << "face flags set";
  if (uv.cornerInvalid != std::vector<std::uint8_t>(3 * mesh.faceCount(), 0)) return failure() << "invalid corners";
  Vec2 lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);
  for (const Vec2& p : uv.uv) {
    if (!p.allFinite()) return failure() << "a UV is not finite";
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (lo != Vec2::Zero()) return failure() << "lower corner " << lo.transpose();
  if (!(std::fabs(hi.maxCoeff() - 1.0) <= 1e-15)) return failure() << "longer side " << hi.maxCoeff();
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    if (!(signedAreaUv(uv, f) > 0.0)) return failure() << "face " << f << " has UV area " << signedAreaUv(uv, f);
  return ::testing::AssertionSuccess();
}

std::string messageOf(const Mesh& mesh, Baseline baseline) {
  try {
    parameterizeDisk(mesh, baseline);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "no UsageError";
}

TEST(Topology, PlaneGridIsADisk) {
  const Topology t = analyzeTopology(meshes::planeGrid(4, 3, 2.0, 1.0));
  EXPECT_TRUE(t.manifold);
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.boundaryLoops, 1u);
  EXPECT_EQ(t.eulerCharacteristic, 1);
  EXPECT_TRUE(t.isDisk());
}

TEST(Topology, ClosedIcosphereHasNoBoundaryAndEulerCharacteristicTwo) {
  const Topology t = analyzeTopology(meshes::icosphere(2));
  EXPECT_TRUE(t.manifold);
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.boundaryLoops, 0u);
  EXPECT_EQ(t.eulerCharacteristic, 2);
  EXPECT_FALSE(t.isDisk());
}

TEST(Topology, OpenCylinderHasTwoBoundaryLoopsAndEulerCharacteristicZero) {
  const Topology t = analyzeTopology(meshes::cylinder(12, 3, 1.0, 2.0, false));
  EXPECT_TRUE(t.manifold);
  EXPECT_EQ(t.boundaryLoops, 2u);
  EXPECT_EQ(t.eulerCharacteristic, 0);
  EXPECT_FALSE(t.isDisk());
}

TEST(Topology, TorusHasEulerCharacteristicZero) {
  const Topology t = analyzeTopology(meshes::torus(12, 8, 2.0, 0.5));
  EXPECT_TRUE(t.manifold);
  EXPECT_EQ(t.boundaryLoops, 0u);
  EXPECT_EQ(t.eulerCharacteristic, 0);
}

TEST(Topology, ThreeTrianglesOnOneEdgeAreNotManifold) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}};
  mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {1, 0, 4}};
  const Topology t = analyzeTopology(mesh);
  EXPECT_FALSE(t.manifold);
  EXPECT_EQ(t.components, 1u);
  EXPECT_FALSE(t.isDisk());
}

TEST(Topology, BowTieIsNotManifoldButConnected) {
  // Two triangles that share only vertex 0: two fans there.
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, -0.5, 0}, {1, 0.5, 0}, {-1, 0.5, 0}, {-1, -0.5, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 3, 4}};
  const Topology t = analyzeTopology(mesh);
  EXPECT_FALSE(t.manifold);
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.eulerCharacteristic, 1);  // like a disk, which is why isDisk() also asks for manifold
  EXPECT_FALSE(t.isDisk());
}

TEST(Topology, InconsistentOrientationAndRepeatedIndicesAreNotManifold) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {1, 2, 3}};  // both traverse the edge 1 -> 2
  EXPECT_FALSE(analyzeTopology(mesh).manifold);
  mesh.triangles = {{0, 1, 1}};
  EXPECT_FALSE(analyzeTopology(mesh).manifold);
}

TEST(Topology, CountsComponentsAndIgnoresUnreferencedVertices) {
  Mesh mesh = meshes::planeGrid(2, 2, 1.0, 1.0);
  Mesh other = meshes::planeGrid(1, 1, 1.0, 1.0);
  const int offset = static_cast<int>(mesh.vertexCount());
  for (const Vec3& p : other.positions) mesh.positions.push_back(p + Vec3(5, 0, 0));
  for (Triangle t : other.triangles) mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  mesh.positions.push_back({9, 9, 9});  // referenced by no triangle
  const Topology t = analyzeTopology(mesh);
  EXPECT_TRUE(t.manifold);
  EXPECT_EQ(t.components, 2u);
  EXPECT_EQ(t.boundaryLoops, 2u);
  EXPECT_EQ(t.eulerCharacteristic, 2);
}

TEST(CutAlongUvSeams, SphereProjectorSeamAndFannedPolesOpenTheSphereIntoADisk) {
  const Mesh sphere = meshes::latLongSphere(16, 8);
  const CutMesh cut = cutSphere(16, 8);
  EXPECT_TRUE(analyzeTopology(cut.mesh).isDisk());
  // The 7 ring vertices on the seam meridian get a second vertex (u = 0 and u = 1); each pole
  // one per face around it (every fanned corner has its own u): 16 * 7 + 2 + 7 + 2 * 15.
  EXPECT_EQ(cut.mesh.vertexCount(), 151u);
  ASSERT_EQ(cut.vertexOf.size(), cut.mesh.vertexCount());
  ASSERT_EQ(cut.mesh.triangles.size(), sphere.triangles.size());
  for (std::size_t v = 0; v < cut.mesh.vertexCount(); ++v)
    EXPECT_EQ(cut.mesh.positions[v], sphere.positions[cut.vertexOf[v]]);
  for (std::size_t f = 0; f < sphere.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(cut.vertexOf[cut.mesh.triangles[f][k]], sphere.triangles[f][k]);
}

TEST(CutAlongUvSeams, UvsWithoutSeamsLeaveTheMeshAsItIs) {
  const Mesh grid = meshes::planeGrid(3, 2, 1.0, 1.0);
  const CutMesh cut = cutAlongUvSeams(grid, planarUvs(grid));
  EXPECT_EQ(cut.mesh.positions, grid.positions);
  EXPECT_EQ(cut.mesh.triangles, grid.triangles);
}

TEST(CutAlongUvSeams, InvalidCornersAndFacesGetVerticesOfTheirOwn) {
  const Mesh grid = meshes::planeGrid(2, 2, 1.0, 1.0);
  UvMap uv = planarUvs(grid);
  uv.faceFlags[0] |= kFaceInvalid;
  uv.cornerInvalid[3 * 5 + 1] = 1;
  // Valid corners share their original vertex; the other 4 corners each add one.
  std::set<int> sharedOriginals;
  for (std::size_t c = 0; c < 3 * grid.faceCount(); ++c)
    if (c / 3 != 0 && c != 3 * 5 + 1) sharedOriginals.insert(grid.triangles[c / 3][c % 3]);
  const CutMesh cut = cutAlongUvSeams(grid, uv);
  EXPECT_EQ(cut.mesh.vertexCount(), sharedOriginals.size() + 4);
  // Face 0 comes off; face 5 stays on through the edge between its two valid corners.
  EXPECT_EQ(analyzeTopology(cut.mesh).components, 2u);
}

TEST(CutAlongUvSeams, WIsPartOfTheTextureCoordinate) {
  // Two triangles sharing an edge with equal (u, v) but different w: cut apart.
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  UvMap uv = planarUvs(mesh);
  uv.w = {0, 0, 0, 1, 1, 1};
  EXPECT_EQ(cutAlongUvSeams(mesh, uv).mesh.vertexCount(), 6u);
}

TEST(ParameterizeDisk, LscmReproducesAPlanarGridUpToASimilarity) {
  const Mesh grid = meshes::planeGrid(8, 5, 2.0, 1.25);
  const UvMap uv = parameterizeDisk(grid, Baseline::Lscm);
  EXPECT_TRUE(normalisedAndUnflipped(grid, uv, Baseline::Lscm));
  const double ratio = signedAreaUv(uv, 0) / area3d(grid, 0);
  for (std::size_t f = 0; f < grid.faceCount(); ++f) {
    EXPECT_NEAR(signedAreaUv(uv, f) / area3d(grid, f), ratio, 1e-9 * ratio) << f;
    const Triangle& t = grid.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      // (u, v, 1): the angle between differences is the angle in the UV plane.
      const double inUv = angleAt(uv.uv[3 * f + k].homogeneous(), uv.uv[3 * f + k1].homogeneous(),
                                  uv.uv[3 * f + k2].homogeneous());
      EXPECT_NEAR(inUv, angleAt(grid.positions[t[k]], grid.positions[t[k1]], grid.positions[t[k2]]), 1e-9) << f;
    }
  }
}

TEST(ParameterizeDisk, CurvedDisksMapWithoutFlippedTriangles) {
  const Mesh half = hemisphere(24, 6);
  const CutMesh cut = cutSphere(16, 8);
  for (Baseline b : kBaselines) {
    EXPECT_TRUE(normalisedAndUnflipped(half, parameterizeDisk(half, b), b));
    EXPECT_TRUE(normalisedAndUnflipped(cut.mesh, parameterizeDisk(cut.mesh, b), b));
  }
}

TEST(ParameterizeDisk, ArapPreservesAreaBetterThanLscm) {
  const Mesh half = hemisphere(24, 6);
  EXPECT_LT(areaRatioSpread(half, parameterizeDisk(half, Baseline::Arap)),
            0.5 * areaRatioSpread(half, parameterizeDisk(half, Baseline::Lscm)));
}

TEST(ParameterizeDisk, DoesNotDependOnTheMeshsUnitsOrPosition) {
  const Mesh half = hemisphere(16, 4);
  Mesh moved = half;
  for (Vec3& p : moved.positions) p = 1000.0 * p + Vec3(5, -3, 2);
  for (Baseline b : kBaselines) {
    const UvMap a = parameterizeDisk(half, b), c = parameterizeDisk(moved, b);
    for (std::size_t i = 0; i < a.uv.size(); ++i) EXPECT_NEAR((a.uv[i] - c.uv[i]).norm(), 0.0, 1e-9) << toString(b);
  }
}

TEST(ParameterizeDisk, RefusesMeshesThatAreNotDisksSayingWhy) {
  for (Baseline b : kBaselines) {
    EXPECT_NE(messageOf(meshes::latLongSphere(16, 8), b).find("0 boundary loops"), std::string::npos);
    EXPECT_NE(messageOf(meshes::cylinder(12, 2, 1.0, 1.0, false), b).find("2 boundary loops"), std::string::npos);
    Mesh bowTie;
    bowTie.positions = {{0, 0, 0}, {1, -0.5, 0}, {1, 0.5, 0}, {-1, 0.5, 0}, {-1, -0.5, 0}};
    bowTie.triangles = {{0, 1, 2}, {0, 3, 4}};
    EXPECT_NE(messageOf(bowTie, b).find("not manifold"), std::string::npos);
    EXPECT_THROW(parameterizeDisk(Mesh{}, b), UsageError);
  }
}

TEST(ParameterizeDisk, RefusesZeroAreaTrianglesInsteadOfCrashing) {
  // A disk whose bottom triangle has three collinear corners.
  Mesh sliver;
  sliver.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1, 0}};
  sliver.triangles = {{0, 1, 3}, {1, 2, 3}, {0, 2, 1}};
  ASSERT_TRUE(analyzeTopology(sliver).isDisk());
  Mesh collapsed = meshes::planeGrid(4, 4, 1.0, 1.0);
  collapsed.positions[6] = collapsed.positions[7];
  Mesh line = meshes::planeGrid(4, 4, 1.0, 1.0);
  for (Vec3& p : line.positions) p.y() = 0.0;
  Mesh point = meshes::planeGrid(2, 2, 1.0, 1.0);
  for (Vec3& p : point.positions) p = Vec3(1, 2, 3);
  for (Baseline b : kBaselines)
    for (const Mesh* mesh : {&sliver, &collapsed, &line, &point})
      EXPECT_NE(messageOf(*mesh, b).find("zero area"), std::string::npos) << toString(b);
}

TEST(ParameterizeDisk, ReportsArapsUnrepairableOverlapAsAUsageError) {
  // On a finer cut sphere the fanned pole triangles of ARAP's map overlap one another, and CGAL's
  // repair needs a UV boundary that does not cross itself. LSCM's conformal map has no overlap.
  const CutMesh cut = cutSphere(32, 16);
  EXPECT_NE(messageOf(cut.mesh, Baseline::Arap).find("overlaps itself"), std::string::npos);
  EXPECT_TRUE(normalisedAndUnflipped(cut.mesh, parameterizeDisk(cut.mesh, Baseline::Lscm), Baseline::Lscm));
}

TEST(Baseline, Names) {
  EXPECT_STREQ(toString(Baseline::Lscm), "lscm");
  EXPECT_STREQ(toString(Baseline::Arap), "arap");
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param
