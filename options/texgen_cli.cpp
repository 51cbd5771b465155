#include "options/texgen_cli.h"

#include <utility>
#include <vector>

#include "options/arithmetic_cli.h"
#include "options/cli_values.h"
#include "inspect/mapping_parameters.h"
#include "param/projector_names.h"

namespace uvtk::cli {

const char* const kCoordinateOptions[4] = {"--s", "--t", "--r", "--q"};

bool TexgenArguments::given() const {
  if (!mode.empty()) return true;
  for (const std::string& c : coordinates)
    if (!c.empty()) return true;
  return false;
}

void TexgenArguments::addTo(param::ParameterDictionary& parameters) const {
  if (!mode.empty()) parameters.add(shortcutOption.substr(2), mode);
  for (std::size_t i = 0; i < 4; ++i)
    if (!coordinates[i].empty()) parameters.add(kCoordinateOptions[i] + 2, coordinates[i]);
  if (!textureMatrix.empty()) {
    const Mat4 matrix = parseMatrix(textureMatrix, "--texmatrix");
    parameters.add("texmatrix", std::vector<double>(matrix.data(), matrix.data() + 16));
  }
  if (noNormalize) parameters.add("no-normalize", true);
}

texgen::TexgenOptions TexgenArguments::resolve(const Mat4& view, const Mat4& model) const {
  param::ParameterDictionary parameters(param::ParameterFace::CommandLine);
  addTo(parameters);
  parameters.add("precision", param::precisionName(arithmetic.precision));
  return inspect::readTexgen(parameters, shortcutOption.substr(2), view, model);
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

void addTexgenThreadsOption(CLI::App& app, int& threads) {
  addThreadsOption(app, threads,
                   "Threads the mesh is read and written with (the library's mapping is also judged with them); 0: "
                   "one per hardware thread");
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
