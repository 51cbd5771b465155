// glibc's hypot, log2 and atan2 on vectors: glibc's bits on every kind of argument, most lanes
// decided by the vectors, and those decided correctly rounded (MPFR).
#include "core/libm_simd.h"

#include <gtest/gtest.h>
#include <mpfr.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <vector>

namespace uvtk::libm {
namespace {
namespace UVTK_TEST_FILE {

std::uint64_t bitsOf(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// The vectors' values differ from glibc's nowhere; NaNs compare as NaNs.
void expectGlibcBits(const std::vector<double>& out, const std::function<double(std::size_t)>& glibc) {
  std::size_t differ = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double expected = glibc(i);
    if (std::isnan(expected) ? !std::isnan(out[i]) : bitsOf(expected) != bitsOf(out[i]))
      if (++differ <= 5) ADD_FAILURE() << std::hexfloat << "argument " << i << ": " << out[i] << ", glibc " << expected;
  }
  EXPECT_EQ(differ, 0u) << "of " << out.size();
}

const double kInf = std::numeric_limits<double>::infinity(), kNan = std::numeric_limits<double>::quiet_NaN();
const std::vector<double> kSpecial = {0.0,     -0.0,    1.0,     -1.0,    kInf,    -kInf,    kNan,   4.9e-324,
                                      -4.9e-324, 1e-310, 1.7e308, -1.7e308, 0x1p-500, 0x1p-501, 0x1p500, 0x1p501,
                                      0x1p-50, 0x1p-51, 3.0,     -0.75,   0x1p-1022, 0x1.fffffffffffffp-1, 2.0};

// Pairs: uniform in the square, of wide exponents, near the diagonals and near u = 1/16, then
// every pair of special values. `count` random pairs.
void argumentPairs(std::size_t count, std::vector<double>& a, std::vector<double>& b) {
  std::mt19937_64 random(26);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-60, 60);
  for (std::size_t i = 0; i < count; ++i) {
    double p = unit(random), q = unit(random);
    if (i % 4 == 1) p = std::ldexp(p, exponent(random)), q = std::ldexp(q, exponent(random));
    if (i % 4 == 2) q = p * (1.0 + 1e-9 * unit(random));
    if (i % 4 == 3) p = q * 0.0625 * (1.0 + 1e-9 * unit(random));
    a.push_back(p), b.push_back(q);
  }
  for (double p : kSpecial)
    for (double q : kSpecial) a.push_back(p), b.push_back(q);
}

TEST(LibmSimd, Atan2IsGlibcsOnUniformWideNearDiagonalSpecialAndSphereArguments) {
  std::vector<double> y, x;
  argumentPairs(3000001, y, x);  // not a multiple of any vector width
  // A 1024 x 512 lat-long sphere's azimuth (y, x) and angle from the nearer pole (hypot(x, y), |z|).
  for (int i = 1; i < 512; ++i)
    for (int j = 0; j < 1024; ++j) {
      const double theta = 2 * M_PI * j / 1024, phi = M_PI * i / 512;
      const double px = std::sin(phi) * std::cos(theta), py = std::sin(phi) * std::sin(theta);
      y.push_back(py), x.push_back(px);
      y.push_back(std::sqrt(px * px + py * py)), x.push_back(std::fabs(std::cos(phi)));
    }
  std::vector<double> out(y.size());
  atan2(y.data(), x.data(), out.data(), y.size());
  expectGlibcBits(out, [&](std::size_t i) { return std::atan2(y[i], x[i]); });
}

TEST(LibmSimd, HypotIsGlibcsOnUniformWideNearDiagonalAndSpecialArguments) {
  std::vector<double> x, y;
  argumentPairs(3000001, x, y);
  std::vector<double> out(x.size());
  hypot(x.data(), y.data(), out.data(), x.size());
  expectGlibcBits(out, [&](std::size_t i) { return std::hypot(x[i], y[i]); });
}

TEST(LibmSimd, Log2IsGlibcsOnWideNearOneNearPowersOfTwoAndSpecialArguments) {
  std::mt19937_64 random(2);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> x;
  for (std::size_t i = 0; i < 3000001; ++i) {
    const double u = unit(random);
    switch (i % 4) {
      case 0: x.push_back(std::ldexp(1.0 + u, int(i % 2000) - 1000)); break;  // every exponent
      case 1: x.push_back(1.0 + (u - 0.5) * 1e-3); break;                     // near 1, both sides
      case 2: x.push_back(std::ldexp(1.0 + (u - 0.5) * 1e-9, int(i % 64) - 32)); break;  // near powers of two
      default: x.push_back(1.0 + 1e-12 * u); break;                            // very near 1
    }
  }
  for (double v : kSpecial) x.push_back(v);
  std::vector<double> out(x.size());
  log2(x.data(), out.data(), x.size());
  expectGlibcBits(out, [&](std::size_t i) { return std::log2(x[i]); });
}

// Where the vectors decide, the value is the correctly rounded one (MPFR), and they decide most
// (atan2 and log2, whose glibc is not correctly rounded: a lane near a rounding boundary is glibc's).
template <class Function>
void expectDecidedCorrectlyRounded(std::size_t byGlibc, std::size_t n, const std::vector<double>& out,
                                   const Function& exact) {
  EXPECT_GT(byGlibc, 0u);
  EXPECT_LT(byGlibc, n / 5);
  mpfr_t value;
  mpfr_init2(value, 200);
  std::size_t correctlyRounded = 0, checked = 0;
  for (std::size_t i = 0; i < n; i += 7, ++checked) {
    exact(i, value);
    correctlyRounded += out[i] == mpfr_get_d(value, MPFR_RNDN);
  }
  // Every decided value is; glibc's own (a few percent of lanes) nearly always.
  EXPECT_GE(correctlyRounded, checked - checked / 100);
  mpfr_clear(value);
}

TEST(LibmSimd, TheVectorsDecideMostLanesAndDecideThemCorrectlyRounded) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const std::size_t n = 200000;
  std::vector<double> a(n), b(n), out(n);
  for (std::size_t i = 0; i < n; ++i) a[i] = unit(random), b[i] = unit(random);
  if (hypot(a.data(), b.data(), out.data(), n) == n)
    GTEST_SKIP() << "no fused multiply-add on this processor: every value is glibc's";
  mpfr_t p, q;
  mpfr_inits2(200, p, q, static_cast<mpfr_ptr>(nullptr));
  const auto set = [&](std::size_t i) { mpfr_set_d(p, a[i], MPFR_RNDN), mpfr_set_d(q, b[i], MPFR_RNDN); };
  expectDecidedCorrectlyRounded(atan2(a.data(), b.data(), out.data(), n), n, out,
                                [&](std::size_t i, mpfr_t v) { set(i), mpfr_atan2(v, p, q, MPFR_RNDN); });
  // hypot has no undecided lanes in its common range: it is glibc's own algorithm.
  EXPECT_EQ(hypot(a.data(), b.data(), out.data(), n), 0u);
  for (double& v : a) v = std::fabs(v) * 100.0;
  expectDecidedCorrectlyRounded(log2(a.data(), out.data(), n), n, out,
                                [&](std::size_t i, mpfr_t v) { set(i), mpfr_log2(v, p, MPFR_RNDN); });
  mpfr_clears(p, q, static_cast<mpfr_ptr>(nullptr));
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::libm
