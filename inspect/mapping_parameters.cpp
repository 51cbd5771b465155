#include "inspect/mapping_parameters.h"

#include <algorithm>
#include <utility>

#include "core/error.h"
#include "core/gl_matrices.h"
#include "core/number_text.h"
#include "param/projector_names.h"

namespace uvtk::inspect {

namespace {

using texgen::TexgenMode;

const char* const kCoordinates[4] = {"s", "t", "r", "q"};
const char* const kModeList = "object_linear|eye_linear|sphere_map|normal_map|reflection_map|off";
// What a projector and texgen both read, each with a meaning of its own (the header says which).
const char* const kShared[] = {"eye", "center", "up", "precision"};
// What only texgen reads besides the shortcut and the coordinates.
const char* const kTexgenOnly[] = {"texmatrix", "no-normalize", "model"};

// "MODE" or "MODE:a,b,c,d" of the parameter `name`, whose place is `place`.
texgen::TexgenCoordinate parseCoordinate(const std::string& text, const std::string& place,
                                         const texgen::TexgenCoordinate& defaults) {
  const std::size_t colon = text.find(':');
  const std::string name = text.substr(0, colon);
  texgen::TexgenCoordinate c = defaults;
  const auto known = std::find_if(texgen::kTexgenModeNames.begin(), texgen::kTexgenModeNames.end(),
                                  [&](const auto& entry) { return entry.first == name; });
  if (known == texgen::kTexgenModeNames.end())
    throw UsageError(place + ": expected " + kModeList + ", found '" + name + "'");
  c.mode = known->second;
  if (colon != std::string::npos) c.plane = parseNumbers(text.substr(colon + 1), 4, place);
  return c;
}

// "--texgen or --s/--t/--r/--q" as the face spells them.
std::string texgenParameters(const param::ParameterDictionary& p) {
  return param::spellName(p.face(), "texgen") + " or " + param::spellName(p.face(), "s") + "/" +
         param::spellName(p.face(), "t") + "/" + param::spellName(p.face(), "r") + "/" + param::spellName(p.face(), "q");
}

// texgen's view, gluLookAt of "eye", "center" and "up", and its model matrix "model".
std::pair<Mat4, Mat4> texgenViewAndModel(const param::ParameterDictionary& p) {
  const Mat4 view = lookAt(p.getVector<3>("eye").value_or(Vec3::Zero()), p.getVector<3>("center").value_or(Vec3(0, 0, -1)),
                           p.getVector<3>("up").value_or(Vec3::UnitY()));
  const std::optional<Eigen::VectorXd> model = p.getNumbers("model", 16);
  return {view, model ? Mat4(Eigen::Map<const Mat4>(model->data())) : Mat4::Identity()};
}

}  // namespace

bool asksForTexgen(const param::ParameterDictionary& p, const std::string& shortcut) {
  return p.given(shortcut) || std::any_of(std::begin(kCoordinates), std::end(kCoordinates),
                                          [&](const char* name) { return p.given(name); });
}

texgen::TexgenOptions readTexgen(const param::ParameterDictionary& p, const std::string& shortcut, const Mat4& view,
                                 const Mat4& model) {
  texgen::TexgenOptions o;
  const std::array<texgen::TexgenCoordinate, 4> defaults = texgen::defaultCoordinates();
  const bool modeOnly = shortcut == "mode";  // `uvtk texgen --mode`: the linear modes are --s/--t's
  if (const std::optional<std::string> text = p.getText(shortcut)) {
    const std::string place = p.spelled(shortcut);
    const texgen::TexgenCoordinate chosen = parseCoordinate(*text, place, {});
    const bool linear = chosen.mode == TexgenMode::ObjectLinear || chosen.mode == TexgenMode::EyeLinear;
    if (chosen.mode == TexgenMode::Off || (linear && modeOnly))
      throw UsageError(place + ": expected " + (modeOnly ? "" : "object_linear|eye_linear|") +
                       "sphere_map|normal_map|reflection_map, found '" + *text + "'");
    const int count = chosen.mode == TexgenMode::NormalMap || chosen.mode == TexgenMode::ReflectionMap ? 3 : 2;
    for (int i = 0; i < count; ++i) o.coordinates[std::size_t(i)].mode = chosen.mode;
  }
  bool any = p.given(shortcut);
  for (std::size_t i = 0; i < 4; ++i)
    if (const std::optional<std::string> text = p.getText(kCoordinates[i])) {  // overrides the shortcut
      o.coordinates[i] = parseCoordinate(*text, p.spelled(kCoordinates[i]), defaults[i]);
      any = true;
    }
  if (!any) o.coordinates[0].mode = o.coordinates[1].mode = TexgenMode::ObjectLinear;
  for (std::size_t i = 0; i < 4; ++i) {
    const TexgenMode m = o.coordinates[i].mode;
    if ((m == TexgenMode::SphereMap && i >= 2) || ((m == TexgenMode::NormalMap || m == TexgenMode::ReflectionMap) && i == 3))
      throw UsageError(p.spelled(kCoordinates[i]) + ": " + texgen::texgenModeName(m) +
                       " is not allowed on this coordinate (sphere_map: s, t only; normal_map, reflection_map: "
                       "s, t, r only)");
  }
  if (const std::optional<Eigen::VectorXd> matrix = p.getNumbers("texmatrix", 16))
    o.textureMatrix = Eigen::Map<const Mat4>(matrix->data());  // column-major, as GL's
  o.normalize = !p.getBool("no-normalize", false);
  o.precision = p.getChoice("precision", param::kPrecisionNames, Precision::Double);
  return texgen::drawnUnder(o, view, model);
}

ResolvedMapping readMapping(const param::ParameterDictionary& p, param::Fit defaultFit) {
  param::ProjectorContext context;
  context.defaultFit = defaultFit;
  ResolvedMapping out;
  if (!asksForTexgen(p, "texgen")) {
    for (const char* name : kTexgenOnly)
      if (p.given(name)) throw UsageError(p.spelled(name) + " goes with " + texgenParameters(p) + " only");
    const param::ProjectorRequest projector = param::makeProjector(p, context);
    out.projector = projector.options;
    out.seamPlaceAuto = projector.seamPlaceAuto;
    return out;
  }
  for (const std::string& name : param::projectorParameterNames(context))
    if (std::none_of(std::begin(kShared), std::end(kShared), [&](const char* shared) { return name == shared; }) &&
        p.given(name))
      throw UsageError(p.spelled(name) + " is a projector option; it does not go with " + texgenParameters(p));
  const auto [view, model] = texgenViewAndModel(p);
  out.texgen = readTexgen(p, "texgen", view, model);
  return out;
}

TexgenSettings readTexgenSettings(const param::ParameterDictionary& p) {
  const auto [view, model] = texgenViewAndModel(p);
  return {readTexgen(p, "mode", view, model), p.getInteger("threads", 0, 0, 1024)};
}

std::vector<std::string> texgenOptionNames(const std::string& shortcut) {
  return {shortcut, "s", "t", "r", "q", "texmatrix", "no-normalize", "precision"};
}

std::vector<std::string> texgenParameterNames() {
  std::vector<std::string> names = texgenOptionNames("mode");
  names.insert(names.end(), {"eye", "center", "up", "model", "threads"});
  return names;
}

bool fitsToMesh(const param::ProjectorOptions& o) {
  return !o.placement.frame && o.placement.fit != param::Fit::None && param::traitsOf(o.surface).fitsToMesh;
}

std::vector<std::string> mappingParameterNames() {
  std::vector<std::string> names = param::projectorParameterNames();
  for (const std::string& name : texgenOptionNames("texgen")) names.push_back(name);
  names.push_back("model");
  std::vector<std::string> once;  // the projector's context names "eye", "center" and "up" twice
  for (const std::string& name : names)
    if (std::find(once.begin(), once.end(), name) == once.end()) once.push_back(name);
  return once;
}

}  // namespace uvtk::inspect
