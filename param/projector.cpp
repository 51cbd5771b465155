#include "param/projector.h"

#include "param/batch_atan2.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>

#include "core/error.h"
#include "core/huge_pages.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/stopwatch.h"
#include "param/sample_evaluator.h"
#include "param/seams.h"
#include "param/uv_kernel.h"

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

// Progress is reported per this many samples (whole blocks of the evaluator) or faces: a cost
// nobody can measure, often enough for a bar.
constexpr std::size_t kSamplesPerReport = std::size_t{1} << 16;

// Evaluates a sample at an object-space point and normal (the seam cut's new vertices).
using PointEvaluator = std::function<VertexUv(const Vec3& position, const Vec3& normal)>;

struct Evaluated {
  CornerField corners;
  PointEvaluator evaluateAt;
  std::array<std::size_t, 3> triplanarFaces{};  // triplanar: faces written by the x, y, z projection
  std::vector<std::uint8_t> triplanarAxis;      // and the projection of each face
  std::optional<Atlas> atlas;                   // the atlas: its charts (its uv moved into corners)
  std::optional<Eigen::AlignedBox3d> sensible;  // the range rule's box the corners were mapped with
};

template <class T>
void mapVerticesThroughKernel(const ProjectorOptions& o, const Affine3& localFromObject,
                              const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                              std::vector<VertexUv>& out, int threads,
                              const std::optional<Eigen::AlignedBox3d>& sensible);

// The cube: a face per triangle, then each corner projected onto it by its own probe.
template <class T, class M>
void evaluateCube(const CubeSurfaceT<T>& surface, const M& mapping, const Mesh& mesh, const LocalFrameT<T>& frame,
                  const std::vector<Vec3>& normals, bool perCorner, const SensibleRangeT<T>& range, CornerField& c) {
  const std::size_t faceCount = mesh.triangles.size();
  c.w.resize(3 * faceCount);
  Progress progress("mapping", faceCount, "faces");
  for (std::size_t f = 0; f < faceCount; ++f) {
    if (f != 0 && f % kSamplesPerReport == 0) progress.advance(kSamplesPerReport);
    const Triangle& t = mesh.triangles[f];
    ProbeT<T> probes[3];
    ProbeT<T> mean{};
    SampleT<T> samples[3];
    for (int k = 0; k < 3; ++k) {
      samples[k] = SampleT<T>{frame.point(mesh.positions[t[k]]), Vec3T<T>::Zero()};
      if constexpr (M::kNeedsNormal) samples[k].n = frame.normal(normals[perCorner ? 3 * f + k : t[k]]);
      probes[k] = mapping.probe(samples[k]);
      mean.kind = probes[k].kind;
      mean.point += probes[k].point / T(3);
      mean.direction += probes[k].direction / T(3);
    }
    const Vec3T<T> faceNormal = triangleAreaNormal(samples[0].p, samples[1].p, samples[2].p);
    const std::optional<CubeFace> face = surface.chooseFace(mean, faceNormal);
    const std::optional<CubeFace> first = surface.cornerFace(probes[0]);
    for (int k = 0; k < 3; ++k) {
      const std::size_t corner = 3 * f + k;
      if (k > 0 && surface.cornerFace(probes[k]) != first) c.faceFlags[f] |= kFaceCubeSeam;
      c.w[corner] = face ? static_cast<double>(*face) : 0.0;
      if (!face) {
        c.invalidate(corner, kCornerMiss);
        continue;
      }
      const HitT<T> hit = surface.projectOnFace(probes[k], *face);
      CornerInvalid reason = judgeHit(hit, range);
      Vec2 uv = Vec2::Zero();
      if (reason == kCornerValid) {
        uv = surface.uvAt(surface.faceSt(hit.q, *face), *face).template cast<double>();
        if (!uv.allFinite()) reason = kCornerNotFinite;
      }
      if (reason != kCornerValid) {
        c.invalidate(corner, reason);
        continue;
      }
      c.uv[corner] = uv;
      c.state[corner] = CornerState::Ok;
      c.reason[corner] = kCornerValid;
    }
  }
}

