#include "timing/bench.h"

#include "core/progress.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/markup.h"
#include "core/plugin.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "io/mesh_format.h"
#include "io/mesh_reader.h"
#include "core/stopwatch.h"
#include "inspect/html_page.h"
#include "inspect/map_job.h"
#include "meshes/generators.h"
#include "inspect/projector_json.h"
#include "param/projector_names.h"
#include "inspect/render_parameters.h"
#include "param/surface_traits.h"
#include "param/batch_atan2.h"
#include "param/uv_kernel.h"
#include "param/reference.h"
#include "peers/assimp_peer.h"
#include "timing/benchmark_runner.h"
#include "views/pareto.h"
#include "views/pareto_svg.h"
#include "io/json_text.h"

namespace uvtk::timing {

using namespace uvtk::inspect;

namespace {

// The benchmark plugin, opened on the first timing.
const runner::Functions& benchmarkRunner() {
  static const runner::Functions* const functions = [] {
    const std::string path = pluginPath("UVTK_BENCHMARK_PLUGIN", UVTK_BENCHMARK_PLUGIN_INSTALLED,
                                        UVTK_BENCHMARK_PLUGIN_BUILT, UVTK_BUILD_DIR);
    std::string error;
    const runner::Functions* loaded = openPluginFunctions<runner::Functions>(path, UVTK_BENCHMARK_RUNNER_ENTRY,
                                                                            "benchmark plugin", runner::kVersion, error);
    if (!loaded) throw std::runtime_error(error);
    return loaded;
  }();
  return *functions;
}

// ---- Mapping ----

struct MappingCase {
  param::ProjectorOptions options;
  int threads = 1;
  std::string name;
  param::MappingError error;
};

std::vector<nlohmann::json> benchMapping(const BenchOptions& a, const Mesh& mesh) {
  const std::vector<Precision>& precisions = a.precisions;
  const std::vector<MathMode>& maths = a.maths;
  const std::vector<int>& threadCounts = a.threads;
  std::vector<MappingCase> cases;
  std::vector<runner::TimedCase> timed;  // one per case
  // One output per precision for every configuration (they run one after another), paged in by the
  // error run before timing.
  param::UvArrays<double> doubleUvs;
  param::UvArrays<float> floatUvs;
  // Normals once, for the O-mappings that read them (one O-mapping for every projector).
  const bool readsNormals = std::any_of(a.projectors.begin(), a.projectors.end(), [](const BenchProjector& p) {
    return p.options.ray == param::RayKind::ObjectNormal || p.options.ray == param::RayKind::Reflection;
  });
  const std::vector<Vec3> normals = readsNormals ? areaWeightedVertexNormals(mesh) : std::vector<Vec3>();
  for (const auto& [projector, base] : a.projectors) {
    UVTK_CHECK(!param::traitsOf(base.surface).choosesPerTriangle);
    const Affine3 frame = param::fitPlacement(mesh.positions, base.surface, base.placement);
    // The kernel's input, in the local frame once per precision (as a caller mapping many times keeps it).
    auto doublePoints = std::make_shared<param::LocalPoints<double>>();
    auto floatPoints = std::make_shared<param::LocalPoints<float>>();
    param::toLocal(frame, mesh.positions, normals, *doublePoints);
    param::toLocal(frame, mesh.positions, normals, *floatPoints);
    if (!quiet()) std::fprintf(stderr, "uvtk bench: %s: the long-double reference ...\n", projector.c_str());
    std::vector<param::ReferenceUv> reference;
    param::mapVerticesReference(base, frame, mesh.positions, normals, reference);
    const bool wraps = param::traitsOf(base.surface).wraps;
    for (Precision precision : precisions)
      for (MathMode math : maths) {
        if (!wraps && math != maths.front()) continue;  // no arctangent: the math mode changes nothing
        param::ProjectorOptions options = base;
        options.arithmetic = {precision, wraps ? math : MathMode::Exact};
        std::vector<param::VertexUv> out;
        param::Projector(options, frame).mapVertices(mesh.positions, normals, out);
        const param::MappingError error = param::mappingError(out, reference, precision, wraps);
        for (int threads : threadCounts) {
          MappingCase c{options, threads, "map/" + std::to_string(cases.size()), error};
          cases.push_back(c);
          // The narrow kernel (param/uv_kernel.h): the same bits as `out`, whose error is above.
          const auto iteration = [options, frame, threads](auto points, auto& uvs) {  // points: shared, outlives the loop
            return std::function<const void*()>([points, &uvs, options, frame, threads] {
              param::mapUvs(options, frame, *points, uvs, threads);
              return static_cast<const void*>(uvs.u.data());
            });
          };
          timed.push_back({c.name,
                           precision == Precision::Float ? iteration(floatPoints, floatUvs)
                                                         : iteration(doublePoints, doubleUvs),
                           a.minTime});
        }
      }
  }
  if (!quiet()) std::fprintf(stderr, "uvtk bench: timing %zu mapping configurations ...\n", cases.size());
  const std::vector<double> seconds = benchmarkRunner().run(timed);

  std::vector<nlohmann::json> records;
  const double vertices = double(mesh.vertexCount());
  for (const MappingCase& c : cases) {
    const param::ProjectorOptions& o = c.options;
    records.push_back({{"section", "mapping"},
                       {"projector", inspect::projectorOptionsJson(o)["projector"]},
                       {"omap", a.omap},
                       {"precision", param::precisionName(o.arithmetic.precision)},
                       {"math", param::mathName(o.arithmetic.math)},
                       {"threads", c.threads},
                       {"vertices", mesh.vertexCount()},
                       {"ns_per_vertex", seconds[std::size_t(&c - cases.data())] * 1e9 / vertices},
                       {"max_err_ulp", c.error.maxUlp},
                       {"p99_err_ulp", c.error.p99Ulp},
                       {"max_err_texels", c.error.maxUv * a.textureWidth},
                       {"p99_err_texels", c.error.p99Uv * a.textureWidth},
                       {"mean_err_texels", c.error.meanUv * a.textureWidth},
                       {"state_mismatches", c.error.stateMismatches}});
  }
  return records;
}

// ---- The peer ----

// What the table says of the peer when it has no rows; empty when it has them or was not asked for.
std::string peerNote(const BenchOptions& a) {
  if (!a.peers || peers::assimpAvailable()) return "";
  return "Peer: assimp's aiProcess_GenUVCoords is not available (" + peers::assimpUnavailableReason() +
         "; the plugin is built when libassimp-dev is installed, which scripts/setup.sh does), so the table has no "
         "assimp rows.\n\n";
}

std::vector<nlohmann::json> benchPeers(const BenchOptions& a, const Mesh& mesh) {
  std::vector<nlohmann::json> records;
  if (!a.peers) return records;
  if (!peers::assimpAvailable()) {
    if (!quiet()) std::fprintf(stderr, "uvtk bench: %s", peerNote(a).c_str());
    return records;
  }
  const std::pair<const char*, peers::AssimpMapping> mappings[] = {{"plane", peers::AssimpMapping::Plane},
                                                                   {"cylinder", peers::AssimpMapping::Cylinder},
                                                                   {"sphere", peers::AssimpMapping::Sphere}};
  // Indexed: the mesh's own shared vertices, as ours are timed; verbose: one vertex per corner, the
  // layout assimp's importers hand the step.
  const std::pair<const char*, peers::AssimpLayout> layouts[] = {{"indexed", peers::AssimpLayout::Indexed},
                                                                 {"verbose", peers::AssimpLayout::Verbose}};
  for (const auto& [name, mapping] : mappings)
    for (const auto& [layoutName, layout] : layouts) {
      if (!quiet()) std::fprintf(stderr, "uvtk bench: assimp %s, %s ...\n", name, layoutName);
      const std::optional<peers::PeerTiming> t = peers::measureAssimpGenUvCoords(mesh, mapping, 5, layout);
      if (!t) continue;
      records.push_back({{"section", "peer"},
                         {"projector", std::string("assimp-") + name + " " + layoutName},
                         {"omap", "isn"},
                         {"precision", "float"},
                         {"math", "libm"},
                         {"threads", 1},
                         {"vertices", mesh.vertexCount()},
                         {"ns_per_vertex", t->nsPerMeshVertex},
                         {"ns_per_corner", t->nsPerVertex},
                         {"max_err_ulp", nullptr},
                         {"max_err_texels", nullptr},
                         {"note",
                          "aiProcess_GenUVCoords on the mesh's vertices (indexed) or one vertex per corner (verbose); "
                          "per vertex of the mesh for comparison; its own conventions, so no error is measured"}});
    }
  return records;
}

// ---- End to end ----

// Milliseconds to read `path` whole in 1 MiB blocks, and, when `copy` is not empty, to write what
// was read there too: the I/O floor of a job that reads one file and writes another (cat, cp).
double ioFloorMs(const std::string& path, const std::string& copy) {
  const auto start = std::chrono::steady_clock::now();
  std::FILE* in = std::fopen(path.c_str(), "rb");
  std::FILE* out = copy.empty() ? nullptr : std::fopen(copy.c_str(), "wb");
  if (!in || (!copy.empty() && !out)) throw OutputError(path + ": error: cannot time reading and copying it");
  std::vector<char> block(std::size_t(1) << 20);
  for (std::size_t n; (n = std::fread(block.data(), 1, block.size(), in)) > 0;)
    if (out && std::fwrite(block.data(), 1, n, out) != n) throw OutputError(copy + ": error: cannot write");
  std::fclose(in);
  if (out) std::fclose(out);
  return millisecondsSince(start);
}

// `uvtk map MESH -o FILE --json` as a user runs it, in a child process so that its peak memory is
// its own, once per thread count; beside it, in the same run, the floor: reading the input (cat)
// and copying the output (cp).
std::vector<nlohmann::json> benchEndToEnd(const BenchOptions& a) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() / ("uvtk-bench-" + std::to_string(getpid()));
  std::error_code ignored;
  fs::create_directories(folder, ignored);
  // The input's own format where it holds UVs (OFF and STL do not: OBJ then).
  const std::optional<io::MeshFormat> format = io::outputFormatOf(a.mesh);
  const io::MeshFormat written = format && io::writesUvs(*format) ? *format : io::MeshFormat::obj;
  const std::string output = (folder / ("mapped" + std::string(io::extensionOf(written)))).string();
  const std::string json = (folder / "mapped.json").string();
  std::vector<nlohmann::json> records;
  for (int threads : a.threads) {
    if (!quiet()) std::fprintf(stderr, "uvtk bench: uvtk map %s on %d thread%s ...\n", a.mesh.c_str(), threads,
                               threads == 1 ? "" : "s");
    const double readFloorMs = ioFloorMs(a.mesh, "");  // also brings the input into the page cache
    std::fflush(nullptr);
    const pid_t child = fork();
    if (child < 0) throw OutputError("uvtk bench: cannot start the mapping process");
    if (child == 0) {
      int status = 0;
      try {
        MapJob job;
        job.settings.projector.options = a.mapProjector.options;
        job.settings.threads = threads;
        setProgressEnabled(false);
        mapMesh({a.mesh, output, json}, job, false);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        status = exitStatus(e);
      }
      std::fflush(nullptr);
      _exit(status);
    }
    int status = 0;
    rusage usage{};
    wait4(child, &status, 0, &usage);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      fs::remove_all(folder, ignored);
      throwWithStatus(WIFEXITED(status) ? WEXITSTATUS(status) : 1, "uvtk bench: uvtk map " + a.mesh + " failed");
    }
    const double copyFloorMs = ioFloorMs(output, (folder / "copy").string());
    const nlohmann::json stages = nlohmann::json::parse(std::ifstream(json))["milliseconds"];
    const double floorMs = readFloorMs + copyFloorMs, outputBytes = double(fs::file_size(output));
    const double peakBytes = 1024.0 * double(usage.ru_maxrss);
    nlohmann::json r = {{"section", "end-to-end"},     {"mesh", a.mesh},
                        {"projector", a.mapProjector.name}, {"threads", threads},
                        {"milliseconds", stages},      {"floor_ms", floorMs},
                        {"ratio_to_floor", stages["total"].get<double>() / floorMs},
                        {"peak_bytes", peakBytes},     {"output_bytes", outputBytes},
                        {"peak_per_output_byte", peakBytes / outputBytes}};
    records.push_back(std::move(r));
    fs::remove((folder / "copy"), ignored);
  }
  fs::remove_all(folder, ignored);
  return records;
}

