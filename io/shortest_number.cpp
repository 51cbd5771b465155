#include "io/shortest_number.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <dragonbox/dragonbox.h>

#include "core/error.h"

namespace uvtk::io {

namespace {

constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// The 8 digits of v < 10^8, zero-padded, in two independent halves (a short chain of divisions).
void eightDigits(char* out, std::uint32_t v) {
  const std::uint32_t high = v / 10000, low = v % 10000;
  std::memcpy(out, kDigitPairs + 2 * (high / 100), 2);
  std::memcpy(out + 2, kDigitPairs + 2 * (high % 100), 2);
  std::memcpy(out + 4, kDigitPairs + 2 * (low / 100), 2);
  std::memcpy(out + 6, kDigitPairs + 2 * (low % 100), 2);
}

char* standardText(char* out, double value) {
  const std::to_chars_result r = std::to_chars(out, out + kShortestNumberBytes, value);
  UVTK_CHECK(r.ec == std::errc());
  return r.ptr;
}

}  // namespace

char* writeShortest(char* out, double value) {
  if (value == 0.0 || !std::isfinite(value)) return standardText(out, value);
  // value = significand 10^exponent, the significand of at most 17 digits and no trailing zero.
  const auto decimal = jkj::dragonbox::to_decimal(value);
  const std::uint64_t significand = decimal.significand;
  const int exponent = decimal.exponent;
  char padded[17];  // the significand's digits, zero-padded on the left
  const std::uint64_t top = significand / 100000000;
  padded[0] = char('0' + top / 100000000);
  eightDigits(padded + 1, std::uint32_t(top % 100000000));
  eightDigits(padded + 9, std::uint32_t(significand % 100000000));
  int length = 17;
  while (padded[17 - length] == '0') --length;
  const char* digits = padded + 17 - length;

  // std::to_chars' plain format (libstdc++'s __floating_to_chars_shortest): fixed where it is no
  // longer than scientific, which bounds the exponent; scientific without a point for one digit.
  const bool oneDigit = length == 1;
  const bool fixed = exponent >= -(length + 3) + (oneDigit ? 1 : 0) && exponent <= 5 - (oneDigit ? 1 : 0);
  char* p = out;
  if (fixed && exponent >= 0) {
    // A whole number: its digits and zeros, where those are its exact value (below 2^50).
    if (63 - __builtin_clzll(significand) + (exponent * 10 + 2) / 3 >= 50) return standardText(out, value);
    if (decimal.is_negative) *p++ = '-';
    std::memcpy(p, digits, std::size_t(length));
    std::memset(p + length, '0', std::size_t(exponent));
    return p + length + exponent;
  }
  if (decimal.is_negative) *p++ = '-';
  if (fixed) {
    const int whole = length + exponent;  // digits before the point
    if (whole <= 0) {
      *p++ = '0', *p++ = '.';
      std::memset(p, '0', std::size_t(-whole));
      p += -whole;
      std::memcpy(p, digits, std::size_t(length));
      return p + length;
    }
    std::memcpy(p, digits, std::size_t(whole));
    p += whole;
    *p++ = '.';
    std::memcpy(p, digits + whole, std::size_t(-exponent));
    return p - exponent;
  }
  *p++ = digits[0];
  if (!oneDigit) {
    *p++ = '.';
    std::memcpy(p, digits + 1, std::size_t(length - 1));
    p += length - 1;
  }
  int power = exponent + length - 1;
  *p++ = 'e';
  *p++ = power < 0 ? '-' : '+';
  power = std::abs(power);
  if (power >= 100) *p++ = char('0' + power / 100), power %= 100;
  std::memcpy(p, kDigitPairs + 2 * power, 2);
  return p + 2;
}

}  // namespace uvtk::io