template <class T, class S, class M>
Evaluated evaluateCorners(const S& surface, const M& mapping, const Mesh& mesh, const Affine3& localFromObject,
                          const ProjectorOptions& o, const std::optional<Eigen::AlignedBox3d>& sensible, int threads) {
  const LocalFrameT<T> frame(localFromObject);
  const SensibleRangeT<T> range(sensible);
  const std::size_t faceCount = mesh.triangles.size();
  Evaluated result;
  CornerField& c = result.corners;
  c.resize(faceCount, threads);

  // Normals only when the O-mapping needs them; the file's normals are per corner.
  const bool perCorner = M::kNeedsNormal && mesh.hasNormals();
  std::vector<Vec3> normals;
  if (M::kNeedsNormal) normals = perCorner ? cornerNormals(mesh) : areaWeightedVertexNormals(mesh);

  if constexpr (std::is_same_v<S, CubeSurfaceT<T>>) {
    evaluateCube(surface, mapping, mesh, frame, normals, perCorner, range, c);
  } else {
    const SampleEvaluator<T, S, M> evaluate(surface, mapping, frame, PoleTest(o.poleEpsilon), o.arithmetic.math,
                                            range);
    result.evaluateAt = [evaluate](const Vec3& position, const Vec3& normal) { return evaluate.at(position, normal); };
    const auto& triangles = mesh.triangles;
    std::vector<VertexUv> samples;
    if (perCorner) {  // the file's normals differ per corner: one sample each
      samples.resize(3 * faceCount);
      Progress progress("mapping", samples.size(), "corners");
      for (std::size_t start = 0; start < samples.size(); start += kSamplesPerReport) {
        const std::size_t count = std::min(kSamplesPerReport, samples.size() - start);
        evaluate(
            count, [&](std::size_t i) -> const Vec3& { return mesh.positions[triangles[(start + i) / 3][(start + i) % 3]]; },
            [&](std::size_t i) -> const Vec3& { return normals[start + i]; }, samples.data() + start);
        progress.advance(count);
      }
    } else {  // the narrow kernel on every vertex, the same bits as `evaluate`
      mapVerticesThroughKernel<T>(o, localFromObject, mesh.positions, normals, samples, threads, sensible);
    }
    // Spread the samples over the corners and mark invalid and pole faces on the way.
    const int chunks = int((faceCount + kSamplesPerReport - 1) / kSamplesPerReport);
    parallelFor(chunks, threads, [&](int chunk) {
      const std::size_t begin = std::size_t(chunk) * kSamplesPerReport;
      for (std::size_t f = begin; f < std::min(faceCount, begin + kSamplesPerReport); ++f) {
        const VertexUv* s[3];
        bool invalid = false, pole = false;
        for (int k = 0; k < 3; ++k) {
          s[k] = &samples[perCorner ? 3 * f + k : triangles[f][k]];
          c.uv[3 * f + k] = s[k]->uv;
          c.state[3 * f + k] = s[k]->state;
          c.reason[3 * f + k] = s[k]->reason;
          invalid |= s[k]->state == CornerState::Invalid;
          pole |= s[k]->state == CornerState::Pole;
        }
        if (invalid)
          c.faceFlags[f] |= kFaceInvalid;
        else if (pole || (S::kTraits.wraps && enclosesAxis(s[0]->axial, s[1]->axial, s[2]->axial)))
          c.faceFlags[f] |= kFacePole;
      }
    });
  }
  return result;
}

// The side of a capped cylinder where CapLayout puts it (§5): beside the caps, v in [0, 1/2].
Vec2 capSideUv(const Vec2& uv, CapLayout layout) {
  return layout == CapLayout::Beside ? Vec2(uv.x(), 0.5 * uv.y()) : uv;
}

// The cylinder cap projection of a local point: orthographic along the axis, (x+1)/2 and (y+1)/2,
// mirrored on the bottom cap (`top` false) so that both read unmirrored seen from outside; then
// where CapLayout puts that cap: beside, the top cap's square [0, 1/2] x [1/2, 1], the bottom's
// [1/2, 1] x [1/2, 1].
template <class T>
Vec2 capUv(const Vec3T<T>& local, bool top, CapLayout layout) {
  const Vec2 square =
      Vec2T<T>(((top ? T(1) : T(-1)) * local.x() + T(1)) * T(0.5), (local.y() + T(1)) * T(0.5)).template cast<double>();
  if (layout == CapLayout::Stacked) return square;
  return Vec2((top ? 0.0 : 0.5) + 0.5 * square.x(), 0.5 + 0.5 * square.y());
}

