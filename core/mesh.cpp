#include "core/mesh.h"

#include <algorithm>
#include <cmath>

namespace uvtk {

std::vector<Vec3> areaWeightedVertexNormals(const Mesh& mesh) {
  std::vector<Vec3> sum(mesh.positions.size(), Vec3::Zero());
  for (const Triangle& t : mesh.triangles) {
    const Vec3 n = triangleAreaNormal(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
    for (int v : t) sum[v] += n;
  }
  for (Vec3& n : sum) {
    const double length = n.norm();
    n = length > 0.0 && std::isfinite(length) ? Vec3(n / length) : Vec3::Zero();
  }
  return sum;
}

std::vector<Vec3> cornerNormals(const Mesh& mesh) {
  const bool everyCornerHasFileNormal =
      mesh.hasNormals() && std::all_of(mesh.cornerNormals.begin(), mesh.cornerNormals.end(),
                                       [](const Triangle& c) { return c[0] >= 0 && c[1] >= 0 && c[2] >= 0; });
  const std::vector<Vec3> vertexNormals =
      everyCornerHasFileNormal ? std::vector<Vec3>() : areaWeightedVertexNormals(mesh);
  std::vector<Vec3> corners(3 * mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int fileNormal = mesh.hasNormals() ? mesh.cornerNormals[f][k] : -1;
      Vec3 n = fileNormal >= 0 ? mesh.normals[fileNormal] : vertexNormals[mesh.triangles[f][k]];
      const double length = n.norm();
      corners[3 * f + k] = length > 0.0 && std::isfinite(length) ? Vec3(n / length) : Vec3::Zero();
    }
  return corners;
}

MeshWarnings checkMesh(const Mesh& mesh) {
  MeshWarnings warnings;
  std::vector<char> used(mesh.positions.size(), 0);
  for (const Triangle& t : mesh.triangles) {
    for (int v : t) used[v] = 1;
    const bool repeated = t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
    if (repeated ||
        triangleAreaNormal(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]).squaredNorm() == 0.0)
      ++warnings.degenerateFaces;
  }
  for (char u : used) warnings.unreferencedVertices += u ? 0 : 1;
  return warnings;
}

}  // namespace uvtk
