// The per-face distortion measures that the heatmap views and the layout view show: the value of
// a face, the colour scale, and the face colours with their legend. docs/views.md, "Heatmaps".
#pragma once

#include <vector>

#include "analysis/distortion.h"
#include "analysis/summary.h"
#include "views/legend.h"
#include "views/views.h"

namespace uvtk::views {

// Stretch, Linf, Angle, Area and Density are measures; the other views are not.
bool isMeasure(View view);

// The value a measure shows for a face with a Jacobian (analysis::isMeasured):
//   stretch  Sander's L2 stretch normalised as the mesh value is: l2Stretch sqrt(sum(Auv) / sum(A3))
//   linf     linfStretch, normalised likewise
//   angle    angleDistortion, s1 / |s2|
//   area     areaDistortion, log2 r
//   density  texel density sqrt(Auv W H / A3) in texels per object unit (analysis::texelDensity),
//            times 2^-density->exponent when !density->finite, so that it stays finite
// `totals`: okAreaTotals of the mesh's faces; `density`: the summary's, required by Density.
// Precondition: isMeasure(measure).
double measureValue(View measure, const analysis::FaceDistortion& face, const analysis::AreaTotals& totals,
                    const analysis::TexelDensity* density = nullptr);

// The colour scale of a measure:
//   stretch, linf, angle: sequential from 1 (isometric, conformal) to top = the measure's p99 over
//                         the ok faces (the summary's statistics), at least 1.0001;
//   area:                 diverging from -R to +R, R = the p99 of |log2 r| over the ok faces
//                         (weighted by their 3D area), at least log2(1.0001);
//   density:              sequential and logarithmic, centred on the median m of the ok faces'
//                         densities: from min(m/2, p10) to max(2m, p90), so that a flat density is
//                         the palette's middle and a factor of 2 either way is visible.
// Values beyond the ends take the end colours.
ColourScale measureScale(View measure, const analysis::FaceMeasures& faces,
                         const analysis::Summary& summary);

// Per face: the measure's colour for ok faces, the status colour for every other status; and the
// legend: the measure's title, its colour bar with five labelled ticks, and one entry per status
// present in the mesh with its face count.
struct FaceColouring {
  std::vector<Vec3> colours;
  Legend legend;
};
FaceColouring colourByMeasure(View measure, const analysis::Judgement& judgement);

}  // namespace uvtk::views
