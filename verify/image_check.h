// Checking a picture drawn by another renderer (a GPU, a shader) against uvtk's rendering of the
// same scene, per pixel, with a set of valid results in the manner of Khronos's conformance tests
// (dEQP: tcuTexLookupVerifier, tcuTexCompareVerifier): a pixel is valid when some texture lookup
// that the allowed rounding of coordinates, filter weights and level of detail can give matches its
// colour within the colour threshold. docs/check.md, "Checking a screenshot".
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/image.h"
#include "core/math.h"
#include "render/renderer.h"

namespace uvtk::verify {

// The precisions a pixel is held to, in bits (dEQP's LookupPrecision and LodPrecision).
struct ImagePrecision {
  // A texel-space coordinate c (s times the level's width) may be off by max(1, |c|) 2^-coordBits.
  int coordBits = 20;
  // Each filter weight (LINEAR's alpha and beta, the mipmap blend's frac(lambda)) by 2^-weightBits.
  int weightBits = 16;
  // Lambda by 2^-lodBits beyond its neighbours' range; unset: 6 (dEQP's GLES 3 filtering tests:
  // llvmpipe's approximate log2 at a grazing angle went 2^-7 beyond 8 bits).
  std::optional<int> lodBits;
  // Each colour channel by 2^-colorBits; unset: the 8-bit format's bits less 1 (7), less 2 (6)
  // for the *_MIPMAP_LINEAR filters.
  std::optional<int> colorBits;
};

// The precisions in force for `sampler` and the mapping: the unset ones given their defaults.
// Throws UsageError for bits outside 1..30 (colour: 1..16).
ImagePrecision resolvePrecision(const ImagePrecision& precision, const render::SamplerState& sampler, bool projective);

// One invalid pixel, for the message: where, the shot's colour and the hull of the colours the
// pixel's own lookups allow (the colour threshold included).
struct InvalidPixel {
  int x = 0, row = 0;  // row 0 at the top
  Vec3 shot = Vec3::Zero();
  Vec3 low = Vec3::Zero(), high = Vec3::Zero();
};

struct ImageCheckResult {
  bool pass = true;
  std::size_t checked = 0;  // every pixel of the frame
  std::size_t invalid = 0;
  double invalidShare = 0.0;  // invalid / checked
  // dEQP's error mask: invalid pixels red, valid ones the shot's colour at a third.
  Image errorMask;
  std::vector<InvalidPixel> firstInvalid;  // the first kFirstInvalid, in row order
  ImagePrecision precision;                // as resolved
};

constexpr std::size_t kFirstInvalid = 10;

// uvtk's renderings of the scene a shot shows, with AOVs: with analytic derivatives (the
// reference proper) and a GPU's quad derivatives (their lambda counts where a pixel's 3 x 3
// neighbourhood holds another face or the background: there a quad extrapolates the triangle to
// pixels it does not cover, which no neighbour shows).
struct Reference {
  render::Rendering analytic;
  // The AOVs drawn with quad derivatives, in the analytic image's orientation; may be empty.
  std::vector<Image> quadAovs;
  // For coordinates interpolated from corners, what it takes to extrapolate any face to any
  // pixel (a pixel at an edge may show a face the reference shows only beside it): the vertices in
  // clip space as the renderer computes them, the triangles and their corners' (s, t, r, q). Empty
  // for a per-pixel mapping.
  std::vector<Vec4> clip;
  std::vector<Triangle> triangles;
  std::vector<Vec4> corners;
};

// The renderings of `mesh` with `options` (aovs set, derivatives replaced): analytic; fine quad
// derivatives; coarse ones from each of the quad's four pixels (render::Derivatives::QuadCoarse
// takes the bottom-left: the frame is drawn mirrored in x, y or both, and mirrored back), since
// GL lets a coarse derivative come from any pixel of the quad (llvmpipe takes the top-left; of
// an odd width or height the mirrored frame pairs other pixels into quads, a little looser). A
// per-pixel mapping that wraps in s has its quads drawn with SeamFix::Tarini: the seam line is a
// fault to find, not a lambda to allow. Throws UsageError as checkImage does (and for a blend of
// lookups), and what render::render throws.
Reference drawReference(const Mesh& mesh, const render::TexcoordSource& texcoords, const render::RenderOptions& options);

// `shot` (1 to 4 channels in [0, 1]: grey, grey and alpha, RGB, RGBA; alpha ignored) against
// `reference`, drawn with `options`. `projective`: q varies over the mesh (the lod tolerance's
// default). Supported: a 2D texture (options.texture) with EnvMode::Replace, one sample per
// pixel, no blend; anything else throws UsageError naming it, as does a shot of another size
// than the reference or a reference without AOVs.
ImageCheckResult checkImage(const Image& shot, const Reference& reference, const render::RenderOptions& options,
                            bool projective, const ImagePrecision& precision = {});

}  // namespace uvtk::verify
