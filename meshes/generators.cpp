#include "meshes/generators.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "core/error.h"

namespace uvtk::meshes {

namespace {

// (cos, sin) of the angle 2 pi k / n, exact at multiples of a quarter turn, so that generated
// points on the coordinate half-planes lie on them exactly.
Vec2 unitCircle(long k, long n) {
  k %= n;
  if ((4 * k) % n == 0) {
    static constexpr double kQuarter[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    const long quarter = 4 * k / n;
    return {kQuarter[quarter][0], kQuarter[quarter][1]};
  }
  const double angle = kTwoPi * static_cast<double>(k) / static_cast<double>(n);
  return {std::cos(angle), std::sin(angle)};
}

// Two triangles of the quad a, b, c, d (counter-clockwise seen from outside).
void addQuad(Mesh& mesh, int a, int b, int c, int d) {
  mesh.triangles.push_back({a, b, c});
  mesh.triangles.push_back({a, c, d});
}

// A grid of (columns + 1) x (rows + 1) vertices starting at index `first`, row by row; the
// columns wrap around when `wrapColumns` (then a row has `columns` vertices).
void addGridFaces(Mesh& mesh, int first, int columns, int rows, bool wrapColumns) {
  const int rowLength = wrapColumns ? columns : columns + 1;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      const int c1 = wrapColumns ? (c + 1) % columns : c + 1;
      addQuad(mesh, first + r * rowLength + c, first + r * rowLength + c1, first + (r + 1) * rowLength + c1,
              first + (r + 1) * rowLength + c);
    }
}

void require(bool condition, const char* what) {
  if (!condition) throw UsageError(what);
}

}  // namespace

Mesh latLongSphere(int longitudes, int latitudes, double radius) {
  require(longitudes >= 3 && latitudes >= 2, "latLongSphere: expected longitudes >= 3 and latitudes >= 2");
  Mesh mesh;
  mesh.positions.push_back({0.0, 0.0, radius});
  for (int i = 1; i < latitudes; ++i) {
    // The polar angle pi i / latitudes as a half of the circle 2 pi i / (2 latitudes).
    const Vec2 polar = unitCircle(i, 2L * latitudes);
    for (int j = 0; j < longitudes; ++j) {
      const Vec2 azimuth = unitCircle(j, longitudes);
      mesh.positions.push_back(radius * Vec3(polar.y() * azimuth.x(), polar.y() * azimuth.y(), polar.x()));
    }
  }
  const int south = static_cast<int>(mesh.positions.size());
  mesh.positions.push_back({0.0, 0.0, -radius});
  auto ring = [&](int i, int j) { return 1 + (i - 1) * longitudes + j % longitudes; };
  for (int j = 0; j < longitudes; ++j) mesh.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
  for (int i = 1; i + 1 < latitudes; ++i)
    for (int j = 0; j < longitudes; ++j) addQuad(mesh, ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1));
  for (int j = 0; j < longitudes; ++j) mesh.triangles.push_back({south, ring(latitudes - 1, j + 1), ring(latitudes - 1, j)});
  return mesh;
}

std::vector<Vec4> latLongCornerTexcoords(const Mesh& mesh, double repeatsS, double repeatsT) {
  std::vector<Vec4> corners;
  for (const Triangle& t : mesh.triangles) {
    double s[3], tc[3];
    bool pole[3];
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = mesh.positions[std::size_t(t[k])].normalized();
      pole[k] = p.x() == 0.0 && p.y() == 0.0;
      const double longitude = std::atan2(p.y(), p.x()) / kTwoPi;
      s[k] = longitude < 0.0 ? longitude + 1.0 : longitude;
      tc[k] = std::acos(std::clamp(p.z(), -1.0, 1.0)) / kPi;
    }
    double lo = 1.0, hi = 0.0;
    for (int k = 0; k < 3; ++k)
      if (!pole[k]) lo = std::min(lo, s[k]), hi = std::max(hi, s[k]);
    for (int k = 0; k < 3; ++k)
      if (!pole[k] && hi - lo > 0.5 && s[k] < 0.5) s[k] += 1.0;
    for (int k = 0; k < 3; ++k)
      if (pole[k]) s[k] = 0.5 * (s[(k + 1) % 3] + s[(k + 2) % 3]);
    for (int k = 0; k < 3; ++k) corners.emplace_back(repeatsS * s[k], repeatsT * tc[k], 0.0, 1.0);
  }
  return corners;
}

