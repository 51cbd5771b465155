#include "param/seams.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include "core/error.h"
#include "core/huge_pages.h"
#include "core/parallel.h"

namespace uvtk::param {

void CornerField::resize(std::size_t faceCount, int threads) {
  resizeFaultedIn(uv, 3 * faceCount, threads);
  state.assign(3 * faceCount, CornerState::Invalid);
  reason.assign(3 * faceCount, kCornerMiss);
  faceFlags.assign(faceCount, kFaceOk);
}

void CornerField::invalidate(std::size_t i, CornerInvalid why) {
  uv[i] = Vec2::Zero();
  state[i] = CornerState::Invalid;
  reason[i] = why;
  faceFlags[i / 3] |= kFaceInvalid;
}

namespace {

constexpr std::size_t kPerRange = std::size_t(1) << 16;  // faces or vertices a thread takes at a time

}  // namespace

UvMap CornerField::toUvMap(int threads) && {
  UvMap map;
  map.uv = std::move(uv);
  map.w = std::move(w);
  map.faceFlags = std::move(faceFlags);
  UVTK_CHECK(state.size() == 3 * map.faceFlags.size());
  map.cornerInvalid.resize(state.size());
  map.cornerPole.resize(state.size());
  const char anyPole = reduceRanges(
      map.faceFlags.size(), kPerRange, threads, char(0),
      [&](char& pole, std::size_t begin, std::size_t end) {
        for (std::size_t i = 3 * begin; i < 3 * end; ++i) {
          map.cornerPole[i] = state[i] == CornerState::Pole;
          pole |= state[i] == CornerState::Pole;
          const bool invalid = state[i] == CornerState::Invalid;
          UVTK_CHECK(invalid == (reason[i] != kCornerValid));
          map.cornerInvalid[i] = reason[i];
          if (invalid) map.uv[i] = Vec2::Zero();
          if (invalid) map.faceFlags[i / 3] |= kFaceInvalid;
        }
      },
      [](char& total, char pole) { total |= pole; });
  if (!anyPole) map.cornerPole = {};
  return map;
}

namespace {

// Twice the signed area of the triangle (0, a, b) in the plane.
double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

bool enclosesAxis(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double ab = cross2(a, b), bc = cross2(b, c), ca = cross2(c, a);
  if (cross2(b - a, c - a) != 0.0)
    return (ab >= 0.0 && bc >= 0.0 && ca >= 0.0) || (ab <= 0.0 && bc <= 0.0 && ca <= 0.0);
  // Collinear corners: the origin must lie on one of the segments.
  auto onSegment = [](const Vec2& p, const Vec2& q) { return cross2(p, q) == 0.0 && p.dot(q) <= 0.0; };
  return onSegment(a, b) || onSegment(b, c) || onSegment(c, a);
}

namespace {

bool isCap(const CornerField& c, std::size_t f) { return (c.faceFlags[f] & kFaceCap) != 0; }

}  // namespace

namespace {

// Which side of the seam a corner lies on: High (u just below uStart + 1), Low (u just above
// uStart, shifted by +1), or On the seam (exactly uStart, or a pole: it belongs to both sides).
enum class Side { High, Low, On };

struct SeamCutter {
  Mesh& mesh;
  CornerField& c;
  double uStart;
  const SeamPointEvaluator& evaluateAt;
  std::vector<Vec3> vertexNormals;  // when the mesh has no normals of its own

  struct CutPoint {
    int vertex;
    int normal;  // index into mesh.normals, or -1
    double v;
  };
  std::unordered_map<std::uint64_t, CutPoint> cutPoints;  // by edge (lower index, higher index)

  Vec3 cornerNormal(std::size_t f, int k) {
    if (mesh.hasNormals() && mesh.cornerNormals[f][k] >= 0) return mesh.normals[mesh.cornerNormals[f][k]];
    if (vertexNormals.empty()) vertexNormals = areaWeightedVertexNormals(mesh);
    return vertexNormals[mesh.triangles[f][k]];
  }

