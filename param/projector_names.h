// The names of the projector's choices, as every face spells them (the command line, scenes,
// Python keywords, the library's options, and every JSON record of a mapping).
#pragma once

#include "core/arithmetic.h"
#include "core/names.h"
#include "param/projector.h"

namespace uvtk::param {

// Other tools' projectors, expressed in uvtk's parameters (docs/conventions.md, "Other tools").
enum class Convention {
  Uvtk,
  Blender,  // uv.sphere_project / uv.cylinder_project, ALIGN_TO_OBJECT, POLAR_ZX
  Assimp,   // aiProcess_GenUVCoords with its default axis +y
  Notes,    // the lecture notes' worked examples (the seeds): cube direct, sphere seed004, object frame
};

extern const ChoiceNames<SurfaceKind> kSurfaceNames;
extern const ChoiceNames<RayKind> kRayNames;
extern const ChoiceNames<Fit> kFitNames;
extern const ChoiceNames<int> kAxisNames;
extern const ChoiceNames<SpherePreset> kSpherePresetNames;
extern const ChoiceNames<CubeConvention> kCubeConventionNames;
extern const ChoiceNames<CubeLayout> kCubeLayoutNames;
extern const ChoiceNames<CapLayout> kCapLayoutNames;
extern const ChoiceNames<SeamMode> kSeamNames;
extern const ChoiceNames<PoleMode> kPoleNames;
extern const ChoiceNames<TriplanarPreset> kTriplanarPresetNames;
extern const ChoiceNames<Precision> kPrecisionNames;
extern const ChoiceNames<MathMode> kMathNames;
extern const ChoiceNames<Convention> kConventionNames;

const std::string& precisionName(Precision precision);
const std::string& mathName(MathMode math);

}  // namespace uvtk::param
