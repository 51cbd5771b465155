// Drawing into RGB images in image coordinates: x to the right, y down, pixel (x, row) the unit
// square whose centre is (x + 1/2, row + 1/2). Pixels outside the image are skipped. Text is
// views/type.h.
#pragma once

#include <functional>

#include "core/image.h"
#include "core/math.h"

namespace uvtk::views {

void setPixel(Image& image, int x, int row, const Vec3& colour);
Vec3 pixelColour(const Image& image, int x, int row);
void fillRect(Image& image, int x, int row, int width, int height, const Vec3& colour);

// Whether a pixel of a segment is drawn, given the parameter t in [0, 1] of its point on the
// segment a + t (b - a).
using SegmentTest = std::function<bool(int x, int row, double t)>;

// A segment `width` pixels wide: along its major axis every pixel whose centre lies between the
// end points, across it the `width` pixels whose centres are nearest the segment. A chain of
// segments therefore draws without gaps, however short its pieces. `test`, if given, decides
// each pixel.
void drawSegment(Image& image, const Vec2& a, const Vec2& b, int width, const Vec3& colour, const SegmentTest& test = {});

// The pixels whose centres lie within `radius` of `centre`.
void drawDot(Image& image, const Vec2& centre, double radius, const Vec3& colour);

}  // namespace uvtk::views
