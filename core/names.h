// Named choices: a table of the names a choice is spelled by, the name of a value, and the
// "did you mean" every face (command line, scenes, Python, the library) gives for a mistyped name.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"

namespace uvtk {

// The names of a choice's values, in the order help and messages list them.
template <class Value>
using ChoiceNames = std::vector<std::pair<std::string, Value>>;

// The name `table` gives `value`.
template <class Value>
const std::string& nameOf(const ChoiceNames<Value>& table, Value value) {
  for (const auto& [name, v] : table)
    if (v == value) return name;
  throw std::logic_error("a choice without a name");
}

template <class Value>
std::vector<std::string> namesOf(const ChoiceNames<Value>& table) {
  std::vector<std::string> names;
  for (const auto& entry : table) names.push_back(entry.first);
  return names;
}

// Each of `items` looked up in `table` (exactly, in order); a UsageError naming `spelled` for an
// unknown name ("--precision: expected a list of double, float, found "quad"") or for no item.
template <class Value>
std::vector<Value> namedValues(const std::vector<std::string>& items, const ChoiceNames<Value>& table,
                               const std::string& spelled) {
  std::vector<Value> values;
  for (const std::string& item : items) {
    const auto found = std::find_if(table.begin(), table.end(), [&](const auto& entry) { return entry.first == item; });
    if (found == table.end()) {
      std::string names;
      for (const auto& entry : table) names += (names.empty() ? "" : ", ") + entry.first;
      throw UsageError(spelled + ": expected a list of " + names + ", found \"" + item + "\"");
    }
    values.push_back(found->second);
  }
  if (values.empty()) throw UsageError(spelled + ": expected at least one value");
  return values;
}

// The name among `names` that a mistyped `typed` most likely meant, ignoring case: the nearest by
// Damerau-Levenshtein distance when it is at most a third of the longer one's length, else the only
// name that `typed` (3 characters or more) begins; "" when none is that close.
std::string nearestName(const std::string& typed, const std::vector<std::string>& names);

// "'sphera' is not one of: plane, two-plane, cylinder, sphere, cube; did you mean 'sphere'?", the
// question only when nearestName finds one.
std::string notOneOf(const std::string& typed, const std::vector<std::string>& names);

// `text` in lower case (ASCII), as names compare.
std::string lowerCase(std::string text);

}  // namespace uvtk
