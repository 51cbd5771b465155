// texgen against a real OpenGL: Mesa's fixed-function pipeline (OSMesa, software), its generated
// texture coordinates read back through feedback mode, vertex by vertex, for every mode.
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <vector>

#include "meshes/generators.h"
#include "texgen/texgen.h"

namespace uvtk::texgen {
namespace {
namespace UVTK_TEST_FILE {

struct MesaContext {
  MesaContext() : context(OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, nullptr)) {
    if (context) OSMesaMakeCurrent(context, pixels.data(), GL_UNSIGNED_BYTE, 16, 16);
  }
  ~MesaContext() {
    if (context) OSMesaDestroyContext(context);
  }
  OSMesaContext context;
  std::vector<unsigned char> pixels = std::vector<unsigned char>(16 * 16 * 4);
};

GLenum glMode(TexgenMode m) {
  switch (m) {
    case TexgenMode::ObjectLinear: return GL_OBJECT_LINEAR;
    case TexgenMode::EyeLinear: return GL_EYE_LINEAR;
    case TexgenMode::SphereMap: return GL_SPHERE_MAP;
    case TexgenMode::NormalMap: return GL_NORMAL_MAP;
    case TexgenMode::ReflectionMap: return GL_REFLECTION_MAP;
    case TexgenMode::Off: break;
  }
  return 0;
}

// (s, t, r, q) per corner as Mesa generates them: planes given under `view`, drawn under `view`.
std::vector<Vec4> mesaTexcoords(const Mesh& mesh, const std::vector<Vec3>& normals, const TexgenOptions& o) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-100, 100, -100, 100, -100, 100);  // nothing is clipped, so feedback returns every vertex
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixd(o.modelviewAtPlanes.data());
  static constexpr GLenum kCoordinate[4] = {GL_S, GL_T, GL_R, GL_Q};
  static constexpr GLenum kEnable[4] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q};
  for (int i = 0; i < 4; ++i) {
    const TexgenCoordinate& c = o.coordinates[i];
    if (c.mode == TexgenMode::Off) {
      glDisable(kEnable[i]);
      continue;
    }
    glTexGeni(kCoordinate[i], GL_TEXTURE_GEN_MODE, static_cast<GLint>(glMode(c.mode)));
    glTexGendv(kCoordinate[i], GL_OBJECT_PLANE, c.plane.data());
    glTexGendv(kCoordinate[i], GL_EYE_PLANE, c.plane.data());
    glEnable(kEnable[i]);
  }
  glLoadMatrixd(o.modelviewAtDraw.data());
  glEnable(GL_NORMALIZE);
  const unsigned char white[4] = {255, 255, 255, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
  glEnable(GL_TEXTURE_2D);  // Mesa computes texture coordinates only for an enabled unit
  std::vector<GLfloat> feedback(mesh.faceCount() * 3 * 12 + mesh.faceCount() * 2 + 16);
  glFeedbackBuffer(static_cast<GLsizei>(feedback.size()), GL_4D_COLOR_TEXTURE, feedback.data());
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_TRIANGLES);
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Vec3& n = normals[3 * f + k];
      const Vec3& p = mesh.positions[mesh.triangles[f][k]];
      glNormal3d(n.x(), n.y(), n.z());
      glVertex3d(p.x(), p.y(), p.z());
    }
  glEnd();
  const int used = glRenderMode(GL_RENDER);
  std::vector<Vec4> out;
  for (int i = 0; i < used;) {  // GL_POLYGON_TOKEN, count, then x y z w r g b a s t r q per vertex
    EXPECT_EQ(static_cast<int>(feedback[i]), GL_POLYGON_TOKEN);
    const int count = static_cast<int>(feedback[i + 1]);
    i += 2;
    for (int k = 0; k < count; ++k, i += 12) out.emplace_back(feedback[i + 8], feedback[i + 9], feedback[i + 10], feedback[i + 11]);
  }
  return out;
}

TEST(MesaReference, EveryModeAgreesWithMesaToFloatPrecision) {
  MesaContext mesa;
  ASSERT_NE(mesa.context, nullptr);
  Mesh mesh = meshes::latLongSphere(16, 8, 0.7);
  for (Vec3& p : mesh.positions) p += Vec3(0.3, -0.2, 0.1);
  const std::vector<Vec3> normals = cornerNormals(mesh);
  const Mat4 view = lookAt(Vec3(2, 1, 3), Vec3(0, 0, 0), Vec3(0, 1, 0));
  const Mat4 model = (Eigen::Affine3d(Eigen::AngleAxisd(0.6, Vec3(1, 2, 0.5).normalized())) *
                      Eigen::Scaling(1.0, 1.5, 0.8)).matrix();
  const struct {
    TexgenMode mode;
    int coordinates;
  } kCases[] = {{TexgenMode::ObjectLinear, 4}, {TexgenMode::EyeLinear, 4}, {TexgenMode::SphereMap, 2},
                {TexgenMode::NormalMap, 3}, {TexgenMode::ReflectionMap, 3}};
  const Vec4 planes[4] = {{0.5, -2, 1.5, 0.25}, {0, 1, 3, -1}, {1, 1, 0, 0.5}, {0.1, 0, 0.2, 1}};
  for (const auto& c : kCases) {
    TexgenOptions o;
    for (int i = 0; i < c.coordinates; ++i) o.coordinates[i] = {c.mode, planes[i]};
    o.modelviewAtPlanes = view;
    o.modelviewAtDraw = view * model;
    const TexgenResult ours = generateTexcoords(mesh, o);
    const std::vector<Vec4> reference = mesaTexcoords(mesh, normals, o);
    ASSERT_EQ(reference.size(), 3 * mesh.faceCount());
    for (std::size_t corner = 0; corner < reference.size(); ++corner) {
      const Vec4 g(ours.uv.uv[corner].x(), ours.uv.uv[corner].y(), ours.uv.w[corner], ours.q[corner]);
      for (int i = 0; i < 4; ++i)
        ASSERT_NEAR(g[i], reference[corner][i], 2e-6 * std::max(1.0, std::abs(reference[corner][i])))
            << "mode " << static_cast<int>(c.mode) << " corner " << corner << " coordinate " << i;
    }
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::texgen
