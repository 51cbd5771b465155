// SLEEF's AVX2 atan2 over arrays (compiled with -mavx2 -mfma).
#include <immintrin.h>
#include <sleef.h>

#include "param/sleef_atan2.h"

namespace uvtk::param {

void atan2FloatAvx2(const float* y, const float* x, float* out, std::size_t n, bool oneUlp) {
  sleefAtan2Block<float, __m256>(y, x, out, n, oneUlp ? UVTK_SLEEF(Sleef_atan2f8_u10avx2) : UVTK_SLEEF(Sleef_atan2f8_u35avx2));
}

void atan2DoubleAvx2(const double* y, const double* x, double* out, std::size_t n, bool oneUlp) {
  sleefAtan2Block<double, __m256d>(y, x, out, n, oneUlp ? UVTK_SLEEF(Sleef_atan2d4_u10avx2) : UVTK_SLEEF(Sleef_atan2d4_u35avx2));
}

}  // namespace uvtk::param
