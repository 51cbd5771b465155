// GoogleTest assertions that check one's own texture-coordinate code (a shader, an exporter, a game
// engine's texgen) against uvtk's mappings (uvtk/point.h). Header-only: link the CMake target
// uvtk::testing (uvtk::point and GTest::gtest). docs/point-api.md shows the messages.
//
//   const uvtk::point::Mapping reference("--projector sphere");
//   EXPECT_UV_NEAR(myShaderUv(p), reference.at(p), 1e-9);
//   EXPECT_UV_STATUS(reference.at({0, 0, 1}), uvtk::point::Status::Pole);
//
// EXPECT_UV_NEAR(actual, expected, tolerance) and ASSERT_UV_NEAR pass when
// uvtk::point::uvError(u, v, expected) <= tolerance: whole periods removed (u compared modulo 1 on a
// wrapping surface) and, at a pole, only the component across the period compared (u is undefined
// there). `actual` is any (u, v) pair: a type with members u and v, or x and y (glm::vec2, a struct
// of one's own, a uvtk::point::Result), a tuple-like pair (std::pair, std::array, std::tuple), or
// anything indexable by [0] and [1] (Eigen::Vector2d, double[2]). `expected` is a Result. An invalid
// Result has no value and never matches: the assertion fails, naming its reason; check such points
// with EXPECT_UV_STATUS(result, uvtk::point::Status::Invalid).
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include "uvtk/point.h"

namespace uvtk::point {

namespace testing_detail {

template <class...>
inline constexpr bool kAlwaysFalse = false;

template <class T, class = void>
struct HasUv : std::false_type {};
template <class T>
struct HasUv<T, std::void_t<decltype(static_cast<double>(std::declval<const T&>().u)),
                            decltype(static_cast<double>(std::declval<const T&>().v))>> : std::true_type {};

template <class T, class = void>
struct HasXy : std::false_type {};
template <class T>
struct HasXy<T, std::void_t<decltype(static_cast<double>(std::declval<const T&>().x)),
                            decltype(static_cast<double>(std::declval<const T&>().y))>> : std::true_type {};

template <class T, class = void>
struct IsPairLike : std::false_type {};
template <class T>
struct IsPairLike<T, std::void_t<decltype(std::tuple_size<T>::value),
                                 decltype(static_cast<double>(std::get<0>(std::declval<const T&>()))),
                                 decltype(static_cast<double>(std::get<1>(std::declval<const T&>())))>>
    : std::bool_constant<(std::tuple_size<T>::value >= 2)> {};

template <class T, class = void>
struct IsIndexable : std::false_type {};
template <class T>
struct IsIndexable<T, std::void_t<decltype(static_cast<double>(std::declval<const T&>()[0]))>> : std::true_type {};

// Every number in full: 17 significant digits read back as the same double.
inline std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

inline std::string shortNumber(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

inline std::string numbers(const double* values, std::size_t count) {
  std::string out = "(";
  for (std::size_t i = 0; i < count; ++i) out += (i ? ", " : "") + number(values[i]);
  return out + ")";
}

inline std::string where(const Result& r) {
  return "at position " + numbers(r.position.data(), 3) + ", mapping \"" + (r.mapping ? r.mapping : "") + "\"";
}

inline std::string statusText(const Result& r) {
  std::string out = statusName(r.status);
  if (r.reason && *r.reason) out += std::string(" (") + r.reason + ")";
  return out;
}

// How uvError compared the two: the line the failure message prints.
inline std::string comparison(double u, double v, const Result& expected) {
  const double pu = expected.period[0], pv = expected.period[1];
  const double length2 = pu * pu + pv * pv;
  if (!(length2 > 0.0)) return "u and v as they are (nothing wraps)";
  const std::string period = numbers(expected.period.data(), 2);
  if (expected.status == Status::Pole)
    return "v only: u is undefined at a pole, so the component along the period " + period + " is ignored";
  std::string out =
      pu == 1.0 && pv == 0.0 ? "u modulo 1 (the period " + period + ")" : "(u, v) modulo the period " + period;
  const double turns = std::nearbyint(((u - expected.u) * pu + (v - expected.v) * pv) / length2);
  if (std::isfinite(turns) && turns != 0.0)
    out += ": the " + number(turns) + (std::fabs(turns) == 1.0 ? " whole turn" : " whole turns") +
           " between actual and expected does not count";
  return out;
}

inline ::testing::AssertionResult uvNear(const char* actualText, const char* expectedText, const char* toleranceText,
                                         const std::array<double, 2>& uv, const Result& expected, double tolerance) {
  const bool hasValue = expected.status != Status::Invalid;
  const double error = uvError(uv[0], uv[1], expected);
  if (hasValue && error <= tolerance) return ::testing::AssertionSuccess();
  std::string m = "UV mismatch " + where(expected) + "\n";
  m += "  actual:    " + std::string(actualText) + " = " + numbers(uv.data(), 2) + "\n";
  m += "  expected:  " + std::string(expectedText) + " = (" + number(expected.u) + ", " + number(expected.v) +
       "), status " + statusText(expected) + "\n";
  if (!hasValue)
    return ::testing::AssertionFailure()
           << m << "  the reference has no value at this point: an invalid Result never matches"
           << " (check such points with EXPECT_UV_STATUS(..., uvtk::point::Status::Invalid))";
  m += "  compared:  " + comparison(uv[0], uv[1], expected) + "\n";
  if (!std::isfinite(uv[0]) || !std::isfinite(uv[1])) m += "  actual is not finite\n";
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance)) m += "  the tolerance is not a finite number >= 0\n";
  m += "  error:     " + number(error);
  if (shortNumber(error) != number(error)) m += " (" + shortNumber(error) + ")";
  m += " > tolerance " + std::string(toleranceText);
  // The tolerance's value too, unless the text is the number itself.
  char* end = nullptr;
  const double literal = std::strtod(toleranceText, &end);
  if (end == toleranceText || *end != '\0' || literal != tolerance) m += " = " + number(tolerance);
  return ::testing::AssertionFailure() << m;
}

}  // namespace testing_detail

