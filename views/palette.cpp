#include "views/palette.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/error.h"

namespace uvtk::views {

namespace {

// matplotlib's viridis (van der Walt and Smith, 2015; CC0), entries round(255 k / 16) of its
// 256-entry table, k = 0..16: perceptually uniform, its luminance rises monotonically.
constexpr double kViridis[][3] = {
    {0.267004, 0.004874, 0.329415}, {0.282327, 0.094955, 0.417331}, {0.278826, 0.175490, 0.483397},
    {0.258965, 0.251537, 0.524736}, {0.229739, 0.322361, 0.545706}, {0.199430, 0.387607, 0.554642},
    {0.172719, 0.448791, 0.557885}, {0.149039, 0.508051, 0.557250}, {0.127568, 0.566949, 0.550556},
    {0.120081, 0.622161, 0.534946}, {0.153894, 0.680203, 0.504172}, {0.239374, 0.735588, 0.455688},
    {0.360741, 0.785964, 0.387814}, {0.506271, 0.828786, 0.300362}, {0.668054, 0.861999, 0.196293},
    {0.835270, 0.886029, 0.102646}, {0.993248, 0.906157, 0.143936},
};

// ColorBrewer RdBu, 11 classes (Brewer, colorbrewer2.org), in 8-bit sRGB from red to blue, its
// centre #f7f7f7 made pure white so that an exact value reads as white.
constexpr double kRdBu[][3] = {
    {103, 0, 31},    {178, 24, 43},   {214, 96, 77},   {244, 165, 130}, {253, 219, 199}, {255, 255, 255},
    {209, 229, 240}, {146, 197, 222}, {67, 147, 195},  {33, 102, 172},  {5, 48, 97},
};

template <std::size_t N>
Vec3 interpolate(const double (&table)[N][3], double t, double unit) {
  const double x = std::clamp(t, 0.0, 1.0) * double(N - 1);
  const std::size_t i = std::min(N - 2, std::size_t(x));
  const double f = x - double(i);
  const Vec3 a(table[i][0], table[i][1], table[i][2]), b(table[i + 1][0], table[i + 1][1], table[i + 1][2]);
  return ((1.0 - f) * a + f * b) / unit;
}

}  // namespace

Vec3 paletteColour(Palette palette, double t) {
  UVTK_CHECK(std::isfinite(t));
  return palette == Palette::Sequential ? interpolate(kViridis, t, 1.0) : interpolate(kRdBu, t, 255.0);
}

Vec3 statusColour(analysis::FaceStatus status) {
  switch (status) {
    case analysis::FaceStatus::ZeroArea3d: return {0.45, 0.25, 0.10};  // brown
    case analysis::FaceStatus::ZeroAreaUv: return {1.00, 0.55, 0.00};  // orange
    case analysis::FaceStatus::Flipped: return {1.00, 0.00, 1.00};     // magenta
    case analysis::FaceStatus::Backfacing: return {0.55, 0.55, 0.55};  // grey
    case analysis::FaceStatus::Invalid: return {0.00, 1.00, 0.00};     // green
    case analysis::FaceStatus::PoleFace: return {0.00, 1.00, 1.00};    // cyan
    case analysis::FaceStatus::Ok: break;
  }
  checkFailed("status != FaceStatus::Ok (ok faces take the measure's colour)", __FILE__, __LINE__);
}

std::optional<Vec3> overlapHatch(int count, int x, int row) {
  constexpr int kPeriod = 8;
  auto stripe = [](int diagonal) -> std::optional<Vec3> {
    const int phase = ((diagonal % kPeriod) + kPeriod) % kPeriod;
    if (phase == 0) return Vec3::Zero();
    if (phase == 1) return Vec3::Ones();
    return std::nullopt;
  };
  if (count < 2) return std::nullopt;
  if (std::optional<Vec3> c = stripe(x + row)) return c;
  return count >= 3 ? stripe(x - row) : std::nullopt;
}

}  // namespace uvtk::views
