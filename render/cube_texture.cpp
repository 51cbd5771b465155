#include "render/cube_texture.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"

namespace uvtk::render {

namespace {

Vec4 widen(const Rgba& texel) { return texel.cast<double>(); }

// `image` upside down: its top row becomes the texture's first row (t = 0), as glTexImage2D
// takes a file read top-down.
Image flipped(const Image& image) {
  Image out = image;
  const std::size_t row = std::size_t(image.width) * std::size_t(image.channels);
  for (int y = 0; y < image.height; ++y)
    std::copy_n(&image.pixels[std::size_t(image.height - 1 - y) * row], row, &out.pixels[std::size_t(y) * row]);
  return out;
}

// The texel (i, j) of face f at one level of n x n texels, where i and j may lie one beyond the
// face (seamless filtering). On a lattice where the face spans [-n, n] and texel k's centre is at
// 2k + 1 - n, a texel one beyond an edge has its centre at +-(n + 1) along the edge's axis: the
// adjacent face is the one of that axis, and the texel there is the one whose centre moves to
// +-n along it and one step in (+-(n - 1)) along f's axis.
Rgba seamlessTexel(const CubeTexture& texture, int levelIndex, CubeFace f, std::int64_t i, std::int64_t j) {
  const TexelLevel* level = &texture.face(f).level(levelIndex);
  const int n = level->width;
  if (i >= 0 && i < n && j >= 0 && j < n) return level->at(int(i), int(j));
  UVTK_CHECK(i >= -1 && i <= n && j >= -1 && j <= n);
  Eigen::Vector3i p = glCubeDirection<int>(f, int(2 * i + 1 - n), int(2 * j + 1 - n), n);
  int beyond = 0;
  for (int axis = 1; axis < 3; ++axis)
    if (std::abs(p[axis]) > std::abs(p[beyond])) beyond = axis;
  const int sign = p[beyond] > 0 ? 1 : -1;
  const CubeFace adjacent = CubeFace(2 * beyond + (sign > 0 ? 0 : 1));
  p[beyond] = sign * n;
  p[faceAxis(f)] = faceSign(f) * (n - 1);
  const Eigen::Vector2i c = glCubeFaceCoordinates<int>(p, adjacent);
  level = &texture.face(adjacent).level(levelIndex);
  return level->at((c.x() + n - 1) / 2, (c.y() + n - 1) / 2);
}

// Any texel of face f one beyond the face or not; beyond a corner (both indices out) the mean of
// the three texels meeting at that corner of the cube (GL 4.6 §8.14.2: "average the values of
// the three available samples").
Vec4 seamlessTexelOrCorner(const CubeTexture& texture, int levelIndex, CubeFace f, std::int64_t i, std::int64_t j) {
  const int n = texture.face(f).level(levelIndex).width;
  const bool outS = i < 0 || i >= n, outT = j < 0 || j >= n;
  if (!(outS && outT)) return widen(seamlessTexel(texture, levelIndex, f, i, j));
  const std::int64_t inI = i < 0 ? 0 : n - 1, inJ = j < 0 ? 0 : n - 1;
  return (widen(seamlessTexel(texture, levelIndex, f, inI, inJ)) + widen(seamlessTexel(texture, levelIndex, f, i, inJ)) +
          widen(seamlessTexel(texture, levelIndex, f, inI, j))) /
         3.0;
}

// Within one level, seamlessly: NEAREST's texel (on the face) or LINEAR's 2 x 2 blend, indices one
// beyond the face taken across its edges. Coordinates are clamped to the face first, which changes no texel
// GL reads from a direction's own face and keeps the indices within one of it.
Vec4 sampleLevelSeamless(const CubeTexture& texture, int levelIndex, bool linear, CubeFace f, double s, double t) {
  const int n = texture.face(f).level(levelIndex).width;
  s = std::clamp(s, 0.0, 1.0);
  t = std::clamp(t, 0.0, 1.0);
  if (!linear)  // NEAREST stays on the face: s = 1 (t = 1) reads its last texel, as CLAMP_TO_EDGE does
    return widen(texture.face(f).level(levelIndex).at(int(std::min<std::int64_t>(nearestTexel(s, n), n - 1)),
                                                      int(std::min<std::int64_t>(nearestTexel(t, n), n - 1))));
  const LinearTap u = linearTap(s, n), v = linearTap(t, n);
  const double a = u.alpha, b = v.alpha;
  const auto texel = [&](std::int64_t i, std::int64_t j) { return seamlessTexelOrCorner(texture, levelIndex, f, i, j); };
  // GL 4.6 §8.14.2: tau = (1-a)(1-b) t_i0j0 + a(1-b) t_i1j0 + (1-a) b t_i0j1 + a b t_i1j1
  return (1 - a) * (1 - b) * texel(u.lower, v.lower) + a * (1 - b) * texel(u.lower + 1, v.lower) +
         (1 - a) * b * texel(u.lower, v.lower + 1) + a * b * texel(u.lower + 1, v.lower + 1);
}

}  // namespace

CubeTexture::CubeTexture(std::vector<Texture> faces) : faces_(std::move(faces)) {
  if (faces_.size() != std::size_t(kCubeFaceCount))
    throw UsageError("cube map: expected 6 faces (+X -X +Y -Y +Z -Z), got " + std::to_string(faces_.size()));
  const int n = faces_[0].width();
  for (const Texture& face : faces_)
    if (face.width() != n || face.height() != n)
      throw UsageError("cube map: expected six square faces of one size, got " + std::to_string(face.width()) + " x " +
                       std::to_string(face.height()) + " beside " + std::to_string(n) + " x " + std::to_string(n));
}

CubeTexture CubeTexture::fromImages(const std::vector<Image>& images, const std::vector<std::string>& names,
                                    bool eightBit) {
  UVTK_CHECK(names.size() == images.size());
  if (images.size() != std::size_t(kCubeFaceCount))
    throw UsageError("cube map: expected 6 face images (+X -X +Y -Y +Z -Z), got " + std::to_string(images.size()));
  std::vector<Texture> faces;
  for (std::size_t f = 0; f < images.size(); ++f) {
    const Image& image = images[f];
    if (image.width != image.height || image.width != images[0].width)
      throw UsageError(names[f] + ": a cube map face must be square and of the size of the first (" +
                       std::to_string(images[0].width) + " x " + std::to_string(images[0].height) + "), found " +
                       std::to_string(image.width) + " x " + std::to_string(image.height));
    faces.push_back(Texture::fromImage(flipped(image), eightBit));
  }
  return CubeTexture(std::move(faces));
}

CubeTexture CubeTexture::fromLayoutImage(const Image& atlas, CubeLayout layout, const std::string& name,
                                         bool eightBit) {
  UVTK_CHECK(layout != CubeLayout::Faces);
  const CubeLayoutCell grid = cubeLayoutCell(CubeFace::PosX, layout);
  const int n = atlas.width / grid.columns;
  if (n < 1 || atlas.width != grid.columns * n || atlas.height != grid.rows * n)
    throw UsageError(name + ": a " + std::to_string(grid.columns) + " x " + std::to_string(grid.rows) +
                     " cube map layout needs an image of " + std::to_string(grid.columns) + "N x " +
                     std::to_string(grid.rows) + "N pixels, found " + std::to_string(atlas.width) + " x " +
                     std::to_string(atlas.height));
  std::vector<Image> images;
  std::vector<std::string> names;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    const CubeLayoutCell cell = cubeLayoutCell(CubeFace(f), layout);
    Image face(n, n, atlas.channels);
    const int top = (grid.rows - 1 - cell.row) * n;  // rows count from the bottom, image rows from the top
    for (int y = 0; y < n; ++y)
      std::copy_n(&atlas.pixels[atlas.index(cell.column * n, top + y)], std::size_t(n) * std::size_t(atlas.channels),
                  &face.pixels[face.index(0, y)]);
    images.push_back(std::move(face));
    names.push_back(name);
  }
  return fromImages(images, names, eightBit);
}