// The cylinder's caps (Projector::isCap): faces whose object-space normal makes an angle of at
// most the cap angle with the axis.
struct CapTest {
  Vec3 axis;  // unit, object space
  double cosLimit;
  static CapTest of(const Affine3& localFromObject, double capAngleDegrees) {
    return {(inverseAtAnyScale(localFromObject.linear()) * Vec3::UnitZ()).stableNormalized(),
            std::cos(capAngleDegrees * (kPi / 180.0))};
  }
  bool isCap(const Vec3& objectNormal) const {
    // The cosine of the angle with the axis line, |n.a| / |n|; stableNorm: an area normal of a mesh
    // at 1e150 or 1e-150 has a norm whose square overflows or underflows.
    const double length = objectNormal.stableNorm();
    return length > 0.0 && std::fabs(objectNormal.dot(axis)) >= cosLimit * length;
  }
  bool isTop(const Vec3& objectNormal) const { return objectNormal.dot(axis) > 0.0; }  // else the bottom cap
};

// Cylinder caps: the faces CapTest takes are mapped by capUv, whatever the mapping said; the
// others are the side, placed by capSideUv.
template <class T>
void applyCaps(const Mesh& mesh, const LocalFrameT<T>& frame, const CapTest& caps, CapLayout layout,
               CornerField& c) {
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3 normal = triangleAreaNormal(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
    if (!caps.isCap(normal)) {
      for (std::size_t corner = 3 * f; corner < 3 * f + 3; ++corner)
        if (c.state[corner] != CornerState::Invalid) c.uv[corner] = capSideUv(c.uv[corner], layout);
      continue;
    }
    c.faceFlags[f] = static_cast<std::uint8_t>((c.faceFlags[f] & ~(kFacePole | kFaceInvalid)) | kFaceCap);
    for (int k = 0; k < 3; ++k) {
      const std::size_t corner = 3 * f + k;
      const Vec2 uv = capUv(frame.point(mesh.positions[t[k]]), caps.isTop(normal), layout);
      if (!uv.allFinite()) {
        c.invalidate(corner, kCornerNotFinite);
        continue;
      }
      c.uv[corner] = uv;
      c.state[corner] = CornerState::Ok;
      c.reason[corner] = kCornerValid;
    }
  }
}

}  // namespace

std::optional<double> uPeriodStartOf(const ProjectorOptions& o) {
  if (o.surface == SurfaceKind::Cylinder) return CylinderSurface{}.uStart();
  if (o.surface == SurfaceKind::Sphere) return SphereSurface{o.spherePreset}.uStart();
  return std::nullopt;
}

