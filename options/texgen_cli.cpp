#include "options/texgen_cli.h"

#include <utility>
#include <vector>

#include "options/arithmetic_cli.h"
#include "options/cli_values.h"
#include "inspect/projector_json.h"
#include "param/projector_names.h"
#include "core/error.h"

namespace uvtk::cli {

namespace {

using texgen::TexgenMode;

const char* const kCoordinateOptions[4] = {"--s", "--t", "--r", "--q"};

// "MODE" or "MODE:a,b,c,d" for the coordinate option `option`.
texgen::TexgenCoordinate parseCoordinate(const std::string& text, const std::string& option,
                                         const texgen::TexgenCoordinate& defaults) {
  const std::size_t colon = text.find(':');
  const std::string name = text.substr(0, colon);
  texgen::TexgenCoordinate c = defaults;
  bool known = false;
  for (const auto& [modeText, value] : texgen::kTexgenModeNames)
    if (name == modeText) {
      c.mode = value;
      known = true;
    }
  if (!known)
    throw UsageError(option + ": expected object_linear|eye_linear|sphere_map|normal_map|reflection_map|off, found '" +
                     name + "'");
  if (colon != std::string::npos) c.plane = parseVec4(text.substr(colon + 1), option);
  return c;
}

}  // namespace

bool TexgenArguments::given() const {
  if (!mode.empty()) return true;
  for (const std::string& c : coordinates)
    if (!c.empty()) return true;
  return false;
}

texgen::TexgenOptions TexgenArguments::resolve(const Mat4& view, const Mat4& model) const {
  texgen::TexgenOptions o;
  const std::array<texgen::TexgenCoordinate, 4> defaults = texgen::defaultCoordinates();
  if (!mode.empty()) {
    const texgen::TexgenCoordinate shortcut = parseCoordinate(mode, shortcutOption, {});
    const bool linear = shortcut.mode == TexgenMode::ObjectLinear || shortcut.mode == TexgenMode::EyeLinear;
    if (shortcut.mode == TexgenMode::Off || (linear && shortcutOption == "--mode"))
      throw UsageError(shortcutOption + ": expected " +
                       (shortcutOption == "--mode" ? "" : "object_linear|eye_linear|") +
                       "sphere_map|normal_map|reflection_map, found '" + mode + "'");
    const int count = shortcut.mode == TexgenMode::NormalMap || shortcut.mode == TexgenMode::ReflectionMap ? 3 : 2;
    for (int i = 0; i < count; ++i) o.coordinates[std::size_t(i)].mode = shortcut.mode;
  }
  bool any = !mode.empty();
  for (std::size_t i = 0; i < 4; ++i)
    if (!coordinates[i].empty()) {  // an explicit coordinate option overrides the shortcut
      o.coordinates[i] = parseCoordinate(coordinates[i], kCoordinateOptions[i], defaults[i]);
      any = true;
    }
  if (!any) o.coordinates[0].mode = o.coordinates[1].mode = TexgenMode::ObjectLinear;
  for (std::size_t i = 0; i < 4; ++i) {
    const TexgenMode m = o.coordinates[i].mode;
    if ((m == TexgenMode::SphereMap && i >= 2) ||
        ((m == TexgenMode::NormalMap || m == TexgenMode::ReflectionMap) && i == 3))
      throw UsageError(std::string(kCoordinateOptions[i]) + ": " + texgen::texgenModeName(m) +
                       " is not allowed on this coordinate (sphere_map: s, t only; normal_map, reflection_map: "
                       "s, t, r only)");
  }
  o.modelviewAtPlanes = view;  // planes are given under the view alone: they act in world space
  o.modelviewAtDraw = view * model;
  if (!textureMatrix.empty()) o.textureMatrix = parseMatrix(textureMatrix, "--texmatrix");
  o.normalize = !noNormalize;
  o.precision = arithmetic.precision;
  return o;
}

void addTexgenOptions(CLI::App& app, TexgenArguments& a, const std::string& shortcut) {
  a.shortcutOption = shortcut;
  const std::string modes = "MODE[:a,b,c,d]";
  const char* const planeHelp =
      ": object_linear|eye_linear|sphere_map|normal_map|reflection_map|off, optionally with the plane "
      "(GL default plane otherwise: s 1,0,0,0, t 0,1,0,0, r and q 0,0,0,0). Default: off, except s and t "
      "object_linear when no coordinate option and no shortcut is given";
  for (std::size_t i = 0; i < 4; ++i)
    app.add_option(kCoordinateOptions[i], a.coordinates[i],
                   std::string("Generation of ") + (kCoordinateOptions[i] + 2) + (i == 0 ? planeHelp : ", as --s"))
        ->type_name(modes);
  if (shortcut == "--mode") addArithmeticOptions(app, a.arithmetic, false);
  if (shortcut == "--mode")
    app.add_option("--mode", a.mode,
                   "Shortcut: s, t (and r for normal_map, reflection_map) in this mode; --s/--t/--r override it")
        ->type_name("sphere_map|normal_map|reflection_map");
  else
    app.add_option(shortcut, a.mode,
                   "Texture coordinates by GL texgen: s, t (and r for normal_map, reflection_map) in this mode "
                   "with GL's default planes, under the camera's view; --s/--t/--r/--q override it")
        ->type_name("object_linear|eye_linear|sphere_map|normal_map|reflection_map");
  app.add_option("--texmatrix", a.textureMatrix,
                 "Texture matrix applied to (s,t,r,q), 16 numbers column-major (default identity); q is kept, not divided");
  app.add_flag("--no-normalize", a.noNormalize,
               "Do not renormalise the eye normal after the inverse transpose (GL's default state; "
               "by default it is renormalised, as with GL_NORMALIZE)");
}

void addTexgenViewOptions(CLI::App& app, std::string& eye, std::string& center, std::string& up, std::string& model) {
  app.add_option("--eye", eye, "View: gluLookAt eye (x,y,z)")->capture_default_str();
  app.add_option("--center", center, "View: gluLookAt center (x,y,z)")->capture_default_str();
  app.add_option("--up", up, "View: gluLookAt up (x,y,z)")->capture_default_str();
  app.add_option("--model", model,
                 "Model matrix, 16 numbers column-major (default identity); vertices are drawn under view * model, "
                 "eye_linear planes are given under the view alone");
}

}  // namespace uvtk::cli
