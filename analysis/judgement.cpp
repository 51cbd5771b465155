#include "analysis/judgement.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

#include "analysis/overlap.h"
#include "core/error.h"
#include "core/parallel.h"

namespace uvtk::analysis {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

// The rules' names and default thresholds (docs/conventions.md §11), in Rule order.
struct RuleEntry {
  const char* name;
  double warn, fail;
  bool isCount;        // a count of corners or faces (printed as an integer)
  const char* advice;  // what would address it (issue "newcomer": a verdict that says what to do next)
  bool below = false;          // triggers below its threshold
  bool separateOnly = false;   // its defaults hold for charts that must stay apart only (Thresholds)
};
constexpr RuleEntry kRules[kRuleCount] = {
    // any invalid corner fails
    {"invalid_corners", kNever, 0.0, true,
     "rays that miss the surface: another --omap (isn never misses a plane) or --fit; --projector atlas maps every face"},
    // any corner beyond the sensible range fails
    {"out_of_range_corners", kNever, 0.0, true,
     "rays nearly parallel to the surface: --omap isn or another --fit; --projector atlas maps every face"},
    // any flip warns, more than 0.1 % of the area fails
    {"flipped_area", 0.0, 1e-3, false,
     "one projection mirrors the faces it sees from behind: --projector atlas keeps every face's winding; "
     "uvtk compare ranks every option"},
    // likewise for faces collapsed in UV
    {"zero_area_uv_area", 0.0, 1e-3, false,
     "faces seen edge-on collapse: another --fit or --projector, or --projector atlas"},
    // 1 % of the faces unmeasurable warns, half of them fails
    {"zero_area_3d_faces", 0.01, 0.5, false, "the mesh itself has faces of no area: merge or remove them"},
    // 0.1 % of the covered texels warns, 1 % fails
    {"overlap", 1e-3, 1e-2, false,
     "one projection cannot cover a closed or curved shape without folding: --projector atlas lays out charts "
     "that do not overlap; uvtk compare ranks every option"},
    // a face still across the seam fails
    {"unrepaired_seam_faces", kNever, 0.0, true, "--seam shift or --seam cut repairs the faces across the seam"},
    // 1 % of the area stretched 3 times the mean warns
    {"stretch_p99", 3.0, kNever, false,
     "faces at grazing angles stretch: another --fit, --projector atlas, or lscm / arap for the least stretch"},
    // pole fans over 2 % of the area warn
    {"pole_area", 0.02, kNever, false,
     "the poles cover dense faces: --fit pca or obb turns them away; --projector atlas has none"},
    // a planar projection's back faces warn
    {"backfacing_area", 0.0, kNever, false,
     "a planar projection maps the back faces mirrored onto the front: --projector atlas or cube"},
    // the best-resolved tenth with twice the texels per unit of the worst warns
    {"density_spread", 2.0, kNever, false,
     "texels per unit differ across the mesh: --projector atlas, lscm or arap keep one density"},
    // any pixel of a GPU's seam mip line warns
    {"mip_line", 0.0, kNever, false,
     "a shader's derivatives jump at the seam: --seam-fix tarini or grad, or a mapping cut at the seam (--seam cut)"},
    // a layout covering under 64 texels of the texture (8 x 8) warns, under 16 (4 x 4) fails
    {"layout_texels", 64.0, 16.0, false,
     "the layout covers a handful of texels: --fit bbox, --uv-scale or --density scale it up; --texture-size "
     "names the texture it is for",
     true},
    // faces under 1/16 texel each on average warn, under 1/256 fail
    {"texels_per_face", 1.0 / 16.0, 1.0 / 256.0, false,
     "the faces are far below a texel: a larger --texture-size, or a layout that uses more of it (--projector "
     "atlas packs it)",
     true},
    // an atlas: any texel whose bilinear footprint mixes two charts fails
    {"texel_clashes", kNever, 0.0, true,
     "charts sit closer than a texel and bilinear filtering mixes them: a larger --margin, or a larger "
     "--texture-size",
     false, true},
    // an atlas: charts under 2 texels apart warn (Unity's lightmap rule), under half a texel fail
    {"gutter", 2.0, 0.5, false,
     "charts bleed into each other at the first mip levels: a larger --margin (a gutter of 2^L texels lasts "
     "to level L)",
     true, true},
};

const RuleEntry& entry(Rule rule) { return kRules[static_cast<std::size_t>(rule)]; }

std::string ruleNames() {
  std::string names;
  for (const RuleEntry& r : kRules) names += std::string(names.empty() ? "" : ", ") + r.name;
  return names;
}

std::string formatValue(Rule rule, double value) {
  if (std::isinf(value)) return "off";
  char text[64];
  if (entry(rule).isCount)
    std::snprintf(text, sizeof text, "%.0f", value);
  else
    std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// One chunk's share of the judgement's per-face counts and areas.
struct FaceTally {
  double surfaceArea = 0.0, poleArea = 0.0;
  std::array<double, kFaceStatusCount> statusArea{};
  std::array<std::size_t, kCornerInvalidCount> invalidCorners{};
  std::size_t otherInvalidFaces = 0, invalidFaces = 0, outOfRangeFaces = 0, straddlingFaces = 0, capFaces = 0,
              cubeSeamFaces = 0, sphereMapSingularFaces = 0, unrepairedSeamFaces = 0;

  void add(const FaceTally& t) {
    surfaceArea += t.surfaceArea, poleArea += t.poleArea;
    for (std::size_t k = 0; k < statusArea.size(); ++k) statusArea[k] += t.statusArea[k];
    for (std::size_t k = 0; k < invalidCorners.size(); ++k) invalidCorners[k] += t.invalidCorners[k];
    otherInvalidFaces += t.otherInvalidFaces, invalidFaces += t.invalidFaces, outOfRangeFaces += t.outOfRangeFaces;
    straddlingFaces += t.straddlingFaces, capFaces += t.capFaces, cubeSeamFaces += t.cubeSeamFaces;
    sphereMapSingularFaces += t.sphereMapSingularFaces, unrepairedSeamFaces += t.unrepairedSeamFaces;
  }
};

// Whether the valid corners of face f span more than half a turn of u (a seam left across it).
bool spansSeam(const UvMap& uv, std::size_t f, double period) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t corner = 3 * f; corner < 3 * f + 3; ++corner) {
    if (!uv.cornerInvalid.empty() && uv.cornerInvalid[corner] != kCornerValid) continue;
    lo = std::min(lo, uv.uv[corner].x());
    hi = std::max(hi, uv.uv[corner].x());
  }
  return hi - lo > 0.5 * period;
}

}  // namespace

