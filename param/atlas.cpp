#include "param/atlas.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <unordered_map>

#include "core/disjoint_sets.h"
#include "core/error.h"
#include "core/parallel.h"
#include "param/atlas_packing.h"
#include "param/baseline.h"
#include "param/cut_graph.h"

namespace uvtk::param {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Charts that pack poorly (too long for the texture, or hollow) are cut only where the pieces
// pack at least this much more densely than the charts did whole: every cut is a seam more.
constexpr double kCutGain = 1.25;
// A chart whose faces cover less of its box than this is hollow (a ring, a coil's arc): halved,
// and its halves again, at most kCutRounds times (64 pieces).
constexpr double kHollowFill = 0.2;
constexpr int kCutRounds = 6;

using Point2 = Vec2;

// The analysis' own rule for a face of no area (analysis/distortion.h): A3 <= 1e-14 (longest edge)^2.
bool isDegenerate(const Vec3& a, const Vec3& b, const Vec3& c, Vec3& unitNormal) {
  const Vec3 e1 = b - a, e2 = c - a, e3 = c - b;
  const double longest = std::max({e1.squaredNorm(), e2.squaredNorm(), e3.squaredNorm()});
  const Vec3 n = e1.cross(e2);
  const double doubleArea = n.norm();
  if (!(0.5 * doubleArea > 1e-14 * longest) || !std::isfinite(doubleArea)) return true;
  unitNormal = n / doubleArea;
  return false;
}

// Every undirected edge once, with the faces that have it: half-edges sorted by their vertex pair.
struct EdgeTable {
  struct HalfEdge {
    int low, high, face;
  };
  std::vector<HalfEdge> halfEdges;  // sorted by (low, high, face)
  std::vector<std::uint32_t> groupStart;  // edge e's half-edges: [groupStart[e], groupStart[e + 1])

