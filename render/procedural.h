// Procedural textures defined exactly, so that anyone can rebuild them texel for texel.
#pragma once

#include <optional>
#include <string>

#include "core/image.h"
#include "render/cube_texture.h"
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

// cube[:N] (N = 64 by default, 1 <= N <= 4096): a cube map of N x N faces, texel (i, j) with i
// along s and j along t (j = 0 at t = 0), in checks of c = max(1, N / 8) texels: face colours +X
// (255,0,0), -X (0,255,255), +Y (0,255,0), -Y (255,0,255), +Z (0,0,255), -Z (255,255,0), each
// channel halved (integer division) where (i / c + j / c) is odd. 8-bit.
CubeTexture cubeCheckerTexture(int n);

// cubeindex[:N] (N = 64 by default, 1 <= N <= 256): texel (i, j) of face f (GL's order) has the
// colour (i, j, 40 (f + 1)) / 255, so that a pixel's bytes name the face and texel it came from.
CubeTexture cubeIndexTexture(int n);

// spheremap[:N[:K]] (N = 256, K = 8 by default; 8 <= N <= 8192, 1 <= K <= 64): the SPHERE_MAP image
// (docs/conventions.md §6) of an environment in checks of 180/K degrees. Texel (i, j) is at
// x = 2 (i + 1/2) / N - 1, y = 2 (j + 1/2) / N - 1, d = hypot(x, y); outside the disc (d > 1) it is
// grey (128,128,128). Inside, the reflection vector whose SPHERE_MAP coordinates these are lies at
// the angle theta = 2 asin(d) from +z (the viewer) and at the azimuth phi = atan2(y, x) in [0, 2 pi);
// band a = min(K - 1, floor(theta K / pi)), sector b = min(2K - 1, floor(phi K / pi)); the check is
// light where a + b is even, else dark; light/dark are white (255,255,255)/black on the side facing
// the viewer (d^2 < 1/2, theta < 90 degrees) and orange (255,160,0)/blue (0,64,160) behind. The
// bands behind crowd into the rim: the classic pinching of sphere maps. 8-bit; the top row is t = 1.
Texture sphereMapCheckerTexture(int n, int k);

// Whether `name` denotes a procedural texture (one of the words above, bare or with a colon), not a
// file; throws UsageError, as proceduralTexture does, when such a name is malformed.
bool isProceduralName(const std::string& name);

// The 2D texture a name denotes when it is procedural ("checker:N[:C]", "uvgrid[:N]",
// "spheremap[:N[:K]]"), else nullopt (the name is then a file, even "checker.png", or a
// procedural cube map). Throws UsageError for a malformed procedural name.
std::optional<Texture> proceduralTexture(const std::string& name);

// Whether `name` denotes a procedural cube map ("cube[:N]", "cubeindex[:N]"); throws UsageError,
// as proceduralCubeTexture does, when a procedural name is malformed.
bool isProceduralCubeName(const std::string& name);

// The cube map a name denotes when it is a procedural one ("cube[:N]", "cubeindex[:N]"), else
// nullopt. Throws UsageError for a malformed procedural name.
std::optional<CubeTexture> proceduralCubeTexture(const std::string& name);

}  // namespace uvtk::render
