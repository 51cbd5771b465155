// glibc's hypot, log2 and atan2 over arrays, with glibc's bits, on the widest SIMD vectors the
// processor has (core/libm_simd-inl.h, dispatched at run time): out[i] = std::hypot(x[i], y[i]),
// std::log2(x[i]), std::atan2(y[i], x[i]) for i < n. The few lanes the vectors leave undecided go
// to glibc after them, in one batch; each function returns how many values glibc computed. On a
// processor without fused multiply-adds every value is glibc's. `out` may not overlap the inputs.
#pragma once

#include <cstddef>

namespace uvtk::libm {

std::size_t hypot(const double* x, const double* y, double* out, std::size_t n);
std::size_t log2(const double* x, double* out, std::size_t n);
std::size_t atan2(const double* y, const double* x, double* out, std::size_t n);

}  // namespace uvtk::libm
