// Cube-map textures as OpenGL samples them (GL 4.6 §8.13, §8.14): six square faces in GL's order
// +X -X +Y -Y +Z -Z; a direction (s, t, r) selects a face and a point (s, t) on it (core/cube.h),
// and the face is filtered as a 2D texture with GL's filters and level of detail. By default each
// face is filtered alone with the sampler's wrap modes, as GL does; the seamless mode (GL's
// TEXTURE_CUBE_MAP_SEAMLESS) takes the texels beyond a face's edge from the adjacent face.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/cube.h"
#include "core/image.h"
#include "render/texture.h"

namespace uvtk::render {

class CubeTexture {
 public:
  // Six faces in GL's order, square and of one size. Throws UsageError otherwise.
  explicit CubeTexture(std::vector<Texture> faces);

  // Six images in GL's order, each loaded as glTexImage2D receives a file read top-down: the
  // image's top row is the face's first row, t = 0 (so on the side faces +y is up). `names` label
  // the errors. Throws UsageError for images that are not square or not of one size.
  static CubeTexture fromImages(const std::vector<Image>& images, const std::vector<std::string>& names, bool eightBit);

  // The faces cut from one atlas image of `layout` (cross, strip or 3x2; core/cube.h), the cells
  // N x N with the image's top row at the atlas's top, each cell read as fromImages reads a file,
  // i.e. the atlas `uvtk map --projector cube --cube-layout L` maps onto. Throws UsageError when
  // the image is not columns N x rows N.
  static CubeTexture fromLayoutImage(const Image& atlas, CubeLayout layout, const std::string& name, bool eightBit);

  // The atlas image of `layout` holding the faces (the inverse of fromLayoutImage); empty cells
  // are black. RGBA, row 0 at the top.
  Image layoutImage(CubeLayout layout) const;

  void buildMipmaps();  // every face's chain down to 1 x 1
  bool hasMipmaps() const { return faces_[0].hasMipmaps(); }
  int size() const { return faces_[0].width(); }
  int levelCount() const { return faces_[0].levelCount(); }
  bool eightBit() const { return faces_[0].eightBit(); }
  const Texture& face(CubeFace f) const { return faces_[std::size_t(f)]; }

 private:
  std::vector<Texture> faces_;
};

// The face a direction selects and its (s, t) there (GL 4.6 §8.13, eq. 8.8): the major axis, ties
// x before y before z, +0 counting as positive. A zero or non-finite direction gives face +X and
// non-finite (s, t).
struct CubeCoordinates {
  CubeFace face = CubeFace::PosX;
  Vec2 st = Vec2::Zero();
};
CubeCoordinates cubeCoordinates(const Vec3& direction);

// The derivative of (s, t) on face f along a derivative dd of the direction d, by the quotient rule
// on GL 4.6 eq. 8.8 (as GL 4.6 §8.13 derives the cube map level of detail):
// ds = (dsc |ma| - sc d|ma|) / (2 ma^2), likewise dt; what the level of detail of a cube map reads.
Vec2 cubeFaceStDerivative(const Vec3& d, const Vec3& dd, CubeFace f);

// The filtered texel of face f at (s, t) for level of detail `lambda` (from the face's N x N
// derivatives). Without `seamless`, the face is sampled as a 2D texture with the sampler's wrap
// modes. With it the wrap modes are ignored: (s, t) is clamped to the face, NEAREST reads the
// texel there (the last one at s or t = 1), and LINEAR's texels one beyond an edge are the
// adjacent face's texels across that edge, one beyond a corner (both indices out) the mean of the
// three texels that meet at the cube's corner (GL 4.6 §8.14.2's recommended choice). Non-finite
// (s, t) give texel (0, 0) of face f's level 0.
Vec4 sampleCube(const CubeTexture& texture, const SamplerState& sampler, CubeFace face, double s, double t,
                double lambda, bool seamless);

}  // namespace uvtk::render
