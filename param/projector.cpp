#include "param/projector.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/error.h"
#include "param/seams.h"
#include "param/surfaces.h"

namespace uvtk::param {

bool UvTransform::isIdentity() const {
  return scale == Vec2::Ones() && offset == Vec2::Zero() && rotateDegrees == 0.0 && !flipU && !flipV;
}

Vec2 UvTransform::apply(const Vec2& uv) const {
  Vec2 r(flipU ? 1.0 - uv.x() : uv.x(), flipV ? 1.0 - uv.y() : uv.y());
  r = r.cwiseProduct(scale);
  if (rotateDegrees != 0.0) {
    const double a = rotateDegrees * (kPi / 180.0), c = std::cos(a), s = std::sin(a);
    const Vec2 d = r - Vec2(0.5, 0.5);
    r = Vec2(0.5 + c * d.x() - s * d.y(), 0.5 + s * d.x() + c * d.y());
  }
  return r + offset;
}

namespace {

// Object-space points and normals carried into the projector's frame.
struct LocalFrame {
  Mat3 linear;
  Vec3 translation;
  Mat3 normalMatrix;  // inverse transpose of `linear`

  explicit LocalFrame(const Affine3& localFromObject)
      : linear(localFromObject.linear()),
        translation(localFromObject.translation()),
        normalMatrix(localFromObject.linear().inverse().transpose()) {}

