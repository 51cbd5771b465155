// Per-corner texture coordinates and per-face status: what every UV source produces
// (a projector, texgen, a file) and what the writers, analysis and renderer consume.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/math.h"

namespace uvtk {

// Per-face status bits. A face may carry several.
enum FaceFlag : std::uint8_t {
  kFaceOk = 0,
  kFaceInvalid = 1 << 0,            // a corner's ray missed the surface or gave a non-finite value
  kFacePole = 1 << 1,               // the face encloses (or touches) the projector's axis
  kFaceSeamStraddle = 1 << 2,       // the corners' u spanned more than 0.5 before seam repair
  kFaceCubeSeam = 1 << 3,           // the corners alone would have chosen different cube faces
  kFaceCap = 1 << 4,                // mapped by a cylinder's planar cap
  kFaceSphereMapSingular = 1 << 5,  // a texgen SPHERE_MAP corner had m = 0 (written as s = t = 1/2)
  kFaceTurnedAway = 1 << 6,         // turned away from a planar projection's direction: mirrored by design
};

// Why a corner has no valid UV: the value of UvMap::cornerInvalid (0: the corner is valid).
// docs/conventions.md §4 defines each case; the verdict (analysis/judgement.h) counts them apart.
enum CornerInvalid : std::uint8_t {
  kCornerValid = 0,
  kCornerMiss = 1,        // the probe misses the surface (or runs exactly parallel to it)
  kCornerBehind = 2,      // the ray meets the surface only behind its origin (planes: the line's crossing at t < 0)
  kCornerOutOfRange = 3,  // the hit lies beyond kSensibleRange times the fitted extent (a nearly parallel ray)
  kCornerNotFinite = 4,   // a value overflowed or was not finite
  kCornerNoTexcoord = 5,  // a file's corner without vt
};
constexpr int kCornerInvalidCount = 6;

// "valid", "miss", "behind", "out_of_range", "not_finite", "no_texcoord": the JSON keys.
inline const char* cornerInvalidName(int reason) {
  static constexpr const char* kNames[kCornerInvalidCount] = {"valid",        "miss",       "behind",
                                                              "out_of_range", "not_finite", "no_texcoord"};
  return reason >= 0 && reason < kCornerInvalidCount ? kNames[reason] : "unknown";
}

struct UvMap {
  std::vector<Vec2> uv;                     // 3 per triangle, corner k of face f at 3 f + k
  std::vector<double> w;                    // optional third component per corner (cube face index), or empty
  std::vector<std::uint8_t> faceFlags;      // one FaceFlag set per triangle
  std::vector<std::uint8_t> cornerInvalid;  // a CornerInvalid per corner, non-zero where it has no valid UV (written as 0, 0)
  // 1 per corner at a pole of the source (a wrapping projector's axis, a singular point, a file's
  // fanned pole): v is defined there, u is not (§5). Empty: no corner is. The source says it, as it
  // says cornerInvalid: nothing downstream rebuilds it.
  std::vector<std::uint8_t> cornerPole;

  std::size_t faceCount() const { return faceFlags.size(); }
  bool faceHas(std::size_t f, FaceFlag flag) const { return (faceFlags[f] & flag) != 0; }
  bool cornerValid(std::size_t c) const { return cornerInvalid.empty() || cornerInvalid[c] == kCornerValid; }
  bool cornerAtPole(std::size_t c) const { return !cornerPole.empty() && cornerPole[c] != 0; }
  // The UV a file holds at corner c: (0, 0) where the corner has no valid UV, whatever is stored
  // there (every writer lists such faces, io/face_lists.h).
  Vec2 writtenUv(std::size_t c) const { return cornerValid(c) ? uv[c] : Vec2::Zero(); }
};

// The distance in UV units between `found` and `expected` with whole periods removed: with d =
// found - expected and a non-zero period p (one turn about a wrapping surface's axis, in UV),
// a = (d . p) / |p|^2 turns; d loses round(a) p (the nearest integer, halves to even), or at a pole
// the whole a p (u is undefined there: only the component across the period counts). The result
// is |d|; a zero period compares plainly; NaN gives infinity. `uvtk check` and uvtk::point::uvError.
inline double wrappedUvError(const Vec2& found, const Vec2& expected, const Vec2& period, bool pole) {
  double du = found.x() - expected.x(), dv = found.y() - expected.y();
  const double pu = period.x(), pv = period.y();
  const double length2 = pu * pu + pv * pv;
  if (length2 > 0.0) {
    const double along = (du * pu + dv * pv) / length2;
    const double turns = pole ? along : std::nearbyint(along);
    if (std::isfinite(turns)) {
      du -= turns * pu;
      dv -= turns * pv;
    }
  }
  const double error = std::hypot(du, dv);
  return std::isnan(error) ? std::numeric_limits<double>::infinity() : error;
}

}  // namespace uvtk