const char* toString(Verdict verdict) {
  switch (verdict) {
    case Verdict::Pass:
      return "pass";
    case Verdict::Warn:
      return "warn";
    case Verdict::Fail:
      return "fail";
  }
  return "?";
}

std::optional<Verdict> parseVerdict(std::string_view name) {
  for (Verdict v : {Verdict::Pass, Verdict::Warn, Verdict::Fail})
    if (name == toString(v)) return v;
  return std::nullopt;
}

const char* toString(Rule rule) { return entry(rule).name; }

std::optional<Rule> parseRule(std::string_view name) {
  for (int k = 0; k < kRuleCount; ++k)
    if (name == kRules[k].name) return Rule(k);
  return std::nullopt;
}

namespace {

// A threshold that never triggers the rule.
double never(Rule rule) { return triggersBelow(rule) ? -kNever : kNever; }

}  // namespace

Thresholds::Thresholds() {
  for (int k = 0; k < kRuleCount; ++k) warn[std::size_t(k)] = kRules[k].warn, fail[std::size_t(k)] = kRules[k].fail;
}

Thresholds Thresholds::forLayout(bool separateCharts) const {
  Thresholds out = *this;
  if (separateCharts) return out;
  for (std::size_t k = 0; k < std::size_t(kRuleCount); ++k) {
    if (!kRules[k].separateOnly) continue;
    if (!warnGiven[k]) out.warn[k] = never(Rule(k));
    if (!failGiven[k]) out.fail[k] = never(Rule(k));
  }
  return out;
}

bool triggersBelow(Rule rule) { return entry(rule).below; }

double& Thresholds::of(Rule rule, Verdict severity) {
  UVTK_CHECK(severity != Verdict::Pass);
  return (severity == Verdict::Fail ? fail : warn)[static_cast<std::size_t>(rule)];
}

double Thresholds::of(Rule rule, Verdict severity) const {
  UVTK_CHECK(severity != Verdict::Pass);
  return (severity == Verdict::Fail ? fail : warn)[static_cast<std::size_t>(rule)];
}

