// Inside render: the shading of 2D-textured fragments with per-corner texture coordinates and
// analytic derivatives on SIMD vectors (Google Highway, dispatched at run time), from the pixel to
// the level of detail: the triangle's perspective-correct barycentrics and their derivatives
// (TriangleInterpolator::at), (s, t) = (s, t) / q and their screen-space derivatives
// (interpolatedTexcoords in renderer.cpp) and lambda (levelOfDetail, with glibc's hypot and log2
// from core/libm_simd-inl.h), each lane with the same operations in the same order as the scalar
// path, so with its bits. A lane whose lambda the vectors leave undecided keeps its derivatives
// for the scalar levelOfDetail.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "render/raster.h"
#include "render/texture.h"

namespace uvtk::render {

// Up to kSize fragments in, structure of arrays.
struct FragmentBatch {
  static constexpr std::size_t kSize = 256;  // a multiple of every vector width
  std::size_t count = 0;
  // In: the pixel centre in window coordinates (y up), the index of its triangle's DrawnFace in
  // TiledRaster::drawnFaces(), and 12 times its face (where its corners' (s, t, r, q) begin among
  // the doubles of TexcoordSource::corners).
  alignas(64) double x[kSize], y[kSize];
  alignas(64) std::int64_t drawn[kSize], corners[kSize];
  // Out: the barycentrics, (s, t), their derivatives, and lambda with the bias added.
  alignas(64) double b0[kSize], b1[kSize], b2[kSize];
  alignas(64) double s[kSize], t[kSize], dsdx[kSize], dtdx[kSize], dsdy[kSize], dtdy[kSize], lambda[kSize];
  // Out: the fragments whose lambda is levelOfDetail(...) + bias still to be taken, in order
  // (room for a whole vector past the last).
  alignas(64) std::int64_t undecided[kSize + 16];
  std::size_t undecidedCount = 0;
  // Out of sampleTexels: the filtered texel (RGBA), and the fragments it left to sample() (s or t
  // not finite), in order.
  alignas(64) double red[kSize], green[kSize], blue[kSize], alpha[kSize];
  alignas(64) std::int64_t unsampled[kSize + 16];
  std::size_t unsampledCount = 0;
  // sampleTexels' own: per level (two) the 2 x 2 texels' indices into the packed texels, the
  // fractions between them, and the level's weight.
  alignas(64) std::int64_t texel[8][kSize];
  alignas(64) double alphaS[2][kSize], betaT[2][kSize], levelWeight[2][kSize];
};

// What every fragment of a frame shares.
struct FragmentFrame {
  const DrawnFace* drawnFaces = nullptr;
  const double* corners = nullptr;  // TexcoordSource::corners[0].data()
  int textureWidth = 0, textureHeight = 0;
  double lodBias = 0.0;
};

// A packed 8-bit texture as the vectorised sampler reads it (render/texture.h).
struct FragmentTexture {
  const std::uint32_t* texels = nullptr;  // Texture::packedTexels(0): every level, with its slack
  std::int64_t levelOffset[32] = {};     // Texture::packedOffset(k)
  int levels = 0, width = 0, height = 0;
  SamplerState sampler;
  bool alpha = true;  // whether alpha is sampled (else left 0: the environment reads RGB alone)
};

// The texture and sampler as the vectorised sampler reads them, or nothing where it does not:
// unless the texture is packed with standard bytes (Texture::standardBytes) and each axis is
// clamped or of a power-of-two size (REPEAT and MIRRORED_REPEAT then take the texel index's
// low bits).
std::optional<FragmentTexture> vectorisedTexture(const Texture& texture, const SamplerState& sampler, bool alpha);

// sample(texture, sampler, s, t, lambda) of each of the batch's `count` fragments into red, green,
// blue and alpha, with the same operations in the same order (texture.cpp); fragments whose s or
// t is not finite are listed in unsampled for sample() itself. Precondition: fragmentsVectorised().
void sampleTexels(const FragmentTexture& texture, FragmentBatch& batch);

// Whether the processor runs the vectorised fragments (they need fused multiply-adds, for glibc's
// log2); where not, the scalar path shades every fragment.
bool fragmentsVectorised();

// Fills the batch's outputs for its `count` fragments (the inputs of whole vectors, 16 lanes at
// most, are read: lanes past count must hold valid indices, and are ignored). Precondition:
// fragmentsVectorised().
void shadeFragments(const FragmentFrame& frame, FragmentBatch& batch);

}  // namespace uvtk::render
