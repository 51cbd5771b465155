// The interactive 3D view of a mapping in an HTML page (docs/views.md, "The 3D view"): the mesh
// with its UVs, turned, zoomed and panned with the mouse or by touch (three.js, vendored in
// third_party/three), with switchable layers (the checker, the UV grid, each distortion heatmap
// with its legend, the face statuses, the seams) and the face under the pointer named with its
// measures. Everything is inlined: the page makes no request.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "analysis/judgement.h"
#include "core/mesh.h"
#include "core/uv_map.h"
#include "inspect/mapped_mesh.h"

namespace uvtk::inspect {

struct MeshViewOptions {
  std::size_t faceBudget = 200000;  // above it, the view shows a decimated mesh and says so
  ViewCamera camera;                // the first view's direction, as the static views'
  int checks = 16;                  // the checker layer's checks across [0, 1]^2, as the checker view's
};

// The faces a 3D view shows: all of them, or within a budget, a vertex clustering of the mesh
// (Rossignac and Borrel 1993): vertices merged per cell of a uniform grid, at the mean of their
// positions, and the faces whose three vertices fall in three cells kept (one per cell triple),
// each with its own corners' UVs. The grid is refined or coarsened until the faces fit the budget.
struct ViewMesh {
  Mesh mesh;                          // the shown vertices and faces
  UvMap uv;                           // the shown faces' corners, from their original faces
  std::vector<std::size_t> faceOf;    // per shown face, the original face
  std::vector<int> vertexOf;          // per original vertex, its shown vertex
  bool decimated = false;
};
// Precondition: uv has 3 corners and one flag set per face of `mesh`; faceBudget >= 1.
ViewMesh viewMesh(const Mesh& mesh, const UvMap& uv, std::size_t faceBudget);

// The view's HTML: a <div class="view3d"> with its controls, canvas, legends and data. `mapped`
// with its `judgement`. A page shows any number of them and then meshViewScripts() once.
std::string meshViewHtml(const MappedMesh& mapped, const analysis::Judgement& judgement,
                         const MeshViewOptions& options);

// The scripts every page with 3D views ends with: three.js and the viewer, inlined.
std::string meshViewScripts();

}  // namespace uvtk::inspect
