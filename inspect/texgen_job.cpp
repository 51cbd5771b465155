#include "inspect/texgen_job.h"

#include <cmath>

#include "core/stopwatch.h"
#include "inspect/run_report.h"
#include "io/atomic_file.h"
#include "io/mesh_reader.h"
#include "io/mesh_format.h"
#include "io/mesh_writer.h"
#include "inspect/projector_json.h"
#include "param/projector_names.h"
#include "io/json_text.h"

namespace uvtk::inspect {

ProjectiveDivision divideByQ(const UvMap& uv, const std::vector<double>& q) {
  ProjectiveDivision out;
  const std::size_t corners = q.size();
  for (std::size_t c = 0; c < corners; ++c)
    if (uv.cornerInvalid[c] == kCornerValid && q[c] != 1.0) ++out.qNotOneCorners;
  if (out.qNotOneCorners == 0) return out;
  out.applied = true;
  out.uv = uv;
  for (std::size_t c = 0; c < corners; ++c) {
    if (uv.cornerInvalid[c] != kCornerValid || q[c] == 1.0) continue;
    const Vec2 st = uv.uv[c] / q[c];
    const double r = uv.w[c] / q[c];
    if (q[c] != 0.0 && st.allFinite() && std::isfinite(r)) {
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

bool texgenWritesR(const texgen::TexgenOptions& options) {
  return options.coordinates[2].mode != texgen::TexgenMode::Off ||
         options.textureMatrix.row(2) != Eigen::RowVector4d(0, 0, 1, 0);
}

nlohmann::json texgenCoordinatesJson(const texgen::TexgenOptions& options) {
  nlohmann::json modes = nlohmann::json::object();
  const char* const names[4] = {"s", "t", "r", "q"};
  for (std::size_t i = 0; i < 4; ++i) {
    const texgen::TexgenCoordinate& c = options.coordinates[i];
    modes[names[i]] = {{"mode", texgen::texgenModeName(c.mode)}, {"plane", {c.plane[0], c.plane[1], c.plane[2], c.plane[3]}}};
  }
  return modes;
}

nlohmann::json texgenSummaryJson(const texgen::TexgenResult& result, const ProjectiveDivision& divided,
                                 const texgen::TexgenOptions& options, const Mesh& mesh, const nlohmann::json& input,
                                 const std::string& output) {
  nlohmann::json coordinates = nlohmann::json::array();
  for (std::size_t c = 0; c < result.q.size(); ++c)
    coordinates.push_back({result.uv.uv[c].x(), result.uv.uv[c].y(), result.uv.w[c], result.q[c]});
  return {{"vertices", mesh.vertexCount()},
          {"faces", mesh.faceCount()},
          {"sphere_map_singular_corners", result.sphereMapSingular},
          {"invalid_corners", result.invalidCorners + divided.qZeroCorners},
          {"q_divided", divided.applied},
          {"q_not_one_corners", divided.qNotOneCorners},
          {"q_zero_corners", divided.qZeroCorners},
          {"normalize", options.normalize},
          {"precision", param::precisionName(options.precision)},
          {"coordinates", texgenCoordinatesJson(options)},
          {"input", input},
          {"output", output},
          {"texcoords", coordinates}};
}

TexgenRun texgenMesh(const std::string& inputPath, const std::string& output, const std::string& json,
                     const texgen::TexgenOptions& options, io::MeshWriteOptions write) {
  const bool holdsR = io::outputFormatOf(output) == io::MeshFormat::obj;
  write.writeW = texgenWritesR(options) && holdsR;
  io::checkMeshOutput(output, write);
  StageClock clock("uvtk texgen");
  clock.start("reading", inputPath);
  const io::ReadMeshResult input = io::readMesh(inputPath, write.threads);
  const double readMs = clock.stop();

  clock.start("generating", std::to_string(input.mesh.faceCount()) + " faces");
  const texgen::TexgenResult result = texgen::generateTexcoords(input.mesh, options);
  const double texgenMs = clock.stop();

  clock.start("writing", output);
  write.header = "uvtk texgen " + inputPath;
  const ProjectiveDivision divided = divideByQ(result.uv, result.q);
  io::OutputSet outputs;  // the mesh and its summary, published together
  io::writeMesh(outputs, output, input.mesh, divided.applied ? &divided.uv : &result.uv, write);
  const double writeMs = clock.stop();

  if (!json.empty()) {
    nlohmann::json j = texgenSummaryJson(result, divided, options, input.mesh, inputJson(inputPath, input), output);
    j["milliseconds"] = {{"read", readMs}, {"texgen", texgenMs}, {"write", writeMs}};
    outputs.writeText(json, io::jsonText(j, 2) + "\n");
  }
  outputs.publish();
  TexgenRun run;
  run.warnings = input.warnings;
  run.vertices = input.mesh.vertexCount();
  run.faces = input.mesh.faceCount();
  run.sphereMapSingular = result.sphereMapSingular;
  run.invalidCorners = result.invalidCorners + divided.qZeroCorners;
  run.qDivided = divided.applied;
  run.qNotOneCorners = divided.qNotOneCorners;
  run.qZeroCorners = divided.qZeroCorners;
  run.writesR = write.writeW;
  run.dropsR = texgenWritesR(options) && !holdsR;
  run.texgenMs = texgenMs;
  return run;
}

}  // namespace uvtk::inspect
