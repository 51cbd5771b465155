// The examples are real commands that work from the source folder (meshes/ holds the bundled
// meshes) when run in this order: later ones read what earlier ones wrote (sphere_uv.obj, mapped/).
// tests/apps/cli_manners_test.cpp runs every one of them.
#include "help_examples.h"

#include <string>
#include <utility>
#include <vector>

namespace uvtk::cli {

namespace {

// Command name ("" for uvtk itself) -> examples: each a command line, then what it does.
const std::vector<std::pair<std::string, std::string>>& examples() {
  static const std::vector<std::pair<std::string, std::string>> table = {
      {"",
       "  uvtk map meshes/sphere_latlong.obj --projector sphere -o sphere_uv.obj\n"
       "      sphere UVs for a mesh\n"
       "  uvtk map --help\n"
       "      every option of a command, and examples"},
      {"map",
       "  uvtk map meshes/sphere_latlong.obj --projector sphere -o sphere_uv.obj\n"
       "      sphere UVs for a mesh\n"
       "  uvtk map meshes -o mapped --json mapped -q\n"
       "      every .obj and .off of a folder, with a JSON summary each and batch.json"},
      {"texgen",
       "  uvtk texgen meshes/icosphere.obj --mode sphere_map -o icosphere_st.obj\n"
       "      glTexGen's sphere map under the default view\n"
       "  uvtk texgen meshes/plane_grid.obj --s object_linear:1,0,0,0 --t object_linear:0,1,0,0 -o plane_st.obj\n"
       "      s = x, t = y"},
      {"render",
       "  uvtk render sphere_uv.obj --texture uvgrid -o sphere.png\n"
       "      the file's own UVs, textured with a UV grid\n"
       "  uvtk render meshes/torus.obj --projector cylinder --view checker,stretch,seams -o torus_views.png\n"
       "      a contact sheet of inspection views of a projector's UVs"},
      {"report",
       "  uvtk report sphere_uv.obj --html sphere.html\n"
       "      one HTML page with the views, measures and histograms of the file's UVs\n"
       "  uvtk report meshes/cube.obj --projector cube --cube-layout cross --json cube.json --fail-on fail\n"
       "      a projector's measures as JSON; exit 1 when the verdict is fail"},
      {"compare",
       "  uvtk compare meshes/cylinder_open.obj --by angle --sheet best.png\n"
       "      every mapping ranked by angle distortion, and a picture of the best ones"},
      {"bench",
       "  uvtk bench --mesh meshes/sphere_latlong.obj --projector sphere,cylinder --threads 1 --min-time 0.1 "
       "--no-peers --json bench.json\n"
       "      a quick measure of two projectors on a small mesh"},
      {"run",
       "  uvtk run meshes/demo.json --plan\n"
       "      the stages the scene's outputs need, without running them\n"
       "  uvtk run meshes/demo.json -o ./demo -q\n"
       "      the scene's outputs, into demo/"},
      {"schema",
       "  uvtk schema > scene.schema.json\n"
       "      the schema, for an editor that checks scene files as they are typed"},
      {"merge-reports",
       "  uvtk merge-reports mapped -o all.json\n"
       "      one report, with totals, of the JSON files that uvtk map wrote into mapped/"},
      {"eval",
       "  uvtk eval --projector sphere --point 1,0,0 --point 0,0,1\n"
       "      the UVs of two points, a CSV line each\n"
       "  echo 0.5,0.5,1 | uvtk eval --projector cylinder --format json\n"
       "      points from stdin, JSON out"},
      {"check",
       "  uvtk check sphere_uv.obj --projector sphere --tolerance 1e-9\n"
       "      exit 1 when a stored UV is more than 1e-9 from the sphere projector's\n"
       "  uvtk check sphere_uv.obj --against mapped/sphere_latlong.obj --view errors.png\n"
       "      compare with another file's UVs, with a heatmap of the errors"},
  };
  return table;
}

void addExamples(CLI::App& app, const std::string& text) {
  const std::string footer = app.get_footer();
  app.footer((footer.empty() ? "" : footer + "\n\n") + "Examples:\n" + text);
}

}  // namespace

void addHelpExamples(CLI::App& root) {
  std::vector<CLI::App*> apps = root.get_subcommands({});
  apps.insert(apps.begin(), &root);
  for (CLI::App* app : apps) {
    const std::string name = app == &root ? "" : app->get_name();
    for (const auto& [command, text] : examples())
      if (command == name) addExamples(*app, text);
  }
}

}  // namespace uvtk::cli
