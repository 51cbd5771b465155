// Projector mappings of Bier & Sloan (1986): a mesh and options in, per-corner UVs, per-face
// status and a summary out. The library entry point behind `uvtk map`.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/arithmetic.h"
#include "core/mesh.h"
#include "core/uv_map.h"
#include "param/atlas.h"
#include "param/camera_projector.h"
#include "param/formulas.h"
#include "param/placement.h"
#include "param/surface_traits.h"
#include "param/triplanar.h"

namespace uvtk::param {

enum class RayKind { SurfaceNormal, Centroid, ObjectNormal, Reflection };

enum class SeamMode {
  None,   // raw per-vertex u: the artifact, for inspection
  Shift,  // add 1 to the low corners of straddling faces: u in [0, 1.5), render with REPEAT
  Cut,    // also cut straddling triangles along the seam: u in [0, 1], CLAMP works
};

// Where a capped cylinder's side and caps lie in the unit square (§5).
enum class CapLayout {
  Beside,   // the side band in v [0, 1/2]; the top cap in [0, 1/2] x [1/2, 1], the bottom one beside it
  Stacked,  // side and both caps each over the whole unit square (they overlap)
};

enum class PoleMode {
  None,  // pole vertices get u = 0
  Fan,   // each face's pole corner gets the mean u of its other corners
};

// The UV transform after mapping: flip, then scale, then rotate about (0.5, 0.5), then offset.
struct UvTransform {
  Vec2 scale = Vec2::Ones();
  Vec2 offset = Vec2::Zero();
  double rotateDegrees = 0.0;
  bool flipU = false;  // u -> 1 - u
  bool flipV = false;  // v -> 1 - v
  bool isIdentity() const;
  Vec2 apply(const Vec2& uv) const;
};

struct ProjectorOptions {
  SurfaceKind surface = SurfaceKind::Sphere;
  RayKind ray = RayKind::SurfaceNormal;
  PlacementOptions placement;
  // two-plane: u and v are signed distances to these object-space planes (a, b, c, d)
  Vec4 planeU = Vec4(1, 0, 0, 0);
  Vec4 planeV = Vec4(0, 1, 0, 0);
  // cylinder: planar caps on faces whose normal is within capAngleDegrees of the axis
  bool cylinderCaps = false;
  double capAngleDegrees = 45.0;
  CapLayout capLayout = CapLayout::Beside;
  SpherePreset spherePreset = SpherePreset::Default;
  CubeConvention cubeConvention = CubeConvention::Gl;
  CubeLayout cubeLayout = CubeLayout::Cross;  // faces keeps each face over the unit square, for cube maps
  // reflection: the eye in object space (required), and lookup by direction only
  std::optional<Vec3> eye;
  bool atInfinity = false;
  CameraProjector camera;  // SurfaceKind::Camera: the view projected from (not the reflection eye above)
  TriplanarOptions triplanar;  // SurfaceKind::Triplanar
  AtlasOptions atlas;          // SurfaceKind::Atlas
  SeamMode seam = SeamMode::Shift;
  PoleMode pole = PoleMode::Fan;
  double poleEpsilon = 1e-6;  // a pole: hypot(x, y) <= eps |q|
  UvTransform uvTransform;
  Arithmetic arithmetic;  // precision and math mode of the per-vertex evaluation (docs/precision.md)
};

// Why a projector found no value at a finite point (docs/conventions.md §4), in words: the reason
// the mapping carried, and for a miss which miss the options make it.
const char* invalidReasonText(const ProjectorOptions& options, CornerInvalid reason);

// Where the u period of a wrapping surface starts (u lies in [start, start + 1)); nothing for the
// surfaces that do not wrap.
std::optional<double> uPeriodStartOf(const ProjectorOptions& options);

// The state of one evaluated vertex or corner.
enum class CornerState : std::uint8_t {
  Ok,
  Pole,     // on the axis of a wrapping surface: v is defined, u is not (§5)
  Invalid,  // no (u, v): the reason (CornerInvalid, core/uv_map.h) says why
};

// One vertex through both stages, before seam and pole repair.
struct VertexUv {
  Vec2 uv = Vec2::Zero();     // u = 0 for poles; (0, 0) when invalid
  Vec2 axial = Vec2::Zero();  // the hit point projected along the surface's axis
  CornerState state = CornerState::Invalid;
  CornerInvalid reason = kCornerMiss;  // kCornerValid exactly when state is not Invalid
};

struct MappingSummary {
  std::size_t vertices = 0, faces = 0;  // of the output mesh
  std::size_t straddlingFaces = 0;      // faces whose u spanned more than 0.5 before repair
  std::size_t poleVertices = 0, poleFaces = 0;
  std::size_t invalidVertices = 0, invalidFaces = 0;
  // Corners of the output mesh per CornerInvalid (entry kCornerValid: the valid corners), as in
  // analysis::Judgement; the invalid entries add up to the corners with cornerInvalid set.
  std::array<std::size_t, kCornerInvalidCount> invalidCorners{};
  std::size_t cubeSeamFaces = 0, capFaces = 0;
  std::size_t addedVertices = 0, addedFaces = 0;  // by --seam cut
  std::array<std::size_t, 3> triplanarFaces{};    // triplanar: faces written by the x, y, z projection (box UVs)
  std::vector<int> invalidVertexList;             // vertex indices (input numbering, 0-based)
  std::vector<int> poleVertexList;
  std::vector<int> poleFaceList;                  // face indices of the output mesh
};

struct Projection {
  Mesh mesh;  // the input, or with straddling triangles cut (SeamMode::Cut); no file texcoords
  UvMap uv;
  MappingSummary summary;
  Affine3 localFromObject = Affine3::Identity();
  std::vector<std::uint8_t> triplanarAxis;  // triplanar: the projection (0: x, 1: y, 2: z) each face carries
  // atlas: its charts and measures (its uv moved into `uv`), shared with what evaluates it per pixel
  std::shared_ptr<const Atlas> atlas;
  // The range rule's box the corners were mapped with (sensibleBox of the mesh before any seam
  // cut), for what evaluates the projector per pixel; nothing without a range check.
  std::optional<Eigen::AlignedBox3d> sensible;
  struct {
    double map = 0.0;    // the placement fit and every corner through both stages
    double seams = 0.0;  // seam and pole repair, the summary, the UV transform
  } milliseconds;
};

// The sensible box B of the range rule (docs/conventions.md §4), in the projector's local frame:
// the box of the mesh's local positions united with the surface's unit shape (plane [0,1]^2 x {0};
// cylinder radius 1, z in [0, 1]; sphere the unit ball; cube [-1,1]^3; two-plane nothing, it works
// in object space). Nothing when it has no finite, non-zero extent (then there is no range check).
// project() computes it from its mesh (Projection::sensible); a Projector of points takes it from
// the caller that has the mesh. On `threads` threads (0: one per core), the same box on any number.
std::optional<Eigen::AlignedBox3d> sensibleBox(const std::vector<Vec3>& positions, const ProjectorOptions& options,
                                               const Affine3& localFromObject, int threads = 1);

// The camera projector's (u, v) = (s/q, t/q) at an object-space point (CameraTransform), in
// double whatever the precision: invalid with kCornerBehind where q <= 0 (at or behind the eye
// plane), kCornerNotFinite where a value is not finite. u, v outside [0, 1] (outside the view's
// sides) stay as they are, as Blender's Project from View leaves them.
VertexUv cameraVertexUv(const CameraTransform& camera, const Vec3& position);

// The triplanar projector's per-corner UVs: the projection of the dominant axis of `faceNormal`
// (dominantAxis; a face normal in the projector's frame) at a point of that frame, invalid with
// kCornerNotFinite where they are not finite. A face gets one projection: a box mapping.
VertexUv triplanarVertexUv(const TriplanarOptions& options, int axis, const Vec3& local);

// A projector's value at one object-space point: what `uvtk eval` reports and the renderer
// evaluates at every pixel.
struct PointUv {
  Vec2 uv = Vec2::Zero();        // the (u, v) a mesh would carry there: caps laid out, the cube's layout, the UV transform
  Vec2 unplaced = Vec2::Zero();  // before the cube's layout and the UV transform: u in its period, a cube face's (s, t)
  Vec2 axial = Vec2::Zero();     // the hit point projected along the surface's axis (VertexUv::axial)
  CornerState state = CornerState::Invalid;
  CornerInvalid reason = kCornerMiss;  // kCornerValid exactly when state is not Invalid
  std::optional<CubeFace> cubeFace;    // the cube: the face of the point's own probe
};

// One projector, made once from its options, placement (fitPlacement) and sensible box
// (sensibleBox of the mesh; without one there is no range check): the one source of UVs behind
// per-vertex mapping (`uvtk map` through project(), mapVertices), per-point evaluation (`uvtk eval`,
// the point API, Python's eval) and per-pixel evaluation (the renderer's exact UVs, views, `check
// --image`). The SIMD kernel (param/uv_kernel.h) and the per-sample templates (sample_evaluator.h)
// are how it evaluates, not other sources. Throws UsageError for inconsistent options
// (reflection without an eye, parallel two-plane planes, ...) and for the atlas, LSCM and ARAP,
// whose charts come from a whole mesh (project() maps those).
class Projector {
 public:
  Projector(const ProjectorOptions& options, const Affine3& localFromObject,
            const std::optional<Eigen::AlignedBox3d>& sensible = std::nullopt);