  // A counting sort by the lower vertex, then each vertex's few half-edges by (high, face):
  // linear in the faces rather than a sort of them all.
  explicit EdgeTable(const Mesh& mesh) {
    std::vector<std::uint32_t> start(mesh.vertexCount() + 1, 0);
    for (const Triangle& t : mesh.triangles)
      for (int k = 0; k < 3; ++k)
        if (t[k] != t[(k + 1) % 3]) ++start[std::size_t(std::min(t[k], t[(k + 1) % 3])) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    halfEdges.resize(start.back());
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t f = 0; f < mesh.faceCount(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
        if (a != b) halfEdges[fill[std::size_t(std::min(a, b))]++] = {std::min(a, b), std::max(a, b), int(f)};
      }
    for (std::size_t v = 0; v + 1 < start.size(); ++v)
      if (start[v + 1] - start[v] > 1)
        std::sort(halfEdges.begin() + start[v], halfEdges.begin() + start[v + 1], [](const HalfEdge& x, const HalfEdge& y) {
          return x.high != y.high ? x.high < y.high : x.face < y.face;
        });
    groupStart.reserve(halfEdges.size() / 2 + 2);
    for (std::size_t i = 0; i < halfEdges.size(); ++i)
      if (i == 0 || halfEdges[i].low != halfEdges[i - 1].low || halfEdges[i].high != halfEdges[i - 1].high)
        groupStart.push_back(std::uint32_t(i));
    groupStart.push_back(std::uint32_t(halfEdges.size()));
  }
  std::size_t edgeCount() const { return groupStart.size() - 1; }
};

// Neighbours across manifold edges (exactly two faces, two different ones): up to three per face.
std::vector<std::array<int, 3>> manifoldNeighbours(const EdgeTable& edges, std::size_t faceCount) {
  std::vector<std::array<int, 3>> out(faceCount, {-1, -1, -1});
  const auto add = [&](int face, int other) {
    for (int& slot : out[std::size_t(face)])
      if (slot < 0) {
        slot = other;
        return;
      }
  };
  for (std::size_t e = 0; e < edges.edgeCount(); ++e) {
    if (edges.groupStart[e + 1] - edges.groupStart[e] != 2) continue;
    const int f = edges.halfEdges[edges.groupStart[e]].face, g = edges.halfEdges[edges.groupStart[e] + 1].face;
    if (f == g) continue;
    add(f, g);
    add(g, f);
  }
  return out;
}

// Smart UV Project's directions: the largest face not yet within the angle limit of a direction
// seeds the next one, the area-weighted mean normal of the faces within half the limit of it
// (which lies within half the limit of the seed, so the seed is covered and the loop ends).
std::vector<Vec3> projectionDirections(const std::vector<Vec3>& normals, const std::vector<double>& areas,
                                       const std::vector<int>& byArea, double cosLimit, double cosHalfLimit) {
  std::vector<Vec3> directions;
  std::vector<double> best(normals.size(), -kInfinity);  // the largest cosine to a direction so far
  int seed = byArea.empty() ? -1 : byArea.front();
  while (seed >= 0) {
    const Vec3 seedNormal = normals[std::size_t(seed)];
    Vec3 sum = Vec3::Zero();
    for (const int f : byArea)
      if (normals[std::size_t(f)].dot(seedNormal) >= cosHalfLimit) sum += areas[std::size_t(f)] * normals[std::size_t(f)];
    const Vec3 direction = sum.norm() > 0.0 ? Vec3(sum.normalized()) : seedNormal;
    directions.push_back(direction);
    // The next seed: the face least like every direction so far, while one is beyond the limit.
    seed = -1;
    double least = cosLimit;
    for (const int f : byArea) {
      double& b = best[std::size_t(f)];
      b = std::max(b, normals[std::size_t(f)].dot(direction));
      if (b < least) least = b, seed = f;
    }
  }
  return directions;
}

// (t1, t2) with t1 x t2 = d: projecting along d keeps a face that looks along d counter-clockwise.
Eigen::Matrix<double, 2, 3> planeFrame(const Vec3& d) {
  const Vec3 helper = std::abs(d.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 t1 = helper.cross(d).normalized();
  const Vec3 t2 = d.cross(t1);
  Eigen::Matrix<double, 2, 3> m;
  m.row(0) = t1.transpose();
  m.row(1) = t2.transpose();
  return m;
}

double orient(const Point2& p, const Point2& q, const Point2& r) {
  return (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
}

// Whether the interiors of two counter-clockwise triangles meet: no edge of either separates
// them. Points within a relative 1e-12 of an edge's line count as on it, so triangles that share
// an edge or a vertex do not overlap.
bool interiorsOverlap(const std::array<Point2, 3>& a, const std::array<Point2, 3>& b) {
  double scale = 0.0;
  for (int i = 0; i < 3; ++i) {
    scale = std::max(scale, (a[i] - a[(i + 1) % 3]).squaredNorm());
    scale = std::max(scale, (b[i] - b[(i + 1) % 3]).squaredNorm());
  }
  const double eps = 1e-12 * scale;
  const auto separates = [eps](const std::array<Point2, 3>& s, const std::array<Point2, 3>& t) {
    for (int i = 0; i < 3; ++i) {
      const Point2 &p = s[i], &q = s[(i + 1) % 3];
      if (orient(p, q, t[0]) <= eps && orient(p, q, t[1]) <= eps && orient(p, q, t[2]) <= eps) return true;
    }
    return false;
  };
  return !separates(a, b) && !separates(b, a);
}

// A face's corners in the plane of a direction, computed when asked: a table of them for a
// million faces would be 48 MB of fresh pages, which cost more than the arithmetic.
class FacePlanes {
 public:
  FacePlanes(const Mesh& mesh, const Vec3& origin, const std::vector<Eigen::Matrix<double, 2, 3>>& frames,
             const std::vector<int>& directionOf)
      : mesh_(mesh), origin_(origin), frames_(frames), directionOf_(directionOf) {}
  // Along the face's own direction.
  std::array<Point2, 3> operator[](std::size_t f) const { return along(f, directionOf_[f]); }
  std::array<Point2, 3> along(std::size_t f, int direction) const {
    const Eigen::Matrix<double, 2, 3>& frame = frames_[std::size_t(direction)];
    const Triangle& t = mesh_.triangles[f];
    return {frame * (mesh_.positions[std::size_t(t[0])] - origin_), frame * (mesh_.positions[std::size_t(t[1])] - origin_),
            frame * (mesh_.positions[std::size_t(t[2])] - origin_)};
  }

 private:
  const Mesh& mesh_;
  Vec3 origin_;
  const std::vector<Eigen::Matrix<double, 2, 3>>& frames_;
  const std::vector<int>& directionOf_;
};

// Every face along one direction.
struct FacesAlong {
  const FacePlanes& planes;
  int direction;
  std::array<Point2, 3> operator[](std::size_t f) const { return planes.along(f, direction); }
};

// The faces of one chart in cells of a uniform grid over their projection (cells about a face's
// size; at most about 4 cells a face), so that overlap tests meet only near faces.
class FaceGrid {
 public:
  template <class Planes>
  FaceGrid(const std::vector<int>& faces, const Planes& projected) {
    Eigen::AlignedBox2d box;
    double size = 0.0;
    for (const int f : faces) {
      Eigen::AlignedBox2d faceBox;
      for (const Point2& p : projected[std::size_t(f)]) faceBox.extend(p), box.extend(p);
      size += faceBox.sizes().maxCoeff();
    }
    origin_ = box.min();
    const Vec2 extent = box.sizes();
    cell_ = std::max(size / double(faces.size()), 1e-300);
    const double maxCells = 4.0 * double(faces.size()) + 16.0;
    while ((extent.x() / cell_ + 1.0) * (extent.y() / cell_ + 1.0) > maxCells) cell_ *= 1.5;
    nx_ = int(extent.x() / cell_) + 1;
    ny_ = int(extent.y() / cell_) + 1;
    start_.assign(std::size_t(nx_) * std::size_t(ny_) + 1, 0);
    for (const int f : faces) forCells(projected[std::size_t(f)], [&](std::size_t c) { ++start_[c + 1]; });
    std::partial_sum(start_.begin(), start_.end(), start_.begin());
    faces_.resize(start_.back());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (const int f : faces) forCells(projected[std::size_t(f)], [&](std::size_t c) { faces_[fill[c]++] = f; });
  }

  template <class F>
  void forCells(const std::array<Point2, 3>& t, F&& f) const {
    Eigen::AlignedBox2d b;
    for (const Point2& p : t) b.extend(p);
    const int x0 = cellOf(b.min().x() - origin_.x(), nx_), x1 = cellOf(b.max().x() - origin_.x(), nx_);
    const int y0 = cellOf(b.min().y() - origin_.y(), ny_), y1 = cellOf(b.max().y() - origin_.y(), ny_);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) f(std::size_t(y) * std::size_t(nx_) + std::size_t(x));
  }
  std::size_t cellCount() const { return start_.size() - 1; }
  std::size_t cellAt(const Point2& p) const {
    return std::size_t(cellOf(p.y() - origin_.y(), ny_)) * std::size_t(nx_) + std::size_t(cellOf(p.x() - origin_.x(), nx_));
  }
  const int* begin(std::size_t c) const { return faces_.data() + start_[c]; }
  const int* end(std::size_t c) const { return faces_.data() + start_[c + 1]; }

 private:
  int cellOf(double offset, int n) const { return std::clamp(int(offset / cell_), 0, n - 1); }
  Point2 origin_ = Point2::Zero();
  double cell_ = 1.0;
  int nx_ = 1, ny_ = 1;
  std::vector<std::size_t> start_;
  std::vector<int> faces_;
};

// Whether two faces of the grid overlap. A pair is tested once, in the cell of the lower left
// corner of their boxes' intersection, and only where the boxes meet.
// Whether two of a few faces overlap: every pair, where their boxes meet.
template <class Planes>
bool fewOverlap(const std::vector<int>& faces, const Planes& projected) {
  std::array<std::array<Point2, 3>, 32> t;
  std::array<Eigen::AlignedBox2d, 32> box;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    t[i] = projected[std::size_t(faces[i])];
    box[i].setEmpty();
    for (const Point2& p : t[i]) box[i].extend(p);
    for (std::size_t j = 0; j < i; ++j)
      if (box[i].intersects(box[j]) && interiorsOverlap(t[i], t[j])) return true;
  }
  return false;
}

template <class Planes>
bool overlapsItself(const FaceGrid& grid, const Planes& projected) {
  std::vector<std::array<Point2, 3>> triangles;
  std::vector<Eigen::AlignedBox2d> boxes;
  for (std::size_t c = 0; c < grid.cellCount(); ++c) {
    const std::size_t n = std::size_t(grid.end(c) - grid.begin(c));
    if (n < 2) continue;
    triangles.resize(n);
    boxes.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      triangles[i] = projected[std::size_t(grid.begin(c)[i])];
      boxes[i].setEmpty();
      for (const Point2& p : triangles[i]) boxes[i].extend(p);
    }
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        if (!boxes[i].intersects(boxes[j]) || grid.cellAt(boxes[i].intersection(boxes[j]).min()) != c) continue;
        if (interiorsOverlap(triangles[i], triangles[j])) return true;
      }
  }
  return false;
}

