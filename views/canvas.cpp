#include "views/canvas.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace uvtk::views {

namespace {

bool inside(const Image& image, int x, int row) { return x >= 0 && x < image.width && row >= 0 && row < image.height; }

}  // namespace

void setPixel(Image& image, int x, int row, const Vec3& colour) {
  UVTK_CHECK(image.channels == 3 && colour.allFinite());
  if (!inside(image, x, row)) return;
  for (int c = 0; c < 3; ++c) image.at(x, row, c) = float(colour[c]);
}

Vec3 pixelColour(const Image& image, int x, int row) {
  UVTK_CHECK(image.channels == 3 && inside(image, x, row));
  return {image.at(x, row, 0), image.at(x, row, 1), image.at(x, row, 2)};
}

void fillRect(Image& image, int x, int row, int width, int height, const Vec3& colour) {
  for (int j = std::max(0, row); j < std::min(image.height, row + height); ++j)
    for (int i = std::max(0, x); i < std::min(image.width, x + width); ++i) setPixel(image, i, j, colour);
}

void drawSegment(Image& image, const Vec2& a, const Vec2& b, int width, const Vec3& colour, const SegmentTest& test) {
  UVTK_CHECK(a.allFinite() && b.allFinite() && width >= 1);
  const Vec2 d = b - a;
  const int major = std::fabs(d.y()) > std::fabs(d.x()) ? 1 : 0, minor = 1 - major;
  const int extent = major == 0 ? image.width : image.height;
  // Major-axis pixels c whose centre c + 1/2 lies between the end points, within the image.
  const double lo = std::min(a[major], b[major]), hi = std::max(a[major], b[major]);
  const int first = int(std::clamp(std::ceil(lo - 0.5), 0.0, double(extent)));
  const int last = int(std::clamp(std::floor(hi - 0.5), -1.0, double(extent - 1)));
  for (int c = first; c <= last; ++c) {
    const double t = d[major] != 0.0 ? (c + 0.5 - a[major]) / d[major] : 0.0;
    const double m = a[minor] + t * d[minor];
    // The `width` pixels whose centres i + 1/2 lie in [m - width/2, m + width/2).
    const int across = int(std::ceil(m - 0.5 * width - 0.5));
    for (int k = 0; k < width; ++k) {
      const int x = major == 0 ? c : across + k, row = major == 0 ? across + k : c;
      if (inside(image, x, row) && (!test || test(x, row, t))) setPixel(image, x, row, colour);
    }
  }
}

void drawDot(Image& image, const Vec2& centre, double radius, const Vec3& colour) {
  UVTK_CHECK(centre.allFinite());
  for (int row = int(std::floor(centre.y() - radius)); row <= int(std::ceil(centre.y() + radius)); ++row)
    for (int x = int(std::floor(centre.x() - radius)); x <= int(std::ceil(centre.x() + radius)); ++x)
      if ((Vec2(x + 0.5, row + 0.5) - centre).squaredNorm() <= radius * radius) setPixel(image, x, row, colour);
}

}  // namespace uvtk::views
