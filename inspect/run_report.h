// What every subcommand tells about its run: the stage under way on a terminal, the time of each
// stage, and the input's warnings (on stderr and in the JSON summary).
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "core/progress.h"
#include "core/stopwatch.h"
#include "io/mesh_reader.h"

namespace uvtk::inspect {

// Times stages one after another. On a terminal, where a person waits for a large mesh, the stage
// under way is shown on one line that the next one overwrites; never in logs, never without
// progress (--quiet), and not when `showStages` is false (a mesh among many under one bar).
class StageClock {
 public:
  explicit StageClock(std::string command, bool showStages = true)
      : command_(std::move(command)), terminal_(showStages && progressEnabled() && ::isatty(STDERR_FILENO) != 0) {}
  void start(const char* what, const std::string& subject) {
    if (terminal_) std::fprintf(stderr, "\r\033[K%s: %s %s ...", command_.c_str(), what, subject.c_str());
    start_ = std::chrono::steady_clock::now();
  }
  // Milliseconds since the last start(); clears the progress line.
  double stop() const {
    if (terminal_) std::fprintf(stderr, "\r\033[K");
    return millisecondsSince(start_);
  }

 private:
  std::string command_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// The "input" object of a JSON summary.
inline nlohmann::json inputJson(const std::string& path, const io::ReadMeshResult& input) {
  return {{"path", path},
          {"vertices", input.mesh.vertexCount()},
          {"faces", input.mesh.faceCount()},
          {"degenerate_faces", input.warnings.degenerateFaces},
          {"unreferenced_vertices", input.warnings.unreferencedVertices},
          {"welded_corners", input.warnings.weldedCorners},
          {"skipped_primitives", input.warnings.skippedPrimitives},
          {"listed_invalid_uv_faces", input.warnings.listedInvalidUvFaces}};
}

// The "path" of an "input" object; empty when there is none (a mesh made in memory).
inline std::string inputPath(const nlohmann::json& input) {
  return input.is_object() && input.contains("path") && input["path"].is_string() ? input["path"].get<std::string>()
                                                                                 : std::string();
}

// One warning line on stderr for each kind of thing the reader counted.
inline void printInputWarnings(const std::string& path, const MeshWarnings& w) {
  if (w.degenerateFaces || w.unreferencedVertices)
    printProgressMessage(path + ": warning: " + std::to_string(w.degenerateFaces) + " degenerate faces, " +
                         std::to_string(w.unreferencedVertices) + " unreferenced vertices");
  if (w.nonSimplePolygons)  // a binary file has no line to name
    printProgressMessage(path + (w.firstNonSimplePolygonLine ? ":" + std::to_string(w.firstNonSimplePolygonLine) : "") +
                         ": warning: polygons that are not simple (self-intersecting, non-planar or of zero area): " +
                         std::to_string(w.nonSimplePolygons) + ", the first here; triangulated as given, they may fold");
  if (w.vertexColours)
    printProgressMessage(path + ": warning: vertex colours ignored: " + std::to_string(w.vertexColours) + " vertices");
  if (w.weldedCorners && !quiet())  // what the format asks for, not a warning
    printProgressMessage(path + ": " + std::to_string(w.weldedCorners) +
                         " corners welded into the vertices of earlier corners at the same position (STL)");
  if (w.listedInvalidUvFaces && !quiet())  // what the writer noted, not a warning
    printProgressMessage(path + ": " + std::to_string(w.listedInvalidUvFaces) +
                         " faces listed by uvtk as having corners without a valid UV: their (0, 0) corners read as without a UV");
  if (w.skippedPrimitives)
    printProgressMessage(path + ": warning: primitives of points or lines left out: " +
                         std::to_string(w.skippedPrimitives));
  if (w.parameterVertices)
    printProgressMessage(path + ": warning: vp lines (free-form parameter vertices) ignored: " +
                         std::to_string(w.parameterVertices));
}

}  // namespace uvtk::inspect
