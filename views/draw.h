// One function per kind of view, behind drawView (views/views.cpp), which checks the inputs
// every view needs (mesh and uv) before dispatching.
#pragma once

#include "core/image.h"
#include "views/views.h"

namespace uvtk::views {

// Each returns the picture without its legend strip, and the legend drawView puts below it.
DrawnView drawTextured(View view, const ViewInput& in, const ViewOptions& options);  // checker, uvgrid
DrawnView drawHeatmap(View view, const ViewInput& in, const ViewOptions& options);   // stretch, linf, angle, area
DrawnView drawSeams(const ViewInput& in, const ViewOptions& options);
DrawnView drawUvError(const ViewInput& in, const ViewOptions& options);
DrawnView drawLayout(const ViewInput& in, const ViewOptions& options);
DrawnView drawWeights(const ViewInput& in, const ViewOptions& options);    // triplanar weights
DrawnView drawBlendZone(const ViewInput& in, const ViewOptions& options);  // triplanar blend zone
DrawnView drawMipLine(const ViewInput& in, const ViewOptions& options);    // the GPU's seam mip line
DrawnView drawBleed(const ViewInput& in, const ViewOptions& options);      // the layout's texels at a mip level

}  // namespace uvtk::views