Image CubeTexture::layoutImage(CubeLayout layout) const {
  UVTK_CHECK(layout != CubeLayout::Faces);
  const CubeLayoutCell grid = cubeLayoutCell(CubeFace::PosX, layout);
  const int n = size();
  Image atlas(grid.columns * n, grid.rows * n, 4);
  for (int y = 0; y < atlas.height; ++y)
    for (int x = 0; x < atlas.width; ++x) atlas.at(x, y, 3) = 1.0f;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    const CubeLayoutCell cell = cubeLayoutCell(CubeFace(f), layout);
    const TexelLevel& level = face(CubeFace(f)).level(0);
    const int top = (grid.rows - 1 - cell.row) * n;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (int c = 0; c < 4; ++c) atlas.at(cell.column * n + i, top + j, c) = level.at(i, j)[c];  // t = 0 on top
  }
  return atlas;
}

void CubeTexture::buildMipmaps() {
  for (Texture& face : faces_) face.buildMipmaps();
}

CubeCoordinates cubeCoordinates(const Vec3& d) {
  CubeCoordinates out;
  if (!d.allFinite() || d.isZero()) {
    out.st = Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
    return out;
  }
  out.face = majorAxisFace(d);
  out.st = glCubeFaceSt(d, out.face);
  return out;
}

Vec2 cubeFaceStDerivative(const Vec3& d, const Vec3& dd, CubeFace f) {
  const Vec2 c = glCubeFaceCoordinates(d, f), dc = glCubeFaceCoordinates(dd, f);
  const double ma = std::fabs(d[faceAxis(f)]), dma = faceSign(f) * dd[faceAxis(f)];  // d|ma| on face f's side
  return (dc * ma - c * dma) / (2.0 * ma * ma);
}

Vec4 sampleCube(const CubeTexture& texture, const SamplerState& sampler, CubeFace face, double s, double t,
                double lambda, bool seamless) {
  if (!seamless) return sample(texture.face(face), sampler, s, t, lambda);
  if (!std::isfinite(s) || !std::isfinite(t)) return widen(texture.face(face).level(0).at(0, 0));
  UVTK_CHECK(!needsMipmaps(sampler.minFilter) || texture.hasMipmaps());
  const LevelChoice choice = chooseLevels(sampler, texture.levelCount(), lambda);
  Vec4 sum = Vec4::Zero();
  for (int k = 0; k < choice.count; ++k)
    sum += choice.weight[std::size_t(k)] *
           sampleLevelSeamless(texture, choice.level[std::size_t(k)], choice.linear, face, s, t);
  return sum;
}

}  // namespace uvtk::render