  // The point of edge (corner i, corner j) of face f where the mapping crosses the seam,
  // found by bisection on the side of the mapped u; shared by both faces of the edge.
  CutPoint cut(std::size_t f, int i, int j) {
    int a = mesh.triangles[f][i], b = mesh.triangles[f][j];
    if (a > b) std::swap(a, b), std::swap(i, j);
    const std::uint64_t key = (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
    if (auto found = cutPoints.find(key); found != cutPoints.end()) return found->second;

    const Vec3 pa = mesh.positions[a], pb = mesh.positions[b];
    const Vec3 na = cornerNormal(f, i), nb = cornerNormal(f, j);
    const double middle = uStart + 0.5;
    const bool aLow = c.uv[3 * f + i].x() >= uStart + 1.0;  // shifted corners were the low ones
    double lo = 0.0, hi = 1.0;
    Vec2 uv(0.0, 0.0);
    for (int iteration = 0; iteration < 60 && lo < hi; ++iteration) {
      const double t = 0.5 * (lo + hi);
      if (!evaluateAt((1.0 - t) * pa + t * pb, ((1.0 - t) * na + t * nb).normalized(), uv)) break;
      ((uv.x() < middle) == aLow ? lo : hi) = t;
    }
    const double t = 0.5 * (lo + hi);
    const Vec3 position = (1.0 - t) * pa + t * pb;
    if (!evaluateAt(position, ((1.0 - t) * na + t * nb).normalized(), uv))
      uv.y() = (1.0 - t) * c.uv[3 * f + i].y() + t * c.uv[3 * f + j].y();
    CutPoint point{static_cast<int>(mesh.positions.size()), -1, uv.y()};
    mesh.positions.push_back(position);
    if (mesh.hasNormals()) {
      point.normal = static_cast<int>(mesh.normals.size());
      mesh.normals.push_back(((1.0 - t) * na + t * nb).normalized());
    }
    cutPoints.emplace(key, point);
    return point;
  }
};

}  // namespace

SeamReport repairSeams(Mesh& mesh, CornerField& c, double uStart, SeamMode mode, const SeamPointEvaluator& evaluateAt,
                       int threads) {
  SeamReport report;
  const std::size_t faceCount = mesh.triangles.size();
  std::vector<char> shifted(faceCount, 0);
  // Each face on its own: its corners, its flags, its entry of `shifted`.
  const auto shiftFace = [&](std::size_t f) -> std::size_t {  // 1 for a straddling face
    if (isCap(c, f) || (c.faceFlags[f] & kFaceInvalid)) return 0;
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < 3; ++k)
      if (c.state[3 * f + k] == CornerState::Ok) lo = std::min(lo, c.uv[3 * f + k].x()), hi = std::max(hi, c.uv[3 * f + k].x());
    if (!(hi - lo > 0.5)) return 0;
    c.faceFlags[f] |= kFaceSeamStraddle;
    if (mode == SeamMode::None) return 1;
    double shiftedLo = INFINITY, shiftedHi = -INFINITY;
    for (int k = 0; k < 3; ++k) {
      if (c.state[3 * f + k] != CornerState::Ok) continue;
      const double u = c.uv[3 * f + k].x();
      const double s = u < uStart + 0.5 ? u + 1.0 : u;
      shiftedLo = std::min(shiftedLo, s), shiftedHi = std::max(shiftedHi, s);
    }
    if (shiftedHi - shiftedLo > 0.5) {  // no shift makes it continuous: it winds around the axis
      c.faceFlags[f] |= kFacePole;
      return 1;
    }
    shifted[f] = 1;
    for (int k = 0; k < 3; ++k)
      if (c.state[3 * f + k] == CornerState::Ok && c.uv[3 * f + k].x() < uStart + 0.5) c.uv[3 * f + k].x() += 1.0;
    return 1;
  };
  report.straddlingFaces = reduceRanges(
      faceCount, kPerRange, threads, std::size_t(0),
      [&](std::size_t& straddling, std::size_t begin, std::size_t end) {
        for (std::size_t f = begin; f < end; ++f) straddling += shiftFace(f);
      },
      [](std::size_t& total, std::size_t straddling) { total += straddling; });
  if (mode != SeamMode::Cut || report.straddlingFaces == 0) return report;