  const ProjectorOptions& options() const { return options_; }
  const Affine3& localFromObject() const { return localFromObject_; }
  const SurfaceTraits& traits() const { return traitsOf(options_.surface); }
  bool needsNormal() const { return needsNormal_; }  // at() and blendAt() read the normal (the O-mapping, triplanar)
  // One turn of u in the final UVs (the UV transform of (1, 0) less that of (0, 0)); zero unless it wraps.
  Vec2 period() const;

  // Per vertex: object-space positions through both stages (placement, O-mapping, surface,
  // S-mapping), no seam or pole repair and no UV transform. `normals` is read only by the normal
  // and reflection O-mappings (then one unit normal per position). `out` is resized, so a caller
  // that maps repeatedly reuses its memory. The cube and triplanar choose per triangle and are a
  // UsageError here (project() maps them). `threads` (0: one per core) split the positions into
  // contiguous ranges; the result does not depend on them.
  void mapVertices(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals, std::vector<VertexUv>& out,
                   int threads = 1) const;

  // Per point and per pixel: the exact mapping, without seam or pole repair (u stays in its period;
  // a pole gets u = 0). The cube takes the face of the point's own probe (exact, where project()
  // chooses one face per triangle). With `capFace` (a face project() mapped by a cylinder cap) the
  // cap projection, mirrored by the sign of `normal` along the axis (pass the face normal).
  // Triplanar gives the projection of the normal's dominant axis; blendAt gives all three.
  PointUv at(const Vec3& position, const Vec3& normal, bool capFace = false) const;
  // Triplanar: the three projections (UV transform applied) and their weights at a point.
  TriplanarSample blendAt(const Vec3& position, const Vec3& normal) const;
  // Whether a cylinder with caps maps a face of this object-space normal by a cap: an angle of at
  // most capAngleDegrees with the axis (the object-space direction of local +z). Decided in object
  // space because a fit scales non-uniformly: a long mesh squeezed to height 1 would tilt every
  // side normal towards the axis. The one test behind project() and per-point evaluation.
  bool isCap(const Vec3& objectNormal) const;

