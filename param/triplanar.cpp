#include "param/triplanar.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace uvtk::param {

void checkTriplanarOptions(const TriplanarOptions& o) {
  if (!std::isfinite(o.tile) || o.tile == 0.0) throw UsageError("--tile: expected a finite, non-zero number");
  if (!std::isfinite(o.blend) || !(o.blend >= 0.0)) throw UsageError("--blend: expected a finite number >= 0");
}

double triplanarExponent(const TriplanarOptions& o) {
  // MaterialX stdlib_ng.mtlx, NG_triplanarprojection: power(|n| / sum |n|, 1 / clamp(blend, low 0.03))
  return o.preset == TriplanarPreset::MaterialX ? 1.0 / std::max(o.blend, 0.03) : o.blend;
}

Vec3 triplanarWeights(const TriplanarOptions& o, const Vec3& normal) {
  const Vec3 a = normal.cwiseAbs();
  const double m = a.maxCoeff();
  if (!(m > 0.0) || !std::isfinite(m)) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  const double e = triplanarExponent(o);
  // Unity Shader Graph, Triplanar node: Blend = pow(abs(Normal), Blend); Blend /= dot(Blend, 1)
  Vec3 w;
  for (int i = 0; i < 3; ++i) w[i] = std::pow(a[i] / m, e);  // the largest is 1: the sum is in [1, 3]
  return w / w.sum();
}

Vec2 triplanarUv(const TriplanarOptions& o, int axis, const Vec3& p) {
  const double t = o.tile;
  switch (o.preset) {
    case TriplanarPreset::Unity:  // Node_UV = Position * Tile; X: Node_UV.zy, Y: .xz, Z: .xy
      return axis == 0 ? Vec2(p.z() * t, p.y() * t) : axis == 1 ? Vec2(p.x() * t, p.z() * t) : Vec2(p.x() * t, p.y() * t);
    case TriplanarPreset::MaterialX:  // NG_triplanarprojection, upaxis 2: X: (y, z), Y: (x, z), Z: (x, y)
      return axis == 0 ? Vec2(p.y() * t, p.z() * t) : axis == 1 ? Vec2(p.x() * t, p.z() * t) : Vec2(p.x() * t, p.y() * t);
    case TriplanarPreset::Godot:  // BaseMaterial3D: pos = VERTEX * scale * (1, -1, 1); X: pos.zy * (-1, 1), Y: .xz, Z: .xy
      return axis == 0 ? Vec2(-p.z() * t, -p.y() * t) : axis == 1 ? Vec2(p.x() * t, p.z() * t) : Vec2(p.x() * t, -p.y() * t);
  }
  return Vec2::Zero();
}

Vec3 triplanarFacing(const TriplanarOptions& o, int axis) {
  Vec3 du, dv;  // the projection is linear: its gradients are its values at the unit vectors
  for (int k = 0; k < 3; ++k) {
    const Vec2 uv = triplanarUv(o, axis, Vec3::Unit(k));
    du[k] = uv.x();
    dv[k] = uv.y();
  }
  return du.cross(dv);
}

TriplanarSample triplanarAt(const TriplanarOptions& o, const Vec3& p, const Vec3& normal) {
  return TriplanarSample{{triplanarUv(o, 0, p), triplanarUv(o, 1, p), triplanarUv(o, 2, p)},
                         triplanarWeights(o, normal),
                         dominantAxis(normal)};
}

int dominantAxis(const Vec3& normal) {
  const Vec3 a = normal.cwiseAbs();
  if (a.x() >= a.y() && a.x() >= a.z()) return 0;
  return a.y() >= a.z() ? 1 : 2;
}

}  // namespace uvtk::param
