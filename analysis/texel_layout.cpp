#include "analysis/texel_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "core/disjoint_sets.h"
#include "core/cancel.h"
#include "core/error.h"

namespace uvtk::analysis {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr std::int32_t kEmpty = kTexelEmpty, kMixed = kTexelMixed;

bool faceValid(const UvMap& uv, std::size_t f) {
  if (uv.faceHas(f, kFaceInvalid)) return false;
  for (std::size_t k = 0; k < 3; ++k)
    if (!uv.cornerValid(3 * f + k)) return false;
  return true;
}

double orient(const Vec2& p, const Vec2& q, const Vec2& r) {
  return (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
}

// Every edge of every face, as (lower vertex, higher vertex, face, the edge's first corner k),
// sorted: the faces of one edge lie together.
struct EdgeUse {
  int low, high, face, k;
  bool operator<(const EdgeUse& o) const {
    return low != o.low ? low < o.low : high != o.high ? high < o.high : face != o.face ? face < o.face : k < o.k;
  }
};
std::vector<EdgeUse> edgeUses(const Mesh& mesh) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * mesh.faceCount());
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
      if (a != b) uses.push_back({std::min(a, b), std::max(a, b), int(f), k});
    }
  std::sort(uses.begin(), uses.end());
  return uses;
}

// The UV at vertex v of face f.
Vec2 uvAtVertex(const Mesh& mesh, const UvMap& uv, int f, int v) {
  const Triangle& t = mesh.triangles[std::size_t(f)];
  return uv.uv[3 * std::size_t(f) + std::size_t(t[0] == v ? 0 : t[1] == v ? 1 : 2)];
}

bool sameUv(const Vec2& a, const Vec2& b) { return std::abs(a.x() - b.x()) <= 1e-9 && std::abs(a.y() - b.y()) <= 1e-9; }

double segmentDistance(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (((o1 > 0) != (o2 > 0)) && ((o3 > 0) != (o4 > 0)) && o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0) return 0.0;
  const auto pointSegment = [](const Vec2& p, const Vec2& s, const Vec2& t) {
    const Vec2 st = t - s;
    const double length2 = st.squaredNorm();
    const double u = length2 > 0.0 ? std::clamp((p - s).dot(st) / length2, 0.0, 1.0) : 0.0;
    return (p - (s + u * st)).norm();
  };
  return std::min({pointSegment(a, c, d), pointSegment(b, c, d), pointSegment(c, a, b), pointSegment(d, a, b)});
}

// The chart a texel holds, merged with another's: nothing, one chart, or several.
std::int32_t merge(std::int32_t a, std::int32_t b) {
  if (a == kEmpty || a == b) return b;
  if (b == kEmpty) return a;
  return kMixed;
}

// Counts of one level from its texels' charts.
void countLevel(const TexelOwners& texels, TexelLevel& out) {
  for (int y = 0; y < texels.height; ++y)
    for (int x = 0; x < texels.width; ++x) {
      const std::int32_t own = texels.at(x, y);
      out.mapped += own != kEmpty;
      out.overwritten += own == kMixed;
      out.touched += own != kEmpty || texels.touchedOnly(x, y);
      out.clashes += texels.clashes(x, y);
    }
}