void Thresholds::set(std::string_view assignment, Verdict severity, std::string_view option) {
  const std::size_t equals = assignment.find('=');
  const auto refuse = [&](const std::string& what) {
    throw UsageError(std::string(option) + ": " + what + " in '" + std::string(assignment) +
                     "': expected RULE=VALUE (VALUE a number >= 0, or off) with RULE one of " + ruleNames());
  };
  if (equals == std::string_view::npos) refuse("no '='");
  const std::optional<Rule> rule = parseRule(assignment.substr(0, equals));
  if (!rule) refuse("unknown rule '" + std::string(assignment.substr(0, equals)) + "'");
  const std::string_view text = assignment.substr(equals + 1);
  double value = 0.0;
  if (text == "off" || text == "inf") {
    value = never(*rule);
  } else {
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !(value >= 0.0)) refuse("bad value");
  }
  of(*rule, severity) = value;
  (severity == Verdict::Fail ? failGiven : warnGiven)[static_cast<std::size_t>(*rule)] = true;
}

std::string Reason::text() const {
  char faceText[64] = "";
  if (faces > 0) std::snprintf(faceText, sizeof faceText, " (%zu face%s)", faces, faces == 1 ? "" : "s");
  return std::string(toString(rule)) + " " + formatValue(rule, value) + (triggersBelow(rule) ? " < " : " > ") +
         formatValue(rule, threshold) + faceText;
}

const char* adviceOf(Rule rule) { return entry(rule).advice; }

std::string Judgement::firstReason() const { return reasons.empty() ? "no rule triggered" : reasons.front().text(); }

std::string Judgement::reasonsText() const {
  std::string text;
  for (std::size_t i = 0; i < reasons.size(); ++i) {
    if (i > 0) text += "; ";
    const bool firstWarning = reasons[i].severity == Verdict::Warn && (i == 0 || reasons[i - 1].severity == Verdict::Fail);
    if (firstWarning && verdict == Verdict::Fail) text += "warn: ";
    text += reasons[i].text();
  }
  return text;
}

void applyThresholds(Judgement& j, const Thresholds& thresholds) {
  j.thresholds = thresholds;
  j.reasons.clear();
  j.verdict = Verdict::Pass;
  for (Verdict severity : {Verdict::Fail, Verdict::Warn})
    for (int k = 0; k < kRuleCount; ++k) {
      const Rule rule = Rule(k);
      const double value = j.values[std::size_t(k)];
      const auto beyond = [&](double threshold) { return triggersBelow(rule) ? value < threshold : value > threshold; };
      const double threshold = thresholds.of(rule, severity);
      if (!beyond(threshold)) continue;
      // A rule that fails is not listed again as a warning.
      if (severity == Verdict::Warn && beyond(thresholds.of(rule, Verdict::Fail))) continue;
      j.reasons.push_back({rule, severity, value, threshold, j.ruleFaces[std::size_t(k)]});
      j.verdict = std::max(j.verdict, severity);
    }
}

void setMeasuredRule(Judgement& j, Rule rule, double value, std::size_t faces) {
  j.values[std::size_t(rule)] = value;
  j.ruleFaces[std::size_t(rule)] = faces;
  applyThresholds(j, j.thresholds);
}

