#include "options/compare_cli.h"

#include "options/cli_values.h"

namespace uvtk::cli {

inspect::CompareOptions CompareArguments::resolve() const {
  inspect::CompareOptions o = options;
  o.textureSize = parseTextureSize(textureSize, "--texture-size");
  o.check();
  o.camera = camera.resolve();
  return o;
}

void addCompareOptions(CLI::App& app, CompareArguments& arguments) {
  inspect::CompareOptions& a = arguments.options;
  addChoice<inspect::RankBy>(app, "--by", a.by, inspect::kRankByNames, "The measure that ranks (ties: the shorter seam)")
      ->default_str("stretch_l2");
  app.add_option("--json", a.json, "Write the ranking with every measure as JSON");
  app.add_option("--markdown", a.markdown, "Also write the table (printed on stdout) to this file");
  app.add_option("--sheet", a.sheet, "Write a contact sheet of the checker and stretch views of the best ones");
  app.add_option("--write-best", a.writeBest,
                 "Write the mesh with the first-ranked mapping's UVs, as uvtk map writes it with that row's options");
  app.add_option("--margin", a.margin, "Texels of gutter between the charts of the atlas, LSCM and ARAP")
      ->capture_default_str();
  app.add_option("--top", a.top, "How many of the best the contact sheet shows")->capture_default_str();
  app.add_option("--tile-size", a.tileSize, "Pixels across each picture of the sheet")->capture_default_str();
  addViewCameraOptions(app, arguments.camera);
  addOverlapResolutionOption(app, a.overlapResolution);
  app.add_option("--texture-size", arguments.textureSize, "Texels W,H (or N: N,N) of the texture texel density counts in")
      ->capture_default_str();
  app.add_flag("--seam-place-auto", a.seamPlaceAuto, "Place the seam of cylinder and sphere (as --seam-place auto)");
  app.add_flag("!--no-baselines", a.baselines, "Leave out CGAL's LSCM and ARAP");
  app.add_option("--baseline-max-faces", a.baselineMaxFaces, "Run LSCM and ARAP only on meshes up to this size")
      ->capture_default_str();
  app.add_option("--threads", a.threads, "Threads for the pictures (0: one per hardware thread)")
      ->capture_default_str();
}

}  // namespace uvtk::cli
