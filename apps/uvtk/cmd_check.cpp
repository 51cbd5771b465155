// `uvtk check`: placeholder until its implementation lands.
#include "commands.h"

namespace uvtk::cli {

void addCheckCommand(CLI::App& root) { root.add_subcommand("check", "(not yet implemented)"); }

}  // namespace uvtk::cli
