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

}  // namespace uvtk::cli
