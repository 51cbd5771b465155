#include "texgen/texgen.h"

#include <Eigen/LU>
#include <cmath>
#include <string>

#include "core/error.h"

namespace uvtk::texgen {

namespace {

const char* const kCoordinateNames[4] = {"s", "t", "r", "q"};

// Everything that does not depend on the vertex, computed once per call in double; T is the
// scalar the vertices are evaluated in (float: these values rounded once, see roundedToFloat).
template <class T>
struct Prepared {
  using V4 = Eigen::Matrix<T, 4, 1>;
  using M3 = Eigen::Matrix<T, 3, 3>;
  using M4 = Eigen::Matrix<T, 4, 4>;
  std::array<TexgenMode, 4> modes{};
  std::array<V4, 4> planes;  // ObjectLinear: the plane; EyeLinear: p' = p M_plane^-1 (as a column)
  M4 draw = M4::Identity();
  M3 normalMatrix = M3::Identity();  // (upper 3x3 of M_draw)^-T
  M4 texture = M4::Identity();
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

Prepared<double> prepare(const TexgenOptions& o) {
  Prepared<double> p;
  requireFinite(o.modelviewAtPlanes, "modelview at the planes");
  requireFinite(o.modelviewAtDraw, "modelview at draw time");
  requireFinite(o.textureMatrix, "texture matrix");
  bool eyeLinear = false;
  for (int i = 0; i < 4; ++i) {
    const TexgenMode m = o.coordinates[i].mode;
    if ((m == TexgenMode::SphereMap && i >= 2) ||
        ((m == TexgenMode::NormalMap || m == TexgenMode::ReflectionMap) && i == 3))
      throw UsageError(
          std::string("texgen: coordinate ") + kCoordinateNames[i] + " cannot take " +
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
    p.normalMatrix =
        inverseOf<Mat3>(o.modelviewAtDraw.topLeftCorner<3, 3>(), "modelview at draw time (upper 3x3)").transpose();
  p.texture = o.textureMatrix;
  p.textureIsIdentity = o.textureMatrix == Mat4::Identity();
  p.normalize = o.normalize;
  return p;
}

// The prepared values rounded to binary32 once, as a GL with float shaders receives its uniforms.
// A value that rounds to infinity is a UsageError, as a non-finite one is in double.
Prepared<float> roundedToFloat(const Prepared<double>& d) {
  Prepared<float> f;
  f.modes = d.modes;
  for (int i = 0; i < 4; ++i) {
    f.planes[i] = d.planes[i].cast<float>();
    if (f.modes[i] == TexgenMode::ObjectLinear || f.modes[i] == TexgenMode::EyeLinear)
      requireFinite(f.planes[i], "texgen plane (rounded to float)");
  }
  f.draw = d.draw.cast<float>();
  f.normalMatrix = d.normalMatrix.cast<float>();
  f.texture = d.texture.cast<float>();
  if (d.needsEye) requireFinite(f.draw, "modelview at draw time (rounded to float)");
  if (d.needsNormal) requireFinite(f.normalMatrix, "inverse transpose of the modelview (rounded to float)");
  if (!d.textureIsIdentity) requireFinite(f.texture, "texture matrix (rounded to float)");
  f.textureIsIdentity = d.textureIsIdentity;
  f.needsEye = d.needsEye;
  f.needsNormal = d.needsNormal;
  f.needsReflection = d.needsReflection;
  f.normalize = d.normalize;
  return f;
}

// Lengths whose square neither overflows nor underflows in T.
template <class T>
struct SafeLength;
template <>
struct SafeLength<double> {
  static constexpr double kMin = 1e-150, kMax = 1e150;
};
template <>
struct SafeLength<float> {
  static constexpr float kMin = 1e-18f, kMax = 1e18f;
};

// Unit vector along v; the zero vector stays zero (as Mesa's NORMALIZE_3FV). Scales first when
// the squared length would overflow or underflow.
template <class T>
Eigen::Matrix<T, 3, 1> normalised(const Eigen::Matrix<T, 3, 1>& v) {
  const T length = v.norm();
  if (length > SafeLength<T>::kMin && length < SafeLength<T>::kMax) return v / length;
  if (!v.allFinite()) return v;  // an overflowed vertex stays non-finite (an invalid corner), not "at the eye"
  const T largest = v.cwiseAbs().maxCoeff();
  if (!(largest > T(0))) return Eigen::Matrix<T, 3, 1>::Zero();
  const Eigen::Matrix<T, 3, 1> scaled = v / largest;
  return scaled / scaled.norm();
}

// g = p1 x + p2 y + p3 z + p4 w, summed left to right (GL 4.6 compat §12.1.3, OBJECT_ and EYE_LINEAR).
template <class T>
inline T planeValue(const Eigen::Matrix<T, 4, 1>& p, T x, T y, T z, T w) {
  return p[0] * x + p[1] * y + p[2] * z + p[3] * w;
}

// (s, t, r, q) of one vertex, every operation in T (the inputs rounded to T first), widened to double.
template <class T>
Vec4 evaluate(const Prepared<T>& p, const Vec3& objectPosition, const Vec3& objectNormal, bool& singular) {
  using V3 = Eigen::Matrix<T, 3, 1>;
  using V4 = Eigen::Matrix<T, 4, 1>;
  singular = false;
  const V3 xo = objectPosition.cast<T>();
  V4 eye = V4::Zero();
  V3 normal = V3::Zero(), reflection = V3::Zero();
  if (p.needsEye) eye = p.draw * V4(xo.x(), xo.y(), xo.z(), T(1));
  if (p.needsNormal) {
    normal = p.normalMatrix * objectNormal.cast<T>();
    if (p.normalize) normal = normalised(normal);  // GL_NORMALIZE
  }
  if (p.needsReflection) {  // GL 4.6 compat §12.1.3: r = u - 2 n (n . u), u the unit eye position
    const V3 u = normalised<T>(eye.template head<3>());
    reflection = u - T(2) * normal.dot(u) * normal;
  }
  V4 g(T(0), T(0), T(0), T(1));  // GL's current texture coordinate where generation is off
  for (int i = 0; i < 4; ++i) {
    switch (p.modes[i]) {
      case TexgenMode::Off:
        break;
      case TexgenMode::ObjectLinear:
        g[i] = planeValue(p.planes[i], xo.x(), xo.y(), xo.z(), T(1));
        break;
      case TexgenMode::EyeLinear:
        g[i] = planeValue(p.planes[i], eye[0], eye[1], eye[2], eye[3]);
        break;
      case TexgenMode::SphereMap: {
        // GL 4.6 compat §12.1.3: m = 2 sqrt(rx^2 + ry^2 + (rz + 1)^2), s = rx/m + 1/2, t = ry/m + 1/2
        const T rz1 = reflection.z() + T(1);
        const T m = T(2) * std::sqrt(reflection.x() * reflection.x() + reflection.y() * reflection.y() + rz1 * rz1);
        if (m > T(0)) {
          g[i] = reflection[i] / m + T(0.5);
        } else if (m == T(0)) {  // r = (0, 0, -1): Mesa's 1/2, flagged
          g[i] = T(0.5);
          singular = true;
        } else {  // NaN (an overflowed vertex) is no reflection: the corner becomes invalid, not singular
          g[i] = m;
        }
        break;
      }
      case TexgenMode::NormalMap:  // GL 4.6 compat §12.1.3: (s, t, r) = n_e
        g[i] = normal[i];
        break;
      case TexgenMode::ReflectionMap:  // GL 4.6 compat §12.1.3: (s, t, r) = r
        g[i] = reflection[i];
        break;
    }
  }
  // Then the texture matrix (GL 4.6 compat §12.1) on (s, t, r, q), in T as well.
  return (p.textureIsIdentity ? g : V4(p.texture * g)).template cast<double>();
}

// Every corner of the mesh (3 per triangle), evaluated in T; non-finite corners written as 0.
template <class T>
TexgenResult generateAll(const Prepared<T>& p, const Mesh& mesh) {
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

}  // namespace

std::array<TexgenCoordinate, 4> defaultCoordinates() {
  std::array<TexgenCoordinate, 4> c;
  c[0].plane = Vec4(1, 0, 0, 0);
  c[1].plane = Vec4(0, 1, 0, 0);
  return c;
}

Vec4 texgenAt(const Vec3& objectPosition, const Vec3& objectNormal, const TexgenOptions& options, bool* singular) {
  const Prepared<double> p = prepare(options);
  bool isSingular = false;
  const Vec4 g = options.precision == Precision::Float
                     ? evaluate(roundedToFloat(p), objectPosition, objectNormal, isSingular)
                     : evaluate(p, objectPosition, objectNormal, isSingular);
  if (singular) *singular = isSingular;
  return g;
}

TexgenResult generateTexcoords(const Mesh& mesh, const TexgenOptions& options) {
  const Prepared<double> p = prepare(options);
  return options.precision == Precision::Float ? generateAll(roundedToFloat(p), mesh) : generateAll(p, mesh);
}

const ChoiceNames<TexgenMode> kTexgenModeNames = {
    {"object_linear", TexgenMode::ObjectLinear}, {"eye_linear", TexgenMode::EyeLinear},
    {"sphere_map", TexgenMode::SphereMap},       {"normal_map", TexgenMode::NormalMap},
    {"reflection_map", TexgenMode::ReflectionMap}, {"off", TexgenMode::Off}};

const char* texgenModeName(TexgenMode mode) { return nameOf(kTexgenModeNames, mode).c_str(); }

TexgenOptions drawnUnder(TexgenOptions options, const Mat4& view, const Mat4& model) {
  options.modelviewAtPlanes = view;
  options.modelviewAtDraw = view * model;
  return options;
}

}  // namespace uvtk::texgen