// ---- Rendering ----

std::vector<nlohmann::json> benchRendering(const BenchOptions& a, const Mesh& mesh) {
  const std::vector<int>& threadCounts = a.threads;
  const std::vector<int>& sampleCounts = a.samples;
  // The scene as `uvtk render` sets it up (cli::renderMeshFile): the camera made on the mesh read,
  // the mesh mapped, the renderer's options of the frame and the texture. Each row then sets its
  // filter, samples and threads.
  const render::Camera camera = a.camera.make(mesh, a.mesh, Mat4::Identity(), a.frame.width, a.frame.height);
  const MappedMesh mapped = mapByProjector(mesh, a.renderProjector.options, false);
  const render::TexcoordSource perVertex = mapped.texcoordSource(false), perPixel = mapped.texcoordSource(true);
  const render::RenderOptions base = renderOptions(a.frame, a.textureOptions, a.texture, camera, Mat4::Identity());

  struct RenderCase {
    std::string name, uv;
    render::Filter filter;
    int spp, threads;
    double rmse = 0, maxError = 0;
  };
  std::vector<RenderCase> cases;
  std::vector<runner::TimedCase> timed;  // one per case
  std::vector<std::unique_ptr<render::RenderOptions>> optionStore;
  auto add = [&](const std::string& uv, render::Filter filter, int spp, int threads) {
    auto options = std::make_unique<render::RenderOptions>(base);
    options->sampler = render::samplerFor(filter, a.textureOptions.wrap);
    options->samplesPerPixel = spp;
    options->raster.threads = threads;
    cases.push_back({"render/" + std::to_string(cases.size()), uv, filter, spp, threads});
    const render::TexcoordSource* source = uv == "per-pixel" ? &perPixel : &perVertex;
    const render::RenderOptions* o = options.get();
    optionStore.push_back(std::move(options));
    timed.push_back({cases.back().name,
                     [&mapped, source, o, frame = std::make_shared<render::Rendering>()] {
                       *frame = render::render(mapped.mesh, *source, *o);
                       return static_cast<const void*>(frame.get());
                     },
                     a.minTime});
  };
  // Per-vertex UVs (the default): every row interpolates them, and one row per thread count
  // evaluates them per pixel to show what exact UVs cost. --uv per-pixel: every row evaluates them,
  // as the user's scene is drawn; interpolated rows would time a picture it never draws.
  const char* uv = a.frame.perPixel ? "per-pixel" : "per-vertex";
  for (int threads : threadCounts) {
    add(uv, a.filter, 1, threads);
    if (!a.frame.perPixel) add("per-pixel", a.filter, 1, threads);
    for (render::Filter filter : a.filters)
      if (filter != a.filter) add(uv, filter, 1, threads);  // the first row has it
    for (int spp : sampleCounts)
      if (spp > 1) add(uv, a.filter, spp, threads);
  }
  if (!quiet()) std::fprintf(stderr, "uvtk bench: the 64-sample reference frame ...\n");
  render::RenderOptions referenceOptions = base;
  referenceOptions.sampler = render::samplerFor(render::Filter::LinearMipmapLinear, a.textureOptions.wrap);
  referenceOptions.samplesPerPixel = 64;
  const Image reference = render::render(mapped.mesh, perPixel, referenceOptions).colour;
  for (RenderCase& c : cases) {
    const Image image = render::render(mapped.mesh, c.uv == "per-pixel" ? perPixel : perVertex,
                                       *optionStore[std::size_t(&c - cases.data())])
                            .colour;
    double sum = 0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
      const double d = double(image.pixels[i]) - double(reference.pixels[i]);
      sum += d * d;
      c.maxError = std::max(c.maxError, std::fabs(d));
    }
    c.rmse = std::sqrt(sum / double(image.pixels.size()));
  }

  // The UV error of interpolation, once: it depends on neither filter nor threads.
  views::UvErrorMap uvError;
  if (!a.frame.perPixel) {
    views::ViewOptions viewOptions;
    viewOptions.render = base;
    uvError = views::uvErrorMap(mapped.viewInput(nullptr), viewOptions);
  }

  if (!quiet()) std::fprintf(stderr, "uvtk bench: timing %zu rendering configurations ...\n", cases.size());
  const std::vector<double> seconds = benchmarkRunner().run(timed);
  const Vec3 eye = camera.eye();
  std::vector<nlohmann::json> records;
  for (const RenderCase& c : cases) {
    const bool perPixelUv = c.uv == "per-pixel";
    records.push_back({{"section", "rendering"},
                       {"projector", a.renderProjector.name},
                       {"triangles", mapped.mesh.faceCount()},
                       {"width", a.frame.width},
                       {"height", a.frame.height},
                       {"camera", a.camera.explicitCamera() ? "explicit" : "auto"},
                       {"projection", a.camera.orthographic() ? "orthographic" : "perspective"},
                       {"eye", {eye.x(), eye.y(), eye.z()}},
                       {"texture", a.textureSource},
                       {"wrap", nameOf(kWrapNames, a.textureOptions.wrap)},
                       {"env", nameOf(kEnvNames, a.textureOptions.env)},
                       {"seamless", a.textureOptions.seamless},
                       {"two_sided", a.textureOptions.twoSided},
                       {"cull", nameOf(kCullNames, a.frame.cull)},
                       {"background", {a.frame.background.x(), a.frame.background.y(), a.frame.background.z()}},
                       {"filter", nameOf(kFilterNames, c.filter)},
                       {"uv", c.uv},
                       {"spp", c.spp},
                       {"threads", c.threads},
                       {"ms_per_frame", seconds[std::size_t(&c - cases.data())] * 1e3},
                       {"rmse", c.rmse},
                       {"max_err", c.maxError},
                       {"uv_err_max_texels", perPixelUv ? 0.0 : uvError.max},
                       {"uv_err_mean_texels", perPixelUv ? 0.0 : uvError.mean}});
  }
  return records;
}