  Vec3 point(const Vec3& p) const { return linear * p + translation; }
  Vec3 normal(const Vec3& n) const {
    const Vec3 m = normalMatrix * n;
    const double length = m.norm();
    return length > 0.0 && std::isfinite(length) ? Vec3(m / length) : Vec3::Zero();
  }
};

Surface makeSurface(const ProjectorOptions& o) {
  switch (o.surface) {
    case SurfaceKind::Plane: return PlaneSurface{};
    case SurfaceKind::TwoPlane: return TwoPlaneSurface(o.planeU, o.planeV);
    case SurfaceKind::Cylinder: return CylinderSurface{};
    case SurfaceKind::Sphere: return SphereSurface{o.spherePreset};
    case SurfaceKind::Cube: return CubeSurface{o.cubeConvention, o.cubeLayout};
  }
  return PlaneSurface{};
}

RayMapping makeRayMapping(const ProjectorOptions& o, const LocalFrame& frame) {
  switch (o.ray) {
    case RayKind::SurfaceNormal: return SurfaceNormalRay{};
    case RayKind::Centroid: return CentroidRay{};
    case RayKind::ObjectNormal: return ObjectNormalRay{};
    case RayKind::Reflection:
      if (!o.eye) throw UsageError("the reflection mapping needs an eye position (--eye x,y,z)");
      return ReflectionRay{frame.point(*o.eye), o.atInfinity};
  }
  return SurfaceNormalRay{};
}

// The whole two-stage mapping of one sample: O-mapping, resolve, pole test, S-mapping.
template <class S, class M>
inline VertexUv evaluateSample(const S& surface, const M& mapping, const Sample& sample, PoleTest isPole) {
  VertexUv out;
  const std::optional<Vec3> q = surface.resolve(mapping.probe(sample));
  if (!q || !q->allFinite()) return out;
  out.axial = Vec2(q->x(), q->y());
  if constexpr (S::kWraps) {
    if (isPole(radialDistance(q->x(), q->y()), q->z())) {
      out.uv = Vec2(0.0, surface.vAt(*q));
      out.state = std::isfinite(out.uv.y()) ? CornerState::Pole : CornerState::Invalid;
      return out;
    }
  }
  const Vec2 uv = surface.uvAt(*q);
  if (uv.allFinite()) {
    out.uv = uv;
    out.state = CornerState::Ok;
  }
  return out;
}

// The hot loop: `count` samples, the i-th at object-space position(i) with normal(i).
template <class S, class M, class PositionOf, class NormalOf>
void evaluateSamples(const S& surface, const M& mapping, const LocalFrame& frame, PoleTest isPole,
                     std::size_t count, PositionOf position, NormalOf normal, VertexUv* out) {
  for (std::size_t i = 0; i < count; ++i) {
    Sample sample{frame.point(position(i)), Vec3::Zero()};
    if constexpr (M::kNeedsNormal) sample.n = frame.normal(normal(i));
    out[i] = evaluateSample(surface, mapping, sample, isPole);
  }
}

// Evaluates a sample at an object-space point and normal (the seam cut's new vertices).
using PointEvaluator = std::function<VertexUv(const Vec3& position, const Vec3& normal)>;

struct Evaluated {
  CornerField corners;
  PointEvaluator evaluateAt;
};

// The cube: a face per triangle, then each corner projected onto it by its own probe.
template <class M>
void evaluateCube(const CubeSurface& surface, const M& mapping, const Mesh& mesh, const LocalFrame& frame,
                  const std::vector<Vec3>& normals, bool perCorner, CornerField& c) {
  const std::size_t faceCount = mesh.triangles.size();
  c.w.resize(3 * faceCount);
  for (std::size_t f = 0; f < faceCount; ++f) {
    const Triangle& t = mesh.triangles[f];
    Probe probes[3];
    Probe mean{};
    Sample samples[3];
    for (int k = 0; k < 3; ++k) {
      samples[k] = Sample{frame.point(mesh.positions[t[k]]), Vec3::Zero()};
      if constexpr (M::kNeedsNormal) samples[k].n = frame.normal(normals[perCorner ? 3 * f + k : t[k]]);
      probes[k] = mapping.probe(samples[k]);
      mean.kind = probes[k].kind;
      mean.point += probes[k].point / 3.0;
      mean.direction += probes[k].direction / 3.0;
    }
    const Vec3 faceNormal = triangleAreaNormal(samples[0].p, samples[1].p, samples[2].p);
    const std::optional<CubeFace> face = surface.chooseFace(mean, faceNormal);
    const std::optional<CubeFace> first = surface.cornerFace(probes[0]);
    for (int k = 0; k < 3; ++k) {
      const std::size_t corner = 3 * f + k;
      if (k > 0 && surface.cornerFace(probes[k]) != first) c.faceFlags[f] |= kFaceCubeSeam;
      const std::optional<Vec2> st = face ? surface.projectOnFace(probes[k], *face) : std::nullopt;
      c.w[corner] = face ? static_cast<double>(*face) : 0.0;
      if (!st || !st->allFinite()) {
        c.uv[corner] = Vec2::Zero();
        c.faceFlags[f] |= kFaceInvalid;
        continue;
      }
      c.uv[corner] = surface.uvAt(*st, *face);
      c.state[corner] = CornerState::Ok;
    }
  }
}

template <class S, class M>
Evaluated evaluateCorners(const S& surface, const M& mapping, const Mesh& mesh, const LocalFrame& frame,
                          const ProjectorOptions& o) {
  const std::size_t faceCount = mesh.triangles.size();
  Evaluated result;
  CornerField& c = result.corners;
  c.resize(faceCount);

  // Normals only when the O-mapping needs them; the file's normals are per corner.
  const bool perCorner = M::kNeedsNormal && mesh.hasNormals();
  std::vector<Vec3> normals;
  if (M::kNeedsNormal) normals = perCorner ? cornerNormals(mesh) : areaWeightedVertexNormals(mesh);

  if constexpr (std::is_same_v<S, CubeSurface>) {
    evaluateCube(surface, mapping, mesh, frame, normals, perCorner, c);
  } else {
    result.evaluateAt = [&surface, &mapping, frame, isPole = PoleTest(o.poleEpsilon)](const Vec3& position, const Vec3& normal) {
      return evaluateSample(surface, mapping, Sample{frame.point(position), frame.normal(normal)}, isPole);
    };
    const auto& triangles = mesh.triangles;
    std::vector<VertexUv> samples(perCorner ? 3 * faceCount : mesh.positions.size());
    if (perCorner) {
      evaluateSamples(
          surface, mapping, frame, PoleTest(o.poleEpsilon), samples.size(),
          [&](std::size_t i) -> const Vec3& { return mesh.positions[triangles[i / 3][i % 3]]; },
          [&](std::size_t i) -> const Vec3& { return normals[i]; }, samples.data());
    } else {
      evaluateSamples(
          surface, mapping, frame, PoleTest(o.poleEpsilon), samples.size(),
          [&](std::size_t i) -> const Vec3& { return mesh.positions[i]; },
          [&](std::size_t i) -> const Vec3& { return normals[i]; }, samples.data());
    }
    // Spread the samples over the corners and mark invalid and pole faces on the way.
    for (std::size_t f = 0; f < faceCount; ++f) {
      const VertexUv* s[3];
      bool invalid = false, pole = false;
      for (int k = 0; k < 3; ++k) {
        s[k] = &samples[perCorner ? 3 * f + k : triangles[f][k]];
        c.uv[3 * f + k] = s[k]->uv;
        c.state[3 * f + k] = s[k]->state;
        invalid |= s[k]->state == CornerState::Invalid;
        pole |= s[k]->state == CornerState::Pole;
      }
      if (invalid)
        c.faceFlags[f] |= kFaceInvalid;
      else if (S::kWraps && (pole || enclosesAxis(s[0]->axial, s[1]->axial, s[2]->axial)))
        c.faceFlags[f] |= kFacePole;
    }
  }
  return result;
}

// The cylinder cap projection of a local point: orthographic along the axis, (x+1)/2 and (y+1)/2,
// mirrored on the bottom cap (`top` false) so that both read unmirrored seen from outside.
Vec2 capUv(const Vec3& local, bool top) { return Vec2(((top ? 1.0 : -1.0) * local.x() + 1.0) * 0.5, (local.y() + 1.0) * 0.5); }

// Cylinder caps: faces whose normal lies within the cap angle of the axis are mapped by capUv.
void applyCaps(const Mesh& mesh, const LocalFrame& frame, double capAngleDegrees, CornerField& c) {
  const double cosLimit = std::cos(capAngleDegrees * (kPi / 180.0));
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3 p[3] = {frame.point(mesh.positions[t[0]]), frame.point(mesh.positions[t[1]]),
                       frame.point(mesh.positions[t[2]])};
    const Vec3 n = triangleAreaNormal(p[0], p[1], p[2]);
    const double length = n.norm();
    if (!(length > 0.0) || std::fabs(n.z()) < cosLimit * length) continue;
    c.faceFlags[f] = static_cast<std::uint8_t>((c.faceFlags[f] & ~(kFacePole | kFaceInvalid)) | kFaceCap);
    for (int k = 0; k < 3; ++k) {
      const Vec2 uv = capUv(p[k], n.z() > 0.0);
      const bool finite = uv.allFinite();
      c.uv[3 * f + k] = finite ? uv : Vec2::Zero();
      c.state[3 * f + k] = finite ? CornerState::Ok : CornerState::Invalid;
      if (!finite) c.faceFlags[f] |= kFaceInvalid;
    }
  }
}

// Where the u period of a wrapping surface starts (u lies in [start, start + 1)); nothing for
// the surfaces that do not wrap.
std::optional<double> uPeriodStartOf(const Surface& surface) {
  return std::visit(
      [](const auto& s) -> std::optional<double> {
        if constexpr (std::decay_t<decltype(s)>::kWraps) return s.uStart();
        return std::nullopt;
      },
      surface);
}

// The checks of values that no type expresses; throws UsageError.
void checkOptions(const ProjectorOptions& o) {
  if (!(o.poleEpsilon >= 0.0 && o.poleEpsilon < 1.0)) throw UsageError("--pole-eps: expected a number in [0, 1)");
  if (!(o.capAngleDegrees >= 0.0 && o.capAngleDegrees <= 90.0))
    throw UsageError("--cap-angle: expected degrees in [0, 90]");
}

}  // namespace

