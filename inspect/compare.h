// The ranking of every projector configuration on one mesh (`uvtk compare`, and a scene's compare
// output), with CGAL's LSCM and ARAP as baselines: a Markdown table, JSON, a contact sheet.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/mesh.h"
#include "io/atomic_file.h"
#include "inspect/mapped_mesh.h"
#include "param/parameters.h"
#include "core/names.h"

namespace uvtk::inspect {

enum class RankBy { StretchL2, StretchLinf, Angle, SeamLength };
// Their names, as every face spells them: stretch_l2, stretch_linf, angle, seam_length.
extern const ChoiceNames<RankBy> kRankByNames;

// The bounds CompareOptions::check and readCompareOptions hold the sheet's pictures to.
inline constexpr int kMinTileSize = 16, kMaxTileSize = 4096;

struct CompareOptions {
  std::string json;                 // the ranking as JSON; empty: not written
  std::string markdown;             // the Markdown table; empty: not written
  std::string sheet;                // the contact sheet of the best; empty: not drawn
  std::string writeBest;            // the first-ranked mapping's mesh, as uvtk map writes it; empty: not written
  RankBy by = RankBy::StretchL2;    // the measure that ranks within a verdict
  int top = 8;                      // candidates on the contact sheet
  int tileSize = 256;               // pixels across each picture of the sheet
  int overlapResolution = analysis::kOverlapFollowsMesh;  // or pixels across the overlap raster (as uvtk map)
  analysis::TextureSize textureSize;  // the texture texel density counts in
  int baselineMaxFaces = 200000;    // LSCM and ARAP only on meshes up to this size
  int margin = 4;                   // the atlas's (and LSCM's and ARAP's) gutter in texels of textureSize
  int threads = 0;                  // threads for the pictures (0: one per hardware thread)
  bool seamPlaceAuto = false;       // place the seam of cylinder and sphere
  bool baselines = true;            // rank CGAL's LSCM and ARAP too
  ViewCamera camera;                // the sheet's camera
  analysis::Thresholds thresholds;  // the verdict's (uvtk compare's --fail-on/--warn-on, a scene's "thresholds")

  void check() const;  // throws UsageError for a value out of range, before any work
};

// The comparison's options as the library and Python's keywords give them: "json", "markdown",
// "sheet", "write-best", "by", "top", "tile-size", "view-dir", "up", "overlap-resolution",
// "texture-size", "seam-place-auto", "no-baselines", "baseline-max-faces", "margin", "threads",
// "fail-on" and "warn-on", each named as given in a message; then check() them.
CompareOptions readCompareOptions(const param::ParameterDictionary& parameters);

// Every name readCompareOptions reads.
std::vector<std::string> compareParameterNames();

// One ranked mapping: a projector configuration or a baseline, with its judgement.
struct RankedMapping {
  std::string name;
  MappedMesh mapped;
  analysis::Judgement judgement;
  double key = 0.0;  // the ranking measure
  nlohmann::json record;

  const analysis::Summary& summary() const { return judgement.summary; }
};

struct Comparison {
  nlohmann::json record;               // what --json writes
  std::string table;                   // the Markdown table
  std::string best;                    // the first-ranked mapping's name
  std::size_t skipped = 0;
  std::vector<RankedMapping> ranking;  // best first
};

// Maps `mesh` with every configuration and ranks them, writing nothing; `input` is the "input"
// record.
Comparison rankMappings(const CompareOptions& options, const Mesh& mesh, const nlohmann::json& input);

// The checker and stretch views of the first options.top mappings, two mappings per row.
Image comparisonSheet(const Comparison& comparison, const CompareOptions& options);

// The `uvtk map` options that make the mapping a ranked row names ("--projector sphere --omap isn
// --fit pca"): what --write-best wrote, and how to write it again.
std::string mapOptionsOf(const param::ProjectorOptions& options);

// rankMappings, then the outputs `options` names, published together.
Comparison compareMappings(const CompareOptions& options, const Mesh& mesh, const nlohmann::json& input);
// The same, staged in `outputs` (a scene's).
Comparison compareMappings(io::OutputSet& outputs, const CompareOptions& options, const Mesh& mesh,
                           const nlohmann::json& input);

}  // namespace uvtk::inspect