Judgement judge(const Mesh& mesh, const UvMap& uv, const JudgementOptions& options) {
  UVTK_CHECK(uv.uv.size() == 3 * mesh.faceCount() && uv.faceFlags.size() == mesh.faceCount());
  Judgement j;
  const MeasureScales scales = measureScales(mesh, uv, options.threads);
  // The seam edges need no per-face measure: classified on a thread of their own while the faces
  // are measured, so that their half-edge index (48 MB at 4 M faces) is given back before the
  // summary's measures take their memory.
  WorkAside seams([&] { return classifySeamEdges(mesh, uv); }, threadCount(options.threads) > 1);
  j.faces = measureFaces(mesh, uv, scales, options.threads);

  // Faces by status and by flag, their 3D areas, and the invalid corners by reason: tallied in
  // fixed chunks and added up in chunk order, so the sums do not depend on the threads. They need
  // no summary: tallied on a thread of their own while the summary's measures run, whose last
  // statistic leaves a core idle.
  constexpr std::size_t kChunk = kFacesPerChunk;
  const auto tallyRange = [&](FaceTally& t, std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      const FaceDistortion& face = j.faces[f];
      t.surfaceArea += face.area3d;
      t.statusArea[static_cast<std::size_t>(face.status)] += face.area3d;
      bool invalid = uv.faceHas(f, kFaceInvalid), outOfRange = false, otherInvalid = false;
      for (std::size_t corner = 3 * f; corner < 3 * f + 3; ++corner) {
        const std::uint8_t reason = uv.cornerInvalid.empty() ? std::uint8_t(kCornerValid) : uv.cornerInvalid[corner];
        UVTK_CHECK(reason < kCornerInvalidCount);
        ++t.invalidCorners[reason];
        invalid |= reason != kCornerValid;
        outOfRange |= reason == kCornerOutOfRange;
        otherInvalid |= reason != kCornerValid && reason != kCornerOutOfRange;
      }
      // A face flagged invalid with no invalid corner counts with the invalid corners' rule.
      otherInvalid |= invalid && !outOfRange;
      t.otherInvalidFaces += otherInvalid ? 1 : 0;
      t.invalidFaces += invalid ? 1 : 0;
      t.outOfRangeFaces += outOfRange ? 1 : 0;
      t.straddlingFaces += uv.faceHas(f, kFaceSeamStraddle) ? 1 : 0;
      t.capFaces += uv.faceHas(f, kFaceCap) ? 1 : 0;
      t.cubeSeamFaces += uv.faceHas(f, kFaceCubeSeam) ? 1 : 0;
      t.sphereMapSingularFaces += uv.faceHas(f, kFaceSphereMapSingular) ? 1 : 0;
      if (uv.faceHas(f, kFacePole)) t.poleArea += face.area3d;
      // A pole fan and a cap are meant to differ from the side; invalid faces are counted above.
      if (options.wrapsU && !invalid && !uv.faceHas(f, kFacePole) && !uv.faceHas(f, kFaceCap) &&
          spansSeam(uv, f, options.uPeriod))
        ++t.unrepairedSeamFaces;
    }
  };
  WorkAside tallying(
      [&] {
        return reduceRanges(mesh.faceCount(), kChunk, 1, FaceTally(), tallyRange,
                            [](FaceTally& total, const FaceTally& t) { total.add(t); });
      },
      threadCount(options.threads) > 1);
  j.summary = summarize(mesh, uv, j.faces, scales, seams.get(), options.overlapResolution, options.threads,
                        options.textureSize);
  const FaceTally tally = tallying.get();
  const std::array<double, kFaceStatusCount>& statusArea = tally.statusArea;
  const double poleArea = tally.poleArea;
  j.surfaceArea = tally.surfaceArea;
  j.invalidCorners = tally.invalidCorners;
  j.otherInvalidFaces = tally.otherInvalidFaces;
  j.invalidFaces = tally.invalidFaces;
  j.outOfRangeFaces = tally.outOfRangeFaces;
  j.straddlingFaces = tally.straddlingFaces;
  j.capFaces = tally.capFaces;
  j.cubeSeamFaces = tally.cubeSeamFaces;
  j.sphereMapSingularFaces = tally.sphereMapSingularFaces;
  j.unrepairedSeamFaces = tally.unrepairedSeamFaces;
  j.overlappedFaces = j.summary.overlap.overlappedFaces;

  const auto share = [&](double area) { return j.surfaceArea > 0.0 ? area / j.surfaceArea : 0.0; };
  const auto set = [&](Rule rule, double value, std::size_t faces) {
    j.values[static_cast<std::size_t>(rule)] = value;
    j.ruleFaces[static_cast<std::size_t>(rule)] = faces;
  };
  std::size_t invalidOther = 0;
  for (int reason = 1; reason < kCornerInvalidCount; ++reason)
    if (reason != kCornerOutOfRange) invalidOther += j.invalidCorners[std::size_t(reason)];
  set(Rule::InvalidCorners, double(invalidOther), j.otherInvalidFaces);
  set(Rule::OutOfRangeCorners, double(j.invalidCorners[kCornerOutOfRange]), j.outOfRangeFaces);
  set(Rule::FlippedArea, share(statusArea[std::size_t(FaceStatus::Flipped)]), j.statusCount(FaceStatus::Flipped));
  set(Rule::ZeroAreaUvArea, share(statusArea[std::size_t(FaceStatus::ZeroAreaUv)]),
      j.statusCount(FaceStatus::ZeroAreaUv));
  const std::size_t zeroArea3d = j.statusCount(FaceStatus::ZeroArea3d);
  set(Rule::ZeroArea3dFaces, mesh.faceCount() > 0 ? double(zeroArea3d) / double(mesh.faceCount()) : 0.0, zeroArea3d);
  set(Rule::Overlap, j.summary.overlap.fraction(), j.overlappedFaces);
  set(Rule::UnrepairedSeamFaces, double(j.unrepairedSeamFaces), j.unrepairedSeamFaces);
  // The ok faces at or above the stretch's p99, and at either end of the density's spread (at or
  // below p10, at or above p90): counted in chunks on threads.
  const double p99 = j.summary.l2Stretches.p99;
  const double normalisation = std::sqrt(1.0 / j.summary.okTotals.surfacePerUv());
  const TexelDensity& density = j.summary.density;
  using Ends = std::array<std::size_t, 2>;  // stretched, spread
  const Ends ends = reduceRanges(
      mesh.faceCount(), kChunk, options.threads, Ends{0, 0},
      [&](Ends& e, std::size_t begin, std::size_t end) {
        for (std::size_t f = begin; f < end; ++f) {
          const FaceDistortion& face = j.faces[f];
          if (face.status != FaceStatus::Ok) continue;
          e[0] += face.l2Stretch() * normalisation >= p99 ? 1 : 0;
          const double d = scaledTexelDensity(face, density.textureSize);
          e[1] += d <= density.scaled.p10 || d >= density.scaled.p90 ? 1 : 0;
        }
      },
      [](Ends& total, const Ends& e) { total[0] += e[0], total[1] += e[1]; });
  const auto [stretched, spread] = ends;
  set(Rule::StretchP99, p99, stretched);
  set(Rule::PoleArea, share(poleArea), j.summary.poleFaces);
  set(Rule::BackfacingArea, share(statusArea[std::size_t(FaceStatus::Backfacing)]),
      j.statusCount(FaceStatus::Backfacing));
  set(Rule::DensitySpread, density.spread, spread);

  // The layout in the texture: the texels the ok faces cover, in all and per face; and where its
  // charts must stay apart, how they meet at level 0 (docs/conventions.md, "Texels of a layout").
  const TextureSize& texture = options.textureSize;
  const std::size_t okFaces = j.statusCount(FaceStatus::Ok);
  // Auv is measured at unit scale (times measureUvScale squared, a power of two): undone here.
  const double layoutTexels = std::ldexp(j.summary.okTotals.uv * double(texture.width) * double(texture.height),
                                         -2 * std::ilogb(measureUvScale(j.summary.uvBounds)));
  // No ok face: nothing to measure (the rules of the faces' status say why): never below.
  set(Rule::LayoutTexels, okFaces > 0 ? layoutTexels : kNever, okFaces);
  set(Rule::TexelsPerFace, okFaces > 0 ? layoutTexels / double(okFaces) : kNever, okFaces);
  const Thresholds thresholds = options.thresholds.forLayout(options.separateCharts);
  const auto on = [&](Rule rule) {
    return thresholds.of(rule, Verdict::Warn) != never(rule) || thresholds.of(rule, Verdict::Fail) != never(rule);
  };
  if ((on(Rule::TexelClashes) || on(Rule::Gutter)) && texture.width <= kMaxTexelSide && texture.height <= kMaxTexelSide) {
    j.texels = texelStatistics(mesh, uv, texture.width, texture.height);
    set(Rule::TexelClashes, double(j.texels->levels.front().clashes), 0);
    set(Rule::Gutter, j.texels->gutters.betweenCharts, 0);
  } else if (on(Rule::Gutter)) {  // a texture too large to raster: the gutter alone, measured exactly
    set(Rule::TexelClashes, 0.0, 0);
    set(Rule::Gutter, measureGutters(mesh, uv, uvCharts(mesh, uv), texture.width, texture.height).betweenCharts, 0);
  } else {
    set(Rule::TexelClashes, 0.0, 0);
    set(Rule::Gutter, kNever, 0);
  }
  applyThresholds(j, thresholds);
  return j;
}

}  // namespace uvtk::analysis