Mesh icosphere(int level, double radius) {
  require(level >= 0 && level <= 10, "icosphere: expected a level in 0..10");
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  Mesh mesh;
  mesh.positions = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0}, {0, -1, phi}, {0, 1, phi},
                    {0, -1, -phi}, {0, 1, -phi}, {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
  mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                    {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (Vec3& p : mesh.positions) p.normalize();
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
      const std::pair<int, int> key(std::min(a, b), std::max(a, b));
      const auto found = midpoints.find(key);
      if (found != midpoints.end()) return found->second;
      const int index = static_cast<int>(mesh.positions.size());
      mesh.positions.push_back((mesh.positions[a] + mesh.positions[b]).normalized());
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<Triangle> finer;
    finer.reserve(4 * mesh.triangles.size());
    for (const Triangle& t : mesh.triangles) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      finer.insert(finer.end(), {{t[0], ab, ca}, {t[1], bc, ab}, {t[2], ca, bc}, {ab, bc, ca}});
    }
    mesh.triangles = std::move(finer);
  }
  for (Vec3& p : mesh.positions) p *= radius;
  return mesh;
}

Mesh cylinder(int segments, int stacks, double radius, double height, bool capped) {
  require(segments >= 3 && stacks >= 1, "cylinder: expected segments >= 3 and stacks >= 1");
  Mesh mesh;
  for (int k = 0; k <= stacks; ++k)
    for (int j = 0; j < segments; ++j) {
      const Vec2 c = unitCircle(j, segments);
      mesh.positions.push_back({radius * c.x(), radius * c.y(), height * k / stacks});
    }
  addGridFaces(mesh, 0, segments, stacks, true);
  if (capped) {
    const int bottom = static_cast<int>(mesh.positions.size()), top = bottom + 1, topRing = stacks * segments;
    mesh.positions.push_back({0.0, 0.0, 0.0});
    mesh.positions.push_back({0.0, 0.0, height});
    for (int j = 0; j < segments; ++j) mesh.triangles.push_back({bottom, (j + 1) % segments, j});
    for (int j = 0; j < segments; ++j) mesh.triangles.push_back({top, topRing + j, topRing + (j + 1) % segments});
  }
  return mesh;
}

Mesh cube(int subdivisions) {
  require(subdivisions >= 1, "cube: expected subdivisions >= 1");
  const int n = subdivisions;
  Mesh mesh;
  std::map<std::tuple<int, int, int>, int> welded;  // by lattice point, so shared edges merge exactly
  auto vertex = [&](const std::array<int, 3>& lattice) {
    const auto key = std::make_tuple(lattice[0], lattice[1], lattice[2]);
    const auto found = welded.find(key);
    if (found != welded.end()) return found->second;
    const int index = static_cast<int>(mesh.positions.size());
    Vec3 p;
    for (int a = 0; a < 3; ++a) p[a] = 2.0 * lattice[a] / n - 1.0;
    mesh.positions.push_back(p);
    welded.emplace(key, index);
    return index;
  };
  // Per face (+X -X +Y -Y +Z -Z): the normal axis and the in-face axes (u, v) with u x v = normal.
  static constexpr int kFaces[6][4] = {{0, 1, 1, 2}, {0, 0, 2, 1}, {1, 1, 2, 0}, {1, 0, 0, 2}, {2, 1, 0, 1}, {2, 0, 1, 0}};
  for (const auto& face : kFaces) {
    const int axis = face[0], side = face[1] ? n : 0, uAxis = face[2], vAxis = face[3];
    auto at = [&](int i, int j) {
      std::array<int, 3> lattice{};
      lattice[axis] = side, lattice[uAxis] = i, lattice[vAxis] = j;
      return vertex(lattice);
    };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        // at() numbers new vertices, so the order of the calls is fixed here (the committed cube.obj's),
        // not left to the order of argument evaluation, which differs between compilers.
        const int d = at(i, j + 1), c = at(i + 1, j + 1), b = at(i + 1, j), a = at(i, j);
        addQuad(mesh, a, b, c, d);
      }
  }
  return mesh;
}

