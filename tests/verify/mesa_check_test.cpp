// The screenshot check is neither fussy nor blind. Fussy: Mesa's own images (OSMesa, a real
// OpenGL with its own rasterizer, fixed-point weights, per-quad level of detail and approximate
// log2) of scenes with every filter, projector, texgen and projective coordinates pass with no
// invalid pixel at the default precisions, on llvmpipe (default, with its 8-bit "AoS" filtering
// left on, as a GPU's own weights would be) and on softpipe (the same tests in a child process
// with GALLIUM_DRIVER=softpipe: Mesa picks its driver once per process). Blind: every fault that
// a shader or a pipeline commonly makes, drawn by uvtk's renderer with changed inputs, is caught.
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "core/gl_matrices.h"
#include "meshes/generators.h"
#include "render/procedural.h"
#include "render/renderer.h"
#include "texgen/texgen.h"
#include "verify/image_check.h"

namespace uvtk::verify {
namespace {

using render::Filter;
using render::Wrap;

constexpr int kWidth = 128, kHeight = 96;

struct Scene {
  std::string name;
  Mesh mesh;
  std::vector<Vec4> corners;  // (s, t, r, q) per corner
  render::Camera camera;
  Mat4 worldFromObject = Mat4::Identity();
  const render::Texture* texture = nullptr;
  Filter filter = Filter::Nearest;
  Wrap wrap = Wrap::Repeat;
  Vec3 background = Vec3(40, 90, 160) / 255.0;  // 8-bit values: both clear to the same bytes
};

render::Camera perspectiveCamera(const Vec3& eye, const Vec3& centre, double fovy, double zNear, double zFar) {
  render::Camera c;
  c.width = kWidth, c.height = kHeight;
  c.viewFromWorld = lookAt(eye, centre, Vec3::UnitY());
  c.clipFromView = perspective(fovy, double(kWidth) / kHeight, zNear, zFar);
  return c;
}

// Every texel a distinct colour with large steps between neighbours: a texel off by one or half
// a texel shows.
render::Texture rampTexture(int size) {
  render::TexelLevel level{size, size, {}};
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i)
      level.texels.push_back(
          render::Rgba(float((i * 97) % 256), float((j * 57) % 256), float(((i + j) * 151 + 37) % 256), 255.0f) / 255.0f);
  render::Texture texture(level, true);
  texture.buildMipmaps();
  return texture;
}

// The square [-1, 1]^2 tilted away from the camera, (s, t) from lo to hi along x and y.
Scene tiltedQuad(std::string name, const render::Texture& texture, Filter filter, Wrap wrap, double lo, double hi) {
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

// The ground y = 0 from just above it: lambda from below 0 in front to the coarsest level far off.
Scene groundPlane(std::string name, const render::Texture& texture, Filter filter) {
  Scene s;
  s.name = std::move(name);
  s.mesh.positions = {Vec3(-40, 0, 2), Vec3(40, 0, 2), Vec3(40, 0, -80), Vec3(-40, 0, -80)};
  s.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  for (const Triangle& t : s.mesh.triangles)
    for (int v : t) {
      const Vec3& p = s.mesh.positions[std::size_t(v)];
      s.corners.emplace_back(p.x() / 8, -p.z() / 8, 0.0, 1.0);
    }
  s.worldFromObject = Affine3(Eigen::AngleAxisd(0.3, Vec3::UnitY())).matrix();
  s.camera = perspectiveCamera(Vec3(0, 0.6, 3), Vec3(0, 0.1, -5), 60.0, 0.1, 200.0);
  s.texture = &texture;
  s.filter = filter;
  return s;
}

// A latitude-longitude sphere under the sphere projector: u = atan2(y, x) / 2 pi continuous
// within each triangle (a pole corner takes its neighbours' mean), v = acos(z) / pi.
Scene projectorSphere(std::string name, const render::Texture& texture, Filter filter) {
  Scene s;
  s.name = std::move(name);
  s.mesh = meshes::latLongSphere(24, 12, 1.0);
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
    double maxU = 0, sum = 0;
    int count = 0;
    for (int k = 0; k < 3; ++k)
      if (!pole[k]) maxU = std::max(maxU, u[k]);
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
  s.texture = &texture;
  s.filter = filter;
  return s;
}

// The sphere with OBJECT_LINEAR texgen: s = (x + 1) / 2, t = (y + 1) / 2 and, projective,
// q = 1.2 + 0.4 z (0.8 to 1.6 over the sphere) when `projective`.
Scene texgenSphere(std::string name, const render::Texture& texture, Filter filter, bool projective) {
  Scene s = projectorSphere(std::move(name), texture, filter);
  texgen::TexgenOptions options;
  options.coordinates[0] = {texgen::TexgenMode::ObjectLinear, Vec4(0.5, 0, 0, 0.5)};
  options.coordinates[1] = {texgen::TexgenMode::ObjectLinear, Vec4(0, 0.5, 0, 0.5)};
  if (projective) options.coordinates[3] = {texgen::TexgenMode::ObjectLinear, Vec4(0, 0, 0.4, 1.2)};
  options.modelviewAtPlanes = options.modelviewAtDraw = s.camera.viewFromWorld * s.worldFromObject;
  const texgen::TexgenResult generated = texgen::generateTexcoords(s.mesh, options);
  s.corners.clear();
  for (std::size_t c = 0; c < generated.uv.uv.size(); ++c)
    s.corners.emplace_back(generated.uv.uv[c].x(), generated.uv.uv[c].y(), generated.uv.w[c], generated.q[c]);
  return s;
}

// The tilted quad with q = 0.5 to 2 at its corners: (s q, t q, 0, q) for the quad's (s, t).
Scene projectiveQuad(std::string name, const render::Texture& texture, Filter filter) {
  Scene s = tiltedQuad(std::move(name), texture, filter, Wrap::Repeat, 0.0, 1.0);
  for (std::size_t c = 0; c < s.corners.size(); ++c) {
    const Vec3& p = s.mesh.positions[std::size_t(s.mesh.triangles[c / 3][int(c % 3)])];
    const double q = 0.5 + 0.75 * (p.x() + 1) * (p.y() + 2) / 3;
    s.corners[c] = Vec4(s.corners[c][0] * q, s.corners[c][1] * q, 0.0, q);
  }
  return s;
}

bool isProjective(const Scene& s) {
  return std::any_of(s.corners.begin(), s.corners.end(), [&](const Vec4& c) { return c[3] != s.corners[0][3]; });
}

std::uint8_t toByte(double c) { return toUInt8(float(c)); }

GLenum glFilter(Filter f) {
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

GLenum glWrap(Wrap w) {
  switch (w) {
    case Wrap::Repeat: return GL_REPEAT;
    case Wrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
    case Wrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
  }
  return 0;
}

// One OSMesa context (RGBA8, 24-bit depth) for the process; Mesa draws the scene as uvtk does:
// the same matrices, texels (every mipmap level uvtk built), sampler, REPLACE, back faces culled.
class Mesa {
 public:
  Mesa() : context_(OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr)) {
    if (context_) OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kWidth, kHeight);
  }
  ~Mesa() {
    if (context_) OSMesaDestroyContext(context_);
  }
  Mesa(const Mesa&) = delete;
  Mesa& operator=(const Mesa&) = delete;

  bool ok() const { return context_ != nullptr; }
  std::string renderer() const {
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return name ? name : "?";
  }

  // RGB in [0, 1] as an 8-bit PNG would hold it, row 0 at the top.
  Image draw(const Scene& s) {
    glViewport(0, 0, kWidth, kHeight);
    glDisable(GL_DITHER);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearDepth(1.0);
    glClearColor(GLfloat(s.background.x()), GLfloat(s.background.y()), GLfloat(s.background.z()), 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glFrontFace(GL_CCW);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixd(s.camera.clipFromView.data());  // Eigen is column-major, as GL reads it
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    const Mat4 modelview = s.camera.viewFromWorld * s.worldFromObject;
    glLoadMatrixd(modelview.data());
    const GLuint name = bindTexture(s);
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_TRIANGLES);
    for (std::size_t f = 0; f < s.mesh.faceCount(); ++f)
      for (int k = 0; k < 3; ++k) {
        const Vec4& c = s.corners[3 * f + std::size_t(k)];
        const Vec3& p = s.mesh.positions[std::size_t(s.mesh.triangles[f][k])];
        glTexCoord4d(c[0], c[1], c[2], c[3]);
        glVertex3d(p.x(), p.y(), p.z());
      }
    glEnd();
    glFinish();
    glDeleteTextures(1, &name);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << s.name;
    Image shot(kWidth, kHeight, 3);
    for (int row = 0; row < kHeight; ++row)
      for (int x = 0; x < kWidth; ++x)
        for (int c = 0; c < 3; ++c)  // OSMesa's row 0 is the bottom
          shot.at(x, row, c) = float(buffer_[(std::size_t(kHeight - 1 - row) * kWidth + std::size_t(x)) * 4 + std::size_t(c)]) / 255.0f;
    return shot;
  }

 private:
  static GLuint bindTexture(const Scene& s) {
    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const int levels = render::needsMipmaps(s.filter) ? s.texture->levelCount() : 1;
    for (int k = 0; k < levels; ++k) {
      const render::TexelLevel& level = s.texture->level(k);
      std::vector<std::uint8_t> bytes;
      for (const render::Rgba& texel : level.texels)
        for (int c = 0; c < 4; ++c) bytes.push_back(toByte(texel[c]));
      glTexImage2D(GL_TEXTURE_2D, k, GL_RGBA8, level.width, level.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels - 1);
    const render::SamplerState sampler = render::samplerFor(s.filter, s.wrap);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GLint(glFilter(sampler.minFilter)));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GLint(glFilter(sampler.magFilter)));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GLint(glWrap(sampler.wrapS)));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GLint(glWrap(sampler.wrapT)));
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    return name;
  }

  OSMesaContext context_;
  std::vector<std::uint8_t> buffer_ = std::vector<std::uint8_t>(std::size_t(kWidth) * kHeight * 4);
};

