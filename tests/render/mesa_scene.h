// Scenes drawn both by uvtk and by Mesa's fixed-function OpenGL through OSMesa, with the same
// matrices, texels, sampler, environment and texture coordinates: the harness shared by the
// renderer's pixel comparison (tests/render/mesa_render_test.cpp) and the screenshot check's
// Mesa images (tests/verify/mesa_check_test.cpp).
#pragma once

#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "core/gl_matrices.h"
#include "meshes/generators.h"
#include "render/renderer.h"
#include "texgen/texgen.h"

namespace uvtk::render::mesa {

inline constexpr int kWidth = 128, kHeight = 96;

struct Scene {
  std::string name;
  Mesh mesh;
  std::vector<Vec4> corners;                    // (s, t, r, q) per corner, what uvtk interpolates
  std::optional<texgen::TexgenOptions> texgen;  // Mesa generates the corners itself with glTexGen
  Camera camera;
  Mat4 worldFromObject = Mat4::Identity();
  const Texture* texture = nullptr;
  const CubeTexture* cubeTexture = nullptr;  // bound instead of `texture` when set
  bool seamless = false;                     // GL_TEXTURE_CUBE_MAP_SEAMLESS
  Filter filter = Filter::Nearest;
  Wrap wrap = Wrap::Repeat;
  EnvMode env = EnvMode::Replace;
  bool twoSided = false;                     // GL_LIGHT_MODEL_TWO_SIDE
  Cull cull = Cull::Back;
  Vec3 background = Vec3(40, 90, 160) / 255.0;  // 8-bit values, so both clear to the same bytes
};

inline Camera perspectiveCamera(const Vec3& eye, const Vec3& centre, double fovy, double zNear, double zFar) {
  Camera c;
  c.width = kWidth, c.height = kHeight;
  c.viewFromWorld = lookAt(eye, centre, Vec3::UnitY());
  c.clipFromView = perspective(fovy, double(kWidth) / kHeight, zNear, zFar);
  return c;
}

// Every texel a distinct colour with large steps between neighbours, so that a texel off by one
// or a blend weight off by a little shows in the 8-bit result. No mipmaps.
inline Texture rampTexture(int width, int height) {
  TexelLevel level{width, height, {}};
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      level.texels.push_back(
          Rgba(float((i * 97) % 256), float((j * 57) % 256), float(((i + j) * 151 + 37) % 256), 255.0f) / 255.0f);
  return Texture(level, true);
}

// The square [-1, 1]^2 of z = 0, two counter-clockwise triangles, texture coordinates from `lo`
// to `hi` along both axes, tilted away from a camera that sees it in perspective.
inline Scene tiltedQuad(std::string name, const Texture& texture, Filter filter, Wrap wrap, double lo, double hi) {
  Scene s;
  s.name = std::move(name);
  s.mesh.positions = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)};
  s.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  for (const Triangle& t : s.mesh.triangles)
    for (int v : t) {
      const Vec3& p = s.mesh.positions[std::size_t(v)];
      s.corners.emplace_back(lo + (hi - lo) * (p.x() + 1) / 2, lo + (hi - lo) * (p.y() + 1) / 2, 0.0, 1.0);
    }
  s.worldFromObject =
      (Affine3(Eigen::AngleAxisd(-1.0, Vec3::UnitX())) * Eigen::AngleAxisd(0.35, Vec3::UnitZ()) * Eigen::Scaling(1.4))
          .matrix();
  s.camera = perspectiveCamera(Vec3(0, 0.4, 3), Vec3::Zero(), 50.0, 0.5, 20.0);
  s.texture = &texture;
  s.filter = filter;
  s.wrap = wrap;
  return s;
}

