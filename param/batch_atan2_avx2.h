// The AVX2 halves of batch_atan2.cpp, compiled with -mavx2 -mfma in their own translation unit,
// which includes nothing else that could be inlined elsewhere. Call only when the processor has
// AVX2 and FMA.
#pragma once

#include <cstddef>

namespace uvtk::param {

void atan2FloatAvx2(const float* y, const float* x, float* out, std::size_t n, bool oneUlp);
void atan2DoubleAvx2(const double* y, const double* x, double* out, std::size_t n, bool oneUlp);

}  // namespace uvtk::param
