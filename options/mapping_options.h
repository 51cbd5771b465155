// The mapping of `uvtk eval`, `uvtk check` and the installed point API (uvtk/point.h): a projector
// with every option of `uvtk map` (and --convention), or GL texgen with every option of `uvtk
// texgen` (--texgen MODE, --s/--t/--r/--q, --texmatrix, --no-normalize) under its gluLookAt view.
// --eye and --center are shared: the reflection eye and the explicit placement's origin for a
// projector, the view's eye and centre for texgen.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "inspect/mapping_parameters.h"
#include "options/projector_cli.h"
#include "options/texgen_cli.h"

namespace uvtk::cli {

struct MappingArguments {
  ProjectorArguments projector;
  TexgenArguments texgen;
  std::string model;  // texgen's model matrix; its view's eye, centre and up are the projector's strings
  CLI::App* app = nullptr;

  bool isTexgen() const { return texgen.given(); }
};

using inspect::ResolvedMapping;

// Adds the projector options, the texgen options and the model matrix (--model) to `app`; texgen's
// view takes the projector's --eye, --center and --up (the camera projector's).
// `defaultFit` is the projector's fit when --fit is not given (`uvtk eval`: none, since points have
// no mesh to fit to unless one is named).
void addMappingOptions(CLI::App& app, MappingArguments& arguments, param::Fit defaultFit);

// The options given, typed, as inspect::readMapping reads them.
param::ParameterDictionary mappingParameters(const MappingArguments& arguments);

// inspect::readMapping of the options given. Throws UsageError for options of the other kind (a
// projector option with --texgen, --model with a projector) and for everything the projector or
// texgen options reject.
ResolvedMapping resolveMapping(const MappingArguments& arguments);

}  // namespace uvtk::cli
