// The assimp peer through its plugin (assimp_peer_module.cpp), opened on the first use: a process
// that does not time the peer never loads assimp.
#include "peers/assimp_peer.h"

#include <string>

#include "core/plugin.h"
#include "peers/assimp_peer_module.h"

namespace uvtk::peers {

namespace {

struct Loaded {
  const AssimpPeerFunctions* functions = nullptr;
  std::string error;
};

Loaded load() {
  const std::string path =
      pluginPath("UVTK_ASSIMP_PEER", UVTK_ASSIMP_PEER_INSTALLED, UVTK_ASSIMP_PEER_BUILT, UVTK_BUILD_DIR);
  std::string error;
  const AssimpPeerFunctions* functions =
      openPluginFunctions<AssimpPeerFunctions>(path, UVTK_ASSIMP_PEER_ENTRY, "assimp peer", kAssimpPeerVersion, error);
  return {functions, error};
}

const Loaded& loaded() {
  static const Loaded plugin = load();
  return plugin;
}

}  // namespace

bool assimpAvailable() { return loaded().functions != nullptr; }

const std::string& assimpUnavailableReason() { return loaded().error; }

std::optional<PeerTiming> measureAssimpGenUvCoords(const Mesh& mesh, AssimpMapping mapping, int repetitions,
                                                   AssimpLayout layout) {
  const AssimpPeerFunctions* functions = loaded().functions;
  PeerTiming timing;
  if (!functions || !functions->measure(mesh, mapping, repetitions, layout, timing)) return std::nullopt;
  return timing;
}

}  // namespace uvtk::peers
