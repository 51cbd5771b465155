// A float image with interleaved channels: what the renderer draws into and what the image
// readers and writers (io/image_io.h) exchange. Row 0 is the top row, as in every image file.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace uvtk {

// A value as an 8-bit image stores it: round(clamp(c, 0, 1) * 255), NaN as 0 (io::writeImage's
// rounding, defined for NaN and the halfway cases).
inline std::uint8_t toUInt8(float c) {
  if (!(c > 0.0f)) return 0;
  if (c >= 1.0f) return 255;
  return static_cast<std::uint8_t>(std::lround(static_cast<double>(c) * 255.0));
}

struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;               // (y * width + x) * channels + c
  std::vector<std::string> channelNames;   // empty: Y, YA, RGB or RGBA by the channel count

  Image() = default;
  Image(int w, int h, int c, float fill = 0.0f)
      : width(w), height(h), channels(c), pixels(std::size_t(w) * std::size_t(h) * std::size_t(c), fill) {}

  std::size_t index(int x, int y, int c = 0) const {
    return (std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels) + std::size_t(c);
  }
  float& at(int x, int y, int c) { return pixels[index(x, y, c)]; }
  float at(int x, int y, int c) const { return pixels[index(x, y, c)]; }
};

}  // namespace uvtk
