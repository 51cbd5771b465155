#include "options/check_cli.h"

#include <cmath>

#include "core/error.h"
#include "io/image_io.h"
#include "options/cli_values.h"

namespace uvtk::cli {

inspect::CheckOptions CheckArguments::resolve() const {
  if (textureSize < 1) throw UsageError("--texture-size: expected a positive number of texels");
  if (worst < 0) throw UsageError("--worst: expected a count of corners, 0 or more");
  if (tolerance && !(std::isfinite(*tolerance) && *tolerance >= 0.0))
    throw UsageError("--tolerance: expected a finite number of UV units, 0 or more");
  if (wrap != "none" && wrap != "u") throw UsageError("--wrap: expected none or u, found \"" + wrap + "\"");
  inspect::CheckOptions o;
  if (!against.empty()) {
    for (const std::string& name : mappingOptions)
      if (given(mapping.app, name.c_str()))
        throw UsageError("--against compares two files: " + name + " (a mapping option) does not go with it");
  } else {
    if (given(mapping.app, "--wrap"))
      throw UsageError("--wrap goes with --against only: a mapping knows its own period");
    const ResolvedMapping resolved = resolveMapping(mapping);
    if (resolved.projector && resolved.projector->seam == param::SeamMode::Cut)
      throw UsageError(
          "--seam cut changes the triangles, and uvtk check compares corner by corner: use --seam shift or none (u "
          "is compared modulo its period, so the seam's side does not matter)");
    o.projector = resolved.projector;
    o.texgen = resolved.texgen;
    o.seamPlaceAuto = resolved.seamPlaceAuto;
  }
  if (!view.empty()) {
    std::tie(o.viewWidth, o.viewHeight) = parseImageSize(viewSize, "--view-size");
    o.viewDir = parseVec3(viewDir, "--view-dir");
    o.viewUp = parseVec3(viewUp, "--view-up");
    io::checkImageType(view, io::PixelType::UInt8);
  }
  o.input = input, o.against = against, o.wrapU = wrap == "u", o.partial = partial;
  o.textureSize = textureSize, o.worst = std::size_t(worst), o.tolerance = tolerance;
  o.thresholds = verdict.thresholds();
  o.json = json, o.view = view;
  return o;
}

}  // namespace uvtk::cli
