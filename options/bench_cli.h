// `uvtk bench`'s options as the command line spells them (lists separated by commas), handed to
// timing::readBenchOptions as typed parameters.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "options/render_cli.h"
#include "timing/bench.h"

namespace uvtk::cli {

struct BenchArguments {
  std::string mesh;  // empty: the built-in 2048 x 1024 lat-long sphere
  std::string projectors = "plane,two-plane,cylinder,sphere", omap = "isn";
  std::string precisions = "double,float", maths = "exact,fast,fast-u10", threads = "1";
  int textureWidth = 4096;
  double minTime = 0.3;
  std::string json, markdown, plot, html;
  bool noPeers = false, noEndToEnd = false;
  std::string mapProjector = "sphere";
  // rendering: `uvtk render`'s camera, texture and frame options, and the lists timed
  bool render = false;
  std::string renderProjector = "sphere";
  CameraArguments camera;
  TextureArguments texture;
  FrameArguments frame;
  std::string filters =
      "nearest,linear,nearest_mipmap_nearest,linear_mipmap_nearest,nearest_mipmap_linear,linear_mipmap_linear";
  std::string samples = "1,4,16";
  CLI::App* app = nullptr;  // where the options were parsed

  // The options they name; UsageError for a malformed value or an output's missing folder, before
  // anything is measured.
  timing::BenchOptions resolve() const;
};

void addBenchOptions(CLI::App& app, BenchArguments& arguments);

}  // namespace uvtk::cli
