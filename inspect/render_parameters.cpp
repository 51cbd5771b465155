#include "inspect/render_parameters.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "core/error.h"
#include "core/gl_matrices.h"
#include "core/number_text.h"
#include "inspect/report.h"
#include "inspect/run_report.h"
#include "io/image_io.h"
#include "param/make_projector.h"

namespace uvtk::inspect {

const ChoiceNames<render::Filter> kFilterNames = {
    {"nearest", render::Filter::Nearest},
    {"linear", render::Filter::Linear},
    {"nearest_mipmap_nearest", render::Filter::NearestMipmapNearest},
    {"linear_mipmap_nearest", render::Filter::LinearMipmapNearest},
    {"nearest_mipmap_linear", render::Filter::NearestMipmapLinear},
    {"linear_mipmap_linear", render::Filter::LinearMipmapLinear}};
const ChoiceNames<render::Wrap> kWrapNames = {{"repeat", render::Wrap::Repeat},
                                              {"clamp_to_edge", render::Wrap::ClampToEdge},
                                              {"mirrored_repeat", render::Wrap::MirroredRepeat}};
const ChoiceNames<render::EnvMode> kEnvNames = {{"replace", render::EnvMode::Replace},
                                                {"modulate", render::EnvMode::Modulate},
                                                {"decal", render::EnvMode::Decal},
                                                {"blend", render::EnvMode::Blend}};
const ChoiceNames<render::Cull> kCullNames = {
    {"back", render::Cull::Back}, {"front", render::Cull::Front}, {"none", render::Cull::None}};

const ChoiceNames<UvSource> kUvNames = {
    {"per-vertex", UvSource::PerVertex}, {"per-pixel", UvSource::PerPixel}, {"baked", UvSource::Baked}};
const ChoiceNames<render::Derivatives> kDerivativeNames = {{"analytic", render::Derivatives::Analytic},
                                                           {"quad-coarse", render::Derivatives::QuadCoarse},
                                                           {"quad-fine", render::Derivatives::QuadFine}};
const ChoiceNames<render::SeamFix> kSeamFixNames = {
    {"none", render::SeamFix::None}, {"grad", render::SeamFix::Grad}, {"tarini", render::SeamFix::Tarini}};
const ChoiceNames<views::View> kLayoutFillNames = {{"stretch", views::View::Stretch},
                                                   {"linf", views::View::Linf},
                                                   {"angle", views::View::Angle},
                                                   {"area", views::View::Area},
                                                   {"density", views::View::Density}};

namespace {

constexpr std::pair<int, int> kAnyInt = {std::numeric_limits<int>::min(), std::numeric_limits<int>::max()};
const ChoiceNames<bool> kCameraModeNames = {{"auto", false}, {"explicit", true}};

// The AOV channels the names ask for ("uv" is u and v), by their names in Rendering::aovs.
std::vector<std::string> aovChannels(const std::vector<std::string>& names, const std::string& spelled) {
  std::vector<std::string> channels;
  for (const std::string& name : names) {
    if (name == "uv") {
      channels.push_back("u"), channels.push_back("v");
    } else if (name == "depth" || name == "face" || name == "lod" || name == "cubeface") {
      channels.push_back(name);
    } else {
      throw UsageError(spelled + ": expected a list of uv, depth, face, lod, cubeface, found '" + name + "'");
    }
  }
  return channels;
}

}  // namespace

render::Camera CameraSettings::make(const Mesh& mesh, const std::string& meshFile, const Mat4& worldFromObject,
                                    int width, int height) const {
  const Vec3 direction = eye ? Vec3(*eye - center) : viewDir;
  // Not given: z up along a view direction (report's camera), y up with an eye (gluLookAt's) or when
  // looking within 18 degrees of the z axis, where z would point almost out of the picture.
  const bool zUp = !eye && std::fabs(direction.normalized().z()) < 0.95;
  const Vec3 upDir = up ? *up : zUp ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
  if (!explicitCamera()) {
    std::vector<Vec3> world(mesh.positions.size());
    for (std::size_t v = 0; v < world.size(); ++v)
      world[v] = (worldFromObject * mesh.positions[v].homogeneous()).head<3>();
    return render::frameSphere(render::boundingSphere(world), direction, upDir, {orthoAuto, fovy}, width, height,
                               meshFile);
  }
  render::Camera camera;
  camera.width = width;
  camera.height = height;
  camera.viewFromWorld = lookAt(*eye, center, upDir);
  const double n = zNear.value_or(0.1), f = zFar.value_or(100.0);
  if (orthoBox) {
    const Vec4& box = *orthoBox;
    camera.clipFromView = uvtk::orthographic(box[0], box[1], box[2], box[3], n, f);
  } else {
    camera.clipFromView = perspective(fovy, double(width) / double(height), n, f);
  }
  return camera;
}

CameraSettings readCameraSettings(const param::ParameterDictionary& p) {
  CameraSettings c;
  if (p.given("camera")) c.explicitMode = p.getChoice("camera", kCameraModeNames, false);
  c.eye = p.getVector<3>("eye");
  c.center = p.getVector<3>("center").value_or(c.center);
  c.up = p.getVector<3>("up");
  c.viewDir = p.getVector<3>("view-dir").value_or(c.viewDir);
  c.fovy = p.getNumber("fovy", c.fovy);
  if (p.given("near")) c.zNear = p.getNumber("near", 0.1);
  if (p.given("far")) c.zFar = p.getNumber("far", 100.0);
  if (p.givenAsText("ortho")) {
    const std::string ortho = *p.getText("ortho");
    if (ortho == "auto") c.orthoAuto = true;
    else c.orthoBox = parseNumbers(ortho, 4, p.spelled("ortho"));
  } else {
    c.orthoBox = p.getVector<4>("ortho");
  }
  const bool manual = c.explicitCamera();
  if (manual && !c.eye) throw UsageError(p.spelledWith("camera", "explicit") + ": expected " + p.spelled("eye") + " x,y,z");
  if (manual && c.orthoAuto) throw UsageError(p.spelledWith("ortho", "auto") + " goes with the automatic camera");
  if (!manual && (c.zNear || c.zFar))
    throw UsageError(p.spelled("near") + " and " + p.spelled("far") + " go with an explicit camera (" + p.spelled("eye") + ")");
  return c;
}

std::vector<std::string> cameraParameterNames() {
  return {"camera", "eye", "center", "up", "view-dir", "fovy", "near", "far", "ortho"};
}

bool TextureSettings::cubeMap() const { return isCubeMapSource(source); }

std::vector<std::string> TextureSettings::files() const { return textureFiles(source); }

void TextureSettings::resolveFiles(const std::function<std::string(const std::string&)>& resolve) {
  source = resolveTextureFiles(source, resolve);
}

render::Wrap TextureSettings::wrapMode() const {
  // GL's default REPEAT would filter a cube face's edge with its opposite edge.
  return wrap.value_or(cubeMap() ? render::Wrap::ClampToEdge : render::Wrap::Repeat);
}

BoundTexture TextureSettings::load() const { return loadTexture(source, filter); }

TextureOptions TextureSettings::options() const {
  TextureOptions o;
  o.filter = filter;
  o.wrap = wrapMode();
  o.env = env;
  o.envColour = envColour;
  o.seamless = seamless;
  o.twoSided = twoSided;
  return o;
}

TextureSettings readTextureSettings(const param::ParameterDictionary& p, const std::string& sourceName) {
  TextureSettings t;
  t.source = p.getText(sourceName).value_or(t.source);
  t.filter = p.getChoice("filter", kFilterNames, t.filter);
  if (p.given("wrap")) t.wrap = p.getChoice("wrap", kWrapNames, render::Wrap::Repeat);
  t.env = p.getChoice("env", kEnvNames, t.env);
  t.envColour = p.getVector<4>("env-color").value_or(t.envColour);
  t.seamless = p.getBool("seamless", t.seamless);
  t.twoSided = p.getBool("two-sided", t.twoSided);
  t.files();  // a malformed source
  if (t.seamless && !t.cubeMap())
    throw UsageError(p.spelled("seamless") + " filters cube maps across their edges: '" + t.source + "' is 2D");
  return t;
}

std::vector<std::string> textureParameterNames(const std::string& sourceName) {
  return {sourceName, "filter", "wrap", "env", "env-color", "seamless", "two-sided"};
}

FrameSettings readFrameSceneSettings(const param::ParameterDictionary& p) {
  FrameSettings s;
  FrameOptions& f = s.frame;
  std::tie(f.width, f.height) = readImageSize(p, "size", {f.width, f.height});
  f.cull = p.getChoice("cull", kCullNames, f.cull);
  f.background = p.getVector<3>("background").value_or(f.background);
  s.uvGiven = p.given("uv");
  const UvSource uv = p.getChoice("uv", kUvNames, UvSource::PerVertex);
  f.perPixel = uv == UvSource::PerPixel;
  f.baked = uv == UvSource::Baked;
  f.derivatives = p.getChoice("derivatives", kDerivativeNames, f.derivatives);
  f.seamFix = p.getChoice("seam-fix", kSeamFixNames, f.seamFix);
  return s;
}

FrameSettings readFrameSettings(const param::ParameterDictionary& p) {
  FrameSettings s = readFrameSceneSettings(p);
  FrameOptions& f = s.frame;
  f.threads = p.getInteger("threads", f.threads, 0, 1024);
  // The renderer checks the count (a square from 1 to 256) and names it.
  f.samplesPerPixel = p.getInteger("spp", f.samplesPerPixel, kAnyInt.first, kAnyInt.second);
  if (p.given("aov")) f.aovs = aovChannels(p.getTexts("aov"), p.spelled("aov"));
  s.aovOutput = p.getText("aov-output").value_or("");
  if (p.given("view")) {
    std::string list;
    for (const std::string& name : p.getTexts("view")) list += (list.empty() ? "" : ",") + name;
    if (!list.empty()) f.views = views::parseViewList(list, p.spelled("view"));  // "": the textured picture
  }
  if (!f.views.empty() && !f.aovs.empty())
    throw UsageError(p.spelled("view") + " and " + p.spelled("aov") + " exclude each other");
  f.layoutFill = p.getChoice("layout-fill", kLayoutFillNames, f.layoutFill);
  if (p.given("layout-size")) {
    f.layoutSize = p.getInteger("layout-size", f.layoutSize, kAnyInt.first, kAnyInt.second);
    if (f.layoutSize < 16 || f.layoutSize > 16384) throw UsageError(p.spelled("layout-size") + ": expected 16 to 16384 pixels");
  }
  if (p.given("bleed-level"))
    f.bleedLevel = p.getInteger("bleed-level", 0, kAnyInt.first, kAnyInt.second);
  if (p.given("checks")) {
    f.checks = p.getInteger("checks", f.checks, kAnyInt.first, kAnyInt.second);
    if (f.checks < 1 || f.checks > 1024)
      throw UsageError(p.spelled("checks") + ": expected 1 to 1024 checks, got " + std::to_string(f.checks));
  }
  if (const std::optional<std::array<int, 2>> size = param::readTextureSize(p))
    s.densityTexture = {(*size)[0], (*size)[1]};
  return s;
}

std::vector<std::string> frameSceneParameterNames() {
  return {"size", "cull", "background", "uv", "derivatives", "seam-fix"};
}

std::vector<std::string> frameParameterNames() {
  std::vector<std::string> names = frameSceneParameterNames();
  names.insert(names.end(), {"threads", "spp", "aov", "aov-output", "view", "layout-fill", "layout-size",
                             "bleed-level", "checks", "texture-size"});
  return names;
}

void checkFrameOutputs(FrameSettings& s, const std::string& output) {
  if (s.frame.aovs.empty()) return io::checkImageType(output, io::PixelType::UInt8);
  if (s.aovOutput.empty()) s.aovOutput = std::filesystem::path(output).replace_extension(".exr").string();
  if (s.aovOutput == output) throw UsageError("--aov-output must differ from --output");
  io::checkImageType(output, io::PixelType::UInt8);
  io::checkImageType(s.aovOutput, io::PixelType::Float);
}

void checkTextureUse(const FrameOptions& frame, const TextureSettings& texture,
                     const param::ProjectorOptions* projector) {
  const bool cube = texture.cubeMap();
  if (cube && projector && !writesCubeFaceIds(*projector))
    throw UsageError(
        "a cube-map texture needs directions: --texgen, a file's vt, or --projector cube --cube-layout faces; for "
        "an atlas layout give the layout image as a 2D texture");
  if (!cube && std::find(frame.aovs.begin(), frame.aovs.end(), "cubeface") != frame.aovs.end())
    throw UsageError("--aov cubeface: the texture '" + texture.source + "' is 2D, not a cube map");
}

}  // namespace uvtk::inspect