// Level 0: each face's texel centres (a centre on an edge shared by two faces goes to one of them:
// the edge's side that runs up, or left along a row), and the count of texels its area meets.
TexelOwners levelZero(const Mesh& mesh, const UvMap& uv, const std::vector<int>& chart, int width, int height,
                      std::size_t* conservative) {
  TexelOwners texels{0, width, height, std::vector<std::int32_t>(std::size_t(width) * std::size_t(height), kEmpty)};
  std::vector<std::uint8_t> met(conservative ? texels.owner.size() : 0, 0);
  const Vec2 size = Vec2(width, height);
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    if (!faceValid(uv, f)) continue;
    std::array<Vec2, 3> p = {uv.uv[3 * f].cwiseProduct(size), uv.uv[3 * f + 1].cwiseProduct(size),
                             uv.uv[3 * f + 2].cwiseProduct(size)};
    const double area = orient(p[0], p[1], p[2]);
    if (!std::isfinite(area)) continue;
    if (area < 0.0) std::swap(p[1], p[2]);
    Eigen::AlignedBox2d box;
    for (const Vec2& q : p) box.extend(q);
    const int x0 = std::max(0, int(std::floor(box.min().x()))), x1 = std::min(width - 1, int(std::floor(box.max().x())));
    const int y0 = std::max(0, int(std::floor(box.min().y()))), y1 = std::min(height - 1, int(std::floor(box.max().y())));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const std::size_t t = std::size_t(y) * std::size_t(width) + std::size_t(x);
        if (conservative) {
          // The texel's square meets the triangle: no edge of the triangle has the whole square
          // strictly outside (the boxes already meet).
          bool meets = area != 0.0;
          for (int i = 0; i < 3 && meets; ++i) {
            const Vec2 &a = p[std::size_t(i)], &b = p[std::size_t((i + 1) % 3)];
            double inside = -kInfinity;
            for (const Vec2& corner : {Vec2(x, y), Vec2(x + 1, y), Vec2(x, y + 1), Vec2(x + 1, y + 1)})
              inside = std::max(inside, orient(a, b, corner));
            meets = inside > 0.0;
          }
          if (meets) met[t] = 1;
        }
        if (area == 0.0) continue;
        const Vec2 centre(x + 0.5, y + 0.5);
        bool in = true;
        for (int i = 0; i < 3 && in; ++i) {
          const Vec2 &a = p[std::size_t(i)], &b = p[std::size_t((i + 1) % 3)];
          const double e = orient(a, b, centre);
          const Vec2 d = b - a;
          in = e > 0.0 || (e == 0.0 && (d.y() > 0.0 || (d.y() == 0.0 && d.x() < 0.0)));
        }
        if (in) texels.owner[t] = merge(texels.owner[t], chart[f]);
      }
  }
  if (conservative) *conservative = std::size_t(std::count(met.begin(), met.end(), std::uint8_t(1)));
  return texels;
}

// The next level: each texel holds every chart its 2 x 2 children hold (GL's box filter).
TexelOwners coarser(const TexelOwners& finer) {
  const int w = finer.width, h = finer.height, nw = std::max(1, w >> 1), nh = std::max(1, h >> 1);
  TexelOwners out{finer.level + 1, nw, nh, std::vector<std::int32_t>(std::size_t(nw) * std::size_t(nh), kEmpty)};
  for (int y = 0; y < nh; ++y)
    for (int x = 0; x < nw; ++x) {
      std::int32_t o = kEmpty;
      for (int cy = 2 * y; cy < std::min(h, 2 * y + 2); ++cy)
        for (int cx = 2 * x; cx < std::min(w, 2 * x + 2); ++cx) o = merge(o, finer.at(cx, cy));
      out.owner[std::size_t(y) * std::size_t(nw) + std::size_t(x)] = o;
    }
  return out;
}

void checkTextureSize(int width, int height) {
  if (width < 1 || height < 1 || width > kMaxTexelSide || height > kMaxTexelSide)
    throw UsageError("--texture-size: the texels of a layout are counted for 1 to 8192 texels a side");
}

// uvCharts and measureGutters on the mesh's sorted edges, made once by texelStatistics for both.
std::vector<int> chartsAlong(const Mesh& mesh, const UvMap& uv, const std::vector<EdgeUse>& uses) {
  DisjointSets sets(mesh.faceCount());
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].low == uses[i].low && uses[j].high == uses[i].high) ++j;
    for (std::size_t a = i; a < j; ++a)
      for (std::size_t b = a + 1; b < j; ++b) {
        const int f = uses[a].face, g = uses[b].face;
        if (!faceValid(uv, std::size_t(f)) || !faceValid(uv, std::size_t(g))) continue;
        const int lo = uses[a].low, hi = uses[a].high;
        if (sameUv(uvAtVertex(mesh, uv, f, lo), uvAtVertex(mesh, uv, g, lo)) &&
            sameUv(uvAtVertex(mesh, uv, f, hi), uvAtVertex(mesh, uv, g, hi)))
          sets.join(std::size_t(f), std::size_t(g));
      }
    i = j;
  }
  std::vector<int> chart(mesh.faceCount(), -1), idOfRoot(mesh.faceCount(), -1);
  int next = 0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    int& id = idOfRoot[sets.find(f)];
    if (id < 0) id = next++;
    chart[f] = id;
  }
  return chart;
}