namespace {

// The checks of values that no type expresses; throws UsageError.
void checkOptions(const ProjectorOptions& o) {
  if (!(o.poleEpsilon >= 0.0 && o.poleEpsilon < 1.0)) throw UsageError("--pole-eps: expected a number in [0, 1)");
  if (!(o.capAngleDegrees >= 0.0 && o.capAngleDegrees <= 90.0))
    throw UsageError("--cap-angle: expected degrees in [0, 90]");
  if (o.surface == SurfaceKind::Camera) checkCameraProjector(o.camera);
  if (o.surface == SurfaceKind::Triplanar) checkTriplanarOptions(o.triplanar);
  if (traitsOf(o.surface).chartsFromMesh) checkAtlasOptions(o.atlas);
}

// Thrown where a point alone is mapped: the atlas's charts come from the whole mesh.
void refuseCharts(const ProjectorOptions& o, const char* where) {
  if (traitsOf(o.surface).chartsFromMesh)
    throw UsageError(std::string(where) + ": the atlas makes its charts from a whole mesh; map the mesh (uvtk map)");
}

// A formula's (u, v) as a corner: valid, or invalid with kCornerNotFinite.
VertexUv finiteVertexUv(const Vec2& uv) {
  VertexUv out;
  if (!uv.allFinite()) {
    out.reason = kCornerNotFinite;
    return out;
  }
  out.uv = uv;
  out.state = CornerState::Ok;
  out.reason = kCornerValid;
  return out;
}

// A corner from a per-point formula's value (the camera, triplanar): its UV, or invalid for the value's reason.
void storeCorner(CornerField& c, std::size_t corner, const VertexUv& s) {
  if (s.state == CornerState::Invalid) {
    c.invalidate(corner, s.reason);
    return;
  }
  c.uv[corner] = s.uv;
  c.state[corner] = CornerState::Ok;
  c.reason[corner] = kCornerValid;
}

// The camera projector at every corner (no placement, seam or pole: the one formula per point).
Evaluated evaluateCamera(const Mesh& mesh, const CameraProjector& camera, int threads) {
  const CameraTransform transform(camera);
  const std::size_t faceCount = mesh.triangles.size();
  Evaluated result;
  CornerField& c = result.corners;
  c.resize(faceCount, threads);
  result.evaluateAt = [transform](const Vec3& p, const Vec3&) { return cameraVertexUv(transform, p); };
  const int chunks = int((faceCount + kSamplesPerReport - 1) / kSamplesPerReport);
  parallelFor(chunks, threads, [&](int chunk) {
    const std::size_t begin = std::size_t(chunk) * kSamplesPerReport;
    for (std::size_t f = begin; f < std::min(faceCount, begin + kSamplesPerReport); ++f)
      for (int k = 0; k < 3; ++k) {
        const std::size_t corner = 3 * f + std::size_t(k);
        storeCorner(c, corner, cameraVertexUv(transform, mesh.positions[mesh.triangles[f][k]]));
      }
  });
  return result;
}

// The direction of a triangle's normal, from edges scaled to a largest component of about 1 so
// that the cross product neither overflows (a mesh at 1e200) nor underflows (at 1e-200).
Vec3 faceDirection(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const double largest = std::max(e1.cwiseAbs().maxCoeff(), e2.cwiseAbs().maxCoeff());
  if (!(largest > 0.0) || !std::isfinite(largest)) return e1.cross(e2);
  const int exponent = std::ilogb(largest);
  return Vec3(e1 * std::ldexp(1.0, -exponent)).cross(Vec3(e2 * std::ldexp(1.0, -exponent)));
}

// The triplanar projector at every corner: each face by the projection of its normal's dominant
// axis in the projector's frame (the box mapping an OBJ can hold; the blend is per pixel).
Evaluated evaluateTriplanar(const Mesh& mesh, const Affine3& localFromObject, const TriplanarOptions& options,
                            int threads) {
  const LocalFrameT<double> frame(localFromObject);
  const std::size_t faceCount = mesh.triangles.size();
  Evaluated result;
  CornerField& c = result.corners;
  c.resize(faceCount, threads);
  result.triplanarAxis.resize(faceCount);
  result.evaluateAt = [frame, options](const Vec3& p, const Vec3& n) {
    return triplanarVertexUv(options, dominantAxis(frame.normal(n)), frame.point(p));
  };
  const int chunks = int((faceCount + kSamplesPerReport - 1) / kSamplesPerReport);
  std::vector<std::array<std::size_t, 3>> facesPerAxis(std::size_t(chunks), std::array<std::size_t, 3>{});
  parallelFor(chunks, threads, [&](int chunk) {
    const std::size_t begin = std::size_t(chunk) * kSamplesPerReport;
    for (std::size_t f = begin; f < std::min(faceCount, begin + kSamplesPerReport); ++f) {
      const Triangle& t = mesh.triangles[f];
      const Vec3 normal = frame.normal(faceDirection(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]));
      const int axis = dominantAxis(normal);
      ++facesPerAxis[std::size_t(chunk)][std::size_t(axis)];
      result.triplanarAxis[f] = std::uint8_t(axis);
      for (int k = 0; k < 3; ++k) {
        const std::size_t corner = 3 * f + std::size_t(k);
        storeCorner(c, corner, triplanarVertexUv(options, axis, frame.point(mesh.positions[t[k]])));
      }
    }
  });
  for (const auto& counts : facesPerAxis)
    for (std::size_t a = 0; a < 3; ++a) result.triplanarFaces[a] += counts[a];
  return result;
}

