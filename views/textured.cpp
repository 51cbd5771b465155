// checker and uvgrid: the mesh as the renderer draws it with a procedural texture, REPLACE.
#include <optional>

#include "core/error.h"
#include "render/procedural.h"
#include "views/draw.h"
#include "views/scene.h"

namespace uvtk::views {

Image drawTextured(View view, const ViewInput& in, const ViewOptions& options) {
  UVTK_CHECK(view == View::Checker || view == View::Uvgrid);
  std::optional<render::Texture> texture = render::proceduralTexture(view == View::Checker ? "checker:64:8" : "uvgrid:1024");
  render::RenderOptions o = options.render;  // the sampler as given: NEAREST and REPEAT by default
  if (render::needsMipmaps(o.sampler.minFilter)) texture->buildMipmaps();
  o.texture = &*texture;
  o.cubeTexture = nullptr;
  o.env = render::EnvMode::Replace;
  o.aovs = false;
  return render::render(*in.mesh, cornerTexcoords(in), o).colour;
}

}  // namespace uvtk::views
