// SLEEF's AVX-512 atan2 over arrays (compiled with -mavx512f).
#include <immintrin.h>
#include <sleef.h>

#include "param/sleef_atan2.h"

namespace uvtk::param {

void atan2FloatAvx512(const float* y, const float* x, float* out, std::size_t n, bool oneUlp) {
  sleefAtan2Block<float, __m512>(y, x, out, n, oneUlp ? UVTK_SLEEF(Sleef_atan2f16_u10avx512f) : UVTK_SLEEF(Sleef_atan2f16_u35avx512f));
}

void atan2DoubleAvx512(const double* y, const double* x, double* out, std::size_t n, bool oneUlp) {
  sleefAtan2Block<double, __m512d>(y, x, out, n, oneUlp ? UVTK_SLEEF(Sleef_atan2d8_u10avx512f) : UVTK_SLEEF(Sleef_atan2d8_u35avx512f));
}

}  // namespace uvtk::param
