// Inside param: the vector stages of the narrow kernel (param/uv_kernel.h) on one block, compiled
// for every instruction set Highway targets and dispatched at run time (uv_kernel_simd.cpp).
#pragma once

#include <cstddef>

namespace uvtk::param {

// The surface and probe the vectors compute; anything else goes through the per-vertex templates.
enum class SimdVariant {
  SphereRadial,     // sphere, isn or centroid: q = p
  CylinderFoot,     // cylinder, isn: q = p
  CylinderCentral,  // cylinder, centroid: q = p / rho
  PlaneFoot,        // plane, isn: q = (x, y, 0)
  PlaneCentral,     // plane, centroid: q = (x/z, y/z, 1)
  TwoPlaneFoot,     // two-plane, isn: q = p
  TwoPlaneCentral,  // two-plane, centroid: q = p / (a.p)
};

template <class T>
struct SimdParams {
  SimdVariant variant = SimdVariant::SphereRadial;
  bool gluAzimuth = false;  // the sphere's azimuth is atan2(x, y) (SpherePreset::Glu)
  bool seed004 = false;     // SpherePreset::Seed004: u = azimuth / 2 pi, v from +z
  T slope = 0;              // PoleTest::slope in T
  T centre[3] = {0, 0, 0};  // SensibleRangeT
  T reach = 0;
  T planeU[4] = {0, 0, 0, 0}, planeV[4] = {0, 0, 0, 0}, axis[3] = {0, 0, 0};  // TwoPlaneSurfaceT
  T twoPi = 0, inverseTwoPi = 0, pi = 0;  // T(kTwoPi), T(1.0 / kTwoPi), T(kPi), as param/formulas.h rounds them
};

// One block's scratch, whole vectors of every target (kSize is a multiple of 16 floats). The
// positions are read from `in` and (u, v) and the axial point written to `out`: the block's own
// arrays (a block shorter than kSize, padded), or the caller's (a whole block, nothing copied).
template <class T>
struct SimdBlock {
  static constexpr std::size_t kSize = 256;
  const T* in[3] = {x, y, z};
  T* out[4] = {u, v, ax, ay};
  alignas(64) T x[kSize], y[kSize], z[kSize];                 // in: local positions
  alignas(64) T y0[kSize], x0[kSize], y1[kSize], x1[kSize];   // the arctangents' arguments
  alignas(64) T angle0[kSize], angle1[kSize];                 // and their values
  alignas(64) T qz[kSize], u[kSize], v[kSize], ax[kSize], ay[kSize];
  alignas(64) T slow[kSize];  // non-zero: the lane is recomputed per vertex
};

// Every lane below n rounded up to whole vectors: from (x, y, z) to the arguments, or to (u, v)
// for the planes, axial and slow. Returns whether any lane is slow.
bool simdPrepare(const SimdParams<float>& p, SimdBlock<float>& b, std::size_t n);
bool simdPrepare(const SimdParams<double>& p, SimdBlock<double>& b, std::size_t n);
// The sphere and cylinder: (u, v) from the angles; a lane whose (u, v) is not finite turns slow.
bool simdFinish(const SimdParams<float>& p, SimdBlock<float>& b, std::size_t n);
bool simdFinish(const SimdParams<double>& p, SimdBlock<double>& b, std::size_t n);

}  // namespace uvtk::param
