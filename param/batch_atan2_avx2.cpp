// SLEEF's AVX2 atan2 over arrays: whole vectors, then the tail through a zero-padded vector.
#include "param/batch_atan2_avx2.h"

#include <immintrin.h>
#include <sleef.h>

namespace uvtk::param {

void atan2FloatAvx2(const float* y, const float* x, float* out, std::size_t n, bool oneUlp) {
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    const __m256 a = _mm256_loadu_ps(y + i), b = _mm256_loadu_ps(x + i);
    _mm256_storeu_ps(out + i, oneUlp ? Sleef_atan2f8_u10avx2(a, b) : Sleef_atan2f8_u35avx2(a, b));
  }
  if (i == n) return;
  float ty[8] = {}, tx[8] = {}, tr[8];
  for (std::size_t k = 0; k < n - i; ++k) ty[k] = y[i + k], tx[k] = x[i + k];
  const __m256 a = _mm256_loadu_ps(ty), b = _mm256_loadu_ps(tx);
  _mm256_storeu_ps(tr, oneUlp ? Sleef_atan2f8_u10avx2(a, b) : Sleef_atan2f8_u35avx2(a, b));
  for (std::size_t k = 0; k < n - i; ++k) out[i + k] = tr[k];
}

void atan2DoubleAvx2(const double* y, const double* x, double* out, std::size_t n, bool oneUlp) {
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    const __m256d a = _mm256_loadu_pd(y + i), b = _mm256_loadu_pd(x + i);
    _mm256_storeu_pd(out + i, oneUlp ? Sleef_atan2d4_u10avx2(a, b) : Sleef_atan2d4_u35avx2(a, b));
  }
  if (i == n) return;
  double ty[4] = {}, tx[4] = {}, tr[4];
  for (std::size_t k = 0; k < n - i; ++k) ty[k] = y[i + k], tx[k] = x[i + k];
  const __m256d a = _mm256_loadu_pd(ty), b = _mm256_loadu_pd(tx);
  _mm256_storeu_pd(tr, oneUlp ? Sleef_atan2d4_u10avx2(a, b) : Sleef_atan2d4_u35avx2(a, b));
  for (std::size_t k = 0; k < n - i; ++k) out[i + k] = tr[k];
}

}  // namespace uvtk::param