// A unit latitude-longitude sphere with its pole tipped towards the camera, culled, with the
// sphere projector's (u, v) per corner: u = atan2(y, x) / 2 pi made continuous within each
// triangle (the pole takes its neighbours' mean), v = acos(z) / pi. No texture bound.
inline Scene sphereMesh(std::string name, int slices, int stacks) {
  Scene s;
  s.name = std::move(name);
  s.mesh = meshes::latLongSphere(slices, stacks, 1.0);
  for (const Triangle& t : s.mesh.triangles) {
    std::array<double, 3> u{}, v{};
    std::array<bool, 3> pole{};
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = s.mesh.positions[std::size_t(t[k])];
      pole[k] = p.x() == 0.0 && p.y() == 0.0;
      u[k] = std::atan2(p.y(), p.x()) / kTwoPi;
      if (u[k] < 0) u[k] += 1;
      v[k] = std::acos(std::clamp(p.z(), -1.0, 1.0)) / kPi;
    }
    double maxU = 0;
    for (int k = 0; k < 3; ++k)
      if (!pole[k]) maxU = std::max(maxU, u[k]);
    double sum = 0;
    int count = 0;
    for (int k = 0; k < 3; ++k)
      if (!pole[k]) {
        if (maxU - u[k] > 0.5) u[k] += 1;
        sum += u[k], ++count;
      }
    for (int k = 0; k < 3; ++k) s.corners.emplace_back(pole[k] ? sum / count : u[k], v[k], 0.0, 1.0);
  }
  s.worldFromObject =
      (Affine3(Eigen::AngleAxisd(-1.1, Vec3::UnitX())) * Eigen::AngleAxisd(0.4, Vec3::UnitZ())).matrix();
  s.camera = perspectiveCamera(Vec3(0.2, 0.3, 2.8), Vec3::Zero(), 45.0, 1.0, 10.0);
  return s;
}

// The ground y = 0 seen from just above it, the texture repeating every `period` units: lambda
// runs from below 0 in front to beyond the coarsest level at the horizon.
inline Scene groundPlane(std::string name, const Texture& texture, Filter filter, double period) {
  Scene s;
  s.name = std::move(name);
  s.mesh.positions = {Vec3(-40, 0, 2), Vec3(40, 0, 2), Vec3(40, 0, -80), Vec3(-40, 0, -80)};
  s.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  for (const Triangle& t : s.mesh.triangles)
    for (int v : t) {
      const Vec3& p = s.mesh.positions[std::size_t(v)];
      s.corners.emplace_back(p.x() / period, -p.z() / period, 0.0, 1.0);
    }
  s.worldFromObject = Affine3(Eigen::AngleAxisd(0.3, Vec3::UnitY())).matrix();
  s.camera = perspectiveCamera(Vec3(0, 0.6, 3), Vec3(0, 0.1, -5), 60.0, 0.1, 200.0);
  s.texture = &texture;
  s.filter = filter;
  return s;
}

// Replaces the scene's corners with generateTexcoords' under the scene's modelview; returns the
// options so completed, from which Mesa generates the same corners when given as Scene::texgen.
inline texgen::TexgenOptions texgenCorners(Scene& s, texgen::TexgenOptions options) {
  options.modelviewAtPlanes = options.modelviewAtDraw = s.camera.viewFromWorld * s.worldFromObject;
  const texgen::TexgenResult generated = texgen::generateTexcoords(s.mesh, options);
  EXPECT_EQ(generated.sphereMapSingular, 0u) << s.name;
  EXPECT_EQ(generated.invalidCorners, 0u) << s.name;
  s.corners.clear();
  for (std::size_t c = 0; c < generated.uv.uv.size(); ++c)
    s.corners.emplace_back(generated.uv.uv[c].x(), generated.uv.uv[c].y(), generated.uv.w[c], generated.q[c]);
  return options;
}

// An 8-bit channel as uvtk writes one (io/image_io.cpp): round(clamp(c, 0, 1) 255).
inline std::uint8_t toByte(double c) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
}

inline GLenum glFilter(Filter f) {
  switch (f) {
    case Filter::Nearest: return GL_NEAREST;
    case Filter::Linear: return GL_LINEAR;
    case Filter::NearestMipmapNearest: return GL_NEAREST_MIPMAP_NEAREST;
    case Filter::LinearMipmapNearest: return GL_LINEAR_MIPMAP_NEAREST;
    case Filter::NearestMipmapLinear: return GL_NEAREST_MIPMAP_LINEAR;
    case Filter::LinearMipmapLinear: return GL_LINEAR_MIPMAP_LINEAR;
  }
  return 0;
}

