#include "analysis/distortion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "core/error.h"
#include "core/libm_simd.h"
#include "core/huge_pages.h"
#include "core/parallel.h"

namespace uvtk::analysis {

namespace {

constexpr double kZeroAreaRelative = 1e-14;  // area <= this times the longest edge squared: zero

// One triangle's areas and normal: what the statuses and the majority vote read.
struct TriangleAreas {
  double area3d = 0.0;
  double signedAreaUv = 0.0;   // positive when the UV corners run counter-clockwise
  double longestEdge3d = 0.0;  // squared lengths, for the zero-area thresholds
  double longestEdgeUv = 0.0;
  Vec3 normal = Vec3::Zero();  // twice the area-weighted normal
};

template <class Point>
double longestSquared(const Point& a, const Point& b, const Point& c) {
  return std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
}

// The corners' positions relative to p0, times the mesh's length scale (exact: a power of two).
struct Edges {
  Vec3 e1, e2;
  Edges(const Vec3& p0, const Vec3& p1, const Vec3& p2, double scale) : e1((p1 - p0) * scale), e2((p2 - p0) * scale) {}
};

TriangleAreas triangleAreas(const Edges& p, const Vec2& t0, const Vec2& t1, const Vec2& t2) {
  const Vec3 p0 = Vec3::Zero(), &p1 = p.e1, &p2 = p.e2;
  TriangleAreas a;
  a.normal = triangleAreaNormal(p0, p1, p2);
  a.area3d = 0.5 * a.normal.stableNorm();  // norm() would square to 0 or inf for edges below 1e-154 or above 1e154
  const Vec2 e1 = t1 - t0, e2 = t2 - t0;
  a.signedAreaUv = 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
  a.longestEdge3d = longestSquared(p0, p1, p2);
  a.longestEdgeUv = longestSquared(t0, t1, t2);
  return a;
}

// The Jacobian J of the linear map surface -> UV of a triangle with non-zero 3D area, in the
// orthonormal frame (e1, e2) of its plane with p0 at the origin. With e2 = n x e1 the corners
// run counter-clockwise in that frame, so det J has the sign of the UV triangle's area.
// `normal` is the triangle's area-weighted normal (TriangleAreas::normal).
Eigen::Matrix2d jacobian(const Edges& p, const Vec3& normal, const Vec2& t0, const Vec2& t1, const Vec2& t2) {
  const Vec3 p0 = Vec3::Zero(), &p1 = p.e1, &p2 = p.e2;
  // Scaled normalisation: the squares of tiny or huge edges and normals would underflow or overflow.
  const Vec3 e1 = (p1 - p0).stableNormalized();
  const Vec3 e2 = normal.stableNormalized().cross(e1);
  Eigen::Matrix2d edges3d, edgesUv;
  edges3d << (p1 - p0).dot(e1), (p2 - p0).dot(e1), 0.0, (p2 - p0).dot(e2);
  edgesUv << t1 - t0, t2 - t0;
  // J takes the triangle's edge vectors to its UV edge vectors: J edges3d = edgesUv.
  return edgesUv * edges3d.inverse();
}

// Singular values of a 2x2 matrix in closed form (Blinn, "Consider the Lowly 2x2 Matrix", IEEE
// CG&A 1996): s1 = Q + R with Q = hypot(e, h), R = hypot(f, g); s2 = det / s1 rather than Q - R,
// which keeps the sign of the determinant and avoids the cancellation. The terms apart, so that
// a block of faces takes its hypotenuses on vectors (core/libm_simd.h: glibc's bits).
struct BlinnTerms {
  double e, f, g, h, det;
};

BlinnTerms blinnTerms(const Eigen::Matrix2d& m) {
  return {0.5 * (m(0, 0) + m(1, 1)), 0.5 * (m(0, 0) - m(1, 1)), 0.5 * (m(1, 0) + m(0, 1)), 0.5 * (m(1, 0) - m(0, 1)),
          m.determinant()};
}

void singularValuesOf(double q, double r, double det, double& s1, double& s2) {
  s1 = q + r;
  s2 = det / s1;
}

void singularValues(const Eigen::Matrix2d& m, double& s1, double& s2) {
  const BlinnTerms b = blinnTerms(m);
  singularValuesOf(std::hypot(b.e, b.h), std::hypot(b.f, b.g), b.det, s1, s2);
}

// Whether singular values measured directly stand: else the face is measured again at unit scale.
bool directlyMeasured(double s1, double s2) { return std::isfinite(s1) && std::isnormal(s2); }

// The singular values of a face's Jacobian (s2 signed as its determinant) for a face whose direct
// ones do not stand. A face far smaller or larger than the mesh (a sliver of a mesh 1e-149 across:
// a determinant of 1e-310 inverted, 1e310 squared) can overflow or underflow on the way to values
// that are themselves representable: it is measured again with its 3D and UV edges each brought
// to about 1 by a power of two (exact), and the values scaled back. Faces measured directly keep
// their bits.
void singularValuesAtUnitScale(const Edges& p, const std::array<Vec2, 3>& t, double& s1, double& s2) {
  const int k3 = std::ilogb(std::max(p.e1.cwiseAbs().maxCoeff(), p.e2.cwiseAbs().maxCoeff()));
  const int kUv = std::ilogb(std::max((t[1] - t[0]).cwiseAbs().maxCoeff(), (t[2] - t[0]).cwiseAbs().maxCoeff()));
  // ldexp per coordinate rather than unitPowerOfTwo's factor: subnormal edges need 2^1074, no double.
  Edges unit = p;
  unit.e1 = p.e1.unaryExpr([&](double x) { return std::ldexp(x, -k3); });
  unit.e2 = p.e2.unaryExpr([&](double x) { return std::ldexp(x, -k3); });
  const auto unitUv = [&](const Vec2& c) { return Vec2((c - t[0]).unaryExpr([&](double x) { return std::ldexp(x, -kUv); })); };
  const Vec3 normal = triangleAreaNormal(Vec3(Vec3::Zero()), unit.e1, unit.e2);
  singularValues(jacobian(unit, normal, Vec2::Zero(), unitUv(t[1]), unitUv(t[2])), s1, s2);
  s1 = std::ldexp(s1, kUv - k3);  // J scales as UV over 3D lengths
  s2 = std::ldexp(s2, kUv - k3);
}

}  // namespace

double log2AreaRatio(double areaUv, double area3d, double surfacePerUv) {
  const double direct = std::log2(areaUv / area3d * surfacePerUv);
  return std::isfinite(direct) ? direct : std::log2(areaUv) - std::log2(area3d) + std::log2(surfacePerUv);
}

const char* toString(FaceStatus status) {
  switch (status) {
    case FaceStatus::Ok: return "ok";
    case FaceStatus::ZeroArea3d: return "zero_area_3d";
    case FaceStatus::ZeroAreaUv: return "zero_area_uv";
    case FaceStatus::Flipped: return "flipped";
    case FaceStatus::Backfacing: return "backfacing";
    case FaceStatus::Invalid: return "invalid";
    case FaceStatus::PoleFace: return "pole_face";
  }
  return "invalid";
}

namespace {

// 1 for a box whose extent lies within 2^-500 .. 2^500, else the power of two that brings it to about 1.
template <class Box>
double scaleOfExtent(const Box& box) {
  if (box.isEmpty()) return 1.0;
  // Halves: the extent of a box spanning -1e308 .. 1e308 does not overflow.
  const double extent = (0.5 * box.max() - 0.5 * box.min()).maxCoeff();
  constexpr double kLow = 0x1p-500, kHigh = 0x1p500;  // about 1e-150 .. 1e150
  return extent >= kLow && extent <= kHigh ? 1.0 : unitPowerOfTwo(extent);
}

}  // namespace

double measureLengthScale(const Mesh& mesh, int threads) {
  return scaleOfExtent(boundsInRanges<Eigen::AlignedBox3d>(
      mesh.positions.size(), threads, [&](Eigen::AlignedBox3d& box, std::size_t i) { box.extend(mesh.positions[i]); }));
}

Eigen::AlignedBox2d validUvBounds(const UvMap& uv, int threads) {
  return boundsInRanges<Bounds2>(uv.uv.size(), threads, [&](Bounds2& box, std::size_t corner) {
           if (uv.cornerValid(corner)) box.extend(uv.uv[corner]);
         }).box();
}

double measureUvScale(const Eigen::AlignedBox2d& validBounds) { return scaleOfExtent(validBounds); }

double measureUvScale(const UvMap& uv, int threads) { return measureUvScale(validUvBounds(uv, threads)); }

namespace {

constexpr std::size_t kFlagChunk = std::size_t(1) << 16;  // faces a thread takes at a time

// Whether a face whose (area-weighted) normal is `normal` points away from where the projector
// looks at face f.
bool facesAway(const Vec3& normal, const ProjectionDirections& directions, std::size_t f) {
  if (!directions.faceProjectionDirections.empty()) return normal.dot(directions.faceProjectionDirections[f]) < 0.0;
  return directions.projectionDirection && normal.dot(*directions.projectionDirection) < 0.0;
}

}  // namespace

void markTurnedAwayFaces(const Mesh& mesh, const ProjectionDirections& directions, UvMap& uv, int threads) {
  const std::size_t faceCount = mesh.triangles.size();
  UVTK_CHECK(uv.faceFlags.size() == faceCount);
  UVTK_CHECK(directions.faceProjectionDirections.empty() || directions.faceProjectionDirections.size() == faceCount);
  if (!directions.projectionDirection && directions.faceProjectionDirections.empty()) return;
  const double scale = measureLengthScale(mesh, threads);  // as measureFaces sees the normals
  parallelFor(int((faceCount + kFlagChunk - 1) / kFlagChunk), threads, [&](int c) {
    for (std::size_t f = std::size_t(c) * kFlagChunk, end = std::min(faceCount, f + kFlagChunk); f < end; ++f) {
      const Triangle& t = mesh.triangles[f];
      const Edges e(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]], scale);
      if (facesAway(triangleAreaNormal(Vec3(Vec3::Zero()), e.e1, e.e2), directions, f)) uv.faceFlags[f] |= kFaceTurnedAway;
    }
  });
}

