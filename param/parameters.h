// Typed parameters with the place each came from (in the spirit of pbrt-v4's ParameterDictionary):
// every face of uvtk (the command line, scene files, Python keywords, the C++ library's option
// structs) fills one dictionary with typed values, and the engine reads them once
// (makeProjector, param/make_projector.h). A message about a parameter names it as the user wrote
// it: "--cap-angle" on the command line, "cap_angle" in a scene or as a Python keyword,
// "capAngle" in the library's struct.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/error.h"
#include "core/math.h"
#include "core/names.h"

namespace uvtk::param {

// Who filled a dictionary: how it spells a parameter's name when it names one the user did not
// give ("--omap reflection: expected --eye x,y,z" on the command line, "eye" for a keyword).
enum class ParameterFace { CommandLine, Scene, Keyword, Library };

// A value as a face gives it: nothing (Python's None, JSON's null), a boolean, an integer, a
// number, a list of numbers, a text (a choice's name, "auto") or a list of texts.
using ParameterValue =
    std::variant<std::monostate, bool, std::int64_t, double, std::vector<double>, std::string, std::vector<std::string>>;

// A value of the wrong kind (a number where a boolean belongs): Python's TypeError. Every other
// refused value is a UsageError.
struct ParameterTypeError : UsageError {
  using UsageError::UsageError;
};

struct Parameter {
  std::string name;      // as the command line spells it without the dashes: "cap-angle"
  ParameterValue value;
  std::string place;     // where it came from, as a message names it
};

class ParameterDictionary {
 public:
  explicit ParameterDictionary(ParameterFace face) : face_(face) {}

  // `place` "" is the face's spelling of `name`. The same name twice is a UsageError.
  void add(const std::string& name, ParameterValue value, std::string place = "");

  ParameterFace face() const { return face_; }
  // Given with a value (None is not a value: it means "not given" where that is allowed).
  bool given(const std::string& name) const;
  // Given as a list of numbers (a size as W,H rather than N), or as a text (--seam-place auto
  // rather than degrees).
  bool givenAsNumbers(const std::string& name) const;
  bool givenAsText(const std::string& name) const;
  // Where the parameter came from, or how this face spells its name.
  std::string spelled(const std::string& name) const;
  // The parameter with a value, as this face writes it: "--projector camera", "projector='camera'".
  std::string spelledWith(const std::string& name, const std::string& value) const;

  // The value of `name`, or `fallback` where it is not given. A value of another kind is a
  // ParameterTypeError; None is one too, except for the optional getters (getVector, getText).
  bool getBool(const std::string& name, bool fallback) const;  // true, false (or the integers 1, 0)
  double getNumber(const std::string& name, double fallback) const;
  // An integer in [low, high] (an integral number is one), else a UsageError naming the range
  // ("at least LOW" when high is INT_MAX).
  int getInteger(const std::string& name, int fallback, int low, int high) const;
  // `n` finite numbers; nothing where not given or None.
  std::optional<Eigen::VectorXd> getNumbers(const std::string& name, int n) const;
  // Finite numbers, as many as given (a number alone is a list of one); none where not given.
  std::vector<double> getNumberList(const std::string& name) const;
  template <int N>
  std::optional<Eigen::Matrix<double, N, 1>> getVector(const std::string& name) const {
    const auto values = getNumbers(name, N);
    if (!values) return std::nullopt;
    return Eigen::Matrix<double, N, 1>(*values);
  }
  std::optional<std::string> getText(const std::string& name) const;
  std::vector<std::string> getTexts(const std::string& name) const;  // a text is a list of one
  // One of the names in `table` (in any case), else a UsageError listing them with "did you mean".
  template <class Value>
  Value getChoice(const std::string& name, const ChoiceNames<Value>& table, Value fallback) const {
    const std::optional<std::string> text = getChoiceText(name, namesOf(table));
    if (!text) return fallback;
    for (const auto& [choice, value] : table)
      if (lowerCase(choice) == lowerCase(*text)) return value;
    return fallback;  // getChoiceText refused every other text
  }

  // A UsageError naming the first parameter no getter (nor given()) has read, with the nearest
  // of `known` (the names the reader takes) when it looks mistyped.
  void checkAllRead(const std::vector<std::string>& known) const;
  // A UsageError naming the first parameter that is not among `known`, before any is read (a face
  // that takes fewer than the reader reads: the library's render takes no AOV file).
  void checkKnown(const std::vector<std::string>& known) const;

  const std::vector<Parameter>& parameters() const { return parameters_; }

 private:
  const Parameter* find(const std::string& name) const;  // marks it read
  std::optional<std::string> getChoiceText(const std::string& name, const std::vector<std::string>& names) const;
  [[noreturn]] void wrongKind(const Parameter& parameter, const std::string& expected) const;
  [[noreturn]] void notAParameter(const Parameter& parameter, const std::vector<std::string>& known) const;

  ParameterFace face_;
  std::vector<Parameter> parameters_;
  mutable std::vector<bool> read_;
};

// `name` ("cap-angle") as `face` spells it: "--cap-angle", "cap_angle", "capAngle".
std::string spellName(ParameterFace face, const std::string& name);

}  // namespace uvtk::param