Mesa& mesa() {
  static Mesa instance;
  return instance;
}

render::RenderOptions optionsFor(const Scene& s) {
  render::RenderOptions o;
  o.camera = s.camera;
  o.worldFromObject = s.worldFromObject;
  o.texture = s.texture;
  o.sampler = render::samplerFor(s.filter, s.wrap);
  o.background = s.background;
  o.aovs = true;
  return o;
}

render::TexcoordSource texcoords(const Scene& s) {
  render::TexcoordSource source;
  source.corners = s.corners;
  return source;
}

// uvtk's colour as the 8-bit PNG `uvtk render` writes.
Image asEightBit(const Image& colour) {
  Image out = colour;
  for (float& c : out.pixels) c = float(toUInt8(c)) / 255.0f;
  return out;
}

std::size_t covered(const render::Rendering& r) {
  std::size_t n = 0;
  for (int row = 0; row < r.aovs.height; ++row)
    for (int x = 0; x < r.aovs.width; ++x) n += r.aovs.at(x, row, 3) >= 0;
  return n;
}

std::string describe(const ImageCheckResult& r) {
  std::string text = std::to_string(r.invalid) + " invalid of " + std::to_string(r.checked);
  for (const InvalidPixel& p : r.firstInvalid) {
    char line[200];
    std::snprintf(line, sizeof line, "\n  (%d, %d) shot %.4f %.4f %.4f valid [%.4f %.4f %.4f] .. [%.4f %.4f %.4f]", p.x,
                  p.row, p.shot.x(), p.shot.y(), p.shot.z(), p.low.x(), p.low.y(), p.low.z(), p.high.x(), p.high.y(),
                  p.high.z());
    text += line;
  }
  return text;
}