void mapVertices(const ProjectorOptions& o, const Affine3& localFromObject, const std::vector<Vec3>& positions,
                 const std::vector<Vec3>& normals, std::vector<VertexUv>& out) {
  checkOptions(o);
  const LocalFrame frame(localFromObject);
  const Surface surface = makeSurface(o);
  const RayMapping mapping = makeRayMapping(o, frame);
  out.resize(positions.size());
  std::visit(
      [&](const auto& s, const auto& m) {
        using S = std::decay_t<decltype(s)>;
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<S, CubeSurface>) {
          throw UsageError("the cube projector chooses a face per triangle: map a mesh with project()");
        } else {
          if (M::kNeedsNormal && normals.size() != positions.size())
            throw UsageError("this O-mapping needs one normal per position");
          evaluateSamples(
              s, m, frame, PoleTest(o.poleEpsilon), positions.size(), [&](std::size_t i) -> const Vec3& { return positions[i]; },
              [&](std::size_t i) -> const Vec3& { return normals[i]; }, out.data());
        }
      },
      surface, mapping);
}

PointMapping::PointMapping(const ProjectorOptions& o, const Affine3& localFromObject) : uvTransform_(o.uvTransform) {
  checkOptions(o);
  const LocalFrame frame(localFromObject);
  const Surface surface = makeSurface(o);
  const RayMapping mapping = makeRayMapping(o, frame);
  std::visit(
      [&](const auto& s, const auto& m) {
        using S = std::decay_t<decltype(s)>;
        using M = std::decay_t<decltype(m)>;
        needsNormal_ = M::kNeedsNormal;
        if constexpr (std::is_same_v<S, CubeSurface>) {
          evaluate_ = [s, m, frame](const Vec3& position, const Vec3& normal) {
            VertexUv out;
            const Probe probe = m.probe(Sample{frame.point(position), frame.normal(normal)});
            const std::optional<CubeFace> face = s.cornerFace(probe);
            const std::optional<Vec2> st = face ? s.projectOnFace(probe, *face) : std::nullopt;
            if (!st || !st->allFinite()) return out;
            out.uv = s.uvAt(*st, *face);
            out.state = CornerState::Ok;
            return out;
          };
        } else {
          wrapsU_ = S::kWraps;
          evaluate_ = [s, m, frame, isPole = PoleTest(o.poleEpsilon)](const Vec3& position, const Vec3& normal) {
            return evaluateSample(s, m, Sample{frame.point(position), frame.normal(normal)}, isPole);
          };
        }
      },
      surface, mapping);
  if (o.surface == SurfaceKind::Cylinder && o.cylinderCaps)
    cap_ = [frame](const Vec3& position, const Vec3& normal) {
      return capUv(frame.point(position), frame.normal(normal).z() > 0.0);
    };
}

