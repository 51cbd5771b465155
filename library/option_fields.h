// How a public options struct meets the command line: one Field per option, which sets the
// struct's field from the option's words (parse()), gives the words of the option (commandLine(),
// nothing at the default) and its typed parameter (parameters()). parse() reads the words as typed
// parameters by each field's kind and hands them to the engine's reader, which checks them as it
// checks the command line's; describe() shows the program's --help (option_help.h).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
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
#include "core/number_text.h"
#include "option_help.h"

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
  const Eigen::VectorXd parsed = parseNumbers(text, int(N), option);
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

// The options `words` give (already checked: typedWords and the engine's reader), set on a default
// struct through `fields`, as written ("--name value...", "--name=value"; a value never starts with
// "--": negative numbers start with one dash).
template <class Options>
Options fromWords(const std::vector<std::string>& words, const std::vector<Field<Options>>& fields) {
  std::map<std::string, std::vector<std::string>> given;
  std::vector<std::string>* values = nullptr;
  for (const std::string& word : words) {
    if (word.rfind("--", 0) == 0) {
      const std::size_t equals = word.find('=');
      const std::string name = word.substr(0, equals);
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

// `text` as the kind of a field takes it (OptionDescription::kind: "str", "float", "int",
// "float[3]", "str[]", "int|int[2]", "float|auto"); a UsageError naming `option` for a malformed one.
inline ParameterValue typedWord(const std::string& text, const std::string& kind, const std::string& option) {
  const auto number = [&](const char* what) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size())
      throw UsageError(option + ": expected " + what + ", found '" + text + "'");
    return value;
  };
  if (kind == "float" || (kind == "float|auto" && text != "auto")) return number("a number");
  if (kind == "int") {
    const double value = number("an integer");
    if (value != std::floor(value) || std::fabs(value) > 2147483647.0)
      throw UsageError(option + ": expected an integer, found '" + text + "'");
    return std::int64_t(value);
  }
  if (kind.compare(0, 6, "float[") == 0) {
    const Eigen::VectorXd values = parseNumbers(text, std::atoi(kind.c_str() + 6), option);
    return std::vector<double>(values.data(), values.data() + values.size());
  }
  return text;  // a text, a choice's name, "auto", a size "W,H" the reader parses
}

// The options `words` give ("--name value", "--name=value", a flag alone or "--flag=0"), typed by
// each field's kind, in the command line's face: what parse() hands the engine's reader. A value
// never starts with "--" (negative numbers start with one dash). A name no field has is a
// UsageError: an option of the program's `command` the struct does not carry (an output file of
// the command's own) says so, another gets the nearest name.
template <class Options>
Parameters typedWords(const std::vector<std::string>& words, const std::vector<Field<Options>>& fields,
                      const std::string& command) {
  Parameters typed;
  typed.face = Parameters::Face::CommandLine;
  std::vector<std::string> names;
  for (const Field<Options>& field : fields) names.push_back(field.name);
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string& word = words[i];
    if (word.size() < 3 || word.compare(0, 2, "--") != 0)
      throw UsageError("expected an option (--name), found '" + word + "'");
    const std::size_t equals = word.find('=');
    const std::string name = word.substr(0, equals);
    const auto field = std::find_if(fields.begin(), fields.end(), [&](const Field<Options>& f) { return name == f.name; });
    if (field == fields.end() && optionHelp(command, name))
      throw UsageError(name + ": `uvtk " + command + "` takes it, the library's options struct does not carry it");
    if (field == fields.end()) {
      const std::string nearest = nearestName(name, names);
      throw UsageError(name + ": not an option here" + (nearest.empty() ? "" : "; did you mean " + nearest + "?"));
    }
    std::optional<std::string> value;
    if (equals != std::string::npos) value = word.substr(equals + 1);
    else if (field->kind != "bool" && i + 1 < words.size() && words[i + 1].compare(0, 2, "--") != 0) value = words[++i];
    ParameterValue typedValue;
    if (field->kind == "bool") {
      const std::string no = value ? lowerCase(*value) : "";
      typedValue = !(no == "0" || no == "false" || no == "off" || no == "no");
    } else if (!value) {
      throw UsageError(name + ": expected a value");
    } else if (field->kind == "str[]") {
      const auto given = std::find_if(typed.values.begin(), typed.values.end(), [&](const Parameter& p) { return p.name == name.substr(2); });
      if (given != typed.values.end()) {
        std::get<std::vector<std::string>>(given->value).push_back(*value);
        continue;
      }
      typedValue = std::vector<std::string>{*value};
    } else {
      typedValue = typedWord(*value, field->kind, name);
    }
    typed.values.push_back({name.substr(2), std::move(typedValue), ""});
  }
  return typed;
}

// Each field as the command's --help shows its option (option_help.h): the help's sentence,
// default and choices (a choice's names are its type name, "a|b|c"), and the field's kind.
template <class Options>
std::vector<OptionDescription> describeFields(const std::string& command, const std::vector<Field<Options>>& fields) {
  std::vector<OptionDescription> out;
  for (const Field<Options>& field : fields) {
    OptionDescription d;
    d.name = field.name + 2;
    d.kind = field.kind;
    d.optional = field.optional;
    if (const OptionHelp* help = optionHelp(command, field.name)) {
      d.help = help->help;
      d.defaultText = help->defaultText;
      const std::string& type = help->typeName;
      d.typeName = type;
      if (d.kind == "str" && type.find('|') != std::string::npos &&
          type.find_first_of("ABCDEFGHIJKLMNOPQRSTUVWXYZ[") == std::string::npos)
        for (std::size_t begin = 0; begin <= type.size();) {
          const std::size_t end = std::min(type.find('|', begin), type.size());
          d.choices.push_back(type.substr(begin, end - begin));
          begin = end + 1;
        }
    }
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace uvtk::api
