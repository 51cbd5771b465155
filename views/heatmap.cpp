// stretch, linf, angle, area, density: each visible face in its measure's colour times a head-light shade.
#include "core/error.h"
#include "views/draw.h"
#include "views/legend.h"
#include "views/measure.h"
#include "views/scene.h"

namespace uvtk::views {

DrawnView drawHeatmap(View view, const ViewInput& in, const ViewOptions& options) {
  UVTK_CHECK(in.judgement);
  const FaceColouring colouring = colourByMeasure(view, *in.judgement);
  const Scene scene = rasterizeScene(*in.mesh, options.render);
  return {shadeFaces(scene, colouring.colours, options.render.background), colouring.legend};
}

}  // namespace uvtk::views