MeasureScales measureScales(const Mesh& mesh, const UvMap& uv, int threads) {
  return {measureLengthScale(mesh, threads), validUvBounds(uv, threads)};
}

FaceMeasures::FaceMeasures(std::size_t count, int threads) {
  status.assign(count, FaceStatus::Invalid);
  for (std::vector<double>* measure : {&area3d, &areaUv, &sigmaMax, &sigmaMin}) resizeFaultedIn(*measure, count, threads);
}

FaceMeasures::FaceMeasures(const std::vector<FaceDistortion>& faces) {
  for (const FaceDistortion& face : faces) {
    status.push_back(face.status);
    area3d.push_back(face.area3d);
    areaUv.push_back(face.areaUv);
    sigmaMax.push_back(face.sigmaMax);
    sigmaMin.push_back(face.sigmaMin);
  }
}

FaceMeasures measureFaces(const Mesh& mesh, const UvMap& uv, int threads) {
  return measureFaces(mesh, uv, measureScales(mesh, uv, threads), threads);
}

FaceMeasures measureFaces(const Mesh& mesh, const UvMap& uv, const MeasureScales& scales, int threads) {
  const std::size_t faceCount = mesh.triangles.size();
  UVTK_CHECK(uv.uv.size() == 3 * faceCount && uv.faceFlags.size() == faceCount);
  UVTK_CHECK(uv.cornerInvalid.empty() || uv.cornerInvalid.size() == 3 * faceCount);
  const double scale = scales.length, uvScale = scales.uv();
  auto edges = [&](std::size_t f) {
    const Triangle& t = mesh.triangles[f];
    return Edges(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]], scale);
  };
  auto uvCorners = [&](std::size_t f) {  // times uvScale (exact: a power of two)
    return std::array<Vec2, 3>{uv.uv[3 * f] * uvScale, uv.uv[3 * f + 1] * uvScale, uv.uv[3 * f + 2] * uvScale};
  };

  // The faces measured in runs of kRun shared out to the threads (a 10 k-face mesh on every core);
  // the vote added up in fixed chunks of kFacesPerChunk, in face order, whatever the thread count.
  constexpr std::size_t kRun = 4096;
  const auto forEachRun = [&](auto&& work) {
    parallelFor(int((faceCount + kRun - 1) / kRun), threads, [&](int r) {
      const std::size_t begin = std::size_t(r) * kRun;
      work(begin, std::min(faceCount, begin + kRun));
    });
  };
  constexpr std::size_t kChunk = kFacesPerChunk;
  const int chunks = int((faceCount + kChunk - 1) / kChunk);

  // First pass: areas, the statuses that need no mesh-wide decision, and the direct singular
  // values of every face that has a Jacobian, a block of faces at a time: their Jacobians' terms,
  // the hypotenuses on vectors, then each face's values (s2 signed by its own winding until the
  // majority's is known).
  FaceMeasures faces(faceCount, threads);
  FaceStatus* const status = faces.status.data();
  double *const area3d = faces.area3d.data(), *const areaUv = faces.areaUv.data();
  double *const sigmaMax = faces.sigmaMax.data(), *const sigmaMin = faces.sigmaMin.data();
  enum : std::uint8_t { kCounterClockwise = 1, kClockwise = 2, kTurnedAway = 4 };
  std::vector<std::uint8_t> orientation(faceCount, 0);  // of the ok faces, for the second pass
  forEachRun([&](std::size_t begin, std::size_t end) {
    constexpr std::size_t kBlock = 256;
    std::size_t blockFaces[kBlock];
    double e[kBlock], f[kBlock], g[kBlock], h[kBlock], det[kBlock], q[kBlock], r[kBlock];
    for (std::size_t block = begin; block < end; block += kBlock) {
      std::size_t n = 0;
      for (std::size_t face = block; face < std::min(end, block + kBlock); ++face) {
        const std::array<Vec2, 3> t = uvCorners(face);
        const Edges p = edges(face);
        const TriangleAreas a = triangleAreas(p, t[0], t[1], t[2]);
        bool invalid = uv.faceHas(face, kFaceInvalid);
        for (int k = 0; k < 3 && !uv.cornerInvalid.empty(); ++k) invalid = invalid || uv.cornerInvalid[3 * face + k] != 0;
        area3d[face] = a.area3d;
        areaUv[face] = invalid ? 0.0 : std::fabs(a.signedAreaUv);
        if (invalid) {
          status[face] = FaceStatus::Invalid;
        } else if (a.area3d <= kZeroAreaRelative * a.longestEdge3d) {
          status[face] = FaceStatus::ZeroArea3d;
        } else if (areaUv[face] <= kZeroAreaRelative * a.longestEdgeUv) {
          status[face] = FaceStatus::ZeroAreaUv;
        } else {
          status[face] = FaceStatus::Ok;  // until the majority winding is known
          const bool away = uv.faceHas(face, kFaceTurnedAway);  // mirrored by design
          orientation[face] = std::uint8_t((a.signedAreaUv > 0.0 ? kCounterClockwise : 0) |
                                           (a.signedAreaUv < 0.0 ? kClockwise : 0) | (away ? kTurnedAway : 0));
          const BlinnTerms b = blinnTerms(jacobian(p, a.normal, t[0], t[1], t[2]));
          e[n] = b.e, f[n] = b.f, g[n] = b.g, h[n] = b.h, det[n] = b.det;
          blockFaces[n++] = face;
        }
      }
      libm::hypot(e, h, q, n);
      libm::hypot(f, g, r, n);
      for (std::size_t k = 0; k < n; ++k)
        singularValuesOf(q[k], r[k], det[k], sigmaMax[blockFaces[k]], sigmaMin[blockFaces[k]]);
    }
  });
  // Per chunk, the 3D area of the ok faces voting for counter-clockwise UV winding minus the area
  // against it (a face turned away votes the other way: it is mirrored by design).
  std::vector<double> votes(std::size_t(chunks), 0.0);
  parallelFor(chunks, threads, [&](int c) {
    const std::size_t begin = std::size_t(c) * kChunk;
    for (std::size_t f = begin; f < std::min(faceCount, begin + kChunk); ++f)
      if (status[f] == FaceStatus::Ok)
        votes[std::size_t(c)] += ((orientation[f] & kCounterClockwise) != 0) != ((orientation[f] & kTurnedAway) != 0)
                                     ? area3d[f]
                                     : -area3d[f];
  });
  double vote = 0.0;
  for (double v : votes) vote += v;
  const double majority = vote >= 0.0 ? 1.0 : -1.0;

  // Second pass: pole and mirrored faces, and each measured face's values (measured again at unit
  // scale where the direct ones do not stand).
  forEachRun([&](std::size_t begin, std::size_t end) {
    for (std::size_t face = begin; face < end; ++face) {
      if (status[face] != FaceStatus::Ok) continue;
      const bool mirrored = (orientation[face] & (majority > 0.0 ? kClockwise : kCounterClockwise)) != 0;
      if (uv.faceHas(face, kFacePole)) status[face] = FaceStatus::PoleFace;
      else if (mirrored) status[face] = orientation[face] & kTurnedAway ? FaceStatus::Backfacing : FaceStatus::Flipped;
      double s1 = sigmaMax[face], s2 = sigmaMin[face];
      if (!directlyMeasured(s1, s2)) singularValuesAtUnitScale(edges(face), uvCorners(face), s1, s2);
      s2 *= majority;
      // Beyond the doubles even at the face's own scale: its UV triangle is degenerate beside its
      // 3D one (s2 underflows), or the other way round (s1 overflows); it is counted as such.
      if (!std::isnormal(s2) || !std::isfinite(1.0 / s2))
        status[face] = FaceStatus::ZeroAreaUv, s1 = s2 = 0.0;
      else if (!std::isfinite(s1))
        status[face] = FaceStatus::ZeroArea3d, s1 = s2 = 0.0;
      sigmaMax[face] = s1, sigmaMin[face] = s2;
    }
  });

  return faces;
}

AreaTotals okAreaTotals(const FaceMeasures& faces) {
  AreaTotals totals;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (faces.status[f] == FaceStatus::Ok) totals.surface += faces.area3d[f], totals.uv += faces.areaUv[f];
  return totals;
}

}  // namespace uvtk::analysis
