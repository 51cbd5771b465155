#include "views/views.h"

#include <string>

#include "core/error.h"
#include "core/names.h"
#include "views/draw.h"

namespace uvtk::views {

namespace {

constexpr View kViews[] = {View::Checker, View::Uvgrid, View::Stretch, View::Linf,    View::Angle,    View::Area,
                           View::Seams,   View::UvError, View::Layout, View::Density, View::Weights, View::BlendZone, View::MipLine,
                           View::Bleed};

std::vector<std::string> viewNames() {
  std::vector<std::string> names;
  for (View v : kViews) names.push_back(toString(v));
  return names;
}

}  // namespace

const char* toString(View view) {
  switch (view) {
    case View::Checker: return "checker";
    case View::Uvgrid: return "uvgrid";
    case View::Stretch: return "stretch";
    case View::Linf: return "linf";
    case View::Angle: return "angle";
    case View::Area: return "area";
    case View::Seams: return "seams";
    case View::UvError: return "uverror";
    case View::Layout: return "layout";
    case View::Density: return "density";
    case View::Weights: return "weights";
    case View::BlendZone: return "blendzone";
    case View::MipLine: return "mipline";
    case View::Bleed: return "bleed";
  }
  return "checker";
}

std::optional<View> parseView(std::string_view name) {
  for (View v : kViews)
    if (name == toString(v)) return v;
  return std::nullopt;
}

std::vector<View> parseViewList(const std::string& commaList, const std::string& option) {
  std::vector<View> views;
  for (std::size_t start = 0;;) {  // every entry, the empty ones too ("", "a,", "a,,b")
    const std::size_t end = commaList.find(',', start);
    const std::string name = commaList.substr(start, end - start);
    const std::optional<View> view = parseView(name);
    if (!view) throw UsageError(option + ": " + notOneOf(name, viewNames()));
    views.push_back(*view);
    if (end == std::string::npos) return views;
    start = end + 1;
  }
}

bool needsExactMapping(View view) { return view == View::UvError || view == View::Weights || view == View::BlendZone; }

Image drawView(View view, const ViewInput& in, const ViewOptions& options) {
  const DrawnView drawn = drawViewAndLegend(view, in, options);
  return drawn.legend.empty() ? drawn.image : withLegend(drawn.image, drawn.legend);
}

DrawnView drawViewAndLegend(View view, const ViewInput& in, const ViewOptions& options) {
  UVTK_CHECK(in.mesh && in.uv && in.uv->uv.size() == 3 * in.mesh->faceCount());
  switch (view) {
    case View::Checker:
    case View::Uvgrid: return drawTextured(view, in, options);
    case View::Stretch:
    case View::Linf:
    case View::Angle:
    case View::Area:
    case View::Density: return drawHeatmap(view, in, options);
    case View::Seams: return drawSeams(in, options);
    case View::UvError: return drawUvError(in, options);
    case View::Layout: return drawLayout(in, options);
    case View::Weights: return drawWeights(in, options);
    case View::BlendZone: return drawBlendZone(in, options);
    case View::MipLine: return drawMipLine(in, options);
    case View::Bleed: return drawBleed(in, options);
  }
  checkFailed("a known view", __FILE__, __LINE__);
}

}  // namespace uvtk::views
