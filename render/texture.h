// Textures as OpenGL samples them: texel arrays in GL order, mipmaps by a 2x2 box filter, the
// wrap modes, NEAREST and LINEAR within a level, the four mipmap filters between levels, and the
// level of detail from the screen-space derivatives of (s, t). OpenGL 4.6 compatibility profile
// §8.14 (texture minification and magnification); docs/conventions.md §7 states our choices.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/image.h"
#include "core/math.h"

namespace uvtk::render {

using Rgba = Eigen::Vector4f;  // a stored texel, each channel in [0, 1] for 8-bit sources

enum class Filter {
  Nearest,
  Linear,
  NearestMipmapNearest,
  LinearMipmapNearest,
  NearestMipmapLinear,
  LinearMipmapLinear,
};

enum class Wrap { Repeat, ClampToEdge, MirroredRepeat };

struct SamplerState {
  Filter minFilter = Filter::Nearest;
  Filter magFilter = Filter::Nearest;  // Nearest or Linear only
  Wrap wrapS = Wrap::Repeat;
  Wrap wrapT = Wrap::Repeat;
};

// The filter a user names on the command line sets both: the minification filter as named, the
// magnification filter NEAREST for nearest and nearest_mipmap_*, LINEAR for the others.
SamplerState samplerFor(Filter filter, Wrap wrap);

bool needsMipmaps(Filter minFilter);

// One level: texel (i, j) with i along s and j along t, j = 0 at t = 0 (GL's first row).
struct TexelLevel {
  int width = 0, height = 0;
  std::vector<Rgba> texels;  // j * width + i
  const Rgba& at(int i, int j) const { return texels[std::size_t(j) * std::size_t(width) + std::size_t(i)]; }
  Rgba& at(int i, int j) { return texels[std::size_t(j) * std::size_t(width) + std::size_t(i)]; }
};

// The most texels a texture's base level may hold: 2^27, 2 GiB as float RGBA (16 bytes a texel),
// e.g. 16384 x 8192; mipmaps add a third. A 16384 x 16384 texture would take 4 GiB.
constexpr std::int64_t kMaxTexels = std::int64_t(1) << 27;

// Throws UsageError naming the size and the limit when width x height exceeds kMaxTexels. Called
// before any texel is allocated.
void checkTextureSize(int width, int height);

class Texture {
 public:
  // `base` in GL order. `eightBit`: the texels are multiples of 1/255 and every mipmap level is
  // rounded back to 8 bits, as a GL texture of internal format RGBA8 stores it. Throws UsageError
  // for an empty size, a texel count that does not match it, or more than kMaxTexels texels.
  Texture(TexelLevel base, bool eightBit);

  // An image whose top row lands at t = 1. Grey images are spread to RGB, a missing alpha is 1.
  // Throws UsageError for more than kMaxTexels pixels.
  static Texture fromImage(const Image& image, bool eightBit);

  // Levels 1..n down to 1 x 1; level k is max(1, floor(w / 2^k)) x max(1, floor(h / 2^k)).
  // A coarse texel is the area-weighted mean of the fine texels under its footprint: the 2 x 2
  // box for even sizes; along an odd axis of size w the coarse texel i covers [i w/w', (i+1) w/w')
  // of the fine one (5 -> 2: weights 1, 1, 1/2 and 1/2, 1, 1 over 2.5 texels, exactly); along an
  // axis of size 1 the single texel. Does nothing when the levels exist.
  void buildMipmaps();

  int levelCount() const { return int(levels_.size()); }
  // The full chain down to 1 x 1 exists (GL's mipmap completeness, §8.17).
  bool hasMipmaps() const { return levels_.back().width == 1 && levels_.back().height == 1; }
  const TexelLevel& level(int k) const { return levels_[std::size_t(k)]; }
  int width() const { return levels_[0].width; }
  int height() const { return levels_[0].height; }
  bool eightBit() const { return eightBit_; }

  // An 8-bit texture's levels also as four bytes a texel (RGBA, R in the low byte), a quarter of
  // the memory the filters read, all levels in one array (level k from packedOffset(k) on), and
  // per level the float each byte value stands for (and one texel of slack past the last): the texel (double) byteValues(k)[b] for
  // b = packedTexels(k)[j w + i] >> 8c & 255 is at(i, j)[c] exactly. Not packed when some channel
  // of some texel is not one of 256 floats in [0, 1] (a float texture). standardBytes(): every
  // level's byte b stands for float(b / 255.0), as an RGBA8 texture's do.
  bool packed() const { return !packed_.empty(); }
  const std::uint32_t* packedTexels(int k) const { return packed_.data() + packedOffset(k); }
  std::size_t packedOffset(int k) const { return packedOffsets_[std::size_t(k)]; }
  const std::array<double, 256>& byteValues(int k) const { return byteValues_[std::size_t(k)]; }
  bool standardBytes() const { return standardBytes_; }

