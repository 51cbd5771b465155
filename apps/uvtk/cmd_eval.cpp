// `uvtk eval`: placeholder until its implementation lands.
#include "commands.h"

namespace uvtk::cli {

void addEvalCommand(CLI::App& root) { root.add_subcommand("eval", "(not yet implemented)"); }

}  // namespace uvtk::cli
