#include "views/measure.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/statistics.h"
#include "core/error.h"

namespace uvtk::views {

namespace {

constexpr double kMinTop = 1.0001;  // the scale keeps a width when every face is exact
constexpr int kTickCount = 5;

std::vector<std::string> titleOf(View measure) {
  if (measure == View::Stretch) return {"L2 stretch, normalised (1: isometric)"};
  if (measure == View::Linf) return {"L∞ stretch, normalised (1: isometric)"};
  if (measure == View::Angle) return {"Angle distortion σ₁/σ₂ (1: conformal)"};
  if (measure == View::Density) return {"Texel density, texels per unit"};
  return {"Area distortion log₂ r (0: equiareal)", "Blue: compressed   red: stretched"};
}

// Evenly spaced over the scale (over log10 of the values for a logarithmic one); the ends say
// that values beyond them take the end colours.
std::vector<Tick> ticksOf(const ColourScale& scale) {
  std::vector<double> values;
  for (int k = 0; k < kTickCount; ++k) {
    const double x = scale.lo + (scale.hi - scale.lo) * k / (kTickCount - 1);
    values.push_back(scale.logarithmic ? std::pow(10.0, x) : x);
  }
  std::vector<std::string> labels = distinctLabels(values);
  // Densities in whole texels per unit where they reach 100 (1024, not 1.02e+03); the ticks lie a
  // constant ratio above 1 apart, so the labels stay distinct.
  if (scale.logarithmic)
    for (std::size_t k = 0; k < values.size(); ++k)
      labels[k] = formatNumber(values[k], std::max(3, 1 + int(std::floor(std::log10(values[k])))));
  if (scale.palette == Palette::Diverging || scale.logarithmic) labels.front() = "≤" + labels.front();
  labels.back() = "≥" + labels.back();
  std::vector<Tick> ticks;
  for (int k = 0; k < kTickCount; ++k) ticks.push_back({values[std::size_t(k)], labels[std::size_t(k)]});
  return ticks;
}

}  // namespace

bool isMeasure(View view) {
  return view == View::Stretch || view == View::Linf || view == View::Angle || view == View::Area ||
         view == View::Density;
}

double measureValue(View measure, const analysis::FaceDistortion& face, const analysis::AreaTotals& totals,
                    const analysis::TexelDensity* density) {
  UVTK_CHECK(isMeasure(measure));
  if (measure == View::Density) {
    UVTK_CHECK(density);
    return density->finite ? analysis::texelDensity(face, *density)
                           : analysis::scaledTexelDensity(face, density->textureSize);
  }
  // Sander et al. 2001, "Texture stretch metric": times sqrt(sum(Auv) / sum(A3)), as analysis/summary.h does.
  const double normalisation = std::sqrt(1.0 / totals.surfacePerUv());
  if (measure == View::Stretch) return face.l2Stretch() * normalisation;
  if (measure == View::Linf) return face.linfStretch() * normalisation;
  if (measure == View::Angle) return face.angleDistortion();
  return face.areaDistortion(totals.surfacePerUv());
}

ColourScale measureScale(View measure, const analysis::FaceMeasures& faces,
                         const analysis::Summary& summary) {
  UVTK_CHECK(isMeasure(measure));
  if (measure == View::Density) {
    const analysis::TexelDensity& d = summary.density;
    const analysis::Statistics& s = d.finite ? d.statistics : d.scaled;
    if (s.totalWeight <= 0.0) return {Palette::Sequential, 0.0, 1.0, true};  // no ok face: nothing on the scale
    const double lo = std::min(s.p50 / 2.0, s.p10), hi = std::max(2.0 * s.p50, s.p90);
    return {Palette::Sequential, std::log10(lo), std::log10(hi), true};
  }
  if (measure == View::Area) {
    std::vector<double> magnitudes, weights;
    const double surfacePerUv = summary.okTotals.surfacePerUv();
    for (const analysis::FaceDistortion& face : faces)
      if (face.status == analysis::FaceStatus::Ok) {
        magnitudes.push_back(std::fabs(face.areaDistortion(surfacePerUv)));
        weights.push_back(face.area3d);
      }
    const double p99 = analysis::weightedStatistics(magnitudes, weights, analysis::BinSpacing::Linear).p99;
    const double r = std::max(p99, std::log2(kMinTop));
    return {Palette::Diverging, -r, r, false};
  }
  const analysis::Statistics& statistics = measure == View::Stretch ? summary.l2Stretches
                                           : measure == View::Linf  ? summary.linfStretches
                                                                    : summary.angleDistortion;
  return {Palette::Sequential, 1.0, std::max(statistics.p99, kMinTop), false};
}

FaceColouring colourByMeasure(View measure, const analysis::Judgement& judgement) {
  const analysis::FaceMeasures& faces = judgement.faces;
  const analysis::Summary& summary = judgement.summary;
  const ColourScale scale = measureScale(measure, faces, summary);
  const analysis::AreaTotals totals = analysis::okAreaTotals(faces);
  FaceColouring out;
  out.colours.reserve(faces.size());
  for (const analysis::FaceDistortion& face : faces)
    out.colours.push_back(face.status == analysis::FaceStatus::Ok
                              ? scale.colour(measureValue(measure, face, totals, &summary.density))
                              : statusColour(face.status));
  out.legend.title = titleOf(measure);
  if (measure == View::Density) {
    const analysis::TexelDensity& d = summary.density;
    out.legend.title.push_back("of a " + std::to_string(d.textureSize.width) + " × " +
                               std::to_string(d.textureSize.height) + " texture" +
                               (d.finite ? "" : ", times 2^" + std::to_string(d.exponent) + " (beyond a double)"));
  }
  out.legend.bar = ColourBar{scale, ticksOf(scale)};
  for (int s = 0; s < analysis::kFaceStatusCount; ++s) {
    const auto status = static_cast<analysis::FaceStatus>(s);
    if (status != analysis::FaceStatus::Ok && summary.statusCounts[status] > 0)
      out.legend.entries.push_back(
          {statusColour(status), std::string(analysis::toString(status)) + ": " + std::to_string(summary.statusCounts[status])});
  }
  return out;
}

}  // namespace uvtk::views