VertexUv PointMapping::at(const Vec3& position, const Vec3& normal, bool capFace) const {
  VertexUv out;
  if (capFace && cap_) {
    out.uv = cap_(position, normal);
    out.state = out.uv.allFinite() ? CornerState::Ok : CornerState::Invalid;
  } else {
    out = evaluate_(position, normal);
  }
  if (out.state == CornerState::Invalid) return out;
  if (!uvTransform_.isIdentity()) out.uv = uvTransform_.apply(out.uv);
  if (!out.uv.allFinite()) out = VertexUv{};
  return out;
}

Projection project(Mesh mesh, const ProjectorOptions& o) {
  checkOptions(o);
  mesh.texcoords.clear();
  mesh.cornerTexcoords.clear();

  Projection out;
  out.localFromObject = fitPlacement(mesh.positions, o.surface, o.placement);
  const LocalFrame frame(out.localFromObject);
  const Surface surface = makeSurface(o);
  const RayMapping mapping = makeRayMapping(o, frame);

  Evaluated evaluated = std::visit(
      [&](const auto& s, const auto& m) { return evaluateCorners(s, m, mesh, frame, o); }, surface, mapping);
  CornerField& corners = evaluated.corners;

  SeamReport seams;
  if (const std::optional<double> uStart = uPeriodStartOf(surface)) {
    if (o.surface == SurfaceKind::Cylinder && o.cylinderCaps) applyCaps(mesh, frame, o.capAngleDegrees, corners);
    seams = repairSeams(mesh, corners, *uStart, o.seam,
                        [&](const Vec3& p, const Vec3& n, Vec2& uv) {
                          const VertexUv s = evaluated.evaluateAt(p, n);
                          uv = s.uv;
                          return s.state == CornerState::Ok;
                        });
    if (o.pole == PoleMode::Fan) fanPoleCorners(corners);
  }
  out.summary = summarize(mesh, corners, seams);
  if (!o.uvTransform.isIdentity()) {
    bool overflowed = false;
    for (std::size_t i = 0; i < corners.uv.size(); ++i) {
      if (corners.state[i] == CornerState::Invalid) continue;
      corners.uv[i] = o.uvTransform.apply(corners.uv[i]);
      if (corners.uv[i].allFinite()) continue;
      corners.state[i] = CornerState::Invalid;  // a scale or offset that overflows
      corners.faceFlags[i / 3] |= kFaceInvalid;
      overflowed = true;
    }
    if (overflowed) {  // recount the invalid corners; the seam counts needed the untransformed u
      const MappingSummary recount = summarize(mesh, corners, seams);
      out.summary.invalidVertices = recount.invalidVertices;
      out.summary.invalidFaces = recount.invalidFaces;
      out.summary.invalidVertexList = recount.invalidVertexList;
    }
  }
  out.uv = std::move(corners).toUvMap();
  out.mesh = std::move(mesh);
  return out;
}

}  // namespace uvtk::param
