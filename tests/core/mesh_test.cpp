// Vertex normals and mesh checks, with OpenMesh's area-weighted normals as the reference.
#include "core/mesh.h"

#include <gtest/gtest.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using OpenMeshTriangles = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

// An irregular closed mesh: a perturbed octahedron, so face areas differ.
Mesh perturbedOctahedron() {
  Mesh m;
  m.positions = {{1.3, 0, 0.1}, {-1, 0.2, 0}, {0, 0.7, 0}, {0.1, -1.6, 0}, {0, 0, 1}, {0.2, -0.1, -2}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

TEST(AreaWeightedVertexNormals, AgreeWithOpenMeshsCorrectVertexNormals) {
  const Mesh mesh = perturbedOctahedron();
  OpenMeshTriangles om;
  std::vector<OpenMeshTriangles::VertexHandle> handles;
  for (const Vec3& p : mesh.positions) handles.push_back(om.add_vertex({p.x(), p.y(), p.z()}));
  for (const Triangle& t : mesh.triangles) om.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
  const std::vector<Vec3> ours = areaWeightedVertexNormals(mesh);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    OpenMeshTriangles::Normal n;
    om.calc_vertex_normal_correct(handles[v], n);
    const Vec3 reference = Vec3(n[0], n[1], n[2]).normalized();
    EXPECT_TRUE(ours[v].isApprox(reference, 1e-14)) << v;
  }
}

TEST(AreaWeightedVertexNormals, WeighsFacesByArea) {
  // Vertex 0 is shared by a unit right triangle in z = 0 and one twice as large in x = 0.
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 2}, {0, 2, 0}};
  m.triangles = {{0, 1, 2}, {0, 4, 3}};
  // area normals: (0,0,1)/2 * 2 = (0,0,1) and (4,0,0)... cross((0,2,0),(0,0,2)) = (4,0,0)
  EXPECT_TRUE(areaWeightedVertexNormals(m)[0].isApprox(Vec3(4, 0, 1).normalized()));
}

TEST(CornerNormals, PreferTheFilesNormalsAndFallBackPerCorner) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}};
  m.normals = {{0, 3, 0}};
  m.cornerNormals = {{0, -1, 0}};
  const std::vector<Vec3> n = cornerNormals(m);
  EXPECT_EQ(n[0], Vec3(0, 1, 0));  // from the file, normalised
  EXPECT_EQ(n[1], Vec3(0, 0, 1));  // no file normal: the face's
  EXPECT_EQ(n[2], Vec3(0, 1, 0));
}

TEST(CheckMesh, CountsDegenerateFacesAndUnreferencedVertices) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {9, 9, 9}};
  m.triangles = {{0, 1, 3}, {0, 1, 2}, {1, 1, 3}};  // ok, collinear, repeated index
  const MeshWarnings w = checkMesh(m);
  EXPECT_EQ(w.degenerateFaces, 2u);
  EXPECT_EQ(w.unreferencedVertices, 1u);
  EXPECT_TRUE(areaWeightedVertexNormals(m)[4].isZero());
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
