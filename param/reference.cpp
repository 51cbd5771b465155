#include "param/reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "param/sample_evaluator.h"

namespace uvtk::param {

void mapVerticesReference(const ProjectorOptions& o, const Affine3& localFromObject, const std::vector<Vec3>& positions,
                          const std::vector<Vec3>& normals, std::vector<ReferenceUv>& out) {
  if (!(o.poleEpsilon >= 0.0 && o.poleEpsilon < 1.0)) throw UsageError("--pole-eps: expected a number in [0, 1)");
  out.resize(positions.size());
  evaluatePositions<long double>(o, localFromObject, positions, normals, out.data(), MathMode::Exact, 1);
}

namespace {

// One unit in the last place of T at |value| (at least that of the smallest normal number).
template <class T>
long double ulpOf(long double value) {
  const T magnitude = std::max(static_cast<T>(std::fabs(value)), std::numeric_limits<T>::min());
  return static_cast<long double>(std::nextafter(magnitude, std::numeric_limits<T>::infinity()) - magnitude);
}

// The 99th percentile of `values` (reordered).
double percentile99(std::vector<double>& values) {
  if (values.empty()) return 0.0;
  const std::size_t k = (values.size() - 1) * 99 / 100;
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
  return values[k];
}

}  // namespace

MappingError mappingError(const std::vector<VertexUv>& result, const std::vector<ReferenceUv>& reference,
                          Precision precision, bool wrapsU) {
  MappingError e;
  std::vector<double> uvErrors, ulpErrors;
  uvErrors.reserve(result.size());
  ulpErrors.reserve(result.size());
  long double sum = 0;
  for (std::size_t i = 0; i < result.size(); ++i) {
    const ReferenceUv& r = reference[i];
    if (result[i].state != r.state) {
      ++e.stateMismatches;
      continue;
    }
    if (r.state == CornerState::Invalid) continue;
    double worstUv = 0, worstUlp = 0;
    for (int c = 0; c < 2; ++c) {
      if (c == 0 && r.state == CornerState::Pole) continue;  // u is not defined at a pole
      long double d = std::fabs(static_cast<long double>(result[i].uv[c]) - r.uv[c]);
      if (c == 0 && wrapsU) d = std::min(d, 1.0L - d);
      const long double ulp = precision == Precision::Float ? ulpOf<float>(r.uv[c]) : ulpOf<double>(r.uv[c]);
      worstUv = std::max(worstUv, static_cast<double>(d));
      worstUlp = std::max(worstUlp, static_cast<double>(d / ulp));
    }
    uvErrors.push_back(worstUv);
    ulpErrors.push_back(worstUlp);
    sum += worstUv;
  }
  e.compared = uvErrors.size();
  if (e.compared == 0) return e;
  e.maxUv = *std::max_element(uvErrors.begin(), uvErrors.end());
  e.maxUlp = *std::max_element(ulpErrors.begin(), ulpErrors.end());
  e.meanUv = static_cast<double>(sum / static_cast<long double>(e.compared));
  e.p99Uv = percentile99(uvErrors);
  e.p99Ulp = percentile99(ulpErrors);
  return e;
}

}  // namespace uvtk::param
