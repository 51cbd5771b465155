// The installed point API (uvtk/point.h): typed parameters (or option text read once into them),
// the mapping inspect::readMapping makes of them, then the PointEvaluator that `uvtk eval` uses.
#include "uvtk/point.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "core/uv_map.h"
#include "inspect/mapping_parameters.h"
#include "point/point_evaluator.h"

namespace uvtk::point {

struct Mapping::Impl {
  PointEvaluator evaluator;
};

namespace {

param::ParameterFace engineFace(Face face) {
  switch (face) {
    case Face::Keyword: return param::ParameterFace::Keyword;
    case Face::CommandLine: return param::ParameterFace::CommandLine;
    case Face::Library: break;
  }
  return param::ParameterFace::Library;
}

// A value word of the option text, typed: a boolean, an integer, a number, comma-separated
// numbers, else the text itself (a choice's name, "auto", a texgen coordinate "MODE:a,b,c,d").
ParameterValue typedValue(const std::string& text) {
  if (text == "true" || text == "false") return text == "true";
  const auto number = [](const std::string& word, double& value) {
    char* end = nullptr;
    errno = 0;
    value = std::strtod(word.c_str(), &end);
    return !word.empty() && end == word.c_str() + word.size() && errno != ERANGE;
  };
  double value = 0.0;
  if (number(text, value)) {
    if (text.find_first_of(".eEnN") == std::string::npos && std::abs(value) < 9e15) return std::int64_t(value);
    return value;
  }
  if (text.find_first_of(", ") == std::string::npos) return text;
  std::vector<double> values;  // separated by commas or spaces ("2 0 0 1 ..." as a matrix)
  std::string spaced = text;
  std::replace(spaced.begin(), spaced.end(), ',', ' ');
  std::istringstream parts(spaced);
  for (std::string part; parts >> part;) {
    if (!number(part, value)) return text;
    values.push_back(value);
  }
  return values;
}

// The words of the option text, as a shell splits them: at blanks, except inside '...' or "...".
std::vector<std::string> wordsOf(const std::string& text) {
  std::vector<std::string> words;
  std::string word;
  bool inWord = false;
  char quote = 0;
  for (const char c : text) {
    if (quote) {
      if (c == quote) quote = 0;
      else word += c;
    } else if (c == '"' || c == '\'') {
      quote = c;
      inWord = true;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      if (inWord) words.push_back(word);
      word.clear();
      inWord = false;
    } else {
      word += c;
      inWord = true;
    }
  }
  if (quote) throw UsageError(std::string("unmatched ") + quote);
  if (inWord) words.push_back(word);
  return words;
}

// "--projector sphere --caps --eye=0,0,5" as typed parameters.
std::vector<Parameter> parametersOf(const std::string& options) {
  const std::vector<std::string> words = wordsOf(options);
  std::vector<Parameter> parameters;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string& word = words[i];
    if (word.size() < 3 || word.compare(0, 2, "--") != 0)
      throw UsageError("expected an option (--name), found '" + word + "'");
    const std::size_t equals = word.find('=');
    const std::string name = word.substr(2, equals == std::string::npos ? std::string::npos : equals - 2);
    ParameterValue value = true;  // a flag
    if (equals != std::string::npos)
      value = typedValue(word.substr(equals + 1));
    else if (i + 1 < words.size() && words[i + 1].compare(0, 2, "--") != 0)
      value = typedValue(words[++i]);
    parameters.push_back({name, std::move(value), "--" + name});
  }
  return parameters;
}

// The parameters as the command line writes them, for Result::mapping.
std::string describe(const std::vector<Parameter>& parameters) {
  const auto number = [](double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return std::string(text);
  };
  std::string out;
  for (const Parameter& p : parameters) {
    std::string value;
    if (std::holds_alternative<std::monostate>(p.value)) continue;
    if (const bool* b = std::get_if<bool>(&p.value)) value = *b ? "" : "=false";
    if (const std::int64_t* i = std::get_if<std::int64_t>(&p.value)) value = " " + std::to_string(*i);
    if (const double* d = std::get_if<double>(&p.value)) value = " " + number(*d);
    if (const std::string* s = std::get_if<std::string>(&p.value)) value = " " + *s;
    if (const auto* numbers = std::get_if<std::vector<double>>(&p.value))
      for (std::size_t k = 0; k < numbers->size(); ++k) value += (k ? "," : " ") + number((*numbers)[k]);
    if (const auto* texts = std::get_if<std::vector<std::string>>(&p.value))
      for (std::size_t k = 0; k < texts->size(); ++k) value += (k ? "," : " ") + (*texts)[k];
    out += (out.empty() ? "--" : " --") + p.name + value;
  }
  return out;
}

PointEvaluator prepare(const std::vector<Parameter>& given, Face face, const std::vector<Vector3>& meshPositions,
                       std::string description) {
  param::ParameterDictionary parameters(engineFace(face));
  for (const Parameter& p : given) std::visit([&](const auto& value) { parameters.add(p.name, value, p.place); }, p.value);
  const inspect::ResolvedMapping mapping = inspect::readMapping(parameters, param::Fit::None);
  parameters.checkAllRead(inspect::mappingParameterNames());
  if (mapping.seamPlaceAuto)
    throw UsageError(parameters.spelledWith("seam-place", "auto") +
                     " needs a mesh's faces; give the angle it chose (uvtk map prints it)");
  Affine3 frame = Affine3::Identity();
  std::optional<Eigen::AlignedBox3d> sensible;  // the range rule needs the mesh (docs/conventions.md §4)
  if (mapping.projector) {
    std::vector<Vec3> positions;
    positions.reserve(meshPositions.size());
    for (const Vector3& p : meshPositions) positions.emplace_back(p[0], p[1], p[2]);
    frame = placementFor(*mapping.projector, positions);
    if (!positions.empty()) sensible = param::sensibleBox(positions, *mapping.projector, frame);
  }
  return PointEvaluator(mapping, frame, std::move(description), sensible);
}

// `prepare`, its refusals as the API's exceptions, each message starting with `what`.
PointEvaluator prepared(const std::string& what, const std::function<PointEvaluator()>& make) {
  try {
    return make();
  } catch (const param::ParameterTypeError& e) {
    throw ParameterTypeError(what + e.what());
  } catch (const UsageError& e) {
    throw std::invalid_argument(what + e.what());
  }
}

}  // namespace

