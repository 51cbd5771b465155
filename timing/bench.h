// The speed-accuracy trade measured in one run on the same data, as `uvtk bench` runs it. Mapping:
// every projector x precision x math mode x thread count, nanoseconds per vertex (Google
// Benchmark) and the error against the long-double reference. Rendering, of the scene `uvtk render`
// draws from the same camera, texture and frame options: per-vertex against per-pixel UVs, and each
// filter and sample count against a 64-sample supersampled reference. The peer, assimp's
// aiProcess_GenUVCoords, in the same run when it was built in. A Markdown table, JSON records,
// Pareto charts as PNG, and one HTML page with the charts as SVG and the tables (docs/precision.md).
// Its own target, uvtk_timing: only the program and scenes link Google Benchmark.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/arithmetic.h"
#include "inspect/frame.h"
#include "inspect/mapped_mesh.h"
#include "io/atomic_file.h"
#include "inspect/render_parameters.h"
#include "param/parameters.h"
#include "param/projector.h"
#include "views/pareto.h"

namespace uvtk::timing {

// A projector as named on the command line (the progress lines and records use the name) and its
// default options.
struct BenchProjector {
  std::string name;
  param::ProjectorOptions options;
};

struct BenchOptions {
  std::string mesh;  // empty: the built-in 2048 x 1024 lat-long sphere (64 x 32 for rendering)
  // Mapping: per-vertex projectors (not the cube), all with the O-mapping named `omap`.
  std::vector<BenchProjector> projectors;
  std::string omap = "isn";
  std::vector<Precision> precisions;
  std::vector<MathMode> maths;  // the first only for surfaces without an arctangent
  std::vector<int> threads;
  int textureWidth = 4096;  // texels across the texture errors are measured in
  double minTime = 0.3;     // seconds each configuration runs at least
  bool peers = true;
  // `uvtk map` of the mesh file end to end (with `mesh` only), by this projector, once per thread count.
  bool endToEnd = true;
  BenchProjector mapProjector;
  // Rendering, when `rendering`: the scene as `uvtk render` sets it up from the same options.
  bool rendering = false;
  BenchProjector renderProjector;
  inspect::CameraSettings camera;  // made on the rendered mesh
  std::string textureSource;    // as given
  inspect::BoundTexture texture;  // loaded, with mipmaps (the 64-sample reference reads them)
  inspect::TextureOptions textureOptions;
  inspect::FrameOptions frame;  // size, culling, background, per-pixel UVs
  render::Filter filter = render::Filter::LinearMipmapLinear;  // of the UV and sample-count rows
  std::vector<render::Filter> filters;                          // the sweep
  std::vector<int> samples;                                     // per pixel
  // Outputs, none when empty; published together.
  std::string json, markdown, plot;  // plot: the mapping's Pareto chart, and FILE-render.png with `rendering`
  std::string html;                  // the charts as SVG and the tables, one self-contained page
};

// `uvtk bench`'s parameters, as the command line, a scene's bench output and the tests give them:
// mesh, projector (a list of names), omap, precision and math (lists of names), threads (a list of
// counts), texture-width, min-time, json, markdown, plot, html (files; their folders must exist),
// no-peers, map-projector, no-end-to-end; render, render-projector, the camera's, the texture's
// ("texture") and the frame's scene parameters, filters, spp (a list of counts). UsageError for a
// malformed value before anything is measured.
BenchOptions readBenchOptions(const param::ParameterDictionary& parameters);
std::vector<std::string> benchParameterNames();

// A Pareto chart's points and texts, drawn as PNG (views::paretoChart) and as SVG (views::paretoChartSvg).
struct BenchChart {
  std::vector<views::ChartPoint> points;
  views::ParetoChartOptions options;
};

// What one run measured.
struct BenchResult {
  std::string mesh;                     // the mesh file, or the built-in sphere's name
  std::string markdown;                 // a line naming the mesh, then the tables
  std::vector<nlohmann::json> records;  // one per configuration, as --json writes them
  BenchChart mapping, rendering;        // rendering: with `rendering` only
  std::string mappingSvg;               // the mapping's chart as an <svg> element
  std::string renderingSvg;             // the rendering's, with `rendering`; else empty
};

// Measures (progress on stderr) and writes nothing.
BenchResult measureBench(const BenchOptions& options);

// Stages the outputs `options` names (json, markdown, plot, html) in `outputs`.
void writeBenchOutputs(io::OutputSet& outputs, const BenchOptions& options, const BenchResult& result);

// Measures, writes the outputs, publishes them together, and returns the Markdown tables.
std::string bench(const BenchOptions& options);

}  // namespace uvtk::timing
