#include "options/mapping_options.h"

#include <algorithm>

#include "core/error.h"
#include "core/gl_matrices.h"
#include "options/cli_values.h"

namespace uvtk::cli {

namespace {

// Options a projector and texgen both read, with a meaning each (see the header).
const char* const kSharedOptions[] = {"--eye", "--center", "--up", "--precision", "--help"};

std::vector<std::string> optionNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options()) names.push_back(option->get_name());
  return names;
}

}  // namespace

void addMappingOptions(CLI::App& app, MappingArguments& a, param::Fit defaultFit) {
  a.app = &app;
  const std::vector<std::string> before = optionNames(app);
  a.projector.options.placement.fit = defaultFit;
  a.projector.context.defaultFit = defaultFit;
  addProjectorOptions(app, a.projector);
  for (const std::string& name : optionNames(app))
    if (std::find(before.begin(), before.end(), name) == before.end() &&
        std::none_of(std::begin(kSharedOptions), std::end(kSharedOptions), [&](const char* s) { return name == s; }))
      a.projectorOnlyOptions.push_back(name);
  app.get_option("--fit")->default_str(defaultFit == param::Fit::None ? "none" : "bbox");
  app.get_option("--eye")->description(
      "reflection: the eye in object space (required); camera: gluLookAt eye (required); texgen: gluLookAt eye "
      "(default 0,0,0)");
  app.get_option("--center")
      ->description(
          "Explicit placement: origin x,y,z (replaces the fit); camera: gluLookAt centre (default 0,0,0); texgen: "
          "gluLookAt centre (default 0,0,-1)");
  app.get_option("--up")->description("camera: gluLookAt up; texgen: gluLookAt up (default 0,1,0 for both)");
  addTexgenOptions(app, a.texgen, "--texgen");
  app.add_option("--model", a.model,
                 "texgen: model matrix, 16 numbers column-major (default identity); eye_linear planes are given under "
                 "the view alone");
}

ResolvedMapping resolveMapping(const MappingArguments& a) {
  ResolvedMapping out;
  if (!a.isTexgen()) {
    for (const char* name : {"--model", "--texmatrix", "--no-normalize"})
      if (given(a.app, name)) throw UsageError(std::string(name) + " goes with --texgen or --s/--t/--r/--q only");
    const param::Projector projector = a.projector.resolve();
    out.projector = projector.options;
    out.seamPlaceAuto = projector.seamPlaceAuto;
    return out;
  }
  for (const std::string& name : a.projectorOnlyOptions)
    if (given(a.app, name.c_str()))
      throw UsageError(name + " is a projector option; it does not go with --texgen or --s/--t/--r/--q");
  const std::string &eye = a.projector.eye, &center = a.projector.center;
  const Mat4 view = lookAt(eye.empty() ? Vec3::Zero() : parseVec3(eye, "--eye"),
                           center.empty() ? Vec3(0, 0, -1) : parseVec3(center, "--center"),
                           a.projector.up.empty() ? Vec3::UnitY() : parseVec3(a.projector.up, "--up"));
  const Mat4 model = a.model.empty() ? Mat4::Identity() : parseMatrix(a.model, "--model");
  TexgenArguments texgen = a.texgen;
  texgen.arithmetic.precision = a.projector.options.arithmetic.precision;
  out.texgen = texgen.resolve(view, model);
  return out;
}

bool fitsToMesh(const param::ProjectorOptions& o) {
  return !o.placement.frame && o.placement.fit != param::Fit::None && param::traitsOf(o.surface).fitsToMesh;
}

}  // namespace uvtk::cli
