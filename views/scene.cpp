#include "views/scene.h"

#include <cmath>

#include "core/error.h"
#include "core/math.h"
#include "views/canvas.h"

namespace uvtk::views {

double faceShade(const Vec3& eye0, const Vec3& eye1, const Vec3& eye2) {
  // The edges at unit scale: the same direction, and a cross product that neither overflows (a mesh
  // at 1e200) nor underflows (at 1e-200).
  Mat3 edges;
  edges << eye1 - eye0, eye2 - eye0, Vec3::Zero();
  edges *= unitPowerOfTwo(edges);
  const Vec3 n = edges.col(0).cross(edges.col(1));
  const double length = n.norm();
  const double cosine = length > 0.0 ? std::fabs(n.z()) / length : 0.0;  // n . l with l = (0, 0, 1)
  return 0.35 + 0.65 * cosine;
}

std::vector<double> faceShades(const Mesh& mesh, const render::RenderOptions& options) {
  const Mat4 eyeFromObject = options.camera.viewFromWorld * options.worldFromObject;
  auto eye = [&](int v) -> Vec3 { return (eyeFromObject * mesh.positions[std::size_t(v)].homogeneous()).head<3>(); };
  std::vector<double> shade(mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    shade[f] = faceShade(eye(t[0]), eye(t[1]), eye(t[2]));
  }
  return shade;
}

Scene rasterizeScene(const Mesh& mesh, const render::RenderOptions& options) {
  const render::Camera& camera = options.camera;
  Scene scene;
  const Mat4 clipFromObject = camera.clipFromView * Mat4(camera.viewFromWorld * options.worldFromObject);
  render::clipPositions(mesh, clipFromObject, options.raster.threads, scene.clip);
  scene.visible = render::rasterize(scene.clip, mesh.triangles, camera.width, camera.height, options.raster);
  scene.shade = faceShades(mesh, options);
  return scene;
}

Image shadeFaces(const Scene& scene, const std::vector<Vec3>& colours, const Vec3& background) {
  UVTK_CHECK(colours.size() == scene.shade.size());
  const render::VisibilityBuffer& visible = scene.visible;
  Image image(visible.width, visible.height, 3);
  for (int row = 0; row < visible.height; ++row)
    for (int x = 0; x < visible.width; ++x) {
      const std::int32_t face = visible.face[visible.index(x, row)];
      setPixel(image, x, row, face < 0 ? background : Vec3(colours[std::size_t(face)] * scene.shade[std::size_t(face)]));
    }
  return image;
}

render::TexcoordSource cornerTexcoords(const ViewInput& in) {
  const UvMap& uv = *in.uv;
  render::TexcoordSource source;
  source.corners.reserve(uv.uv.size());
  for (std::size_t c = 0; c < uv.uv.size(); ++c)
    source.corners.emplace_back(uv.uv[c].x(), uv.uv[c].y(), uv.w.empty() ? 0.0 : uv.w[c], in.q ? (*in.q)[c] : 1.0);
  source.cubeFaceIds = in.cubeFaceIds;
  return source;
}

}  // namespace uvtk::views
