// The checker view: ViewOptions::checks light and dark checks across the unit square, shaded by
// the renderer's head-light (MODULATE), the background left alone (docs/views.md).
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "core/error.h"
#include "meshes/generators.h"
#include "render/camera.h"
#include "render/raster.h"
#include "render/shading.h"
#include "views/views.h"

namespace uvtk::views {
namespace {
namespace UVTK_TEST_FILE {

constexpr float kLight = 230.0f / 255.0f, kDark = 89.0f / 255.0f;  // the texels, as a float image stores them

// A mesh with per-corner UVs from its positions: (x, y) -> ((x + 1)/2, (y + 1)/2).
struct Flat {
  Mesh mesh;
  UvMap uv;
  explicit Flat(Mesh m) : mesh(std::move(m)) {
    for (const Triangle& t : mesh.triangles)
      for (int k = 0; k < 3; ++k) {
        const Vec3& p = mesh.positions[std::size_t(t[k])];
        uv.uv.emplace_back((p.x() + 1.0) / 2.0, (p.y() + 1.0) / 2.0);
      }
    uv.faceFlags.assign(mesh.faceCount(), kFaceOk);
    uv.cornerInvalid.assign(3 * mesh.faceCount(), kCornerValid);
  }
  ViewInput input() const {
    ViewInput in;
    in.mesh = &mesh;
    in.uv = &uv;
    return in;
  }
};

ViewOptions orthographicFrom(const Mesh& mesh, const Vec3& direction, const Vec3& up, int size) {
  ViewOptions o;
  o.render.camera =
      render::frameSphere(render::boundingSphere(mesh.positions), direction, up, {true, 40.0}, size, size);
  o.render.background = Vec3(0.1, 0.2, 0.3);
  return o;
}

// The window pixel (column, row from the top) of an object-space point.
std::pair<int, int> pixelOf(const ViewOptions& o, const Vec3& p) {
  const Vec4 c = o.render.camera.clipFromView * o.render.camera.viewFromWorld * o.render.worldFromObject * p.homogeneous();
  const int w = o.render.camera.width, h = o.render.camera.height;
  return {int((c.x() / c.w() + 1.0) * 0.5 * w), int(h - (c.y() / c.w() + 1.0) * 0.5 * h)};
}

Vec3 pixel(const Image& image, int x, int y) {
  return Vec3(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2));
}

// The runs of equal colour along row y over the pixels that are not the background.
std::vector<Vec3> runsAlongRow(const Image& image, int y, const Vec3& background) {
  std::vector<Vec3> runs;
  for (int x = 0; x < image.width; ++x) {
    const Vec3 c = pixel(image, x, y);
    if ((c - background).norm() < 1e-6) continue;
    if (runs.empty() || (runs.back() - c).norm() > 1e-6) runs.push_back(c);
  }
  return runs;
}

TEST(CheckerView, SixteenChecksAcrossTheUnitSquareByDefault) {
  const Flat quad(meshes::planeGrid(4, 4, 2.0, 2.0));  // [-1, 1]^2 in z = 0: UVs over [0, 1]^2
  const ViewOptions o = orthographicFrom(quad.mesh, Vec3::UnitZ(), Vec3::UnitY(), 256);
  ASSERT_EQ(o.checks, 16);
  const Image image = drawView(View::Checker, quad.input(), o);
  ASSERT_EQ(image.width, 256);
  ASSERT_EQ(image.height, 256);
  // A row at v = 0.55 (y = 0.1), inside the ninth row of checks: 16 checks, alternating.
  const int row = pixelOf(o, Vec3(0.0, 0.1, 0.0)).second;
  const std::vector<Vec3> runs = runsAlongRow(image, row, o.render.background);
  ASSERT_EQ(runs.size(), 16u);
  // Face-on the head-light gives 0.04 + 0.8 + 0.5, clamped to 1: the checks' own colours. The
  // ninth row (j = 8) starts light at u = 0, as the row at v = 0 does.
  for (std::size_t i = 0; i < runs.size(); ++i)
    EXPECT_LT((runs[i] - Vec3::Constant(i % 2 == 0 ? kLight : kDark)).norm(), 1e-6) << i << ": " << runs[i].transpose();
  // The corner check at u = v = 0 (bottom left) is light.
  const auto [x0, y0] = pixelOf(o, Vec3(-0.97, -0.97, 0.0));
  EXPECT_LT((pixel(image, x0, y0) - Vec3::Constant(kLight)).norm(), 1e-6);
  // The background stays the background.
  EXPECT_LT((pixel(image, 0, 0) - o.render.background).norm(), 1e-6);
  EXPECT_LT((pixel(image, 255, 128) - o.render.background).norm(), 1e-6);
}

TEST(CheckerView, ChecksFollowTheOption) {
  const Flat quad(meshes::planeGrid(4, 4, 2.0, 2.0));
  ViewOptions o = orthographicFrom(quad.mesh, Vec3::UnitZ(), Vec3::UnitY(), 256);
  const int row = pixelOf(o, Vec3(0.0, 0.03, 0.0)).second;
  for (int checks : {1, 5, 16, 40}) {
    o.checks = checks;
    EXPECT_EQ(runsAlongRow(drawView(View::Checker, quad.input(), o), row, o.render.background).size(),
              std::size_t(checks))
        << checks;
  }
  for (int checks : {0, -3, 1025}) {
    o.checks = checks;
    EXPECT_THROW(drawView(View::Checker, quad.input(), o), UsageError) << checks;
  }
}

TEST(CheckerView, FacesAtDifferentAnglesToTheLightAreShadedByTheRenderersLighting) {
  // One check (all light): every covered pixel is the light texel times the head-light's colour
  // (render::headlightColour, the renderer's lighting) of the face's eye-space normal.
  const Flat cube(meshes::cube(4));  // each face a 4 x 4 grid: the face centre's neighbours share its normal
  ViewOptions o = orthographicFrom(cube.mesh, Vec3(1.0, 0.6, 0.3).normalized(), Vec3::UnitZ(), 256);
  o.checks = 1;
  const Image image = drawView(View::Checker, cube.input(), o);
  const Mat3 eyeFromObject = o.render.camera.viewFromWorld.topLeftCorner<3, 3>();
  std::vector<double> brightness;
  const Vec3 axes[] = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
  for (const Vec3& n : axes) {
    const auto [x, y] = pixelOf(o, n);  // the centre of the face whose normal is n
    const Vec4 lit = render::headlightColour(o.render.lighting, (eyeFromObject * n).normalized());
    const Vec3 expected = lit.head<3>() * double(kLight);
    EXPECT_LT((pixel(image, x, y) - expected).norm(), 2e-6) << n.transpose() << ": " << pixel(image, x, y).transpose();
    brightness.push_back(pixel(image, x, y).x());
  }
  // The three faces meet the light at different angles: three different brightnesses of one check colour.
  EXPECT_GT(brightness[0], brightness[1] + 0.05);
  EXPECT_GT(brightness[1], brightness[2] + 0.05);
  EXPECT_LT((pixel(image, 0, 0) - o.render.background).norm(), 1e-6);
}

TEST(CheckerView, LightAndDarkChecksStayApartAtEveryAngle) {
  // A light check's shade over a dark check's is the texels' ratio, 230/89, wherever both are lit.
  const Flat quad(meshes::planeGrid(4, 4, 2.0, 2.0));
  ViewOptions o = orthographicFrom(quad.mesh, Vec3(0.0, -1.0, 0.6).normalized(), Vec3::UnitZ(), 256);
  const Image image = drawView(View::Checker, quad.input(), o);
  const std::vector<Vec3> runs = runsAlongRow(image, pixelOf(o, Vec3(0.0, 0.03, 0.0)).second, o.render.background);
  ASSERT_EQ(runs.size(), 16u);
  for (std::size_t i = 0; i + 1 < runs.size(); ++i) {
    const double ratio = i % 2 == 0 ? runs[i].x() / runs[i + 1].x() : runs[i + 1].x() / runs[i].x();
    EXPECT_NEAR(ratio, 230.0 / 89.0, 1e-5) << i;
    EXPECT_LT(runs[i].x(), kLight - 0.05);  // shaded: the plane is seen (and lit) at a slant
  }
}

TEST(CheckerView, AMeshWoundInwardsIsLitAsItsOutwardTwinTwoSided) {
  // Drawn without culling, every face the camera sees of the inward cube is a back face, which
  // two-sided lighting lights with its normals negated: the outward twin's. The same picture, but
  // where a pixel centre lies on a check's edge (the reversed corners' barycentrics may round
  // differently there).
  const Flat outward(meshes::cube(4));
  Mesh reversed = meshes::cube(4);
  for (Triangle& t : reversed.triangles) std::swap(t[1], t[2]);
  const Flat inward(std::move(reversed));
  ViewOptions o = orthographicFrom(outward.mesh, Vec3(1.0, 0.6, 0.3).normalized(), Vec3::UnitZ(), 256);
  o.render.raster.cull = render::Cull::None;
  const Image a = drawView(View::Checker, outward.input(), o), b = drawView(View::Checker, inward.input(), o);
  std::size_t covered = 0, same = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      if ((pixel(a, x, y) - o.render.background).norm() < 1e-6) continue;
      ++covered;
      same += (pixel(a, x, y) - pixel(b, x, y)).norm() < 1e-6;
    }
  EXPECT_GT(covered, 10000u);
  EXPECT_GE(double(same), 0.999 * double(covered)) << same << " of " << covered;
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::views
