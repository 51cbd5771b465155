// The inspection views of a UV mapping: the mesh textured with test patterns, per-face
// distortion heatmaps, the seams, the error of per-vertex UVs against the exact mapping, and the
// UV layout itself; and a contact sheet that puts several views side by side. docs/views.md
// describes every view, its colour map, legend and scale so that it can be reproduced.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "analysis/distortion.h"
#include "analysis/judgement.h"
#include "core/image.h"
#include "core/mesh.h"
#include "core/uv_map.h"
#include "render/renderer.h"
#include "views/legend.h"

namespace uvtk::views {

enum class View { Checker, Uvgrid, Stretch, Linf, Angle, Area, Seams, UvError, Layout, Density, Weights, BlendZone, MipLine, Bleed };

// "checker", "uvgrid", "stretch", "linf", "angle", "area", "seams", "uverror", "layout", "density",
// "weights", "blendzone", "mipline", "bleed".
const char* toString(View view);
std::optional<View> parseView(std::string_view name);
// "stretch,seams" -> {Stretch, Seams}, in the given order. Throws UsageError naming the bad entry
// and the valid names.
// Throws UsageError naming `option` for an unknown name, with the nearest one.
std::vector<View> parseViewList(const std::string& commaList, const std::string& option = "--view");
// Whether the view reads the mapping evaluated per pixel (ViewInput::exact): UvError, and Weights
// and BlendZone, which read a triplanar mapping's blend weights (PixelMapping::blendAt).
bool needsExactMapping(View view);

struct ViewInput {
  const Mesh* mesh = nullptr;
  const UvMap* uv = nullptr;  // 3 corners per triangle, face flags (kFaceSeamStraddle, kFacePole, kFaceInvalid...)
  // The mapping's judgement (analysis/judgement.h): its per-face measures, summary, pole vertices
  // and counts. Every number a legend shows is read from it, so that legends equal the JSON.
  const analysis::Judgement* judgement = nullptr;
  bool wrapsU = false;            // u compared modulo 1 by uverror
  std::optional<render::PixelMapping> exact;  // the mapping evaluated per pixel; required by UvError (UsageError if missing)
  const std::vector<double>* q = nullptr;     // texgen's q per corner; none: 1
  bool cubeFaceIds = false;                   // uv.w holds cube face ids (render::TexcoordSource::cubeFaceIds)
};

struct ViewOptions {
  // Camera, model, raster options, lighting, background; render.texture = the bound texture
  // (uverror measures in its texels; checker and uvgrid bind their own).
  render::RenderOptions render;
  View layoutFill = View::Stretch;  // measure that fills triangles in the layout view: Stretch, Linf, Angle, Area or Density
  int layoutSize = 512;             // layout image is layoutSize x layoutSize (+ legend); the bleed view's too
  // bleed: the mip level shown (0 the full texture); unset: the first level where charts mix, else 0.
  std::optional<int> bleedLevel;
  int checks = 16;                  // checker view: checks across the unit square, 1..1024 (UsageError outside)
  // weights and blendzone: a covered pixel is in the triplanar blend zone when every weight is
  // below this, i.e. no single projection dominates it; in (0, 1] (UsageError outside).
  double blendZoneThreshold = 0.9;
  // mipline: draw the mapping evaluated per pixel (ViewInput::exact), as a shader does; else, or
  // without it, the corners as interpolated.
  bool perPixel = false;
};

// The view as a 3-channel RGB image in [0, 1], row 0 at the top. The camera views are
// render.camera's width x height, with the legend in a strip below (docs/views.md).
// Preconditions: mesh and uv set; the judgement for the heatmaps, seams and layout. Throws UsageError for uverror without `exact`,
// for weights and blendzone without a triplanar `exact` (one with blendAt), and for a layout fill
// that is not a measure or a layoutSize outside 16..16384.
Image drawView(View view, const ViewInput& in, const ViewOptions& options);

// A view before its legend strip is drawn, and that legend.
struct DrawnView {
  Image image;
  Legend legend;
};
// drawView's picture and legend apart (drawView puts the legend in a strip below the picture).
DrawnView drawViewAndLegend(View view, const ViewInput& in, const ViewOptions& options);

// Per pixel, |uv_per_vertex - uv_exact| in texels of options.render.texture (W x H; 1024 x 1024
// if none): sqrt((du W)^2 + (dv H)^2), du taken modulo 1 to [-0.5, 0.5] when wrapsU. One channel
// "uverror": -1 on the background, -2 where either value is not finite (counted in
// invalidPixels). max and mean are over the `pixels` covered pixels with a finite error.
struct UvErrorMap {
  Image texels;
  double max = 0, mean = 0;
  std::size_t pixels = 0, invalidPixels = 0;
};
UvErrorMap uvErrorMap(const ViewInput& in, const ViewOptions& options);

// The triplanar blend zone: of the `coveredPixels` covered pixels with weights, the `pixels` where
// max(w_x, w_y, w_z) < threshold (options.blendZoneThreshold); `invalidPixels` covered pixels have
// no weights (non-finite). Counted on a rendering of in.exact at one sample per pixel with
// options.render's camera and raster options, the weights as the image stores them (float).
// Throws UsageError without a triplanar in.exact (PixelMapping::blendAt) or for a threshold
// outside (0, 1].
struct BlendZone {
  std::size_t pixels = 0, coveredPixels = 0, invalidPixels = 0;
  double threshold = 0.9;
  double share() const { return coveredPixels > 0 ? double(pixels) / double(coveredPixels) : 0.0; }
};
BlendZone blendZone(const ViewInput& in, const ViewOptions& options);

// The seam mip line a GPU draws: of the `coveredPixels` covered pixels, the `pixels` whose lambda
// from differences across their 2 x 2 quad (options.render.derivatives when a quad mode, else
// QuadCoarse, with options.render.seamFix) exceeds the analytic lambda by more than 1, with the
// bound texture's size (1024 x 1024 without one). Where they are, each counted once in this order:
// on a pole face (kFacePole), at a seam (a kFaceSeamStraddle face, or a quad whose u spans more than
// 1/2), at a cube edge (kFaceCubeSeam, or a quad seeing two cube faces), elsewhere. `faces`: the
// triangles with a line pixel. One sample per pixel, options.render's camera and raster options.
struct MipLine {
  std::size_t pixels = 0, coveredPixels = 0, faces = 0;
  std::size_t pole = 0, seam = 0, cubeEdge = 0, other = 0;
  render::Derivatives derivatives = render::Derivatives::QuadCoarse;
  render::SeamFix seamFix = render::SeamFix::None;
  bool perPixel = false;  // drawn per pixel (else per corner)
  double share() const { return coveredPixels > 0 ? double(pixels) / double(coveredPixels) : 0.0; }
};
MipLine mipLine(const ViewInput& in, const ViewOptions& options);

// Tiles in a grid, `columns` per row, each with its label drawn under it (views/type.h, 15 pixels
// per em), on a dark grey background. Throws UsageError for no tiles or columns < 1.
Image contactSheet(const std::vector<std::pair<std::string, Image>>& tiles, int columns);

}  // namespace uvtk::views
