#include "param/batch_atan2.h"

#include <sleef.h>

#include <cmath>
#include <cstring>

#include "core/libm_simd.h"
#include "param/sleef_atan2.h"

namespace uvtk::param {

namespace {

bool hasAvx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return avx2;
}

bool hasAvx512() {
  static const bool avx512 = __builtin_cpu_supports("avx512f");
  return avx512;
}

template <class T>
void libmAtan2(const T* y, const T* x, T* out, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) out[i] = std::atan2(y[i], x[i]);
}

}  // namespace

void atan2Block(MathMode math, const float* y, const float* x, float* out, std::size_t n) {
  switch (math) {
    case MathMode::Exact:
      return libmAtan2(y, x, out, n);
    case MathMode::Fast:
    case MathMode::FastU10: {
      const bool oneUlp = math == MathMode::FastU10;
      if (hasAvx512()) return atan2FloatAvx512(y, x, out, n, oneUlp);
      if (hasAvx2()) return atan2FloatAvx2(y, x, out, n, oneUlp);
      return sleefAtan2Block<float, __m128>(y, x, out, n, oneUlp ? Sleef_atan2f4_u10 : Sleef_atan2f4_u35);
    }
  }
}

void atan2Block(MathMode math, const double* y, const double* x, double* out, std::size_t n) {
  switch (math) {
    case MathMode::Exact:
      libm::atan2(y, x, out, n);  // glibc's bits, vectorised
      return;
    case MathMode::Fast:
    case MathMode::FastU10: {
      const bool oneUlp = math == MathMode::FastU10;
      if (hasAvx512()) return atan2DoubleAvx512(y, x, out, n, oneUlp);
      if (hasAvx2()) return atan2DoubleAvx2(y, x, out, n, oneUlp);
      return sleefAtan2Block<double, __m128d>(y, x, out, n, oneUlp ? Sleef_atan2d2_u10 : Sleef_atan2d2_u35);
    }
  }
}

void atan2Block(MathMode, const long double* y, const long double* x, long double* out, std::size_t n) {
  libmAtan2(y, x, out, n);
}

const char* fastMathInstructionSet() { return hasAvx512() ? "avx512f" : hasAvx2() ? "avx2" : "sse2"; }

}  // namespace uvtk::param
