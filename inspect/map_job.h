// A projector over mesh files, as `uvtk map` runs it: one mesh read, mapped, judged and written
// with its JSON summary, or every mesh of a folder or a list, several at once, into an output
// folder (docs/scale-out.md).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "analysis/judgement.h"
#include "io/mesh_format.h"
#include "io/mesh_writer.h"
#include "inspect/map_parameters.h"
#include "inspect/mapped_mesh.h"
#include "param/projector.h"

namespace uvtk::inspect {

// How the meshes are mapped, judged and written.
struct MapJob {
  // The projector, the judgement's parameters, and the threads each mesh is read, mapped, judged and
  // written with (0: one per hardware thread for a single mesh, one for each mesh of a batch, whose
  // meshes run side by side).
  MapSettings settings;
  io::MeshWriteOptions write;  // the written mesh's options (the header is set per mesh)
  io::MeshFormat batchFormat = io::MeshFormat::obj;  // what a batch writes, OUTDIR/STEM.obj by default
};

// Multiplies every valid corner's (u, v) by D / mean about (0, 0), mean the area-weighted texel
// density of `judgement`'s ok faces (judged on `mapped`), so that the mean becomes `density` (a
// density is linear in a uniform scale of the UVs); records the factor in mapped.uvScale and
// returns it. Throws InputError naming `path`, changing nothing, when there is no ok face, when
// the mean is not a finite positive number, or when a scaled UV would not be finite.
// Precondition: density > 0 and finite.
double scaleToTexelDensity(MappedMesh& mapped, const analysis::Judgement& judgement, double density,
                           const std::string& path);

// Memory before work: a file the machine cannot map is refused (InputError) before it is read,
// and a large one announced.
void checkMapMemory(const std::string& input);

// Where one mesh is read and written; no JSON summary when `json` is empty.
struct MeshPaths {
  std::string input, output, json;
};

// One mesh's summary line ("N vertices, ...; verdict ...") and its verdict.
struct MeshResult {
  std::string numbers;
  analysis::Verdict verdict = analysis::Verdict::Pass;
  std::vector<std::string> advice;  // what would address the reasons, each once (analysis::adviceOf)
};

// Reads, maps, judges and writes one mesh (and its JSON summary, published together with it),
// prints the input's notes, and returns its summary line. The stages are shown on a terminal only
// with `showStages`.
MeshResult mapMesh(const MeshPaths& paths, const MapJob& job, bool showStages);

// Every .obj and .off file directly in `folder`, sorted by name; InputError when there is none.
std::vector<std::string> meshesInFolder(const std::string& folder);

// The paths of a list file, one a line, relative to the list's folder; blank lines and lines whose
// first non-blank character is '#' are skipped (a '#' later on a line belongs to the file name).
std::vector<std::string> meshesInList(const std::string& list);

// How a batch ended.
struct BatchResult {
  int status = 0;  // the highest exit status of the failed meshes (0: none failed)
  std::size_t mapped = 0, failed = 0;
  std::array<std::size_t, 3> verdicts{};  // the meshes mapped, by verdict (pass, warn, fail)
  analysis::Verdict worst = analysis::Verdict::Pass;  // of the meshes mapped
};

// Every mesh of `inputs` into the folder `output` as STEM.obj (and STEM.json with batch.json in
// the folder `json` unless it is empty), `jobs` at a time (0: one per hardware thread), each
// mapped on `job.threads` threads (0: one); a failing mesh does not stop the others, and is printed. Unless `quiet`,
// each mesh's summary line is printed too. Throws UsageError before any work when two inputs share
// a stem, when an output would replace an input, or when a summary would be named batch.json.
BatchResult mapBatch(const std::vector<std::string>& inputs, const std::string& output, const std::string& json,
                     int jobs, bool quiet, const MapJob& job);

}  // namespace uvtk::inspect
