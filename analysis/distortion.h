// Per-triangle distortion of a UV layout: the linear map from each 3D triangle to its UV
// triangle, its singular values and the stretch measures of Sander, Snyder, Gortler and Hoppe,
// "Texture Mapping Progressive Meshes", SIGGRAPH 2001.
//
// For a face, J is the Jacobian of the map surface -> UV, written in an orthonormal frame of the
// triangle's plane; s1 >= |s2| are its singular values. Sander et al. measure the inverse map
// UV -> surface, whose singular values are G = 1/|s2| (largest) and g = 1/s1 (smallest).
//
// Status of a face, the first that applies (priority order):
//   invalid       the face has kFaceInvalid or a corner with cornerInvalid set
//   zero_area_3d  A3  <= 1e-14 (longest 3D edge)^2: the triangle is a point or a segment
//   zero_area_uv  Auv <= 1e-14 (longest UV edge)^2
//   pole_face     the face has kFacePole
//   backfacing    mirrored, and turned away from its projection (kFaceTurnedAway, which
//                 markTurnedAwayFaces sets): planar and triplanar projections mirror such faces
//                 by design
//   flipped       mirrored: its UV winding is opposite to the mesh's majority winding
//   ok
// The zero-area thresholds are relative, so they do not depend on the units; 1e-14 lies about
// 50 times above the rounding noise of a cross product (2^-52 times the squared edge length).
//
// Majority winding: each non-degenerate, valid face (status ok, pole_face, backfacing or flipped)
// votes its 3D area for the sign of its UV signed area; a face turned away from its projection
// (kFaceTurnedAway) votes with the opposite sign, since its mirroring is expected.
// The sign with the larger total wins; a tie goes to counter-clockwise (positive).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <optional>
#include <vector>

#include "core/math.h"
#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk::analysis {

enum class FaceStatus : std::uint8_t { Ok, ZeroArea3d, ZeroAreaUv, Flipped, Backfacing, Invalid, PoleFace };
constexpr int kFaceStatusCount = 7;

// "ok", "zero_area_3d", "zero_area_uv", "flipped", "backfacing", "invalid", "pole_face".
const char* toString(FaceStatus status);

// Whether a face of this status has a non-degenerate Jacobian, so that its measures are defined:
// ok, pole_face, backfacing and flipped faces.
constexpr bool isMeasured(FaceStatus status) {
  return status == FaceStatus::Ok || status == FaceStatus::PoleFace || status == FaceStatus::Backfacing ||
         status == FaceStatus::Flipped;
}

// The judgement's loops over faces take them in fixed chunks of this many, so that what they add
// up adds up in the same order whatever the threads.
constexpr std::size_t kFacesPerChunk = std::size_t(1) << 16;

// log2 of r = (Auv / A3) (sum(A3) / sum(Auv)), by logarithms where the quotients overflow or
// underflow (a sliver's Auv / A3 = 1e308).
double log2AreaRatio(double areaUv, double area3d, double surfacePerUv);

// The measures of one face. area3d is always set, areaUv unless the face is invalid; the
// Jacobian's measures only where isMeasured(status), else they are 0. Nothing is NaN or infinite.
// The measures that follow from the singular values and the areas are computed when read: stored,
// they took 80 bytes a face instead of 40 (320 MB for 4 M faces); the area distortion, which also
// needs the mesh's totals, is computed from them when read too.
struct FaceDistortion {
  FaceStatus status = FaceStatus::Invalid;
  double area3d = 0.0;  // A3, the triangle's area in object space (times measureLengthScale squared)
  double areaUv = 0.0;  // Auv, the absolute area of its UV triangle (times measureUvScale squared)
  double sigmaMax = 0.0;  // s1, the larger singular value of J
  double sigmaMin = 0.0;  // s2, |s2| <= s1; negative when the face is mirrored against the majority

  // Sander et al. 2001, "Texture stretch metric": UV -> surface has singular values G = 1/|s2|, g = 1/s1.
  // L2 = sqrt((G^2 + g^2) / 2), the root-mean-square stretch; in UV units.
  double l2Stretch() const {
    if (!isMeasured(status)) return 0.0;
    const double bigG = 1.0 / std::fabs(sigmaMin), smallG = 1.0 / sigmaMax;
    const double squares = bigG * bigG + smallG * smallG;
    if (squares >= 0x1p-1022 && squares <= 0x1p1023) return std::sqrt(0.5 * squares);
    // Squares beyond the doubles (a sliver of a mesh 1e150 across): the same, taken out of the larger, G >= g.
    const double ratio = smallG / bigG;
    return bigG * std::sqrt(0.5 * (1.0 + ratio * ratio));
  }
  // Linf = G, the greatest stretch in any direction.
  double linfStretch() const { return isMeasured(status) ? 1.0 / std::fabs(sigmaMin) : 0.0; }
  // Conformal distortion: s1/|s2|, the dilatation of a quasi-conformal map, 1 where angles are preserved.
  double angleDistortion() const { return isMeasured(status) ? sigmaMax / std::fabs(sigmaMin) : 0.0; }
  // Auv / A3, not normalised.
  double areaRatio() const { return isMeasured(status) ? areaUv / area3d : 0.0; }
  // Area distortion: log2(r), r = areaRatio() sum(A3) / sum(Auv) (AreaTotals::surfacePerUv over
  // the ok faces); 0 where equiareal.
  double areaDistortion(double surfacePerUv) const {
    return isMeasured(status) ? log2AreaRatio(areaUv, area3d, surfacePerUv) : 0.0;
  }
};

// The texels of the texture a texel density counts in: W x H (docs/conventions.md, "Texel density").
struct TextureSize {
  int width = 1024, height = 1024;
  bool operator==(const TextureSize& other) const { return width == other.width && height == other.height; }
};

