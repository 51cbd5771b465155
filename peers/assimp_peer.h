// The "peer" of `uvtk bench`: the speed of assimp's aiProcess_GenUVCoords step on the same mesh.
// assimp lives in a plugin (libuvtk_peer_assimp.so, opened on the first call, found as
// core/plugin.h says; $UVTK_ASSIMP_PEER names another), built when libassimp-dev is found: without
// it assimpAvailable() is false and the measurement is std::nullopt. No assimp header leaks out.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/mesh.h"

namespace uvtk::peers {

// The material's diffuse texture mapping handed to assimp (aiTextureMapping_SPHERE, ..._CYLINDER,
// ..._PLANE, ..._BOX), always with the mapping axis +Y (assimp's default).
// Box: assimp 5.2.5 does not implement it; the step logs an error and leaves the channel it
// allocated at (0, 0), so its timing is an allocation only and its UVs are all zero.
enum class AssimpMapping { Sphere, Cylinder, Plane, Box };

// How the mesh is laid out in the aiMesh that assimp maps.
//  Verbose: what every assimp loader hands the post-processing pipeline (BaseImporter contract,
//           "pseudo-indexed" vertices): one aiVector3D per triangle corner, assimp vertex 3t + c is
//           corner c of mesh.triangles[t]. Seam removal then works per face, as assimp intends.
//  Indexed: the mesh's own shared vertices, assimp vertex i is mesh.positions[i]. Same vertex count
//           as ours, but assimp's seam removal then moves u of vertices shared with other faces
//           (assimp does not expect this layout), so the UVs near the seam are not assimp's real output.
enum class AssimpLayout { Verbose, Indexed };

struct PeerTiming {
  double nsPerVertex = 0;      // median ns of one GenUVCoords run / `vertices`
  std::size_t vertices = 0;    // vertices of the assimp mesh (3 * triangles for Verbose)
  std::vector<Eigen::Vector2d> uv;  // per vertex of the assimp mesh, the last run's output

  // Beside the fields asked for: the median itself and the same time per vertex of the input mesh
  // (mesh.positions.size()), the unit our own mapping speed is reported in.
  double medianNs = 0;
  double nsPerMeshVertex = 0;
  int repetitions = 0;  // timed runs (one more untimed warm-up run precedes them)
};

// True when the plugin loads; else assimpUnavailableReason() says why in one line.
bool assimpAvailable();
const std::string& assimpUnavailableReason();

// Builds the aiScene contents for `mesh` once (outside the timing): one aiMesh in the given layout,
// one aiMaterial with a diffuse texture "checker.png" whose mapping is `mapping` around +Y. Then for
// each of `repetitions` runs (at least 1) hands a fresh copy of that scene to an Assimp::Importer
// (untimed) and times only Importer::ApplyPostProcessing(aiProcess_GenUVCoords) with a steady clock.
// Returns std::nullopt without assimp, for an empty mesh, an index out of range, or when assimp
// produced no UV channel.
std::optional<PeerTiming> measureAssimpGenUvCoords(const Mesh& mesh, AssimpMapping mapping,
                                                   int repetitions,
                                                   AssimpLayout layout = AssimpLayout::Verbose);

}  // namespace uvtk::peers
