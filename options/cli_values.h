// Option values shared by the subcommands: named choices, vectors written as "x,y,z", matrices.
#pragma once

#include <CLI/CLI.hpp>
#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/error.h"
#include "analysis/distortion.h"
#include "core/math.h"
#include "core/names.h"
#include "core/number_text.h"

namespace uvtk::cli {

using uvtk::parseNumbers;
using uvtk::parseMatrix;
using uvtk::parseImageSize;

inline Vec2 parseVec2(const std::string& text, const std::string& option) { return parseNumbers(text, 2, option); }
inline Vec3 parseVec3(const std::string& text, const std::string& option) { return parseNumbers(text, 3, option); }
inline Vec4 parseVec4(const std::string& text, const std::string& option) { return parseNumbers(text, 4, option); }

// Accepts exactly the strings in `names`, refusing others with notOneOf's text (CLI11 puts the
// option's name before it): for a string option checked against a list of names.
CLI::Validator nameCheck(std::vector<std::string> names);

// --threads: 0 to 1024, 0 being one per hardware thread; `help` says what they do.
CLI::Option* addThreadsOption(CLI::App& app, int& threads, const std::string& help);

// --overlap-resolution: the pixels across the judgement's overlap raster, 0 (the default) for a
// raster that follows the mesh (analysis::followingOverlapResolution); `map`, `report` and `compare`.
CLI::Option* addOverlapResolutionOption(CLI::App& app, int& overlapResolution);

// A named choice: the help shows the names (a|b|c), not the enumerators they map to. Only the
// names are accepted (in any case): not the numbers behind them.
template <class Enum>
inline CLI::Option* addChoice(CLI::App& app, const std::string& name, Enum& target,
                       const std::vector<std::pair<std::string, Enum>>& table, const std::string& help) {
  std::vector<std::string> names;
  for (const auto& entry : table) names.push_back(entry.first);
  // Hands CLI11 the value as the number it converts an enum (or int, or bool) from.
  const auto toValue = [table, names](std::string& text) -> std::string {
    for (const auto& [choice, value] : table)
      if (CLI::detail::to_lower(choice) == CLI::detail::to_lower(text)) {
        if constexpr (std::is_enum_v<Enum>)
          text = std::to_string(static_cast<std::underlying_type_t<Enum>>(value));
        else
          text = std::to_string(value);
        return "";
      }
    return notOneOf(text, names);
  };
  return app.add_option(name, target, help)->transform(CLI::Validator(toValue, ""))->type_name(CLI::detail::join(names, "|"));
}

// The items of a comma-separated list.
std::vector<std::string> splitList(const std::string& text);

// The items of a comma-separated list of names, each looked up in `table`; throws UsageError
// naming `option` for an unknown name or an empty list.
template <class Enum>
std::vector<Enum> parseNameList(const std::string& text, const std::vector<std::pair<std::string, Enum>>& table,
                                const std::string& option) {
  return namedValues(splitList(text), table, option);
}

// Whether the user typed option `name` (rather than leaving its default).
inline bool given(const CLI::App* app, const char* name) { return app->get_option(name)->count() > 0; }


inline analysis::TextureSize parseTextureSize(const std::string& text, const std::string& option) {
  const auto [width, height] = uvtk::parseTextureSize(text, option);
  return {width, height};
}

}  // namespace uvtk::cli
