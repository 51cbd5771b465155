// The subcommand table of the `uvtk` program: each adds itself to the root app.
#pragma once

#include <CLI/CLI.hpp>

namespace uvtk::cli {

void addMapCommand(CLI::App& root);
void addTexgenCommand(CLI::App& root);
void addRenderCommand(CLI::App& root);
void addReportCommand(CLI::App& root);
void addCompareCommand(CLI::App& root);
void addBenchCommand(CLI::App& root);
void addRunCommand(CLI::App& root);
void addSchemaCommand(CLI::App& root);
void addMergeReportsCommand(CLI::App& root);
void addEvalCommand(CLI::App& root);
void addCheckCommand(CLI::App& root);

// The subcommands by the name each registers, in the order `uvtk --help` lists them. A run names
// one first (`uvtk map ...`) and needs only that one built: each registers a hundred options or
// more, which costs a millisecond of a small mesh's ten (tests/apps/cli_manners_test.cpp checks
// the names against what the functions register).
struct Command {
  const char* name;
  void (*add)(CLI::App& root);
};
inline constexpr Command kCommands[] = {
    {"map", addMapCommand},         {"texgen", addTexgenCommand},
    {"render", addRenderCommand},   {"report", addReportCommand},
    {"compare", addCompareCommand}, {"bench", addBenchCommand},
    {"run", addRunCommand},         {"schema", addSchemaCommand},
    {"merge-reports", addMergeReportsCommand}, {"eval", addEvalCommand},
    {"check", addCheckCommand},
};

}  // namespace uvtk::cli