// The atlas's charts at every corner: each valid, the chart's own plane (param/atlas.h).
Evaluated evaluateAtlas(const Mesh& mesh, SurfaceKind surface, AtlasOptions options, int threads) {
  options.chartMap = traitsOf(surface).chartMap;
  Evaluated result;
  CornerField& c = result.corners;
  result.atlas = makeAtlas(mesh, options, threads);
  c.uv = std::move(result.atlas->uv);  // moved, not copied: 16 bytes a corner
  c.state.assign(c.uv.size(), CornerState::Ok);
  c.reason.assign(c.uv.size(), kCornerValid);
  c.faceFlags.assign(mesh.triangles.size(), kFaceOk);
  for (std::size_t corner = 0; corner < c.uv.size(); ++corner)
    if (!c.uv[corner].allFinite()) c.invalidate(corner, kCornerNotFinite);
  return result;
}

// Calls f with a value of the scalar type the precision names (0.0f or 0.0).
template <class F>
decltype(auto) withPrecision(Precision precision, F&& f) {
  return precision == Precision::Float ? f(0.0f) : f(0.0);
}

// Every corner of the mesh through the mapping in precision T, caps included.
template <class T>
Evaluated evaluateMesh(const Mesh& mesh, const Affine3& localFromObject, const ProjectorOptions& o, int threads) {
  const LocalFrameT<T> frame(localFromObject);
  const std::optional<Eigen::AlignedBox3d> sensible = sensibleBox(mesh.positions, o, localFromObject, threads);
  Evaluated evaluated = visitProjector<T>(o, frame, [&](const auto& s, const auto& m) {
    return evaluateCorners<T>(s, m, mesh, localFromObject, o, sensible, threads);
  });
  evaluated.sensible = sensible;
  if (o.surface == SurfaceKind::Cylinder && o.cylinderCaps) {
    applyCaps(mesh, frame, CapTest::of(localFromObject, o.capAngleDegrees), o.capLayout, evaluated.corners);
    // Points on the seam that --seam cut adds lie on the side.
    evaluated.evaluateAt = [side = std::move(evaluated.evaluateAt), layout = o.capLayout](const Vec3& p, const Vec3& n) {
      VertexUv out = side(p, n);
      if (out.state != CornerState::Invalid) out.uv = capSideUv(out.uv, layout);
      return out;
    };
  }
  return evaluated;
}

// mapVertices on the narrow kernel: per run of kRun vertices (a thread's scratch stays in the
// caches), the move to the local frame, the kernel, then the wide records with the exceptions'
// states.
template <class T>
void mapVerticesThroughKernel(const ProjectorOptions& o, const Affine3& localFromObject,
                              const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                              std::vector<VertexUv>& out, int threads,
                              const std::optional<Eigen::AlignedBox3d>& sensible) {
  const UvKernel<T> kernel(o, localFromObject, sensible);
  const bool withNormals = kernel.needsNormals();
  if (withNormals && normals.size() != positions.size())
    throw UsageError("this O-mapping needs one normal per position");
  const LocalFrameT<T> frame(localFromObject);
  const std::size_t n = positions.size();
  resizeFaultedIn(out, n, threads);
  const int chunks = threadCount(threads);
  const std::size_t size = (n / std::size_t(chunks) + 255) / 256 * 256;
  parallelFor(chunks, chunks, [&](int chunk) {
    constexpr std::size_t kRun = 4096;
    const std::size_t begin = std::min(n, std::size_t(chunk) * size);
    const std::size_t end = chunk + 1 == chunks ? n : std::min(n, begin + size);
    // Ten arrays of a run, left unset (every value is written before it is read): a small mesh's
    // map touches only the pages its vertices need.
    const std::size_t run = std::min(kRun, end - begin);
    const std::unique_ptr<T[]> scratch(new T[10 * run]);
    std::vector<UvException> exceptions;
    for (std::size_t start = begin; start < end; start += run) {
      KernelSpan<T> span;
      span.count = std::min(run, end - start);
      T* x = scratch.get();
      T *y = x + run, *z = y + run, *nx = z + run, *ny = nx + run, *nz = ny + run;
      span.x = x, span.y = y, span.z = z;
      span.u = nz + run, span.v = span.u + run, span.axialX = span.v + run, span.axialY = span.axialX + run;
      for (std::size_t i = 0; i < span.count; ++i) {
        const Vec3T<T> p = frame.point(positions[start + i]);
        x[i] = p.x(), y[i] = p.y(), z[i] = p.z();
      }
      if (withNormals) {
        span.nx = nx, span.ny = ny, span.nz = nz;
        for (std::size_t i = 0; i < span.count; ++i) {
          const Vec3T<T> m = frame.normal(normals[start + i]);
          nx[i] = m.x(), ny[i] = m.y(), nz[i] = m.z();
        }
      }
      kernel.run(span, start, exceptions);
      for (std::size_t i = 0; i < span.count; ++i)
        out[start + i] = VertexUv{Vec2(double(span.u[i]), double(span.v[i])),
                                  Vec2(double(span.axialX[i]), double(span.axialY[i])), CornerState::Ok, kCornerValid};
      for (const UvException& e : exceptions) out[e.index].state = e.state, out[e.index].reason = e.reason;
      exceptions.clear();
    }
  });
}

}  // namespace

