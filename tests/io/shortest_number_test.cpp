// io/shortest_number.h: the text of std::to_chars (libstdc++'s Ryu, written apart from Dragonbox),
// byte for byte, and hand-computed texts at each boundary between fixed and scientific.
#include "io/shortest_number.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

std::string shortest(double value) {
  char text[kShortestNumberBytes];
  return std::string(text, writeShortest(text, value));
}

std::string standard(double value) {
  char text[64];
  return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}

TEST(ShortestNumber, HandComputedTexts) {
  EXPECT_EQ(shortest(0.1), "0.1");
  EXPECT_EQ(shortest(-2.5), "-2.5");
  EXPECT_EQ(shortest(0.001), "0.001");    // one digit: fixed down to 10^-3 ...
  EXPECT_EQ(shortest(0.0001), "1e-04");   // ... then scientific, shorter
  EXPECT_EQ(shortest(0.00012), "0.00012");  // two digits: fixed to 10^-5 (7 characters against 7)
  EXPECT_EQ(shortest(0.000012), "1.2e-05");
  EXPECT_EQ(shortest(10000.0), "10000");
  EXPECT_EQ(shortest(100000.0), "1e+05");
  EXPECT_EQ(shortest(120000.0), "120000");
  EXPECT_EQ(shortest(1200000.0), "1200000");  // 7 characters against 7: fixed
  EXPECT_EQ(shortest(12000000.0), "1.2e+07");
  EXPECT_EQ(shortest(123456.7), "123456.7");
  EXPECT_EQ(shortest(1.0 / 3.0), "0.3333333333333333");
  EXPECT_EQ(shortest(0.30000000000000004), "0.30000000000000004");
  EXPECT_EQ(shortest(1e100), "1e+100");
  EXPECT_EQ(shortest(-1.5e-300), "-1.5e-300");
  EXPECT_EQ(shortest(std::numeric_limits<double>::max()), "1.7976931348623157e+308");
  EXPECT_EQ(shortest(std::numeric_limits<double>::denorm_min()), "5e-324");
  EXPECT_EQ(shortest(0.0), "0");
  EXPECT_EQ(shortest(-0.0), "-0");
  EXPECT_EQ(shortest(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(shortest(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(shortest(std::numeric_limits<double>::quiet_NaN()), "nan");
  // A whole number whose shortest digits are not its value: the exact digits, as printf's %.0f.
  EXPECT_EQ(shortest(1152921504606846976.0), "1152921504606846976");  // 2^60, shortest 1152921504606847e3
  EXPECT_EQ(shortest(9007199254740993.0), "9007199254740992");
  EXPECT_EQ(shortest(1125899906842624.0), "1125899906842624");  // 2^50
}

// Every kind of double against std::to_chars: random bits (all exponents, subnormals), short
// decimals m 10^k and their neighbours, whole numbers around 2^50 to 2^54, mesh-like coordinates.
TEST(ShortestNumber, TheTextOfStdToChars) {
  std::mt19937_64 random(20261207);
  long mismatches = 0;
  const auto check = [&](double value) {
    const std::string a = shortest(value), b = standard(value);
    if (a != b && mismatches++ < 10) ADD_FAILURE() << "writeShortest " << a << ", std::to_chars " << b;
  };
  for (int i = 0; i < 1000000; ++i) {
    const std::uint64_t bits = random();
    double value;
    std::memcpy(&value, &bits, sizeof value);
    check(value);
  }
  for (int power = -325; power <= 309; ++power)
    for (int m : {1, 2, 5, 9, 12, 99, 123, 1000001, 123456789}) {
      const double value = std::strtod((std::to_string(m) + "e" + std::to_string(power)).c_str(), nullptr);
      for (const double v : {value, std::nextafter(value, 0.0), std::nextafter(value, HUGE_VAL)}) check(v), check(-v);
    }
  for (int power = 48; power <= 55; ++power)
    for (int step = -20; step <= 20; ++step) check(std::ldexp(1.0, power) + step * std::ldexp(1.0, power - 52));
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 200000; ++i) {
    const double x = unit(random);
    check(x), check(x * 1e5), check(x * 3.1e5), check(x * 1e-5), check(std::round(x * 1e6) / 1e3), check(std::round(x * 1e7));
  }
  EXPECT_EQ(mismatches, 0);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
