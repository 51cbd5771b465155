// Between assimp_peer.cpp and the plugin that holds assimp (assimp_peer_module.cpp): one table of
// functions, looked up by its entry's name. Both are built by this project with one compiler, so
// the table passes the C++ types of assimp_peer.h.
#pragma once

#include "peers/assimp_peer.h"

#define UVTK_ASSIMP_PEER_ENTRY "uvtk_assimp_peer"

namespace uvtk::peers {

constexpr int kAssimpPeerVersion = 1;

struct AssimpPeerFunctions {
  int version;
  // measureAssimpGenUvCoords: false where that returns nothing.
  bool (*measure)(const Mesh& mesh, AssimpMapping mapping, int repetitions, AssimpLayout layout, PeerTiming& out);
};

}  // namespace uvtk::peers
