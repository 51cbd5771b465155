// A 5 x 7 bitmap font for the labels of the procedural uvgrid texture, texture content compared
// pixel for pixel with Mesa (the views' text is views/type.h).
#pragma once

#include <string>

#include "core/image.h"

namespace uvtk::render {

// Glyphs for ' ', 0-9, A-Z, a-z (drawn as capitals), and . , : ; - + = / % ( ) [ ] < > _ # * ? !
// Any other character draws as '?'.

// Draws `text` with its top-left corner at pixel (x, y) (row 0 at the top), each font pixel a
// `scale` x `scale` block, one blank column between glyphs, in `colour` (first `image.channels`
// entries used). Pixels outside the image are skipped.
void drawText(Image& image, int x, int y, const std::string& text, int scale, const float colour[4]);

// The width and height in pixels drawText covers.
int textWidth(const std::string& text, int scale);
inline int textHeight(int scale) { return 7 * scale; }

}  // namespace uvtk::render
