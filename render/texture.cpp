#include "render/texture.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "core/error.h"

namespace uvtk::render {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Texel coordinates beyond 2^62 are all "far outside"; clamping there keeps the int64 cast defined.
constexpr double kFarTexel = 4611686018427387904.0;  // 2^62

// i mod n in [0, n) for n > 0, whatever the sign of i. A power of two, as mipmapped sizes mostly
// are, takes the low bits (two's complement), which is the same and saves a 64-bit division.
std::int64_t positiveModulo(std::int64_t i, std::int64_t n) {
  if ((n & (n - 1)) == 0) return i & (n - 1);
  const std::int64_t r = i % n;
  return r < 0 ? r + n : r;
}

Vec4 widen(const Rgba& texel) { return texel.cast<double>(); }

// Within-level filtering by a filter that names NEAREST or LINEAR (alone or within a mipmap filter).
Vec4 sampleLevel(const TexelLevel& level, bool linear, const SamplerState& sampler, double s, double t) {
  return linear ? sampleLinear(level, sampler.wrapS, sampler.wrapT, s, t)
                : widen(sampleNearest(level, sampler.wrapS, sampler.wrapT, s, t));
}

// One axis of the box filter: the fine texels under coarse texel i and their overlaps. A fine
// texel k spans [k w', (k+1) w') and the coarse one [i w, (i+1) w) in units of 1/w' fine texels,
// so the overlaps are integers and sum to w.
struct AxisTap {
  int fine;
  std::int64_t overlap;
};

std::vector<std::vector<AxisTap>> boxTaps(int fineSize, int coarseSize) {
  std::vector<std::vector<AxisTap>> taps(static_cast<std::size_t>(coarseSize));
  const std::int64_t w = fineSize, wc = coarseSize;
  for (std::int64_t i = 0; i < wc; ++i) {
    const std::int64_t begin = i * w, end = (i + 1) * w;
    for (std::int64_t k = begin / wc; k * wc < end; ++k) {
      const std::int64_t overlap = std::min((k + 1) * wc, end) - std::max(k * wc, begin);
      if (overlap > 0) taps[std::size_t(i)].push_back({int(k), overlap});
    }
  }
  return taps;
}

// The next coarser level: the area-weighted mean of the texels under each coarse texel (GL 4.6
// §8.14.4 leaves the filter open and suggests a 2 x 2 box; this is that box, exact on odd sizes).
// For an 8-bit texture the mean is taken over the stored byte values and rounded half away from
// zero, exactly, as an RGBA8 level stores it.
TexelLevel downsample(const TexelLevel& fine, bool eightBit) {
  TexelLevel coarse;
  coarse.width = std::max(1, fine.width / 2);
  coarse.height = std::max(1, fine.height / 2);
  coarse.texels.resize(std::size_t(coarse.width) * std::size_t(coarse.height));
  const auto tapsS = boxTaps(fine.width, coarse.width);
  const auto tapsT = boxTaps(fine.height, coarse.height);
  const double area = double(fine.width) * double(fine.height);  // the overlaps sum to w along s, h along t
  for (int j = 0; j < coarse.height; ++j)
    for (int i = 0; i < coarse.width; ++i) {
      Vec4 sum = Vec4::Zero();
      for (const AxisTap& tj : tapsT[std::size_t(j)])
        for (const AxisTap& ti : tapsS[std::size_t(i)]) {
          const Vec4 texel = widen(fine.at(ti.fine, tj.fine));
          sum += double(ti.overlap * tj.overlap) * (eightBit ? Vec4((texel * 255.0).array().round()) : texel);
        }
      const Vec4 mean = sum / area;
      coarse.at(i, j) = (eightBit ? Vec4(mean.array().round() / 255.0) : mean).cast<float>();
    }
  return coarse;
}

bool isMipmapFilter(Filter filter) { return filter != Filter::Nearest && filter != Filter::Linear; }

}  // namespace

SamplerState samplerFor(Filter filter, Wrap wrap) {
  SamplerState sampler;
  sampler.minFilter = filter;
  const bool nearest = filter == Filter::Nearest || filter == Filter::NearestMipmapNearest ||
                       filter == Filter::NearestMipmapLinear;
  sampler.magFilter = nearest ? Filter::Nearest : Filter::Linear;
  sampler.wrapS = sampler.wrapT = wrap;
  return sampler;
}

bool needsMipmaps(Filter minFilter) { return isMipmapFilter(minFilter); }

void checkTextureSize(int width, int height) {
  const std::int64_t texels = std::int64_t(width) * std::int64_t(height);
  if (texels <= kMaxTexels) return;
  const double gib = double(texels) * double(sizeof(Rgba)) / double(std::int64_t(1) << 30);
  std::ostringstream message;
  message << "texture: " << width << " x " << height << " texels would take " << gib
          << " GiB as float RGBA, more than the 2 GiB limit (" << kMaxTexels << " texels, e.g. 16384 x 8192)";
  throw UsageError(message.str());
}

