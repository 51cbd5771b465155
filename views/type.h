// Text in the views' images: DejaVu Sans (fonts-dejavu-core) rasterised by FreeType, mixed case,
// any character the face has (UTF-8: "≥", "σ", "×", "²"), anti-aliased, kerned where the face has
// kerning pairs. The face is loaded once per process on first use; both functions may be called
// from any thread.
#pragma once

#include <string>

#include "core/image.h"
#include "core/math.h"

namespace uvtk::views {

enum class Weight { Regular, Bold };

// The box a line of text takes, in pixels: `width` from the pen's start to its end (or to the
// rightmost ink, if further), `ascent` from the box's top to the baseline and `descent` below it,
// height = ascent + descent. ascent and descent are the face's at that size, so that lines of one
// size share a baseline, widened only for a glyph that reaches beyond them. All ink drawText
// puts down lies inside the box.
struct TextMetrics {
  int width = 0, ascent = 0, descent = 0, height = 0;
};

// The metrics of `utf8` at `pixelSize` pixels per em (1 to 512). measureText("", size) is the
// empty line box: width 0, the face's ascent and descent. Malformed UTF-8 measures and draws as
// U+FFFD, characters the face lacks as its missing-glyph box. Throws InputError naming the font
// file when it cannot be loaded.
TextMetrics measureText(const std::string& utf8, double pixelSize, Weight weight = Weight::Regular);

// Draws `utf8` with its box's top-left corner at pixel (x, top) into an RGB image, each pixel
// becoming old (1 - c) + colour c, c the glyph's coverage of the pixel in [0, 1]: blended in the
// image's float values, as every view's colours are chosen (no gamma). Pixels outside the image
// are skipped. Throws as measureText.
void drawText(Image& image, int x, int top, const std::string& utf8, double pixelSize, const Vec3& colour,
              Weight weight = Weight::Regular);

}  // namespace uvtk::views
