#include "texgen/texgen.h"

#include <Eigen/LU>
#include <cmath>
#include <string>

#include "core/error.h"

namespace uvtk::texgen {

namespace {

const char* const kCoordinateNames[4] = {"s", "t", "r", "q"};

// Everything that does not depend on the vertex, computed once per call.
struct Prepared {
  std::array<TexgenMode, 4> modes{};
  std::array<Vec4, 4> planes;  // ObjectLinear: the plane; EyeLinear: p' = p M_plane^-1 (as a column)
  Mat4 draw = Mat4::Identity();
  Mat3 normalMatrix = Mat3::Identity();  // (upper 3x3 of M_draw)^-T
  Mat4 texture = Mat4::Identity();
  bool textureIsIdentity = true;
  bool needsEye = false, needsNormal = false, needsReflection = false, normalize = true;
};

bool isNormalMode(TexgenMode m) {
  return m == TexgenMode::SphereMap || m == TexgenMode::NormalMap || m == TexgenMode::ReflectionMap;
}

template <class Matrix>
void requireFinite(const Matrix& m, const char* what) {
  if (!m.allFinite()) throw UsageError(std::string("texgen: the ") + what + " has a non-finite entry");
}

// The inverse of `m`; a UsageError when it is singular to working precision (Eigen's full-pivot
// LU rank test, threshold 4 eps relative to the largest pivot: a condition number of 1e12 passes).
template <class Matrix>
Matrix inverseOf(const Matrix& m, const char* what) {
  const Eigen::FullPivLU<Matrix> lu(m);
  if (!lu.isInvertible())
    throw UsageError(std::string("texgen: the ") + what + " is singular, so its inverse does not exist");
  return lu.inverse();
}

Prepared prepare(const TexgenOptions& o) {
  Prepared p;
  requireFinite(o.modelviewAtPlanes, "modelview at the planes");
  requireFinite(o.modelviewAtDraw, "modelview at draw time");
  requireFinite(o.textureMatrix, "texture matrix");
  bool eyeLinear = false;
  for (int i = 0; i < 4; ++i) {
    const TexgenMode m = o.coordinates[i].mode;
    if ((m == TexgenMode::SphereMap && i >= 2) ||
        ((m == TexgenMode::NormalMap || m == TexgenMode::ReflectionMap) && i == 3))
      throw UsageError(std::string("texgen: coordinate ") + kCoordinateNames[i] + " cannot take " +
                       (m == TexgenMode::SphereMap ? "sphere_map (s, t only)" : "normal_map or reflection_map (s, t, r only)"));
    if (m == TexgenMode::ObjectLinear || m == TexgenMode::EyeLinear)
      requireFinite(o.coordinates[i].plane, "texgen plane");
    p.modes[i] = m;
    p.planes[i] = o.coordinates[i].plane;
    eyeLinear |= m == TexgenMode::EyeLinear;
    p.needsNormal |= isNormalMode(m);
    p.needsReflection |= m == TexgenMode::SphereMap || m == TexgenMode::ReflectionMap;
  }
  p.needsEye = eyeLinear || p.needsReflection;
  if (eyeLinear) {
    // GL 4.6 compat §12.1.3: (p1' p2' p3' p4') = (p1 p2 p3 p4) M^-1, M the modelview at glTexGen.
    const Mat4 planeInverseTransposed = inverseOf(o.modelviewAtPlanes, "modelview at the planes").transpose();
    for (int i = 0; i < 4; ++i)
      if (p.modes[i] == TexgenMode::EyeLinear) p.planes[i] = planeInverseTransposed * p.planes[i];
  }
  p.draw = o.modelviewAtDraw;
  if (p.needsNormal)  // GL 4.6 compat §12.1.2: n_e = n M_u^-1 (a row vector), M_u the upper 3x3
    p.normalMatrix = inverseOf<Mat3>(o.modelviewAtDraw.topLeftCorner<3, 3>(), "modelview at draw time (upper 3x3)")
                         .transpose();
  p.texture = o.textureMatrix;
  p.textureIsIdentity = o.textureMatrix == Mat4::Identity();
  p.normalize = o.normalize;
  return p;
}

// Unit vector along v; the zero vector stays zero (as Mesa's NORMALIZE_3FV). Scales first when
// the squared length would overflow or underflow.
Vec3 normalised(const Vec3& v) {
  const double length = v.norm();
  if (length > 1e-150 && length < 1e150) return v / length;
  const double largest = v.cwiseAbs().maxCoeff();
  if (!(largest > 0.0) || !std::isfinite(largest)) return largest > 0.0 ? v : Vec3::Zero();
  const Vec3 scaled = v / largest;
  return scaled / scaled.norm();
}

// g = p1 x + p2 y + p3 z + p4 w, summed left to right (GL 4.6 compat §12.1.3, OBJECT_ and EYE_LINEAR).
inline double planeValue(const Vec4& p, double x, double y, double z, double w) {
  return p[0] * x + p[1] * y + p[2] * z + p[3] * w;
}

Vec4 evaluate(const Prepared& p, const Vec3& xo, const Vec3& no, bool& singular) {
  singular = false;
  Vec4 eye = Vec4::Zero();
  Vec3 normal = Vec3::Zero(), reflection = Vec3::Zero();
  if (p.needsEye) eye = p.draw * Vec4(xo.x(), xo.y(), xo.z(), 1.0);
  if (p.needsNormal) {
    normal = p.normalMatrix * no;
    if (p.normalize) normal = normalised(normal);  // GL_NORMALIZE
  }
  if (p.needsReflection) {  // GL 4.6 compat §12.1.3: r = u - 2 n (n . u), u the unit eye position
    const Vec3 u = normalised(eye.head<3>());
    reflection = u - 2.0 * normal.dot(u) * normal;
  }
  Vec4 g(0.0, 0.0, 0.0, 1.0);  // GL's current texture coordinate where generation is off
  for (int i = 0; i < 4; ++i) {
    switch (p.modes[i]) {
      case TexgenMode::Off: break;
      case TexgenMode::ObjectLinear: g[i] = planeValue(p.planes[i], xo.x(), xo.y(), xo.z(), 1.0); break;
      case TexgenMode::EyeLinear: g[i] = planeValue(p.planes[i], eye[0], eye[1], eye[2], eye[3]); break;
      case TexgenMode::SphereMap: {
        // GL 4.6 compat §12.1.3: m = 2 sqrt(rx^2 + ry^2 + (rz + 1)^2), s = rx/m + 1/2, t = ry/m + 1/2
        const double rz1 = reflection.z() + 1.0;
        const double m = 2.0 * std::sqrt(reflection.x() * reflection.x() + reflection.y() * reflection.y() + rz1 * rz1);
        if (m > 0.0) {
          g[i] = reflection[i] / m + 0.5;
        } else {  // r = (0, 0, -1): Mesa's 1/2, flagged
          g[i] = 0.5;
          singular = true;
        }
        break;
      }
      case TexgenMode::NormalMap: g[i] = normal[i]; break;  // GL 4.6 compat §12.1.3: (s, t, r) = n_e
      case TexgenMode::ReflectionMap: g[i] = reflection[i]; break;  // (s, t, r) = r
    }
  }
  return p.textureIsIdentity ? g : Vec4(p.texture * g);
}

}  // namespace

std::array<TexgenCoordinate, 4> defaultCoordinates() {
  std::array<TexgenCoordinate, 4> c;
  c[0].plane = Vec4(1, 0, 0, 0);
  c[1].plane = Vec4(0, 1, 0, 0);
  return c;
}

Vec4 texgenAt(const Vec3& objectPosition, const Vec3& objectNormal, const TexgenOptions& options, bool* singular) {
  const Prepared p = prepare(options);
  bool isSingular = false;
  const Vec4 g = evaluate(p, objectPosition, objectNormal, isSingular);
  if (singular) *singular = isSingular;
  return g;
}

TexgenResult generateTexcoords(const Mesh& mesh, const TexgenOptions& options) {
  const Prepared p = prepare(options);
  const std::size_t faces = mesh.faceCount(), corners = 3 * faces;
  std::vector<Vec3> normals;
  if (p.needsNormal) normals = cornerNormals(mesh);
  TexgenResult out;
  out.uv.uv.resize(corners);
  out.uv.w.resize(corners);
  out.q.resize(corners);
  out.uv.faceFlags.assign(faces, kFaceOk);
  out.uv.cornerInvalid.assign(corners, 0);
  const Vec3 noNormal = Vec3::Zero();
  for (std::size_t f = 0; f < faces; ++f) {
    for (int k = 0; k < 3; ++k) {
      const std::size_t c = 3 * f + static_cast<std::size_t>(k);
      bool singular = false;
      Vec4 g = evaluate(p, mesh.positions[static_cast<std::size_t>(mesh.triangles[f][k])],
                        p.needsNormal ? normals[c] : noNormal, singular);
      if (singular) {
        out.uv.faceFlags[f] |= kFaceSphereMapSingular;
        ++out.sphereMapSingular;
      }
      if (!g.allFinite()) {
        g.setZero();
        out.uv.cornerInvalid[c] = 1;
        out.uv.faceFlags[f] |= kFaceInvalid;
        ++out.invalidCorners;
      }
      out.uv.uv[c] = g.head<2>();
      out.uv.w[c] = g[2];
      out.q[c] = g[3];
    }
  }
  return out;
}

}  // namespace uvtk::texgen