// The scenes Mesa draws; the textures live as long as the process.
std::vector<Scene> mesaScenes() {
  static const render::Texture ramp16 = rampTexture(16), ramp64 = rampTexture(64);
  std::vector<Scene> scenes;
  for (Filter f : {Filter::Nearest, Filter::Linear})
    for (Wrap w : {Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat})
      scenes.push_back(tiltedQuad("quad ramp16", ramp16, f, w, -0.4, 1.6));
  for (Filter f : {Filter::NearestMipmapNearest, Filter::LinearMipmapNearest, Filter::NearestMipmapLinear,
                   Filter::LinearMipmapLinear}) {
    scenes.push_back(groundPlane("ground ramp64", ramp64, f));
    scenes.push_back(tiltedQuad("quad ramp64", ramp64, f, Wrap::Repeat, 0.0, 3.0));
  }
  for (Filter f : {Filter::Nearest, Filter::Linear, Filter::LinearMipmapLinear}) {
    scenes.push_back(projectorSphere("projector sphere ramp16", ramp16, f));
    scenes.push_back(texgenSphere("texgen object_linear sphere ramp16", ramp16, f, false));
    scenes.push_back(texgenSphere("texgen projective sphere ramp16", ramp16, f, true));
    scenes.push_back(projectiveQuad("projective quad ramp16", ramp16, f));
  }
  for (Scene& s : scenes) {
    static const char* const kFilters[] = {"nearest", "linear", "nearest_mipmap_nearest", "linear_mipmap_nearest",
                                           "nearest_mipmap_linear", "linear_mipmap_linear"};
    static const char* const kWraps[] = {"repeat", "clamp", "mirror"};
    s.name += std::string(" ") + kFilters[int(s.filter)] + " " + kWraps[int(s.wrap)];
  }
  return scenes;
}

