// Overlap of a UV layout, measured by rasterizing it: how much of the covered texture area is
// covered more than once.
//
// The faces are drawn into a resolution x resolution grid of pixels over a box of the UV plane;
// measureOverlap uses the faces' own UV bounding box (as they lie: a seam-shifted layout in u in
// [0, 1.5) is not wrapped). A pixel is covered by a triangle when its centre is. Corners snap to
// 1/256 pixel and coverage is decided by exact integer edge functions with a tie rule (an edge
// owns the centres on it when, with the corners made counter-clockwise, it runs downward in v or
// horizontally towards +u: the top-left rule with rows counted from v = max), so two triangles
// sharing an edge cover each centre on it once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include <Eigen/Geometry>

#include "analysis/distortion.h"
#include "core/uv_map.h"

namespace uvtk::analysis {

struct Overlap {
  int resolution = 0;  // the raster's, after overlapResolution
  std::size_t coveredPixels = 0;     // covered at least once
  std::size_t overlappedPixels = 0;  // covered at least twice
  std::size_t overlappedFaces = 0;   // faces covering a pixel centre that another face covers too
  // overlappedPixels / coveredPixels; 0 when nothing is covered.
  double fraction() const {
    return coveredPixels == 0 ? 0.0 : static_cast<double>(overlappedPixels) / static_cast<double>(coveredPixels);
  }
};

// A resolution x resolution grid over `bounds`: pixel (x, y) is the cell whose lower-left corner
// is bounds.min() + (x, y) bounds.sizes() / resolution, y counted upward from v = bounds.min().y()
// (pixel index y * resolution + x); its centre is half a cell further.
struct UvGrid {
  Eigen::AlignedBox2d bounds;  // in UV units times scale
  int resolution = 0;
  // A power of two every UV is multiplied by before it is placed: 1, except for layouts beyond about
  // 1e150 or below 1e-150 (measureUvScale), whose box would overflow or underflow (-1e308 .. 1e308).
  double scale = 1.0;
};

// The UV bounding box of the faces the overlap raster draws (isMeasured), the box measureOverlap's grid spans.
Eigen::AlignedBox2d measuredUvBounds(const UvMap& uv, const FaceMeasures& faces);

// The grid of `resolution` pixels a side over `uvBounds` (non-empty, finite), with its scale.
UvGrid uvGridOver(const Eigen::AlignedBox2d& uvBounds, int resolution);

// Calls visit(face, y, x0, x1) for every row y of `grid` whose pixel centres x0..x1 (inclusive, never
// empty) a face covers: the rows of forEachCoveredPixel's pixels, each solved exactly in integers from
// the three edge functions, so the cost is one call per row and face plus the pixels themselves.
// Preconditions as forEachCoveredPixel.
void forEachCoveredSpan(const UvMap& uv, const FaceMeasures& faces, const UvGrid& grid,
                        const std::function<void(std::size_t face, int y, int x0, int x1)>& visit);

// Calls visit(face, x, y) for every pixel centre of `grid` that a face covers, face by face in
// index order, for the faces with a non-degenerate Jacobian (isMeasured(faces.status[f]): ok,
// pole, backfacing and flipped faces, whatever their winding). Preconditions: `faces` from
// measureFaces on the same UVs; bounds of positive finite size; resolution in [1, 65536]; every
// corner of a drawn face within the bounds enlarged by their size on every side, which keeps the
// exact integer arithmetic far from overflow (the grid may show part of a layout: pixels outside
// it are skipped).
void forEachCoveredPixel(const UvMap& uv, const FaceMeasures& faces, const UvGrid& grid,
                         const std::function<void(std::size_t face, int x, int y)>& visit);

// Per pixel of `grid` (index y * resolution + x), how many faces cover its centre, saturating at
// 255. Preconditions as forEachCoveredPixel.
std::vector<std::uint8_t> coverageCounts(const UvMap& uv, const FaceMeasures& faces, const UvGrid& grid);

// The raster's work is bounded by the input: at most kOverlapWorkBase plus kOverlapWorkPerFace per
// measured face. Its work is the grid's scan (resolution^2) and a step per span of a face's row
// (spans are counted as differences, not pixel by pixel), so faces stacked on one another cost their
// rows, not their area: a thousand copies of a triangle over the grid stay at 1024; a million faces
// each as tall as the layout would not.
constexpr double kOverlapWorkBase = double(1 << 23);
constexpr double kOverlapWorkPerFace = 256.0;

// `resolution` (for kOverlapFollowsMesh, followingOverlapResolution of these faces), halved until the
// raster's estimated work (the grid's pixels, the faces' rows twice, one step per face) is within the
// budget above. `unitGrid`: uvGridOver(measuredUvBounds(uv, faces), 1).
int overlapResolution(const UvMap& uv, const FaceMeasures& faces, const UvGrid& unitGrid,
                      int resolution);

// The judgement's raster follows the mesh unless a resolution is asked (kOverlapFollowsMesh):
// sixteen pixels for the mean measured face, R = sqrt(kOverlapPixelsPerFace F / share) for F faces
// covering `share` of the layout's box (their UV areas summed, overlaps counted each time), rounded,
// from kOverlapMinResolution to kOverlapMaxFollowingResolution. Measured on 42 mappings of like-real
// meshes (docs/benchmarks.md, issue 45), sixteen pixels a face keep the overlapped fraction within
// 0.002 of a 1024 grid's; counting the box's share keeps a sparse layout (a few faces in a wide box)
// as fine as a full one.
constexpr int kOverlapFollowsMesh = 0;  // the resolution that asks for it
constexpr int kMaxOverlapResolution = 16384;  // the most `--overlap-resolution` may ask for
constexpr int kOverlapMinResolution = 256;
constexpr int kOverlapMaxFollowingResolution = 1024;
constexpr double kOverlapPixelsPerFace = 16.0;

// That rule: round(sqrt(16 F / boxShare)) clamped to 256 .. 1024; 1024 when boxShare is 0.
int followingOverlapResolution(std::size_t measuredFaces, double boxShare);

// Covered and overlapped pixels from the coverageCounts of those faces over their own UV bounding
// box at overlapResolution, and the faces that cover an overlapped pixel. Preconditions: `faces` from
// measureFaces on the same UVs, resolution kOverlapFollowsMesh or in [1, 65536]. Bands of the grid's
// rows are shared out to `threads` (core/parallel.h's count).
Overlap measureOverlap(const UvMap& uv, const FaceMeasures& faces, int resolution = 1024, int threads = 1);

}  // namespace uvtk::analysis
