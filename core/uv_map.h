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
};

struct UvMap {
  std::vector<Vec2> uv;                     // 3 per triangle, corner k of face f at 3 f + k
  std::vector<double> w;                    // optional third component per corner (cube face index), or empty
  std::vector<std::uint8_t> faceFlags;      // one FaceFlag set per triangle
  std::vector<std::uint8_t> cornerInvalid;  // 1 where the corner has no valid UV (written as 0, 0)

  std::size_t faceCount() const { return faceFlags.size(); }
  bool faceHas(std::size_t f, FaceFlag flag) const { return (faceFlags[f] & flag) != 0; }
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
