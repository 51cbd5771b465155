#include "options/report_cli.h"

#include "options/cli_values.h"

namespace uvtk::cli {

inspect::ViewCamera ViewCameraArguments::resolve() const {
  inspect::ViewCamera camera;
  camera.viewDir = parseVec3(viewDir, "--view-dir");
  camera.up = parseVec3(up, "--up");
  return camera;
}

void addViewCameraOptions(CLI::App& app, ViewCameraArguments& a) {
  app.add_option("--view-dir", a.viewDir, "Direction from the mesh to the camera of the views")->capture_default_str();
  app.add_option("--up", a.up, "The up direction of the views' camera")->capture_default_str();
}

void addReportOptions(CLI::App& app, ReportArguments& a) {
  app.add_option("--json", a.json, "Write every measure as JSON");
  app.add_option("--html", a.html, "Write one self-contained HTML page with the views, measures and histograms");
  app.add_option("--views", a.views, "The views on the HTML page")->capture_default_str();
  app.add_option("--size", a.size, "Size of each view WxH")->capture_default_str();
  addViewCameraOptions(app, a.camera);
  app.add_option("--texture-size", a.textureSize,
                 "Texels W,H (or N: N,N) of the texture that texel density and uverror count in")
      ->capture_default_str();
  addOverlapResolutionOption(app, a.overlapResolution);
  app.add_option("--threads", a.threads, "Threads for the views (0: one per hardware thread)")->capture_default_str();
  app.add_option("--view3d-faces", a.view3dFaces, "Faces the page's 3D view shows before it decimates (0: no 3D view)")
      ->capture_default_str();
}

inspect::ReportOptions ReportArguments::options() const {
  const auto numbers = [](const auto& vector) { return std::vector<double>(vector.data(), vector.data() + vector.size()); };
  param::ParameterDictionary p(param::ParameterFace::CommandLine);
  p.add("json", json);
  p.add("html", html);
  p.add("views", views);
  p.add("size", size);
  p.add("view-dir", numbers(parseVec3(camera.viewDir, "--view-dir")));
  p.add("up", numbers(parseVec3(camera.up, "--up")));
  const analysis::TextureSize texture = parseTextureSize(textureSize, "--texture-size");
  p.add("texture-size", std::vector<double>{double(texture.width), double(texture.height)});
  p.add("overlap-resolution", std::int64_t(overlapResolution));
  p.add("threads", std::int64_t(threads));
  p.add("view3d-faces", std::int64_t(view3dFaces));
  const inspect::ReportOptions o = inspect::readReportOptions(p);
  o.check();
  return o;
}

}  // namespace uvtk::cli
