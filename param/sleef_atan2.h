// SLEEF's vectorised atan2 over arrays for batch_atan2.cpp: one template for every vector width,
// and the AVX2 and AVX-512 instances, each compiled with its instruction set in its own
// translation unit (batch_atan2_avx2.cpp, batch_atan2_avx512.cpp), which includes nothing else
// that could be inlined elsewhere. Call an instance only when the processor has its instructions.
#pragma once

#include <cstddef>
#include <cstring>

namespace uvtk::param {

// The address of SLEEF's function `name`, from libsleef opened on the first --math fast rather than
// linked: linked, the library cost every process 0.14 ms at start whether or not it took an
// arctangent (docs/benchmarks.md, "Start-up"). Throws std::runtime_error, naming the library, when
// it cannot be opened or has no such function.
void* sleefSymbol(const char* name);

// SLEEF's `function` (as sleef.h declares it), looked up once per use site.
#define UVTK_SLEEF(function)                                                                           \
  ([] {                                                                                                \
    static const auto address = reinterpret_cast<decltype(&function)>(::uvtk::param::sleefSymbol(#function)); \
    return address;                                                                                    \
  }())

// out[i] = atan2(y[i], x[i]) by `atan2` on vectors V of T: whole vectors, then the tail through a
// zero-padded vector.
template <class T, class V, class F>
void sleefAtan2Block(const T* y, const T* x, T* out, std::size_t n, F atan2) {
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

// AVX2 with FMA (8 floats, 4 doubles a vector); oneUlp: SLEEF's 1.0-ULP functions, else 3.5-ULP.
void atan2FloatAvx2(const float* y, const float* x, float* out, std::size_t n, bool oneUlp);
void atan2DoubleAvx2(const double* y, const double* x, double* out, std::size_t n, bool oneUlp);
// AVX-512F (16 floats, 8 doubles a vector).
void atan2FloatAvx512(const float* y, const float* x, float* out, std::size_t n, bool oneUlp);
void atan2DoubleAvx512(const double* y, const double* x, double* out, std::size_t n, bool oneUlp);

}  // namespace uvtk::param