Texture::Texture(TexelLevel base, bool eightBit) : eightBit_(eightBit) {
  checkTextureSize(base.width, base.height);
  if (base.width < 1 || base.height < 1 ||
      base.texels.size() != std::size_t(base.width) * std::size_t(base.height))
    throw UsageError("texture: expected width, height >= 1 and width * height texels, got " +
                     std::to_string(base.width) + " x " + std::to_string(base.height) + " with " +
                     std::to_string(base.texels.size()) + " texels");
  levels_.push_back(std::move(base));
  pack();
}

void Texture::pack() {
  packed_.clear(), packedOffsets_.clear(), byteValues_.clear(), standardBytes_ = false;
  if (!eightBit_) return;
  std::vector<std::uint32_t> packed;
  std::vector<std::size_t> offsets;
  std::vector<std::array<double, 256>> values(levels_.size());
  bool standard = true;
  for (std::size_t k = 0; k < levels_.size(); ++k) {
    const TexelLevel& level = levels_[k];
    std::array<float, 256> value;
    std::array<bool, 256> seen{};
    offsets.push_back(packed.size());
    for (const Rgba& texel : level.texels) {
      std::uint32_t bytes = 0;
      for (int c = 0; c < 4; ++c) {
        const float v = texel[c];
        if (!(v >= 0.0f && v <= 1.0f)) return;  // NaN included
        const auto b = static_cast<std::uint32_t>(std::lround(double(v) * 255.0));
        if (seen[b] && value[b] != v) return;  // two floats for one byte value: keep the floats
        seen[b] = true, value[b] = v;
        bytes |= b << (8 * c);
      }
      packed.push_back(bytes);
    }
    for (std::size_t b = 0; b < 256; ++b) {
      values[k][b] = seen[b] ? double(value[b]) : 0.0;
      standard = standard && (!seen[b] || value[b] == float(double(b) / 255.0));
    }
  }
  packed.push_back(0);  // slack: an 8-byte read at the last texel stays inside
  packed_ = std::move(packed), packedOffsets_ = std::move(offsets), byteValues_ = std::move(values);
  standardBytes_ = standard;
}

Texture Texture::fromImage(const Image& image, bool eightBit) {
  if (image.channels < 1 || image.channels > 4)
    throw UsageError("texture: expected an image of 1 to 4 channels, got " + std::to_string(image.channels));
  checkTextureSize(image.width, image.height);
  TexelLevel base;
  base.width = image.width;
  base.height = image.height;
  base.texels.resize(std::size_t(std::max(0, image.width)) * std::size_t(std::max(0, image.height)));
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto channel = [&](int c) { return image.at(x, y, c); };
      Rgba texel;
      switch (image.channels) {
        case 1: texel = Rgba(channel(0), channel(0), channel(0), 1.0f); break;
        case 2: texel = Rgba(channel(0), channel(0), channel(0), channel(1)); break;
        case 3: texel = Rgba(channel(0), channel(1), channel(2), 1.0f); break;
        default: texel = Rgba(channel(0), channel(1), channel(2), channel(3)); break;
      }
      base.at(x, image.height - 1 - y) = texel;  // image row 0 (top) is GL's last row, t = 1
    }
  return Texture(std::move(base), eightBit);
}

void Texture::buildMipmaps() {
  if (levels_.size() > 1) return;
  // GL 4.6 §8.14.3: level k is max(1, floor(w / 2^k)) x max(1, floor(h / 2^k)), down to 1 x 1.
  while (levels_.back().width > 1 || levels_.back().height > 1)
    levels_.push_back(downsample(levels_.back(), eightBit_));
  pack();
}

int wrapTexel(std::int64_t i, int size, Wrap wrap) {
  UVTK_CHECK(size > 0);
  const std::int64_t n = size;
  if (wrap == Wrap::Repeat) return int(positiveModulo(i, n));  // GL 4.6 §8.14.2: REPEAT, i mod size
  if (wrap == Wrap::ClampToEdge) return int(std::clamp<std::int64_t>(i, 0, n - 1));  // GL 4.6 §8.14.2
  // GL 4.6 §8.14.2: MIRRORED_REPEAT, (size - 1) - mirror((i mod 2 size) - size), mirror(a) = a >= 0 ? a : -(1 + a)
  const std::int64_t a = positiveModulo(i, 2 * n) - n;
  return int((n - 1) - (a >= 0 ? a : -(1 + a)));
}