Mapping::Mapping(const std::string& options, const std::vector<Vector3>& meshPositions)
    : impl_(new Impl{prepared("uvtk::point::Mapping(\"" + options + "\"): ", [&] {
        return prepare(parametersOf(options), Face::CommandLine, meshPositions, options);
      })}) {}

Mapping::Mapping(const std::vector<Parameter>& parameters, const std::vector<Vector3>& meshPositions, Face face)
    : impl_(new Impl{prepared("uvtk::point::Mapping: ", [&] {
        return prepare(parameters, face, meshPositions, describe(parameters));
      })}) {}

Mapping::~Mapping() = default;
Mapping::Mapping(Mapping&&) noexcept = default;
Mapping& Mapping::operator=(Mapping&&) noexcept = default;

Result Mapping::at(const Vector3& position, const Vector3& normal) const noexcept {
  return impl_->evaluator.at(position, normal);
}

bool Mapping::needsNormal() const { return impl_->evaluator.needsNormal(); }
const std::string& Mapping::options() const { return impl_->evaluator.description(); }

std::vector<std::string> parameterNames() { return inspect::mappingParameterNames(); }

double uvError(double u, double v, const Result& expected) {
  return wrappedUvError(Vec2(u, v), Vec2(expected.u, expected.v), Vec2(expected.period[0], expected.period[1]),
                        expected.status == Status::Pole);
}

}  // namespace uvtk::point