  // Cut: split every shifted face whose corners reach past uStart + 1 into the pieces on either
  // side of the seam, and put every u back into [uStart, uStart + 1].
  SeamCutter cutter{mesh, c, uStart, evaluateAt, {}, {}};
  const std::size_t vertexCountBefore = mesh.positions.size();
  std::vector<Triangle> triangles, cornerNormals;
  CornerField out;
  out.resize(0);
  auto emit = [&](const Triangle& t, const Triangle& normals, const Vec2 (&uv)[3], const CornerState (&state)[3],
                  const CornerInvalid (&reason)[3], std::uint8_t flags) {
    triangles.push_back(t);
    if (mesh.hasNormals()) cornerNormals.push_back(normals);
    for (int k = 0; k < 3; ++k) {
      out.uv.push_back(uv[k]);
      out.state.push_back(state[k]);
      out.reason.push_back(reason[k]);
    }
    out.faceFlags.push_back(flags);
  };
  for (std::size_t f = 0; f < faceCount; ++f) {
    const Triangle& t = mesh.triangles[f];
    const Triangle normals = mesh.hasNormals() ? mesh.cornerNormals[f] : Triangle{-1, -1, -1};
    Side side[3];
    bool anyLow = false;
    for (int k = 0; k < 3; ++k) {
      const double u = c.uv[3 * f + k].x();
      side[k] = c.state[3 * f + k] == CornerState::Pole || u == uStart + 1.0 ? Side::On
                : u > uStart + 1.0                                           ? Side::Low
                                                                             : Side::High;
      anyLow |= side[k] == Side::Low;
    }
    if (!shifted[f] || !anyLow) {
      const Vec2 uv[3] = {c.uv[3 * f], c.uv[3 * f + 1], c.uv[3 * f + 2]};
      const CornerState state[3] = {c.state[3 * f], c.state[3 * f + 1], c.state[3 * f + 2]};
      const CornerInvalid reason[3] = {c.reason[3 * f], c.reason[3 * f + 1], c.reason[3 * f + 2]};
      emit(t, normals, uv, state, reason, c.faceFlags[f]);
      continue;
    }
    // Clip the triangle by the seam: one polygon per side, corners in order, cut points between.
    struct Corner {
      int vertex, normal;
      Vec2 uv;
      CornerState state;
      CornerInvalid reason;
    };
    std::vector<Corner> high, low;
    for (int k = 0; k < 3; ++k) {
      const int next = (k + 1) % 3;
      const Vec2 uv = c.uv[3 * f + k];
      const CornerState state = c.state[3 * f + k];
      const CornerInvalid reason = c.reason[3 * f + k];
      if (side[k] != Side::Low)
        high.push_back({t[k], normals[k], {side[k] == Side::On ? uStart + 1.0 : uv.x(), uv.y()}, state, reason});
      if (side[k] != Side::High)
        low.push_back({t[k], normals[k], {side[k] == Side::On ? uStart : uv.x() - 1.0, uv.y()}, state, reason});
      if ((side[k] == Side::High && side[next] == Side::Low) || (side[k] == Side::Low && side[next] == Side::High)) {
        const SeamCutter::CutPoint p = cutter.cut(f, k, next);
        high.push_back({p.vertex, p.normal, {uStart + 1.0, p.v}, CornerState::Ok, kCornerValid});
        low.push_back({p.vertex, p.normal, {uStart, p.v}, CornerState::Ok, kCornerValid});
      }
    }
    for (const std::vector<Corner>* piece : {&high, &low})
      for (std::size_t k = 1; k + 1 < piece->size(); ++k) {
        const Corner& a = (*piece)[0];
        const Corner& b = (*piece)[k];
        const Corner& d = (*piece)[k + 1];
        const Vec2 uv[3] = {a.uv, b.uv, d.uv};
        const CornerState state[3] = {a.state, b.state, d.state};
        const CornerInvalid reason[3] = {a.reason, b.reason, d.reason};
        emit({a.vertex, b.vertex, d.vertex}, {a.normal, b.normal, d.normal}, uv, state, reason, c.faceFlags[f]);
      }
  }
  report.addedVertices = mesh.positions.size() - vertexCountBefore;
  report.addedFaces = triangles.size() - faceCount;
  mesh.triangles = std::move(triangles);
  if (mesh.hasNormals()) mesh.cornerNormals = std::move(cornerNormals);
  c = std::move(out);
  return report;
}

void fanPoleCorners(CornerField& c, int threads) {
  parallelForRanges(c.faceFlags.size(), kPerRange, threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      if (isCap(c, f)) continue;
      double sum = 0.0;
      int count = 0;
      for (int k = 0; k < 3; ++k)
        if (c.state[3 * f + k] == CornerState::Ok) sum += c.uv[3 * f + k].x(), ++count;
      if (count == 0 || count == 3) continue;
      for (int k = 0; k < 3; ++k)
        if (c.state[3 * f + k] == CornerState::Pole) c.uv[3 * f + k].x() = sum / count;
    }
  });
}

