#include "param/batch_atan2.h"

#include <sleef.h>

#include <cmath>
#include <cstring>

#include "param/batch_atan2_avx2.h"

namespace uvtk::param {

namespace {

bool hasAvx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return avx2;
}

template <class T>
void libmAtan2(const T* y, const T* x, T* out, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) out[i] = std::atan2(y[i], x[i]);
}

// SSE2: whole vectors, then the tail through a zero-padded vector.
template <class T, class V, class F>
void sleefAtan2(const T* y, const T* x, T* out, std::size_t n, F atan2) {
  constexpr std::size_t kLanes = sizeof(V) / sizeof(T);
  std::size_t i = 0;
  V a, b;
  for (; i + kLanes <= n; i += kLanes) {
    std::memcpy(&a, y + i, sizeof a);
    std::memcpy(&b, x + i, sizeof b);
    const V r = atan2(a, b);
    std::memcpy(out + i, &r, sizeof r);
  }
  if (i == n) return;
  T ty[kLanes] = {}, tx[kLanes] = {}, tr[kLanes];
  std::memcpy(ty, y + i, (n - i) * sizeof(T));
  std::memcpy(tx, x + i, (n - i) * sizeof(T));
  std::memcpy(&a, ty, sizeof a);
  std::memcpy(&b, tx, sizeof b);
  const V r = atan2(a, b);
  std::memcpy(tr, &r, sizeof r);
  std::memcpy(out + i, tr, (n - i) * sizeof(T));
}

}  // namespace

void atan2Block(MathMode math, const float* y, const float* x, float* out, std::size_t n) {
  switch (math) {
    case MathMode::Exact:
      return libmAtan2(y, x, out, n);
    case MathMode::Fast:
      if (hasAvx2()) return atan2FloatAvx2(y, x, out, n, false);
      return sleefAtan2<float, __m128>(y, x, out, n, Sleef_atan2f4_u35);
    case MathMode::FastU10:
      if (hasAvx2()) return atan2FloatAvx2(y, x, out, n, true);
      return sleefAtan2<float, __m128>(y, x, out, n, Sleef_atan2f4_u10);
  }
}

void atan2Block(MathMode math, const double* y, const double* x, double* out, std::size_t n) {
  switch (math) {
    case MathMode::Exact:
      return libmAtan2(y, x, out, n);
    case MathMode::Fast:
      if (hasAvx2()) return atan2DoubleAvx2(y, x, out, n, false);
      return sleefAtan2<double, __m128d>(y, x, out, n, Sleef_atan2d2_u35);
    case MathMode::FastU10:
      if (hasAvx2()) return atan2DoubleAvx2(y, x, out, n, true);
      return sleefAtan2<double, __m128d>(y, x, out, n, Sleef_atan2d2_u10);
  }
}

void atan2Block(MathMode, const long double* y, const long double* x, long double* out, std::size_t n) {
  libmAtan2(y, x, out, n);
}

const char* fastMathInstructionSet() { return hasAvx2() ? "avx2" : "sse2"; }

}  // namespace uvtk::param
