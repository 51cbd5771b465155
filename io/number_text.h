// Numbers in the text of mesh files (OBJ, OFF, ASCII PLY and STL), parsed with std::from_chars:
// the C locale whatever the global one is, no allocation, and overflow told apart from underflow.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>
#include <system_error>

namespace uvtk::io {

enum class NumberSyntax {
  ok,         // a finite value (one too small for the type became a signed zero)
  malformed,  // not a decimal number
  notFinite,  // nan or inf
  tooLarge,   // a decimal beyond the type's range
};

// from_chars reports overflow and underflow alike as out of range; for a syntactically valid
// decimal, tell them apart by the decimal exponent of its leading digit (>= 0: too large).
inline bool overflows(const char* p, const char* last) {
  if (p != last && *p == '-') ++p;
  long long integerDigits = 0, fractionZeros = 0;
  bool inFraction = false, leadingDigitSeen = false;
  for (; p != last && *p != 'e' && *p != 'E'; ++p) {
    if (*p == '.') {
      inFraction = true;
    } else if (!leadingDigitSeen) {
      leadingDigitSeen = *p != '0';
      if (!leadingDigitSeen && inFraction) ++fractionZeros;
      if (leadingDigitSeen && !inFraction) ++integerDigits;
    } else if (!inFraction) {
      ++integerDigits;
    }
  }
  long long exponent = 0;
  bool negativeExponent = false;
  if (p != last) ++p;  // 'e'
  if (p != last && (*p == '+' || *p == '-')) negativeExponent = *p++ == '-';
  for (; p != last; ++p) exponent = std::min(exponent * 10 + (*p - '0'), 1'000'000'000LL);
  const long long leading = integerDigits > 0 ? integerDigits - 1 : -(fractionZeros + 1);
  return leading + (negativeExponent ? -exponent : exponent) >= 0;
}

// The whole token as a T (float or double); a leading '+' is accepted, as strtod and "%+g" have it.
template <typename T>
NumberSyntax parseReal(std::string_view token, T& value) {
  const char* first = token.data();
  const char* last = first + token.size();
  if (first != last && *first == '+') {  // from_chars rejects the '+'
    ++first;
    if (first != last && *first == '-') return NumberSyntax::malformed;
  }
  const auto [end, error] = std::from_chars(first, last, value, std::chars_format::general);
  if (error == std::errc::invalid_argument || end != last) return NumberSyntax::malformed;
  if (error == std::errc::result_out_of_range) {
    if (overflows(first, last)) return NumberSyntax::tooLarge;
    value = *first == '-' ? -T(0) : T(0);
    return NumberSyntax::ok;
  }
  return std::isfinite(value) ? NumberSyntax::ok : NumberSyntax::notFinite;
}

// The whole token as a decimal integer, with an optional sign; false if malformed or beyond long long.
inline bool parseInteger(std::string_view token, long long& value) {
  const char* first = token.data();
  const char* last = first + token.size();
  if (first != last && *first == '+') {  // from_chars rejects the '+' that strtol accepts
    ++first;
    if (first == last || *first < '0' || *first > '9') return false;
  }
  const auto [end, error] = std::from_chars(first, last, value);
  return error == std::errc() && end == last;
}

}  // namespace uvtk::io
