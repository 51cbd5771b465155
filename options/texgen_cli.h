// The texgen options of `uvtk texgen`, shared with `uvtk render`: the generation of each
// coordinate, a mode shortcut, the texture matrix and GL_NORMALIZE. The view and model matrices
// come from the subcommand (texgen's own --eye/--center/--up, render's camera).
#pragma once

#include <CLI/CLI.hpp>
#include <array>
#include <string>

#include "param/parameters.h"
#include "texgen/texgen.h"

namespace uvtk::cli {

struct TexgenArguments {
  std::array<std::string, 4> coordinates;  // --s --t --r --q as given, empty when absent
  std::string mode;                        // the shortcut option's value, empty when absent
  std::string textureMatrix;
  bool noNormalize = false;
  Arithmetic arithmetic;  // --precision in `uvtk texgen` (no --math: no transcendental function); render sets it
  std::string shortcutOption;  // the shortcut's name as registered, for messages

  bool given() const;  // any coordinate option or the shortcut
  // The options given, typed, as inspect::readTexgen reads them (the shortcut under its own name).
  void addTo(param::ParameterDictionary& parameters) const;
  // inspect::readTexgen of the options given. Throws UsageError for a malformed or disallowed
  // coordinate. Without any coordinate option s and t are OBJECT_LINEAR with GL's default planes.
  texgen::TexgenOptions resolve(const Mat4& view, const Mat4& model) const;
};

// `shortcut` names the mode shortcut option: "--mode" in `uvtk texgen`, "--texgen" in `uvtk
// render`, where it also takes object_linear and eye_linear (s and t with GL's default planes).
void addTexgenOptions(CLI::App& app, TexgenArguments& arguments, const std::string& shortcut);
// `uvtk texgen`'s --threads: those the mesh is read and written with (and the library's mapping judged).
void addTexgenThreadsOption(CLI::App& app, int& threads);
// `uvtk texgen`'s view and model (--eye, --center, --up, --model), shared with the library's TexgenOptions.
void addTexgenViewOptions(CLI::App& app, std::string& eye, std::string& center, std::string& up, std::string& model);

}  // namespace uvtk::cli