inline GLenum glWrap(Wrap w) {
  switch (w) {
    case Wrap::Repeat: return GL_REPEAT;
    case Wrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
    case Wrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
  }
  return 0;
}

inline GLenum glEnv(EnvMode m) {
  switch (m) {
    case EnvMode::Replace: return GL_REPLACE;
    case EnvMode::Modulate: return GL_MODULATE;
    case EnvMode::Decal: return GL_DECAL;
    case EnvMode::Blend: return GL_BLEND;
  }
  return 0;
}

inline GLenum glTexgenMode(texgen::TexgenMode m) {
  switch (m) {
    case texgen::TexgenMode::ObjectLinear: return GL_OBJECT_LINEAR;
    case texgen::TexgenMode::EyeLinear: return GL_EYE_LINEAR;
    case texgen::TexgenMode::SphereMap: return GL_SPHERE_MAP;
    case texgen::TexgenMode::NormalMap: return GL_NORMAL_MAP;
    case texgen::TexgenMode::ReflectionMap: return GL_REFLECTION_MAP;
    case texgen::TexgenMode::Off: break;
  }
  return 0;
}

inline std::array<GLfloat, 4> floats(const Vec4& v) {
  return {GLfloat(v[0]), GLfloat(v[1]), GLfloat(v[2]), GLfloat(v[3])};
}

// An OSMesa context on a kWidth x kHeight RGBA8 buffer with a 24-bit depth buffer.
class Mesa {
 public:
  // How llvmpipe filters 8-bit textures with REPEAT or CLAMP_TO_EDGE. Its default is its "AoS"
  // path with 8-bit fixed-point weights, as a GPU's own weights would be; Float is its float path
  // (which MIRRORED_REPEAT always takes), GL's filter to float precision. gallivm reads
  // GALLIVM_PERF once, when the first context creates the screen: a process gets one of the two.
  enum class Filtering { DriverDefault, Float };
  enum class Pass { Colour, FaceIds };

