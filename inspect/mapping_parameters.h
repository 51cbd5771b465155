// A mapping at points, read from typed parameters: a projector (makeProjector) or OpenGL's texgen,
// as `uvtk eval`, `uvtk check`, `uvtk texgen`, `uvtk render`, the point API (uvtk/point.h) and
// Python's uvtk.eval ask for it. Every face fills a ParameterDictionary; the rules (which
// parameters go with which, the texgen modes each coordinate takes) live here once.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "param/make_projector.h"
#include "texgen/texgen.h"

namespace uvtk::inspect {

// Exactly one of the two is set.
struct ResolvedMapping {
  std::optional<param::ProjectorOptions> projector;
  std::optional<texgen::TexgenOptions> texgen;
  bool seamPlaceAuto = false;  // seam-place auto: the caller, which has the mesh, places the seam
};

// OpenGL's texgen from "s", "t", "r", "q" (each "MODE" or "MODE:a,b,c,d", the plane; GL's default
// plane otherwise), the shortcut `shortcut` (every coordinate it implies in one mode: "mode" in
// `uvtk texgen`, which takes sphere_map, normal_map and reflection_map; "texgen" elsewhere, which
// also takes object_linear and eye_linear), "texmatrix" (16 numbers, column-major), "no-normalize"
// and "precision", drawn under `view` (the planes' modelview) and `view * model`. Without a
// coordinate or the shortcut, s and t are OBJECT_LINEAR. Throws UsageError naming the parameter.
texgen::TexgenOptions readTexgen(const param::ParameterDictionary& parameters, const std::string& shortcut,
                                 const Mat4& view, const Mat4& model);

// Whether the parameters ask for texgen: the shortcut or a coordinate given.
bool asksForTexgen(const param::ParameterDictionary& parameters, const std::string& shortcut);

// The mapping of `uvtk eval` and the point API: texgen when asked for ("texgen" the shortcut; its
// view is gluLookAt("eye" 0,0,0, "center" 0,0,-1, "up" 0,1,0) and "model" its model matrix), else
// the projector (its fit `defaultFit` unless given). A parameter of the other kind is a UsageError.
ResolvedMapping readMapping(const param::ParameterDictionary& parameters, param::Fit defaultFit);

// `uvtk texgen`'s parameters: readTexgen with the shortcut "mode", under the view gluLookAt("eye"
// 0,0,0, "center" 0,0,-1, "up" 0,1,0) and the model matrix "model"; and "threads", those the mesh
// is read, judged and written with (0 to 1024; 0: one per hardware thread).
struct TexgenSettings {
  texgen::TexgenOptions texgen;
  int threads = 0;
};
TexgenSettings readTexgenSettings(const param::ParameterDictionary& parameters);

// The names readTexgen reads with the shortcut `shortcut` (not the view's and the model's).
std::vector<std::string> texgenOptionNames(const std::string& shortcut);

// Every name readTexgenSettings reads.
std::vector<std::string> texgenParameterNames();

// Whether the placement is fitted to a mesh (a fit other than none and no explicit frame).
bool fitsToMesh(const param::ProjectorOptions& options);

// Every name readMapping reads, for ParameterDictionary::checkAllRead.
std::vector<std::string> mappingParameterNames();

}  // namespace uvtk::inspect
