// How a public options struct meets the command line: one Field per option, which sets the
// struct's field from the option's parsed results (parse()) and gives the words of the option
// (commandLine(), nothing at the default). The command line's own parser checks the words.
#pragma once

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/names.h"
#include "uvtk/mapping.h"
#include "options/cli_values.h"

namespace uvtk::api {

// Shortest text that reads back as the same double.
inline std::string number(double value) {
  char text[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  return text;
}

template <std::size_t N>
std::string numbers(const std::array<double, N>& values) {
  std::string text;
  for (std::size_t i = 0; i < N; ++i) text += (i ? "," : "") + number(values[i]);
  return text;
}

// A number the command line's parser has accepted, as it read it (strtod: 1e-400 is 0, not an
// exception as std::stod's out_of_range).
inline double numberFrom(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

template <std::size_t N>
std::array<double, N> arrayFrom(const std::string& text, const std::string& option) {
  const Eigen::VectorXd parsed = cli::parseNumbers(text, int(N), option);
  std::array<double, N> values;
  for (std::size_t i = 0; i < N; ++i) values[i] = parsed[Eigen::Index(i)];
  return values;
}

// One option of a struct: how parse() sets its field from the option's results, the words
// commandLine() gives for it, and the typed parameter parameters() gives (neither at its default).
template <class Options>
struct Field {
  const char* name;  // "--cap-angle"; the parameter's name is without the dashes
  std::function<void(Options&, const std::vector<std::string>&)> set;
  std::function<std::vector<std::string>(const Options&)> words;
  std::function<std::optional<ParameterValue>(const Options&)> value;
  // The value's kind as OptionDescription::kind spells it, and whether it may be left unset (None).
  std::string kind = "str";
  bool optional = false;
};

template <class Options, class Value, class Set, class Words, class Typed>
Field<Options> field(const char* name, Value Options::*member, Set set, Words words, Typed typed, std::string kind,
                     bool optional = false) {
  return {name, std::move(set),
          [name, member, words](const Options& o) {
            return o.*member == Options{}.*member ? std::vector<std::string>{}
                                                  : std::vector<std::string>{name, words(o.*member)};
          },
          [member, typed](const Options& o) -> std::optional<ParameterValue> {
            if (o.*member == Options{}.*member) return std::nullopt;
            return ParameterValue(typed(o.*member));
          },
          std::move(kind), optional};
}

template <class Options>
Field<Options> textField(const char* name, std::string Options::*member) {
  return field(
      name, member, [member](Options& o, const std::vector<std::string>& r) { o.*member = r.back(); },
      [](const std::string& v) { return v; }, [](const std::string& v) { return v; }, "str");
}

template <class Options>
Field<Options> optionalTextField(const char* name, std::optional<std::string> Options::*member) {
  return field(
      name, member, [member](Options& o, const std::vector<std::string>& r) { o.*member = r.back(); },
      [](const std::optional<std::string>& v) { return *v; }, [](const std::optional<std::string>& v) { return *v; },
      "str", true);
}

template <class Options>
Field<Options> numberField(const char* name, double Options::*member) {
  return field(
      name, member, [member](Options& o, const std::vector<std::string>& r) { o.*member = numberFrom(r.back()); },
      [](double v) { return number(v); }, [](double v) { return v; }, "float");
}

template <class Options>
Field<Options> optionalNumberField(const char* name, std::optional<double> Options::*member) {
  return field(
      name, member, [member](Options& o, const std::vector<std::string>& r) { o.*member = numberFrom(r.back()); },
      [](const std::optional<double>& v) { return number(*v); }, [](const std::optional<double>& v) { return *v; },
      "float", true);
}

template <class Options>
Field<Options> integerField(const char* name, int Options::*member) {
  return field(
      name, member, [member](Options& o, const std::vector<std::string>& r) { o.*member = int(numberFrom(r.back())); },
      [](int v) { return std::to_string(v); }, [](int v) { return std::int64_t(v); }, "int");
}

// A flag: the option alone sets the field to `whenGiven` (false: --no-normalize); with a value the
// parser took as false ("--seamless=0", "=false", "=off", "=no", as Python's seamless=0 becomes), the
// other way.
template <class Options>
Field<Options> flagField(const char* name, bool Options::*member, bool whenGiven = true) {
  return {name,
          [member, whenGiven](Options& o, const std::vector<std::string>& r) {
            const std::string value = r.empty() ? "" : lowerCase(r.back());
            const bool no = value == "0" || value == "false" || value == "off" || value == "no";
            o.*member = no ? !whenGiven : whenGiven;
          },
          [name, member, whenGiven](const Options& o) {
            return o.*member == whenGiven ? std::vector<std::string>{name} : std::vector<std::string>{};
          },
          [member, whenGiven](const Options& o) -> std::optional<ParameterValue> {
            if (o.*member != whenGiven) return std::nullopt;
            return ParameterValue(true);
          },
          "bool", false};
}

template <class Options, std::size_t N>
Field<Options> arrayField(const char* name, std::array<double, N> Options::*member) {
  return field(
      name, member,
      [member, name](Options& o, const std::vector<std::string>& r) { o.*member = arrayFrom<N>(r.back(), name); },
      [](const std::array<double, N>& v) { return numbers(v); },
      [](const std::array<double, N>& v) { return std::vector<double>(v.begin(), v.end()); },
      "float[" + std::to_string(N) + "]");
}

template <class Options, std::size_t N>
Field<Options> optionalArrayField(const char* name, std::optional<std::array<double, N>> Options::*member) {
  return field(
      name, member,
      [member, name](Options& o, const std::vector<std::string>& r) { o.*member = arrayFrom<N>(r.back(), name); },
      [](const std::optional<std::array<double, N>>& v) { return numbers(*v); },
      [](const std::optional<std::array<double, N>>& v) { return std::vector<double>(v->begin(), v->end()); },
      "float[" + std::to_string(N) + "]", true);
}

template <class Options>
Field<Options> listField(const char* name, std::vector<std::string> Options::*member) {
  return {name, [member](Options& o, const std::vector<std::string>& r) { o.*member = r; },
          [name, member](const Options& o) {
            std::vector<std::string> words;
            for (const std::string& value : o.*member) words.insert(words.end(), {name, value});
            return words;
          },
          [member](const Options& o) -> std::optional<ParameterValue> {
            if ((o.*member).empty()) return std::nullopt;
            return ParameterValue(o.*member);
          },
          "str[]", false};
}

// The fields that differ from their defaults as typed parameters, named without the dashes.
template <class Options>
Parameters parametersOf(const Options& options, const std::vector<Field<Options>>& fields) {
  Parameters parameters;
  for (const Field<Options>& field : fields)
    if (std::optional<ParameterValue> value = field.value(options))
      parameters.values.push_back({field.name + 2, std::move(*value), ""});
  return parameters;
}

template <class Options>
std::vector<std::string> wordsOf(const Options& options, const std::vector<Field<Options>>& fields) {
  std::vector<std::string> words;
  for (const Field<Options>& field : fields) {
    const std::vector<std::string> more = field.words(options);
    words.insert(words.end(), more.begin(), more.end());
  }
  return words;
}

// The options `words` give (already checked by the command line's parser), set on a default
// struct through `fields`. Read from the words, not from the parser's results, which hold a
// choice's value rather than its name. "--name value...", "--name=value"; a value never starts
// with "--" (negative numbers start with one dash). An option the command takes but the struct
// does not carry (an output file of the command's own) is a UsageError, never dropped silently.
template <class Options>
Options fromWords(const std::vector<std::string>& words, const std::vector<Field<Options>>& fields) {
  std::map<std::string, std::vector<std::string>> given;
  std::vector<std::string>* values = nullptr;
  for (const std::string& word : words) {
    if (word.rfind("--", 0) == 0) {
      const std::size_t equals = word.find('=');
      const std::string name = word.substr(0, equals);
      if (std::none_of(fields.begin(), fields.end(), [&](const Field<Options>& f) { return name == f.name; }))
        throw UsageError(name + ": the command line takes it, the library's options struct does not carry it");
      values = &given[name];
      if (equals != std::string::npos) values->push_back(word.substr(equals + 1));
    } else if (values) {
      values->push_back(word);
    }
  }
  Options options;
  for (const Field<Options>& field : fields) {
    const auto found = given.find(field.name);
    if (found != given.end()) field.set(options, found->second);
  }
  return options;
}

// Each field as the command's --help shows its option: the help's sentence, default and choices
// (a choice's names are its type name, "a|b|c"), and the field's kind.
template <class Options>
std::vector<OptionDescription> describeFields(const CLI::App& app, const std::vector<Field<Options>>& fields) {
  std::vector<OptionDescription> out;
  for (const Field<Options>& field : fields) {
    OptionDescription d;
    d.name = field.name + 2;
    d.kind = field.kind;
    d.optional = field.optional;
    if (const CLI::Option* option = app.get_option_no_throw(field.name)) {
      d.help = option->get_description();
      d.defaultText = option->get_default_str();
      const std::string type = option->get_type_name();
      d.typeName = type;
      if (d.kind == "str" && type.find('|') != std::string::npos &&
          type.find_first_of("ABCDEFGHIJKLMNOPQRSTUVWXYZ[") == std::string::npos)
        d.choices = CLI::detail::split(type, '|');
    }
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace uvtk::api
