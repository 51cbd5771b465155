// uverror: how far the per-vertex UVs, interpolated by the rasterizer, are from the mapping
// evaluated at every pixel, in texels, on a logarithmic scale.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/cube.h"
#include "core/error.h"
#include "render/procedural.h"
#include "views/canvas.h"
#include "views/draw.h"
#include "views/legend.h"
#include "views/scene.h"

namespace uvtk::views {

namespace {

constexpr int kDefaultTexels = 1024;  // the texture size when none is bound
constexpr float kBackground = -1.0f, kNoValue = -2.0f;
constexpr int kU = 0, kV = 1, kFace = 3, kCubeFace = 5;  // channels of render::Rendering::aovs
constexpr int kLowestDecade = -4;                          // the colour scale starts at 1e-4 texels

// The size of the texture the error is measured in: the bound one (a cube map's face), or 1024 x 1024.
std::pair<int, int> texelCounts(const render::RenderOptions& options) {
  if (options.cubeTexture) return {options.cubeTexture->size(), options.cubeTexture->size()};
  if (!options.texture) return {kDefaultTexels, kDefaultTexels};
  return {options.texture->width(), options.texture->height()};
}

// A point (s, t) of cube face `from` seen on face `onto`: where the direction through it meets
// onto's plane, so that two lookups on adjacent faces are compared in one face's texels, as
// though the cube were unfolded along their edge. NaN when the direction points away from onto.
Vec2 onCubeFace(const Vec2& st, CubeFace from, CubeFace onto) {
  if (from == onto) return st;
  const Vec3 d = glCubeDirection(from, 2.0 * st.x() - 1.0, 2.0 * st.y() - 1.0, 1.0);
  if (!(faceSign(onto) * d[faceAxis(onto)] > 0.0)) return Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
  return glCubeFaceSt(d, onto);
}

}  // namespace

UvErrorMap uvErrorMap(const ViewInput& in, const ViewOptions& options) {
  if (!in.exact)
    throw UsageError("uverror: expected the mapping evaluated per pixel (UVs from a projector or texgen), found none");
  UVTK_CHECK(in.mesh && in.uv);
  const auto [texelsU, texelsV] = texelCounts(options.render);
  const bool cube = options.render.cubeTexture != nullptr;

  // Only the AOVs are read: any texture of the bound kind will do, and a 1 x 1 one sampled NEAREST
  // costs least. A cube map's AOVs hold the face and (s, t) on it.
  const render::Texture unit = render::checkerTexture(1, 1);
  const render::CubeTexture unitCube = render::cubeIndexTexture(1);
  render::RenderOptions o = options.render;
  o.texture = cube ? nullptr : &unit;
  o.cubeTexture = cube ? &unitCube : nullptr;
  o.sampler = render::SamplerState{};
  o.env = render::EnvMode::Replace;
  o.aovs = true;
  const render::Rendering perVertex = render::render(*in.mesh, cornerTexcoords(in), o);
  render::TexcoordSource exactSource;
  exactSource.pixelMapping = in.exact;
  exactSource.cubeFaceIds = in.cubeFaceIds;
  const render::Rendering exact = render::render(*in.mesh, exactSource, o);

  UvErrorMap map;
  map.texels = Image(o.camera.width, o.camera.height, 1);
  map.texels.channelNames = {"uverror"};
  double sum = 0.0;
  for (int row = 0; row < map.texels.height; ++row)
    for (int x = 0; x < map.texels.width; ++x) {
      float& out = map.texels.at(x, row, 0);
      const float face = perVertex.aovs.at(x, row, kFace);
      UVTK_CHECK(face == exact.aovs.at(x, row, kFace));  // one mesh, one camera: one visibility
      if (face < 0.0f) {
        out = kBackground;
        continue;
      }
      const Vec2 a(perVertex.aovs.at(x, row, kU), perVertex.aovs.at(x, row, kV));
      Vec2 b(exact.aovs.at(x, row, kU), exact.aovs.at(x, row, kV));
      if (cube) {
        const int faceA = int(perVertex.aovs.at(x, row, kCubeFace)), faceB = int(exact.aovs.at(x, row, kCubeFace));
        b = faceA < 0 || faceB < 0 ? Vec2::Constant(std::numeric_limits<double>::quiet_NaN())
                                   : onCubeFace(b, CubeFace(faceB), CubeFace(faceA));
      }
      if (!a.allFinite() || !b.allFinite()) {
        out = kNoValue;
        ++map.invalidPixels;
        continue;
      }
      Vec2 d = a - b;
      if (in.wrapsU && !cube) d.x() -= std::round(d.x());  // u has period 1: the nearest of its differences
      const double error = std::hypot(d.x() * double(texelsU), d.y() * double(texelsV));
      out = float(error);
      sum += error;
      map.max = std::max(map.max, error);
      ++map.pixels;
    }
  map.mean = map.pixels > 0 ? sum / double(map.pixels) : 0.0;
  return map;
}

DrawnView drawUvError(const ViewInput& in, const ViewOptions& options) {
  const UvErrorMap map = uvErrorMap(in, options);
  // Decades from 1e-4 texels to the first power of ten at or above the largest error, at least one.
  int topDecade = kLowestDecade + 1;
  if (map.max > std::pow(10.0, topDecade)) topDecade = int(std::ceil(std::log10(map.max)));
  const ColourScale scale{Palette::Sequential, double(kLowestDecade), double(topDecade), true};

  Image image(map.texels.width, map.texels.height, 3);
  for (int row = 0; row < image.height; ++row)
    for (int x = 0; x < image.width; ++x) {
      const float error = map.texels.at(x, row, 0);
      setPixel(image, x, row,
               error == kBackground ? options.render.background
               : error == kNoValue  ? statusColour(analysis::FaceStatus::Invalid)
                                    : scale.colour(error));
    }

  std::vector<double> decades;
  for (int k = kLowestDecade; k <= topDecade; ++k) decades.push_back(std::pow(10.0, k));
  const std::vector<std::string> labels = distinctLabels(decades);
  ColourBar bar{scale, {}};
  for (std::size_t k = 0; k < decades.size(); ++k) bar.ticks.push_back({decades[k], (k == 0 ? "≤" : "") + labels[k]});
  const auto [texelsU, texelsV] = texelCounts(options.render);
  Legend legend;
  legend.title = {"UV error, per-vertex vs exact, in texels of " + std::to_string(texelsU) + "×" + std::to_string(texelsV),
                  "max " + formatNumber(map.max) + "   mean " + formatNumber(map.mean)};
  legend.bar = bar;
  if (map.invalidPixels > 0)
    legend.entries.push_back({statusColour(analysis::FaceStatus::Invalid), "no value: " + std::to_string(map.invalidPixels) + " pixels"});
  return {image, legend};
}

}  // namespace uvtk::views