// The (u, v) of any pair-like value (see the top of this file), as doubles.
template <class T>
std::array<double, 2> uvOf(const T& value) {
  using namespace testing_detail;
  if constexpr (HasUv<T>::value)
    return {static_cast<double>(value.u), static_cast<double>(value.v)};
  else if constexpr (HasXy<T>::value)
    return {static_cast<double>(value.x), static_cast<double>(value.y)};
  else if constexpr (IsPairLike<T>::value)
    return {static_cast<double>(std::get<0>(value)), static_cast<double>(std::get<1>(value))};
  else if constexpr (IsIndexable<T>::value)
    return {static_cast<double>(value[0]), static_cast<double>(value[1])};
  else
    static_assert(kAlwaysFalse<T>,
                  "EXPECT_UV_NEAR: expected a (u, v) pair: members u, v or x, y, std::pair, std::array, or [0], [1]");
}

// The predicate-formatters behind the macros (usable with EXPECT_PRED_FORMAT3/2 directly).
template <class UV>
::testing::AssertionResult UvNear(const char* actualText, const char* expectedText, const char* toleranceText,
                                  const UV& actual, const Result& expected, double tolerance) {
  return testing_detail::uvNear(actualText, expectedText, toleranceText, uvOf(actual), expected, tolerance);
}

inline ::testing::AssertionResult UvStatusIs(const char* resultText, const char* statusText, const Result& result,
                                             Status status) {
  if (result.status == status) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "UV status mismatch " << testing_detail::where(result) << "\n"
                                       << "  actual:    " << resultText << " has status "
                                       << testing_detail::statusText(result) << ", (u, v) = ("
                                       << testing_detail::number(result.u) << ", " << testing_detail::number(result.v)
                                       << ")\n"
                                       << "  expected:  " << statusText << " = " << statusName(status);
}

// GoogleTest prints these in its own messages (EXPECT_EQ and the like).
inline void PrintTo(Status status, std::ostream* os) { *os << statusName(status); }

inline void PrintTo(const Result& r, std::ostream* os) {
  *os << "{(u, v) = (" << testing_detail::number(r.u) << ", " << testing_detail::number(r.v) << "), w "
      << testing_detail::number(r.w) << ", q " << testing_detail::number(r.q) << ", status "
      << testing_detail::statusText(r) << ", period " << testing_detail::numbers(r.period.data(), 2) << ", "
      << testing_detail::where(r) << "}";
}

}  // namespace uvtk::point

#define EXPECT_UV_NEAR(actual, expected, tolerance) \
  EXPECT_PRED_FORMAT3(::uvtk::point::UvNear, actual, expected, tolerance)
#define ASSERT_UV_NEAR(actual, expected, tolerance) \
  ASSERT_PRED_FORMAT3(::uvtk::point::UvNear, actual, expected, tolerance)
#define EXPECT_UV_STATUS(result, status) EXPECT_PRED_FORMAT2(::uvtk::point::UvStatusIs, result, status)
#define ASSERT_UV_STATUS(result, status) ASSERT_PRED_FORMAT2(::uvtk::point::UvStatusIs, result, status)
