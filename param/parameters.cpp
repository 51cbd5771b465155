#include "param/parameters.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace uvtk::param {

namespace {

std::string numberText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// A value as a message shows it, in the face's own words for nothing and the booleans.
std::string describe(const ParameterValue& value, ParameterFace face) {
  const bool python = face == ParameterFace::Keyword;
  if (std::holds_alternative<std::monostate>(value)) return python ? "None" : "null";
  if (const bool* b = std::get_if<bool>(&value)) return python ? (*b ? "True" : "False") : (*b ? "true" : "false");
  if (const std::int64_t* i = std::get_if<std::int64_t>(&value)) return std::to_string(*i);
  if (const double* d = std::get_if<double>(&value)) return numberText(*d);
  if (const std::string* s = std::get_if<std::string>(&value)) return "'" + *s + "'";
  std::string list;
  if (const auto* numbers = std::get_if<std::vector<double>>(&value))
    for (const double d : *numbers) list += (list.empty() ? "" : ", ") + numberText(d);
  if (const auto* texts = std::get_if<std::vector<std::string>>(&value))
    for (const std::string& s : *texts) list += (list.empty() ? "'" : ", '") + s + "'";
  return "[" + list + "]";
}

}  // namespace

std::string spellName(ParameterFace face, const std::string& name) {
  std::string spelled;
  switch (face) {
    case ParameterFace::CommandLine:
      return "--" + name;
    case ParameterFace::Scene:
    case ParameterFace::Keyword:
      spelled = name;
      std::replace(spelled.begin(), spelled.end(), '-', '_');
      return spelled;
    case ParameterFace::Library:
      for (std::size_t i = 0; i < name.size(); ++i)
        if (name[i] == '-' && i + 1 < name.size())
          spelled += char(std::toupper(static_cast<unsigned char>(name[++i])));
        else
          spelled += name[i];
      return spelled;
  }
  return name;
}

void ParameterDictionary::add(const std::string& name, ParameterValue value, std::string place) {
  for (const Parameter& p : parameters_)
    if (p.name == name) throw UsageError(p.place + ": given twice");
  if (place.empty()) place = spellName(face_, name);
  parameters_.push_back({name, std::move(value), std::move(place)});
  read_.push_back(false);
}

const Parameter* ParameterDictionary::find(const std::string& name) const {
  for (std::size_t i = 0; i < parameters_.size(); ++i)
    if (parameters_[i].name == name) {
      read_[i] = true;
      return &parameters_[i];
    }
  return nullptr;
}

bool ParameterDictionary::given(const std::string& name) const {
  const Parameter* p = find(name);
  return p && !std::holds_alternative<std::monostate>(p->value);
}

bool ParameterDictionary::givenAsNumbers(const std::string& name) const {
  const Parameter* p = find(name);
  return p && std::holds_alternative<std::vector<double>>(p->value);
}

bool ParameterDictionary::givenAsText(const std::string& name) const {
  const Parameter* p = find(name);
  return p && std::holds_alternative<std::string>(p->value);
}

std::string ParameterDictionary::spelled(const std::string& name) const {
  for (const Parameter& p : parameters_)
    if (p.name == name) return p.place;
  return spellName(face_, name);
}

std::string ParameterDictionary::spelledWith(const std::string& name, const std::string& value) const {
  const std::string spelledName = spellName(face_, name);
  switch (face_) {
    case ParameterFace::Keyword:
      return spelledName + "='" + value + "'";
    case ParameterFace::Library:
      return spelledName + " \"" + value + "\"";
    default:
      return spelledName + " " + value;
  }
}

void ParameterDictionary::wrongKind(const Parameter& p, const std::string& expected) const {
  throw ParameterTypeError(p.place + ": expected " + expected + ", got " + describe(p.value, face_));
}

bool ParameterDictionary::getBool(const std::string& name, bool fallback) const {
  const Parameter* p = find(name);
  if (!p) return fallback;
  if (const bool* b = std::get_if<bool>(&p->value)) return *b;
  const std::int64_t* i = std::get_if<std::int64_t>(&p->value);
  if (i && (*i == 0 || *i == 1)) return *i == 1;
  wrongKind(*p, face_ == ParameterFace::Keyword ? "True or False" : "true or false");
}

double ParameterDictionary::getNumber(const std::string& name, double fallback) const {
  const Parameter* p = find(name);
  if (!p) return fallback;
  if (const double* d = std::get_if<double>(&p->value)) return *d;
  if (const std::int64_t* i = std::get_if<std::int64_t>(&p->value)) return double(*i);
  wrongKind(*p, "a number");
}

