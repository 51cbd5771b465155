// `uvtk eval`: any mapping at single points. Points (with optional normals and eyes) come from
// --point/--normal or as CSV or JSON-line rows on stdin; each point's (u, v, w, q), status and
// reason go out as CSV or JSON lines with every number in 17 significant digits (docs/eval.md).
// The numbers are PointEvaluator's, hence those of the point API and of `uvtk map` before its
// seam and pole repair.
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "core/progress.h"
#include "core/error.h"
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
  const bool fromStdin = a.points.empty();
  if (!fromStdin && given(a.app, "--input"))
    throw UsageError("--input describes rows on stdin; it does not go with --point");
  if (!fromStdin && a.normals.size() > 1 && a.normals.size() != a.points.size())
    throw UsageError("--normal: expected one normal for every point, or one per point (" +
                     std::to_string(a.points.size()) + "), found " + std::to_string(a.normals.size()));
  if (fromStdin && a.normals.size() > 1)
    throw UsageError(
        "--normal: with rows on stdin, expected at most one (the normal of rows without their own), "
        "found " +
        std::to_string(a.normals.size()) + "; give each row's normal in its nx,ny,nz or \"n\"");
  if (fromStdin && isatty(STDIN_FILENO))
    throw UsageError("expected --point x,y,z, or rows on stdin (CSV or JSON lines; see --help), found a terminal");
  point::EvalJob job;
  for (const std::string& p : a.points) job.rows.push_back({0, point::parseTriple(p, "--point"), {}, {}});
  for (std::size_t i = 0; i < a.normals.size(); ++i) {
    const point::Vector3 n = point::parseTriple(a.normals[i], "--normal");
    if (a.normals.size() == 1)
      job.defaultNormal = n;
    else
      job.rows[i].normal = n;
  }
  if (fromStdin) job.in = &std::cin;
  job.input = a.input, job.format = a.format, job.mesh = a.mesh, job.output = a.output;
  const point::EvalCounts c = point::evaluatePoints(job, a.mapping);
  using point::Status;
  if (!quiet())
    std::fprintf(stderr, "uvtk eval: %zu points, %zu ok, %zu poles, %zu on seam, %zu invalid\n", c.points,
               c.byStatus[int(Status::Ok)], c.byStatus[int(Status::Pole)], c.byStatus[int(Status::OnSeam)],
               c.byStatus[int(Status::Invalid)]);
}

const char* const kFooter = R"(
Points in: --point x,y,z (repeatable) with --normal x,y,z (one for all points, or one per point);
or, without --point, rows on stdin:
  --input csv   one point a line: x,y,z[,nx,ny,nz][,ex,ey,ez] (3, 6 or 9 columns), or any of
                these columns in the order an optional first line (header) names them, e.g.
                "x,y,z,ex,ey,ez"; blank lines and lines starting with # are skipped.
  --input json  one JSON object a line: {"p": [x, y, z], "n": [nx, ny, nz], "eye": [ex, ey, ez]};
                n and eye optional; "nan", "inf", "-inf" as strings for non-finite values.
  A single --normal is the normal of rows without their own. A row's eye replaces --eye: the
  reflection O-mapping's eye (projector) or the gluLookAt eye of texgen's view.
  nan, inf and numbers beyond double range are values: such a point is invalid, not an error.
  A malformed row is an error (exit 3): "<stdin>:LINE: error: expected ..., found ...".

Placement: --fit none by default (object coordinates, or --center/--axis-dir/--ref-dir/--scale).
--fit bbox|center|pca|obb and --convention blender|assimp fit the placement to --mesh FILE exactly
as `uvtk map` fits it; --seam-place auto places the seam on that mesh. --seam and --pole repair a
mesh's faces and do nothing here: each point gets its own value (as uvtk map --seam none --pole none).

Out (stdout, or -o FILE written atomically), one line per point, every number %.17g (it reads back
as the same double):
  --format csv   header x,y,z[,nx,ny,nz][,ex,ey,ez],u,v,w,q,status,reason; reason quoted
  --format json  {"p": [...], "n": [...], "eye": [...], "u", "v", "w", "q", "status", "reason"}
  u, v: the projector's (u, v) or texgen's (s, t); w: the cube face id 0..5 (+X -X +Y -Y +Z -Z)
  with --cube-layout faces, texgen's r, else 0; q: texgen's q (not divided out), else 1.
  nx,ny,nz appear when normals were given, ex,ey,ez when rows brought eyes.
Status: ok; pole (on a wrapping surface's axis: v exact, u undefined and written 0; texgen: the
sphere map's singular point, s = t = 1/2); on-seam (u = 0 and u = 1 are the same point, or a cube
edge); invalid (no value: non-finite or zero input, the ray misses; u = v = 0). reason says why.
A summary goes to stderr: "uvtk eval: N points, K ok, P poles, S on seam, I invalid".
Exit status: 0 ok, 2 usage error, 3 malformed row or mesh, 4 output not writable.)";

}  // namespace

void addEvalCommand(CLI::App& root) {
  auto arguments = std::make_shared<EvalArguments>();
  CLI::App* cmd = root.add_subcommand(
      "eval", "Texture coordinates of single points under any projector or texgen mapping, with status and reason");
  arguments->app = cmd;
  cmd->add_option("--point", arguments->points,
                  "A point x,y,z in object space (repeatable; nan/inf allowed: an invalid point). Without --point "
                  "the points are read from stdin")
      ->type_name("X,Y,Z")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--normal", arguments->normals,
                  "The object-space normal x,y,z of every point (once) or of each point (once per --point); with "
                  "rows on stdin, of the rows without their own")
      ->type_name("X,Y,Z")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
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
                  "Mesh (.obj or .off) that a fitted placement (--fit, --convention) and --seam-place auto are "
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
  cmd->footer(kFooter);
  cmd->callback([arguments] { runEval(*arguments); });
}

}  // namespace uvtk::cli