MappingSummary summarize(const Mesh& mesh, const CornerField& c, const SeamReport& seams, int threads) {
  MappingSummary s;
  s.vertices = mesh.positions.size();
  s.faces = mesh.triangles.size();
  s.straddlingFaces = seams.straddlingFaces;
  s.addedVertices = seams.addedVertices;
  s.addedFaces = seams.addedFaces;

  // Counted in ranges of faces, then of vertices; the lists joined in range order, ascending.
  struct Counts {
    std::vector<int> list, other;  // faces: pole faces; vertices: pole vertices, invalid vertices
    std::size_t invalidFaces = 0, cubeSeamFaces = 0, capFaces = 0;
    std::array<std::size_t, kCornerInvalidCount> invalidCorners{};
  };
  const auto join = [](Counts& total, const Counts& part) {
    total.list.insert(total.list.end(), part.list.begin(), part.list.end());
    total.other.insert(total.other.end(), part.other.begin(), part.other.end());
    total.invalidFaces += part.invalidFaces, total.cubeSeamFaces += part.cubeSeamFaces, total.capFaces += part.capFaces;
    for (std::size_t k = 0; k < total.invalidCorners.size(); ++k) total.invalidCorners[k] += part.invalidCorners[k];
  };
  std::vector<std::uint8_t> vertexState(mesh.positions.size(), 0);  // bit 1: pole, bit 2: invalid
  const Counts faces = reduceRanges(
      mesh.triangles.size(), kPerRange, threads, Counts{},
      [&](Counts& n, std::size_t begin, std::size_t end) {
        for (std::size_t f = begin; f < end; ++f) {
          const std::uint8_t flags = c.faceFlags[f];
          if (flags & kFacePole) n.list.push_back(static_cast<int>(f));
          n.invalidFaces += (flags & kFaceInvalid) ? 1 : 0;
          n.cubeSeamFaces += (flags & kFaceCubeSeam) ? 1 : 0;
          n.capFaces += (flags & kFaceCap) ? 1 : 0;
          for (int k = 0; k < 3; ++k) {
            const CornerState state = c.state[3 * f + k];
            ++n.invalidCorners[state == CornerState::Invalid ? c.reason[3 * f + k] : kCornerValid];
            std::uint8_t& vertex = vertexState[std::size_t(mesh.triangles[f][k])];  // threads may mark one at once
            if (state == CornerState::Pole) orBitsAtomically(vertex, std::uint8_t(1));
            if (state == CornerState::Invalid) orBitsAtomically(vertex, std::uint8_t(2));
          }
        }
      },
      join);
  const Counts vertices = reduceRanges(
      vertexState.size(), kPerRange, threads, Counts{},
      [&](Counts& n, std::size_t begin, std::size_t end) {
        for (std::size_t v = begin; v < end; ++v) {
          if (vertexState[v] & 1) n.list.push_back(static_cast<int>(v));
          if (vertexState[v] & 2) n.other.push_back(static_cast<int>(v));
        }
      },
      join);
  s.poleFaceList = faces.list;
  s.invalidFaces = faces.invalidFaces, s.cubeSeamFaces = faces.cubeSeamFaces, s.capFaces = faces.capFaces;
  s.invalidCorners = faces.invalidCorners;
  s.poleVertexList = vertices.list;
  s.invalidVertexList = vertices.other;
  s.poleFaces = s.poleFaceList.size();
  s.poleVertices = s.poleVertexList.size();
  s.invalidVertices = s.invalidVertexList.size();
  return s;
}

}  // namespace uvtk::param