// ---- Output ----

std::string formatNumber(const nlohmann::json& value, const char* format) {
  if (value.is_null()) return "-";
  char text[64];
  std::snprintf(text, sizeof text, format, value.get<double>());
  return text;
}

std::string markdownTables(const std::vector<nlohmann::json>& records, int textureWidth) {
  std::string md;
  bool mappingHeader = false, renderHeader = false, endToEndHeader = false;
  for (const nlohmann::json& r : records) {
    if (r["section"] == "end-to-end") {
      if (!endToEndHeader)
        md += std::string(md.empty() ? "" : "\n") + "| uvtk map | threads | read | map | seams | judge | write | total ms | floor ms (cat + cp) | x floor | "
              "peak MB | output MB | peak / output |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
            endToEndHeader = true;
      const nlohmann::json& ms = r["milliseconds"];
      md += "| " + r["projector"].get<std::string>() + " | " + std::to_string(r["threads"].get<int>()) + " | " +
            formatNumber(ms["read"], "%.0f") + " | " + formatNumber(ms["map"], "%.0f") + " | " +
            formatNumber(ms["seams"], "%.0f") + " | " + formatNumber(ms["judge"], "%.0f") + " | " +
            formatNumber(ms["write"], "%.0f") + " | " + formatNumber(ms["total"], "%.0f") + " | " +
            formatNumber(r["floor_ms"], "%.0f") + " | " + formatNumber(r["ratio_to_floor"], "%.2f") + " | " +
            formatNumber(r["peak_bytes"].get<double>() / 1e6, "%.0f") + " | " +
            formatNumber(r["output_bytes"].get<double>() / 1e6, "%.0f") + " | " +
            formatNumber(r["peak_per_output_byte"], "%.2f") + " |\n";
    } else if (r["section"] != "rendering") {
      if (!mappingHeader)
        md += std::string(md.empty() ? "" : "\n") +
            "| projector | omap | precision | math | threads | ns/vertex | max err (ulp) | p99 err (ulp) | max err "
            "(texels @" +
            std::to_string(textureWidth) + ") | p99 err (texels) |\n|---|---|---|---|---|---|---|---|---|---|\n",
            mappingHeader = true;
      md += "| " + r["projector"].get<std::string>() + " | " + r["omap"].get<std::string>() + " | " +
            r["precision"].get<std::string>() + " | " + r["math"].get<std::string>() + " | " +
            std::to_string(r["threads"].get<int>()) + " | " + formatNumber(r["ns_per_vertex"], "%.2f") + " | " +
            formatNumber(r["max_err_ulp"], "%.3g") + " | " +
            formatNumber(r.value("p99_err_ulp", nlohmann::json()), "%.3g") + " | " +
            formatNumber(r["max_err_texels"], "%.3g") + " | " +
            formatNumber(r.value("p99_err_texels", nlohmann::json()), "%.3g") + " |\n";
    } else {
      if (!renderHeader)
        md += "\nScene: camera " + r["camera"].get<std::string>() + " (" + r["projection"].get<std::string>() +
              "), texture " + r["texture"].get<std::string>() + ", wrap " + r["wrap"].get<std::string>() + ", env " +
              r["env"].get<std::string>() + (r["seamless"].get<bool>() ? ", seamless" : "") + ", cull " +
              r["cull"].get<std::string>() + ".\n" +
              "\n| triangles | size | uv | filter | spp | threads | ms/frame | RMSE vs 64 spp | max err | UV err max "
              "(texels) | UV err mean (texels) |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
            renderHeader = true;
      md += "| " + std::to_string(r["triangles"].get<std::size_t>()) + " | " + std::to_string(r["width"].get<int>()) +
            "x" + std::to_string(r["height"].get<int>()) + " | " + r["uv"].get<std::string>() + " | " +
            r["filter"].get<std::string>() + " | " + std::to_string(r["spp"].get<int>()) + " | " +
            std::to_string(r["threads"].get<int>()) + " | " + formatNumber(r["ms_per_frame"], "%.1f") + " | " +
            formatNumber(r["rmse"], "%.4f") + " | " + formatNumber(r["max_err"], "%.3f") + " | " +
            formatNumber(r["uv_err_max_texels"], "%.3g") + " | " + formatNumber(r["uv_err_mean_texels"], "%.3g") +
            " |\n";
    }
  }
  return md;
}

