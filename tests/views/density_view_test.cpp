// The density view, pixel by pixel: a flat density is one colour, the palette's middle (the scale
// is logarithmic and centred on the median); two densities take the bar's colours at their values,
// on a scale from min(median / 2, p10) to max(2 median, p90); the legend in texels per unit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "views/canvas.h"
#include "views/legend.h"
#include "views/measure.h"
#include "views/palette.h"
#include "views/scene.h"
#include "views/views.h"
#include "views/mapped_layout.h"

namespace uvtk::views {
namespace {
namespace UVTK_TEST_FILE {

// The square [x0, x0 + 2] x [0, 2] in z = 0 (two triangles), mapped by ((x - x0) s + u0, y s).
void addSquare(Mapped& m, double x0, double s, double u0) {
  const int first = int(m.mesh.positions.size());
  for (const Vec2& c : {Vec2(0, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, 2)}) m.mesh.positions.push_back({x0 + c.x(), c.y(), 0});
  m.mesh.triangles.push_back({first, first + 1, first + 2});
  m.mesh.triangles.push_back({first, first + 2, first + 3});
  for (int k : {0, 1, 2, 0, 2, 3}) {
    const Vec3& p = m.mesh.positions[std::size_t(first + k)];
    m.uv.uv.push_back(Vec2((p.x() - x0) * s + u0, p.y() * s));
  }
  m.uv.faceFlags.insert(m.uv.faceFlags.end(), {kFaceOk, kFaceOk});
}

ViewOptions faceOn(const Mesh& mesh, int size) {
  ViewOptions o;
  o.render.camera = render::frameSphere(render::boundingSphere(mesh.positions), Vec3::UnitZ(), Vec3::UnitY(),
                                        {true, 40.0}, size, size);
  o.render.background = Vec3(0.0, 0.0, 0.0);
  return o;
}

TEST(DensityView, AFlatDensityIsOneColourThePalettesMiddle) {
  Mapped m;
  addSquare(m, 0.0, 0.5, 0.0);  // side 2 on the unit UV square: sqrt(1 * 1024 * 1024 / 4) = 512
  m.analyse();
  ASSERT_DOUBLE_EQ(m.judgement.summary.density.statistics.p50, 512.0);
  const ViewOptions o = faceOn(m.mesh, 64);
  const Scene scene = rasterizeScene(m.mesh, o.render);
  const Image image = drawView(View::Density, m.input(), o);
  const Vec3 middle = paletteColour(Palette::Sequential, 0.5);
  int covered = 0;
  for (int row = 0; row < 64; ++row)
    for (int x = 0; x < 64; ++x) {
      const bool face = scene.visible.face[scene.visible.index(x, row)] >= 0;
      ASSERT_LT((pixelColour(image, x, row) - (face ? middle : o.render.background)).cwiseAbs().maxCoeff(), 1e-6)
          << x << ", " << row;
      covered += face;
    }
  EXPECT_GT(covered, 64 * 64 / 3);
  // The legend: texels per unit, from 256 to 1024 at equal ratios.
  const FaceColouring colouring = colourByMeasure(View::Density, m.judgement);
  EXPECT_EQ(colouring.legend.title.front(), "Texel density, texels per unit");
  EXPECT_EQ(colouring.legend.title.back(), "of a 1024 × 1024 texture");
  ASSERT_EQ(colouring.legend.bar->ticks.size(), 5u);
  EXPECT_EQ(colouring.legend.bar->ticks.front().label, "≤256");
  EXPECT_EQ(colouring.legend.bar->ticks[2].label, "512");
  EXPECT_EQ(colouring.legend.bar->ticks.back().label, "≥1024");
  EXPECT_DOUBLE_EQ(colouring.legend.bar->ticks[1].value, 256.0 * std::sqrt(2.0));
}

TEST(DensityView, TwoDensitiesTakeTheirPlacesOnTheLogarithmicScale) {
  Mapped m;
  addSquare(m, 0.0, 0.5, 0.0);    // density 512
  addSquare(m, 2.5, 0.125, 2.0);  // density 128
  m.analyse();
  // Equal areas: p10 = p50 = 128 (the lower inverse), p90 = 512. Scale 64 .. 512: 128 lies at a third.
  const analysis::Statistics& s = m.judgement.summary.density.statistics;
  ASSERT_DOUBLE_EQ(s.p50, 128.0);
  ASSERT_DOUBLE_EQ(s.p90, 512.0);
  const ColourScale scale = measureScale(View::Density, m.judgement.faces, m.judgement.summary);
  EXPECT_TRUE(scale.logarithmic);
  EXPECT_NEAR(scale.position(128.0), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(scale.position(512.0), 1.0, 1e-12);
  const ViewOptions o = faceOn(m.mesh, 96);
  const Scene scene = rasterizeScene(m.mesh, o.render);
  const Image image = drawView(View::Density, m.input(), o);
  int seen[2] = {0, 0};
  for (int row = 0; row < 96; ++row)
    for (int x = 0; x < 96; ++x) {
      const std::int32_t face = scene.visible.face[scene.visible.index(x, row)];
      if (face < 0) continue;
      const bool dense = face < 2;
      const Vec3 expected = paletteColour(Palette::Sequential, dense ? 1.0 : 1.0 / 3.0);
      ASSERT_LT((pixelColour(image, x, row) - expected).cwiseAbs().maxCoeff(), 1e-5) << x << ", " << row;
      ++seen[dense];
    }
  EXPECT_GT(seen[0], 100);
  EXPECT_GT(seen[1], 100);
}

TEST(DensityView, IsAViewByNameAndALayoutFill) {
  EXPECT_EQ(parseView("density"), View::Density);
  EXPECT_STREQ(toString(View::Density), "density");
  EXPECT_TRUE(isMeasure(View::Density));
  Mapped m;
  addSquare(m, 0.0, 0.5, 0.0);
  m.analyse();
  ViewOptions o = faceOn(m.mesh, 32);
  o.layoutFill = View::Density;
  o.layoutSize = 32;
  const Image layout = drawView(View::Layout, m.input(), o);
  // The UV square filled with the flat density's colour: the palette's middle at its centre.
  bool middle = false;
  for (int row = 0; row < layout.height && !middle; ++row)
    for (int x = 0; x < layout.width && !middle; ++x)
      middle = (pixelColour(layout, x, row) - paletteColour(Palette::Sequential, 0.5)).cwiseAbs().maxCoeff() < 1e-6;
  EXPECT_TRUE(middle);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::views