std::optional<Eigen::AlignedBox3d> sensibleBox(const std::vector<Vec3>& positions, const ProjectorOptions& o,
                                               const Affine3& localFromObject, int threads) {
  const LocalFrameT<double> frame(localFromObject);  // the local positions the mapping itself sees
  Eigen::AlignedBox3d box = boundsInRanges<Eigen::AlignedBox3d>(
      positions.size(), threads, [&](Eigen::AlignedBox3d& b, std::size_t i) { b.extend(frame.point(positions[i])); });
  switch (traitsOf(o.surface).shape) {  // the unit shape the fits put the mesh on (§2)
    case UnitShape::Plane:
      box.extend(Vec3(0, 0, 0)).extend(Vec3(1, 1, 0));
      break;
    case UnitShape::Cylinder:
      box.extend(Vec3(-1, -1, 0)).extend(Vec3(1, 1, 1));
      break;
    case UnitShape::Ball:
    case UnitShape::Cube:
      box.extend(Vec3(-1, -1, -1)).extend(Vec3(1, 1, 1));
      break;
    case UnitShape::None:  // object space (two-plane; the camera is caught below): no unit shape
      if (traitsOf(o.surface).isPerspective) return std::nullopt;  // no surface to hit: nothing is out of range
      break;
    case UnitShape::Box:  // triplanar: three planes, every hit in range
      return std::nullopt;
  }
  if (box.isEmpty() || !box.sizes().allFinite() || !(box.sizes().maxCoeff() > 0.0)) return std::nullopt;
  return box;
}

VertexUv triplanarVertexUv(const TriplanarOptions& options, int axis, const Vec3& local) {
  return finiteVertexUv(triplanarUv(options, axis, local));
}

VertexUv cameraVertexUv(const CameraTransform& camera, const Vec3& position) {
  VertexUv out;
  const Vec4 h = camera.homogeneous(position);
  if (!h.allFinite()) {
    out.reason = kCornerNotFinite;
    return out;
  }
  if (!(h.w() > 0.0)) {
    out.reason = kCornerBehind;
    return out;
  }
  return finiteVertexUv(Vec2(h.x() / h.w(), h.y() / h.w()));  // not finite: a q so small that the divide overflows
}

