// The triplanar views: weights draws (w_x, w_y, w_z) as RGB, blendzone marks where no weight
// reaches the threshold, and blendZone counts those pixels; checked on planes whose weights are
// known by hand and on a sphere, where every covered pixel's weights sum to 1 (docs/views.md).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/error.h"
#include "doubles.h"
#include "meshes/generators.h"
#include "param/triplanar.h"
#include "render/camera.h"
#include "views/canvas.h"
#include "views/scene.h"
#include "views/views.h"

namespace uvtk::views {
namespace {
namespace UVTK_TEST_FILE {

// Unity's triplanar weights |n_i|^B / sum_j |n_j|^B with B = 1, and its three (u, v), as the
// triplanar projector hands them to the renderer.
render::PixelMapping unityTriplanar() {
  render::PixelMapping m;
  m.needsNormal = true;
  m.blendAt = [](const Vec3& p, const Vec3& n, std::int32_t) {
    const param::TriplanarSample s = param::triplanarAt(param::TriplanarOptions{}, p, n);
    return render::TexcoordBlend{s.uv, s.weights};
  };
  return m;
}

// A mesh with one (unused) UV per corner and the triplanar mapping.
struct Triplanar {
  Mesh mesh;
  UvMap uv;
  std::optional<render::PixelMapping> exact = unityTriplanar();
  explicit Triplanar(Mesh m) : mesh(std::move(m)) {
    uv.uv.assign(3 * mesh.faceCount(), Vec2::Zero());
    uv.faceFlags.assign(mesh.faceCount(), kFaceOk);
    uv.cornerInvalid.assign(3 * mesh.faceCount(), kCornerValid);
  }
  ViewInput input() const {
    ViewInput in;
    in.mesh = &mesh, in.uv = &uv, in.exact = exact;
    return in;
  }
};

// The square [-1, 1]^2 of the plane through the origin with unit normal `normal`, wound
// counter-clockwise seen from the normal's side.
Mesh squareFacing(const Vec3& normal) {
  const Vec3 n = normal.normalized();
  const Vec3 u = n.unitOrthogonal(), v = n.cross(u);
  Mesh mesh;
  for (const Vec2& c : {Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)}) mesh.positions.push_back(c.x() * u + c.y() * v);
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

const Vec3 kBackground(0.1, 0.2, 0.3);  // sums to 0.6: never a weights colour

ViewOptions viewFrom(const Mesh& mesh, const Vec3& direction, bool orthographic, int size = 64) {
  ViewOptions o;
  o.render.camera = render::frameSphere(render::boundingSphere(mesh.positions), direction, direction.unitOrthogonal(),
                                        {orthographic, 40.0}, size, size);
  o.render.background = kBackground;
  return o;
}

bool covered(const Scene& scene, int x, int row) { return scene.visible.face[scene.visible.index(x, row)] >= 0; }

std::size_t coveredCount(const Scene& scene) {
  std::size_t n = 0;
  for (std::int32_t f : scene.visible.face) n += f >= 0;
  return n;
}

bool hasLine(const Legend& legend, const std::string& text) {
  for (const std::string& line : legend.lines())
    if (line.find(text) != std::string::npos) return true;
  return false;
}

TEST(TriplanarViews, NamesRoundTripAndNeedTheExactMapping) {
  for (View v : {View::Weights, View::BlendZone}) {
    ASSERT_EQ(parseView(toString(v)), v);
    EXPECT_TRUE(needsExactMapping(v));
  }
  EXPECT_STREQ(toString(View::Weights), "weights");
  EXPECT_STREQ(toString(View::BlendZone), "blendzone");
  EXPECT_EQ(parseViewList("weights,blendzone"), (std::vector<View>{View::Weights, View::BlendZone}));
  EXPECT_FALSE(needsExactMapping(View::Seams));
  try {
    parseViewList("weight");
    FAIL() << "no exception";
  } catch (const UsageError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("weights"), std::string::npos) << message;
    EXPECT_NE(message.find("blendzone"), std::string::npos) << message;
  }
}

TEST(TriplanarViews, WeightsOfAPlaneAreItsNormalsComponentsOverTheirSum) {
  const Triplanar t(squareFacing(Vec3(1, 2, 3)));
  const ViewOptions o = viewFrom(t.mesh, Vec3(1, 2, 3).normalized(), true);
  const Scene scene = rasterizeScene(t.mesh, o.render);
  ASSERT_GT(coveredCount(scene), 1000u);
  const DrawnView drawn = drawViewAndLegend(View::Weights, t.input(), o);
  ASSERT_EQ(drawn.image.width, 64);
  ASSERT_EQ(drawn.image.height, 64);
  for (int row = 0; row < 64; ++row)
    for (int x = 0; x < 64; ++x)
      ASSERT_TRUE(near(pixelColour(drawn.image, x, row), covered(scene, x, row) ? Vec3(1, 2, 3) / 6.0 : kBackground))
          << x << ", " << row << ": " << pixelColour(drawn.image, x, row).transpose();
  EXPECT_EQ(drawn.legend.title.front(), "triplanar weights");
  ASSERT_EQ(drawn.legend.entries.size(), 3u);  // every pixel has weights: no "no weights" entry
  EXPECT_EQ(drawn.legend.entries[0].colour, Vec3(1, 0, 0));
  EXPECT_EQ(drawn.legend.entries[0].label, "x projection");
  EXPECT_EQ(drawn.legend.entries[2].colour, Vec3(0, 0, 1));
  // The largest weight is 1/2 < 0.9: every covered pixel is in the blend zone.
  EXPECT_TRUE(hasLine(drawn.legend, "blend zone (every weight < 0.9): 100 % of " + std::to_string(coveredCount(scene)) +
                                        " covered pixels"));
}

TEST(TriplanarViews, WeightsOnASphereSumToOneAndLeaveTheBackground) {
  const Triplanar t(meshes::icosphere(3));
  ViewOptions o = viewFrom(t.mesh, Vec3(0.3, 0.5, 0.8).normalized(), false, 96);
  const Scene scene = rasterizeScene(t.mesh, o.render);
  const Image image = drawViewAndLegend(View::Weights, t.input(), o).image;
  std::size_t mixed = 0;
  for (int row = 0; row < image.height; ++row)
    for (int x = 0; x < image.width; ++x) {
      const Vec3 c = pixelColour(image, x, row);
      if (!covered(scene, x, row)) {
        ASSERT_TRUE(near(c, kBackground)) << x << ", " << row;
        continue;
      }
      ASSERT_NEAR(c.sum(), 1.0, 1e-6) << x << ", " << row;
      ASSERT_GE(c.minCoeff(), 0.0);
      mixed += c.maxCoeff() < 0.9;
    }
  EXPECT_GT(mixed, 0u);  // a sphere has every normal: some blend all three
  EXPECT_EQ(mixed, blendZone(t.input(), o).pixels);

  // Supersampled, an interior pixel is the mean of its samples' weights: still summing to 1.
  o.render.samplesPerPixel = 4;
  const Image smooth = drawViewAndLegend(View::Weights, t.input(), o).image;
  EXPECT_NEAR(pixelColour(smooth, 48, 48).sum(), 1.0, 1e-6);
}

TEST(TriplanarViews, BlendZoneCountsPixelsWhereNoWeightReachesTheThreshold) {
  const Triplanar oblique(squareFacing(Vec3(1, 2, 3)));
  ViewOptions o = viewFrom(oblique.mesh, Vec3(1, 2, 3).normalized(), true);
  const std::size_t covered = coveredCount(rasterizeScene(oblique.mesh, o.render));
  BlendZone zone = blendZone(oblique.input(), o);  // weights 1/6, 1/3, 1/2
  EXPECT_EQ(zone.threshold, 0.9);
  EXPECT_EQ(zone.coveredPixels, covered);
  EXPECT_EQ(zone.pixels, covered);
  EXPECT_EQ(zone.invalidPixels, 0u);
  o.blendZoneThreshold = 0.4;
  zone = blendZone(oblique.input(), o);
  EXPECT_EQ(zone.coveredPixels, covered);
  EXPECT_EQ(zone.pixels, 0u);
  EXPECT_EQ(zone.share(), 0.0);

  const Triplanar facingZ(meshes::planeGrid(2, 2, 2.0, 2.0));  // z = 0, normal +z: weights (0, 0, 1)
  const ViewOptions z = viewFrom(facingZ.mesh, Vec3::UnitZ(), true);
  zone = blendZone(facingZ.input(), z);
  EXPECT_GT(zone.coveredPixels, 1000u);
  EXPECT_EQ(zone.pixels, 0u);

  for (double bad : {0.0, -0.5, 1.5, std::nan("")}) {
    o.blendZoneThreshold = bad;
    EXPECT_THROW(blendZone(oblique.input(), o), UsageError) << bad;
  }
}

TEST(TriplanarViews, BlendZoneViewIsMagentaInTheZoneAndDimGreyElsewhere) {
  const Vec3 magenta(1, 0, 1), dimGrey = Vec3::Constant(0.45);  // face-on and orthographic: shade 1
  const Triplanar oblique(squareFacing(Vec3(1, 2, 3)));
  const Triplanar facingZ(meshes::planeGrid(2, 2, 2.0, 2.0));
  for (const Triplanar* t : {&oblique, &facingZ}) {
    const bool inZone = t == &oblique;
    const ViewOptions o = viewFrom(t->mesh, inZone ? Vec3(1, 2, 3).normalized() : Vec3::UnitZ(), true);
    const Scene scene = rasterizeScene(t->mesh, o.render);
    const DrawnView drawn = drawViewAndLegend(View::BlendZone, t->input(), o);
    for (int row = 0; row < 64; ++row)
      for (int x = 0; x < 64; ++x)
        ASSERT_TRUE(near(pixelColour(drawn.image, x, row),
                         !covered(scene, x, row) ? kBackground : inZone ? magenta : dimGrey))
            << inZone << ": " << x << ", " << row;
    const std::size_t n = coveredCount(scene);
    EXPECT_EQ(drawn.legend.title, std::vector<std::string>{"triplanar blend zone: every weight < 0.9"});
    EXPECT_TRUE(hasLine(drawn.legend, inZone ? "blend zone: " + std::to_string(n) + " pixels, 100 % of " + std::to_string(n)
                                             : "blend zone: 0 pixels, 0 % of " + std::to_string(n)));
  }
}

TEST(TriplanarViews, PixelsWithoutWeightsAreWhiteAndCountedApart) {
  Triplanar t(squareFacing(Vec3(1, 2, 3)));
  const ViewOptions o = viewFrom(t.mesh, Vec3(1, 2, 3).normalized(), true);
  const render::PixelMapping unity = *t.exact;
  t.exact->blendAt = [unity](const Vec3& p, const Vec3& n, std::int32_t face) {
    render::TexcoordBlend b = unity.blendAt(p, n, face);
    if (face == 0) b.weights = Vec3::Constant(std::nan(""));
    return b;
  };
  const Scene scene = rasterizeScene(t.mesh, o.render);
  std::size_t onFace0 = 0;
  for (std::int32_t f : scene.visible.face) onFace0 += f == 0;
  ASSERT_GT(onFace0, 100u);
  const BlendZone zone = blendZone(t.input(), o);
  EXPECT_EQ(zone.invalidPixels, onFace0);
  EXPECT_EQ(zone.coveredPixels + zone.invalidPixels, coveredCount(scene));
  EXPECT_EQ(zone.pixels, zone.coveredPixels);
  for (View view : {View::Weights, View::BlendZone}) {
    const DrawnView drawn = drawViewAndLegend(view, t.input(), o);
    for (int row = 0; row < 64; ++row)
      for (int x = 0; x < 64; ++x)
        if (scene.visible.face[scene.visible.index(x, row)] == 0) {
          ASSERT_EQ(pixelColour(drawn.image, x, row), Vec3(1, 1, 1)) << x << ", " << row;
        }
    EXPECT_EQ(drawn.legend.entries.back().label, "no weights: " + std::to_string(onFace0) + " pixels");
  }
}

TEST(TriplanarViews, MappingsWithoutBlendWeightsAreRefused) {
  Triplanar t(squareFacing(Vec3(1, 2, 3)));
  const ViewOptions o = viewFrom(t.mesh, Vec3(1, 2, 3).normalized(), true);
  t.exact = render::PixelMapping{[](const Vec3& p, const Vec3&, std::int32_t) { return Vec4(p.x(), p.y(), 0, 1); }};
  for (View view : {View::Weights, View::BlendZone}) {
    try {
      drawView(view, t.input(), o);
      FAIL() << "no exception";
    } catch (const UsageError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(std::string(toString(view)) + ": expected a triplanar mapping (--projector triplanar), found", 0),
                0u) << message;
    }
  }
  EXPECT_THROW(blendZone(t.input(), o), UsageError);
  t.exact.reset();
  for (View view : {View::Weights, View::BlendZone}) EXPECT_THROW(drawView(view, t.input(), o), UsageError);
  EXPECT_THROW(blendZone(t.input(), o), UsageError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::views