TEST(MesaCheck, MesasImagesPassWithNoInvalidPixel) {
  Mesa& gl = mesa();
  ASSERT_TRUE(gl.ok());
  std::cout << "[mesa-check] renderer: " << gl.renderer() << "\n";
  for (const Scene& s : mesaScenes()) {
    const render::RenderOptions o = optionsFor(s);
    const Reference reference = drawReference(s.mesh, texcoords(s), o);
    EXPECT_GE(covered(reference.analytic), std::size_t(kWidth * kHeight / 8)) << s.name;
    const ImageCheckResult result = checkImage(gl.draw(s), reference, o, isProjective(s));
    EXPECT_EQ(result.invalid, 0u) << s.name << " on " << gl.renderer() << ": " << describe(result);
    // uvtk's own picture passes too.
    EXPECT_EQ(checkImage(asEightBit(reference.analytic.colour), reference, o, isProjective(s)).invalid, 0u) << s.name;
  }
}

TEST(MesaCheck, SoftpipesImagesPassToo) {
  if (std::getenv("UVTK_MESA_CHECK_CHILD")) GTEST_SKIP() << "the child itself";
  std::array<char, 4096> self{};
  const ssize_t length = readlink("/proc/self/exe", self.data(), self.size() - 1);
  ASSERT_GT(length, 0);
  const std::string command = "GALLIUM_DRIVER=softpipe UVTK_MESA_CHECK_CHILD=1 '" + std::string(self.data()) +
                              "' --gtest_filter=MesaCheck.MesasImagesPassWithNoInvalidPixel 2>&1";
  FILE* child = popen(command.c_str(), "r");
  ASSERT_NE(child, nullptr);
  std::string output;
  std::array<char, 4096> chunk{};
  while (const std::size_t n = std::fread(chunk.data(), 1, chunk.size(), child)) output.append(chunk.data(), n);
  const int status = pclose(child);
  if (output.find("renderer: softpipe") == std::string::npos)
    GTEST_SKIP() << "GALLIUM_DRIVER=softpipe did not select softpipe:\n" << output;
  EXPECT_EQ(status, 0) << output;
  EXPECT_NE(output.find("[  PASSED  ] 1 test"), std::string::npos) << output;
}

// A fault: the reference scene and the options of its picture, drawn by uvtk with a changed input.
struct Fault {
  std::string name;
  Scene reference;
  Scene faulty;
  render::RenderOptions faultyOptions;
  std::size_t atLeast;  // invalid pixels the check must find
};

ImageCheckResult checkFault(const Fault& f) {
  const render::RenderOptions o = optionsFor(f.reference);
  const Reference reference = drawReference(f.reference.mesh, texcoords(f.reference), o);
  EXPECT_EQ(checkImage(asEightBit(reference.analytic.colour), reference, o, isProjective(f.reference)).invalid, 0u)
      << f.name;
  const Image shot = asEightBit(render::render(f.faulty.mesh, texcoords(f.faulty), f.faultyOptions).colour);
  return checkImage(shot, reference, o, isProjective(f.reference));
}

