// The narrow mapping kernel: positions in the projector's local frame as structure of arrays, (u, v)
// out as two arrays, and only the vertices that are not plainly valid (poles, invalid hits) in a
// sparse list. The frame's move, the probe, the pole test and the S-mapping run on whole SIMD
// vectors (Google Highway, dispatched to the widest instruction set present) around one call of
// atan2Block per block, so the arctangents are SLEEF's vectors in the fast modes and glibc's, one
// value at a time, in exact mode. Every vertex gets exactly the bits mapVertices gave before the
// kernel existed: lanes the vectors cannot take on (poles, misses, hypot's range, values out of
// range or not finite, the normal and reflection O-mappings) go through the per-vertex templates of
// param/surfaces.h. mapVertices runs on it; `uvtk bench` times it directly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <variant>
#include <vector>

#include "param/projector.h"
#include "param/surfaces.h"

namespace uvtk::param {

// Vertices in the projector's local frame in precision T (float for Precision::Float). The normals
// are filled only for the O-mappings that read them (normal, reflection); unit length, or zero.
template <class T>
struct LocalPoints {
  std::vector<T> x, y, z;
  std::vector<T> nx, ny, nz;
  std::size_t size() const { return x.size(); }
};

// The move into the local frame, once (as mapVertices does it: in double, then rounded to T).
// `normals` is read when it is not empty (one per position).
template <class T>
void toLocal(const Affine3& localFromObject, const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
             LocalPoints<T>& out, int threads = 1);

// A vertex without a plain (u, v): a pole (v defined, u = 0) or invalid (u = v = 0, reason says why).
struct UvException {
  std::uint32_t index;
  CornerState state;
  CornerInvalid reason;  // kCornerValid for poles
};

// The kernel's output: u[i], v[i] per vertex (8 bytes a vertex in float, 16 in double), and the
// exceptions in increasing index order; a vertex not listed is CornerState::Ok.
template <class T>
struct UvArrays {
  std::vector<T> u, v;
  std::vector<UvException> exceptions;
};

// One contiguous run of vertices for UvKernel::run: count inputs and outputs per pointer.
template <class T>
struct KernelSpan {
  std::size_t count = 0;
  const T *x = nullptr, *y = nullptr, *z = nullptr;
  const T *nx = nullptr, *ny = nullptr, *nz = nullptr;  // read only by the normal and reflection O-mappings
  T *u = nullptr, *v = nullptr;
  T *axialX = nullptr, *axialY = nullptr;  // optional: the hit point's (x, y), VertexUv::axial
};

// The mapping of ProjectorOptions (surface, O-mapping, sphere preset, pole epsilon, math mode; T
// must match options.arithmetic.precision) prepared once, then run on any number of spans from
// any number of threads. Throws UsageError like mapVertices: inconsistent options, the cube.
template <class T>
class UvKernel {
 public:
  UvKernel(const ProjectorOptions& options, const Affine3& localFromObject,
           const std::optional<Eigen::AlignedBox3d>& sensible = std::nullopt);
  bool needsNormals() const { return needsNormals_; }
  // Maps span's vertices; their exceptions are appended with index first + i.
  void run(const KernelSpan<T>& span, std::size_t first, std::vector<UvException>& exceptions) const;

 private:
  SurfaceT<T> surface_;
  RayMappingT<T> mapping_;
  ProjectorOptions options_;
  SensibleRangeT<T> range_;
  bool needsNormals_ = false;
};

// The kernel over all of `points` (sensible: sensibleBox of the mesh, as for mapVertices), split
// into `threads` contiguous ranges (0: one per core). The exceptions do not depend on `threads`.
// `uvtk bench` times this with points from toLocal, computed once outside the timing:
//   LocalPoints<float> points; toLocal(frame, mesh.positions, normals, points);
//   UvArrays<float> uvs; mapUvs(options, frame, points, uvs, threads);
template <class T>
void mapUvs(const ProjectorOptions& options, const Affine3& localFromObject, const LocalPoints<T>& points,
            UvArrays<T>& out, int threads = 1, const std::optional<Eigen::AlignedBox3d>& sensible = std::nullopt);

}  // namespace uvtk::param
