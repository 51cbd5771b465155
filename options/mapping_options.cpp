#include "options/mapping_options.h"

#include "core/error.h"
#include "core/gl_matrices.h"
#include "options/cli_values.h"

namespace uvtk::cli {

void addMappingOptions(CLI::App& app, MappingArguments& a, param::Fit defaultFit) {
  a.app = &app;
  a.projector.options.placement.fit = defaultFit;
  a.projector.context.defaultFit = defaultFit;
  addProjectorOptions(app, a.projector);
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

param::ParameterDictionary mappingParameters(const MappingArguments& a) {
  param::ParameterDictionary parameters = a.projector.parameters();
  a.texgen.addTo(parameters);
  if (!a.model.empty()) {
    const Mat4 model = parseMatrix(a.model, "--model");
    parameters.add("model", std::vector<double>(model.data(), model.data() + 16));
  }
  return parameters;
}

ResolvedMapping resolveMapping(const MappingArguments& a) {
  return inspect::readMapping(mappingParameters(a), a.projector.context.defaultFit);
}

}  // namespace uvtk::cli
