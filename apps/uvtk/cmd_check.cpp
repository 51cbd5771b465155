// `uvtk check`: the texture coordinates stored in a mesh file against those a mapping gives (any
// projector of `uvtk map`, with its conventions, or GL texgen), or against another file's, corner
// by corner (inspect/check.h, docs/check.md).
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "core/error.h"
#include "inspect/check.h"
#include "options/check_cli.h"

namespace uvtk::cli {

namespace {

void runImageCheck(const CheckArguments& a) {
  const inspect::ImageCheckRun run = checkImageFile(a);
  std::fputs(run.text.c_str(), stdout);
  std::fflush(stdout);
  if (!run.pass) throw CheckFailure("the check failed");  // exit status 1
}

void runCheck(const CheckArguments& a) {
  if (!a.image.empty()) return runImageCheck(a);
  const inspect::CheckRun run = inspect::checkStoredUvs(a.resolve());
  std::fputs(run.text.c_str(), stdout);
  std::fflush(stdout);
  if (!run.pass) throw CheckFailure("the check failed");
  enforceVerdict(a.verdict, run.storedVerdict, "uvtk check");  // exit status 1 (2, 3, 4: usage, input, output errors)
}

}  // namespace

void addCheckCommand(CLI::App& root) {
  auto a = std::make_shared<CheckArguments>();
  CLI::App* cmd = root.add_subcommand(
      "check",
      "Compare the UVs stored in a mesh file with a mapping's (or another file's), corner by corner; with --image, "
      "a picture of the mesh made by another renderer with uvtk's rendering, pixel by pixel");
  cmd->add_option("input", a->input, "Mesh with texture coordinates (.obj with vt, .ply with s t or texcoord, .gltf/.glb with TEXCOORD_0)")->required();
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
  std::vector<std::string> beforeVerdict;
  for (const CLI::Option* option : cmd->get_options()) beforeVerdict.push_back(option->get_name());
  addVerdictOptions(*cmd, a->verdict);
  for (const CLI::Option* option : cmd->get_options())
    if (std::find(beforeVerdict.begin(), beforeVerdict.end(), option->get_name()) == beforeVerdict.end())
      a->uvOptions.push_back(option->get_name());
  for (const char* name : {"--against", "--tolerance", "--texture-size", "--worst", "--partial", "--view", "--view-size",
                           "--view-up"})
    a->uvOptions.push_back(name);
  addImageCheckOptions(*cmd, *a);
  cmd->callback([a] { runCheck(*a); });
}

}  // namespace uvtk::cli