Mesh torus(int majorSegments, int minorSegments, double majorRadius, double minorRadius) {
  require(majorSegments >= 3 && minorSegments >= 3, "torus: expected at least 3 segments each way");
  Mesh mesh;
  for (int j = 0; j < minorSegments; ++j) {
    const Vec2 tube = unitCircle(j, minorSegments);
    for (int i = 0; i < majorSegments; ++i) {
      const Vec2 around = unitCircle(i, majorSegments);
      const double rho = majorRadius + minorRadius * tube.x();
      mesh.positions.push_back({rho * around.x(), rho * around.y(), minorRadius * tube.y()});
    }
  }
  for (int j = 0; j < minorSegments; ++j)
    for (int i = 0; i < majorSegments; ++i) {
      const int i1 = (i + 1) % majorSegments, j1 = (j + 1) % minorSegments;
      addQuad(mesh, j * majorSegments + i, j * majorSegments + i1, j1 * majorSegments + i1, j1 * majorSegments + i);
    }
  return mesh;
}

Mesh planeGrid(int nx, int ny, double width, double height) {
  require(nx >= 1 && ny >= 1, "planeGrid: expected nx >= 1 and ny >= 1");
  Mesh mesh;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      mesh.positions.push_back({width * (static_cast<double>(i) / nx - 0.5), height * (static_cast<double>(j) / ny - 0.5), 0.0});
  addGridFaces(mesh, 0, nx, ny, false);
  return mesh;
}

}  // namespace uvtk::meshes

