#include "options/bench_cli.h"

#include <algorithm>

#include "options/cli_values.h"

namespace uvtk::cli {

timing::BenchOptions BenchArguments::resolve() const {
  param::ParameterDictionary p(param::ParameterFace::CommandLine);
  const auto add = [&](const char* option, param::ParameterValue value) {
    if (given(app, option)) p.add(option + 2, std::move(value));
  };
  const auto counts = [](const std::string& text, const char* option) {
    const Eigen::VectorXd numbers = parseNumbers(text, int(std::count(text.begin(), text.end(), ',')) + 1, option);
    return std::vector<double>(numbers.data(), numbers.data() + numbers.size());
  };
  add("--mesh", mesh);
  add("--omap", omap);
  add("--projector", splitList(projectors));
  add("--precision", splitList(precisions));
  add("--math", splitList(maths));
  if (given(app, "--threads")) p.add("threads", counts(threads, "--threads"));
  add("--texture-width", std::int64_t(textureWidth));
  add("--min-time", minTime);
  for (const auto& [option, file] : {std::pair{"--json", &json}, {"--markdown", &markdown}, {"--plot", &plot}, {"--html", &html}})
    add(option, *file);
  add("--no-peers", noPeers);
  add("--map-projector", mapProjector);
  add("--no-end-to-end", noEndToEnd);
  add("--render", render);
  add("--render-projector", renderProjector);
  camera.addTo(p);
  texture.addTo(p);
  frame.addSceneTo(p);
  add("--filters", splitList(filters));
  if (given(app, "--spp")) p.add("spp", counts(samples, "--spp"));
  const timing::BenchOptions options = timing::readBenchOptions(p);
  p.checkAllRead(timing::benchParameterNames());
  return options;
}

void addBenchOptions(CLI::App& cmd, BenchArguments& a) {
  cmd.add_option("--mesh", a.mesh, "Mesh to measure (default: the built-in 2048 x 1024 lat-long sphere)");
  cmd.add_option("--projector", a.projectors, "Projectors to time (plane, two-plane, cylinder, sphere)")
      ->capture_default_str();
  cmd.add_option("--omap", a.omap, "O-mapping of every projector (isn, centroid, normal, reflection)")
      ->capture_default_str();
  cmd.add_option("--precision", a.precisions, "Precisions (double, float)")->capture_default_str();
  cmd.add_option("--math", a.maths, "Math modes (exact, fast, fast-u10); one for surfaces without atan2")
      ->capture_default_str();
  cmd.add_option("--threads", a.threads, "Thread counts, e.g. 1,2")->capture_default_str();
  cmd.add_option("--texture-width", a.textureWidth, "Texels across the texture errors are measured in")
      ->capture_default_str();
  cmd.add_option("--min-time", a.minTime, "Seconds each configuration runs at least")->capture_default_str();
  cmd.add_option("--json", a.json, "One record per configuration as JSON");
  cmd.add_option("--markdown", a.markdown, "The table as Markdown to this file (default: stdout)");
  cmd.add_option("--plot", a.plot, "Pareto chart PNG (with --render also FILE-render.png)");
  cmd.add_option("--html", a.html, "One self-contained HTML page: the Pareto charts as SVG and the tables");
  cmd.add_flag("--no-peers", a.noPeers, "Skip the peers (assimp's aiProcess_GenUVCoords)");
  cmd.add_option("--map-projector", a.mapProjector,
                 "With --mesh: the projector of the end-to-end `uvtk map` (read, map, seams, judge, write, peak "
                 "memory, against reading and copying the files)")
      ->capture_default_str();
  cmd.add_flag("--no-end-to-end", a.noEndToEnd, "With --mesh: skip the end-to-end `uvtk map`");
  cmd.add_flag("--render", a.render,
               "Also measure rendering (default mesh there: a 64 x 32 lat-long sphere), of the scene `uvtk render` "
               "draws from the same camera, texture, --size, --cull, --background and --uv options");
  cmd.add_option("--render-projector", a.renderProjector, "Projector whose UVs are rendered")->capture_default_str();
  addCameraOptions(cmd, a.camera);
  addTextureOptions(cmd, a.texture, "--texture");
  addFrameSceneOptions(cmd, a.frame);
  cmd.add_option("--filters", a.filters,
                 "Rendering: the minification filters to time (an explicit --filter: that one alone)")
      ->capture_default_str();
  cmd.add_option("--spp", a.samples, "Rendering: samples per pixel to time (squares)")->capture_default_str();
  a.app = &cmd;
}

}  // namespace uvtk::cli