// Speed against accuracy, one point per configuration of the mapping or the rendering, grouped by
// projector or by UVs: what both the PNG and the SVG chart draw.
BenchChart chartOf(const std::vector<nlohmann::json>& records, bool rendering, int textureWidth) {
  BenchChart chart;
  views::ParetoChartOptions& options = chart.options;
  for (const nlohmann::json& r : records) {
    if ((r["section"] == "rendering") != rendering || r["section"] == "peer" || r["section"] == "end-to-end") continue;
    const std::string group = rendering ? r["uv"].get<std::string>() : r["projector"].get<std::string>();
    auto found = std::find(options.groupNames.begin(), options.groupNames.end(), group);
    if (found == options.groupNames.end()) found = options.groupNames.insert(found, group);
    views::ChartPoint p;
    p.group = int(found - options.groupNames.begin());
    if (rendering) {
      p.label = r["filter"].get<std::string>() + " " + std::to_string(r["spp"].get<int>()) + " spp T" +
                std::to_string(r["threads"].get<int>());
      p.x = r["ms_per_frame"].get<double>();
      p.y = r["rmse"].get<double>();
    } else {
      p.label = r["projector"].get<std::string>() + " " + r["precision"].get<std::string>() + " " +
                r["math"].get<std::string>() + " T" + std::to_string(r["threads"].get<int>());
      p.x = r["ns_per_vertex"].get<double>();
      p.y = r["max_err_texels"].get<double>();
    }
    chart.points.push_back(p);
  }
  options.title = rendering ? "Rendering: time per frame against RMSE to a 64-sample reference"
                            : "Mapping: time per vertex against max error";
  options.xLabel = rendering ? "ms per frame" : "ns per vertex";
  options.yLabel = rendering ? "RMSE" : "max error, texels at " + std::to_string(textureWidth);
  return chart;
}