namespace uvtk::meshes {

namespace {

// A deterministic hash of an integer triple to [-1, 1] (no random state: tests assert exact counts).
double hashNoise(long a, long b, long c) {
  unsigned long long h = 1469598103934665603ULL;
  for (long v : {a, b, c}) {
    h ^= static_cast<unsigned long long>(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h *= 1099511628211ULL;
  }
  h ^= h >> 33;
  return static_cast<double>(h % 2000001ULL) / 1000000.0 - 1.0;
}

}  // namespace

Mesh torusKnot(int p, int q, int segments, int sides, double tubeRadius) {
  require(p >= 1 && q >= 1 && segments >= 3 && sides >= 3 && tubeRadius > 0.0,
          "torusKnot: expected p, q >= 1, segments, sides >= 3 and a positive tube radius");
  const auto curve = [p, q](double t) {
    const double r = 2.0 + std::cos(q * t);
    return Vec3(r * std::cos(p * t), r * std::sin(p * t), -std::sin(q * t));
  };
  Mesh mesh;
  const double h = 1e-4;
  for (int i = 0; i < segments; ++i) {
    const double t = kTwoPi * i / segments;
    const Vec3 c = curve(t), d1 = (curve(t + h) - curve(t - h)) / (2 * h),
               d2 = (curve(t + h) - 2.0 * c + curve(t - h)) / (h * h);
    const Vec3 tangent = d1.normalized();
    const Vec3 binormal = d1.cross(d2).normalized();
    const Vec3 normal = binormal.cross(tangent);
    for (int j = 0; j < sides; ++j) {
      const double a = kTwoPi * j / sides;
      mesh.positions.push_back(c + tubeRadius * (std::cos(a) * normal + std::sin(a) * binormal));
    }
  }
  for (int i = 0; i < segments; ++i)
    for (int j = 0; j < sides; ++j) {
      const int i1 = (i + 1) % segments, j1 = (j + 1) % sides;
      addQuad(mesh, i * sides + j, i * sides + j1, i1 * sides + j1, i1 * sides + j);
    }
  return mesh;
}

Mesh bone(int stacks, int sides, double length) {
  require(stacks >= 4 && sides >= 3 && length > 0.0, "bone: expected stacks >= 4, sides >= 3 and a positive length");
  Mesh mesh;
  mesh.positions.push_back({0.0, 0.0, 0.0});
  for (int k = 1; k < stacks; ++k) {
    const double s = static_cast<double>(k) / stacks;
    const double knob = std::exp(-std::pow((s - 0.07) / 0.07, 2)) + 0.8 * std::exp(-std::pow((s - 0.93) / 0.06, 2));
    const double radius = (0.32 + 0.55 * knob) * std::pow(std::sin(kPi * s), 0.35) * length / 10.0;
    const double twist = 0.6 * s;
    for (int j = 0; j < sides; ++j) {
      const double a = kTwoPi * j / sides + twist;
      const double bump = 1.0 + 0.04 * std::sin(3 * a + 7 * s) + 0.02 * hashNoise(k, j, 7);
      mesh.positions.push_back(
          {1.25 * radius * bump * std::cos(a), 0.85 * radius * bump * std::sin(a), length * s});
    }
  }
  mesh.positions.push_back({0.0, 0.0, length});
  const int last = static_cast<int>(mesh.positions.size()) - 1;
  for (int j = 0; j < sides; ++j) mesh.triangles.push_back({0, 1 + (j + 1) % sides, 1 + j});
  addGridFaces(mesh, 1, sides, stacks - 2, true);
  const int top = 1 + (stacks - 2) * sides;
  for (int j = 0; j < sides; ++j) mesh.triangles.push_back({top + j, top + (j + 1) % sides, last});
  return mesh;
}

Mesh bumpyBlob(int level, double noise) {
  require(noise >= 0.0 && noise < 0.5, "bumpyBlob: expected a noise in [0, 0.5)");
  Mesh mesh = icosphere(level);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3 d = mesh.positions[i];
    const double lobes = 0.18 * std::sin(2.1 * d.x() + 0.4) * std::cos(1.7 * d.y()) + 0.12 * d.z() * d.z() +
                         0.06 * std::sin(5.0 * d.y() + 3.0 * d.z());
    const double grain = noise * hashNoise(std::lround(d.x() * 1e6), std::lround(d.y() * 1e6), std::lround(d.z() * 1e6));
    mesh.positions[i] = Vec3(0.3, -0.2, 0.1) + (1.0 + lobes + grain) * Vec3(1.0 * d.x(), 0.8 * d.y(), 1.15 * d.z());
  }
  return mesh;
}

Mesh scannedPatch(int level) {
  const Mesh blob = bumpyBlob(level);
  Mesh patch;
  std::vector<int> renumbered(blob.positions.size(), -1);
  for (const Triangle& t : blob.triangles) {
    const Vec3 centroid = (blob.positions[t[0]] + blob.positions[t[1]] + blob.positions[t[2]]) / 3.0;
    const Vec3 d = centroid - Vec3(0.3, -0.2, 0.1);
    // A wavy cut, smooth enough that every boundary vertex keeps one fan (the patch stays a disk).
    const double threshold = -0.2 + 0.1 * std::sin(3.0 * std::atan2(d.z(), d.y()));
    if (d.x() < threshold * d.norm()) continue;
    Triangle kept;
    for (int k = 0; k < 3; ++k) {
      if (renumbered[t[k]] < 0) {
        renumbered[t[k]] = static_cast<int>(patch.positions.size());
        patch.positions.push_back(blob.positions[t[k]]);
      }
      kept[k] = renumbered[t[k]];
    }
    patch.triangles.push_back(kept);
  }
  return patch;
}

std::vector<BundledMesh> bundledMeshes() {
  return {
      {"sphere_latlong.obj", "latLongSphere(32, 16)", latLongSphere(32, 16)},
      {"icosphere.obj", "icosphere(3)", icosphere(3)},
      {"cylinder_open.obj", "cylinder(32, 8, 0.5, 2, false)", cylinder(32, 8, 0.5, 2.0, false)},
      {"cylinder_capped.obj", "cylinder(32, 8, 0.5, 2, true)", cylinder(32, 8, 0.5, 2.0, true)},
      {"cube.obj", "cube(4)", cube(4)},
      {"torus.obj", "torus(48, 24, 1, 0.35)", torus(48, 24, 1.0, 0.35)},
      {"plane_grid.obj", "planeGrid(16, 16, 2, 2)", planeGrid(16, 16, 2.0, 2.0)},
      {"scanned_patch.ply", "scannedPatch(3)", scannedPatch(3)},
      {"torus_knot.glb", "torusKnot(2, 3, 120, 12)", torusKnot(2, 3, 120, 12)},
  };
}

}  // namespace uvtk::meshes
