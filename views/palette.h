// The colours of the inspection views: two colour maps, the fixed colours of face statuses and
// of the marks drawn over the views, and the overlap hatching. docs/views.md lists every value.
#pragma once

#include <optional>

#include "analysis/distortion.h"
#include "core/math.h"

namespace uvtk::views {

enum class Palette {
  Sequential,  // viridis: dark violet at 0 through blue and green to yellow at 1, luminance rising
  Diverging,   // ColorBrewer RdBu: dark red at 0, white at 1/2, dark blue at 1
};

// The colour at t in [0, 1], interpolated linearly between the palette's table entries.
// Precondition: t finite (values clamp to [0, 1]).
Vec3 paletteColour(Palette palette, double t);

// The fixed colour of a face status other than ok (ok faces take the measure's colour).
Vec3 statusColour(analysis::FaceStatus status);

// The marks drawn over the views.
inline const Vec3 kWrapSeamColour{0.10, 0.35, 1.00};  // wrap seam edges
inline const Vec3 kCutColour{1.00, 0.10, 0.10};       // cut edges
inline const Vec3 kStraddleColour{1.00, 0.90, 0.45};  // faces flagged kFaceSeamStraddle (seams view)
inline const Vec3 kPoleVertexColour{0.0, 0.0, 0.0};   // pole vertex dots
inline const Vec3 kNeutralColour{0.75, 0.75, 0.75};   // unmarked faces in the seams view
inline const Vec3 kFrameColour{0.90, 0.90, 0.90};     // the [0, 1]^2 frame of the layout view
inline const Vec3 kLayoutBackground{0.30, 0.30, 0.30};  // layout pixels no face covers
inline const Vec3 kPanelColour{0.15, 0.15, 0.15};     // legend strips and the contact sheet
inline const Vec3 kTextColour{0.92, 0.92, 0.92};

// The marking of a layout pixel covered `count` times: for 2, one-pixel stripes along the image
// diagonal x + row, black at (x + row) mod 8 = 0 and white at 1; for 3 or more, the same stripes
// along the other diagonal (x - row) as well. nullopt between the stripes (and for count < 2),
// where the fill shows through.
std::optional<Vec3> overlapHatch(int count, int x, int row);

}  // namespace uvtk::views
