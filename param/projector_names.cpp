#include "param/projector_names.h"

#include "param/surface_traits.h"

namespace uvtk::param {

const ChoiceNames<SurfaceKind> kSurfaceNames = [] {
  ChoiceNames<SurfaceKind> names;
  for (const SurfaceKind surface : kSurfaces) names.emplace_back(traitsOf(surface).name, surface);
  return names;
}();
const ChoiceNames<TriplanarPreset> kTriplanarPresetNames = {
    {"unity", TriplanarPreset::Unity}, {"materialx", TriplanarPreset::MaterialX}, {"godot", TriplanarPreset::Godot}};
const ChoiceNames<RayKind> kRayNames = {{"isn", RayKind::SurfaceNormal},
                                        {"centroid", RayKind::Centroid},
                                        {"normal", RayKind::ObjectNormal},
                                        {"reflection", RayKind::Reflection}};
const ChoiceNames<Fit> kFitNames = {
    {"none", Fit::None}, {"bbox", Fit::BBox}, {"center", Fit::Center}, {"pca", Fit::Pca}, {"obb", Fit::Obb}};
const ChoiceNames<int> kAxisNames = {{"x", 0}, {"y", 1}, {"z", 2}};
const ChoiceNames<SpherePreset> kSpherePresetNames = {
    {"default", SpherePreset::Default}, {"glu", SpherePreset::Glu}, {"seed004", SpherePreset::Seed004}};
const ChoiceNames<CubeConvention> kCubeConventionNames = {{"gl", CubeConvention::Gl}, {"direct", CubeConvention::Direct}};
const ChoiceNames<CubeLayout> kCubeLayoutNames = {
    {"faces", CubeLayout::Faces}, {"cross", CubeLayout::Cross}, {"strip", CubeLayout::Strip}, {"3x2", CubeLayout::ThreeByTwo}};
const ChoiceNames<CapLayout> kCapLayoutNames = {{"beside", CapLayout::Beside}, {"stacked", CapLayout::Stacked}};
const ChoiceNames<SeamMode> kSeamNames = {{"none", SeamMode::None}, {"shift", SeamMode::Shift}, {"cut", SeamMode::Cut}};
const ChoiceNames<PoleMode> kPoleNames = {{"none", PoleMode::None}, {"fan", PoleMode::Fan}};
const ChoiceNames<Precision> kPrecisionNames = {{"double", Precision::Double}, {"float", Precision::Float}};
const ChoiceNames<MathMode> kMathNames = {
    {"exact", MathMode::Exact}, {"fast", MathMode::Fast}, {"fast-u10", MathMode::FastU10}};
const ChoiceNames<Convention> kConventionNames = {
    {"uvtk", Convention::Uvtk}, {"blender", Convention::Blender}, {"assimp", Convention::Assimp}, {"notes", Convention::Notes}};

const std::string& precisionName(Precision precision) { return nameOf(kPrecisionNames, precision); }
const std::string& mathName(MathMode math) { return nameOf(kMathNames, math); }

}  // namespace uvtk::param
