#include "analysis/uv_check.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace uvtk::analysis {

ErrorStatistics errorStatistics(std::vector<double> values) {
  ErrorStatistics s;
  s.count = values.size();
  if (values.empty()) return s;
  double sum = 0.0;
  for (double x : values) sum += x;
  s.mean = sum / double(values.size());
  // Errors near the largest double overflow their sum, not their mean: each divided first there.
  if (std::isinf(s.mean) && std::all_of(values.begin(), values.end(), [](double x) { return std::isfinite(x); })) {
    s.mean = 0.0;
    for (double x : values) s.mean += x / double(values.size());
  }
  // Nearest rank: the ceil(0.99 n)-th smallest, in integers so that no rounding moves the rank.
  const std::size_t rank = (99 * values.size() + 99) / 100;  // 1-based, in [1, n]
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(rank - 1), values.end());
  s.p99 = values[rank - 1];
  s.max = *std::max_element(values.begin() + std::ptrdiff_t(rank - 1), values.end());
  return s;
}

std::vector<CornerError> worstCorners(const std::vector<double>& error, const std::vector<CornerClass>& classes,
                                      CornerClass which, std::size_t count) {
  UVTK_CHECK(error.size() == classes.size());
  std::vector<CornerError> all;
  for (std::size_t c = 0; c < error.size(); ++c)
    if (classes[c] == which || (which == CornerClass::Pole && classes[c] == CornerClass::PoleFace))
      all.push_back({c, error[c]});
  const auto larger = [](const CornerError& a, const CornerError& b) {
    return a.error != b.error ? a.error > b.error : a.corner < b.corner;
  };
  const std::size_t n = std::min(count, all.size());
  std::partial_sort(all.begin(), all.begin() + std::ptrdiff_t(n), all.end(), larger);
  all.resize(n);
  return all;
}

UvCheck checkUvs(const UvMap& expected, const UvMap& found, const UvCheckOptions& options) {
  const std::size_t faces = expected.faceCount(), corners = 3 * faces;
  UVTK_CHECK(expected.uv.size() == corners && found.uv.size() == corners);
  UVTK_CHECK(expected.cornerInvalid.empty() || expected.cornerInvalid.size() == corners);
  UVTK_CHECK(found.cornerInvalid.empty() || found.cornerInvalid.size() == corners);
  UVTK_CHECK(options.poleCorners.empty() || options.poleCorners.size() == corners);
  const bool wraps = options.period.squaredNorm() > 0.0;

  UvCheck out;
  out.error.assign(corners, std::numeric_limits<double>::quiet_NaN());
  out.cornerClass.assign(corners, CornerClass::Main);
  std::vector<double> mainErrors, poleErrors;
  mainErrors.reserve(corners);
  for (std::size_t f = 0; f < faces; ++f) {
    const bool poleFace = expected.faceHas(f, kFacePole);
    out.poleFaces += poleFace;
    const Vec2 period = wraps && !expected.faceHas(f, kFaceCap) ? options.period : Vec2::Zero();
    for (std::size_t c = 3 * f; c < 3 * f + 3; ++c) {
      const bool noExpected = !expected.cornerInvalid.empty() && expected.cornerInvalid[c] != 0;
      const bool noFound = !found.cornerInvalid.empty() && found.cornerInvalid[c] != 0;
      if (noExpected || noFound) {
        out.cornerClass[c] = CornerClass::Invalid;
        out.invalidCorners.push_back(c);
        out.noExpected += noExpected;
        out.noFound += noFound;
        continue;
      }
      const bool pole = !options.poleCorners.empty() && options.poleCorners[c] != 0;
      out.error[c] = wrappedUvError(found.uv[c], expected.uv[c], period, pole);
      if (pole) {
        out.cornerClass[c] = CornerClass::Pole;
        ++out.poleCorners;
        poleErrors.push_back(out.error[c]);
      } else if (poleFace) {
        out.cornerClass[c] = CornerClass::PoleFace;
        ++out.poleFaceCorners;
        poleErrors.push_back(out.error[c]);
      } else {
        mainErrors.push_back(out.error[c]);
      }
    }
  }
  out.main = errorStatistics(std::move(mainErrors));
  out.pole = errorStatistics(std::move(poleErrors));
  out.worst = worstCorners(out.error, out.cornerClass, CornerClass::Main, options.worst);
  out.worstPole = worstCorners(out.error, out.cornerClass, CornerClass::Pole, options.worst);
  return out;
}

}  // namespace uvtk::analysis
