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
  return {"Area distortion log₂ r (0: equiareal)", "Blue: compressed   red: stretched"};
}

// Evenly spaced over the scale; the ends say that values beyond them take the end colours.
std::vector<Tick> ticksOf(const ColourScale& scale) {
  std::vector<double> values;
  for (int k = 0; k < kTickCount; ++k) values.push_back(scale.lo + (scale.hi - scale.lo) * k / (kTickCount - 1));
  std::vector<std::string> labels = distinctLabels(values);
  if (scale.palette == Palette::Diverging) labels.front() = "≤" + labels.front();
  labels.back() = "≥" + labels.back();
  std::vector<Tick> ticks;
  for (int k = 0; k < kTickCount; ++k) ticks.push_back({values[std::size_t(k)], labels[std::size_t(k)]});
  return ticks;
}

}  // namespace

bool isMeasure(View view) {
  return view == View::Stretch || view == View::Linf || view == View::Angle || view == View::Area;
}

double measureValue(View measure, const analysis::FaceDistortion& face, const analysis::AreaTotals& totals) {
  UVTK_CHECK(isMeasure(measure));
  // Sander et al. 2001, "Texture stretch metric": times sqrt(sum(Auv) / sum(A3)), as analysis/summary.h does.
  const double normalisation = std::sqrt(1.0 / totals.surfacePerUv());
  if (measure == View::Stretch) return face.l2Stretch * normalisation;
  if (measure == View::Linf) return face.linfStretch * normalisation;
  if (measure == View::Angle) return face.angleDistortion;
  return face.areaDistortion;
}

ColourScale measureScale(View measure, const std::vector<analysis::FaceDistortion>& faces,
                         const analysis::Summary& summary) {
  UVTK_CHECK(isMeasure(measure));
  if (measure == View::Area) {
    std::vector<double> magnitudes, weights;
    for (const analysis::FaceDistortion& face : faces)
      if (face.status == analysis::FaceStatus::Ok) {
        magnitudes.push_back(std::fabs(face.areaDistortion));
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
  const std::vector<analysis::FaceDistortion>& faces = judgement.faces;
  const analysis::Summary& summary = judgement.summary;
  const ColourScale scale = measureScale(measure, faces, summary);
  const analysis::AreaTotals totals = analysis::okAreaTotals(faces);
  FaceColouring out;
  out.colours.reserve(faces.size());
  for (const analysis::FaceDistortion& face : faces)
    out.colours.push_back(face.status == analysis::FaceStatus::Ok ? scale.colour(measureValue(measure, face, totals))
                                                                  : statusColour(face.status));
  out.legend.title = titleOf(measure);
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
