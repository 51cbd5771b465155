// The sample-mesh generators: counts, exact special points, outward orientation, closedness,
// and the committed files under meshes/ being exactly what the generators write.
#include "meshes/generators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.h"
#include "io/mesh_writer.h"
#include "io/obj_writer.h"

namespace uvtk::meshes {
namespace {
namespace UVTK_TEST_FILE {

// The signed volume enclosed by a closed mesh (divergence theorem): positive when every
// triangle is counter-clockwise seen from outside.
double signedVolume(const Mesh& m) {
  double six = 0.0;
  for (const Triangle& t : m.triangles) six += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]]));
  return six / 6.0;
}

// Every directed edge appears once and its reverse once: a closed, consistently oriented
// 2-manifold (without boundary).
bool isClosedAndOriented(const Mesh& m) {
  std::map<std::pair<int, int>, int> directed;
  for (const Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) return false;
  }
  return true;
}

TEST(LatLongSphere, HasTheDocumentedCountsAndExactPoles) {
  const Mesh m = latLongSphere(16, 8, 2.0);
  EXPECT_EQ(m.vertexCount(), 16u * 7u + 2u);
  EXPECT_EQ(m.faceCount(), 2u * 16u * 7u);
  EXPECT_EQ(m.positions.front(), Vec3(0, 0, 2));
  EXPECT_EQ(m.positions.back(), Vec3(0, 0, -2));
  for (const Vec3& p : m.positions) EXPECT_NEAR(p.norm(), 2.0, 1e-15);
}

TEST(LatLongSphere, StartsEveryRingOnThePlusXHalfPlaneWithPositiveZeroY) {
  const Mesh m = latLongSphere(12, 6);
  for (int ring = 0; ring < 5; ++ring) {
    const Vec3& first = m.positions[1 + 12 * ring];
    EXPECT_EQ(first.y(), 0.0);
    EXPECT_FALSE(std::signbit(first.y()));
    EXPECT_GT(first.x(), 0.0);
    // A quarter turn on is exactly on +y.
    EXPECT_EQ(m.positions[1 + 12 * ring + 3].x(), 0.0);
  }
  EXPECT_EQ(m.positions[1 + 12 * 2].z(), 0.0);  // the equator ring lies at z = 0 exactly
}

TEST(Generators, ClosedMeshesAreOrientedOutwardWithTheRightVolume) {
  EXPECT_TRUE(isClosedAndOriented(latLongSphere(24, 12)));
  EXPECT_NEAR(signedVolume(latLongSphere(256, 128)), 4.0 / 3.0 * kPi, 2e-3);  // inscribed: slightly less
  EXPECT_TRUE(isClosedAndOriented(icosphere(2)));
  EXPECT_NEAR(signedVolume(icosphere(5)), 4.0 / 3.0 * kPi, 1e-2);
  EXPECT_TRUE(isClosedAndOriented(cylinder(16, 3, 0.5, 2.0, true)));
  EXPECT_NEAR(signedVolume(cylinder(4, 1, 1.0, 3.0, true)), 2.0 * 3.0, 1e-14);  // a square prism
  EXPECT_TRUE(isClosedAndOriented(cube(3)));
  EXPECT_NEAR(signedVolume(cube(3)), 8.0, 1e-13);
  EXPECT_TRUE(isClosedAndOriented(torus(24, 12, 1.0, 0.25)));
  EXPECT_NEAR(signedVolume(torus(512, 256, 1.0, 0.25)), 2 * kPi * kPi * 1.0 * 0.25 * 0.25, 1e-3);
}

TEST(Icosphere, HasTheDocumentedCountsOnTheSphere) {
  const Mesh m = icosphere(2, 3.0);
  EXPECT_EQ(m.vertexCount(), 10u * 16u + 2u);
  EXPECT_EQ(m.faceCount(), 20u * 16u);
  for (const Vec3& p : m.positions) EXPECT_NEAR(p.norm(), 3.0, 1e-14);
}

TEST(Cylinder, SpansZeroToHeightWithCentresOnTheAxis) {
  const Mesh open = cylinder(8, 2, 0.5, 3.0, false);
  EXPECT_EQ(open.vertexCount(), 8u * 3u);
  EXPECT_EQ(open.faceCount(), 2u * 8u * 2u);
  for (const Vec3& p : open.positions) {
    EXPECT_NEAR(std::hypot(p.x(), p.y()), 0.5, 1e-15);
    EXPECT_TRUE(p.z() == 0.0 || p.z() == 1.5 || p.z() == 3.0);
  }
  const Mesh capped = cylinder(8, 2, 0.5, 3.0, true);
  EXPECT_EQ(capped.vertexCount(), open.vertexCount() + 2);
  EXPECT_EQ(capped.faceCount(), open.faceCount() + 16);
  EXPECT_EQ(capped.positions[capped.vertexCount() - 2], Vec3(0, 0, 0));
  EXPECT_EQ(capped.positions[capped.vertexCount() - 1], Vec3(0, 0, 3));
}

TEST(Cube, IsWeldedAlongItsEdges) {
  const Mesh m = cube(2);
  EXPECT_EQ(m.vertexCount(), 6u * 4u + 2u);
  EXPECT_EQ(m.faceCount(), 12u * 4u);
  for (const Vec3& p : m.positions) EXPECT_EQ(p.cwiseAbs().maxCoeff(), 1.0);
}

