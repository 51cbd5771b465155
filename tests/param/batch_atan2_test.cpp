// atan2 over arrays in every math mode, against atan2l: each within its documented bound
// (docs/precision.md), with C99's results on zeros, axes and infinities.
#include "param/batch_atan2.h"

#include <gtest/gtest.h>
#include <link.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

// The error of `value` in units in the last place of T at the exact result `reference`.
template <class T>
double ulpsOff(T value, long double reference) {
  const T rounded = static_cast<T>(reference);
  const T ulp = std::nextafter(std::fabs(rounded), std::numeric_limits<T>::infinity()) - std::fabs(rounded);
  return static_cast<double>(std::fabs(static_cast<long double>(value) - reference) / ulp);
}

// Random (y, x): uniform in the square, scaled by wide exponents, and near the diagonals.
template <class T>
void randomArguments(std::vector<T>& y, std::vector<T>& x, int maxExponent) {
  std::mt19937_64 random(2026);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-maxExponent, maxExponent);
  for (std::size_t i = 0; i < y.size(); ++i) {
    double a = unit(random), b = unit(random);
    if (i % 3 == 1) a = std::ldexp(a, exponent(random)), b = std::ldexp(b, exponent(random));
    if (i % 3 == 2) b = a * (1.0 + 1e-6 * unit(random));
    y[i] = static_cast<T>(a), x[i] = static_cast<T>(b);
  }
}

template <class T>
double worstUlps(MathMode math) {
  const std::size_t n = 400003;  // not a multiple of any vector width: the tail is covered
  std::vector<T> y(n), x(n), angle(n);
  randomArguments(y, x, std::is_same_v<T, float> ? 60 : 500);
  atan2Block(math, y.data(), x.data(), angle.data(), n);
  double worst = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    worst =
        std::max(worst, ulpsOff(angle[i], std::atan2(static_cast<long double>(y[i]), static_cast<long double>(x[i]))));
  return worst;
}

TEST(Atan2Block, EachModeIsWithinItsBoundInDouble) {
  EXPECT_LE(worstUlps<double>(MathMode::Exact), 1.0);
  EXPECT_LE(worstUlps<double>(MathMode::FastU10), 1.0);
  const double fast = worstUlps<double>(MathMode::Fast);
  EXPECT_LE(fast, 3.5);
  EXPECT_GT(fast, 1.0);  // the 3.5-ULP variant really ran
}

TEST(Atan2Block, EachModeIsWithinItsBoundInFloat) {
  EXPECT_LE(worstUlps<float>(MathMode::Exact), 2.0);  // glibc 2.36's atan2f: 1.41 ulp measured
  EXPECT_LE(worstUlps<float>(MathMode::FastU10), 1.0);
  EXPECT_LE(worstUlps<float>(MathMode::Fast), 3.5);
}

TEST(Atan2Block, FollowsC99OnZerosAxesAndInfinities) {
  const double specials[] = {0.0, -0.0, 1.0, -1.0, 1e-310, -1e308, INFINITY, -INFINITY};
  std::vector<double> y, x;
  for (double a : specials)
    for (double b : specials) y.push_back(a), x.push_back(b);
  for (MathMode math : {MathMode::Exact, MathMode::Fast, MathMode::FastU10}) {
    std::vector<double> angle(y.size());
    atan2Block(math, y.data(), x.data(), angle.data(), y.size());
    for (std::size_t i = 0; i < y.size(); ++i) {
      const double expected = std::atan2(y[i], x[i]);
      EXPECT_NEAR(angle[i], expected, 4.5e-16 * std::fabs(expected)) << y[i] << " " << x[i];
      EXPECT_EQ(std::signbit(angle[i]), std::signbit(expected)) << y[i] << " " << x[i];
    }
  }
}

TEST(Atan2Block, ALongDoubleBlockIsAtan2l) {
  const long double y[] = {1.0L, -0.0L, 3.0L}, x[] = {3.0L, -1.0L, -4.0L};
  long double angle[3];
  atan2Block(MathMode::Fast, y, x, angle, 3);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(angle[i], std::atan2(y[i], x[i]));
}

// SLEEF is opened on the first fast arctangent, not linked: a process that takes only libm's
// never loads it. Each check in a fresh process (a "threadsafe" death test re-executes this
// program), since the other tests load it.
bool sleefLoaded() {
  bool found = false;
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* data) {
        if (info->dlpi_name && std::strstr(info->dlpi_name, "libsleef")) *static_cast<bool*>(data) = true;
        return 0;
      },
      &found);
  std::fprintf(stderr, "libsleef: %s\n", found ? "loaded" : "not loaded");
  return found;
}

// Exit statuses of the checks' child processes: 0 when SLEEF is loaded exactly as expected.
[[noreturn]] void exitAfterExactArctangents() {
  const double y[] = {1.0, -2.0}, x[] = {0.5, 3.0};
  double angle[2];
  atan2Block(MathMode::Exact, y, x, angle, 2);
  prepareAtan2(MathMode::Exact);
  std::exit(!sleefLoaded() && angle[0] == std::atan2(1.0, 0.5) ? 0 : 1);
}

[[noreturn]] void exitAfterPreparingFastArctangents() {
  prepareAtan2(MathMode::Fast);
  std::exit(sleefLoaded() ? 0 : 1);
}

TEST(Atan2Loading, ExactArctangentsDoNotLoadSleefAndFastOnesDo) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(exitAfterExactArctangents(), ::testing::ExitedWithCode(0), "libsleef: not loaded");
  EXPECT_EXIT(exitAfterPreparingFastArctangents(), ::testing::ExitedWithCode(0), "libsleef: loaded");
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param
