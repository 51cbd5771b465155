// One function per kind of view, behind drawView (views/views.cpp), which checks the inputs
// every view needs (mesh and uv) before dispatching.
#pragma once

#include "core/image.h"
#include "views/views.h"

namespace uvtk::views {

Image drawTextured(View view, const ViewInput& in, const ViewOptions& options);  // checker, uvgrid
Image drawHeatmap(View view, const ViewInput& in, const ViewOptions& options);   // stretch, linf, angle, area
Image drawSeams(const ViewInput& in, const ViewOptions& options);
Image drawUvError(const ViewInput& in, const ViewOptions& options);
Image drawLayout(const ViewInput& in, const ViewOptions& options);

}  // namespace uvtk::views
