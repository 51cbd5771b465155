// The judgement of one UV mapping: every per-face status and count, the measures, the seams and
// poles, the overlap, and a verdict (pass, warn or fail) with the reasons for it. Computed once
// per mapping; every consumer (the CLI's summary line, `map --json`, `report`, the views' legends,
// `compare`, scene reports and the gallery) reads this one object and recounts nothing.
// The rules and their default thresholds: docs/conventions.md §11.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/distortion.h"
#include "analysis/summary.h"
#include "analysis/texel_layout.h"
#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk::analysis {

enum class Verdict : std::uint8_t { Pass, Warn, Fail };
const char* toString(Verdict verdict);  // "pass", "warn", "fail"
std::optional<Verdict> parseVerdict(std::string_view name);

// The rules of the verdict, each a measured value compared with a warn and a fail threshold.
enum class Rule : std::uint8_t {
  InvalidCorners,       // corners with no valid UV, out of range apart (count)
  OutOfRangeCorners,    // corners beyond the projector's sensible range (count)
  FlippedArea,          // flipped faces' share of the 3D area
  ZeroAreaUvArea,       // zero-UV-area faces' share of the 3D area
  ZeroArea3dFaces,      // zero-3D-area faces' share of the faces: what the other rules cannot measure
  Overlap,              // overlapped share of the covered UV raster
  UnrepairedSeamFaces,  // faces still spanning more than half a turn of a wrapping u (count)
  StretchP99,           // the 99th percentile of the normalised per-face L2 stretch
  PoleArea,             // pole faces' share of the 3D area
  BackfacingArea,       // backfacing faces' share of the 3D area (planar projections)
  DensitySpread,        // p90 / p10 of the ok faces' texel density
  MipLine,              // the share of a view's covered pixels on a GPU's seam mip line (set where one is drawn)
  LayoutTexels,         // the texels the ok faces cover in the texture (sum of Auv W H): below is worse
  TexelsPerFace,        // LayoutTexels per ok face: below is worse
  TexelClashes,         // level-0 texels whose bilinear footprint mixes two charts (count; separate charts only)
  Gutter,               // the smallest gutter between charts, in level-0 texels: below is worse (separate charts only)
};
constexpr int kRuleCount = 16;
const char* toString(Rule rule);  // "invalid_corners", "out_of_range_corners", ...
// One line of what would address a rule's trigger (the option, projector or command).
const char* adviceOf(Rule rule);
std::optional<Rule> parseRule(std::string_view name);
// Whether the rule triggers when its value falls below a threshold (LayoutTexels, TexelsPerFace,
// Gutter) rather than exceeds it.
bool triggersBelow(Rule rule);

// A threshold per rule and severity: the rule triggers when its value exceeds the threshold, or
// for the rules that trigger below, falls below it (infinity, minus infinity for those: never).
// Defaults: docs/conventions.md §11. TexelClashes and Gutter have their defaults only for a layout
// whose charts must stay apart (an atlas: JudgementOptions::separateCharts); elsewhere (charts meant
// to tile across their seams) they are off unless set.
struct Thresholds {
  std::array<double, kRuleCount> warn, fail;
  std::array<bool, kRuleCount> warnGiven{}, failGiven{};  // set by set(): kept whatever the layout
  Thresholds();  // the defaults
  double& of(Rule rule, Verdict severity);
  double of(Rule rule, Verdict severity) const;
  // "RULE=VALUE" (VALUE a number >= 0, or "off"/"inf": never) for the given severity. Throws
  // UsageError naming `option`, the bad text and the rule names.
  void set(std::string_view assignment, Verdict severity, std::string_view option);
  // The thresholds in force for a layout whose charts must stay apart or not.
  Thresholds forLayout(bool separateCharts) const;
  bool operator==(const Thresholds& other) const {
    return warn == other.warn && fail == other.fail && warnGiven == other.warnGiven && failGiven == other.failGiven;
  }
};