// Where a projector looks, for markTurnedAwayFaces.
struct ProjectionDirections {
  // The direction the projector looks along, in object space (for the plane projector the image
  // of local +z: localFromObject.inverse().linear().col(2)). Unset: no face is turned away.
  std::optional<Vec3> projectionDirection;
  // Per face, in place of projectionDirection when not empty: a projector whose direction changes
  // from face to face (triplanar: the facing of each face's projection, param::triplanarFacing).
  std::vector<Vec3> faceProjectionDirections;
};

// The factor every 3D length is measured in: 1 for a mesh whose extent lies within 2^-500 .. 2^500
// (about 1e-150 .. 1e150, where areas and stretches are representable: object units), else the
// power of two that brings the extent to about 1, so that the areas of meshes at 1e-300 or 1e300
// neither underflow to 0 (every face zero_area_3d) nor overflow (NaN stretches). The normalised measures (area
// distortion, the summary's stretches, the verdict) do not depend on it; A3, the singular values
// and the raw stretches are in object units times it.
// `threads` (0: one per core) share the positions; the result does not depend on them.
double measureLengthScale(const Mesh& mesh, int threads = 1);

// The same for the valid corners' UVs (a two-plane layout of a mesh at 1e200 spans about 1e200), so
// that UV areas and the Jacobian's determinant neither overflow nor underflow. Auv, the singular
// values and the raw stretches are in UV units times it; the normalised measures do not depend on it.
double measureUvScale(const UvMap& uv, int threads = 1);
// The same from the valid corners' bounding box, where the caller has it (validUvBounds).
double measureUvScale(const Eigen::AlignedBox2d& validBounds);

// The bounding box of the valid corners' UVs; empty when there is none. `threads` (0: one per core)
// share the corners; the result does not depend on them.
Eigen::AlignedBox2d validUvBounds(const UvMap& uv, int threads = 1);

// Sets kFaceTurnedAway on the faces whose 3D normal n points away from where the projector looks
// (n . direction < 0): the faces a planar or triplanar projection mirrors by design, which
// measureFaces counts as backfacing rather than flipped. The flag travels with the UVs (a uvtk
// writer lists the faces, io/face_lists.h), so a written file is judged as its map was.
void markTurnedAwayFaces(const Mesh& mesh, const ProjectionDirections& directions, UvMap& uv, int threads = 1);

// The scales measureFaces measures at: measureLengthScale of the mesh, and measureUvScale of
// validUvBounds, which the summary reports (taken once: 50 ms each at 4 M faces).
struct MeasureScales {
  double length = 1.0;
  Eigen::AlignedBox2d uvBounds;
  double uv() const { return measureUvScale(uvBounds); }
};
MeasureScales measureScales(const Mesh& mesh, const UvMap& uv, int threads = 1);

// Every face's measures, an array per measure: 33 bytes a face (the status apart from the four
// doubles; as FaceDistortions, padded, 40), and each array contiguous for the loops that read one
// measure (the statistics' weights are `area3d` itself). faces[f] is face f's FaceDistortion.
class FaceMeasures {
 public:
  std::vector<FaceStatus> status;
  std::vector<double> area3d, areaUv, sigmaMax, sigmaMin;

  FaceMeasures() = default;
  // `count` faces, each invalid with zero measures; the arrays faulted in on `threads` threads.
  explicit FaceMeasures(std::size_t count, int threads = 1);
  // The measures `faces` list (a test's hand-made faces, a part of a mesh's).
  FaceMeasures(const std::vector<FaceDistortion>& faces);  // NOLINT: converts, as a container of them

  std::size_t size() const { return status.size(); }
  bool empty() const { return status.empty(); }
  FaceDistortion operator[](std::size_t f) const { return {status[f], area3d[f], areaUv[f], sigmaMax[f], sigmaMin[f]}; }

  // Face by face, each read as a FaceDistortion (a value, not a reference into the arrays).
  class Iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = FaceDistortion;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = FaceDistortion;
    Iterator(const FaceMeasures& faces, std::size_t f) : faces_(&faces), f_(f) {}
    FaceDistortion operator*() const { return (*faces_)[f_]; }
    Iterator& operator++() { return ++f_, *this; }
    Iterator operator++(int) { Iterator before = *this; ++f_; return before; }
    bool operator==(const Iterator& other) const { return f_ == other.f_; }
    bool operator!=(const Iterator& other) const { return f_ != other.f_; }

   private:
    const FaceMeasures* faces_;
    std::size_t f_;
  };
  Iterator begin() const { return {*this, 0}; }
  Iterator end() const { return {*this, size()}; }
};

// The measures of every triangle of `mesh`, at `scales` = measureScales(mesh, uv) (the second form
// takes them). Precondition: `uv` has 3 corners per triangle. `threads` (0: one per core) share the
// faces; the result does not depend on them.
FaceMeasures measureFaces(const Mesh& mesh, const UvMap& uv, const MeasureScales& scales, int threads = 0);
FaceMeasures measureFaces(const Mesh& mesh, const UvMap& uv, int threads = 0);

// The sums sum(A3) and sum(Auv) over the status-ok faces: the normalisation of every mesh-wide
// value. Faces of any other status are reported by count only.
struct AreaTotals {
  double surface = 0.0;  // sum(A3)
  double uv = 0.0;       // sum(Auv)
  // sum(A3) / sum(Auv): multiplies Auv/A3 into the normalised ratio r; 1 when there is no ok face.
  double surfacePerUv() const { return surface > 0.0 && uv > 0.0 ? surface / uv : 1.0; }
};
AreaTotals okAreaTotals(const FaceMeasures& faces);

}  // namespace uvtk::analysis