int ParameterDictionary::getInteger(const std::string& name, int fallback, int low, int high) const {
  const Parameter* p = find(name);
  if (!p) return fallback;
  double value = 0.0;
  if (const std::int64_t* i = std::get_if<std::int64_t>(&p->value))
    value = double(*i);
  else if (const double* d = std::get_if<double>(&p->value); d && *d == std::floor(*d))
    value = *d;
  else
    wrongKind(*p, "an integer");
  if (!(value >= low && value <= high))
    throw UsageError(p->place + ": expected " +
                     (high == std::numeric_limits<int>::max() ? "at least " + std::to_string(low)
                                                               : std::to_string(low) + " to " + std::to_string(high)) +
                     ", got " + describe(p->value, face_));
  return int(value);
}

std::optional<Eigen::VectorXd> ParameterDictionary::getNumbers(const std::string& name, int n) const {
  const Parameter* p = find(name);
  if (!p || std::holds_alternative<std::monostate>(p->value)) return std::nullopt;
  const auto* numbers = std::get_if<std::vector<double>>(&p->value);
  const std::string expected = std::to_string(n) + " finite numbers";
  if (!numbers) wrongKind(*p, expected);
  if (numbers->size() != std::size_t(n) ||
      std::any_of(numbers->begin(), numbers->end(), [](double d) { return !std::isfinite(d); }))
    throw UsageError(p->place + ": expected " + expected + ", got " + describe(p->value, face_));
  return Eigen::Map<const Eigen::VectorXd>(numbers->data(), n);
}

std::vector<double> ParameterDictionary::getNumberList(const std::string& name) const {
  const Parameter* p = find(name);
  if (!p || std::holds_alternative<std::monostate>(p->value)) return {};
  std::vector<double> numbers;
  if (const auto* list = std::get_if<std::vector<double>>(&p->value)) numbers = *list;
  else if (const std::int64_t* i = std::get_if<std::int64_t>(&p->value)) numbers = {double(*i)};
  else if (const double* d = std::get_if<double>(&p->value)) numbers = {*d};
  else wrongKind(*p, "a list of numbers");
  if (std::any_of(numbers.begin(), numbers.end(), [](double d) { return !std::isfinite(d); }))
    throw UsageError(p->place + ": expected finite numbers, got " + describe(p->value, face_));
  return numbers;
}

std::optional<std::string> ParameterDictionary::getText(const std::string& name) const {
  const Parameter* p = find(name);
  if (!p || std::holds_alternative<std::monostate>(p->value)) return std::nullopt;
  if (const std::string* s = std::get_if<std::string>(&p->value)) return *s;
  wrongKind(*p, "a text");
}

std::vector<std::string> ParameterDictionary::getTexts(const std::string& name) const {
  const Parameter* p = find(name);
  if (!p) return {};
  if (const std::string* s = std::get_if<std::string>(&p->value)) return {*s};
  if (const auto* texts = std::get_if<std::vector<std::string>>(&p->value)) return *texts;
  wrongKind(*p, "a list of texts");
}

std::optional<std::string> ParameterDictionary::getChoiceText(const std::string& name,
                                                             const std::vector<std::string>& names) const {
  const Parameter* p = find(name);
  if (!p) return std::nullopt;
  const std::string* text = std::get_if<std::string>(&p->value);
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "'" : ", '") + n + "'";
  if (!text) wrongKind(*p, "one of " + list);
  for (const std::string& n : names)
    if (lowerCase(n) == lowerCase(*text)) return *text;
  throw UsageError(p->place + ": " + notOneOf(*text, names));
}

void ParameterDictionary::notAParameter(const Parameter& parameter, const std::vector<std::string>& known) const {
  std::vector<std::string> spelledKnown;
  for (const std::string& name : known) spelledKnown.push_back(spellName(face_, name));
  const std::string nearest = nearestName(spellName(face_, parameter.name), spelledKnown);
  throw UsageError(parameter.place + ": not a parameter here" + (nearest.empty() ? "" : "; did you mean " + nearest + "?"));
}

void ParameterDictionary::checkAllRead(const std::vector<std::string>& known) const {
  for (std::size_t i = 0; i < parameters_.size(); ++i)
    if (!read_[i]) notAParameter(parameters_[i], known);
}

void ParameterDictionary::checkKnown(const std::vector<std::string>& known) const {
  for (const Parameter& parameter : parameters_)
    if (std::find(known.begin(), known.end(), parameter.name) == known.end()) notAParameter(parameter, known);
}

}  // namespace uvtk::param
