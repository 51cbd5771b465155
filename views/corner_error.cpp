// The check view: per-corner errors interpolated across the faces, on a decade scale in texels.
#include "views/corner_error.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "render/procedural.h"
#include "views/canvas.h"
#include "views/legend.h"
#include "views/scene.h"

namespace uvtk::views {

namespace {

constexpr int kLowestDecade = -4;  // the scale starts at 1e-4 texels, as uverror's
constexpr int kU = 0, kFace = 3;   // channels of render::Rendering::aovs

}  // namespace

Image drawCornerError(const CornerErrorInput& in, const render::RenderOptions& options) {
  UVTK_CHECK(in.mesh != nullptr);
  const Mesh& mesh = *in.mesh;
  const std::size_t faces = mesh.faceCount();
  UVTK_CHECK(in.faces.size() == faces && in.texels.size() == 3 * faces);

  // The scale: decades from 1e-4 texels to the first power of ten at or above the largest error.
  double largest = 0.0;
  std::size_t poleFaces = 0, noValueFaces = 0;
  for (std::size_t f = 0; f < faces; ++f) {
    poleFaces += in.faces[f] == CheckedFace::Pole;
    noValueFaces += in.faces[f] == CheckedFace::NoValue;
    if (in.faces[f] == CheckedFace::Compared)
      for (std::size_t c = 3 * f; c < 3 * f + 3; ++c)
        if (std::isfinite(in.texels[c])) largest = std::max(largest, in.texels[c]);
  }
  int topDecade = kLowestDecade + 1;
  if (largest > std::pow(10.0, topDecade)) topDecade = int(std::ceil(std::log10(largest)));
  const ColourScale scale{Palette::Sequential, double(kLowestDecade), double(topDecade), true};

  // Each corner's position on the scale, interpolated by the renderer as the s coordinate.
  render::TexcoordSource corners;
  corners.corners.resize(3 * faces, Vec4(0, 0, 0, 1));
  for (std::size_t f = 0; f < faces; ++f)
    if (in.faces[f] == CheckedFace::Compared)
      for (std::size_t c = 3 * f; c < 3 * f + 3; ++c) {
        const double e = in.texels[c];
        corners.corners[c].x() = std::isfinite(e) ? scale.position(e) : 1.0;
      }
  // Only the AOVs are read: a 1 x 1 texture sampled NEAREST costs least.
  const render::Texture unit = render::checkerTexture(1, 1);
  render::RenderOptions o = options;
  o.texture = &unit;
  o.cubeTexture = nullptr;
  o.sampler = render::SamplerState{};
  o.env = render::EnvMode::Replace;
  o.aovs = true;
  o.samplesPerPixel = 1;
  const render::Rendering rendering = render::render(mesh, corners, o);

  // The head-light shade of each face, as the heatmaps compute it.
  const Mat4 eyeFromObject = options.camera.viewFromWorld * options.worldFromObject;
  std::vector<Vec3> eye(mesh.vertexCount());
  for (std::size_t v = 0; v < eye.size(); ++v) eye[v] = (eyeFromObject * mesh.positions[v].homogeneous()).head<3>();
  std::vector<double> shade(faces);
  for (std::size_t f = 0; f < faces; ++f) {
    const Triangle& t = mesh.triangles[f];
    shade[f] = faceShade(eye[std::size_t(t[0])], eye[std::size_t(t[1])], eye[std::size_t(t[2])]);
  }

  const Vec3 poleColour = statusColour(analysis::FaceStatus::PoleFace);
  const Vec3 noValueColour = statusColour(analysis::FaceStatus::Invalid);
  Image image(o.camera.width, o.camera.height, 3);
  for (int row = 0; row < image.height; ++row)
    for (int x = 0; x < image.width; ++x) {
      const float face = rendering.aovs.at(x, row, kFace);
      if (face < 0.0f) {
        setPixel(image, x, row, options.background);
        continue;
      }
      const std::size_t f = std::size_t(face);
      const double t = std::clamp(double(rendering.aovs.at(x, row, kU)), 0.0, 1.0);
      const Vec3 colour = in.faces[f] == CheckedFace::Pole      ? poleColour
                          : in.faces[f] == CheckedFace::NoValue ? noValueColour
                                                                : paletteColour(scale.palette, t);
      setPixel(image, x, row, Vec3(colour * shade[f]));
    }

  std::vector<double> decades;
  for (int k = kLowestDecade; k <= topDecade; ++k) decades.push_back(std::pow(10.0, k));
  const std::vector<std::string> labels = distinctLabels(decades);
  ColourBar bar{scale, {}};
  for (std::size_t k = 0; k < decades.size(); ++k) bar.ticks.push_back({decades[k], (k == 0 ? "≤" : "") + labels[k]});
  Legend legend;
  legend.title = in.title;
  legend.bar = bar;
  if (poleFaces > 0) legend.entries.push_back({poleColour, "pole faces: " + std::to_string(poleFaces)});
  if (noValueFaces > 0)
    legend.entries.push_back({noValueColour, "no value: " + std::to_string(noValueFaces) + " faces"});
  return withLegend(image, legend);
}

}  // namespace uvtk::views
