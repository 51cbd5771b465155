// `uvtk texgen`: OpenGL fixed-function texture-coordinate generation on a mesh, written as an
// OBJ with per-corner `vt s t` (or `vt s t r`), and optionally every (s, t, r, q) as JSON.
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>

#include "options/arithmetic_cli.h"
#include "options/cli_values.h"
#include "commands.h"
#include "run_report.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "io/mesh_reader.h"
#include "io/obj_writer.h"
#include "texgen/texgen.h"
#include "options/texgen_cli.h"

namespace uvtk::cli {

namespace {

using texgen::TexgenMode;

// An OBJ cannot carry q: when q is not 1 at some (valid) corner, the file gets the projective
// division (s/q, t/q, r/q) at every corner, as a projective lookup would see it. A corner whose q
// is 0 (or whose quotient is not finite) has no texture coordinate: written (0, 0, 0), marked
// invalid and counted. docs/conventions.md §6.
struct ProjectiveDivision {
  bool applied = false;           // q was not 1 at some valid corner: uv holds the quotients
  std::size_t qNotOneCorners = 0;  // valid corners with q != 1
  std::size_t qZeroCorners = 0;    // of those, corners with q = 0 or a non-finite quotient
  UvMap uv;
};

ProjectiveDivision divideByQ(const texgen::TexgenResult& result) {
  ProjectiveDivision out;
  const std::size_t corners = result.q.size();
  for (std::size_t c = 0; c < corners; ++c)
    if (result.uv.cornerInvalid[c] == kCornerValid && result.q[c] != 1.0) ++out.qNotOneCorners;
  if (out.qNotOneCorners == 0) return out;
  out.applied = true;
  out.uv = result.uv;
  for (std::size_t c = 0; c < corners; ++c) {
    if (result.uv.cornerInvalid[c] != kCornerValid || result.q[c] == 1.0) continue;
    const double q = result.q[c];
    const Vec2 st = result.uv.uv[c] / q;
    const double r = result.uv.w[c] / q;
    if (q != 0.0 && st.allFinite() && std::isfinite(r)) {
      out.uv.uv[c] = st;
      out.uv.w[c] = r;
      continue;
    }
    out.uv.uv[c] = Vec2::Zero();
    out.uv.w[c] = 0.0;
    out.uv.cornerInvalid[c] = kCornerNotFinite;
    out.uv.faceFlags[c / 3] |= kFaceInvalid;
    ++out.qZeroCorners;
  }
  return out;
}

struct TexgenCommandArguments {
  std::string input, output, json;
  std::string eye = "0,0,0", center = "0,0,-1", up = "0,1,0";
  std::string model;
  TexgenArguments texgen;
};

void runTexgen(const TexgenCommandArguments& a) {
  const Mat4 view = lookAt(parseVec3(a.eye, "--eye"), parseVec3(a.center, "--center"), parseVec3(a.up, "--up"));
  const Mat4 model = a.model.empty() ? Mat4::Identity() : parseMatrix(a.model, "--model");
  const texgen::TexgenOptions options = a.texgen.resolve(view, model);
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
  const ProjectiveDivision divided = divideByQ(result);
  io::OutputSet outputs;  // the OBJ and its summary, published together
  io::writeObj(outputs, a.output, input.mesh, divided.applied ? &divided.uv : &result.uv, write);
  const double writeMs = clock.stop();
  const std::size_t invalidCorners = result.invalidCorners + divided.qZeroCorners;

  const std::size_t vertices = input.mesh.vertexCount(), faces = input.mesh.faceCount();
  if (!a.json.empty()) {
    nlohmann::json coordinates = nlohmann::json::array();
    for (std::size_t c = 0; c < result.q.size(); ++c)
      coordinates.push_back({result.uv.uv[c].x(), result.uv.uv[c].y(), result.uv.w[c], result.q[c]});
    nlohmann::json modes = nlohmann::json::object();
    const char* const names[4] = {"s", "t", "r", "q"};
    for (int i = 0; i < 4; ++i) {
      const texgen::TexgenCoordinate& c = options.coordinates[i];
      modes[names[i]] = {{"mode", texgenModeName(c.mode)}, {"plane", {c.plane[0], c.plane[1], c.plane[2], c.plane[3]}}};
    }
    nlohmann::json j = {{"vertices", vertices},
                        {"faces", faces},
                        {"sphere_map_singular_corners", result.sphereMapSingular},
                        {"invalid_corners", invalidCorners},
                        {"q_divided", divided.applied},
                        {"q_not_one_corners", divided.qNotOneCorners},
                        {"q_zero_corners", divided.qZeroCorners},
                        {"normalize", options.normalize},
                        {"precision", precisionName(options.precision)},
                        {"coordinates", modes},
                        {"input", inputJson(a.input, input)},
                        {"output", a.output},
                        {"milliseconds", {{"read", readMs}, {"texgen", texgenMs}, {"write", writeMs}}},
                        {"texcoords", coordinates}};
    outputs.writeText(a.json, j.dump(2) + "\n");
  }
  outputs.publish();
  printInputWarnings(a.input, input.warnings);
  if (divided.applied)
    std::fprintf(stderr, "uvtk texgen: q is not 1 at %zu corners: wrote s/q, t/q%s (%zu corners with q = 0 written as 0 and counted invalid)\n",
                 divided.qNotOneCorners, write.writeW ? ", r/q" : "", divided.qZeroCorners);
  std::fprintf(stderr, "uvtk texgen: %zu vertices, %zu faces, %zu sphere-map singular corners, %zu invalid corners, %.1f ms\n",
               vertices, faces, result.sphereMapSingular, invalidCorners, texgenMs);
}

}  // namespace

void addTexgenCommand(CLI::App& root) {
  auto arguments = std::make_shared<TexgenCommandArguments>();
  CLI::App* cmd = root.add_subcommand(
      "texgen", "OpenGL fixed-function texture-coordinate generation (glTexGen, GL 4.6 compatibility §12.1.3)");
  cmd->add_option("input", arguments->input, "Input mesh (.obj or .off)")->required();
  cmd->add_option("-o,--output", arguments->output, "Output OBJ with per-corner vt s t (vt s t r when r is generated); divided by q where q is not 1")
      ->required();
  addTexgenOptions(*cmd, arguments->texgen, "--mode");
  cmd->add_option("--eye", arguments->eye, "View: gluLookAt eye (x,y,z)")->capture_default_str();
  cmd->add_option("--center", arguments->center, "View: gluLookAt center (x,y,z)")->capture_default_str();
  cmd->add_option("--up", arguments->up, "View: gluLookAt up (x,y,z)")->capture_default_str();
  cmd->add_option("--model", arguments->model,
                  "Model matrix, 16 numbers column-major (default identity); vertices are drawn under view * model, "
                  "eye_linear planes are given under the view alone");
  cmd->add_option("--json", arguments->json, "Also write the summary and every corner's [s, t, r, q] (undivided) as JSON");
  cmd->callback([arguments] { runTexgen(*arguments); });
}

}  // namespace uvtk::cli
