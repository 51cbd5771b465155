// Overlap of a UV layout, measured by rasterizing it: how much of the covered texture area is
// covered more than once.
//
// The faces are drawn into a resolution x resolution grid over their own UV bounding box (as
// they lie: a seam-shifted layout in u in [0, 1.5) is not wrapped). A pixel is covered by a
// triangle when its centre is. Corners snap to 1/256 pixel and coverage is decided by exact
// integer edge functions with a tie rule (an edge owns the centres on it when, with the corners
// made counter-clockwise, it runs downward in v or horizontally towards +u: the top-left rule
// with rows counted from v = max), so two triangles sharing an edge cover each centre on it once.
#pragma once

#include <cstddef>
#include <vector>

#include "analysis/distortion.h"
#include "core/uv_map.h"

namespace uvtk::analysis {

struct Overlap {
  int resolution = 0;
  std::size_t coveredPixels = 0;     // covered at least once
  std::size_t overlappedPixels = 0;  // covered at least twice
  // overlappedPixels / coveredPixels; 0 when nothing is covered.
  double fraction() const {
    return coveredPixels == 0 ? 0.0 : static_cast<double>(overlappedPixels) / static_cast<double>(coveredPixels);
  }
};

// Rasterizes the faces with a non-degenerate Jacobian (isMeasured(faces[f].status): ok, pole,
// backfacing and flipped faces, whatever their winding). Preconditions: `faces` from
// measureFaces on the same UVs, resolution in [1, 65536].
Overlap measureOverlap(const UvMap& uv, const std::vector<FaceDistortion>& faces, int resolution = 1024);

}  // namespace uvtk::analysis