// The Markdown of markdownTables as HTML: its tables as tables, its other lines as paragraphs.
std::string htmlOfMarkdown(const std::string& md) {
  std::string html;
  bool inTable = false, header = false;
  std::size_t begin = 0;
  for (std::size_t end; begin < md.size(); begin = end + 1) {
    end = std::min(md.find('\n', begin), md.size());
    const std::string line = md.substr(begin, end - begin);
    if (line.rfind("|", 0) != 0) {
      if (inTable) html += "</table>\n", inTable = false;
      if (!line.empty()) html += "<p>" + xmlEscaped(line) + "</p>\n";
      continue;
    }
    if (line.rfind("|---", 0) == 0) continue;  // the separator below the header
    if (!inTable) html += "<table>\n", inTable = header = true;
    std::string row = "<tr>";
    const char* cell = header ? "th" : "td";
    for (std::size_t at = 1; at < line.size();) {
      const std::size_t next = std::min(line.find('|', at), line.size());
      std::string text = line.substr(at, next - at);
      text.erase(0, text.find_first_not_of(' '));
      text.erase(text.find_last_not_of(' ') + 1);
      if (next < line.size()) row += std::string("<") + cell + ">" + xmlEscaped(text) + "</" + cell + ">";
      at = next + 1;
    }
    html += row + "</tr>\n";
    header = false;
  }
  return html + (inTable ? "</table>\n" : "");
}

