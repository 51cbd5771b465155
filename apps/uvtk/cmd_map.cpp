// `uvtk map`: assign UVs to a mesh with a projector and write an OBJ with per-corner UVs.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli_values.h"
#include "commands.h"
#include "io/atomic_file.h"
#include "io/mesh_reader.h"
#include "io/obj_writer.h"
#include "mapped_mesh.h"
#include "param/projector.h"
#include "projector_cli.h"
#include "run_report.h"
#include "summary_json.h"

namespace uvtk::cli {

namespace {

struct MapArguments {
  std::string input, output, json;
  bool writeW = false;
  bool floatDigits = false;
  ProjectorArguments projector;
};

void runMap(const MapArguments& a) {
  const param::ProjectorOptions options = a.projector.resolve();
  StageClock clock("uvtk map");
  clock.start("reading", a.input);
  io::ReadMeshResult input = io::readMesh(a.input);
  const double readMs = clock.stop();
  const nlohmann::json inputSummary = inputJson(a.input, input);

  clock.start("mapping", std::to_string(input.mesh.faceCount()) + " faces");
  const MappedMesh mapped = mapByProjector(std::move(input.mesh), options, a.projector.seamPlaceAuto());
  const double mapMs = clock.stop();
  const param::MappingSummary& s = mapped.projection->summary;

  clock.start("writing", a.output);
  io::ObjWriteOptions write;
  write.writeW = a.writeW;
  write.floatPrecision = a.floatDigits;
  write.header = "uvtk map " + a.input;
  io::writeObj(a.output, mapped.mesh, &mapped.uv, write);
  const double writeMs = clock.stop();

  if (!a.json.empty()) {
    nlohmann::json j = summaryJson(s);
    j["input"] = inputSummary;
    j["output"] = a.output;
    j["options"] = projectorOptionsJson(options);
    if (mapped.seamPlacement) j["seam_placement"] = seamPlacementJson(*mapped.seamPlacement);
    j["milliseconds"] = {{"read", readMs}, {"map", mapMs}, {"write", writeMs}};
    io::writeFileAtomically(a.json, j.dump(2) + "\n");
  }
  printMappingNotes(a.input, input.warnings, mapped);
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
