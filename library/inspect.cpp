// Reports, pictures and rankings of a public mapping, through the engine's inspect/ module with
// the options parsed by the command line's own option groups.
#include <nlohmann/json.hpp>

#include "detail.h"
#include "inspect/compare.h"
#include "inspect/frame.h"
#include "inspect/render_parameters.h"
#include "inspect/report.h"
#include "option_fields.h"
#include "io/json_text.h"

namespace uvtk::api {

namespace {

const std::vector<Field<ReportOptions>>& reportFields() {
  using O = ReportOptions;
  static const std::vector<Field<O>> fields = {
      textField("--json", &O::json),
      textField("--html", &O::html),
      textField("--views", &O::views),
      textField("--size", &O::size),
      arrayField("--view-dir", &O::viewDir),
      arrayField("--up", &O::up),
      integerField("--texture-size", &O::textureSize),
      integerField("--overlap-resolution", &O::overlapResolution),
      integerField("--threads", &O::threads),
  };
  return fields;
}

const std::vector<Field<RenderOptions>>& renderFields() {
  using O = RenderOptions;
  static const std::vector<Field<O>> fields = {
      textField("--view", &O::view),
      textField("--size", &O::size),
      arrayField("--view-dir", &O::viewDir),
      optionalArrayField("--up", &O::up),
      textField("--camera", &O::camera),
      optionalArrayField("--eye", &O::eye),
      arrayField("--center", &O::center),
      numberField("--fovy", &O::fovy),
      numberField("--near", &O::zNear),
      numberField("--far", &O::zFar),
      textField("--ortho", &O::ortho),
      textField("--cull", &O::cull),
      textField("--texture", &O::texture),
      textField("--filter", &O::filter),
      textField("--wrap", &O::wrap),
      flagField("--seamless", &O::seamless),
      textField("--env", &O::env),
      arrayField("--env-color", &O::envColor),
      flagField("--two-sided", &O::twoSided),
      textField("--texture-size", &O::textureSize),
      integerField("--checks", &O::checks),
      textField("--layout-fill", &O::layoutFill),
      integerField("--layout-size", &O::layoutSize),
      integerField("--spp", &O::spp),
      arrayField("--background", &O::background),
      textField("--uv", &O::uv),
      textField("--derivatives", &O::derivatives),
      textField("--seam-fix", &O::seamFix),
      integerField("--threads", &O::threads),
  };
  return fields;
}

const std::vector<Field<CompareOptions>>& compareFields() {
  using O = CompareOptions;
  static const std::vector<Field<O>> fields = {
      textField("--by", &O::by),
      integerField("--top", &O::top),
      flagField("--no-baselines", &O::baselines, false),
      integerField("--tile-size", &O::tileSize),
      arrayField("--view-dir", &O::viewDir),
      arrayField("--up", &O::up),
      integerField("--overlap-resolution", &O::overlapResolution),
      flagField("--seam-place-auto", &O::seamPlaceAuto),
      integerField("--baseline-max-faces", &O::baselineMaxFaces),
      listField("--fail-on", &O::failOn),
      listField("--warn-on", &O::warnOn),
      textField("--json", &O::json),
      textField("--markdown", &O::markdown),
      textField("--sheet", &O::sheet),
      integerField("--threads", &O::threads),
  };
  return fields;
}

// The names an options struct takes: its fields' (not the command's others, e.g. `uvtk report
// --view3d-faces`).
template <class Options>
std::vector<std::string> namesOf(const std::vector<Field<Options>>& fields) {
  std::vector<std::string> names;
  for (const Field<Options>& field : fields) names.push_back(field.name + 2);
  return names;
}

// A picture's camera, texture and frame, as `uvtk render` reads them, from the parameters the struct has.
struct RenderSettings {
  inspect::CameraSettings camera;
  inspect::TextureSettings texture;
  inspect::FrameSettings frame;
};

RenderSettings readRenderSettings(const param::ParameterDictionary& parameters) {
  parameters.checkKnown(namesOf(renderFields()));
  RenderSettings settings{inspect::readCameraSettings(parameters), inspect::readTextureSettings(parameters, "texture"),
                          inspect::readFrameSettings(parameters)};
  return settings;
}

}  // namespace

ReportOptions ReportOptions::parse(const std::string& commandLine) {
  return translatingErrors([&] {
    const std::vector<std::string> words = splitCommandLine(commandLine);
    inspect::readReportOptions(toEngine(typedWords(words, reportFields(), "report"))).check();
    return fromWords(words, reportFields());
  });
}

RenderOptions RenderOptions::parse(const std::string& commandLine) {
  return translatingErrors([&] {
    const std::vector<std::string> words = splitCommandLine(commandLine);
    readRenderSettings(toEngine(typedWords(words, renderFields(), "render")));
    return fromWords(words, renderFields());
  });
}

CompareOptions CompareOptions::parse(const std::string& commandLine) {
  return translatingErrors([&] {
    const std::vector<std::string> words = splitCommandLine(commandLine);
    inspect::readCompareOptions(toEngine(typedWords(words, compareFields(), "compare")));
    return fromWords(words, compareFields());
  });
}

std::vector<OptionDescription> ReportOptions::describe() { return describeFields("report", reportFields()); }
std::vector<OptionDescription> RenderOptions::describe() { return describeFields("render", renderFields()); }
std::vector<OptionDescription> CompareOptions::describe() { return describeFields("compare", compareFields()); }

std::string ReportOptions::commandLine() const { return joinCommandLine(wordsOf(*this, reportFields())); }
Parameters ReportOptions::parameters() const { return parametersOf(*this, reportFields()); }
std::string RenderOptions::commandLine() const { return joinCommandLine(wordsOf(*this, renderFields())); }
Parameters RenderOptions::parameters() const { return parametersOf(*this, renderFields()); }
std::string CompareOptions::commandLine() const { return joinCommandLine(wordsOf(*this, compareFields())); }
Parameters CompareOptions::parameters() const { return parametersOf(*this, compareFields()); }

std::string report(const Mapping& mapping, const ReportOptions& options) {
  return report(mapping, options.parameters());
}

std::string report(const Mapping& mapping, const Parameters& parameters) {
  judgedDetailOf(mapping, "report");
  return translatingErrors([&] {
    const param::ParameterDictionary dictionary = toEngine(parameters);
    const inspect::ReportOptions o = inspect::readReportOptions(dictionary);
    dictionary.checkAllRead(namesOf(reportFields()));
    o.check();
    const inspect::MappedMesh& mapped = mapping.detail->mapped;
    const analysis::Judgement& judged = mapping.detail->judgement;
    const bool asJudged = o.overlapResolution == mapping.detail->overlapResolution &&
                          o.textureSize == judged.summary.density.textureSize;
    const analysis::Judgement judgement =
        asJudged ? judged : mapped.judge(judged.thresholds, o.overlapResolution, 0, o.textureSize);
    const nlohmann::json& input = mapping.detail->input;
    const nlohmann::json record = o.json.empty() && o.html.empty() ? inspect::reportJson(mapped, judgement, o, input)
                                                                    : inspect::writeReport(o, mapped, judgement, input);
    return io::jsonText(record, 2);
  });
}

std::vector<std::uint8_t> Image::bytes() const {
  std::vector<std::uint8_t> out(pixels.size());
  for (std::size_t i = 0; i < pixels.size(); ++i) out[i] = toUInt8(pixels[i]);
  return out;
}

Image render(const Mapping& mapping, const RenderOptions& options) { return render(mapping, options.parameters()); }

Image render(const Mapping& mapping, const Parameters& parameters) {
  judgedDetailOf(mapping, "render");
  return translatingErrors([&] {
    const RenderSettings settings = readRenderSettings(toEngine(parameters));
    const inspect::MappedMesh& mapped = mapping.detail->mapped;
    const inspect::FrameOptions& frame = settings.frame.frame;
    if (frame.needsExact() && !mapped.exact)
      throw UsageError(frame.perPixel ? "--uv per-pixel evaluates a mapping: the file's texture coordinates have none"
                                      : "--view uverror compares with the exact mapping: the file's texture coordinates "
                                        "have none");
    inspect::checkTextureUse(frame, settings.texture, mapped.projector ? &*mapped.projector : nullptr);
    const render::Camera camera =
        settings.camera.make(mapped.mesh, "the mapping's mesh", Mat4::Identity(), frame.width, frame.height);
    const inspect::BoundTexture texture = frame.samplesTexture() ? settings.texture.load() : inspect::BoundTexture{};
    const render::RenderOptions renderOptions =
        inspect::renderOptions(frame, settings.texture.options(), texture, camera, Mat4::Identity());
    const analysis::Judgement& judgement = mapping.detail->judgement;
    const inspect::DrawnFrame drawn =
        inspect::drawFrame(frame, mapped, renderOptions, [&]() -> const analysis::Judgement& { return judgement; });
    Image image;
    image.width = drawn.picture.width;
    image.height = drawn.picture.height;
    image.channels = drawn.picture.channels;
    image.pixels = drawn.picture.pixels;
    return image;
  });
}

Comparison compare(const Mesh& mesh, const CompareOptions& options) { return compare(mesh, options.parameters()); }

Comparison compare(const Mesh& mesh, const Parameters& parameters) {
  const CheckedMesh in = checked(mesh);
  return translatingErrors([&] {
    const param::ParameterDictionary dictionary = toEngine(parameters);
    const inspect::CompareOptions o = inspect::readCompareOptions(dictionary);
    dictionary.checkAllRead(namesOf(compareFields()));
    const uvtk::Mesh& engine = in.engine;
    const nlohmann::json& input = in.input;
    const bool writes = !o.json.empty() || !o.markdown.empty() || !o.sheet.empty();
    const inspect::Comparison ranked =
        writes ? inspect::compareMappings(o, engine, input) : inspect::rankMappings(o, engine, input);
    return Comparison{io::jsonText(ranked.record, 2), ranked.table, ranked.best};
  });
}

}  // namespace uvtk::api
