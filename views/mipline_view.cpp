// mipline: the line of a too coarse mipmap level that a GPU draws where a mapping wraps. The
// mapping is drawn twice with the same camera, its level of detail taken from the analytic
// derivatives and from differences across 2 x 2 pixel quads as a GPU takes them
// (render::Derivatives); a pixel is on the line when the quad's lambda exceeds the analytic one by
// more than 1. docs/views.md.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "render/procedural.h"
#include "render/texture.h"
#include "views/canvas.h"
#include "views/draw.h"
#include "views/legend.h"
#include "views/scene.h"

namespace uvtk::views {

namespace {

constexpr int kU = 0, kFace = 3, kLod = 4, kCubeFace = 5;  // channels of render::Rendering::aovs
constexpr double kLineLevels = 1.0;                        // a pixel is on the line beyond this many levels
constexpr double kDimGrey = 0.45;                          // the rest of the mesh, times its shade

// Where a line pixel is, in this order of precedence.
enum class Place { Pole, Seam, CubeEdge, Other };
const std::array<Vec3, 4> kPlaceColour{Vec3(1.0, 0.6, 0.0), Vec3(1.0, 0.0, 0.0), Vec3(1.0, 1.0, 0.0), Vec3(1.0, 0.0, 1.0)};
const std::array<const char*, 4> kPlaceName{"pole", "seam", "cube edge", "other"};

render::Derivatives quadMode(const ViewOptions& options) {
  return options.render.derivatives == render::Derivatives::Analytic ? render::Derivatives::QuadCoarse
                                                                     : options.render.derivatives;
}

// The two renderings: lambda from the analytic derivatives and from the quad's, with AOVs.
struct LinePair {
  render::Rendering analytic, quad;
};

LinePair renderPair(const ViewInput& in, const ViewOptions& options) {
  // Lambda depends on the texture's size alone: the bound one, else 1024 x 1024 as uverror's.
  std::optional<render::Texture> fallback;
  render::RenderOptions o = options.render;
  if (!o.texture && !o.cubeTexture) {
    fallback = render::checkerTexture(1024, 128);
    o.texture = &*fallback;
  }
  o.sampler = render::SamplerState{};  // NEAREST: no mipmaps needed to read lambda
  o.env = render::EnvMode::Replace;
  o.aovs = true;
  o.samplesPerPixel = 1;
  o.lodBias = 0.0;
  render::TexcoordSource source;
  if (options.perPixel && in.exact)
    source.pixelMapping = in.exact;
  else
    source = cornerTexcoords(in);
  LinePair out;
  o.derivatives = quadMode(options);
  out.quad = render::render(*in.mesh, source, o);
  o.derivatives = render::Derivatives::Analytic;
  o.seamFix = render::SeamFix::None;
  out.analytic = render::render(*in.mesh, source, o);
  return out;
}

bool onLine(const LinePair& p, int x, int row) {
  const float face = p.quad.aovs.at(x, row, kFace);
  UVTK_CHECK(face == p.analytic.aovs.at(x, row, kFace));  // one mesh, one camera: one visibility
  return face >= 0.0f && p.quad.aovs.at(x, row, kLod) > p.analytic.aovs.at(x, row, kLod) + kLineLevels;
}

// The pixel's 2 x 2 quad (window y up, so rows pair from the bottom of the image): whether its
// covered pixels' u spans more than half a period, and whether they see different cube faces.
struct QuadSpread {
  bool wrapsU = false, cubeFaces = false;
};
QuadSpread quadSpread(const render::Rendering& r, int x, int row) {
  const int height = r.aovs.height, y = height - 1 - row;
  double lo = INFINITY, hi = -INFINITY;
  float firstFace = -2.0f;
  QuadSpread out;
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const int qx = (x & ~1) + dx, qy = (y & ~1) + dy, qrow = height - 1 - qy;
      if (qx >= r.aovs.width || qrow < 0 || r.aovs.at(qx, qrow, kFace) < 0.0f) continue;
      const double u = r.aovs.at(qx, qrow, kU);
      if (std::isfinite(u)) lo = std::min(lo, u), hi = std::max(hi, u);
      if (r.aovs.channels > kCubeFace) {
        const float cubeFace = r.aovs.at(qx, qrow, kCubeFace);
        if (firstFace == -2.0f) firstFace = cubeFace;
        out.cubeFaces = out.cubeFaces || cubeFace != firstFace;
      }
    }
  out.wrapsU = hi - lo > 0.5;
  return out;
}

Place placeOf(const ViewInput& in, const LinePair& p, int x, int row) {
  const std::size_t face = std::size_t(p.quad.aovs.at(x, row, kFace));
  const unsigned flags = in.uv->faceFlags.empty() ? unsigned(kFaceOk) : unsigned(in.uv->faceFlags[face]);
  if (flags & kFacePole) return Place::Pole;
  const QuadSpread spread = quadSpread(p.analytic, x, row);
  if ((flags & kFaceSeamStraddle) || spread.wrapsU) return Place::Seam;
  if ((flags & kFaceCubeSeam) || spread.cubeFaces) return Place::CubeEdge;
  return Place::Other;
}

struct CountedLine {
  LinePair pair;
  MipLine line;
};

CountedLine countLine(const ViewInput& in, const ViewOptions& options) {
  UVTK_CHECK(in.mesh && in.uv);
  CountedLine out{renderPair(in, options), MipLine{}};
  MipLine& line = out.line;
  line.derivatives = quadMode(options);
  line.seamFix = options.render.seamFix;
  line.perPixel = options.perPixel && in.exact;
  std::set<std::size_t> faces;
  const Image& aovs = out.pair.quad.aovs;
  for (int row = 0; row < aovs.height; ++row)
    for (int x = 0; x < aovs.width; ++x) {
      if (aovs.at(x, row, kFace) < 0.0f) continue;
      ++line.coveredPixels;
      if (!onLine(out.pair, x, row)) continue;
      ++line.pixels;
      faces.insert(std::size_t(aovs.at(x, row, kFace)));
      switch (placeOf(in, out.pair, x, row)) {
        case Place::Pole: ++line.pole; break;
        case Place::Seam: ++line.seam; break;
        case Place::CubeEdge: ++line.cubeEdge; break;
        case Place::Other: ++line.other; break;
      }
    }
  line.faces = faces.size();
  return out;
}

}  // namespace

