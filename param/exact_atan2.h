// The exact mode's double arctangent over arrays: glibc's atan2, bit for bit, on whole SIMD vectors.
// Each lane is evaluated in double-double to about 2^-12 ulp; where that decides the correctly
// rounded value and glibc 2.36's own error bound (the "Max ULP" of each branch of
// sysdeps/ieee754/dbl-64/e_atan2.c: 0.56 in the first octant's table branch, at most 0.504
// elsewhere) leaves glibc no other value, that is glibc's result too. The lanes near a rounding
// boundary (about one in twelve), and zeros, infinities, NaNs and extreme exponents, call glibc.
// docs/precision.md, "Math mode".
#pragma once

#include <cstddef>

namespace uvtk::param {

// out[i] = std::atan2(y[i], x[i]) for i < n, the same bits; the arrays may not overlap `out`.
// Returns how many of the n values glibc computed (the rest the vectors decided).
std::size_t exactAtan2Block(const double* y, const double* x, double* out, std::size_t n);

}  // namespace uvtk::param