 private:
  void pack();  // packed_, packedOffsets_, byteValues_ and standardBytes_ for every level, or none

  std::vector<TexelLevel> levels_;
  bool eightBit_ = false;
  std::vector<std::uint32_t> packed_;
  std::vector<std::size_t> packedOffsets_;
  bool standardBytes_ = false;
  std::vector<std::array<double, 256>> byteValues_;
};

// GL's wrap of an integer texel coordinate onto [0, size): REPEAT i mod size, CLAMP_TO_EDGE
// clamp(i, 0, size - 1), MIRRORED_REPEAT (size - 1) - mirror((i mod 2 size) - size) with
// mirror(a) = a >= 0 ? a : -(1 + a).
int wrapTexel(std::int64_t i, int size, Wrap wrap);

// NEAREST's texel index along one axis: floor(s size), in double; NaN gives 0, beyond 2^62 texels
// the index stops at +-2^62.
std::int64_t nearestTexel(double coordinate, int size);

// LINEAR's lower texel index along one axis, i0 = floor(s size - 1/2), and the weight of the
// upper one, alpha = frac(s size - 1/2); NaN counts as 0, far coordinates stop at +-2^62.
struct LinearTap {
  std::int64_t lower;
  double alpha;
};
LinearTap linearTap(double coordinate, int size);

// GL 4.6 §8.14.2's bilinear blend of a 2 x 2 quad of texels (t_ij with i along s), alpha the
// weight of the upper i, beta of the upper j, evaluated in this order.
template <typename Texel>
Texel bilinear(const Texel& t00, const Texel& t10, const Texel& t01, const Texel& t11, double alpha, double beta) {
  const double a = alpha, b = beta;
  // tau = (1-a)(1-b) t_i0j0 + a(1-b) t_i1j0 + (1-a) b t_i0j1 + a b t_i1j1
  return (1 - a) * (1 - b) * t00 + a * (1 - b) * t10 + (1 - a) * b * t01 + a * b * t11;
}

// NEAREST within one level: texel (wrap(floor(s W)), wrap(floor(t H))), products in double.
Rgba sampleNearest(const TexelLevel& level, Wrap wrapS, Wrap wrapT, double s, double t);

// LINEAR within one level: i0 = floor(s W - 1/2), alpha = frac(s W - 1/2), likewise j0, beta;
// the 2 x 2 texels wrapped separately and blended with weights (1-alpha)(1-beta) ... in double.
Vec4 sampleLinear(const TexelLevel& level, Wrap wrapS, Wrap wrapT, double s, double t);

// lambda = log2(rho), rho = max(|(ds/dx W, dt/dx H)|, |(ds/dy W, dt/dy H)|) for the base level's
// W x H; -infinity when rho = 0, +infinity for infinite or NaN derivatives (the coarsest level).
double levelOfDetail(int width, int height, const Vec2& dstDx, const Vec2& dstDy);

// The levels a filter reads at level of detail `lambda` and their weights (GL 4.6 §8.14.3, §8.15):
// one level (weight 1) or two blended; `linear` says whether each is filtered LINEAR within the
// level. Magnification (lambda <= c, c = 0.5 when the magnification filter is LINEAR and the
// minification filter NEAREST_MIPMAP_NEAREST or NEAREST_MIPMAP_LINEAR, else c = 0) reads level 0
// with the magnification filter. `levelCount` counts the levels that exist (all down to 1 x 1
// when the minification filter is a mipmap filter). NaN lambda counts as +infinity.
struct LevelChoice {
  int count = 1;
  std::array<int, 2> level{0, 0};
  std::array<double, 2> weight{1.0, 0.0};
  bool linear = false;
};
LevelChoice chooseLevels(const SamplerState& sampler, int levelCount, double lambda);

// The filtered texel at (s, t) for level of detail `lambda`: magnification (lambda <= c, c = 0.5
// when the magnification filter is LINEAR and the minification filter NEAREST_MIPMAP_NEAREST or
// NEAREST_MIPMAP_LINEAR, else c = 0) samples level 0 with the magnification filter; minification
// uses the minification filter with GL's level selection (GL 4.6 §8.14.3). A mipmap filter on a
// texture without mipmaps is a programmer error. Non-finite s or t give texel (0, 0) of level 0.
Vec4 sample(const Texture& texture, const SamplerState& sampler, double s, double t, double lambda);

}  // namespace uvtk::render
