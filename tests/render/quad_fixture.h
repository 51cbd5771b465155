// The textured quad the renderer tests draw.
#pragma once

#include "core/mesh.h"
#include "render/procedural.h"
#include "render/renderer.h"

namespace uvtk::render {

// A quad p00 + u a + v b, (u, v) in [0, 1]^2, as two counter-clockwise triangles with per-corner
// texture coordinates (u, v, 0, 1).
struct Quad {
  Mesh mesh;
  TexcoordSource texcoords;
  Quad(const Vec3& p00, const Vec3& a, const Vec3& b) {
    mesh.positions = {p00, p00 + a, p00 + a + b, p00 + b};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    const Vec4 uv[4] = {Vec4(0, 0, 0, 1), Vec4(1, 0, 0, 1), Vec4(1, 1, 0, 1), Vec4(0, 1, 0, 1)};
    for (const Triangle& t : mesh.triangles)
      for (int v : t) texcoords.corners.push_back(uv[v]);
  }
};

// A checker of `size` texels a side in squares of `square` texels, with its mipmaps.
inline Texture mipmappedChecker(int size, int square) {
  Texture texture = checkerTexture(size, square);
  texture.buildMipmaps();
  return texture;
}

}  // namespace uvtk::render
