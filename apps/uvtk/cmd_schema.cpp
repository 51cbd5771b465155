// `uvtk schema`: the JSON Schema of scene files, as shipped in schema/scene.schema.json.
#include <cstdio>

#include "commands.h"
#include "scene/scene.h"

namespace uvtk::cli {

using namespace uvtk::scene;

void addSchemaCommand(CLI::App& root) {
  CLI::App* cmd = root.add_subcommand("schema", "Print the JSON Schema of scene files (uvtk run)");
  cmd->callback([] { std::fputs(sceneSchemaText(), stdout); });
}

}  // namespace uvtk::cli
