// The exact mode's vectorised double arctangent: glibc's atan2 bit for bit on every kind of
// argument, most lanes decided by the vectors, and those decided correctly rounded (MPFR).
#include "param/exact_atan2.h"

#include <gtest/gtest.h>
#include <mpfr.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "meshes/generators.h"

namespace uvtk::param {
namespace {

std::uint64_t bitsOf(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// The values the vectors give differ from glibc's nowhere; NaNs compare as NaNs.
void expectGlibcBits(const std::vector<double>& y, const std::vector<double>& x) {
  std::vector<double> out(y.size());
  exactAtan2Block(y.data(), x.data(), out.data(), y.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double glibc = std::atan2(y[i], x[i]);
    if (std::isnan(glibc) ? !std::isnan(out[i]) : bitsOf(glibc) != bitsOf(out[i])) {
      if (++differ <= 5) ADD_FAILURE() << std::hexfloat << "atan2(" << y[i] << ", " << x[i] << "): " << out[i]
                                       << ", glibc " << glibc;
    }
  }
  EXPECT_EQ(differ, 0u) << "of " << y.size();
}

TEST(ExactAtan2, TheTableIsAtanOfEighthsAsHiPlusLo) {
  // Read back through the vectors: atan2(i, 8) is atan(i/8) + atan(0); the table is internal, so
  // check its entries by the value they give where the series adds nothing (u = c exactly).
  mpfr_t exact, c;
  mpfr_inits2(300, exact, c, static_cast<mpfr_ptr>(nullptr));
  for (int i = 1; i <= 8; ++i) {
    const double y = i, x = 8.0;
    double out = 0.0;
    exactAtan2Block(&y, &x, &out, 1);
    mpfr_set_si(c, i, MPFR_RNDN);
    mpfr_div_ui(c, c, 8, MPFR_RNDN);
    mpfr_atan(exact, c, MPFR_RNDN);
    EXPECT_EQ(out, mpfr_get_d(exact, MPFR_RNDN)) << "atan(" << i << "/8)";
  }
  mpfr_clears(exact, c, static_cast<mpfr_ptr>(nullptr));
}

TEST(ExactAtan2, EqualsGlibcOnUniformWideAndNearDiagonalArguments) {
  std::mt19937_64 random(26);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-60, 60);
  const std::size_t n = 3000001;  // not a multiple of any vector width
  std::vector<double> y(n), x(n);
  for (std::size_t i = 0; i < n; ++i) {
    double a = unit(random), b = unit(random);
    if (i % 4 == 1) a = std::ldexp(a, exponent(random)), b = std::ldexp(b, exponent(random));
    if (i % 4 == 2) b = a * (1.0 + 1e-9 * unit(random));   // near the diagonals: u near 1
    if (i % 4 == 3) a = b * 0.0625 * (1.0 + 1e-9 * unit(random));  // u near 1/16, glibc's branch point
    y[i] = a, x[i] = b;
  }
  expectGlibcBits(y, x);
}

TEST(ExactAtan2, EqualsGlibcOnTheSpheresArguments) {
  // The sphere projector's two arctangents over a 1024 x 512 lat-long sphere: azimuth (y, x) and
  // the angle from the nearer pole (hypot(x, y), |z|).
  const Mesh mesh = meshes::latLongSphere(1024, 512);
  std::vector<double> y, x;
  for (const Vec3& p : mesh.positions) {
    y.push_back(p.y()), x.push_back(p.x());
    y.push_back(std::sqrt(p.x() * p.x() + p.y() * p.y())), x.push_back(std::fabs(p.z()));
  }
  expectGlibcBits(y, x);
}

TEST(ExactAtan2, EqualsGlibcOnZerosInfinitiesNansAndExtremes) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const double tiny = std::numeric_limits<double>::denorm_min(), huge = std::numeric_limits<double>::max();
  const double values[] = {0.0, -0.0, 1.0, -1.0, inf, -inf, nan, tiny, -tiny, 1e-310, huge, -huge,
                           0x1p-500, 0x1p-501, 0x1p500, 0x1p501, 0x1p-50, 0x1p-51, 3.0, -0.75};
  std::vector<double> y, x;
  for (double a : values)
    for (double b : values) y.push_back(a), x.push_back(b);
  expectGlibcBits(y, x);
}

TEST(ExactAtan2, TheVectorsDecideMostLanesAndDecideThemCorrectlyRounded) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const std::size_t n = 200000;
  std::vector<double> y(n), x(n), out(n);
  for (std::size_t i = 0; i < n; ++i) y[i] = unit(random), x[i] = unit(random);
  const std::size_t byGlibc = exactAtan2Block(y.data(), x.data(), out.data(), n);
  if (byGlibc == n) GTEST_SKIP() << "no fused multiply-add on this processor: every value is glibc's";
  // About one lane in twelve lies near a rounding boundary (docs/precision.md).
  EXPECT_GT(byGlibc, n / 100);
  EXPECT_LT(byGlibc, n / 6);
  // Every value, decided by the vectors or not, is within glibc's 0.56 ulp; and the correctly
  // rounded value wherever the true one lies 0.44 ulp or less from it.
  mpfr_t my, mx, exact;
  mpfr_inits2(200, my, mx, exact, static_cast<mpfr_ptr>(nullptr));
  std::size_t correctlyRounded = 0;
  for (std::size_t i = 0; i < n; i += 7) {
    mpfr_set_d(my, y[i], MPFR_RNDN);
    mpfr_set_d(mx, x[i], MPFR_RNDN);
    mpfr_atan2(exact, my, mx, MPFR_RNDN);
    const double nearest = mpfr_get_d(exact, MPFR_RNDN);
    correctlyRounded += out[i] == nearest;
    const double ulp = std::nextafter(std::fabs(nearest), 4.0) - std::fabs(nearest);
    mpfr_sub_d(exact, exact, out[i], MPFR_RNDN);
    EXPECT_LE(std::fabs(mpfr_get_d(exact, MPFR_RNDN)) / ulp, 0.56) << std::hexfloat << y[i] << ", " << x[i];
  }
  EXPECT_GT(correctlyRounded, (n / 7) * 99 / 100);
  mpfr_clears(my, mx, exact, static_cast<mpfr_ptr>(nullptr));
}

}  // namespace
}  // namespace uvtk::param
