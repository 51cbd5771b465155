// bleed: the layout as its texture holds it at one mip level (analysis/texel_layout.h): each
// texel in its chart's colour, texels of two charts red, texels where a bilinear lookup mixes two
// charts yellow, the gutter's reach (empty texels a lookup of a chart reads) grey; the legend gives
// the level's figures and the first level where charts bleed.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "analysis/texel_layout.h"
#include "core/error.h"
#include "views/canvas.h"
#include "views/draw.h"
#include "views/legend.h"
#include "views/palette.h"

namespace uvtk::views {

namespace {

constexpr int kMinSize = 16, kMaxSize = 16384;
const Vec3 kOverwrittenColour{0.90, 0.10, 0.10};
const Vec3 kClashColour{1.00, 0.85, 0.10};
const Vec3 kReachColour{0.45, 0.45, 0.45};

// Charts in muted, well-separated hues (the golden angle), so neighbours differ.
Vec3 chartColour(std::int32_t chart) {
  const double hue = std::fmod(double(chart) * 0.61803398874989485, 1.0) * 6.0;
  const double x = 1.0 - std::abs(std::fmod(hue, 2.0) - 1.0);
  const Vec3 rgb = hue < 1 ? Vec3(1, x, 0) : hue < 2 ? Vec3(x, 1, 0) : hue < 3 ? Vec3(0, 1, x)
                 : hue < 4 ? Vec3(0, x, 1) : hue < 5 ? Vec3(x, 0, 1) : Vec3(1, 0, x);
  return Vec3::Constant(0.35) + 0.4 * rgb;
}

std::string texelsText(double texels) {
  return std::isinf(texels) ? "none (one chart)" : formatNumber(texels) + " texels";
}

}  // namespace

DrawnView drawBleed(const ViewInput& in, const ViewOptions& options) {
  UVTK_CHECK(in.judgement);
  if (options.layoutSize < kMinSize || options.layoutSize > kMaxSize)
    throw UsageError("bleed: expected a size in " + std::to_string(kMinSize) + ".." + std::to_string(kMaxSize) +
                     ", found " + std::to_string(options.layoutSize));
  const analysis::TextureSize texture = in.judgement->summary.density.textureSize;
  std::vector<analysis::TexelOwners> owners;
  const analysis::TexelStatistics statistics =
      analysis::texelStatistics(*in.mesh, *in.uv, texture.width, texture.height, &owners);
  const int levels = int(statistics.levels.size());
  if (options.bleedLevel && (*options.bleedLevel < 0 || *options.bleedLevel >= levels))
    throw UsageError("--bleed-level: expected 0 to " + std::to_string(levels - 1) + " (the levels of a " +
                     std::to_string(texture.width) + " x " + std::to_string(texture.height) + " texture), found " +
                     std::to_string(*options.bleedLevel));
  const int level = options.bleedLevel.value_or(statistics.firstBleedLevel.value_or(0));
  const analysis::TexelOwners& texels = owners[std::size_t(level)];
  const analysis::TexelLevel& figures = statistics.levels[std::size_t(level)];

  // The unit square, v up: each pixel shows the texel under its centre.
  const int n = options.layoutSize;
  Image image(n, n, 3);
  for (int row = 0; row < n; ++row) {
    const int y = std::min(texels.height - 1, int((1.0 - (row + 0.5) / n) * texels.height));
    for (int px = 0; px < n; ++px) {
      const int x = std::min(texels.width - 1, int((px + 0.5) / n * texels.width));
      const std::int32_t owner = texels.at(x, y);
      const Vec3 colour = owner == analysis::kTexelMixed ? kOverwrittenColour
                          : texels.clashes(x, y)         ? kClashColour
                          : owner >= 0                   ? chartColour(owner)
                          : texels.touchedOnly(x, y)     ? kReachColour
                                                         : kLayoutBackground;
      setPixel(image, px, row, colour);
    }
  }

  Legend legend;
  legend.title.push_back("texels at mip level " + std::to_string(level) + " (" + std::to_string(texels.width) + " x " +
                         std::to_string(texels.height) + ") of a " + std::to_string(texture.width) + " x " +
                         std::to_string(texture.height) + " texture, " + std::to_string(statistics.charts) + " charts");
  legend.title.push_back("gutter " + texelsText(figures.gutterTexels) + " here; charts first mix at level " +
                         (statistics.firstBleedLevel ? std::to_string(*statistics.firstBleedLevel) : std::string("none")));
  legend.entries.push_back({chartColour(1), "mapped: " + std::to_string(figures.mapped) + " texels"});
  legend.entries.push_back({kReachColour, "gutter a lookup reads: " + std::to_string(figures.touched - figures.mapped)});
  legend.entries.push_back({kOverwrittenColour, "two charts: " + std::to_string(figures.overwritten)});
  legend.entries.push_back({kClashColour, "clashes (a lookup mixes charts): " + std::to_string(figures.clashes)});
  legend.entries.push_back({kLayoutBackground, "empty"});
  return {image, legend};
}

}  // namespace uvtk::views