Gutters guttersAlong(const Mesh& mesh, const UvMap& uv, const std::vector<int>& chartOfFace, int width, int height,
                     const std::vector<EdgeUse>& uses) {
  Gutters g{kInfinity, kInfinity};
  const Vec2 texels = Vec2(width, height);
  // Corners to their tile's border.
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    if (!faceValid(uv, f)) continue;
    for (std::size_t k = 0; k < 3; ++k) {
      const Vec2 p = uv.uv[3 * f + k];
      const Vec2 inTile = (p - Vec2(std::floor(p.x()), std::floor(p.y()))).cwiseProduct(texels);
      g.toBorder = std::min({g.toBorder, inTile.x(), inTile.y(), texels.x() - inTile.x(), texels.y() - inTile.y()});
    }
  }
  // The charts' boundary edges in texels (an edge no other face of the same chart shares at equal
  // UVs): two charts are nearest along them.
  struct Boundary {
    Vec2 a, b;
    int chart;
  };
  std::vector<Boundary> boundary;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].low == uses[i].low && uses[j].high == uses[i].high) ++j;
    for (std::size_t a = i; a < j; ++a) {
      const int f = uses[a].face;
      if (!faceValid(uv, std::size_t(f))) continue;
      const Vec2 pa = uvAtVertex(mesh, uv, f, uses[a].low), pb = uvAtVertex(mesh, uv, f, uses[a].high);
      bool inside = false;
      for (std::size_t b = i; b < j && !inside; ++b) {
        const int other = uses[b].face;
        inside = b != a && faceValid(uv, std::size_t(other)) && chartOfFace[std::size_t(other)] == chartOfFace[std::size_t(f)] &&
                 sameUv(pa, uvAtVertex(mesh, uv, other, uses[a].low)) && sameUv(pb, uvAtVertex(mesh, uv, other, uses[a].high));
      }
      if (!inside) boundary.push_back({pa.cwiseProduct(texels), pb.cwiseProduct(texels), chartOfFace[std::size_t(f)]});
    }
    i = j;
  }
  // Pairs of edges of two charts compared where they lie in neighbouring cells: every pair nearer
  // than a cell is found, so once the nearest pair found is nearer than a cell it is the nearest
  // of all; else the cells grow fourfold and the search runs again (a packed layout ends at once).
  if (boundary.empty()) return g;
  double meanLength = 0.0;
  for (const Boundary& b : boundary) meanLength += (b.b - b.a).norm();
  double best = kInfinity;
  const double widest = 2.0 * std::max(texels.x(), texels.y());
  for (double cell = std::max(1.0, 2.0 * meanLength / double(boundary.size()));; cell *= 4.0) {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> cells;
    const auto cellOf = [cell](double x) {
      return std::int64_t(std::clamp(std::floor(x / cell), -double(1 << 29), double(1 << 29))) + (std::int64_t(1) << 30);
    };
    const auto keyOf = [](std::int64_t x, std::int64_t y) { return (std::uint64_t(x) << 32) | std::uint64_t(y); };
    for (std::size_t s = 0; s < boundary.size(); ++s) {
      const Boundary& b = boundary[s];
      const std::int64_t x0 = cellOf(std::min(b.a.x(), b.b.x())), x1 = cellOf(std::max(b.a.x(), b.b.x()));
      const std::int64_t y0 = cellOf(std::min(b.a.y(), b.b.y())), y1 = cellOf(std::max(b.a.y(), b.b.y()));
      for (std::int64_t y = y0; y <= y1; ++y)
        for (std::int64_t x = x0; x <= x1; ++x) cells.emplace_back(keyOf(x, y), std::uint32_t(s));
    }
    std::sort(cells.begin(), cells.end());
    const auto range = [&](std::uint64_t key) {
      return std::equal_range(cells.begin(), cells.end(), std::make_pair(key, std::uint32_t(0)),
                              [](const auto& x, const auto& y) { return x.first < y.first; });
    };
    for (std::size_t i = 0; i < cells.size();) {
      std::size_t j = i;
      while (j < cells.size() && cells[j].first == cells[i].first) ++j;
      const std::int64_t x = std::int64_t(cells[i].first >> 32), y = std::int64_t(cells[i].first & 0xffffffffu);
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          const auto [from, to] = range(keyOf(x + dx, y + dy));
          for (std::size_t a = i; a < j; ++a)
            for (auto b = from; b != to; ++b) {
              const Boundary &p = boundary[cells[a].second], &q = boundary[b->second];
              if (p.chart >= q.chart) continue;
              const double gapX = std::max({0.0, std::min(p.a.x(), p.b.x()) - std::max(q.a.x(), q.b.x()),
                                            std::min(q.a.x(), q.b.x()) - std::max(p.a.x(), p.b.x())});
              const double gapY = std::max({0.0, std::min(p.a.y(), p.b.y()) - std::max(q.a.y(), q.b.y()),
                                            std::min(q.a.y(), q.b.y()) - std::max(p.a.y(), p.b.y())});
              if (gapX * gapX + gapY * gapY >= best * best) continue;
              best = std::min(best, segmentDistance(p.a, p.b, q.a, q.b));
            }
        }
      i = j;
    }
    if (best <= cell || cell > widest) break;
  }
  g.betweenCharts = best;
  return g;
}

}  // namespace