MipLine mipLine(const ViewInput& in, const ViewOptions& options) { return countLine(in, options).line; }

DrawnView drawMipLine(const ViewInput& in, const ViewOptions& options) {
  const CountedLine counted = countLine(in, options);
  const Image& aovs = counted.pair.quad.aovs;
  const std::vector<double> shade = faceShades(*in.mesh, options.render);
  Image image(aovs.width, aovs.height, 3);
  for (int row = 0; row < aovs.height; ++row)
    for (int x = 0; x < aovs.width; ++x) {
      const float face = aovs.at(x, row, kFace);
      Vec3 colour = options.render.background;
      if (face >= 0.0f)
        colour = onLine(counted.pair, x, row) ? kPlaceColour[std::size_t(placeOf(in, counted.pair, x, row))]
                                              : Vec3::Constant(kDimGrey * shade[std::size_t(face)]);
      setPixel(image, x, row, colour);
    }
  const MipLine& line = counted.line;
  Legend legend;
  legend.title = {std::string("mip line: ") + render::toString(line.derivatives) + " lambda > analytic + 1" +
                      (line.seamFix != render::SeamFix::None ? std::string(", fix ") + render::toString(line.seamFix) : ""),
                  std::to_string(line.pixels) + " pixels, " + formatNumber(100.0 * line.share()) + " % of " +
                      std::to_string(line.coveredPixels) + " covered (" + (line.perPixel ? "per pixel" : "per corner") +
                      ")"};
  const std::array<std::size_t, 4> counts{line.pole, line.seam, line.cubeEdge, line.other};
  for (std::size_t place = 0; place < counts.size(); ++place)
    if (counts[place] > 0)
      legend.entries.push_back({kPlaceColour[place], std::string(kPlaceName[place]) + ": " + std::to_string(counts[place]) + " pixels"});
  legend.entries.push_back({Vec3::Constant(kDimGrey), "no line"});
  return {image, legend};
}

}  // namespace uvtk::views
