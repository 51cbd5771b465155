// stretch, linf, angle, area: each visible face in its measure's colour times a head-light shade.
#include "core/error.h"
#include "views/draw.h"
#include "views/legend.h"
#include "views/measure.h"
#include "views/scene.h"

namespace uvtk::views {

Image drawHeatmap(View view, const ViewInput& in, const ViewOptions& options) {
  UVTK_CHECK(in.faces && in.summary);
  const FaceColouring colouring = colourByMeasure(view, *in.faces, *in.summary);
  const Scene scene = rasterizeScene(*in.mesh, options.render);
  return withLegend(shadeFaces(scene, colouring.colours, options.render.background), colouring.legend);
}

}  // namespace uvtk::views
