// OpenGL texgen on a mesh file, as `uvtk texgen` runs it: the coordinates generated, divided by q
// where an OBJ needs it, written as an OBJ with its JSON summary.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/uv_map.h"
#include "io/mesh_writer.h"
#include "texgen/texgen.h"

namespace uvtk::inspect {

// An OBJ cannot carry q: when q is not 1 at some (valid) corner, the file gets the projective
// division (s/q, t/q, r/q) at every corner, as a projective lookup would see it. A corner whose q
// is 0 (or whose quotient is not finite) has no texture coordinate: written (0, 0, 0), marked
// invalid and counted. docs/conventions.md §6.
struct ProjectiveDivision {
  bool applied = false;            // q was not 1 at some valid corner: uv holds the quotients
  std::size_t qNotOneCorners = 0;  // valid corners with q != 1
  std::size_t qZeroCorners = 0;    // of those, corners with q = 0 or a non-finite quotient
  UvMap uv;                        // empty unless applied
};

// The division of `uv` (s, t in uv.uv, r in uv.w) by `q`, one per corner (empty: q is 1).
ProjectiveDivision divideByQ(const UvMap& uv, const std::vector<double>& q);

// What an OBJ of these coordinates holds in its third vt component: r is written when generated,
// or when the texture matrix feeds something else into it.
bool texgenWritesR(const texgen::TexgenOptions& options);

// Each coordinate's mode and plane: {"s": {"mode", "plane"}, "t": ..., "r": ..., "q": ...}.
nlohmann::json texgenCoordinatesJson(const texgen::TexgenOptions& options);

// The summary `uvtk texgen --json` writes, without the times: the counts, the division, the
// options, the "input" record, the output file, and every corner's [s, t, r, q] as generated.
nlohmann::json texgenSummaryJson(const texgen::TexgenResult& result, const ProjectiveDivision& divided,
                                 const texgen::TexgenOptions& options, const Mesh& mesh, const nlohmann::json& input,
                                 const std::string& output);

// One mesh file through texgen: what `uvtk texgen` prints and tells.
struct TexgenRun {
  MeshWarnings warnings;  // the input's
  std::size_t vertices = 0, faces = 0;
  std::size_t sphereMapSingular = 0;
  std::size_t invalidCorners = 0;  // texgen's, and those of q = 0
  bool qDivided = false;           // ProjectiveDivision's counts
  std::size_t qNotOneCorners = 0, qZeroCorners = 0;
  bool writesR = false;  // r written as the OBJ's third component
  bool dropsR = false;   // r generated, but the output's format holds two components
  double texgenMs = 0.0;
};

// Reads `input`, generates, and writes the mesh `output` by its extension (and the summary `json`
// unless empty, published together with it) on write.threads threads (reading too); the stages are
// shown on a terminal. `write.writeW` is set here: r is written when texgen generates it and the format holds it (OBJ).
TexgenRun texgenMesh(const std::string& input, const std::string& output, const std::string& json,
                     const texgen::TexgenOptions& options, io::MeshWriteOptions write = {});

}  // namespace uvtk::inspect
