#include "param/batch_atan2.h"

#include <hwy/targets.h>
#include <sleef.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "core/libm_simd.h"
#include "core/plugin.h"
#include "param/sleef_atan2.h"

namespace uvtk::param {

namespace {

// Highway's targets (core/simd_targets.cpp), whose AVX2 includes FMA and whose AVX3 is AVX-512 F,
// VL, DQ and BW: __builtin_cpu_supports would link libgcc's own CPU probe, which runs at every
// start (0.06 to 0.12 ms of CPUID on this virtual machine) whether or not an atan2 is taken.
bool hasAvx2() { return (hwy::SupportedTargets() & HWY_AVX2) != 0; }

bool hasAvx512() { return (hwy::SupportedTargets() & HWY_AVX3) != 0; }

template <class T>
void libmAtan2(const T* y, const T* x, T* out, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) out[i] = std::atan2(y[i], x[i]);
}

}  // namespace

void* sleefSymbol(const char* name) {
  static OpenedLibrary library(UVTK_LIBSLEEF);
  void* address = nullptr;
  library.bind(address, name);
  if (!address) throw std::runtime_error("cannot load SLEEF for --math fast: " + library.error());
  return address;
}

void atan2Block(MathMode math, const float* y, const float* x, float* out, std::size_t n) {
  switch (math) {
    case MathMode::Exact:
      return libmAtan2(y, x, out, n);
    case MathMode::Fast:
    case MathMode::FastU10: {
      const bool oneUlp = math == MathMode::FastU10;
      if (hasAvx512()) return atan2FloatAvx512(y, x, out, n, oneUlp);
      if (hasAvx2()) return atan2FloatAvx2(y, x, out, n, oneUlp);
      return sleefAtan2Block<float, __m128>(y, x, out, n, oneUlp ? UVTK_SLEEF(Sleef_atan2f4_u10) : UVTK_SLEEF(Sleef_atan2f4_u35));
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
      return sleefAtan2Block<double, __m128d>(y, x, out, n, oneUlp ? UVTK_SLEEF(Sleef_atan2d2_u10) : UVTK_SLEEF(Sleef_atan2d2_u35));
    }
  }
}

void atan2Block(MathMode, const long double* y, const long double* x, long double* out, std::size_t n) {
  libmAtan2(y, x, out, n);
}

void prepareAtan2(MathMode math) {
  if (math == MathMode::Exact) return;
  const float yf = 0.0f, xf = 1.0f;
  float outf;
  atan2Block(math, &yf, &xf, &outf, 1);
  const double y = 0.0, x = 1.0;
  double out;
  atan2Block(math, &y, &x, &out, 1);
}

const char* fastMathInstructionSet() { return hasAvx512() ? "avx512f" : hasAvx2() ? "avx2" : "sse2"; }

}  // namespace uvtk::param
