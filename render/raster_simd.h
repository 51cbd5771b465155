// Inside render: the per-vertex steps of a frame on SIMD vectors (Google Highway, dispatched at
// run time), each lane with the same operations in the same order as their scalar statement, so
// with its bits: the move to clip space and the snapped window position.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>

#include "core/math.h"

namespace uvtk::render {

// clip[v] = clipFromObject (positions[v], 1) for v < n, each row ((m0 x + m1 y) + m2 z) + m3 as
// Eigen's product with homogeneous() takes it. Returns the least and the greatest of the
// vertices' largest finite non-zero |coordinate| (infinity and 0 when there is none).
std::pair<double, double> transformToClip(const Mat4& clipFromObject, const Vec3* positions, Vec4* clip, std::size_t n);

// The not-inside mark of snapToWindow: no snapped coordinate is this low (they stay below 2^28).
constexpr std::int32_t kOutsideWindow = INT32_MIN;

// window[v] for v < n: a vertex finite, with w > 0, inside the near and far planes and the guard
// band (|x|, |y| <= guard w) gets its window position snapped to 1/256 pixel, x in the low 32
// bits and y in the high ones, x = round((x/w + 1) / 2 width 256) half away from zero, likewise
// y; any other vertex x = kOutsideWindow.
void snapToWindow(const Vec4* clip, std::size_t n, double guard, int width, int height, std::int64_t* window);

// The snapped window position of one point with w > 0 (a clipped polygon's corner), as
// snapToWindow packs it, whether inside the planes or on one of them.
std::int64_t snapPoint(const Vec4& clip, int width, int height);

}  // namespace uvtk::render