// The convex hull of points (Andrew's monotone chain), counter-clockwise.
std::vector<Point2> convexHull(std::vector<Point2> points) {
  std::sort(points.begin(), points.end(),
            [](const Point2& a, const Point2& b) { return a.x() != b.x() ? a.x() < b.x() : a.y() < b.y(); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Point2> hull(2 * points.size());
  std::size_t k = 0;
  for (const Point2& p : points) {
    while (k >= 2 && orient(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && orient(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

// The rotation that gives the hull its bounding box of least area (one of its edges lies along a
// side), turned a quarter more when the box is taller than wide.
Eigen::Matrix2d smallestBoxRotation(const std::vector<Point2>& hull) {
  Eigen::Matrix2d best = Eigen::Matrix2d::Identity();
  double bestArea = kInfinity;
  Vec2 bestSize = Vec2::Zero();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec2 edge = hull[(i + 1) % hull.size()] - hull[i];
    if (!(edge.norm() > 0.0)) continue;
    const Vec2 x = edge.normalized();
    Eigen::Matrix2d r;
    r << x.x(), x.y(), -x.y(), x.x();
    Eigen::AlignedBox2d box;
    for (const Point2& p : hull) box.extend(r * p);
    const double area = box.volume();
    if (area < bestArea) bestArea = area, best = r, bestSize = box.sizes();
  }
  if (bestSize.y() > bestSize.x()) {
    Eigen::Matrix2d quarter;
    quarter << 0.0, 1.0, -1.0, 0.0;  // (x, y) -> (y, -x): a rotation, never a mirror
    best = quarter * best;
  }
  return best;
}

// The faces of each direction in a FaceGrid of its plane, made when a merge first asks about that
// direction, so that a chart being merged meets only the faces near it; the faces merges projected
// along the direction since go in a side table by cell (cells clamp, so they are found as well).
class DirectionGrids {
 public:
  DirectionGrids(const std::vector<int>& faces, const std::vector<int>& directionOf, const FacePlanes& projected,
                 std::size_t directions)
      : faces_(faces), directionOf_(directionOf), projected_(projected), grids_(directions) {}
  // A face now projected along `direction` (once its grid is made, which then holds it).
  void insert(int direction, const std::array<Point2, 3>& t, int face) {
    Grid& grid = grids_[std::size_t(direction)];
    if (grid.cells) grid.cells->forCells(t, [&](std::size_t c) { grid.added[c].push_back(face); });
  }
  // Calls f(face) for every face in the cells `t` covers in `direction`'s plane (a face may come twice).
  template <class F>
  void near(int direction, const std::array<Point2, 3>& t, F&& f) {
    Grid& grid = grids_[std::size_t(direction)];
    if (!grid.cells) {
      std::vector<int> faces;
      for (const int face : faces_)
        if (directionOf_[std::size_t(face)] == direction) faces.push_back(face);
      grid.cells.emplace(faces, projected_);
    }
    grid.cells->forCells(t, [&](std::size_t c) {
      for (const int* face = grid.cells->begin(c); face != grid.cells->end(c); ++face) f(*face);
      if (const auto extra = grid.added.find(c); extra != grid.added.end())
        for (const int face : extra->second) f(face);
    });
  }

 private:
  struct Grid {
    std::optional<FaceGrid> cells;
    std::unordered_map<std::size_t, std::vector<int>> added;
  };
  const std::vector<int>& faces_;
  const std::vector<int>& directionOf_;
  const FacePlanes& projected_;
  std::vector<Grid> grids_;
};

}  // namespace

namespace {

// LSCM or ARAP of every chart (cut to a disk first where it is not one), scaled to the chart's own
// area so that one density serves all; a chart whose solution fails, flips a face or overlaps
// itself keeps its plane projection (Atlas::fallbackCharts, with the reason).
void solveCharts(const Mesh& mesh, const std::vector<int>& chartOf, std::size_t chartCount, ChartMap chartMap,
                 Atlas& atlas, std::vector<Point2>& solved) {
  solved.assign(3 * mesh.faceCount(), Point2::Zero());
  std::vector<std::vector<int>> facesOf(chartCount);
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) facesOf[std::size_t(chartOf[f])].push_back(int(f));
  const Baseline baseline = chartMap == ChartMap::Lscm ? Baseline::Lscm : Baseline::Arap;
  for (std::size_t c = 0; c < chartCount; ++c) {
    const std::vector<int>& faces = facesOf[c];
    // The chart's own mesh, a vertex per fan of corners: two corners of a vertex share one only
    // where faces of the chart join them across an edge, so that a chart touching itself at a
    // vertex (a bowtie) is cut there rather than refused as not manifold.
    DisjointSets fans(3 * faces.size());
    std::vector<std::array<int, 4>> halfEdges;  // (low, high, corner of low, corner of high)
    for (std::size_t i = 0; i < faces.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        const int a = mesh.triangles[std::size_t(faces[i])][k], b = mesh.triangles[std::size_t(faces[i])][(k + 1) % 3];
        const int ca = int(3 * i) + k, cb = int(3 * i) + (k + 1) % 3;
        halfEdges.push_back(a < b ? std::array<int, 4>{a, b, ca, cb} : std::array<int, 4>{b, a, cb, ca});
      }
    std::sort(halfEdges.begin(), halfEdges.end());
    for (std::size_t i = 0; i < halfEdges.size();) {
      std::size_t j = i;
      while (j < halfEdges.size() && halfEdges[j][0] == halfEdges[i][0] && halfEdges[j][1] == halfEdges[i][1]) ++j;
      if (j - i == 2) fans.join(std::size_t(halfEdges[i][2]), std::size_t(halfEdges[i + 1][2])),
                      fans.join(std::size_t(halfEdges[i][3]), std::size_t(halfEdges[i + 1][3]));
      i = j;
    }
    Mesh chart;
    std::vector<int> vertexOfSet(3 * faces.size(), -1);
    for (std::size_t i = 0; i < faces.size(); ++i) {
      Triangle t;
      for (int k = 0; k < 3; ++k) {
        int& v = vertexOfSet[fans.find(3 * i + std::size_t(k))];
        if (v < 0) {
          v = int(chart.positions.size());
          chart.positions.push_back(mesh.positions[std::size_t(mesh.triangles[std::size_t(faces[i])][k])]);
        }
        t[k] = v;
      }
      chart.triangles.push_back(t);
    }
    const auto fallBack = [&](const std::string& why) {
      ++atlas.fallbackCharts;
      if (atlas.fallbackReasons.size() < 8)
        atlas.fallbackReasons.push_back("chart " + std::to_string(c) + " (" + std::to_string(faces.size()) +
                                        " faces): " + why);
    };
    std::vector<Point2> uv;
    try {
      const Mesh disk = analyzeTopology(chart).isDisk() ? chart : cutToDisk(chart).mesh;
      const UvMap map = parameterizeDisk(disk, baseline);
      uv = map.uv;
    } catch (const UsageError& e) {
      fallBack(e.what());
      continue;
    }
    double area3 = 0.0, areaUv = 0.0;
    std::size_t positive = 0, negative = 0;
    for (std::size_t i = 0; i < faces.size(); ++i) {
      const Triangle& t = chart.triangles[i];
      area3 += 0.5 * (chart.positions[std::size_t(t[1])] - chart.positions[std::size_t(t[0])])
                         .cross(chart.positions[std::size_t(t[2])] - chart.positions[std::size_t(t[0])])
                         .norm();
      const double a = 0.5 * orient(uv[3 * i], uv[3 * i + 1], uv[3 * i + 2]);
      areaUv += std::abs(a);
      positive += a > 0.0;
      negative += a < 0.0;
    }
    if (positive != faces.size() && negative != faces.size()) {
      fallBack(std::to_string(std::min(positive, negative)) + " faces flipped");
      continue;
    }
    if (!(areaUv > 0.0) || !(area3 > 0.0)) {
      fallBack("no area");
      continue;
    }
    const double scale = std::sqrt(area3 / areaUv);
    const double mirror = negative == faces.size() ? -1.0 : 1.0;  // a mirrored solution, turned over whole
    std::vector<std::array<Point2, 3>> triangles(faces.size());
    std::vector<int> indices(faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i) {
      indices[i] = int(i);
      for (int k = 0; k < 3; ++k) triangles[i][std::size_t(k)] = Point2(mirror * uv[3 * i + std::size_t(k)].x(), uv[3 * i + std::size_t(k)].y()) * scale;
    }
    if (faces.size() >= 3 && overlapsItself(FaceGrid(indices, triangles), triangles)) {
      fallBack("its flattening overlaps itself");
      continue;
    }
    for (std::size_t i = 0; i < faces.size(); ++i)
      for (int k = 0; k < 3; ++k) solved[3 * std::size_t(faces[i]) + std::size_t(k)] = triangles[i][std::size_t(k)];
    atlas.charts[c].solved = true;
  }
}


// Each chart's box: its corners in its direction's plane (or as LSCM or ARAP flattened them),
// turned to their bounding box of least area, wider than tall (R, and the box in the turned plane).
struct ChartBoxes {
  std::vector<Eigen::Matrix2d> rotation;
  std::vector<Vec2> low, size;
};

ChartBoxes chartBoxes(const Mesh& mesh, const std::vector<int>& chartOf, const std::vector<AtlasChart>& charts,
                      const std::vector<int>& chartDirection, const std::vector<Eigen::Matrix<double, 2, 3>>& frames,
                      const Vec3& origin, const std::vector<Point2>& solved) {
  const std::size_t chartCount = charts.size();
  std::vector<std::vector<Point2>> points(chartCount);
  std::vector<int> lastChartOfVertex(mesh.vertexCount(), -1);  // each vertex once a chart (its run of faces)
  for (std::size_t f = 0; f < chartOf.size(); ++f) {
    const std::size_t c = std::size_t(chartOf[f]);
    if (charts[c].solved) {
      for (int k = 0; k < 3; ++k) points[c].push_back(solved[3 * f + std::size_t(k)]);
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[f][k];
      if (lastChartOfVertex[std::size_t(v)] == int(c)) continue;
      lastChartOfVertex[std::size_t(v)] = int(c);
      points[c].push_back(frames[std::size_t(chartDirection[c])] * (mesh.positions[std::size_t(v)] - origin));
    }
  }
  ChartBoxes boxes;
  boxes.rotation.resize(chartCount);
  boxes.low.resize(chartCount);
  boxes.size.resize(chartCount);
  for (std::size_t c = 0; c < chartCount; ++c) {
    boxes.rotation[c] = smallestBoxRotation(convexHull(points[c]));
    Eigen::AlignedBox2d box;
    for (const Point2& p : points[c]) box.extend(boxes.rotation[c] * p);
    boxes.low[c] = box.min();
    boxes.size[c] = box.sizes();
    std::vector<Point2>().swap(points[c]);
  }
  return boxes;
}

// One round of cuts of the charts that pack poorly (docs/conventions.md, "The atlas"); the charts
// are plane projections (not LSCM or ARAP). With `cutLong`, one whose longer side, at the density
// the charts' area allows, exceeds `side` texels (what one box may span, chartRoom) while its
// shorter side takes at most half of it is cut into the fewest slabs of equal length along its box
// that are at most `side` long; else one whose faces cover less than kHollowFill of its box is
// cut into two. The slabs go by the faces' centroids, and each slab's pieces joined across shared
// edges are charts: subsets of a chart, so no new flip or overlap. Charts are numbered by their
// first face; `from` is empty when no chart was cut.
struct CutCharts {
  std::vector<int> chartOf;
  std::vector<int> from;  // each new chart's chart before the cut
};

CutCharts cutPoorlyPackedCharts(const Mesh& mesh, const EdgeTable& edges, const std::vector<int>& chartOf,
                        const std::vector<AtlasChart>& charts, const ChartBoxes& boxes,
                        const std::vector<int>& chartDirection, const std::vector<Eigen::Matrix<double, 2, 3>>& frames,
                        const Vec3& origin, double density, double side, bool cutLong) {
  const std::size_t faceCount = chartOf.size(), chartCount = charts.size();
  const double pieceLength = side / density;
  // Each chart's faces' area in its plane, against its box's.
  std::vector<double> area(chartCount, 0.0);
  for (std::size_t f = 0; f < faceCount; ++f) {
    const std::size_t c = std::size_t(chartOf[f]);
    const Eigen::Matrix<double, 2, 3>& frame = frames[std::size_t(chartDirection[c])];
    const Triangle& t = mesh.triangles[f];
    const Point2 a = frame * (mesh.positions[std::size_t(t[0])] - origin), b = frame * (mesh.positions[std::size_t(t[1])] - origin),
                 d = frame * (mesh.positions[std::size_t(t[2])] - origin);
    area[c] += 0.5 * std::abs(orient(a, b, d));
  }
  std::vector<int> slabs(chartCount, 1);
  bool any = false;
  for (std::size_t c = 0; c < chartCount; ++c) {
    const Vec2& s = boxes.size[c];  // wider than tall
    if (cutLong && s.x() * density > side && s.y() * density <= 0.5 * side)
      slabs[c] = int(std::min(std::ceil(s.x() / pieceLength), double(charts[c].faces)));
    else if (charts[c].faces > 1 && area[c] < kHollowFill * s.x() * s.y())
      slabs[c] = 2;
    any = any || slabs[c] > 1;
  }
  CutCharts cut;
  if (!any) return cut;
  // Each face's slab: where its centroid lies along its chart's box.
  std::vector<int> slab(faceCount, 0);
  for (std::size_t f = 0; f < faceCount; ++f) {
    const std::size_t c = std::size_t(chartOf[f]);
    if (slabs[c] == 1) continue;
    const Triangle& t = mesh.triangles[f];
    Vec3 centroid = Vec3::Zero();  // about the origin, as the boxes' corners
    for (int k = 0; k < 3; ++k) centroid += (mesh.positions[std::size_t(t[k])] - origin) / 3.0;
    const double x = (boxes.rotation[c] * (frames[std::size_t(chartDirection[c])] * centroid)).x();
    const double along = (x - boxes.low[c].x()) / boxes.size[c].x() * slabs[c];
    slab[f] = along > 0.0 ? int(std::min(along, double(slabs[c] - 1))) : 0;
  }
  // The faces of one chart and slab, joined across the edges they share.
  DisjointSets pieces(faceCount);
  for (std::size_t e = 0; e < edges.edgeCount(); ++e)
    for (std::size_t i = edges.groupStart[e] + 1; i < edges.groupStart[e + 1]; ++i) {
      const std::size_t f = std::size_t(edges.halfEdges[i].face);
      for (std::size_t j = edges.groupStart[e]; j < i; ++j) {
        const std::size_t g = std::size_t(edges.halfEdges[j].face);
        if (chartOf[f] == chartOf[g] && slab[f] == slab[g]) {
          pieces.join(f, g);
          break;
        }
      }
    }
  // A chart left whole keeps its faces; a cut one's faces go by their piece.
  std::vector<int> numberOfChart(chartCount, -1), numberOfPiece(faceCount, -1);
  cut.chartOf.resize(faceCount);
  for (std::size_t f = 0; f < faceCount; ++f) {
    const std::size_t c = std::size_t(chartOf[f]);
    int& number = slabs[c] == 1 ? numberOfChart[c] : numberOfPiece[pieces.find(f)];
    if (number < 0) {
      number = int(cut.from.size());
      cut.from.push_back(int(c));
    }
    cut.chartOf[f] = number;
  }
  return cut;
}

}  // namespace

void checkAtlasOptions(const AtlasOptions& o) {
  if (!(o.angleLimitDegrees >= 1.0 && o.angleLimitDegrees <= 89.0))
    throw UsageError("--angle-limit: expected degrees in [1, 89]");
  if (!(o.marginTexels >= 0.0 && o.marginTexels <= 1024.0))
    throw UsageError("--margin: expected texels in [0, 1024]");
  if (o.textureSize[0] < 1 || o.textureSize[1] < 1 || o.textureSize[0] > 16384 || o.textureSize[1] > 16384)
    throw UsageError("--texture-size: expected 1 to 16384 texels");
  if (2.0 * o.marginTexels >= double(std::min(o.textureSize[0], o.textureSize[1])))
    throw UsageError("--margin: two margins must leave room in the texture");
  if (o.texelsPerUnit && !(*o.texelsPerUnit > 0.0 && std::isfinite(*o.texelsPerUnit)))
    throw UsageError("--texels-per-unit: expected a finite number above 0");
}

Atlas makeAtlas(const Mesh& input, const AtlasOptions& options, int threads) {
  checkAtlasOptions(options);
  const std::size_t faceCount = input.faceCount();
  Atlas atlas;
  atlas.stretchBound = 1.0 / std::cos(options.angleLimitDegrees * kPi / 180.0);
  if (faceCount == 0) return atlas;

  // The charts are made on the mesh moved to its box's centre and scaled by a power of two to a
  // size between 1 and 2: exactly, so that every decision and number is what the mesh itself
  // gives, while areas, cross products and box areas stay finite and nonzero for a mesh 1e-300 or
  // 1e300 across (docs/extremes.md). `scale` turns the atlas's lengths back into object units.
  Eigen::AlignedBox3d bounds;
  for (const Vec3& p : input.positions) bounds.extend(p);
  const Vec3 centre = bounds.center();
  const double toUnit = unitPowerOfTwo(bounds.sizes().maxCoeff()), scale = 1.0 / toUnit;
  Mesh mesh;
  mesh.triangles = input.triangles;
  mesh.positions.reserve(input.positions.size());
  for (const Vec3& p : input.positions) mesh.positions.push_back((p - centre) * toUnit);
  const Vec3 origin = Vec3::Zero();

  // The faces' unit normals and areas; degenerate faces have neither.
  std::vector<Vec3> normals(faceCount, Vec3::Zero());
  std::vector<double> areas(faceCount, 0.0);
  std::vector<char> degenerate(faceCount, 0);
  std::vector<int> byArea;
  for (std::size_t f = 0; f < faceCount; ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3 a = mesh.positions[std::size_t(t[0])] - origin, b = mesh.positions[std::size_t(t[1])] - origin,
               c = mesh.positions[std::size_t(t[2])] - origin;
    degenerate[f] = isDegenerate(a, b, c, normals[f]);
    if (degenerate[f]) continue;
    areas[f] = 0.5 * (b - a).cross(c - a).norm();
    byArea.push_back(int(f));
  }
  atlas.degenerateFaces = faceCount - byArea.size();
  std::stable_sort(byArea.begin(), byArea.end(), [&](int x, int y) { return areas[std::size_t(x)] > areas[std::size_t(y)]; });

  const double limit = options.angleLimitDegrees * kPi / 180.0;
  const std::vector<Vec3> directions =
      projectionDirections(normals, areas, byArea, std::cos(limit), std::cos(0.5 * limit));
  atlas.directions = directions.size();
  std::vector<Eigen::Matrix<double, 2, 3>> frames;
  for (const Vec3& d : directions) frames.push_back(planeFrame(d));

  // Each face takes the direction nearest its normal, and is projected along it.
  std::vector<int> directionOf(faceCount, -1);
  const FacePlanes projected(mesh, origin, frames, directionOf);
  for (const int f : byArea) {
    double best = -kInfinity;
    for (std::size_t d = 0; d < directions.size(); ++d) {
      const double cosine = normals[std::size_t(f)].dot(directions[d]);
      if (cosine > best) best = cosine, directionOf[std::size_t(f)] = int(d);
    }
  }

  // Charts: the faces of one direction joined across manifold edges, in face order; a chart whose
  // projection overlaps itself is grown again face by face, each face joining only if it overlaps
  // none of the chart so far, and what is left seeds further charts.
  const EdgeTable edges(mesh);
  std::vector<std::array<int, 3>> neighbours = manifoldNeighbours(edges, faceCount);
  std::vector<int> chartOf(faceCount, -1);
  std::vector<int> tried(faceCount, -1);  // the last chart that tested the face and refused it
  int charts = 0;
  std::vector<int> queue;
  const bool wholeDisk = options.chartMap != ChartMap::Plane && analyzeTopology(mesh).isDisk();
  for (std::size_t seed = 0; seed < faceCount && wholeDisk; ++seed) chartOf[seed] = 0;
  charts = wholeDisk ? 1 : 0;
  // The components first, then whether each overlaps itself (side by side: they are
  // independent, and the answer does not depend on the threads), then the overlapping ones split.
  std::vector<std::vector<int>> components;
  for (std::size_t seed = 0; seed < faceCount && !wholeDisk; ++seed) {
    if (degenerate[seed] || chartOf[seed] >= 0) continue;
    std::vector<int>& component = components.emplace_back(1, int(seed));
    chartOf[seed] = int(components.size() - 1);
    for (std::size_t i = 0; i < component.size(); ++i)
      for (const int g : neighbours[std::size_t(component[i])])
        if (g >= 0 && chartOf[std::size_t(g)] < 0 && directionOf[std::size_t(g)] == directionOf[seed]) {
          chartOf[std::size_t(g)] = chartOf[seed];
          component.push_back(g);
        }
  }
  std::vector<char> overlapping(components.size(), 0);
  parallelFor(int(components.size()), threads, [&](int i) {
    const std::vector<int>& component = components[std::size_t(i)];
    if (component.size() < 3) return;  // two faces across an edge, both facing the direction, cannot overlap
    overlapping[std::size_t(i)] = component.size() <= 32 ? fewOverlap(component, projected)
                                                         : overlapsItself(FaceGrid(component, projected), projected);
  });
  for (std::size_t k = 0; k < components.size(); ++k) {
    const std::vector<int>& component = components[k];
    const int first = charts;
    if (!overlapping[k]) {
      for (const int f : component) chartOf[std::size_t(f)] = first;
      ++charts;
      continue;
    }
    const FaceGrid grid(component, projected);
    const int direction = directionOf[std::size_t(component[0])];
    for (const int f : component) chartOf[std::size_t(f)] = -1;
    for (const int start : component) {
      if (chartOf[std::size_t(start)] >= 0) continue;
      const int chart = charts++;
      chartOf[std::size_t(start)] = chart;
      queue.assign(1, start);
      for (std::size_t i = 0; i < queue.size(); ++i)
        for (const int g : neighbours[std::size_t(queue[i])]) {
          if (g < 0 || chartOf[std::size_t(g)] >= 0 || tried[std::size_t(g)] == chart ||
              directionOf[std::size_t(g)] != direction)
            continue;
          bool overlaps = false;
          const std::array<Point2, 3> tg = projected[std::size_t(g)];
          grid.forCells(tg, [&](std::size_t c) {
            for (const int* h = grid.begin(c); h != grid.end(c) && !overlaps; ++h)
              overlaps = chartOf[std::size_t(*h)] == chart && interiorsOverlap(tg, projected[std::size_t(*h)]);
          });
          if (overlaps) {
            tried[std::size_t(g)] = chart;
            continue;
          }
          chartOf[std::size_t(g)] = chart;
          queue.push_back(g);
        }
    }
    atlas.splitCharts += std::size_t(charts - first - 1);
  }
  std::vector<std::vector<int>>().swap(components);

  // Merging, smallest chart first: a chart joins the neighbour it shares the most edges with when
  // every face of it lies within the angle limit of that neighbour's direction and, projected
  // along it, overlaps neither the neighbour nor itself. Fewer charts, shorter seams, the same
  // guarantees. Charts are then numbered by their first face.
  if (!wholeDisk) {
    const double cosLimit = std::cos(limit);
    const std::size_t initialCharts = std::size_t(charts);
    std::vector<std::vector<int>> facesOf(initialCharts);
    for (std::size_t f = 0; f < faceCount; ++f)
      if (chartOf[f] >= 0) facesOf[std::size_t(chartOf[f])].push_back(int(f));
    std::vector<int> directionOfChart(initialCharts);
    for (std::size_t c = 0; c < initialCharts; ++c) directionOfChart[c] = directionOf[std::size_t(facesOf[c][0])];
    DirectionGrids grids(byArea, directionOf, projected, directions.size());
    std::vector<int> bySize(initialCharts);
    std::iota(bySize.begin(), bySize.end(), 0);
    std::stable_sort(bySize.begin(), bySize.end(),
                     [&](int a, int b) { return facesOf[std::size_t(a)].size() < facesOf[std::size_t(b)].size(); });
    std::vector<std::pair<int, int>> shared;  // (edges shared, chart)
    for (const int a : bySize) {
      std::vector<int>& faces = facesOf[std::size_t(a)];
      shared.clear();
      for (const int f : faces)
        for (const int g : neighbours[std::size_t(f)])
          if (g >= 0 && chartOf[std::size_t(g)] >= 0 && chartOf[std::size_t(g)] != a) shared.emplace_back(0, chartOf[std::size_t(g)]);
      std::sort(shared.begin(), shared.end(), [](const auto& x, const auto& y) { return x.second < y.second; });
      std::vector<std::pair<int, int>> counted;
      for (const auto& [unused, b] : shared)
        if (!counted.empty() && counted.back().second == b) --counted.back().first;
        else counted.emplace_back(-1, b);
      std::sort(counted.begin(), counted.end());  // the most shared edges first, then the lower chart
      for (const std::pair<int, int>& candidate : counted) {
        const int b = candidate.second;  // a named variable, not a binding: lambdas capture it (C++17)
        const int direction = directionOfChart[std::size_t(b)];
        const Vec3& d = directions[std::size_t(direction)];
        bool fits = true;
        for (const int f : faces) fits = fits && normals[std::size_t(f)].dot(d) >= cosLimit;
        if (!fits) continue;
        const FacesAlong moved{projected, direction};
        const bool selfOverlap = faces.size() >= 3 && (faces.size() <= 32 ? fewOverlap(faces, moved)
                                                                         : overlapsItself(FaceGrid(faces, moved), moved));
        if (selfOverlap) continue;
        for (std::size_t i = 0; i < faces.size() && fits; ++i) {
          const std::array<Point2, 3> t = moved[std::size_t(faces[i])];
          grids.near(direction, t, [&](int h) {
            fits = fits && !(chartOf[std::size_t(h)] == b && directionOf[std::size_t(h)] == direction &&
                             interiorsOverlap(t, projected[std::size_t(h)]));
          });
        }
        if (!fits) continue;
        for (const int f : faces) {
          chartOf[std::size_t(f)] = b;
          directionOf[std::size_t(f)] = direction;
          grids.insert(direction, moved[std::size_t(f)], f);
        }
        std::vector<int>& into = facesOf[std::size_t(b)];
        into.insert(into.end(), faces.begin(), faces.end());
        std::vector<int>().swap(faces);
        ++atlas.mergedCharts;
        break;
      }
    }
    std::vector<int> renumber(initialCharts, -1);
    charts = 0;
    for (std::size_t f = 0; f < faceCount; ++f)
      if (chartOf[f] >= 0) {
        int& to = renumber[std::size_t(chartOf[f])];
        if (to < 0) to = charts++;
        chartOf[f] = to;
      }
  }

  // What the charts needed and the rest does not: 40 bytes a face on a big mesh's peak.
  std::vector<std::array<int, 3>>().swap(neighbours);
  std::vector<Vec3>().swap(normals);
  std::vector<int>().swap(tried);

  // Degenerate faces join the chart of a face they share an edge with, nearest first; the rest
  // (components of nothing but degenerate faces) get a chart each, looking along +z.
  std::vector<int> chartDirection(std::size_t(charts), 0);
  for (std::size_t f = 0; f < faceCount; ++f)
    if (chartOf[f] >= 0) chartDirection[std::size_t(chartOf[f])] = directionOf[f];
  if (atlas.degenerateFaces > 0) {
    std::vector<std::vector<std::size_t>> edgesOfFace(faceCount);
    for (std::size_t e = 0; e < edges.edgeCount(); ++e)
      for (std::size_t i = edges.groupStart[e]; i < edges.groupStart[e + 1]; ++i)
        edgesOfFace[std::size_t(edges.halfEdges[i].face)].push_back(e);
    queue.clear();
    for (std::size_t f = 0; f < faceCount; ++f)
      if (chartOf[f] >= 0 && !edgesOfFace[f].empty()) queue.push_back(int(f));
    for (std::size_t i = 0; i < queue.size(); ++i)
      for (const std::size_t e : edgesOfFace[std::size_t(queue[i])])
        for (std::size_t h = edges.groupStart[e]; h < edges.groupStart[e + 1]; ++h) {
          const int g = edges.halfEdges[h].face;
          if (chartOf[std::size_t(g)] >= 0) continue;
          chartOf[std::size_t(g)] = chartOf[std::size_t(queue[i])];
          queue.push_back(g);
        }
    const int lone = int(frames.size());
    frames.push_back(planeFrame(Vec3::UnitZ()));
    for (std::size_t f = 0; f < faceCount; ++f)
      if (chartOf[f] < 0) {
        chartOf[f] = charts++;
        chartDirection.push_back(lone);
      }
  }

  // Each chart turned to its smallest box, then packed. Charts that pack poorly are cut, the long
  // ones in the first round and the hollow ones in every round (cutPoorlyPackedCharts), and the
  // cut charts kept where they pack at least kCutGain times as densely.
  const auto chartsOfFaces = [&](const std::vector<int>& chartOfFace, std::size_t count) {
    std::vector<AtlasChart> made(count);
    for (std::size_t f = 0; f < faceCount; ++f) ++made[std::size_t(chartOfFace[f])].faces;
    return made;
  };
  std::size_t chartCount = std::size_t(charts);
  atlas.charts = chartsOfFaces(chartOf, chartCount);
  std::vector<Point2> solved;  // per corner, for the solved charts
  if (options.chartMap != ChartMap::Plane) {
    // CGAL solves the mesh as given (its solvers' rounding is not scale-free), then the solution is
    // scaled as the mesh was.
    solveCharts(input, chartOf, chartCount, options.chartMap, atlas, solved);
    for (Point2& p : solved) p *= toUnit;
  }
  ChartBoxes boxes = chartBoxes(mesh, chartOf, atlas.charts, chartDirection, frames, origin, solved);
  Packing packing = packCharts(boxes.size, atlas.charts, options, scale);
  if (options.chartMap == ChartMap::Plane && !options.texelsPerUnit) {
    std::vector<int> cutChartOf = chartOf, cutDirection = chartDirection;
    std::vector<AtlasChart> cutCharts = atlas.charts;
    ChartBoxes cutBoxes = boxes;
    for (int round = 0; round < kCutRounds; ++round) {
      CutCharts cut = cutPoorlyPackedCharts(mesh, edges, cutChartOf, cutCharts, cutBoxes, cutDirection, frames, origin,
                                            areaDensity(cutBoxes.size, options), chartRoom(options).minCoeff(),
                                            round == 0);
      if (cut.from.size() <= cutCharts.size()) break;  // no chart was cut, or none came apart
      std::vector<int> direction(cut.from.size());
      for (std::size_t c = 0; c < cut.from.size(); ++c) direction[c] = cutDirection[std::size_t(cut.from[c])];
      cutDirection = std::move(direction);
      cutChartOf = std::move(cut.chartOf);
      cutCharts = chartsOfFaces(cutChartOf, cutDirection.size());
      cutBoxes = chartBoxes(mesh, cutChartOf, cutCharts, cutDirection, frames, origin, solved);
    }
    if (cutCharts.size() > chartCount) {
      Packing cutPacking = packCharts(cutBoxes.size, cutCharts, options, scale);
      if (cutPacking.fits && cutPacking.density >= kCutGain * packing.density) {
        atlas.cutCharts = cutCharts.size() - chartCount;
        chartCount = cutCharts.size();
        chartOf = std::move(cutChartOf);
        atlas.charts = std::move(cutCharts);
        chartDirection = std::move(cutDirection);
        boxes = std::move(cutBoxes);
        packing = std::move(cutPacking);
      }
    }
  }
  if (!packing.fits) throwChartsDoNotFit(chartCount, options);
  const double density = packing.density;  // texels per unit of the scaled mesh
  const std::vector<Placement>& placements = packing.placements;
  std::vector<Eigen::Matrix2d>& rotation = boxes.rotation;
  std::vector<Vec2>&low = boxes.low, &size = boxes.size;
  atlas.texelsPerUnit = density * toUnit;

  // A chart packed turned takes a quarter turn more (a rotation, never a mirror).
  for (std::size_t c = 0; c < chartCount; ++c)
    if (placements[c].turned) {
      Eigen::Matrix2d quarter;
      quarter << 0.0, -1.0, 1.0, 0.0;
      rotation[c] = quarter * rotation[c];
      low[c] = Vec2(-(low[c].y() + size[c].y()), low[c].x());
      size[c] = Vec2(size[c].y(), size[c].x());
    }

  // The charts' maps: texel = density (R (T (p - origin)) - low) + at, uv = texel / (W, H) + tile.
  const Vec2 perTexel(1.0 / double(options.textureSize[0]), 1.0 / double(options.textureSize[1]));
  for (std::size_t c = 0; c < chartCount; ++c) {
    AtlasChart& chart = atlas.charts[c];
    const Eigen::Matrix<double, 2, 3>& frame = frames[std::size_t(chartDirection[c])];
    chart.direction = frame.row(0).transpose().cross(frame.row(1).transpose());
    chart.origin = centre;
    chart.linear = perTexel.asDiagonal() * (atlas.texelsPerUnit * rotation[c] * frame);
    chart.tile = placements[c].tile;
    const Vec2 tileCorner(double(chart.tile % 10), double(chart.tile / 10));
    chart.offset = perTexel.asDiagonal() * (placements[c].at - density * low[c]) + tileCorner;
    atlas.tiles = std::max(atlas.tiles, chart.tile + 1);
  }
  atlas.uv.resize(3 * faceCount);
  atlas.chartOfFace = std::move(chartOf);
  double uvArea = 0.0;
  for (std::size_t f = 0; f < faceCount; ++f) {
    const AtlasChart& chart = atlas.charts[std::size_t(atlas.chartOfFace[f])];
    const std::size_t c = std::size_t(atlas.chartOfFace[f]);
    for (int k = 0; k < 3; ++k) {
      const std::size_t corner = 3 * f + std::size_t(k);
      atlas.uv[corner] = chart.solved ? Vec2(perTexel.cwiseProduct(density * (rotation[c] * solved[corner] - low[c]) +
                                                                    placements[c].at) +
                                             Vec2(double(chart.tile % 10), double(chart.tile / 10)))
                                      : chart.uvAt(input.positions[std::size_t(input.triangles[f][k])]);
    }
    uvArea += 0.5 * std::abs(orient(atlas.uv[3 * f], atlas.uv[3 * f + 1], atlas.uv[3 * f + 2]));
  }
  atlas.occupancy = uvArea / double(atlas.tiles);

  // Seams: the edges between charts. (How far apart the charts lie is measured on the layout,
  // analysis/texel_layout.h, as for any UVs.)
  for (std::size_t e = 0; e < edges.edgeCount(); ++e) {
    const std::size_t begin = edges.groupStart[e], end = edges.groupStart[e + 1];
    const EdgeTable::HalfEdge& first = edges.halfEdges[begin];
    // Between charts, or inside an LSCM or ARAP chart where its cut to a disk runs: the faces
    // give an endpoint different UVs.
    const auto uvAt = [&](int face, int vertex) {
      const Triangle& t = mesh.triangles[std::size_t(face)];
      return atlas.uv[3 * std::size_t(face) + std::size_t(t[0] == vertex ? 0 : t[1] == vertex ? 1 : 2)];
    };
    bool seam = false;
    for (std::size_t i = begin + 1; i < end; ++i) {
      const int face = edges.halfEdges[i].face;
      seam |= atlas.chartOfFace[std::size_t(face)] != atlas.chartOfFace[std::size_t(first.face)] ||
              uvAt(face, first.low) != uvAt(first.face, first.low) || uvAt(face, first.high) != uvAt(first.face, first.high);
    }
    if (!seam) continue;
    ++atlas.seamEdges;
    const Vec3 edge = input.positions[std::size_t(first.high)] - input.positions[std::size_t(first.low)];
    // norm() squares an edge of 1e200 to infinity and one of 1e-200 to 0.
    atlas.seamLength += std::isnormal(edge.squaredNorm()) ? edge.norm() : edge.stableNorm();
  }
  return atlas;
}

}  // namespace uvtk::param
