// Inside the library: what a public Mapping keeps of the engine's (the mapped mesh and its
// judgement), the conversions between the public value types and the engine's, and the one place
// that turns the engine's errors into the public ones.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/judgement.h"
#include "core/error.h"
#include "core/mesh.h"
#include "inspect/mapped_mesh.h"
#include "param/parameters.h"
#include "texgen/texgen.h"
#include "uvtk/uvtk.h"

namespace uvtk::api {

struct MappingDetail {
  inspect::MappedMesh mapped;
  analysis::Judgement judgement;
  int overlapResolution = analysis::kOverlapFollowsMesh;  // the judgement's
  nlohmann::json input;          // the summaries' "input" record: the input mesh's counts
  std::optional<texgen::TexgenOptions> texgen;  // the options of a texgen mapping: its OBJ's r and q
  bool restored = false;  // made by restoreMapping(): `mapped` holds the mesh and the UVs, nothing judged
};

uvtk::Mesh toEngine(const Mesh& mesh);
Mesh fromEngine(const uvtk::Mesh& mesh);
MeshWarnings fromEngine(const uvtk::MeshWarnings& warnings);

// A public mesh checked (std::invalid_argument, as checkMesh) and converted once, with the "input"
// record of its summaries (as `uvtk map --json` writes it, without the path).
struct CheckedMesh {
  uvtk::Mesh engine;
  nlohmann::json input;
};
CheckedMesh checked(const Mesh& mesh);

// The public Mapping of `mapped`, judged under `thresholds`; `input` is the summary's "input" record.
Mapping makeMapping(inspect::MappedMesh mapped, const analysis::Thresholds& thresholds, int overlapResolution,
                    nlohmann::json input, std::optional<texgen::TexgenOptions> texgen = std::nullopt,
                    analysis::TextureSize textureSize = {}, int threads = 0);

// What report() and render() need of a mapping: its detail, judged (not a restored one's).
const MappingDetail& judgedDetailOf(const Mapping& mapping, const char* function);

// What `function` needs of a mapping: its detail, which only map(), texgen() and fileUvs() make;
// a default Mapping{} is std::invalid_argument.
const MappingDetail& detailOf(const Mapping& mapping, const char* function);

// The public parameters as the engine's dictionary (the same values; a Python keyword's face).
param::ParameterDictionary toEngine(const Parameters& parameters);

// `text` split as a shell would split it (whitespace, '...' and "..." quotes, backslash escapes).
std::vector<std::string> splitCommandLine(const std::string& text);
// `words` joined into one line, each quoted where a shell would need it.
std::string joinCommandLine(const std::vector<std::string>& words);

// Runs `work`, turning the engine's errors into the public ones: UsageError into
// std::invalid_argument, InputError into InputError, OutputError into OutputError.
template <class Work>
auto translatingErrors(Work&& work) -> decltype(work()) {
  try {
    return work();
  } catch (const param::ParameterTypeError& error) {
    throw ParameterTypeError(uvtk::errorMessage(error));
  } catch (const uvtk::UsageError& error) {
    throw std::invalid_argument(uvtk::errorMessage(error));
  } catch (const uvtk::InputError& error) {
    throw InputError(uvtk::errorMessage(error));
  } catch (const uvtk::OutputError& error) {
    throw OutputError(uvtk::errorMessage(error));
  }
}

}  // namespace uvtk::api
