// The mesh as the camera sees it, for the views that colour faces themselves: clip-space
// vertices, the visibility buffer (render/raster.h) and a flat head-light shade per face.
#pragma once

#include <vector>

#include "core/image.h"
#include "core/mesh.h"
#include "core/uv_map.h"
#include "render/raster.h"
#include "render/renderer.h"
#include "views/views.h"

namespace uvtk::views {

struct Scene {
  std::vector<Vec4> clip;             // per vertex, as render::clipPositions gives them
  render::VisibilityBuffer visible;   // camera.width x camera.height
  std::vector<double> shade;          // per face: faceShade of its eye-space corners
};

// Lambert's cosine under the renderer's head-light (a directional light along the view, as
// render/shading.h), lifted so that faces seen edge-on stay readable: 0.35 + 0.65 |n . l| with
// n the face's unit normal in eye space and l = (0, 0, 1); 0.35 for a face of zero area. The same
// for the triangle at any scale (1e-200 or 1e200).
double faceShade(const Vec3& eye0, const Vec3& eye1, const Vec3& eye2);

// faceShade of every face's eye-space corners under options.camera and worldFromObject.
std::vector<double> faceShades(const Mesh& mesh, const render::RenderOptions& options);

// Rasterizes `mesh` with options.camera, worldFromObject and raster options.
Scene rasterizeScene(const Mesh& mesh, const render::RenderOptions& options);

// The visible faces in colours[face] times their shade, `background` elsewhere (RGB, row 0 at the top).
Image shadeFaces(const Scene& scene, const std::vector<Vec3>& colours, const Vec3& background);

// The per-corner texture coordinates as the renderer takes them: (s, t, r, q) with r from uv.w
// (0 without) and q from in.q (1 without), cube face ids as in.cubeFaceIds says.
render::TexcoordSource cornerTexcoords(const ViewInput& in);

}  // namespace uvtk::views