  explicit Mesa(Filtering filtering) : context_(createContext(filtering)) {
    if (!context_) return;
    OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kWidth, kHeight);
    seamlessCubeMaps_ = supportsSeamlessCubeMaps();
  }
  ~Mesa() {
    if (context_) OSMesaDestroyContext(context_);
  }
  Mesa(const Mesa&) = delete;
  Mesa& operator=(const Mesa&) = delete;

  bool ok() const { return context_ != nullptr; }
  // GL_TEXTURE_CUBE_MAP_SEAMLESS: core from GL 3.2, else ARB_seamless_cube_map.
  bool seamlessCubeMaps() const { return seamlessCubeMaps_; }

  std::string renderer() const {
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return name ? name : "?";
  }

  // RGBA, row 0 at the top like uvtk's Image (OSMesa's row 0 is the bottom). The FaceIds pass
  // draws each triangle flat in the colour face + 1 (24 bits) on black: Mesa's coverage.
  std::vector<std::uint8_t> draw(const Scene& s, Pass pass) {
    const bool colour = pass == Pass::Colour;
    glViewport(0, 0, kWidth, kHeight);
    glDisable(GL_DITHER);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearDepth(1.0);
    if (colour)
      glClearColor(GLfloat(s.background.x()), GLfloat(s.background.y()), GLfloat(s.background.z()), 1.0f);
    else
      glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glFrontFace(GL_CCW);
    enable(GL_CULL_FACE, s.cull != Cull::None);
    glCullFace(s.cull == Cull::Front ? GL_FRONT : GL_BACK);
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
    glShadeModel(colour ? GL_SMOOTH : GL_FLAT);
    glEnable(GL_NORMALIZE);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixd(s.camera.clipFromView.data());  // Eigen is column-major, as GL reads it
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    const bool lit = colour && readsFragmentColour(s.env);
    Lighting lighting;  // as uvtkOptions(s) gives it
    lighting.twoSided = s.twoSided;
    if (lit) setHeadlight(lighting);
    enable(GL_LIGHTING, lit);
    GLuint name = 0;
    if (colour) name = bindTexture(s);
    enable(GL_TEXTURE_2D, colour && !s.cubeTexture);
    enable(GL_TEXTURE_CUBE_MAP, colour && s.cubeTexture);
    if (seamlessCubeMaps_) enable(GL_TEXTURE_CUBE_MAP_SEAMLESS, colour && s.seamless);
    EXPECT_TRUE(seamlessCubeMaps_ || !s.seamless) << s.name;
    setTexgen(colour ? s.texgen : std::nullopt);

    const Mat4 modelview = s.camera.viewFromWorld * s.worldFromObject;
    glLoadMatrixd(modelview.data());
    const std::vector<Vec3> normals = cornerNormals(s.mesh);
    glTexCoord4d(0, 0, 0, 1);  // what texgen leaves in the coordinates it does not generate
    glBegin(GL_TRIANGLES);
    for (std::size_t f = 0; f < s.mesh.faceCount(); ++f) {
      const auto id = std::uint32_t(f + 1);  // the colour pass ignores it: REPLACE or lighting replaces it
      glColor4ub(GLubyte(id & 0xff), GLubyte((id >> 8) & 0xff), GLubyte((id >> 16) & 0xff), 255);
      for (int k = 0; k < 3; ++k) {
        const std::size_t c = 3 * f + std::size_t(k);
        const Vec3& p = s.mesh.positions[std::size_t(s.mesh.triangles[f][k])];
        glNormal3d(normals[c].x(), normals[c].y(), normals[c].z());
        if (!s.texgen) glTexCoord4d(s.corners[c][0], s.corners[c][1], s.corners[c][2], s.corners[c][3]);
        glVertex3d(p.x(), p.y(), p.z());
      }
    }
    glEnd();
    glFinish();
    if (name) glDeleteTextures(1, &name);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << s.name;

    std::vector<std::uint8_t> topDown(buffer_.size());
    const std::size_t rowBytes = std::size_t(kWidth) * 4;
    for (int row = 0; row < kHeight; ++row)
      std::copy_n(&buffer_[std::size_t(kHeight - 1 - row) * rowBytes], rowBytes, &topDown[std::size_t(row) * rowBytes]);
    return topDown;
  }

 private:
  static void enable(GLenum capability, bool on) { on ? glEnable(capability) : glDisable(capability); }

  static bool supportsSeamlessCubeMaps() {
    const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    int major = 0, minor = 0;
    if (version && std::sscanf(version, "%d.%d", &major, &minor) == 2 && (major > 3 || (major == 3 && minor >= 2)))
      return true;
    const auto* extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
    return extensions &&
           std::string(" ").append(extensions).append(" ").find(" GL_ARB_seamless_cube_map ") != std::string::npos;
  }

  // uvtk's head-light (render/shading.h): GL_LIGHT0 at (0, 0, 1, 0) given under the identity.
  static void setHeadlight(const Lighting& l) {
    const GLfloat position[4] = {0, 0, 1, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glLightfv(GL_LIGHT0, GL_AMBIENT, floats(l.lightAmbient).data());
    glLightfv(GL_LIGHT0, GL_DIFFUSE, floats(l.lightDiffuse).data());
    glLightfv(GL_LIGHT0, GL_SPECULAR, floats(l.lightSpecular).data());
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, floats(l.materialAmbient).data());
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, floats(l.materialDiffuse).data());
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, floats(l.materialSpecular).data());
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, GLfloat(l.shininess));
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, floats(l.modelAmbient).data());
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_FALSE);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, l.twoSided ? GL_TRUE : GL_FALSE);
    glEnable(GL_LIGHT0);
  }

  // The scene's texels as RGBA8, every mipmap level uvtk built when the filter reads them, so
  // that both sample identical levels. A cube map's six faces go to GL's six face targets in
  // uvtk's (and GL's) face order, each with its rows j = 0 first like a 2D texture.
  static GLuint bindTexture(const Scene& s) {
    const GLenum target = s.cubeTexture ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(target, name);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const int faces = s.cubeTexture ? kCubeFaceCount : 1;
    for (int f = 0; f < faces; ++f) {
      const Texture& texture = s.cubeTexture ? s.cubeTexture->face(CubeFace(f)) : *s.texture;
      const GLenum image = s.cubeTexture ? GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f) : GL_TEXTURE_2D;
      const int levels = needsMipmaps(s.filter) ? texture.levelCount() : 1;
      EXPECT_TRUE(!needsMipmaps(s.filter) || levels > 1) << s.name;
      for (int k = 0; k < levels; ++k) {
        const TexelLevel& level = texture.level(k);
        std::vector<std::uint8_t> bytes;
        for (int j = 0; j < level.height; ++j)
          for (int i = 0; i < level.width; ++i)
            for (int c = 0; c < 4; ++c) bytes.push_back(toByte(level.at(i, j)[c]));
        glTexImage2D(image, k, GL_RGBA8, level.width, level.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
      }
    }
    const SamplerState sampler = samplerFor(s.filter, s.wrap);
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GLint(glFilter(sampler.minFilter)));
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GLint(glFilter(sampler.magFilter)));
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GLint(glWrap(sampler.wrapS)));
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GLint(glWrap(sampler.wrapT)));
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GLint(glEnv(s.env)));
    return name;
  }

  // texgen::TexgenOptions as GL state; the planes given under modelviewAtPlanes.
  static void setTexgen(const std::optional<texgen::TexgenOptions>& o) {
    static constexpr GLenum kCoordinate[4] = {GL_S, GL_T, GL_R, GL_Q};
    static constexpr GLenum kEnable[4] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q};
    glMatrixMode(GL_TEXTURE);
    o ? glLoadMatrixd(o->textureMatrix.data()) : glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    if (o) glLoadMatrixd(o->modelviewAtPlanes.data());
    for (int i = 0; i < 4; ++i) {
      if (!o || o->coordinates[std::size_t(i)].mode == texgen::TexgenMode::Off) {
        glDisable(kEnable[i]);
        continue;
      }
      const texgen::TexgenCoordinate& c = o->coordinates[std::size_t(i)];
      glTexGeni(kCoordinate[i], GL_TEXTURE_GEN_MODE, GLint(glTexgenMode(c.mode)));
      glTexGendv(kCoordinate[i], GL_OBJECT_PLANE, c.plane.data());
      glTexGendv(kCoordinate[i], GL_EYE_PLANE, c.plane.data());
      glEnable(kEnable[i]);
    }
  }

  static OSMesaContext createContext(Filtering filtering) {
    if (filtering == Filtering::Float) setenv("GALLIVM_PERF", "no_aos_sampling", 1);
    return OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  }

  OSMesaContext context_;
  bool seamlessCubeMaps_ = false;
  std::vector<std::uint8_t> buffer_ = std::vector<std::uint8_t>(std::size_t(kWidth) * kHeight * 4);
};

// uvtk's options for the scene, with its AOVs.
inline RenderOptions uvtkOptions(const Scene& s) {
  RenderOptions o;
  o.camera = s.camera;
  o.worldFromObject = s.worldFromObject;
  o.raster.cull = s.cull;
  o.texture = s.texture;
  o.cubeTexture = s.cubeTexture;
  o.seamless = s.seamless;
  o.sampler = samplerFor(s.filter, s.wrap);
  o.env = s.env;
  o.lighting.twoSided = s.twoSided;
  o.background = s.background;
  o.aovs = true;
  return o;
}

inline TexcoordSource texcoords(const Scene& s) {
  TexcoordSource source;
  source.corners = s.corners;
  return source;
}

}  // namespace uvtk::render::mesa
