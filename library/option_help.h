// The help of the options of `uvtk map`, `texgen`, `report`, `render` and `compare` as the program's
// --help shows it, written at build time by uvtk_option_help from the option groups' registration
// (the one place the texts are written): what the options structs' describe() shows.
#pragma once

#include <string>
#include <vector>

namespace uvtk::api {

struct OptionHelp {
  std::string command;      // "map"
  std::string name;         // "--cap-angle"
  std::string help;         // --help's sentence
  std::string defaultText;  // "" when the option shows none
  std::string typeName;     // "FLOAT", "a|b|c" for a choice
};

const std::vector<OptionHelp>& optionHelpTable();

// The row of `name` in `command`'s options; nullptr when the program has no such option.
inline const OptionHelp* optionHelp(const std::string& command, const std::string& name) {
  for (const OptionHelp& row : optionHelpTable())
    if (row.command == command && row.name == name) return &row;
  return nullptr;
}

}  // namespace uvtk::api
