// The one place a projector is made from parameters (pbrt-v4's TextureMapping2D::Create): every
// face (the command line, scene files, Python keywords, the library's MapOptions) fills a
// ParameterDictionary, and makeProjector reads it once: the choices, the placement, the
// combinations that make no sense (refused here, naming the parameter as the user wrote it), and
// the conventions of other tools.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "param/parameters.h"
#include "param/projector.h"
#include "param/projector_names.h"

namespace uvtk::param {

// What a command calls the projector's parameters where its own camera has taken the plain names,
// and what it assumes when a parameter is not given.
struct ProjectorContext {
  std::string center = "center";  // the explicit placement's origin (`uvtk render`: frame-center)
  // The camera projector's gluLookAt and gluPerspective (`uvtk render`: proj-eye, ...; `uvtk
  // report`: proj-up, whose own camera has --up). "center" is also the placement's origin.
  std::string cameraEye = "eye", cameraCenter = "center", cameraUp = "up", cameraFovy = "fovy",
              cameraAspect = "aspect";
  // `uvtk render`, `uvtk check --image`: "eye" is the camera's own, set by the command as the
  // reflection O-mapping's eye; it is not a parameter the user combines with the O-mapping.
  bool cameraOwnsEye = false;
  Fit defaultFit = Fit::BBox;  // `uvtk eval` without a mesh: none
};

// A projector as the parameters ask for it, before it is placed on a mesh (param::Projector).
// `seamPlaceAuto`: --seam-place auto, which the caller (who has the mesh) carries out
// (inspect::mapByProjector).
struct ProjectorRequest {
  ProjectorOptions options;
  bool seamPlaceAuto = false;
};

// "texture-size": W,H or N (N,N) texels, 1 to 16384 each (numbers, or as text "W,H" or "N"); nothing when not given. The texture the
// atlas packs for and the judgement counts texel densities in.
std::optional<std::array<int, 2>> readTextureSize(const ParameterDictionary& parameters);

// Throws UsageError (ParameterTypeError for a value of the wrong kind) naming the parameter.
ProjectorRequest makeProjector(const ParameterDictionary& parameters, const ProjectorContext& context = {});

// The names makeProjector reads under `context`, for ParameterDictionary::checkAllRead.
std::vector<std::string> projectorParameterNames(const ProjectorContext& context = {});

}  // namespace uvtk::param
