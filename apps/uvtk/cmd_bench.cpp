// `uvtk bench`: the speed-accuracy trade measured in one run on the same data: mapping, rendering
// (--render) and the peers; a Markdown table, JSON records and Pareto charts (inspect/bench.h,
// docs/precision.md).
#include <cstdio>
#include <memory>
#include <string>

#include "commands.h"
#include "inspect/bench.h"
#include "options/render_cli.h"

namespace uvtk::cli {

namespace {

void runBench(const inspect::BenchArguments& a) {
  const std::string md = inspect::bench(a.resolve());
  if (a.markdown.empty()) std::fputs(md.c_str(), stdout);
}

}  // namespace

void addBenchCommand(CLI::App& root) {
  auto a = std::make_shared<inspect::BenchArguments>();
  CLI::App* cmd = root.add_subcommand("bench", "Measure speed against accuracy: mapping, rendering, and the peers");
  cmd->add_option("--mesh", a->mesh, "Mesh to measure (default: the built-in 2048 x 1024 lat-long sphere)");
  cmd->add_option("--projector", a->projectors, "Projectors to time (plane, two-plane, cylinder, sphere)")
      ->capture_default_str();
  cmd->add_option("--omap", a->omap, "O-mapping of every projector (isn, centroid, normal, reflection)")
      ->capture_default_str();
  cmd->add_option("--precision", a->precisions, "Precisions (double, float)")->capture_default_str();
  cmd->add_option("--math", a->maths, "Math modes (exact, fast, fast-u10); one for surfaces without atan2")
      ->capture_default_str();
  cmd->add_option("--threads", a->threads, "Thread counts, e.g. 1,2")->capture_default_str();
  cmd->add_option("--texture-width", a->textureWidth, "Texels across the texture errors are measured in")
      ->capture_default_str();
  cmd->add_option("--min-time", a->minTime, "Seconds each configuration runs at least")->capture_default_str();
  cmd->add_option("--json", a->json, "One record per configuration as JSON");
  cmd->add_option("--markdown", a->markdown, "The table as Markdown to this file (default: stdout)");
  cmd->add_option("--plot", a->plot, "Pareto chart PNG (with --render also FILE-render.png)");
  cmd->add_flag("--no-peers", a->noPeers, "Skip the peers (assimp's aiProcess_GenUVCoords)");
  cmd->add_option("--map-projector", a->mapProjector,
                  "With --mesh: the projector of the end-to-end `uvtk map` (read, map, seams, judge, write, peak "
                  "memory, against reading and copying the files)")
      ->capture_default_str();
  cmd->add_flag("--no-end-to-end", a->noEndToEnd, "With --mesh: skip the end-to-end `uvtk map`");
  cmd->add_flag("--render", a->render,
                "Also measure rendering (default mesh there: a 64 x 32 lat-long sphere), of the scene `uvtk render` "
                "draws from the same camera, texture, --size, --cull, --background and --uv options");
  cmd->add_option("--render-projector", a->renderProjector, "Projector whose UVs are rendered")->capture_default_str();
  addCameraOptions(*cmd, a->camera);
  addTextureOptions(*cmd, a->texture, "--texture");
  addFrameSceneOptions(*cmd, a->frame);
  cmd->add_option("--filters", a->filters,
                  "Rendering: the minification filters to time (an explicit --filter: that one alone)")
      ->capture_default_str();
  cmd->add_option("--spp", a->samples, "Rendering: samples per pixel to time (squares)")->capture_default_str();
  a->app = cmd;
  cmd->callback([a] { runBench(*a); });
}

}  // namespace uvtk::cli
