// Procedural textures defined exactly, so that anyone can rebuild them texel for texel.
#pragma once

#include <optional>
#include <string>

#include "core/image.h"
#include "render/texture.h"

namespace uvtk::render {

// checker:N[:C]: N x N texels in squares of C x C texels; the square holding texel (0, 0) (at
// s = 0, t = 0) is white (1,1,1,1), its neighbours black (0,0,0,1): texel (i, j) is white when
// (i / C + j / C) is even (integer division); C > N gives one white square. 8-bit. Throws
// UsageError unless 1 <= N, C <= 16384 and N x N <= kMaxTexels (N <= 11585).
Texture checkerTexture(int n, int c);

// uvgrid[:N] (N = 1024 by default, 64 <= N <= 8192): an N x N image of 8 x 8 cells, each a
// distinct pale colour, labelled with its column letter A..H (along u) and row digit 1..8 (along
// v, 1 at v = 0), grid lines one texel wide (two at the domain border), and a small arrow in
// cell A1 pointing along +u, so that a rotated or mirrored mapping reads rotated or mirrored.
// The image's top row is at v = 1. 8-bit.
Image uvGridImage(int n);

// Whether `name` denotes a procedural texture ("checker", "uvgrid", or either with a colon), not a
// file; throws UsageError, as proceduralTexture does, when such a name is malformed.
bool isProceduralName(const std::string& name);

// The texture a name denotes when it is procedural ("checker:N[:C]", "uvgrid[:N]"), else
// nullopt (the name is then a file, even "checker.png"). Throws UsageError for a malformed procedural name.
std::optional<Texture> proceduralTexture(const std::string& name);

}  // namespace uvtk::render
