// checker and uvgrid: the mesh as the renderer draws it with a procedural texture. The checker is
// shaded by the renderer's head-light (MODULATE), so that silhouettes and the mesh's form read
// through the checks; uvgrid shows its texture as it is (REPLACE). docs/views.md.
#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "core/error.h"
#include "render/procedural.h"
#include "views/draw.h"
#include "views/scene.h"

namespace uvtk::views {

namespace {

// The checker view's texture: `checks` x `checks` squares over [0, 1]^2 of c = clamp(2048 /
// checks, 1, 8) texels each; the square holding texel (0, 0) (at u = v = 0) is light
// (230, 230, 230) / 255, its neighbours dark (89, 89, 89) / 255 (about 0.9 and 0.35): both stay
// apart under any shade, and neither is the usual black background. 8-bit.
render::Texture checkerViewTexture(int checks) {
  if (checks < 1 || checks > 1024)
    throw UsageError("checker view: expected 1 to 1024 checks, got " + std::to_string(checks));
  const int c = std::clamp(2048 / checks, 1, 8), n = checks * c;
  render::TexelLevel base;
  base.width = base.height = n;
  base.texels.resize(std::size_t(n) * std::size_t(n));
  const render::Rgba light(230.0f / 255.0f, 230.0f / 255.0f, 230.0f / 255.0f, 1.0f);
  const render::Rgba dark(89.0f / 255.0f, 89.0f / 255.0f, 89.0f / 255.0f, 1.0f);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) base.at(i, j) = (i / c + j / c) % 2 == 0 ? light : dark;
  return render::Texture(std::move(base), true);
}

}  // namespace

DrawnView drawTextured(View view, const ViewInput& in, const ViewOptions& options) {
  UVTK_CHECK(view == View::Checker || view == View::Uvgrid);
  const bool checker = view == View::Checker;
  std::optional<render::Texture> texture =
      checker ? std::optional<render::Texture>(checkerViewTexture(options.checks)) : render::proceduralTexture("uvgrid:1024");
  render::RenderOptions o = options.render;  // the sampler as given: NEAREST and REPEAT by default
  if (render::needsMipmaps(o.sampler.minFilter)) texture->buildMipmaps();
  o.texture = &*texture;
  o.cubeTexture = nullptr;
  // The checker: the texel times the renderer's lighting (options.render.lighting, the head-light
  // of render/shading.h, per vertex); uvgrid: the texel alone.
  o.env = checker ? render::EnvMode::Modulate : render::EnvMode::Replace;
  // Two-sided, as the other views' shade |n . l|: an open scan or an inward-wound mesh seen from
  // behind is lit as its front would be, not left in the ambient term.
  o.lighting.twoSided = true;
  o.aovs = false;
  return {render::render(*in.mesh, cornerTexcoords(in), o).colour, Legend{}};
}

}  // namespace uvtk::views