std::vector<int> uvCharts(const Mesh& mesh, const UvMap& uv) { return chartsAlong(mesh, uv, edgeUses(mesh)); }

Gutters measureGutters(const Mesh& mesh, const UvMap& uv, const std::vector<int>& chartOfFace, int width, int height) {
  return guttersAlong(mesh, uv, chartOfFace, width, height, edgeUses(mesh));
}

bool TexelOwners::clashes(int x, int y) const {
  const std::int32_t own = at(x, y);
  if (own == kMixed) return true;
  if (own == kEmpty) return false;
  for (int ny = std::max(0, y - 1); ny <= std::min(height - 1, y + 1); ++ny)
    for (int nx = std::max(0, x - 1); nx <= std::min(width - 1, x + 1); ++nx) {
      const std::int32_t other = at(nx, ny);
      if (other != kEmpty && other != own) return true;
    }
  return false;
}

bool TexelOwners::touchedOnly(int x, int y) const {
  if (at(x, y) != kEmpty) return false;
  for (int ny = std::max(0, y - 1); ny <= std::min(height - 1, y + 1); ++ny)
    for (int nx = std::max(0, x - 1); nx <= std::min(width - 1, x + 1); ++nx)
      if (at(nx, ny) != kEmpty) return true;
  return false;
}

TexelStatistics texelStatistics(const Mesh& mesh, const UvMap& uv, int width, int height,
                                std::vector<TexelOwners>* levels) {
  checkTextureSize(width, height);
  TexelStatistics out;
  // Each phase is long on a large mesh and single-threaded: a cancellation is seen between them.
  const std::vector<EdgeUse> uses = edgeUses(mesh);
  throwIfCancelled();
  const std::vector<int> chart = chartsAlong(mesh, uv, uses);
  out.charts = chart.empty() ? 0 : std::size_t(*std::max_element(chart.begin(), chart.end()) + 1);
  throwIfCancelled();
  out.gutters = guttersAlong(mesh, uv, chart, width, height, uses);
  throwIfCancelled();

  std::size_t conservative = 0;
  TexelOwners texels = levelZero(mesh, uv, chart, width, height, &conservative);
  for (;;) {
    TexelLevel l;
    l.level = texels.level, l.width = texels.width, l.height = texels.height;
    countLevel(texels, l);
    l.mappedConservative = texels.level == 0 ? conservative : l.mapped;
    l.gutterTexels = std::ldexp(out.gutters.betweenCharts, -texels.level);
    if (!out.firstBleedLevel && l.clashes > 0) out.firstBleedLevel = texels.level;
    out.levels.push_back(l);
    const bool last = texels.width == 1 && texels.height == 1;
    TexelOwners next = last ? TexelOwners{} : coarser(texels);
    if (levels) levels->push_back(std::move(texels));
    if (last) break;
    texels = std::move(next);
  }
  return out;
}

}  // namespace uvtk::analysis