Projector::Projector(const ProjectorOptions& o, const Affine3& localFromObject,
                     const std::optional<Eigen::AlignedBox3d>& sensible)
    : options_(o), localFromObject_(localFromObject), sensible_(sensible) {
  checkOptions(o);
  refuseCharts(o, "a projector of points");
  prepareAtan2(o.arithmetic.math);
  const CapTest caps = CapTest::of(localFromObject, o.capAngleDegrees);
  capAxis_ = caps.axis;
  capCosLimit_ = caps.cosLimit;
  const auto ofVertex = [](const VertexUv& v) { return PointUv{v.uv, v.uv, v.axial, v.state, v.reason, std::nullopt}; };
  if (o.surface == SurfaceKind::Camera) {
    point_ = [ofVertex, camera = CameraTransform(o.camera)](const Vec3& p, const Vec3&) {
      return ofVertex(cameraVertexUv(camera, p));
    };
    return;
  }
  if (o.surface == SurfaceKind::Triplanar) {
    needsNormal_ = true;
    const LocalFrameT<double> frame(localFromObject);
    point_ = [ofVertex, frame, options = o.triplanar](const Vec3& p, const Vec3& n) {
      return ofVertex(triplanarVertexUv(options, dominantAxis(frame.normal(n)), frame.point(p)));
    };
    blend_ = [frame, options = o.triplanar, transform = o.uvTransform](const Vec3& p, const Vec3& n) {
      TriplanarSample s = triplanarAt(options, frame.point(p), frame.normal(n));
      if (!transform.isIdentity())
        for (Vec2& uv : s.uv) uv = transform.apply(uv);
      return s;
    };
    return;
  }
  withPrecision(o.arithmetic.precision, [&](auto zero) {
    using T = decltype(zero);
    const LocalFrameT<T> frame(localFromObject);
    const SensibleRangeT<T> range(sensible);
    visitProjector<T>(o, frame, [&](const auto& s, const auto& m) {
      using S = std::decay_t<decltype(s)>;
      using M = std::decay_t<decltype(m)>;
      needsNormal_ = M::kNeedsNormal;
      if constexpr (std::is_same_v<S, CubeSurfaceT<T>>) {
        point_ = [s, m, frame, range](const Vec3& position, const Vec3& normal) {
          PointUv out;
          const ProbeT<T> probe = m.probe(SampleT<T>{frame.point(position), frame.normal(normal)});
          out.cubeFace = s.cornerFace(probe);
          if (!out.cubeFace) return out;  // a miss
          const HitT<T> hit = s.projectOnFace(probe, *out.cubeFace);
          out.reason = judgeHit(hit, range);
          if (out.reason != kCornerValid) return out;
          const Vec2T<T> st = s.faceSt(hit.q, *out.cubeFace);
          const Vec2 uv = s.uvAt(st, *out.cubeFace).template cast<double>();
          if (!uv.allFinite()) {
            out.reason = kCornerNotFinite;
            return out;
          }
          out.uv = uv;
          out.unplaced = st.template cast<double>();
          out.state = CornerState::Ok;
          return out;
        };
      } else {
        const SampleEvaluator<T, S, M> evaluate(s, m, frame, PoleTest(o.poleEpsilon), o.arithmetic.math, range);
        point_ = [ofVertex, evaluate](const Vec3& position, const Vec3& normal) {
          return ofVertex(evaluate.at(position, normal));
        };
      }
    });
    if (o.surface == SurfaceKind::Cylinder && o.cylinderCaps)
      cap_ = [frame, caps, layout = o.capLayout](const Vec3& position, const Vec3& normal) {
        return capUv(frame.point(position), caps.isTop(normal), layout);
      };
  });
}

Vec2 Projector::period() const {
  if (!traits().wraps) return Vec2::Zero();
  return options_.uvTransform.apply(Vec2(1, 0)) - options_.uvTransform.apply(Vec2(0, 0));
}

bool Projector::isCap(const Vec3& objectNormal) const {
  return CapTest{capAxis_, capCosLimit_}.isCap(objectNormal);
}

void Projector::mapVertices(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                            std::vector<VertexUv>& out, int threads) const {
  const ProjectorOptions& o = options_;
  if (o.surface == SurfaceKind::Camera) {
    const CameraTransform camera(o.camera);
    resizeFaultedIn(out, positions.size(), threads);
    parallelFor(threadCount(threads), threads, [&](int chunk) {
      const std::size_t n = positions.size(), chunks = std::size_t(threadCount(threads));
      for (std::size_t i = n * std::size_t(chunk) / chunks; i < n * (std::size_t(chunk) + 1) / chunks; ++i)
        out[i] = cameraVertexUv(camera, positions[i]);
    });
    return;
  }
  if (o.surface == SurfaceKind::Triplanar)
    throw UsageError("mapVertices: triplanar chooses a projection per triangle; map the mesh, or evaluate points");
  withPrecision(o.arithmetic.precision, [&](auto zero) {
    mapVerticesThroughKernel<decltype(zero)>(o, localFromObject_, positions, normals, out, threads, sensible_);
  });
}

