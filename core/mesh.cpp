#include "core/mesh.h"

#include <algorithm>
#include <cmath>

#include "core/parallel.h"

namespace uvtk {

namespace {

// The power of two that brings the mesh's largest coordinate to about 1. Areas computed from
// positions times it stay out of underflow and overflow for meshes at 1e-300 or 1e300, and
// scaling by a power of two changes no direction and no ratio of areas.
double unitScale(const Mesh& mesh, int threads = 1) {
  const double largest = reduceRanges(
      mesh.positions.size(), std::size_t(1) << 16, threads, 0.0,
      [&](double& range, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) range = std::max(range, mesh.positions[i].cwiseAbs().maxCoeff());
      },
      [](double& total, double range) { total = std::max(total, range); });
  return unitPowerOfTwo(largest);
}

Vec3 scaledAreaNormal(const Mesh& mesh, const Triangle& t, double scale) {
  return triangleAreaNormal<double>(mesh.positions[t[0]] * scale, mesh.positions[t[1]] * scale,
                                    mesh.positions[t[2]] * scale);
}

}  // namespace

std::vector<Vec3> areaWeightedVertexNormals(const Mesh& mesh) {
  std::vector<Vec3> sum(mesh.positions.size(), Vec3::Zero());
  const double scale = unitScale(mesh);
  for (const Triangle& t : mesh.triangles) {
    const Vec3 n = scaledAreaNormal(mesh, t, scale);
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

MeshWarnings checkMesh(const Mesh& mesh, int threads) {
  constexpr std::size_t kChunk = std::size_t(1) << 16;
  MeshWarnings warnings;
  std::vector<char> used(mesh.positions.size(), 0);
  const double scale = unitScale(mesh, threads);
  warnings.degenerateFaces = reduceRanges(
      mesh.triangles.size(), kChunk, threads, std::size_t(0),
      [&](std::size_t& degenerate, std::size_t begin, std::size_t end) {
        for (std::size_t f = begin; f < end; ++f) {
          const Triangle& t = mesh.triangles[f];
          for (int v : t) orBitsAtomically(used[std::size_t(v)], char(1));  // threads may mark one vertex at once
          const bool repeated = t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
          if (repeated || scaledAreaNormal(mesh, t, scale).squaredNorm() == 0.0) ++degenerate;
        }
      },
      [](std::size_t& total, std::size_t degenerate) { total += degenerate; });
  warnings.unreferencedVertices = std::size_t(std::count(used.begin(), used.end(), 0));
  return warnings;
}

}  // namespace uvtk