std::int64_t nearestTexel(double coordinate, int size) {
  const double u = coordinate * size;  // GL 4.6 §8.14.2: NEAREST takes floor(u), u = s w
  if (std::isnan(u)) return 0;
  return static_cast<std::int64_t>(std::floor(std::clamp(u, -kFarTexel, kFarTexel)));
}

LinearTap linearTap(double coordinate, int size) {
  double u = coordinate * size - 0.5;  // GL 4.6 §8.14.2: u = s w - 1/2, i0 = floor(u), alpha = frac(u)
  u = std::isnan(u) ? 0.0 : std::clamp(u, -kFarTexel, kFarTexel);
  const double lower = std::floor(u);
  return {static_cast<std::int64_t>(lower), u - lower};
}

Rgba sampleNearest(const TexelLevel& level, Wrap wrapS, Wrap wrapT, double s, double t) {
  const int i = wrapTexel(nearestTexel(s, level.width), level.width, wrapS);
  const int j = wrapTexel(nearestTexel(t, level.height), level.height, wrapT);
  return level.at(i, j);
}

Vec4 sampleLinear(const TexelLevel& level, Wrap wrapS, Wrap wrapT, double s, double t) {
  const LinearTap u = linearTap(s, level.width), v = linearTap(t, level.height);
  const int i0 = wrapTexel(u.lower, level.width, wrapS), i1 = wrapTexel(u.lower + 1, level.width, wrapS);
  const int j0 = wrapTexel(v.lower, level.height, wrapT), j1 = wrapTexel(v.lower + 1, level.height, wrapT);
  return bilinear(widen(level.at(i0, j0)), widen(level.at(i1, j0)), widen(level.at(i0, j1)), widen(level.at(i1, j1)),
                  u.alpha, v.alpha);
}

double levelOfDetail(int width, int height, const Vec2& dstDx, const Vec2& dstDy) {
  if (dstDx.hasNaN() || dstDy.hasNaN()) return kInfinity;  // undefined footprint: the coarsest level
  // GL 4.6 §8.14.1: rho = max(sqrt((du/dx)^2 + (dv/dx)^2), sqrt((du/dy)^2 + (dv/dy)^2)), u = s w, v = t h
  const double dudx = dstDx.x() * width, dvdx = dstDx.y() * height, dudy = dstDy.x() * width, dvdy = dstDy.y() * height;
  // hypot is within an ulp of the true length: when the squared lengths, exact to a few ulp,
  // differ by far more than that, the longer one is rho and the other need not be computed.
  // Outside [1e-290, 1e290] a square may have overflowed or lost its precision to underflow.
  const double sx = dudx * dudx + dvdx * dvdx, sy = dudy * dudy + dvdy * dvdy;
  constexpr double kSeparated = 1.0 + 1e-9, kLow = 1e-290, kHigh = 1e290;
  if (sx >= kLow && sx <= kHigh && sy >= kLow && sy <= kHigh) {
    if (sx > sy * kSeparated) return std::log2(std::hypot(dudx, dvdx));
    if (sy > sx * kSeparated) return std::log2(std::hypot(dudy, dvdy));
  }
  const double rho = std::max(std::hypot(dudx, dvdx), std::hypot(dudy, dvdy));
  return std::log2(rho);  // GL 4.6 §8.14.1: lambda_base = log2(rho); log2(0) = -inf, log2(inf) = +inf
}

LevelChoice chooseLevels(const SamplerState& sampler, int levelCount, double lambda) {
  UVTK_CHECK(!isMipmapFilter(sampler.magFilter) && levelCount >= 1);
  if (std::isnan(lambda)) lambda = kInfinity;  // as levelOfDetail for an undefined footprint
  // GL 4.6 §8.15: c = 0.5 for a LINEAR magnification filter with a NEAREST_MIPMAP_* minification filter
  const bool halfCrossover = sampler.magFilter == Filter::Linear && (sampler.minFilter == Filter::NearestMipmapNearest ||
                                                                     sampler.minFilter == Filter::NearestMipmapLinear);
  const double c = halfCrossover ? 0.5 : 0.0;
  LevelChoice choice;
  if (lambda <= c) {
    choice.linear = sampler.magFilter == Filter::Linear;
    return choice;
  }
  if (!isMipmapFilter(sampler.minFilter)) {
    choice.linear = sampler.minFilter == Filter::Linear;
    return choice;
  }
  const int q = levelCount - 1;
  choice.linear = sampler.minFilter == Filter::LinearMipmapNearest || sampler.minFilter == Filter::LinearMipmapLinear;
  if (sampler.minFilter == Filter::NearestMipmapNearest || sampler.minFilter == Filter::LinearMipmapNearest) {
    // GL 4.6 §8.14.3: d = 0 for lambda <= 1/2, ceil(lambda + 1/2) - 1 up to q + 1/2, else q
    choice.level[0] = lambda <= 0.5 ? 0 : lambda > q + 0.5 ? q : int(std::ceil(lambda + 0.5)) - 1;
    return choice;
  }
  // GL 4.6 §8.14.3: d1 = d2 = q for lambda >= q, else d1 = floor(lambda), d2 = d1 + 1;
  // tau = (1 - frac(lambda)) tau1 + frac(lambda) tau2
  if (lambda >= q) {
    choice.level[0] = q;
    return choice;
  }
  const double f = lambda - std::floor(lambda);
  choice.count = 2;
  choice.level = {int(std::floor(lambda)), int(std::floor(lambda)) + 1};  // lambda < q: d2 <= q
  choice.weight = {1 - f, f};
  return choice;
}

