// weights and blendzone: a triplanar mapping's blend weights per pixel. The renderer draws the
// blend itself with a solid red, green and blue texture for the x, y and z lookups, so that each
// pixel's colour is (w_x, w_y, w_z): the weights exactly as `uvtk render` blends them. docs/views.md.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "render/texture.h"
#include "views/canvas.h"
#include "views/draw.h"
#include "views/legend.h"
#include "views/palette.h"
#include "views/scene.h"

namespace uvtk::views {

namespace {

constexpr int kU = 0, kFace = 3;  // channels of render::Rendering::aovs
// Not a weights colour (those sum to 1): pixels where the mapping has no weights.
const Vec3 kNoWeightsColour{1.0, 1.0, 1.0};
const Vec3 kBlendZoneColour{1.0, 0.0, 1.0};  // magenta
constexpr double kDimGrey = 0.45;             // blendzone: the rest of the mesh, times its shade

render::Texture solidTexture(const Vec3& colour) {
  render::TexelLevel base;
  base.width = base.height = 1;
  base.texels = {render::Rgba(float(colour.x()), float(colour.y()), float(colour.z()), 1.0f)};
  return render::Texture(std::move(base), false);
}

void requireBlend(View view, const ViewInput& in) {
  if (!in.exact || !in.exact->blendAt)
    throw UsageError(std::string(toString(view)) + ": expected a triplanar mapping (--projector triplanar), found " +
                     (in.exact ? "a mapping without blend weights" : "no mapping evaluated per pixel"));
}

// The weights as colours: in.exact drawn with the x, y and z lookups reading solid red, green and
// blue (NEAREST, REPLACE, so no lighting), and `texture` white, which a blend reads only where it
// has no weights. `samplesPerPixel` as RenderOptions::samplesPerPixel.
render::Rendering renderWeights(const ViewInput& in, const ViewOptions& options, int samplesPerPixel, bool aovs) {
  const render::Texture red = solidTexture(Vec3::UnitX()), green = solidTexture(Vec3::UnitY()),
                        blue = solidTexture(Vec3::UnitZ()), none = solidTexture(kNoWeightsColour);
  render::RenderOptions o = options.render;
  o.texture = &none;
  o.cubeTexture = nullptr;
  o.axisTextures = {&red, &green, &blue};
  o.sampler = render::SamplerState{};
  o.env = render::EnvMode::Replace;
  o.aovs = aovs;
  o.samplesPerPixel = samplesPerPixel;
  render::TexcoordSource source;
  source.pixelMapping = in.exact;
  return render::render(*in.mesh, source, o);
}

// What each pixel of a one-sample rendering with AOVs is for the blend zone.
enum class ZonePixel { Background, NoWeights, InZone, Outside };

ZonePixel zonePixel(const render::Rendering& r, int x, int row, double threshold) {
  if (r.aovs.at(x, row, kFace) < 0.0f) return ZonePixel::Background;
  // A blend without weights leaves (u, v) NaN (render/renderer.h); with weights, those of the heaviest lookup.
  if (!std::isfinite(r.aovs.at(x, row, kU))) return ZonePixel::NoWeights;
  const Vec3 w = pixelColour(r.colour, x, row);
  return w.maxCoeff() < threshold ? ZonePixel::InZone : ZonePixel::Outside;
}

struct ZoneRendering {
  render::Rendering rendering;  // one sample per pixel, with AOVs
  BlendZone zone;
};

ZoneRendering zoneRendering(View view, const ViewInput& in, const ViewOptions& options) {
  requireBlend(view, in);
  UVTK_CHECK(in.mesh);
  const double t = options.blendZoneThreshold;
  if (!(t > 0.0 && t <= 1.0))
    throw UsageError(std::string(toString(view)) + ": expected a blend-zone threshold in (0, 1], found " + formatNumber(t));
  ZoneRendering out{renderWeights(in, options, 1, true), BlendZone{}};
  out.zone.threshold = t;
  const Image& colour = out.rendering.colour;
  for (int row = 0; row < colour.height; ++row)
    for (int x = 0; x < colour.width; ++x) {
      const ZonePixel pixel = zonePixel(out.rendering, x, row, t);
      out.zone.invalidPixels += pixel == ZonePixel::NoWeights;
      out.zone.coveredPixels += pixel == ZonePixel::InZone || pixel == ZonePixel::Outside;
      out.zone.pixels += pixel == ZonePixel::InZone;
    }
  return out;
}

std::string zoneShare(const BlendZone& zone) {
  return formatNumber(100.0 * zone.share()) + " % of " + std::to_string(zone.coveredPixels) + " covered pixels";
}

void addNoWeights(Legend& legend, const BlendZone& zone) {
  if (zone.invalidPixels > 0)
    legend.entries.push_back({kNoWeightsColour, "no weights: " + std::to_string(zone.invalidPixels) + " pixels"});
}

}  // namespace

BlendZone blendZone(const ViewInput& in, const ViewOptions& options) {
  return zoneRendering(View::BlendZone, in, options).zone;
}

DrawnView drawWeights(const ViewInput& in, const ViewOptions& options) {
  ZoneRendering counted = zoneRendering(View::Weights, in, options);
  // The picture at the samples per pixel asked for; the counts always at one, a fragment a pixel.
  Image image = options.render.samplesPerPixel == 1
                    ? std::move(counted.rendering.colour)
                    : renderWeights(in, options, options.render.samplesPerPixel, false).colour;
  const BlendZone& zone = counted.zone;
  Legend legend;
  legend.title = {"triplanar weights",
                  "blend zone (every weight < " + formatNumber(zone.threshold) + "): " + zoneShare(zone)};
  legend.entries = {{Vec3::UnitX(), "x projection"}, {Vec3::UnitY(), "y projection"}, {Vec3::UnitZ(), "z projection"}};
  addNoWeights(legend, zone);
  return {std::move(image), legend};
}

DrawnView drawBlendZone(const ViewInput& in, const ViewOptions& options) {
  const ZoneRendering counted = zoneRendering(View::BlendZone, in, options);
  const render::Rendering& r = counted.rendering;
  // The rest of the mesh dim grey under the views' head-light shade.
  const std::vector<double> shade = faceShades(*in.mesh, options.render);
  Image image(r.colour.width, r.colour.height, 3);
  for (int row = 0; row < image.height; ++row)
    for (int x = 0; x < image.width; ++x) {
      Vec3 colour = options.render.background;
      switch (zonePixel(r, x, row, counted.zone.threshold)) {
        case ZonePixel::Background: break;
        case ZonePixel::NoWeights: colour = kNoWeightsColour; break;
        case ZonePixel::InZone: colour = kBlendZoneColour; break;
        case ZonePixel::Outside: colour = Vec3::Constant(kDimGrey * shade[std::size_t(r.aovs.at(x, row, kFace))]); break;
      }
      setPixel(image, x, row, colour);
    }
  const BlendZone& zone = counted.zone;
  const std::string t = formatNumber(zone.threshold);
  Legend legend;
  legend.title = {"triplanar blend zone: every weight < " + t};
  legend.entries = {{kBlendZoneColour, "blend zone: " + std::to_string(zone.pixels) + " pixels, " + zoneShare(zone)},
                    {Vec3::Constant(kDimGrey), "a weight ≥ " + t}};
  addNoWeights(legend, zone);
  return {image, legend};
}

}  // namespace uvtk::views