// One reason of a verdict: the rule, how bad (Warn or Fail), its value, the threshold it exceeded,
// and how many faces it concerns.
struct Reason {
  Rule rule = Rule::InvalidCorners;
  Verdict severity = Verdict::Warn;
  double value = 0.0, threshold = 0.0;
  std::size_t faces = 0;
  // "flipped_area 0.42 > 0.001 (1,152 faces)"
  std::string text() const;
};

// What the judgement needs to know about where the UVs came from.
struct JudgementOptions {
  bool wrapsU = false;                       // u has period uPeriod (cylinder, sphere): seams are expected, not failed
  double uPeriod = 1.0;                      // 1, or what `uvtk map --density` scaled the UVs by
  int overlapResolution = kOverlapFollowsMesh;  // pixels across the overlap raster, or follows the mesh
  TextureSize textureSize;                   // the texels a texel density counts, and the texel rules
  // The charts are meant to stay apart in the texture (an atlas): the texel clash and gutter rules
  // are on by default. Elsewhere charts are meant to tile across their seams.
  bool separateCharts = false;
  Thresholds thresholds;
  int threads = 0;                           // 0: one per core; the judgement does not depend on it
};

struct Judgement {
  FaceMeasures faces;  // measureFaces
  Summary summary;                    // summarize, with the pole vertices of the options
  double surfaceArea = 0.0;           // sum(A3) over every face: the denominator of the area shares
  std::array<std::size_t, kCornerInvalidCount> invalidCorners{};  // per CornerInvalid (entry 0: valid corners)
  std::size_t invalidFaces = 0;         // faces with an invalid corner or kFaceInvalid
  std::size_t outOfRangeFaces = 0;      // faces with an out-of-range corner
  std::size_t otherInvalidFaces = 0;    // invalid faces with a corner invalid for another reason (or none)
  std::size_t straddlingFaces = 0;      // kFaceSeamStraddle: faces the seam crossed (repaired unless --seam none)
  std::size_t unrepairedSeamFaces = 0;  // of a wrapping u, faces whose valid corners span more than 0.5
  std::size_t capFaces = 0, cubeSeamFaces = 0, sphereMapSingularFaces = 0;
  std::size_t overlappedFaces = 0;      // faces covering a pixel that another face covers too
  // The values the rules compare, indexed by Rule, and the faces each concerns.
  std::array<double, kRuleCount> values{};
  std::array<std::size_t, kRuleCount> ruleFaces{};
  Thresholds thresholds;  // those the verdict was taken under
  // The layout's texels, where the texel clash or gutter rule was on (JudgementOptions::separateCharts).
  std::optional<TexelStatistics> texels;
  Verdict verdict = Verdict::Pass;
  std::vector<Reason> reasons;  // fail reasons first, then warn reasons, each in Rule order

  std::size_t statusCount(FaceStatus status) const { return summary.statusCounts[status]; }
  // The first reason's text, or "no rule triggered".
  std::string firstReason() const;
  // Every reason's text, "; " between them, the warnings after "warn: " when some rule fails:
  // "flipped_area 0.00454 > 0.001 (20 faces); warn: overlap 0.00803 > 0.001 (99 faces)".
  std::string reasonsText() const;
};

// Measures `uv` on `mesh` and judges it. Preconditions: 3 corners per triangle, matching face flags.
Judgement judge(const Mesh& mesh, const UvMap& uv, const JudgementOptions& options = {});

// The verdict and reasons of `values` under `thresholds` (judge's last step, exposed so that a
// changed threshold needs no new measuring).
void applyThresholds(Judgement& judgement, const Thresholds& thresholds);

// A rule measured after the judgement (Rule::MipLine, from a rendered view): its value and the
// faces it concerns set, the verdict taken again under the judgement's thresholds.
void setMeasuredRule(Judgement& judgement, Rule rule, double value, std::size_t faces);

}  // namespace uvtk::analysis
