// `uvtk bench`: the speed-accuracy trade measured in one run on the same data: mapping, rendering
// (--render) and the peers; a Markdown table, JSON records and Pareto charts (inspect/bench.h,
// docs/precision.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "core/error.h"
#include "inspect/bench.h"
#include "options/cli_values.h"
#include "options/projector_cli.h"
#include "options/render_cli.h"
#include "options/view_camera_cli.h"
#include "render/procedural.h"

namespace uvtk::cli {

namespace {

struct BenchArguments {
  std::string mesh;  // empty: the built-in 2048 x 1024 lat-long sphere
  std::string projectors = "plane,two-plane,cylinder,sphere", omap = "isn";
  std::string precisions = "double,float", maths = "exact,fast,fast-u10", threads = "1";
  int textureWidth = 4096;
  double minTime = 0.3;
  std::string json, markdown, plot;
  bool noPeers = false;
  // rendering
  bool render = false;
  std::string renderProjector = "sphere", size = "512x512", texture = "checker:512:16";
  std::string filters =
      "nearest,linear,nearest_mipmap_nearest,linear_mipmap_nearest,nearest_mipmap_linear,linear_mipmap_linear";
  std::string samples = "1,4,16";
  ViewCameraArguments camera;
};

// A comma-separated list of whole numbers in [low, high].
std::vector<int> parseCounts(const std::string& text, const std::string& option, int low, int high) {
  std::vector<int> values;
  for (double v : parseNumbers(text, int(std::count(text.begin(), text.end(), ',')) + 1, option)) {
    if (v != std::floor(v) || v < low || v > high)
      throw UsageError(option + ": expected whole numbers in [" + std::to_string(low) + ", " + std::to_string(high) +
                       "]");
    values.push_back(int(v));
  }
  return values;
}

void runBench(const BenchArguments& a) {
  a.camera.check();
  if (!(a.minTime > 0)) throw UsageError("--min-time: expected seconds > 0");
  if (a.textureWidth < 1) throw UsageError("--texture-width: expected a positive number of texels");
  // Every output's folder is checked before the first measurement.
  for (const std::string* path : {&a.json, &a.markdown, &a.plot}) {
    const std::filesystem::path folder = std::filesystem::path(*path).parent_path();
    std::error_code error;
    if (!path->empty() && !folder.empty() && !std::filesystem::is_directory(folder, error))
      throw UsageError(*path + ": the folder " + folder.string() + " does not exist");
  }
  inspect::BenchOptions o;
  o.precisions = parseNameList(a.precisions, kPrecisionNames, "--precision");
  o.maths = parseNameList(a.maths, kMathNames, "--math");
  o.threads = parseCounts(a.threads, "--threads", 1, 256);
  projectorNamed("plane", a.omap);  // a bad --omap is named before a bad projector
  for (const std::string& projector : splitList(a.projectors)) {
    o.projectors.push_back({projector, projectorNamed(projector, a.omap)});
    if (o.projectors.back().options.surface == param::SurfaceKind::Cube)
      throw UsageError(
          "--projector cube: the cube chooses its face per triangle; `uvtk bench` times per-vertex mappings");
  }
  if (a.render) {
    std::tie(o.width, o.height) = parseImageSize(a.size, "--size");
    o.samples = parseCounts(a.samples, "--spp", 1, 256);
    o.filters = parseNameList(a.filters, kFilterNames, "--filters");
    o.texture = render::proceduralTexture(a.texture);
    if (!o.texture) throw UsageError("--texture: expected checker:N[:C] or uvgrid[:N], found \"" + a.texture + "\"");
    o.renderProjector = {a.renderProjector, projectorNamed(a.renderProjector, "isn")};
    o.camera = a.camera.resolve();
  }
  o.mesh = a.mesh, o.omap = a.omap, o.textureWidth = a.textureWidth, o.minTime = a.minTime, o.peers = !a.noPeers;
  o.rendering = a.render, o.json = a.json, o.markdown = a.markdown, o.plot = a.plot;
  const std::string md = inspect::bench(o);
  if (a.markdown.empty()) std::fputs(md.c_str(), stdout);
}

}  // namespace

void addBenchCommand(CLI::App& root) {
  auto a = std::make_shared<BenchArguments>();
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
  cmd->add_flag("--render", a->render, "Also measure rendering (default mesh there: a 64 x 32 lat-long sphere)");
  cmd->add_option("--render-projector", a->renderProjector, "Projector whose UVs are rendered")->capture_default_str();
  cmd->add_option("--size", a->size, "Rendering: image size WxH")->capture_default_str();
  cmd->add_option("--texture", a->texture, "Rendering: procedural texture (checker:N[:C], uvgrid[:N])")
      ->capture_default_str();
  cmd->add_option("--filters", a->filters, "Rendering: filters to time")->capture_default_str();
  cmd->add_option("--spp", a->samples, "Rendering: samples per pixel to time (squares)")->capture_default_str();
  addViewCameraOptions(*cmd, a->camera);
  cmd->callback([a] { runBench(*a); });
}

}  // namespace uvtk::cli
