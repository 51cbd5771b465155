// Mapping a public mesh: the options of `uvtk map` and `uvtk texgen` as structs and as command
// lines, and map(), texgen(), fileUvs() over the engine's mapped-mesh step.
#include <algorithm>
#include <cstdio>
#include <functional>
#include <nlohmann/json.hpp>

#include "core/math.h"
#include "core/number_text.h"
#include "detail.h"
#include "option_fields.h"
#include "inspect/map_job.h"
#include "inspect/map_parameters.h"
#include "inspect/mapping_parameters.h"
#include "inspect/texgen_job.h"
#include "io/mesh_format.h"
#include "io/mesh_writer.h"
#include "io/json_text.h"

namespace uvtk::api {

namespace {

// --seam-place: degrees or auto, two fields of the struct.
Field<MapOptions> seamPlaceField() {
  const auto given = [](const MapOptions& o) -> std::optional<ParameterValue> {
    if (o.seamPlaceAuto) return ParameterValue(std::string("auto"));
    if (o.seamPlace) return ParameterValue(*o.seamPlace);
    return std::nullopt;
  };
  return {"--seam-place",
          [](MapOptions& o, const std::vector<std::string>& r) {
            if (r.back() == "auto") o.seamPlaceAuto = true;
            else o.seamPlace = numberFrom(r.back());
          },
          [](const MapOptions& o) {
            if (o.seamPlaceAuto) return std::vector<std::string>{"--seam-place", "auto"};
            if (o.seamPlace) return std::vector<std::string>{"--seam-place", number(*o.seamPlace)};
            return std::vector<std::string>{};
          },
          given, "float|auto", true};
}

// --texture-size W,H (or N).
Field<MapOptions> textureSizeField() {
  return field(
      "--texture-size", &MapOptions::textureSize,
      [](MapOptions& o, const std::vector<std::string>& r) {
        const auto [width, height] = parseTextureSize(r.back(), "--texture-size");
        o.textureSize = {width, height};
      },
      [](const std::array<int, 2>& v) { return std::to_string(v[0]) + "," + std::to_string(v[1]); },
      [](const std::array<int, 2>& v) { return std::vector<double>{double(v[0]), double(v[1])}; }, "int|int[2]");
}

const std::vector<Field<MapOptions>>& mapFields() {
  using O = MapOptions;
  static const std::vector<Field<O>> fields = {
      textField("--projector", &O::projector),
      textField("--omap", &O::omap),
      optionalTextField("--fit", &O::fit),
      textField("--axis", &O::axis),
      optionalArrayField("--center", &O::center),
      arrayField("--axis-dir", &O::axisDir),
      arrayField("--ref-dir", &O::refDir),
      numberField("--scale", &O::scale),
      arrayField("--plane-u", &O::planeU),
      arrayField("--plane-v", &O::planeV),
      flagField("--caps", &O::caps),
      numberField("--cap-angle", &O::capAngle),
      textField("--cap-layout", &O::capLayout),
      textField("--sphere-preset", &O::spherePreset),
      textField("--cube-convention", &O::cubeConvention),
      textField("--cube-layout", &O::cubeLayout),
      optionalArrayField("--eye", &O::eye),
      optionalArrayField("--up", &O::up),
      numberField("--fovy", &O::fovy),
      numberField("--aspect", &O::aspect),
      numberField("--tile", &O::tile),
      numberField("--blend", &O::blend),
      textField("--triplanar-preset", &O::triplanarPreset),
      numberField("--angle-limit", &O::angleLimit),
      numberField("--margin", &O::margin),
      optionalNumberField("--texels-per-unit", &O::texelsPerUnit),
      flagField("--at-infinity", &O::atInfinity),
      textField("--seam", &O::seam),
      textField("--pole", &O::pole),
      numberField("--pole-eps", &O::poleEps),
      seamPlaceField(),
      arrayField("--uv-scale", &O::uvScale),
      arrayField("--uv-offset", &O::uvOffset),
      numberField("--uv-rotate", &O::uvRotate),
      flagField("--flip-u", &O::flipU),
      flagField("--flip-v", &O::flipV),
      textField("--precision", &O::precision),
      textField("--math", &O::math),
      textField("--convention", &O::convention),
      listField("--fail-on", &O::failOn),
      listField("--warn-on", &O::warnOn),
      integerField("--overlap-resolution", &O::overlapResolution),
      textureSizeField(),
      optionalNumberField("--density", &O::density),
      integerField("--threads", &O::threads),
  };
  return fields;
}

const std::vector<Field<TexgenOptions>>& texgenFields() {
  using O = TexgenOptions;
  static const std::vector<Field<O>> fields = {
      textField("--s", &O::s),
      textField("--t", &O::t),
      textField("--r", &O::r),
      textField("--q", &O::q),
      textField("--mode", &O::mode),
      optionalArrayField("--texmatrix", &O::texmatrix),
      flagField("--no-normalize", &O::normalize, false),
      arrayField("--eye", &O::eye),
      arrayField("--center", &O::center),
      arrayField("--up", &O::up),
      optionalArrayField("--model", &O::model),
      textField("--precision", &O::precision),
      integerField("--threads", &O::threads),
  };
  return fields;
}

Reason reasonOf(const analysis::Reason& reason) {
  return {analysis::toString(reason.rule), analysis::toString(reason.severity), reason.value, reason.threshold,
          reason.faces, reason.text()};
}

}  // namespace

MapOptions MapOptions::parse(const std::string& commandLine) {
  return translatingErrors([&] {
    const std::vector<std::string> words = splitCommandLine(commandLine);
    const param::ParameterDictionary typed = toEngine(typedWords(words, mapFields(), "map"));
    inspect::readMapSettings(typed);  // the engine's checks of each value and the combination
    return fromWords(words, mapFields());
  });
}

std::vector<OptionDescription> MapOptions::describe() { return describeFields("map", mapFields()); }

std::vector<OptionDescription> TexgenOptions::describe() { return describeFields("texgen", texgenFields()); }

std::string MapOptions::commandLine() const { return joinCommandLine(wordsOf(*this, mapFields())); }

Parameters MapOptions::parameters() const { return parametersOf(*this, mapFields()); }

TexgenOptions TexgenOptions::parse(const std::string& commandLine) {
  return translatingErrors([&] {
    const std::vector<std::string> words = splitCommandLine(commandLine);
    inspect::readTexgenSettings(toEngine(typedWords(words, texgenFields(), "texgen")));
    return fromWords(words, texgenFields());
  });
}

std::string TexgenOptions::commandLine() const { return joinCommandLine(wordsOf(*this, texgenFields())); }

Parameters TexgenOptions::parameters() const { return parametersOf(*this, texgenFields()); }

Mapping makeMapping(inspect::MappedMesh mapped, const analysis::Thresholds& thresholds, int overlapResolution,
                    nlohmann::json input, std::optional<texgen::TexgenOptions> texgen, analysis::TextureSize textureSize,
                    int threads) {
  auto detail = std::make_shared<MappingDetail>();
  detail->judgement = mapped.judge(thresholds, overlapResolution, threads, textureSize);
  detail->overlapResolution = overlapResolution;
  detail->input = std::move(input);
  detail->texgen = std::move(texgen);
  detail->mapped = std::move(mapped);
  const inspect::MappedMesh& m = detail->mapped;
  const analysis::Judgement& judgement = detail->judgement;

  Mapping mapping;
  mapping.mesh = fromEngine(m.mesh);
  const std::size_t corners = m.uv.uv.size();
  mapping.uv.resize(corners);
  for (std::size_t c = 0; c < corners; ++c) mapping.uv[c] = {m.uv.uv[c].x(), m.uv.uv[c].y()};
  mapping.w = m.uv.w;
  mapping.q = m.q;
  constexpr auto same = [](auto a, auto b) { return int(a) == int(b); };  // two enums, one bit each
  static_assert(same(api::kFaceTurnedAway, uvtk::kFaceTurnedAway) &&
                same(api::kFaceSphereMapSingular, uvtk::kFaceSphereMapSingular) && same(api::kFaceCap, uvtk::kFaceCap) &&
                same(api::kFaceCubeSeam, uvtk::kFaceCubeSeam) && same(api::kFaceSeamStraddle, uvtk::kFaceSeamStraddle) &&
                same(api::kFacePole, uvtk::kFacePole) && same(api::kFaceInvalid, uvtk::kFaceInvalid));  // the bits are copied as they are
  mapping.faceFlags = m.uv.faceFlags;
  mapping.invalidReason.resize(corners);
  mapping.state.resize(corners, CornerState::Ok);
  for (std::size_t c = 0; c < corners; ++c) {
    mapping.invalidReason[c] = InvalidReason(m.uv.cornerInvalid[c]);
    if (m.uv.cornerInvalid[c] != kCornerValid)
      mapping.state[c] = CornerState::Invalid;
    else if (m.uv.cornerAtPole(c))
      mapping.state[c] = CornerState::Pole;
  }
  mapping.source = m.source;
  mapping.verdict.status = analysis::toString(judgement.verdict);
  for (const analysis::Reason& reason : judgement.reasons) mapping.verdict.reasons.push_back(reasonOf(reason));
  nlohmann::json summary = inspect::mapSummaryJson(m, judgement, detail->input, "");
  summary.erase("output");
  mapping.summaryJson = io::jsonText(summary);
  mapping.detail = std::move(detail);
  return mapping;
}

const MappingDetail& detailOf(const Mapping& mapping, const char* function) {
  if (!mapping.detail)
    throw std::invalid_argument(std::string(function) +
                                ": the mapping is empty (a default Mapping); make one with map(), texgen() or fileUvs()");
  return *mapping.detail;
}

const MappingDetail& judgedDetailOf(const Mapping& mapping, const char* function) {
  const MappingDetail& detail = detailOf(mapping, function);
  if (detail.restored)
    throw std::invalid_argument(std::string(function) +
                                ": the mapping was restored from its data (unpickled), which holds no judgement "
                                "nor a projector's per-pixel evaluation: call it where the mapping was made, or map again");
  return detail;
}

Mapping restoreMapping(Mapping data) {
  const std::size_t faces = data.mesh.triangles.size(), corners = 3 * faces;
  if (data.uv.size() != corners || data.invalidReason.size() != corners || data.state.size() != corners ||
      data.faceFlags.size() != faces || (!data.w.empty() && data.w.size() != corners) ||
      (!data.q.empty() && data.q.size() != corners))
    throw std::invalid_argument("restoreMapping: the per-corner and per-face arrays do not match the mesh's " +
                                std::to_string(faces) + " faces");
  if (data.source != "projector" && data.source != "texgen" && data.source != "file")
    throw std::invalid_argument("restoreMapping: source '" + data.source + "' is not projector, texgen or file");
  CheckedMesh in = checked(data.mesh);
  auto detail = std::make_shared<MappingDetail>();
  detail->restored = true;
  detail->input = std::move(in.input);
  inspect::MappedMesh& mapped = detail->mapped;
  mapped.mesh = std::move(in.engine);
  mapped.uv.uv.resize(corners);
  for (std::size_t c = 0; c < corners; ++c) mapped.uv.uv[c] = Vec2(data.uv[c][0], data.uv[c][1]);
  mapped.uv.w = data.w;
  mapped.uv.faceFlags = data.faceFlags;
  mapped.uv.cornerInvalid.resize(corners);
  for (std::size_t c = 0; c < corners; ++c) mapped.uv.cornerInvalid[c] = std::uint8_t(data.invalidReason[c]);
  if (std::find(data.state.begin(), data.state.end(), CornerState::Pole) != data.state.end()) {
    mapped.uv.cornerPole.resize(corners);
    for (std::size_t c = 0; c < corners; ++c) mapped.uv.cornerPole[c] = data.state[c] == CornerState::Pole;
  }
  mapped.q = data.q;
  mapped.source = data.source;
  data.detail = std::move(detail);
  return data;
}

param::ParameterDictionary toEngine(const Parameters& parameters) {
  param::ParameterDictionary dictionary(parameters.face == Parameters::Face::Keyword       ? param::ParameterFace::Keyword
                                        : parameters.face == Parameters::Face::CommandLine ? param::ParameterFace::CommandLine
                                                                                           : param::ParameterFace::Library);
  for (const Parameter& p : parameters.values)
    std::visit([&](const auto& value) { dictionary.add(p.name, value, p.place); }, p.value);
  return dictionary;
}

Mapping map(const Mesh& mesh, const MapOptions& options) { return map(mesh, options.parameters()); }

Mapping map(const Mesh& mesh, const Parameters& parameters) {
  return translatingErrors([&] {
    const param::ParameterDictionary dictionary = toEngine(parameters);
    const inspect::MapSettings s = inspect::readMapSettings(dictionary);
    dictionary.checkAllRead(inspect::mapParameterNames());
    CheckedMesh in = checked(mesh);
    inspect::MappedMesh mapped =
        inspect::mapByProjector(std::move(in.engine), s.projector.options, s.projector.seamPlaceAuto, s.threads);
    if (s.density)  // as `uvtk map --density`: scaled by the mean of the judgement before it
      inspect::scaleToTexelDensity(mapped, mapped.judge(s.thresholds, s.overlapResolution, s.threads, s.textureSize),
                                   *s.density, "mesh");
    return makeMapping(std::move(mapped), s.thresholds, s.overlapResolution, std::move(in.input), std::nullopt,
                       s.textureSize, s.threads);
  });
}

Mapping texgen(const Mesh& mesh, const TexgenOptions& options) { return texgen(mesh, options.parameters()); }

Mapping texgen(const Mesh& mesh, const Parameters& parameters) {
  return translatingErrors([&] {
    const param::ParameterDictionary dictionary = toEngine(parameters);
    const inspect::TexgenSettings s = inspect::readTexgenSettings(dictionary);
    dictionary.checkAllRead(inspect::texgenParameterNames());
    CheckedMesh in = checked(mesh);
    return makeMapping(inspect::mapByTexgen(std::move(in.engine), s.texgen), {}, 1024, std::move(in.input), s.texgen,
                       {}, s.threads);
  });
}

Mapping fileUvs(const Mesh& mesh) {
  CheckedMesh in = checked(mesh);
  return translatingErrors(
      [&] { return makeMapping(inspect::withFileUvs(std::move(in.engine), "mesh"), {}, 1024, std::move(in.input)); });
}

void writeMesh(const std::string& path, const Mapping& mapping, const WriteOptions& options) {
  if (options.uvDigits != "double" && options.uvDigits != "float")
    throw std::invalid_argument("writeMesh: uvDigits is '" + options.uvDigits + "', expected double or float");
  const MappingDetail& detail = detailOf(mapping, "writeMesh");
  if (detail.restored && detail.mapped.source == "texgen")  // which of r and q its OBJ holds is in the options
    throw std::invalid_argument("writeMesh: a texgen mapping restored from its data (unpickled) does not carry "
                                "its texgen options, which decide what its file holds: write it where it was made");
  translatingErrors([&] {
    const inspect::MappedMesh& mapped = detail.mapped;
    io::MeshWriteOptions write;
    write.writeW = options.writeW;
    write.floatDigits = options.uvDigits == "float";
    write.ascii = options.ascii;
    write.header = options.header;
    write.threads = options.threads;
    if (!detail.texgen) return io::writeMesh(path, mapped.mesh, &mapped.uv, write);
    // As `uvtk texgen -o`: r when generated (in an OBJ), and (s, t, r) divided by q where q is not 1.
    const bool obj = io::outputFormatOf(path) == io::MeshFormat::obj;
    write.writeW = write.writeW || (obj && inspect::texgenWritesR(*detail.texgen));
    const inspect::ProjectiveDivision divided = inspect::divideByQ(mapped.uv, mapped.q);
    io::writeMesh(path, mapped.mesh, divided.applied ? &divided.uv : &mapped.uv, write);
  });
}

}  // namespace uvtk::api
