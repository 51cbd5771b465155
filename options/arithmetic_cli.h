// --precision and --math: the speed-accuracy choices (docs/precision.md), shared by every
// subcommand that maps or generates texture coordinates, and by `uvtk bench`.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/arithmetic.h"
#include "param/projector_names.h"  // the names of --precision and --math

namespace uvtk::cli {

// Adds --precision (and --math unless `withMath` is false: texgen has no transcendental function).
void addArithmeticOptions(CLI::App& app, Arithmetic& arithmetic, bool withMath = true);

nlohmann::json arithmeticJson(const Arithmetic& arithmetic);

}  // namespace uvtk::cli
