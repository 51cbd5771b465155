// atan2 over arrays, in the math mode a user chose (--math): libm's values (in double vectorised
// with its bits, core/libm_simd.h; in float one at a time), or SLEEF's
// vectorised functions with their documented error bounds (3.5 or 1.0 ULP), on the widest vectors
// the processor has (AVX-512F or AVX2 when present, SSE2 otherwise). The only transcendental function of the
// S-mappings, so the only place where the math mode matters.
#pragma once

#include <cstddef>

#include "core/arithmetic.h"

namespace uvtk::param {

// out[i] = atan2(y[i], x[i]) for i < n. The arrays may not overlap `out`.
void atan2Block(MathMode math, const float* y, const float* x, float* out, std::size_t n);
void atan2Block(MathMode math, const double* y, const double* x, double* out, std::size_t n);
// References are computed in long double with libm's atan2l whatever the mode.
void atan2Block(MathMode math, const long double* y, const long double* x, long double* out, std::size_t n);

// Loads what atan2Block calls in `math` (SLEEF, for the fast modes: opened on first use), so that
// its later calls allocate nothing and cannot fail; throws std::runtime_error when SLEEF cannot be
// loaded. A projector does this when it is made.
void prepareAtan2(MathMode math);

// The instruction set SLEEF runs on here: "avx512f", "avx2" or "sse2".
const char* fastMathInstructionSet();

}  // namespace uvtk::param
