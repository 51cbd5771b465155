#include "param/atlas.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>

#include "core/error.h"

namespace uvtk::param {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

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
  std::vector<std::size_t> groupStart;  // edge e's half-edges: [groupStart[e], groupStart[e + 1])

  explicit EdgeTable(const Mesh& mesh) {
    halfEdges.reserve(3 * mesh.faceCount());
    for (std::size_t f = 0; f < mesh.faceCount(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
        if (a != b) halfEdges.push_back({std::min(a, b), std::max(a, b), int(f)});
      }
    std::sort(halfEdges.begin(), halfEdges.end(), [](const HalfEdge& x, const HalfEdge& y) {
      return x.low != y.low ? x.low < y.low : x.high != y.high ? x.high < y.high : x.face < y.face;
    });
    for (std::size_t i = 0; i < halfEdges.size(); ++i)
      if (i == 0 || halfEdges[i].low != halfEdges[i - 1].low || halfEdges[i].high != halfEdges[i - 1].high)
        groupStart.push_back(i);
    groupStart.push_back(halfEdges.size());
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
  for (const int seed : byArea) {
    if (best[std::size_t(seed)] >= cosLimit) continue;
    const Vec3 seedNormal = normals[std::size_t(seed)];
    Vec3 sum = Vec3::Zero();
    for (const int f : byArea)
      if (normals[std::size_t(f)].dot(seedNormal) >= cosHalfLimit) sum += areas[std::size_t(f)] * normals[std::size_t(f)];
    const Vec3 direction = sum.norm() > 0.0 ? Vec3(sum.normalized()) : seedNormal;
    directions.push_back(direction);
    for (const int f : byArea) best[std::size_t(f)] = std::max(best[std::size_t(f)], normals[std::size_t(f)].dot(direction));
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

// The faces of one chart in cells of a uniform grid over their projection (cells about a face's
// size; at most about 4 cells a face), so that overlap tests meet only near faces.
class FaceGrid {
 public:
  FaceGrid(const std::vector<int>& faces, const std::vector<std::array<Point2, 3>>& projected) {
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

bool overlapsItself(const FaceGrid& grid, const std::vector<std::array<Point2, 3>>& projected) {
  for (std::size_t c = 0; c < grid.cellCount(); ++c)
    for (const int* i = grid.begin(c); i != grid.end(c); ++i)
      for (const int* j = i + 1; j != grid.end(c); ++j)
        if (interiorsOverlap(projected[std::size_t(*i)], projected[std::size_t(*j)])) return true;
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

// Bottom-left skyline packing of boxes into a bin: each box goes where its bottom is lowest,
// then leftmost. Returns false as soon as a box does not fit.
class Skyline {
 public:
  Skyline(double width, double height) : width_(width), height_(height), segments_{{0.0, 0.0, width}} {}

  bool place(double w, double h, Vec2& at) {
    constexpr double kSlack = 1e-9;
    double bestY = kInfinity, bestX = 0.0;
    std::size_t bestIndex = 0;
    for (std::size_t i = 0; i < segments_.size(); ++i) {
      const double x = segments_[i].x;
      if (x + w > width_ + kSlack) break;
      double y = 0.0;
      for (std::size_t j = i; j < segments_.size() && segments_[j].x < x + w - kSlack; ++j) y = std::max(y, segments_[j].y);
      if (y + h <= height_ + kSlack && y < bestY) bestY = y, bestX = x, bestIndex = i;
    }
    if (bestY == kInfinity) return false;
    at = Vec2(bestX, bestY);
    const double right = bestX + w;
    std::size_t j = bestIndex;
    while (j < segments_.size() && segments_[j].x + segments_[j].w <= right + kSlack) ++j;
    if (j < segments_.size() && segments_[j].x < right) {
      segments_[j].w -= right - segments_[j].x;
      segments_[j].x = right;
    }
    segments_.erase(segments_.begin() + std::ptrdiff_t(bestIndex), segments_.begin() + std::ptrdiff_t(j));
    segments_.insert(segments_.begin() + std::ptrdiff_t(bestIndex), Segment{bestX, bestY + h, w});
    if (bestIndex + 1 < segments_.size() && segments_[bestIndex + 1].y == segments_[bestIndex].y) {
      segments_[bestIndex].w += segments_[bestIndex + 1].w;
      segments_.erase(segments_.begin() + std::ptrdiff_t(bestIndex) + 1);
    }
    if (bestIndex > 0 && segments_[bestIndex - 1].y == segments_[bestIndex].y) {
      segments_[bestIndex - 1].w += segments_[bestIndex].w;
      segments_.erase(segments_.begin() + std::ptrdiff_t(bestIndex));
    }
    return true;
  }

 private:
  struct Segment {
    double x, y, w;
  };
  double width_, height_;
  std::vector<Segment> segments_;
};

struct Placement {
  Vec2 at;  // the box's lower left corner in the tile, in texels
  int tile;
};

// Packs boxes of size * density + margin (texels) in `order` into tiles of W x H less the margin
// along the left and bottom border. With one tile only, false when they do not all fit.
bool pack(const std::vector<Vec2>& sizes, const std::vector<int>& order, double density, double margin,
          const std::array<int, 2>& texture, bool manyTiles, std::vector<Placement>& out) {
  out.assign(sizes.size(), Placement{Vec2::Zero(), 0});
  const double binW = double(texture[0]) - margin, binH = double(texture[1]) - margin;
  Skyline skyline(binW, binH);
  int tile = 0;
  for (const int c : order) {
    const double w = sizes[std::size_t(c)].x() * density + margin, h = sizes[std::size_t(c)].y() * density + margin;
    Vec2 at;
    if (!skyline.place(w, h, at)) {
      if (!manyTiles) return false;
      skyline = Skyline(binW, binH);
      ++tile;
      if (!skyline.place(w, h, at)) return false;
    }
    out[std::size_t(c)] = Placement{at + Vec2(margin, margin), tile};
  }
  return true;
}

double segmentDistance(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (((o1 > 0) != (o2 > 0)) && ((o3 > 0) != (o4 > 0)) && o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0) return 0.0;
  const auto pointSegment = [](const Point2& p, const Point2& s, const Point2& t) {
    const Vec2 st = t - s;
    const double length2 = st.squaredNorm();
    const double u = length2 > 0.0 ? std::clamp((p - s).dot(st) / length2, 0.0, 1.0) : 0.0;
    return (p - (s + u * st)).norm();
  };
  return std::min({pointSegment(a, c, d), pointSegment(b, c, d), pointSegment(c, a, b), pointSegment(d, a, b)});
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

Atlas makeAtlas(const Mesh& mesh, const AtlasOptions& options) {
  checkAtlasOptions(options);
  const std::size_t faceCount = mesh.faceCount();
  Atlas atlas;
  atlas.stretchBound = 1.0 / std::cos(options.angleLimitDegrees * kPi / 180.0);
  if (faceCount == 0) return atlas;

  // The faces' unit normals and areas; degenerate faces have neither.
  std::vector<Vec3> normals(faceCount, Vec3::Zero());
  std::vector<double> areas(faceCount, 0.0);
  std::vector<char> degenerate(faceCount, 0);
  std::vector<int> byArea;
  Eigen::AlignedBox3d bounds;
  for (const Vec3& p : mesh.positions) bounds.extend(p);
  const Vec3 origin = bounds.center();
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
  std::vector<std::array<Point2, 3>> projected(faceCount);
  for (const int f : byArea) {
    double best = -kInfinity;
    for (std::size_t d = 0; d < directions.size(); ++d) {
      const double cosine = normals[std::size_t(f)].dot(directions[d]);
      if (cosine > best) best = cosine, directionOf[std::size_t(f)] = int(d);
    }
    for (int k = 0; k < 3; ++k)
      projected[std::size_t(f)][std::size_t(k)] =
          frames[std::size_t(directionOf[std::size_t(f)])] * (mesh.positions[std::size_t(mesh.triangles[std::size_t(f)][k])] - origin);
  }

  // Charts: the faces of one direction joined across manifold edges, in face order; a chart whose
  // projection overlaps itself is grown again face by face, each face joining only if it overlaps
  // none of the chart so far, and what is left seeds further charts.
  const EdgeTable edges(mesh);
  const std::vector<std::array<int, 3>> neighbours = manifoldNeighbours(edges, faceCount);
  std::vector<int> chartOf(faceCount, -1);
  std::vector<int> tried(faceCount, -1);  // the last chart that tested the face and refused it
  int charts = 0;
  std::vector<int> component, queue;
  for (std::size_t seed = 0; seed < faceCount; ++seed) {
    if (degenerate[seed] || chartOf[seed] >= 0) continue;
    component.assign(1, int(seed));
    const int first = charts;
    chartOf[seed] = first;
    for (std::size_t i = 0; i < component.size(); ++i)
      for (const int g : neighbours[std::size_t(component[i])])
        if (g >= 0 && chartOf[std::size_t(g)] < 0 && directionOf[std::size_t(g)] == directionOf[seed]) {
          chartOf[std::size_t(g)] = first;
          component.push_back(g);
        }
    ++charts;
    if (component.size() < 3) continue;  // two faces across an edge, both facing the direction, cannot overlap
    const FaceGrid grid(component, projected);
    if (!overlapsItself(grid, projected)) continue;
    for (const int f : component) chartOf[std::size_t(f)] = -1;
    charts = first;
    for (const int start : component) {
      if (chartOf[std::size_t(start)] >= 0) continue;
      const int chart = charts++;
      chartOf[std::size_t(start)] = chart;
      queue.assign(1, start);
      for (std::size_t i = 0; i < queue.size(); ++i)
        for (const int g : neighbours[std::size_t(queue[i])]) {
          if (g < 0 || chartOf[std::size_t(g)] >= 0 || tried[std::size_t(g)] == chart ||
              directionOf[std::size_t(g)] != directionOf[seed])
            continue;
          bool overlaps = false;
          grid.forCells(projected[std::size_t(g)], [&](std::size_t c) {
            for (const int* h = grid.begin(c); h != grid.end(c) && !overlaps; ++h)
              overlaps = chartOf[std::size_t(*h)] == chart &&
                         interiorsOverlap(projected[std::size_t(g)], projected[std::size_t(*h)]);
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

  // Each chart's corners in its direction's plane, turned to their smallest box.
  const std::size_t chartCount = std::size_t(charts);
  atlas.charts.assign(chartCount, AtlasChart{});
  std::vector<std::vector<Point2>> chartPoints(chartCount);
  for (std::size_t f = 0; f < faceCount; ++f) {
    const int c = chartOf[f];
    for (int k = 0; k < 3; ++k)
      chartPoints[std::size_t(c)].push_back(frames[std::size_t(chartDirection[std::size_t(c)])] *
                                            (mesh.positions[std::size_t(mesh.triangles[f][k])] - origin));
    ++atlas.charts[std::size_t(c)].faces;
  }
  std::vector<Eigen::Matrix2d> rotation(chartCount);
  std::vector<Vec2> low(chartCount), size(chartCount);
  for (std::size_t c = 0; c < chartCount; ++c) {
    rotation[c] = smallestBoxRotation(convexHull(chartPoints[c]));
    Eigen::AlignedBox2d box;
    for (const Point2& p : chartPoints[c]) box.extend(rotation[c] * p);
    low[c] = box.min();
    size[c] = box.sizes();
    std::vector<Point2>().swap(chartPoints[c]);
  }

  // One density for every chart: the largest at which all fit (bisection between no area and
  // the area bound), or the one asked for, over as many tiles as it takes.
  std::vector<int> order(chartCount);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return size[std::size_t(a)].y() != size[std::size_t(b)].y() ? size[std::size_t(a)].y() > size[std::size_t(b)].y()
                                                                 : size[std::size_t(a)].x() > size[std::size_t(b)].x();
  });
  const double margin = options.marginTexels;
  const double binW = double(options.textureSize[0]) - margin, binH = double(options.textureSize[1]) - margin;
  std::vector<Placement> placements;
  double density = 0.0;
  if (options.texelsPerUnit) {
    density = *options.texelsPerUnit;
    for (std::size_t c = 0; c < chartCount; ++c)
      if (size[c].x() * density + margin > binW || size[c].y() * density + margin > binH)
        throw UsageError("--texels-per-unit " + std::to_string(density) + ": a chart of " +
                         std::to_string(atlas.charts[c].faces) + " faces needs " +
                         std::to_string(int(std::ceil(size[c].x() * density))) + " x " +
                         std::to_string(int(std::ceil(size[c].y() * density))) +
                         " texels, more than one texture less its margins holds");
    pack(size, order, density, margin, options.textureSize, true, placements);
  } else {
    if (!pack(size, order, 0.0, margin, options.textureSize, false, placements))
      throw UsageError(std::to_string(charts) + " charts with " + std::to_string(margin) +
                       " texels of margin each do not fit a " + std::to_string(options.textureSize[0]) + " x " +
                       std::to_string(options.textureSize[1]) +
                       " texture even at no size: give a larger --texture-size or a smaller --margin");
    double area = 0.0, high = kInfinity;
    for (std::size_t c = 0; c < chartCount; ++c) {
      area += size[c].x() * size[c].y();
      if (size[c].x() > 0.0) high = std::min(high, (binW - margin) / size[c].x());
      if (size[c].y() > 0.0) high = std::min(high, (binH - margin) / size[c].y());
    }
    if (area > 0.0) high = std::min(high, std::sqrt(binW * binH / area));
    if (!std::isfinite(high)) high = 1.0;  // nothing has extent: any density will do
    double lowDensity = 0.0;
    std::vector<Placement> trial;
    if (pack(size, order, high, margin, options.textureSize, false, trial)) {
      lowDensity = high;
    } else {
      for (int step = 0; step < 40 && high - lowDensity > 1e-6 * high; ++step) {
        const double mid = 0.5 * (lowDensity + high);
        (pack(size, order, mid, margin, options.textureSize, false, trial) ? lowDensity : high) = mid;
      }
    }
    density = lowDensity;
    pack(size, order, density, margin, options.textureSize, false, placements);
  }
  atlas.texelsPerUnit = density;

  // The charts' maps: texel = density (R (T (p - origin)) - low) + at, uv = texel / (W, H) + tile.
  const Vec2 perTexel(1.0 / double(options.textureSize[0]), 1.0 / double(options.textureSize[1]));
  for (std::size_t c = 0; c < chartCount; ++c) {
    AtlasChart& chart = atlas.charts[c];
    const Eigen::Matrix<double, 2, 3>& frame = frames[std::size_t(chartDirection[c])];
    chart.direction = frame.row(0).transpose().cross(frame.row(1).transpose());
    chart.origin = origin;
    chart.linear = perTexel.asDiagonal() * (density * rotation[c] * frame);
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
    for (int k = 0; k < 3; ++k) atlas.uv[3 * f + std::size_t(k)] = chart.uvAt(mesh.positions[std::size_t(mesh.triangles[f][k])]);
    uvArea += 0.5 * std::abs(orient(atlas.uv[3 * f], atlas.uv[3 * f + 1], atlas.uv[3 * f + 2]));
  }
  atlas.occupancy = uvArea / double(atlas.tiles);

  // Seams: edges between charts. Gutters: the charts' boundary edges in texels, those of two
  // charts compared where they lie within a few margins of each other.
  const Vec2 texels(double(options.textureSize[0]), double(options.textureSize[1]));
  const auto texelOf = [&](std::size_t corner) {  // in the corner's tile
    const int tile = atlas.charts[std::size_t(atlas.chartOfFace[corner / 3])].tile;
    return Vec2((atlas.uv[corner] - Vec2(double(tile % 10), double(tile / 10))).cwiseProduct(texels));
  };
  struct Boundary {
    Point2 a, b;
    int chart, tile;
  };
  std::vector<Boundary> boundary;
  const auto cornerOf = [&](int face, int vertex) {
    const Triangle& t = mesh.triangles[std::size_t(face)];
    return 3 * std::size_t(face) + std::size_t(t[0] == vertex ? 0 : t[1] == vertex ? 1 : 2);
  };
  for (std::size_t e = 0; e < edges.edgeCount(); ++e) {
    const std::size_t begin = edges.groupStart[e], end = edges.groupStart[e + 1];
    const EdgeTable::HalfEdge& first = edges.halfEdges[begin];
    bool seam = false;
    for (std::size_t i = begin + 1; i < end; ++i)
      seam |= atlas.chartOfFace[std::size_t(edges.halfEdges[i].face)] != atlas.chartOfFace[std::size_t(first.face)];
    if (seam) {
      ++atlas.seamEdges;
      atlas.seamLength += (mesh.positions[std::size_t(first.high)] - mesh.positions[std::size_t(first.low)]).norm();
    }
    for (std::size_t i = begin; i < end; ++i) {
      const int face = edges.halfEdges[i].face, chart = atlas.chartOfFace[std::size_t(face)];
      bool inside = false;  // another face of the same chart across this edge
      for (std::size_t j = begin; j < end; ++j)
        inside |= j != i && atlas.chartOfFace[std::size_t(edges.halfEdges[j].face)] == chart;
      if (!inside)
        boundary.push_back({texelOf(cornerOf(face, first.low)), texelOf(cornerOf(face, first.high)), chart,
                            atlas.charts[std::size_t(chart)].tile});
    }
  }
  atlas.borderTexels = kInfinity;
  for (std::size_t corner = 0; corner < atlas.uv.size(); ++corner) {
    const Vec2 t = texelOf(corner);
    atlas.borderTexels = std::min({atlas.borderTexels, t.x(), t.y(), texels.x() - t.x(), texels.y() - t.y()});
  }
  atlas.gutterTexels = kInfinity;
  const double cell = std::max(4.0 * margin, 16.0);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> cells;
  const auto keyOf = [](int tile, long x, long y) {
    return (std::uint64_t(std::uint32_t(tile)) << 42) | (std::uint64_t(x + 1) << 21) | std::uint64_t(y + 1);
  };
  for (std::size_t s = 0; s < boundary.size(); ++s) {
    const Boundary& b = boundary[s];
    const long x0 = long(std::floor(std::min(b.a.x(), b.b.x()) / cell)), x1 = long(std::floor(std::max(b.a.x(), b.b.x()) / cell));
    const long y0 = long(std::floor(std::min(b.a.y(), b.b.y()) / cell)), y1 = long(std::floor(std::max(b.a.y(), b.b.y()) / cell));
    for (long y = y0; y <= y1; ++y)
      for (long x = x0; x <= x1; ++x) cells.emplace_back(keyOf(b.tile, x, y), std::uint32_t(s));
  }
  std::sort(cells.begin(), cells.end());
  const auto range = [&](std::uint64_t key) {
    return std::equal_range(cells.begin(), cells.end(), std::make_pair(key, std::uint32_t(0)),
                            [](const auto& x, const auto& y) { return x.first < y.first; });
  };
  for (std::size_t i = 0; i < cells.size();) {
    std::size_t j = i;
    while (j < cells.size() && cells[j].first == cells[i].first) ++j;
    const std::uint64_t key = cells[i].first;
    const int tile = int(key >> 42);
    const long x = long((key >> 21) & ((1u << 21) - 1)) - 1, y = long(key & ((1u << 21) - 1)) - 1;
    for (long dy = -1; dy <= 1; ++dy)
      for (long dx = -1; dx <= 1; ++dx) {
        if (x + dx < -1 || y + dy < -1) continue;
        const auto [from, to] = range(keyOf(tile, x + dx, y + dy));
        for (std::size_t a = i; a < j; ++a)
          for (auto b = from; b != to; ++b) {
            const Boundary &p = boundary[cells[a].second], &q = boundary[b->second];
            if (p.chart >= q.chart) continue;
            atlas.gutterTexels = std::min(atlas.gutterTexels, segmentDistance(p.a, p.b, q.a, q.b));
          }
      }
    i = j;
  }
  return atlas;
}

}  // namespace uvtk::param