// One self-contained page: the charts inline, then the tables; nothing external, no script.
std::string benchHtml(const BenchResult& result) {
  const std::size_t firstLineEnd = result.markdown.find('\n');
  std::string html = pageStart("uvtk bench") +
                     "<style>svg{max-width:100%;height:auto}td{text-align:right}td:first-child{text-align:left}</style>\n<p>" +
                     xmlEscaped(result.markdown.substr(0, firstLineEnd)) + "</p>\n";
  html += "<h2>Mapping</h2>\n<figure>" + result.mappingSvg + "</figure>\n";
  if (!result.renderingSvg.empty()) html += "<h2>Rendering</h2>\n<figure>" + result.renderingSvg + "</figure>\n";
  html += "<h2>Tables</h2>\n" + htmlOfMarkdown(result.markdown.substr(std::min(firstLineEnd, result.markdown.size())));
  return html + "</body>\n</html>\n";
}

// `path` with `suffix` before its extension.
std::string withSuffix(const std::string& path, const std::string& suffix) {
  const std::size_t dot = path.find_last_of('.');
  return dot == std::string::npos ? path + suffix : path.substr(0, dot) + suffix + path.substr(dot);
}

// Whole numbers in [low, high], each; `fallback` when not given.
std::vector<int> counts(const param::ParameterDictionary& p, const std::string& name, int low, int high,
                        std::vector<int> fallback) {
  if (!p.given(name)) return fallback;
  std::vector<int> values;
  for (const double v : p.getNumberList(name)) {
    if (v != std::floor(v) || v < low || v > high)
      throw UsageError(p.spelled(name) + ": expected whole numbers in [" + std::to_string(low) + ", " +
                       std::to_string(high) + "]");
    values.push_back(int(v));
  }
  if (values.empty()) throw UsageError(p.spelled(name) + ": expected at least one value");
  return values;
}

