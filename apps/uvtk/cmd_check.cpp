// `uvtk check`: the texture coordinates stored in a mesh file against those a mapping gives (any
// projector of `uvtk map`, with its conventions, or GL texgen), or against another file's, corner
// by corner (inspect/check.h, docs/check.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "core/error.h"
#include "inspect/check.h"
#include "io/image_io.h"
#include "options/cli_values.h"
#include "options/mapping_options.h"
#include "options/verdict_cli.h"

namespace uvtk::cli {

namespace {

struct CheckArguments {
  std::string input, against, json, view;
  std::string viewSize = "512x512", viewDir = "0,0,1", viewUp = "0,1,0";
  std::string wrap = "none";
  std::optional<double> tolerance;
  int textureSize = 1024;
  int worst = 10;
  bool partial = false;
  MappingArguments mapping;
  std::vector<std::string> mappingOptions;  // every option addMappingOptions added
  VerdictArguments verdict;                 // of the stored UVs as a layout (docs/conventions.md §11)
};

void runCheck(CheckArguments& a) {
  // Every option first, so that nothing is read or written for a bad command line.
  if (a.textureSize < 1) throw UsageError("--texture-size: expected a positive number of texels");
  if (a.worst < 0) throw UsageError("--worst: expected a count of corners, 0 or more");
  if (a.tolerance && !(std::isfinite(*a.tolerance) && *a.tolerance >= 0.0))
    throw UsageError("--tolerance: expected a finite number of UV units, 0 or more");
  if (a.wrap != "none" && a.wrap != "u") throw UsageError("--wrap: expected none or u, found \"" + a.wrap + "\"");
  inspect::CheckOptions o;
  if (!a.against.empty()) {
    for (const std::string& name : a.mappingOptions)
      if (given(a.mapping.app, name.c_str()))
        throw UsageError("--against compares two files: " + name + " (a mapping option) does not go with it");
  } else {
    if (given(a.mapping.app, "--wrap"))
      throw UsageError("--wrap goes with --against only: a mapping knows its own period");
    const ResolvedMapping resolved = resolveMapping(a.mapping);
    if (resolved.projector && resolved.projector->seam == param::SeamMode::Cut)
      throw UsageError(
          "--seam cut changes the triangles, and uvtk check compares corner by corner: use --seam shift or none (u "
          "is compared modulo its period, so the seam's side does not matter)");
    o.projector = resolved.projector;
    o.texgen = resolved.texgen;
    o.seamPlaceAuto = resolved.seamPlaceAuto;
  }
  if (!a.view.empty()) {
    std::tie(o.viewWidth, o.viewHeight) = parseImageSize(a.viewSize, "--view-size");
    o.viewDir = parseVec3(a.viewDir, "--view-dir");
    o.viewUp = parseVec3(a.viewUp, "--view-up");
    io::checkImageType(a.view, io::PixelType::UInt8);
  }
  o.input = a.input, o.against = a.against, o.wrapU = a.wrap == "u", o.partial = a.partial;
  o.textureSize = a.textureSize, o.worst = std::size_t(a.worst), o.tolerance = a.tolerance;
  o.thresholds = a.verdict.thresholds();
  o.json = a.json, o.view = a.view;
  const inspect::CheckRun run = inspect::checkStoredUvs(o);
  std::fputs(run.text.c_str(), stdout);
  std::fflush(stdout);
  if (!run.pass) throw CheckFailure("the check failed");
  enforceVerdict(a.verdict, run.storedVerdict, "uvtk check");  // exit status 1 (2, 3, 4: usage, input, output errors)
}

}  // namespace

void addCheckCommand(CLI::App& root) {
  auto a = std::make_shared<CheckArguments>();
  CLI::App* cmd = root.add_subcommand(
      "check", "Compare the UVs stored in a mesh file with a mapping's (or another file's), corner by corner");
  cmd->add_option("input", a->input, "Mesh with texture coordinates (.obj with vt)")->required();
  cmd->add_option("--against", a->against,
                  "Compare with this file's UVs instead of a mapping (same vertices and faces)");
  cmd->add_option("--wrap", a->wrap, "--against: none, or u (compare u modulo 1)")
      ->type_name("none|u")
      ->capture_default_str();
  cmd->add_option("--tolerance", a->tolerance,
                  "Exit status 1 when the largest error of the main corners exceeds this (UV units); without it the "
                  "check only reports");
  cmd->add_option("--texture-size", a->textureSize, "Texels per UV unit for the errors in texels")
      ->capture_default_str();
  cmd->add_option("--worst", a->worst, "How many of the worst corners to list")->capture_default_str();
  cmd->add_flag("--partial", a->partial,
                "Accept faces without vt: their corners are listed as invalid instead of an input error");
  cmd->add_option("--json", a->json, "Also write everything as JSON");
  cmd->add_option("--view", a->view, "Also draw the per-corner error as a heatmap (PNG)");
  cmd->add_option("--view-size", a->viewSize, "The heatmap's viewport WxH (the legend is added below)")
      ->capture_default_str();
  cmd->add_option("--view-dir", a->viewDir, "The heatmap's camera: direction from the mesh to the eye")
      ->capture_default_str();
  cmd->add_option("--view-up", a->viewUp, "The heatmap's camera: up")->capture_default_str();
  std::vector<std::string> before;
  for (const CLI::Option* option : cmd->get_options()) before.push_back(option->get_name());
  addMappingOptions(*cmd, a->mapping, param::Fit::BBox);
  for (const CLI::Option* option : cmd->get_options()) {
    const std::string name = option->get_name();
    if (std::find(before.begin(), before.end(), name) == before.end() && name != "--help")
      a->mappingOptions.push_back(name);
  }
  addVerdictOptions(*cmd, a->verdict);
  cmd->callback([a] { runCheck(*a); });
}

}  // namespace uvtk::cli