std::vector<Fault> faults() {
  static const render::Texture ramp16 = rampTexture(16), ramp64 = rampTexture(64);
  std::vector<Fault> out;
  const auto add = [&](std::string name, const Scene& reference, Scene faulty, std::size_t atLeast,
                       const std::function<void(render::RenderOptions&)>& change = {}) {
    render::RenderOptions o = optionsFor(faulty);
    if (change) change(o);
    out.push_back({std::move(name), reference, std::move(faulty), o, atLeast});
  };
  const auto mapCorners = [](Scene s, const std::function<Vec4(const Vec4&)>& f) {
    for (Vec4& c : s.corners) c = f(c);
    return s;
  };
  for (Filter filter : {Filter::LinearMipmapLinear, Filter::NearestMipmapNearest}) {
    const Scene ground = groundPlane("ground", ramp64, filter);
    add("lod + 1", ground, ground, 500, [](render::RenderOptions& o) { o.lodBias = 1.0; });
  }
  for (Filter filter : {Filter::Nearest, Filter::Linear}) {
    const Scene quad = tiltedQuad("quad", ramp16, filter, Wrap::Repeat, -0.4, 1.6);
    add("half-texel shift", quad, mapCorners(quad, [](const Vec4& c) { return Vec4(c[0] + 0.5 / 16, c[1], c[2], c[3]); }),
        500);
    Scene clamped = quad;
    clamped.wrap = Wrap::ClampToEdge;
    add("repeat for clamp", clamped, quad, 500);
    add("clamp for repeat", quad, clamped, 500);
    const Scene sphere = projectorSphere("sphere", ramp16, filter);
    add("v flipped", sphere, mapCorners(sphere, [](const Vec4& c) { return Vec4(c[0], 1 - c[1], c[2], c[3]); }), 500);
    add("s and t swapped", sphere, mapCorners(sphere, [](const Vec4& c) { return Vec4(c[1], c[0], c[2], c[3]); }), 500);
    const Scene projective = projectiveQuad("projective quad", ramp16, filter);
    add("q dropped", projective, mapCorners(projective, [](const Vec4& c) { return Vec4(c[0], c[1], c[2], 1.0); }),
        500);
  }
  return out;
}

TEST(MesaCheck, EveryInjectedFaultIsCaught) {
  for (const Fault& f : faults()) {
    const ImageCheckResult result = checkFault(f);
    std::cout << "[mesa-check] " << f.name << " (" << f.reference.name << ", filter " << int(f.reference.filter)
              << "): " << result.invalid << " invalid\n";
    EXPECT_GE(result.invalid, f.atLeast) << f.name << " " << f.reference.name;
    EXPECT_FALSE(result.pass) << f.name;
  }
}

// The seam line: a per-pixel atan2 (sphere) mapping looked up with a GPU's quad derivatives
// jumps by about 1 in s across the seam, so the coarsest level shows in a thin line there. The
// reference (analytic derivatives) has no line; the check finds the line and nothing else.
TEST(MesaCheck, SeamLineOfPerPixelSphereMappingIsCaught) {
  static const render::Texture ramp64 = rampTexture(64);
  Scene s = projectorSphere("per-pixel sphere", ramp64, Filter::LinearMipmapLinear);
  s.worldFromObject = Affine3(Eigen::AngleAxisd(-kPi / 2, Vec3::UnitX())).matrix();  // the seam faces the camera
  s.camera = perspectiveCamera(Vec3(2.6, 0, 0.3), Vec3::Zero(), 45.0, 1.0, 10.0);
  render::TexcoordSource source;
  render::PixelMapping mapping;
  mapping.texcoordAt = [](const Vec3& p, const Vec3&, std::int32_t) {
    double u = std::atan2(p.y(), p.x()) / kTwoPi;
    if (u < 0) u += 1;
    return Vec4(u, std::acos(std::clamp(p.z() / p.norm(), -1.0, 1.0)) / kPi, 0.0, 1.0);
  };
  mapping.wrapsS = true;
  source.pixelMapping = mapping;
  render::RenderOptions o = optionsFor(s);
  const Reference reference = drawReference(s.mesh, source, o);
  EXPECT_EQ(checkImage(asEightBit(reference.analytic.colour), reference, o, false).invalid, 0u);
  for (render::Derivatives d : {render::Derivatives::QuadCoarse, render::Derivatives::QuadFine}) {
    render::RenderOptions gpu = o;
    gpu.derivatives = d;
    const ImageCheckResult result = checkImage(asEightBit(render::render(s.mesh, source, gpu).colour), reference, o, false);
    std::cout << "[mesa-check] seam line (derivatives " << int(d) << "): " << result.invalid << " invalid\n";
    EXPECT_GE(result.invalid, 20u) << describe(result);
    // The line is a line: each invalid pixel lies near the seam, u within a few texels of 0 or 1.
    for (int row = 0; row < kHeight; ++row)
      for (int x = 0; x < kWidth; ++x)
        if (result.errorMask.at(x, row, 0) == 1.0f && result.errorMask.at(x, row, 1) == 0.0f) {
          const double u = reference.analytic.aovs.at(x, row, 0);
          EXPECT_LT(std::min(u, 1 - u), 0.05) << x << ", " << row;
        }
  }
}

}  // namespace
}  // namespace uvtk::verify