// The values a list of names gives; `fallback`'s names when not given.
template <class Value>
std::vector<Value> choices(const param::ParameterDictionary& p, const std::string& name, const ChoiceNames<Value>& table,
                           const std::vector<std::string>& fallback) {
  return namedValues(p.given(name) ? p.getTexts(name) : fallback, table, p.spelled(name));
}

// A projector with its default options, by name and O-mapping.
param::ProjectorOptions projectorNamed(const param::ParameterDictionary& p, const std::string& name,
                                       const std::string& surface, param::RayKind ray) {
  param::ProjectorOptions o;
  o.surface = namedValues({surface}, param::kSurfaceNames, p.spelled(name)).at(0);
  o.ray = ray;
  return o;
}

}  // namespace

BenchOptions readBenchOptions(const param::ParameterDictionary& p) {
  BenchOptions o;
  o.mesh = p.getText("mesh").value_or("");
  o.minTime = p.getNumber("min-time", o.minTime);
  if (!(o.minTime > 0)) throw UsageError(p.spelled("min-time") + ": expected seconds > 0");
  o.textureWidth = p.getInteger("texture-width", o.textureWidth, std::numeric_limits<int>::min(),
                                std::numeric_limits<int>::max());
  if (o.textureWidth < 1) throw UsageError(p.spelled("texture-width") + ": expected a positive number of texels");
  o.json = p.getText("json").value_or("");
  o.markdown = p.getText("markdown").value_or("");
  o.plot = p.getText("plot").value_or("");
  o.html = p.getText("html").value_or("");
  // Every output's folder is checked before the first measurement.
  for (const std::string* path : {&o.json, &o.markdown, &o.plot, &o.html}) {
    const std::filesystem::path folder = std::filesystem::path(*path).parent_path();
    std::error_code error;
    if (!path->empty() && !folder.empty() && !std::filesystem::is_directory(folder, error))
      throw UsageError(*path + ": the folder " + folder.string() + " does not exist");
  }
  o.precisions = choices(p, "precision", param::kPrecisionNames, {"double", "float"});
  o.maths = choices(p, "math", param::kMathNames, {"exact", "fast", "fast-u10"});
  o.threads = counts(p, "threads", 1, 256, {1});
  o.omap = p.getText("omap").value_or(o.omap);
  const param::RayKind ray = namedValues({o.omap}, param::kRayNames, p.spelled("omap")).at(0);
  const std::vector<std::string> projectors =
      p.given("projector") ? p.getTexts("projector") : std::vector<std::string>{"plane", "two-plane", "cylinder", "sphere"};
  for (const std::string& projector : projectors) {
    o.projectors.push_back({projector, projectorNamed(p, "projector", projector, ray)});
    if (param::traitsOf(o.projectors.back().options.surface).choosesPerTriangle)
      throw UsageError(p.spelledWith("projector", projector) +
                       ": it chooses a projection per triangle; `uvtk bench` times per-vertex mappings");
  }
  o.peers = !p.getBool("no-peers", false);
  o.endToEnd = !p.getBool("no-end-to-end", false);
  const std::string mapProjector = p.getText("map-projector").value_or("sphere");
  o.mapProjector = {mapProjector, projectorNamed(p, "map-projector", mapProjector, ray)};
  o.rendering = p.getBool("render", false);
  const std::string renderProjector = p.getText("render-projector").value_or("sphere");
  o.renderProjector = {renderProjector, projectorNamed(p, "render-projector", renderProjector, param::RayKind::SurfaceNormal)};
  // Rendering's parameters are checked with or without --render, as the others.
  const std::vector<int> samples = counts(p, "spp", 1, 256, {1, 4, 16});
  // filter given: the one filter timed; else the sweep, and the UV and sample-count rows in
  // linear_mipmap_linear.
  const bool filterGiven = p.given("filter");
  if (filterGiven && p.given("filters"))
    throw UsageError(p.spelled("filter") + " and " + p.spelled("filters") + " exclude each other: " +
                     p.spelled("filter") + " times one filter, " + p.spelled("filters") + " several");
  const TextureSettings texture = readTextureSettings(p, "texture");
  const std::vector<render::Filter> filters =
      filterGiven ? std::vector<render::Filter>{texture.filter} : choices(p, "filters", kFilterNames, namesOf(kFilterNames));
  const FrameOptions frame = readFrameSceneSettings(p).frame;
  const CameraSettings camera = readCameraSettings(p);
  if (!o.rendering) return o;
  o.samples = samples;
  o.filters = filters;
  o.filter = filterGiven ? texture.filter : render::Filter::LinearMipmapLinear;
  // A cube map is looked up per face: the cube projector's faces layout (its map default is the cross).
  if (texture.cubeMap()) o.renderProjector.options.cubeLayout = CubeLayout::Faces;
  checkTextureUse(frame, texture, &o.renderProjector.options);  // as `uvtk render` refuses, before any work
  o.frame = frame;
  o.camera = camera;
  o.textureSource = texture.source;
  o.textureOptions = texture.options();
  TextureSettings mipmapped = texture;  // the reference reads the mipmaps; level 0 is the texture
  mipmapped.filter = render::Filter::LinearMipmapLinear;
  o.texture = mipmapped.load();
  return o;
}

