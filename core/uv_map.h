// Per-corner texture coordinates and per-face status: what every UV source produces
// (a projector, texgen, a file) and what the writers, analysis and renderer consume.
#pragma once

#include <cstdint>
#include <vector>

#include "core/math.h"

namespace uvtk {

// Per-face status bits. A face may carry several.
enum FaceFlag : std::uint8_t {
  kFaceOk = 0,
  kFaceInvalid = 1 << 0,       // a corner's ray missed the surface or gave a non-finite value
  kFacePole = 1 << 1,          // the face encloses (or touches) the projector's axis
  kFaceSeamStraddle = 1 << 2,  // the corners' u spanned more than 0.5 before seam repair
  kFaceCubeSeam = 1 << 3,      // the corners alone would have chosen different cube faces
  kFaceCap = 1 << 4,           // mapped by a cylinder's planar cap
  kFaceSphereMapSingular = 1 << 5,  // a texgen SPHERE_MAP corner had m = 0 (written as s = t = 1/2)
};

struct UvMap {
  std::vector<Vec2> uv;            // 3 per triangle, corner k of face f at 3 f + k
  std::vector<double> w;           // optional third component per corner (cube face index), or empty
  std::vector<std::uint8_t> faceFlags;       // one FaceFlag set per triangle
  std::vector<std::uint8_t> cornerInvalid;   // 1 where the corner has no valid UV (written as 0, 0)

  std::size_t faceCount() const { return faceFlags.size(); }
  bool faceHas(std::size_t f, FaceFlag flag) const { return (faceFlags[f] & flag) != 0; }
};

}  // namespace uvtk
