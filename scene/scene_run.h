// What `uvtk run` does with a scene: the plan (the stages the requested outputs need, and nothing
// else) and its execution, one mesh's stages after another on each of the worker threads.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace uvtk::scene {

struct Stage {
  enum class Kind { Texture, Read, Map, Measure, Mesh, Render, Report, Compare, Gallery, Bench };
  Kind kind = Kind::Read;
  std::size_t index = 0;              // of the texture (textures.size(): the default one), mesh, mapping or output
  int overlapResolution = 0;          // Measure
  std::optional<std::size_t> mesh;    // the mesh whose work it is; none for textures and the gallery
  std::string subject;                // a name or a file, for people
  std::vector<std::string> computes;  // what it computes beyond the obvious ("vertex normals", "mipmaps", ...)
  std::vector<std::size_t> needs;     // the earlier stages whose results it reads
};

const char* toString(Stage::Kind kind);

// The stages the outputs of `scene` need, in an order that runs: textures, then each used mesh's
// reading, mappings, measures and outputs, then the benchmarks (each reads its mesh itself), the
// gallery last. A mesh no output uses is not read, a
// mapping no output uses not computed, a measure taken once per mapping (and overlap resolution).
std::vector<Stage> planScene(const Scene& scene);

nlohmann::json planJson(const Scene& scene, const std::vector<Stage>& plan);
std::string planText(const Scene& scene, const std::vector<Stage>& plan);

struct RunOptions {
  int jobs = 0;  // meshes worked on at once (0: one per hardware thread)
};

struct RunResult {
  nlohmann::json report;  // the plan with every stage's time and status, the outputs, the failures
  int status = 0;         // 0, or the exit status of the worst failure (3 input, 4 output, 1 other)
};

// Runs `plan`. A failing stage stops only the stages that need its results (a failing mesh does
// not stop the others); the failure is recorded and printed on stderr as it happens. The meshes
// are worked on in parallel, then the benchmarks one after another on an otherwise idle process.
RunResult runScene(const Scene& scene, const std::vector<Stage>& plan, const RunOptions& options);

}  // namespace uvtk::scene