std::vector<std::string> benchParameterNames() {
  std::vector<std::string> names = {"mesh",          "projector", "omap",       "precision",        "math",
                                    "threads",       "texture-width", "min-time", "json",           "markdown",
                                    "plot",          "html",      "no-peers",   "map-projector",    "no-end-to-end",
                                    "render",        "render-projector", "filters", "spp"};
  for (const std::vector<std::string>& more :
       {cameraParameterNames(), textureParameterNames("texture"), frameSceneParameterNames()})
    names.insert(names.end(), more.begin(), more.end());
  return names;
}

BenchResult measureBench(const BenchOptions& a) {
  BenchResult result;
  std::vector<nlohmann::json>& records = result.records;
  // First, from a process that holds no mesh yet (a forked child's peak counts the pages it shares).
  if (!a.mesh.empty() && a.endToEnd) records = benchEndToEnd(a);
  Mesh mesh;
  std::string& meshName = result.mesh;
  if (a.mesh.empty()) {
    if (!quiet()) std::fprintf(stderr, "uvtk bench: building the 2048 x 1024 lat-long sphere ...\n");
    mesh = meshes::latLongSphere(2048, 1024);
    meshName = "built-in lat-long sphere 2048 x 1024";
  } else {
    mesh = io::readMesh(a.mesh).mesh;
    meshName = a.mesh;
  }
  for (nlohmann::json& r : benchMapping(a, mesh)) records.push_back(std::move(r));
  for (nlohmann::json& r : benchPeers(a, mesh)) records.push_back(std::move(r));
  if (a.rendering) {
    const Mesh renderMesh = a.mesh.empty() ? meshes::latLongSphere(64, 32) : mesh;
    for (nlohmann::json& r : benchRendering(a, renderMesh)) records.push_back(std::move(r));
  }

  result.markdown = "Mesh: " + meshName + " (" + std::to_string(mesh.vertexCount()) +
                    " vertices). atan2: " + param::fastMathInstructionSet() + " for fast modes.\n\n" + peerNote(a) +
                    markdownTables(records, a.textureWidth);
  result.mapping = chartOf(records, false, a.textureWidth);
  result.mappingSvg = views::paretoChartSvg(result.mapping.points, result.mapping.options);
  if (a.rendering) {
    result.rendering = chartOf(records, true, a.textureWidth);
    result.renderingSvg = views::paretoChartSvg(result.rendering.points, result.rendering.options);
  }
  return result;
}

void writeBenchOutputs(io::OutputSet& outputs, const BenchOptions& a, const BenchResult& result) {
  if (!a.markdown.empty()) outputs.writeText(a.markdown, result.markdown);
  if (!a.json.empty()) {
    const nlohmann::json j = {{"mesh", result.mesh},
                              {"texture_width", a.textureWidth},
                              {"fast_math_isa", param::fastMathInstructionSet()},
                              {"records", result.records}};
    outputs.writeText(a.json, io::jsonText(j, 2) + "\n");
  }
  if (!a.plot.empty()) {
    const auto png = [](const BenchChart& c) { return views::paretoChart(c.points, c.options); };
    io::writeImage(outputs, a.plot, png(result.mapping), io::PixelType::UInt8);
    if (a.rendering)
      io::writeImage(outputs, withSuffix(a.plot, "-render"), png(result.rendering), io::PixelType::UInt8);
  }
  if (!a.html.empty()) outputs.writeText(a.html, benchHtml(result));
}

std::string bench(const BenchOptions& a) {
  const BenchResult result = measureBench(a);
  io::OutputSet outputs;  // every file, published together (stdout gets the table once they are in place)
  writeBenchOutputs(outputs, a, result);
  outputs.publish();
  return result.markdown;
}

}  // namespace uvtk::timing