PointUv Projector::at(const Vec3& position, const Vec3& normal, bool capFace) const {
  PointUv out;
  if (capFace && cap_) {
    out.uv = cap_(position, normal);
    const bool finite = out.uv.allFinite();
    out.state = finite ? CornerState::Ok : CornerState::Invalid;
    out.reason = finite ? kCornerValid : kCornerNotFinite;
    if (!finite) out.uv = Vec2::Zero();
    out.unplaced = out.uv;
  } else {
    out = point_(position, normal);
    if (cap_ && out.state != CornerState::Invalid) out.uv = out.unplaced = capSideUv(out.uv, options_.capLayout);
  }
  if (out.state == CornerState::Invalid) return out;
  if (!options_.uvTransform.isIdentity()) out.uv = options_.uvTransform.apply(out.uv);
  if (!out.uv.allFinite()) {
    out = PointUv{};
    out.reason = kCornerNotFinite;
  }
  return out;
}

TriplanarSample Projector::blendAt(const Vec3& position, const Vec3& normal) const {
  UVTK_CHECK(blend_ != nullptr);  // triplanar only
  return blend_(position, normal);
}

Projection project(Mesh mesh, const ProjectorOptions& o, int threads) {
  checkOptions(o);
  // The file's own UVs are replaced: their memory freed, not only emptied (a 4 M-face OBJ's vt
  // held 100 MB through the judgement's peak).
  std::vector<Vec3>().swap(mesh.texcoords);
  std::vector<Triangle>().swap(mesh.cornerTexcoords);

  Projection out;
  const auto start = std::chrono::steady_clock::now();
  out.localFromObject = fitPlacement(mesh.positions, o.surface, o.placement, threads);
  Evaluated evaluated = o.surface == SurfaceKind::Camera      ? evaluateCamera(mesh, o.camera, threads)
                        : o.surface == SurfaceKind::Triplanar ? evaluateTriplanar(mesh, out.localFromObject, o.triplanar, threads)
                        : traitsOf(o.surface).chartsFromMesh  ? evaluateAtlas(mesh, o.surface, o.atlas, threads)
                            : withPrecision(o.arithmetic.precision, [&](auto zero) {
                                return evaluateMesh<decltype(zero)>(mesh, out.localFromObject, o, threads);
                              });
  CornerField& corners = evaluated.corners;
  out.milliseconds.map = millisecondsSince(start);
  const auto seamStart = std::chrono::steady_clock::now();

  SeamReport seams;
  if (const std::optional<double> uStart = uPeriodStartOf(o)) {
    seams = repairSeams(mesh, corners, *uStart, o.seam,
                        [&](const Vec3& p, const Vec3& n, Vec2& uv) {
                          const VertexUv s = evaluated.evaluateAt(p, n);
                          uv = s.uv;
                          return s.state == CornerState::Ok;
                        }, threads);
    if (o.pole == PoleMode::Fan) fanPoleCorners(corners, threads);
  }
  out.summary = summarize(mesh, corners, seams, threads);
  out.summary.triplanarFaces = evaluated.triplanarFaces;
  out.triplanarAxis = std::move(evaluated.triplanarAxis);
  if (evaluated.atlas) out.atlas = std::make_shared<const Atlas>(std::move(*evaluated.atlas));
  out.sensible = evaluated.sensible;
  if (!o.uvTransform.isIdentity()) {
    bool overflowed = false;
    for (std::size_t i = 0; i < corners.uv.size(); ++i) {
      if (corners.state[i] == CornerState::Invalid) continue;
      corners.uv[i] = o.uvTransform.apply(corners.uv[i]);
      if (corners.uv[i].allFinite()) continue;
      corners.invalidate(i, kCornerNotFinite);  // a scale or offset that overflows
      overflowed = true;
    }
    if (overflowed) {  // recount the invalid corners; the seam counts needed the untransformed u
      const MappingSummary recount = summarize(mesh, corners, seams, threads);
      out.summary.invalidVertices = recount.invalidVertices;
      out.summary.invalidFaces = recount.invalidFaces;
      out.summary.invalidVertexList = recount.invalidVertexList;
      out.summary.invalidCorners = recount.invalidCorners;
    }
  }
  out.uv = std::move(corners).toUvMap(threads);
  out.mesh = std::move(mesh);
  out.milliseconds.seams = millisecondsSince(seamStart);
  return out;
}

}  // namespace uvtk::param
