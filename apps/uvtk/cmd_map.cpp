// `uvtk map`: assign UVs to a mesh with a projector and write an OBJ with per-corner UVs.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli_values.h"
#include "commands.h"
#include "io/atomic_file.h"
#include "io/mesh_reader.h"
#include "io/obj_writer.h"
#include "param/projector.h"
#include "projector_cli.h"
#include "summary_json.h"

namespace uvtk::cli {

namespace {

struct MapArguments {
  std::string input, output, json;
  bool writeW = false;
  bool floatDigits = false;
  ProjectorArguments projector;
};

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The stage under way, on one line that the next stage overwrites; only on a terminal, where a
// person waits for a large mesh, never in logs.
class Progress {
 public:
  Progress() : enabled_(::isatty(STDERR_FILENO) != 0) {}
  void stage(const char* what, const std::string& subject) const {
    if (enabled_) std::fprintf(stderr, "\r\033[Kuvtk map: %s %s ...", what, subject.c_str());
  }
  void done() const {
    if (enabled_) std::fprintf(stderr, "\r\033[K");
  }

 private:
  bool enabled_;
};

void runMap(const MapArguments& a) {
  const param::ProjectorOptions options = a.projector.resolve();
  const Progress progress;
  progress.stage("reading", a.input);
  auto start = std::chrono::steady_clock::now();
  io::ReadMeshResult input = io::readMesh(a.input);
  const double readMs = millisecondsSince(start);
  const std::size_t inputVertices = input.mesh.vertexCount(), inputFaces = input.mesh.faceCount();

  progress.stage("mapping", std::to_string(inputFaces) + " faces");
  start = std::chrono::steady_clock::now();
  const param::Projection projection = param::project(std::move(input.mesh), options);
  const double mapMs = millisecondsSince(start);
  const param::MappingSummary& s = projection.summary;

  progress.stage("writing", a.output);
  start = std::chrono::steady_clock::now();
  io::ObjWriteOptions write;
  write.writeW = a.writeW;
  write.floatPrecision = a.floatDigits;
  write.header = "uvtk map " + a.input;
  io::writeObj(a.output, projection.mesh, &projection.uv, write);
  const double writeMs = millisecondsSince(start);

  if (!a.json.empty()) {
    nlohmann::json j = summaryJson(s);
    j["input"] = {{"path", a.input}, {"vertices", inputVertices}, {"faces", inputFaces},
                  {"degenerate_faces", input.warnings.degenerateFaces},
                  {"unreferenced_vertices", input.warnings.unreferencedVertices}};
    j["output"] = a.output;
    j["milliseconds"] = {{"read", readMs}, {"map", mapMs}, {"write", writeMs}};
    io::writeFileAtomically(a.json, j.dump(2) + "\n");
  }
  progress.done();
  if (input.warnings.degenerateFaces || input.warnings.unreferencedVertices)
    std::fprintf(stderr, "%s: warning: %zu degenerate faces, %zu unreferenced vertices\n", a.input.c_str(),
                 input.warnings.degenerateFaces, input.warnings.unreferencedVertices);
  std::fprintf(stderr,
               "uvtk map: %zu vertices, %zu faces, %zu seam edges, %zu pole vertices, %zu pole faces, "
               "%zu invalid vertices, %.1f ms\n",
               s.vertices, s.faces, s.seamEdges, s.poleVertices, s.poleFaces, s.invalidVertices, mapMs);
}

}  // namespace

void addMapCommand(CLI::App& root) {
  auto arguments = std::make_shared<MapArguments>();
  CLI::App* map = root.add_subcommand("map", "Assign UVs with a projector (Bier & Sloan two-stage mapping)");
  map->add_option("input", arguments->input, "Input mesh (.obj or .off)")->required();
  map->add_option("-o,--output", arguments->output, "Output OBJ with per-corner UVs")->required();
  map->add_option("--json", arguments->json, "Also write the summary as JSON");
  map->add_flag("--write-w", arguments->writeW, "Write the third UV component (the cube face id)");
  addChoice<bool>(*map, "--uv-digits", arguments->floatDigits, {{"double", false}, {"float", true}},
                  "UV text that round-trips a double (up to 17 digits) or a float (up to 9)")
      ->default_str("double");
  addProjectorOptions(*map, arguments->projector);
  map->callback([arguments] { runMap(*arguments); });
}

}  // namespace uvtk::cli