 private:
  ProjectorOptions options_;
  Affine3 localFromObject_;
  std::optional<Eigen::AlignedBox3d> sensible_;
  std::function<PointUv(const Vec3&, const Vec3&)> point_;  // the surface's own value, before caps and the UV transform
  std::function<Vec2(const Vec3&, const Vec3&)> cap_;       // a cap face's (u, v), laid out
  std::function<TriplanarSample(const Vec3&, const Vec3&)> blend_;  // triplanar's three projections
  Vec3 capAxis_ = Vec3::UnitZ();                            // unit, object space
  double capCosLimit_ = 0.0;
  bool needsNormal_ = false;
};

// Seam placement (`--seam-place auto`): the turn of a wrapping projector about its axis
// (PlacementOptions::turnDegrees) whose seam crosses the fewest faces.
struct SeamPlacement {
  double turnDegrees = 0.0;
  std::size_t facesCrossed = 0, facesCrossedBefore = 0;  // straddling faces at the chosen turn, and at the given one
  double seamLength = 0.0, seamLengthBefore = 0.0;       // the seam edges' total length, likewise
};

// Candidate turns put the seam midway between the azimuths of neighbouring corners, so that no
// corner lies on it; the given turn is kept unless a candidate crosses fewer faces; among equal
// candidates the widest gap wins. Straddling is decided as project() decides it (§5). It maps the
// mesh up to three times: unrepaired for the sweep, then at the given and the chosen turn for the
// numbers it reports. Throws
// UsageError unless the surface wraps (cylinder, sphere).
SeamPlacement placeSeam(const Mesh& mesh, const ProjectorOptions& options);

// Where the seam went, as one line on stderr above a progress bar (nothing when quiet).
void printSeamPlacement(const SeamPlacement& placement);

// Maps `mesh` (taken by value: with SeamMode::Cut its triangles change) on `threads` (0: one per
// core; the result does not depend on them). Throws UsageError for inconsistent options
// (reflection without an eye, parallel two-plane planes, ...).
Projection project(Mesh mesh, const ProjectorOptions& options, int threads = 0);

}  // namespace uvtk::param
