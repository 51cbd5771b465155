// OpenGL fixed-function texture-coordinate generation (glTexGen), exactly as the OpenGL 4.6
// compatibility profile specifies it (§12.1.3, "Generating Texture Coordinates"), followed by the
// texture matrix. docs/conventions.md §6 states the decisions where GL leaves a choice.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "core/arithmetic.h"
#include "core/gl_matrices.h"
#include "core/math.h"
#include "core/mesh.h"
#include "core/names.h"
#include "core/uv_map.h"

namespace uvtk::texgen {

enum class TexgenMode {
  Off,            // the coordinate keeps GL's current texture coordinate (0, 0, 0, 1)
  ObjectLinear,   // plane . object coordinates
  EyeLinear,      // (plane * M_plane^-1) . eye coordinates
  SphereMap,      // s, t only
  NormalMap,      // s, t, r only
  ReflectionMap,  // s, t, r only
};

struct TexgenCoordinate {
  TexgenMode mode = TexgenMode::Off;
  Vec4 plane = Vec4::Zero();  // (p1, p2, p3, p4), not normalised; read by the linear modes
};

// GL's initial state: every coordinate off, planes s (1,0,0,0), t (0,1,0,0), r and q zero.
std::array<TexgenCoordinate, 4> defaultCoordinates();

struct TexgenOptions {
  std::array<TexgenCoordinate, 4> coordinates = defaultCoordinates();  // s, t, r, q
  Mat4 modelviewAtPlanes = Mat4::Identity();  // the modelview when the EYE_LINEAR planes were given
  Mat4 modelviewAtDraw = Mat4::Identity();    // the modelview the vertices are drawn under
  Mat4 textureMatrix = Mat4::Identity();      // applied to (s, t, r, q) after generation
  bool normalize = true;                      // renormalise the eye normal after the inverse transpose (GL_NORMALIZE)
  // Double: binary64 throughout. Float: the matrices, planes and inverses are prepared in double,
  // rounded to binary32 once, and every per-vertex operation is binary32 (a GL with float shaders);
  // the results are widened to double. A prepared value beyond float range is a UsageError.
  Precision precision = Precision::Double;
};

// `options` drawn under `view` and `model`: the EYE_LINEAR planes count as given under the view
// alone (so they act in world space), the vertices are drawn under view * model.
TexgenOptions drawnUnder(TexgenOptions options, const Mat4& view, const Mat4& model);

struct TexgenResult {
  UvMap uv;                           // uv = (s, t) and w = r per corner (3 per triangle)
  std::vector<double> q;              // per corner; never divided out (projective lookup divides)
  std::size_t sphereMapSingular = 0;  // corners with m = 0 (reflection (0, 0, -1)): s = t = 1/2
  std::size_t invalidCorners = 0;     // corners with a non-finite result: written as 0
};

// (s, t, r, q) of one vertex after the texture matrix. `singular`, if not null, is set to true
// when a SPHERE_MAP coordinate met m = 0, else false. Throws UsageError for a mode a coordinate
// cannot take (sphere map on r or q, normal or reflection map on q), a singular matrix whose
// inverse a mode needs, or (Precision::Float) a matrix, inverse or plane beyond float range.
Vec4 texgenAt(const Vec3& objectPosition, const Vec3& objectNormal, const TexgenOptions& options,
              bool* singular = nullptr);

// Per corner (3 per triangle) with the mesh's corner normals (core cornerNormals). Faces with a
// sphere-map singular corner carry kFaceSphereMapSingular, faces with a non-finite corner
// kFaceInvalid (that corner is written as (0, 0, 0, 0) and marked in cornerInvalid).
TexgenResult generateTexcoords(const Mesh& mesh, const TexgenOptions& options);

// GL's names of the modes, as every face spells them ("object_linear", ...).
extern const ChoiceNames<TexgenMode> kTexgenModeNames;
const char* texgenModeName(TexgenMode mode);

}  // namespace uvtk::texgen