namespace {

// sampleLinear on a level whose sizes are powers of two, with REPEAT along both axes: the wrap is
// the low bits of the texel index, with no check per tap, and the blend is sampleLinear's.
Vec4 sampleLinearRepeatPow2(const TexelLevel& level, double s, double t) {
  const LinearTap u = linearTap(s, level.width), v = linearTap(t, level.height);
  const auto maskS = std::uint64_t(level.width - 1), maskT = std::uint64_t(level.height - 1);
  const auto i0 = std::size_t(std::uint64_t(u.lower) & maskS), i1 = std::size_t(std::uint64_t(u.lower + 1) & maskS);
  const std::size_t w = std::size_t(level.width);
  const Rgba* row0 = &level.texels[std::size_t(std::uint64_t(v.lower) & maskT) * w];
  const Rgba* row1 = &level.texels[std::size_t(std::uint64_t(v.lower + 1) & maskT) * w];
  const double a = u.alpha, b = v.alpha;
  return (1 - a) * (1 - b) * widen(row0[i0]) + a * (1 - b) * widen(row0[i1]) + (1 - a) * b * widen(row1[i0]) +
         a * b * widen(row1[i1]);
}

// sampleLinearRepeatPow2 on a packed level: the same taps and blend, each texel's channels read as
// the doubles its bytes stand for.
Vec4 sampleLinearRepeatPow2Packed(const Texture& texture, int k, double s, double t) {
  const TexelLevel& level = texture.level(k);
  const LinearTap u = linearTap(s, level.width), v = linearTap(t, level.height);
  const auto maskS = std::uint64_t(level.width - 1), maskT = std::uint64_t(level.height - 1);
  const auto i0 = std::size_t(std::uint64_t(u.lower) & maskS), i1 = std::size_t(std::uint64_t(u.lower + 1) & maskS);
  const std::size_t w = std::size_t(level.width);
  const std::uint32_t* row0 = texture.packedTexels(k) + std::size_t(std::uint64_t(v.lower) & maskT) * w;
  const std::uint32_t* row1 = texture.packedTexels(k) + std::size_t(std::uint64_t(v.lower + 1) & maskT) * w;
  const std::array<double, 256>& value = texture.byteValues(k);
  const auto texel = [&value](std::uint32_t bytes) {
    return Vec4(value[bytes & 255], value[bytes >> 8 & 255], value[bytes >> 16 & 255], value[bytes >> 24]);
  };
  const double a = u.alpha, b = v.alpha;
  return (1 - a) * (1 - b) * texel(row0[i0]) + a * (1 - b) * texel(row0[i1]) + (1 - a) * b * texel(row1[i0]) +
         a * b * texel(row1[i1]);
}

bool isPowerOfTwo(int n) { return (n & (n - 1)) == 0; }

}  // namespace

Vec4 sample(const Texture& texture, const SamplerState& sampler, double s, double t, double lambda) {
  if (!std::isfinite(s) || !std::isfinite(t)) return widen(texture.level(0).at(0, 0));
  UVTK_CHECK(!isMipmapFilter(sampler.minFilter) || texture.hasMipmaps());
  const LevelChoice choice = chooseLevels(sampler, texture.levelCount(), lambda);
  // Every level of a power-of-two texture has power-of-two sizes.
  const bool repeatPow2 = choice.linear && sampler.wrapS == Wrap::Repeat && sampler.wrapT == Wrap::Repeat &&
                          isPowerOfTwo(texture.width()) && isPowerOfTwo(texture.height());
  Vec4 sum = Vec4::Zero();
  for (int k = 0; k < choice.count; ++k) {
    const TexelLevel& level = texture.level(choice.level[std::size_t(k)]);
    sum += choice.weight[std::size_t(k)] *
           (repeatPow2 ? (texture.packed() ? sampleLinearRepeatPow2Packed(texture, choice.level[std::size_t(k)], s, t)
                                            : sampleLinearRepeatPow2(level, s, t))
                       : sampleLevel(level, choice.linear, sampler, s, t));
  }
  return sum;
}

}  // namespace uvtk::render