TEST(PlaneGrid, IsCentredInZZeroAndFacesPlusZ) {
  const Mesh m = planeGrid(3, 2, 3.0, 1.0);
  EXPECT_EQ(m.vertexCount(), 4u * 3u);
  EXPECT_EQ(m.faceCount(), 2u * 3u * 2u);
  EXPECT_EQ(m.positions.front(), Vec3(-1.5, -0.5, 0));
  EXPECT_EQ(m.positions.back(), Vec3(1.5, 0.5, 0));
  for (const Triangle& t : m.triangles)
    EXPECT_GT(triangleAreaNormal(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]).z(), 0.0);
}

TEST(Generators, RejectTooFewSegments) {
  EXPECT_THROW(latLongSphere(2, 4), UsageError);
  EXPECT_THROW(cylinder(8, 0, 1, 1, false), UsageError);
  EXPECT_THROW(cube(0), UsageError);
}

TEST(BundledMeshes, TheCommittedFilesAreWhatTheGeneratorWrites) {
  for (const BundledMesh& b : bundledMeshes()) {
    std::ifstream file(std::string(UVTK_MESHES_DIR) + "/" + b.file, std::ios::binary);
    ASSERT_TRUE(file) << b.file << ": missing; run `build/meshes/uvtk_meshgen meshes`";
    std::stringstream committed;
    committed << file.rdbuf();
    // Written as uvtk_meshgen writes it: by the file's extension.
    const std::string written = ::testing::TempDir() + "bundled_" + b.file;
    io::MeshWriteOptions options;
    options.header = b.header();
    io::writeMesh(written, b.mesh, nullptr, options);
    std::ifstream generatedFile(written, std::ios::binary);
    std::stringstream generated;
    generated << generatedFile.rdbuf();
    std::remove(written.c_str());
    EXPECT_TRUE(committed.str() == generated.str()) << b.file << " differs; run `build/meshes/uvtk_meshgen meshes`";
    EXPECT_LT(committed.str().size(), 1u << 20) << b.file;
  }
}


// ---- The meshes like real ones ----

// Boundary edges (directed edges without their reverse) and the loops they form.
int boundaryLoops(const Mesh& m) {
  std::map<std::pair<int, int>, int> directed;
  for (const Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  std::map<int, int> next;
  for (const auto& [edge, count] : directed)
    if (!directed.count({edge.second, edge.first})) next[edge.first] = edge.second;
  int loops = 0;
  while (!next.empty()) {
    int v = next.begin()->first;
    while (next.count(v)) {
      const int w = next[v];
      next.erase(v);
      v = w;
    }
    ++loops;
  }
  return loops;
}

int eulerCharacteristic(const Mesh& m) {
  std::map<std::pair<int, int>, int> edges;
  for (const Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++edges[std::minmax(t[k], t[(k + 1) % 3])];
  return int(m.positions.size()) - int(edges.size()) + int(m.triangles.size());
}

TEST(TorusKnot, IsAClosedOutwardTubeOfGenusOne) {
  const Mesh m = torusKnot(2, 3, 120, 10);
  EXPECT_EQ(m.positions.size(), 1200u);
  EXPECT_EQ(m.triangles.size(), 2400u);
  EXPECT_TRUE(isClosedAndOriented(m));
  EXPECT_EQ(eulerCharacteristic(m), 0);
  // The tube's volume is about pi r^2 times the curve's length (about 2 pi 4.3 for (2, 3), R = 2).
  const double volume = signedVolume(m);
  EXPECT_GT(volume, 0.0);
  EXPECT_NEAR(volume / (kPi * 0.16), 27.0, 6.0);
}

TEST(Bone, IsClosedOutwardLongAndThinWithPolesAtItsEnds) {
  const Mesh m = bone(80, 24, 10.0);
  EXPECT_EQ(m.positions.size(), std::size_t(79 * 24 + 2));
  EXPECT_TRUE(isClosedAndOriented(m));
  EXPECT_EQ(eulerCharacteristic(m), 2);
  EXPECT_GT(signedVolume(m), 0.0);
  EXPECT_EQ(m.positions.front(), Vec3(0, 0, 0));
  EXPECT_EQ(m.positions.back(), Vec3(0, 0, 10));
  double widest = 0.0;
  for (const Vec3& p : m.positions) widest = std::max(widest, std::hypot(p.x(), p.y()));
  EXPECT_LT(widest, 1.5);  // more than 6 times longer than wide
}

TEST(BumpyBlob, IsAClosedOutwardSphereOffTheOrigin) {
  const Mesh m = bumpyBlob(3);
  EXPECT_EQ(m.triangles.size(), 1280u);
  EXPECT_TRUE(isClosedAndOriented(m));
  EXPECT_EQ(eulerCharacteristic(m), 2);
  EXPECT_GT(signedVolume(m), 0.0);
  EXPECT_EQ(bumpyBlob(3).positions, m.positions);  // deterministic
}

TEST(ScannedPatch, IsAnOpenDiskWithOneRaggedBoundary) {
  const Mesh m = scannedPatch(4);
  EXPECT_GT(m.triangles.size(), 2000u);
  EXPECT_LT(m.triangles.size(), 5120u);
  EXPECT_EQ(boundaryLoops(m), 1);
  EXPECT_EQ(eulerCharacteristic(m), 1);
  EXPECT_EQ(checkMesh(m).unreferencedVertices, 0u);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::meshes
