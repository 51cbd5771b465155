// The view of `uvtk check --view`: the mesh coloured by a per-corner error (stored UVs against the
// mapping's), interpolated across each face, on the uverror view's decade scale in texels, with
// the faces whose corners are set apart (pole faces, corners without a value) in their fixed
// colours. docs/check.md describes it; the colours and the legend are those of docs/views.md.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/mesh.h"
#include "render/renderer.h"

namespace uvtk::views {

enum class CheckedFace : std::uint8_t {
  Compared,  // coloured by its corners' errors
  Pole,      // a pole face: the pole_face colour (cyan)
  NoValue,   // a corner without a value on either side: the invalid colour (green)
};

struct CornerErrorInput {
  const Mesh* mesh = nullptr;
  std::vector<double> texels;      // per corner (3 per face): the error in texels; read on Compared faces
  std::vector<CheckedFace> faces;  // per face
  std::vector<std::string> title;  // the legend's title lines
};

// The mesh as options.camera sees it (the visibility and perspective-correct interpolation of
// render::render): on a Compared face each pixel takes the viridis colour of its position on the
// decade scale, t = clamp((log10 e + 4) / (k + 4)) from 1e-4 texels to 10^k (k the smallest integer
// with 10^k at least the largest error of a Compared corner, at least -3), with t computed per
// corner and interpolated across the face; the other faces take their fixed colours. Every face
// is then multiplied by its head-light shade (views/scene.h: 0.35 + 0.65 |n . l|), as the
// heatmaps are. Legend below: the title lines, the bar ticked at every decade, and an entry for
// pole faces and for faces without a value when there are any.
Image drawCornerError(const CornerErrorInput& in, const render::RenderOptions& options);

}  // namespace uvtk::views
