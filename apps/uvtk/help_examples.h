// Examples at the end of every command's --help.
#pragma once

#include <CLI/CLI.hpp>

namespace uvtk::cli {

// Ends the help of `root` and of each of its commands with their examples (after any footer a
// command has already). Call it once every command is registered.
void addHelpExamples(CLI::App& root);

}  // namespace uvtk::cli
