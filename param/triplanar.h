// Triplanar (box-blend) projection: three planar projections along the projector frame's axes,
// blended per point by weights from the normal, as game engines texture terrain, rocks and scans
// without UVs. The default is Unity Shader Graph's Triplanar node; presets give MaterialX's
// triplanarprojection and Godot's BaseMaterial3D triplanar (docs/conventions.md, "Triplanar").
#pragma once

#include <array>

#include "core/math.h"

namespace uvtk::param {

enum class TriplanarPreset { Unity, MaterialX, Godot };

struct TriplanarOptions {
  TriplanarPreset preset = TriplanarPreset::Unity;
  double tile = 1.0;   // T: UV units per unit of the projector's frame; finite, non-zero
  // Unity's Blend and Godot's blend sharpness: the exponent B of |n|; MaterialX's blend b, whose
  // exponent is 1 / max(b, 0.03). Finite, >= 0.
  double blend = 1.0;
};

// Throws UsageError naming --tile or --blend for a value outside its range.
void checkTriplanarOptions(const TriplanarOptions& options);

// The exponent the weights raise |n_i| to (Unity, Godot: B; MaterialX: 1 / max(b, 0.03)).
double triplanarExponent(const TriplanarOptions& options);

// w_i = |n_i|^e / sum_j |n_j|^e for the exponent e (triplanarExponent), computed as
// (|n_i|/m)^e / sum_j (|n_j|/m)^e with m = max_j |n_j| so that no exponent underflows the sum to
// 0 or overflows it: e = 0 gives 1/3 each, a huge e the largest component alone (shared on ties).
// The weights do not depend on |n|. NaN for a zero or non-finite normal.
Vec3 triplanarWeights(const TriplanarOptions& options, const Vec3& normal);

// The (u, v) of projection `axis` (0: along x, 1: y, 2: z) of a point p of the projector's frame:
//   Unity      x: (p.z, p.y) T   y: (p.x, p.z) T   z: (p.x, p.y) T
//   MaterialX  x: (p.y, p.z) T   y: (p.x, p.z) T   z: (p.x, p.y) T   (upaxis Z, its default)
//   Godot      x: (-p.z, -p.y) T y: (p.x, p.z) T   z: (p.x, -p.y) T  (uv1_triplanar_pos * (1, -1, 1))
Vec2 triplanarUv(const TriplanarOptions& options, int axis, const Vec3& p);

// The axis of the largest |n_i| (for B > 0 the largest weight), ties to the lower axis (x before
// y before z, the cube's tie rule); x for a zero normal. What a mesh written with per-corner UVs
// takes per face (a box mapping).
int dominantAxis(const Vec3& normal);

// The normal a face needs to see projection `axis` unmirrored: grad u x grad v of triplanarUv, in
// the projector's frame (Unity: -x, -y, +z; so Unity mirrors the texture on +x, +y and -z faces).
Vec3 triplanarFacing(const TriplanarOptions& options, int axis);

// The three projections and their weights at a point of the projector's frame with normal n.
struct TriplanarSample {
  std::array<Vec2, 3> uv;  // uv_x, uv_y, uv_z
  Vec3 weights;
  int dominant = 0;  // dominantAxis(n)
};
TriplanarSample triplanarAt(const TriplanarOptions& options, const Vec3& p, const Vec3& normal);

}  // namespace uvtk::param
