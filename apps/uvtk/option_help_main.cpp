// Writes the help of `uvtk map`, `texgen`, `report`, `render` and `compare`'s options as a C++
// table (library/option_help.h), at build time: the library's describe() shows each option as the
// program's --help does, from the one place its text is written (the option groups' registration),
// without linking CLI11 itself.
#include <cstdio>
#include <fstream>
#include <string>

#include "commands.h"

namespace {

// `text` as a C++ string literal.
std::string literal(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (c == '\n') out += "\\n";
    else out += c;
  }
  return out + "\"";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: uvtk_option_help OUTPUT.cpp\n");
    return 2;
  }
  CLI::App app;
  uvtk::cli::addMapCommand(app);
  uvtk::cli::addTexgenCommand(app);
  uvtk::cli::addReportCommand(app);
  uvtk::cli::addRenderCommand(app);
  uvtk::cli::addCompareCommand(app);
  std::string rows;
  for (const CLI::App* command : app.get_subcommands({}))
    for (const CLI::Option* option : command->get_options()) {
      if (option->get_lnames().empty()) continue;
      rows += "    {" + literal(command->get_name()) + ", " + literal("--" + option->get_lnames().front()) + ", " +
              literal(option->get_description()) + ", " + literal(option->get_default_str()) + ", " +
              literal(option->get_type_name()) + "},\n";
    }
  std::ofstream out(argv[1]);
  out << "// Written by uvtk_option_help (apps/uvtk/option_help_main.cpp) from the program's options.\n"
         "#include \"option_help.h\"\n\nnamespace uvtk::api {\n\nconst std::vector<OptionHelp>& optionHelpTable() {\n"
         "  static const std::vector<OptionHelp> table = {\n"
      << rows << "  };\n  return table;\n}\n\n}  // namespace uvtk::api\n";
  return out.good() ? 0 : 4;
}
