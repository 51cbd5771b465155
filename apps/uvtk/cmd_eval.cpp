// `uvtk eval`: any mapping at single points. Points (with optional normals and eyes) come from
// --point/--normal or as CSV or JSON-line rows on stdin; each point's (u, v, w, q), status and
// reason go out as CSV or JSON lines with every number in 17 significant digits (docs/eval.md).
// The numbers are PointEvaluator's, hence those of the point API and of `uvtk map` before its
// seam and pole repair.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "core/progress.h"
#include "options/cli_values.h"
#include "options/mapping_options.h"
#include "point/point_io.h"

namespace uvtk::cli {

namespace {

using point::TextFormat;

struct EvalArguments {
  std::vector<std::string> points, normals;
  TextFormat input = TextFormat::Csv, format = TextFormat::Csv;
  std::string mesh, output;
  MappingArguments mapping;
  CLI::App* app = nullptr;
};

void runEval(const EvalArguments& a) {
  point::EvalJob job = point::evalJobOf(a.points, a.normals, given(a.app, "--input"));
  job.input = a.input, job.format = a.format, job.mesh = a.mesh, job.output = a.output;
  const point::EvalCounts c = point::evaluatePoints(job, mappingParameters(a.mapping));
  using point::Status;
  if (!quiet())
    std::fprintf(stderr, "uvtk eval: %zu points, %zu ok, %zu poles, %zu on seam, %zu invalid\n", c.points,
                 c.byStatus[int(Status::Ok)], c.byStatus[int(Status::Pole)], c.byStatus[int(Status::OnSeam)],
                 c.byStatus[int(Status::Invalid)]);
}

}  // namespace

void addEvalCommand(CLI::App& root) {
  auto arguments = std::make_shared<EvalArguments>();
  CLI::App* cmd = root.add_subcommand(
      "eval", "Texture coordinates of single points under any projector or texgen mapping, with status and reason");
  arguments->app = cmd;
  const auto addTriples = [cmd](const char* name, std::vector<std::string>& values, const char* help) {
    cmd->add_option(name, values, help)->type_name("X,Y,Z")->expected(1)->multi_option_policy(
        CLI::MultiOptionPolicy::TakeAll);
  };
  addTriples("--point", arguments->points,
             "A point x,y,z in object space (repeatable; nan/inf allowed: an invalid point). Without --point "
             "the points are read from stdin");
  addTriples("--normal", arguments->normals,
             "The object-space normal x,y,z of every point (once) or of each point (once per --point); with "
             "rows on stdin, of the rows without their own");
  const std::vector<std::pair<std::string, TextFormat>> formats = {{"csv", TextFormat::Csv},
                                                                   {"json", TextFormat::Json}};
  addChoice<TextFormat>(*cmd, "--input", arguments->input, formats,
                        "The rows on stdin: csv (x,y,z[,nx,ny,nz][,ex,ey,ez], optional header) or json (one "
                        "{\"p\":[x,y,z],\"n\":[...],\"eye\":[...]} a line)")
      ->default_str("csv");
  addChoice<TextFormat>(*cmd, "--format", arguments->format, formats,
                        "Output: csv (header x,y,z,...,u,v,w,q,status,reason) or json (one object a line)")
      ->default_str("csv");
  cmd->add_option("--mesh", arguments->mesh,
                  "Mesh (.obj, .off, .ply, .stl, .gltf, .glb) that a fitted placement (--fit, --convention) and --seam-place auto are "
                  "fitted to, as uvtk map fits them")
      ->type_name("FILE");
  cmd->add_option("-o,--output", arguments->output, "Write to this file (atomically) instead of stdout")
      ->type_name("FILE");
  addMappingOptions(*cmd, arguments->mapping, param::Fit::None);
  cmd->get_option("--texgen")
      ->description(
          "Texture coordinates by GL texgen: s, t (and r for normal_map, reflection_map) in this mode with "
          "GL's default planes, under the gluLookAt view of --eye, --center, --up; --s/--t/--r/--q "
          "override it");
  cmd->footer(point::kEvalHelp);
  cmd->callback([arguments] { runEval(*arguments); });
}

}  // namespace uvtk::cli
