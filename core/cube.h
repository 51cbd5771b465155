// The cube of OpenGL's cube maps (GL 4.6 §8.13, table 8.19): which face a direction selects, where
// on that face it lands, and back. The cube projector (param/) and cube-map textures (render/)
// both use it; docs/conventions.md §3.
#pragma once

#include <cmath>

#include "core/math.h"

namespace uvtk {

enum class CubeFace { PosX, NegX, PosY, NegY, PosZ, NegZ };  // the GL order; index = face id
constexpr int kCubeFaceCount = 6;

// The face of the major axis; ties go to x before y before z, the sign follows the sign bit,
// so +0 picks the + face and -0 the - face.
template <class T>
CubeFace majorAxisFace(const Vec3T<T>& d) {
  const T ax = std::fabs(d.x()), ay = std::fabs(d.y()), az = std::fabs(d.z());
  if (ax >= ay && ax >= az) return std::signbit(d.x()) ? CubeFace::NegX : CubeFace::PosX;
  if (ay >= az) return std::signbit(d.y()) ? CubeFace::NegY : CubeFace::PosY;
  return std::signbit(d.z()) ? CubeFace::NegZ : CubeFace::PosZ;
}

inline int faceAxis(CubeFace f) { return static_cast<int>(f) / 2; }
inline int faceSign(CubeFace f) { return static_cast<int>(f) % 2 == 0 ? 1 : -1; }

// (sc, tc) of direction d on face f, before the division by |ma| (GL 4.6 table 8.19): seen from
// outside the cube, s runs right and t runs down.
template <class T>
Vec2T<T> glCubeFaceCoordinates(const Vec3T<T>& d, CubeFace f) {
  const T x = d.x(), y = d.y(), z = d.z();
  switch (f) {
    case CubeFace::PosX:
      return {-z, -y};
    case CubeFace::NegX:
      return {z, -y};
    case CubeFace::PosY:
      return {x, z};
    case CubeFace::NegY:
      return {x, -z};
    case CubeFace::PosZ:
      return {x, -y};
    case CubeFace::NegZ:
      return {-x, -y};
  }
  return {};
}

// GL 4.6 eq. 8.8: s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2.
template <class T>
Vec2T<T> faceStFromCoordinates(const Vec2T<T>& c, T ma) {
  return {(c.x() / std::fabs(ma) + T(1)) * T(0.5), (c.y() / std::fabs(ma) + T(1)) * T(0.5)};
}

// The (s, t) of direction d on face f by GL's table; f is usually majorAxisFace(d), but any face
// whose axis d points along (d[faceAxis(f)] faceSign(f) > 0) gives d's point on that face's plane.
template <class T>
Vec2T<T> glCubeFaceSt(const Vec3T<T>& d, CubeFace f) {
  return faceStFromCoordinates(glCubeFaceCoordinates(d, f), d[faceAxis(f)]);
}

// The inverse of table 8.19: the direction with major component ma > 0 along face f's axis (in
// its sign) and face coordinates (sc, tc).
template <class T>
Vec3T<T> glCubeDirection(CubeFace f, T sc, T tc, T ma) {
  switch (f) {
    case CubeFace::PosX:
      return {ma, -tc, -sc};
    case CubeFace::NegX:
      return {-ma, -tc, sc};
    case CubeFace::PosY:
      return {sc, ma, tc};
    case CubeFace::NegY:
      return {sc, -ma, -tc};
    case CubeFace::PosZ:
      return {sc, -tc, ma};
    case CubeFace::NegZ:
      return {-sc, -tc, -ma};
  }
  return {};
}

enum class CubeLayout {
  Faces,       // per-face [0,1]^2, the face id kept as the third texture coordinate
  Cross,       // 4x3 horizontal cross: -X +Z +X -Z in the middle row, +Y above and -Y below +Z
  Strip,       // 6x1 in the order +X -X +Y -Y +Z -Z
  ThreeByTwo,  // top row +X -X +Y, bottom row -Y +Z -Z
};

// Where face f sits in an atlas of `layout`: cell (column, row), the row counted from the bottom
// (v = 0), in a grid of columns x rows cells. Faces is a single cell.
struct CubeLayoutCell {
  int column = 0, row = 0, columns = 1, rows = 1;
};

inline CubeLayoutCell cubeLayoutCell(CubeFace f, CubeLayout layout) {
  const int face = static_cast<int>(f);
  switch (layout) {
    case CubeLayout::Faces:
      return {};
    case CubeLayout::Strip:
      return {face, 0, 6, 1};
    case CubeLayout::ThreeByTwo:
      return {face % 3, face < 3 ? 1 : 0, 3, 2};
    case CubeLayout::Cross: {
      static constexpr int kCell[kCubeFaceCount][2] = {{2, 1}, {0, 1}, {1, 2}, {1, 0}, {1, 1}, {3, 1}};
      return {kCell[face][0], kCell[face][1], 4, 3};
    }
  }
  return {};
}

}  // namespace uvtk
