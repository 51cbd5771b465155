// The mipline view and count: a sphere projector evaluated per pixel, seen so that its seam crosses
// pixel quads, shows a line along the seam (and specks at the poles) with quad derivatives; the
// per-corner UVs (seam split) and the fixes (textureGrad, Tarini) show none; the picture's red
// pixels are the counted seam pixels.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "meshes/generators.h"
#include "views/canvas.h"
#include "views/mapped_layout.h"
#include "views/views.h"

namespace uvtk::views {
namespace {
namespace UVTK_TEST_FILE {

// The lat-long sphere by the sphere projector (axis z, seam towards +x), seen from beside the
// seam and a little above, so that the seam runs down the picture off the quad boundaries.
struct SeamView {
  Mapped mapped = mapWith(meshes::latLongSphere(48, 24), projector(param::SurfaceKind::Sphere));
  ViewOptions options;
  SeamView() {
    options.render.camera = render::frameSphere(render::boundingSphere(mapped.mesh.positions), Vec3(1, 0.2, 0.3),
                                                Vec3::UnitZ(), {false, 40.0}, 160, 160);
    options.perPixel = true;
  }
};

TEST(MipLineView, APerPixelSphereShowsTheSeamLineAndTheFixesRemoveIt) {
  SeamView view;
  const MipLine line = mipLine(view.mapped.input(), view.options);
  EXPECT_EQ(line.derivatives, render::Derivatives::QuadCoarse);  // what the analytic default compares with
  EXPECT_TRUE(line.perPixel);
  EXPECT_GT(line.coveredPixels, 10000u);
  // The seam runs from pole to pole over about 70 visible rows, one or two pixels wide.
  EXPECT_GT(line.seam, 40u);
  EXPECT_LT(line.seam, 300u);
  EXPECT_EQ(line.pixels, line.pole + line.seam + line.cubeEdge + line.other);
  EXPECT_EQ(line.cubeEdge, 0u);
  EXPECT_LE(line.other, line.pixels / 10);
  EXPECT_GT(line.faces, 10u);
  EXPECT_NEAR(line.share(), double(line.pixels) / double(line.coveredPixels), 1e-15);

  view.options.render.derivatives = render::Derivatives::QuadFine;
  EXPECT_GT(mipLine(view.mapped.input(), view.options).seam, 20u);

  for (render::SeamFix fix : {render::SeamFix::Grad, render::SeamFix::Tarini}) {
    view.options.render.seamFix = fix;
    const MipLine fixed = mipLine(view.mapped.input(), view.options);
    EXPECT_EQ(fixed.seam, 0u) << render::toString(fix);
    EXPECT_EQ(fixed.seamFix, fix);
    EXPECT_EQ(fixed.coveredPixels, line.coveredPixels);
  }
}

TEST(MipLineView, SeamSplitCornersShowNoSeamLine) {
  SeamView view;
  view.options.perPixel = false;  // the projector's per-corner UVs, repaired across the seam
  const MipLine line = mipLine(view.mapped.input(), view.options);
  EXPECT_FALSE(line.perPixel);
  EXPECT_EQ(line.seam, 0u);
  view.options.render.seamFix = render::SeamFix::Tarini;  // Tarini reads a per-pixel mapping
  EXPECT_THROW(mipLine(view.mapped.input(), view.options), UsageError);
}

TEST(MipLineView, ThePictureMarksTheCountedPixels) {
  const SeamView view;
  const MipLine line = mipLine(view.mapped.input(), view.options);
  const DrawnView drawn = drawViewAndLegend(View::MipLine, view.mapped.input(), view.options);
  std::size_t red = 0, orange = 0, magenta = 0;
  for (int row = 0; row < drawn.image.height; ++row)
    for (int x = 0; x < drawn.image.width; ++x) {
      const Vec3 c = pixelColour(drawn.image, x, row);
      red += c == Vec3(1, 0, 0);
      orange += (c - Vec3(1, 0.6, 0)).cwiseAbs().maxCoeff() < 1e-6;
      magenta += c == Vec3(1, 0, 1);
    }
  EXPECT_EQ(red, line.seam);
  EXPECT_EQ(orange, line.pole);
  EXPECT_EQ(magenta, line.other);
  ASSERT_FALSE(drawn.legend.title.empty());
  EXPECT_NE(drawn.legend.title[1].find(std::to_string(line.pixels) + " pixels"), std::string::npos) << drawn.legend.title[1];
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::views
