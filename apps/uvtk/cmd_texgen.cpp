// `uvtk texgen`: OpenGL fixed-function texture-coordinate generation on a mesh, written as an
// OBJ with per-corner `vt s t` (or `vt s t r`), and optionally every (s, t, r, q) as JSON.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>

#include "cli_values.h"
#include "run_report.h"
#include "commands.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "io/mesh_reader.h"
#include "io/obj_writer.h"
#include "texgen/texgen.h"

namespace uvtk::cli {

namespace {

using texgen::TexgenMode;

const std::vector<std::pair<std::string, TexgenMode>> kModeNames = {
    {"object_linear", TexgenMode::ObjectLinear}, {"eye_linear", TexgenMode::EyeLinear},
    {"sphere_map", TexgenMode::SphereMap},       {"normal_map", TexgenMode::NormalMap},
    {"reflection_map", TexgenMode::ReflectionMap}, {"off", TexgenMode::Off}};

const char* modeName(TexgenMode mode) {
  for (const auto& [name, value] : kModeNames)
    if (value == mode) return name.c_str();
  return "?";
}

struct TexgenArguments {
  std::string input, output, json;
  std::array<std::string, 4> coordinates;  // --s --t --r --q as given, empty when absent
  std::string mode;                        // --mode shortcut
  std::string eye = "0,0,0", center = "0,0,-1", up = "0,1,0";
  std::string model, textureMatrix;
  bool noNormalize = false;
};

// "MODE" or "MODE:a,b,c,d" for the coordinate option `option`.
texgen::TexgenCoordinate parseCoordinate(const std::string& text, const std::string& option,
                                         const texgen::TexgenCoordinate& defaults) {
  const std::size_t colon = text.find(':');
  const std::string name = text.substr(0, colon);
  texgen::TexgenCoordinate c = defaults;
  bool known = false;
  for (const auto& [modeText, value] : kModeNames)
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

texgen::TexgenOptions resolve(const TexgenArguments& a) {
  texgen::TexgenOptions o;
  const std::array<texgen::TexgenCoordinate, 4> defaults = texgen::defaultCoordinates();
  const char* const names[4] = {"--s", "--t", "--r", "--q"};
  if (!a.mode.empty()) {
    const texgen::TexgenCoordinate shortcut = parseCoordinate(a.mode, "--mode", {});
    if (shortcut.mode != TexgenMode::SphereMap && shortcut.mode != TexgenMode::NormalMap &&
        shortcut.mode != TexgenMode::ReflectionMap)
      throw UsageError("--mode: expected sphere_map|normal_map|reflection_map, found '" + a.mode + "'");
    const int count = shortcut.mode == TexgenMode::SphereMap ? 2 : 3;
    for (int i = 0; i < count; ++i) o.coordinates[i].mode = shortcut.mode;
  }
  bool any = !a.mode.empty();
  for (int i = 0; i < 4; ++i)
    if (!a.coordinates[i].empty()) {  // an explicit coordinate option overrides --mode
      o.coordinates[i] = parseCoordinate(a.coordinates[i], names[i], defaults[i]);
      any = true;
    }
  if (!any) o.coordinates[0].mode = o.coordinates[1].mode = TexgenMode::ObjectLinear;
  for (int i = 0; i < 4; ++i) {
    const TexgenMode m = o.coordinates[i].mode;
    if ((m == TexgenMode::SphereMap && i >= 2) ||
        ((m == TexgenMode::NormalMap || m == TexgenMode::ReflectionMap) && i == 3))
      throw UsageError(std::string(names[i]) + ": " + modeName(m) + " is not allowed on this coordinate " +
                       "(sphere_map: s, t only; normal_map, reflection_map: s, t, r only)");
  }
  const Mat4 view = texgen::lookAt(parseVec3(a.eye, "--eye"), parseVec3(a.center, "--center"),
                                   parseVec3(a.up, "--up"));
  const Mat4 model = a.model.empty() ? Mat4::Identity() : parseMatrix(a.model, "--model");
  o.modelviewAtPlanes = view;  // planes are given under the view alone: they act in world space
  o.modelviewAtDraw = view * model;
  if (!a.textureMatrix.empty()) o.textureMatrix = parseMatrix(a.textureMatrix, "--texmatrix");
  o.normalize = !a.noNormalize;
  return o;
}

void runTexgen(const TexgenArguments& a) {
  const texgen::TexgenOptions options = resolve(a);
  StageClock clock("uvtk texgen");
  clock.start("reading", a.input);
  const io::ReadMeshResult input = io::readMesh(a.input);
  const double readMs = clock.stop();

  clock.start("generating", std::to_string(input.mesh.faceCount()) + " faces");
  const texgen::TexgenResult result = texgen::generateTexcoords(input.mesh, options);
  const double texgenMs = clock.stop();

  clock.start("writing", a.output);
  io::ObjWriteOptions write;
  // r is written when generated, or when the texture matrix feeds something else into it.
  write.writeW = options.coordinates[2].mode != TexgenMode::Off ||
                 options.textureMatrix.row(2) != Eigen::RowVector4d(0, 0, 1, 0);
  write.header = "uvtk texgen " + a.input;
  io::writeObj(a.output, input.mesh, &result.uv, write);
  const double writeMs = clock.stop();

  const std::size_t vertices = input.mesh.vertexCount(), faces = input.mesh.faceCount();
  if (!a.json.empty()) {
    nlohmann::json coordinates = nlohmann::json::array();
    for (std::size_t c = 0; c < result.q.size(); ++c)
      coordinates.push_back({result.uv.uv[c].x(), result.uv.uv[c].y(), result.uv.w[c], result.q[c]});
    nlohmann::json modes = nlohmann::json::object();
    const char* const names[4] = {"s", "t", "r", "q"};
    for (int i = 0; i < 4; ++i) {
      const texgen::TexgenCoordinate& c = options.coordinates[i];
      modes[names[i]] = {{"mode", modeName(c.mode)}, {"plane", {c.plane[0], c.plane[1], c.plane[2], c.plane[3]}}};
    }
    nlohmann::json j = {{"vertices", vertices},
                        {"faces", faces},
                        {"sphere_map_singular_corners", result.sphereMapSingular},
                        {"invalid_corners", result.invalidCorners},
                        {"normalize", options.normalize},
                        {"coordinates", modes},
                        {"input", inputJson(a.input, input)},
                        {"output", a.output},
                        {"milliseconds", {{"read", readMs}, {"texgen", texgenMs}, {"write", writeMs}}},
                        {"texcoords", coordinates}};
    io::writeFileAtomically(a.json, j.dump(2) + "\n");
  }
  printInputWarnings(a.input, input.warnings);
  std::fprintf(stderr, "uvtk texgen: %zu vertices, %zu faces, %zu sphere-map singular corners, %zu invalid corners, %.1f ms\n",
               vertices, faces, result.sphereMapSingular, result.invalidCorners, texgenMs);
}

}  // namespace

void addTexgenCommand(CLI::App& root) {
  auto arguments = std::make_shared<TexgenArguments>();
  CLI::App* cmd = root.add_subcommand(
      "texgen", "OpenGL fixed-function texture-coordinate generation (glTexGen, GL 4.6 compatibility §12.1.3)");
  cmd->add_option("input", arguments->input, "Input mesh (.obj or .off)")->required();
  cmd->add_option("-o,--output", arguments->output, "Output OBJ with per-corner vt s t (vt s t r when r is generated)")
      ->required();
  const std::string modes = "MODE[:a,b,c,d]";
  const char* const planeHelp =
      ": object_linear|eye_linear|sphere_map|normal_map|reflection_map|off, optionally with the plane "
      "(GL default plane otherwise: s 1,0,0,0, t 0,1,0,0, r and q 0,0,0,0). Default: off, except s and t "
      "object_linear when no coordinate option and no --mode is given";
  const char* const coordinateNames[4] = {"--s", "--t", "--r", "--q"};
  for (int i = 0; i < 4; ++i)
    cmd->add_option(coordinateNames[i], arguments->coordinates[i],
                    std::string("Generation of ") + (coordinateNames[i] + 2) + (i == 0 ? planeHelp : ", as --s"))
        ->type_name(modes);
  cmd->add_option("--mode", arguments->mode,
                  "Shortcut: s, t (and r for normal_map, reflection_map) in this mode; --s/--t/--r override it")
      ->type_name("sphere_map|normal_map|reflection_map");
  cmd->add_option("--eye", arguments->eye, "View: gluLookAt eye (x,y,z)")->capture_default_str();
  cmd->add_option("--center", arguments->center, "View: gluLookAt center (x,y,z)")->capture_default_str();
  cmd->add_option("--up", arguments->up, "View: gluLookAt up (x,y,z)")->capture_default_str();
  cmd->add_option("--model", arguments->model,
                  "Model matrix, 16 numbers column-major (default identity); vertices are drawn under view * model, "
                  "eye_linear planes are given under the view alone");
  cmd->add_option("--texmatrix", arguments->textureMatrix,
                  "Texture matrix applied to (s,t,r,q), 16 numbers column-major (default identity); q is kept, not divided");
  cmd->add_flag("--no-normalize", arguments->noNormalize,
                "Do not renormalise the eye normal after the inverse transpose (GL's default state; "
                "by default it is renormalised, as with GL_NORMALIZE)");
  cmd->add_option("--json", arguments->json, "Also write the summary and every corner's [s, t, r, q] as JSON");
  cmd->callback([arguments] { runTexgen(*arguments); });
}

}  // namespace uvtk::cli
