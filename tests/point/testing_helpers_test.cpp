// The GoogleTest helpers of uvtk/testing.h: what they accept, and what their failures say.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <limits>
#include <string>
#include <tuple>
#include <utility>

#include "uvtk/point.h"
#include "uvtk/testing.h"

namespace {
namespace UVTK_TEST_FILE {

using uvtk::point::Mapping;
using uvtk::point::Result;
using uvtk::point::Status;

struct Xy {
  float x, y;
};
struct Uv {
  double u, v;
};
struct Indexed {  // like Eigen::Vector2d: x() is a function, operator[] reads
  double values[2];
  double x() const { return values[0]; }
  double operator[](int i) const { return values[i]; }
};

const Mapping& sphere() {
  static const Mapping m("--projector sphere");
  return m;
}

// The one failure `check` reports, captured instead of failing this test.
std::string failureOf(const std::function<void()>& check) {
  ::testing::TestPartResultArray results;
  {
    ::testing::ScopedFakeTestPartResultReporter reporter(
        ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &results);
    check();
  }
  EXPECT_EQ(results.size(), 1);
  return results.size() == 1 ? results.GetTestPartResult(0).message() : "";
}

void expectContains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "expected \"" << part << "\" in:\n" << text;
}

TEST(UvNear, AcceptsEveryPairShape) {
  const Result r = sphere().at({0, 1, 0});  // (0.25, 0.5)
  EXPECT_UV_NEAR((std::array<double, 2>{0.25, 0.5}), r, 1e-12);
  EXPECT_UV_NEAR((std::array<float, 2>{0.25f, 0.5f}), r, 1e-7);
  EXPECT_UV_NEAR(std::make_pair(0.25, 0.5), r, 1e-12);
  EXPECT_UV_NEAR(std::make_tuple(0.25f, 0.5, 7), r, 1e-12);
  EXPECT_UV_NEAR((Xy{0.25f, 0.5f}), r, 1e-7);
  EXPECT_UV_NEAR((Uv{0.25, 0.5}), r, 1e-12);
  EXPECT_UV_NEAR((Indexed{{0.25, 0.5}}), r, 1e-12);
  const double raw[2] = {0.25, 0.5};
  EXPECT_UV_NEAR(raw, r, 1e-12);
  EXPECT_UV_NEAR(r, r, 0.0);  // another Result
  ASSERT_UV_NEAR(std::make_pair(0.25, 0.5), r, 1e-12);
  const std::array<double, 2> uv = uvtk::point::uvOf(Xy{1.5f, -2});
  EXPECT_EQ(uv[0], 1.5);
  EXPECT_EQ(uv[1], -2.0);
}

TEST(UvNear, ComparesUModuloOneAndIgnoresUAtPoles) {
  const Result r = sphere().at({1, -0.1, 0});                // u just below 1
  EXPECT_UV_NEAR(std::make_pair(r.u - 1.0, r.v), r, 1e-12);  // a shader's (-1/2, 1/2] range
  EXPECT_UV_NEAR(std::make_pair(r.u + 3.0, r.v), r, 1e-12);
  const Result seam = sphere().at({1, 0, 0});
  EXPECT_UV_NEAR(std::make_pair(1.0, 0.5), seam, 0.0);
  EXPECT_UV_NEAR(std::make_pair(0.0, 0.5), seam, 0.0);
  const Result pole = sphere().at({0, 0, 1});
  EXPECT_UV_NEAR(std::make_pair(0.37, 1.0), pole, 0.0);  // u is anything at a pole
}

TEST(UvNear, FailureNamesPositionMappingAndModulo) {
  const Result r = sphere().at({0, 1, 0});
  const std::pair<double, double> shaderUv(1.3, 0.5);
  // The documented form: the failure names the corner and the comparison.
  EXPECT_NONFATAL_FAILURE(EXPECT_UV_NEAR(shaderUv, r, 1e-9), "u modulo 1");
  const std::string message = failureOf([&] { EXPECT_UV_NEAR(shaderUv, r, 1e-9); });
  expectContains(message, "UV mismatch at position (0, 1, 0), mapping \"--projector sphere\"");
  expectContains(message, "actual:    shaderUv = (1.3, 0.5)");
  expectContains(message, "expected:  r = (0.25, 0.5), status ok");
  expectContains(message,
                 "compared:  u modulo 1 (the period (1, 0)): the 1 whole turn between actual and expected does not "
                 "count");
  expectContains(message, "error:     0.050000000000000044 (0.05) > tolerance 1e-9");
  EXPECT_EQ(message.find("1e-9 ="), std::string::npos) << message;  // the literal is its own value
  // A tolerance given by name shows its value.
  const double kTolerance = 1e-3;
  const std::string named = failureOf([&] { EXPECT_UV_NEAR(shaderUv, r, kTolerance); });
  expectContains(named, "> tolerance kTolerance = 0.001");
}

TEST(UvNear, FailureAtPoleSaysUIsIgnored) {
  const Result pole = sphere().at({0, 0, -4});
  const std::string message = failureOf([&] { EXPECT_UV_NEAR(std::make_pair(0.5, 0.25), pole, 1e-12); });
  expectContains(message, "at position (0, 0, -4)");
  expectContains(message, "status pole (on the axis: u is undefined there (written as 0), v is exact)");
  expectContains(message,
                 "compared:  v only: u is undefined at a pole, so the component along the period (1, 0) is "
                 "ignored");
  expectContains(message, "error:     0.25 > tolerance 1e-12");
}

TEST(UvNear, FailureWhereNothingWrapsComparesDirectly) {
  const Mapping plane("--projector plane");
  const Result r = plane.at({0.25, 0.5, 0});
  const std::string message = failureOf([&] { EXPECT_UV_NEAR(std::make_pair(1.25, 0.5), r, 0.0); });
  expectContains(message, "mapping \"--projector plane\"");
  expectContains(message, "compared:  u and v as they are (nothing wraps)");
  EXPECT_EQ(message.find("modulo"), std::string::npos) << message;
}

TEST(UvNear, AnInvalidReferenceAlwaysFails) {
  const Result centre = sphere().at({0, 0, 0});
  const std::string message = failureOf([&] { EXPECT_UV_NEAR(std::make_pair(0.0, 0.0), centre, 1.0); });
  expectContains(message, "status invalid (the point is the sphere's centre)");
  expectContains(message, "the reference has no value at this point");
  EXPECT_UV_STATUS(centre, Status::Invalid);
}

TEST(UvNear, NotFiniteActualFails) {
  const Result r = sphere().at({0, 1, 0});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::string message = failureOf([&] { EXPECT_UV_NEAR(std::make_pair(nan, 0.5), r, 1.0); });
  expectContains(message, "actual is not finite");
}

void assertThenContinue(const Result& r, bool* reached) {
  ASSERT_UV_NEAR(std::make_pair(0.5, 0.5), r, 1e-12);
  *reached = true;
}

TEST(UvNear, AssertStopsTheFunction) {
  static Result r;
  r = sphere().at({0, 1, 0});
  static bool reached = false;
  EXPECT_FATAL_FAILURE(assertThenContinue(r, &reached), "UV mismatch at position (0, 1, 0)");
  EXPECT_FALSE(reached);
}

TEST(UvStatus, PassesAndFailsWithTheReason) {
  const Result pole = sphere().at({0, 0, 1});
  EXPECT_UV_STATUS(pole, Status::Pole);
  const std::string message = failureOf([&] { EXPECT_UV_STATUS(pole, Status::Ok); });
  expectContains(message, "UV status mismatch at position (0, 0, 1), mapping \"--projector sphere\"");
  expectContains(message,
                 "actual:    pole has status pole (on the axis: u is undefined there (written as 0), v is "
                 "exact), (u, v) = (0, 1)");
  expectContains(message, "expected:  Status::Ok = ok");
}

TEST(UvStatus, GoogleTestPrintsStatusesAndResults) {
  EXPECT_EQ(::testing::PrintToString(Status::OnSeam), "on-seam");
  const std::string printed = ::testing::PrintToString(sphere().at({0, 1, 0}));
  expectContains(printed, "(u, v) = (0.25, 0.5)");
  expectContains(printed, "status ok");
  expectContains(printed, "mapping \"--projector sphere\"");
}

}  // namespace UVTK_TEST_FILE
}  // namespace
