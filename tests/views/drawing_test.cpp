// The views drawn from projected and hand-made layouts, checked pixel by pixel where the answer is
// known: isometric heatmaps, a flipped face, the legend bar against face colours, seam lines where
// the seam edges project, the UV error of linear and spherical maps, and layout pixels.
#include "views/views.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "core/error.h"
#include "core/seam_edges.h"
#include "doubles.h"
#include "meshes/generators.h"
#include "param/projector.h"
#include "render/procedural.h"
#include "texgen/texgen.h"
#include "views/canvas.h"
#include "views/layout.h"
#include "views/legend.h"
#include "views/mapped_layout.h"
#include "views/measure.h"
#include "views/palette.h"
#include "views/scene.h"

namespace uvtk::views {
namespace {
namespace UVTK_TEST_FILE {

// The plane grid of side 2 in z = 0 by the plane projector: an isometry up to a scale of 1/2.
Mapped planarPlane(int n = 4) { return mapWith(meshes::planeGrid(n, n, 2.0, 2.0), projector(param::SurfaceKind::Plane)); }

ViewOptions viewFrom(const Mesh& mesh, const Vec3& direction, const Vec3& up, int size, bool orthographic = false) {
  ViewOptions o;
  o.render.camera =
      render::frameSphere(render::boundingSphere(mesh.positions), direction, up, {orthographic, 40.0}, size, size);
  o.render.background = Vec3(0.0, 0.0, 0.0);
  return o;
}

// Colours compared as an Image stores them, in float.

// A window point (image coordinates) of an object-space point under the view's camera.
Vec2 projectToImage(const ViewOptions& o, const Vec3& p) {
  const Vec4 c = o.render.camera.clipFromView * o.render.camera.viewFromWorld * o.render.worldFromObject * p.homogeneous();
  const int w = o.render.camera.width, h = o.render.camera.height;
  return {(c.x() / c.w() + 1.0) * 0.5 * w, h - (c.y() / c.w() + 1.0) * 0.5 * h};
}

// ---- checker and uvgrid ----

// The checker view (shaded, ViewOptions::checks) is checked in checker_view_test.cpp.
TEST(TexturedViews, UvgridIsTheRendererWithTheProceduralTextureReplace) {
  const Mapped m = planarPlane();
  ViewOptions o = viewFrom(m.mesh, Vec3::UnitZ(), Vec3::UnitY(), 64);
  o.render.env = render::EnvMode::Modulate;  // overridden: uvgrid shows the texture as it is
  const std::optional<render::Texture> uvgrid = render::proceduralTexture("uvgrid:1024");
  render::RenderOptions direct = o.render;
  direct.texture = &*uvgrid;
  direct.env = render::EnvMode::Replace;
  const Image expected = render::render(m.mesh, cornerTexcoords(m.input()), direct).colour;
  const Image uvgridView = drawView(View::Uvgrid, m.input(), o);
  ASSERT_EQ(uvgridView.width, 64);
  ASSERT_EQ(uvgridView.height, 64);
  EXPECT_EQ(uvgridView.pixels, expected.pixels);
}

// ---- heatmaps ----

TEST(Heatmaps, AnIsometricPlaneIsUniformlyTheColourOfTheExactValue) {
  const Mapped m = planarPlane();
  ASSERT_EQ(m.judgement.summary.statusCounts[analysis::FaceStatus::Ok], m.mesh.faceCount());
  const ViewOptions o = viewFrom(m.mesh, Vec3::UnitZ(), Vec3::UnitY(), 64, true);  // face-on: shade 1
  const Scene scene = rasterizeScene(m.mesh, o.render);
  for (View view : {View::Stretch, View::Linf, View::Angle, View::Area}) {
    const Image image = drawView(view, m.input(), o);
    EXPECT_GT(image.height, 64);  // the legend strip
    EXPECT_GE(image.width, 64);
    // Sequential measures are 1 at the isometry, the bottom of their scale; area is 0: white.
    const Vec3 exact = view == View::Area ? Vec3(1, 1, 1) : paletteColour(Palette::Sequential, 0.0);
    int covered = 0;
    for (int row = 0; row < 64; ++row)
      for (int x = 0; x < 64; ++x) {
        const std::int32_t face = scene.visible.face[scene.visible.index(x, row)];
        const Vec3 expected = face < 0 ? o.render.background : exact;
        ASSERT_LT((pixelColour(image, x, row) - expected).cwiseAbs().maxCoeff(), 1e-6) << toString(view) << " " << x << ", " << row;
        covered += face >= 0;
      }
    EXPECT_GT(covered, 64 * 64 / 3);
  }
}

TEST(Heatmaps, AFlippedFaceShowsTheFlippedColourAndIsListedInTheLegend) {
  Mapped m = planarPlane();
  constexpr std::size_t kFlipped = 9;
  std::swap(m.uv.uv[3 * kFlipped + 1], m.uv.uv[3 * kFlipped + 2]);  // mirrors the face in UV
  m.analyse();
  ASSERT_EQ(m.judgement.faces[kFlipped].status, analysis::FaceStatus::Flipped);
  ASSERT_EQ(m.judgement.summary.statusCounts[analysis::FaceStatus::Flipped], 1u);
  const ViewOptions o = viewFrom(m.mesh, Vec3::UnitZ(), Vec3::UnitY(), 64, true);
  const Scene scene = rasterizeScene(m.mesh, o.render);
  const Vec3 flipped = statusColour(analysis::FaceStatus::Flipped);
  const Image image = drawView(View::Stretch, m.input(), o);
  int flippedPixels = 0;
  for (int row = 0; row < 64; ++row)
    for (int x = 0; x < 64; ++x) {
      const bool isFlipped = scene.visible.face[scene.visible.index(x, row)] == std::int32_t(kFlipped);
      ASSERT_EQ(near(pixelColour(image, x, row), flipped), isFlipped) << x << ", " << row;
      flippedPixels += isFlipped;
    }
  EXPECT_GT(flippedPixels, 20);
  // In the legend strip: the flipped swatch, and no swatch for statuses the mesh does not have.
  bool flippedSwatch = false, poleSwatch = false;
  for (int row = 64; row < image.height; ++row)
    for (int x = 0; x < image.width; ++x) {
      flippedSwatch = flippedSwatch || near(pixelColour(image, x, row), flipped);
      poleSwatch = poleSwatch || near(pixelColour(image, x, row), statusColour(analysis::FaceStatus::PoleFace));
    }
  EXPECT_TRUE(flippedSwatch);
  EXPECT_FALSE(poleSwatch);
  const FaceColouring colouring = colourByMeasure(View::Stretch, m.judgement);
  ASSERT_EQ(colouring.legend.entries.size(), 1u);
  EXPECT_EQ(colouring.legend.entries[0].label, "flipped: 1");
}

// Separate triangles in z = 0, each mapped by its (x, y) scaled by (1, s): a different stretch
// per face. Each face's colour is the legend bar's at the face's value, and the largest value
// (the p99 of the four, the top of the scale, labelled "≥") is the bar's last pixel.
TEST(Heatmaps, FaceColoursMatchTheLegendBarAtTheirValues) {
  Mapped m;
  const double scales[] = {1.0, 1.6, 2.5, 4.0};
  for (int f = 0; f < 4; ++f) {
    const Vec3 origin(1.2 * f, 0, 0);
    for (const Vec3& corner : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}) {
      m.mesh.positions.push_back(origin + corner);
      m.uv.uv.push_back(Vec2(corner.x(), scales[f] * corner.y()) + Vec2(2.0 * f, 0));
    }
    m.mesh.triangles.push_back({3 * f, 3 * f + 1, 3 * f + 2});
  }
  m.uv.faceFlags.assign(4, kFaceOk);
  m.analyse();
  const ViewOptions o = viewFrom(m.mesh, Vec3::UnitZ(), Vec3::UnitY(), 96, true);
  for (View view : {View::Stretch, View::Linf, View::Angle, View::Area}) {
    const FaceColouring colouring = colourByMeasure(view, m.judgement);
    const ColourBar& bar = *colouring.legend.bar;
    EXPECT_EQ(bar.ticks.back().label.substr(0, 3), "≥");
    const Image image = drawView(view, m.input(), o);
    const BarPlacement at = barPlacement(colouring.legend, 96);
    const Scene scene = rasterizeScene(m.mesh, o.render);
    const analysis::AreaTotals totals = analysis::okAreaTotals(m.judgement.faces);
    double largest = -1e300;
    int largestFace = 0;
    for (int f = 0; f < 4; ++f) {
      const double value = measureValue(view, m.judgement.faces[std::size_t(f)], totals);
      if (value > largest) largest = value, largestFace = f;
    }
    for (int row = 0; row < 96; ++row)
      for (int x = 0; x < 96; ++x) {
        const std::int32_t face = scene.visible.face[scene.visible.index(x, row)];
        if (face < 0) continue;
        const double value = measureValue(view, m.judgement.faces[std::size_t(face)], totals);
        const Vec3 barColour = pixelColour(image, at.columnAt(bar.scale.position(value)), at.top + kBarHeight / 2);
        // The bar samples its pixel's centre: within half a pixel of the value's position.
        ASSERT_LT((pixelColour(image, x, row) - barColour).cwiseAbs().maxCoeff(), 0.01) << toString(view) << " face " << face;
        if (face == largestFace && view != View::Area) {
          EXPECT_EQ(at.columnAt(bar.scale.position(value)), at.left + kBarLength - 1);
        }
      }
    if (view != View::Area) {
      EXPECT_DOUBLE_EQ(bar.scale.position(largest), 1.0) << toString(view);
    }
  }
}

// ---- seams ----

// An open cylinder by the cylinder projector: the wrap seam runs up the +x side.
TEST(SeamsView, DrawsTheSeamWhereItsEdgesProjectAndNotBehindTheSurface) {
  const Mapped m = mapWith(meshes::cylinder(24, 4, 1.0, 2.0, false), projector(param::SurfaceKind::Cylinder));
  const std::vector<SeamEdge> edges = seamEdgeList(m.mesh, m.uv);
  ASSERT_EQ(edges.size(), 4u);
  const Vec3& wrap = kWrapSeamColour;

  const ViewOptions front = viewFrom(m.mesh, Vec3::UnitX(), Vec3::UnitZ(), 128);
  const Image image = drawView(View::Seams, m.input(), front);
  for (const SeamEdge& edge : edges) {
    ASSERT_TRUE(edge.wrap);
    const Vec2 p = projectToImage(front, 0.5 * (m.mesh.positions[edge.a] + m.mesh.positions[edge.b]));
    EXPECT_TRUE(near(pixelColour(image, int(p.x()), int(p.y())), wrap)) << p.transpose();
  }
  // Faces beside the seam straddled it before the repair: tinted, times their shade.
  const Scene scene = rasterizeScene(m.mesh, front.render);
  int tinted = 0;
  for (int row = 0; row < 128; ++row)
    for (int x = 0; x < 128; ++x) {
      const std::int32_t face = scene.visible.face[scene.visible.index(x, row)];
      if (face < 0 || !m.uv.faceHas(std::size_t(face), kFaceSeamStraddle) || near(pixelColour(image, x, row), wrap)) continue;
      ASSERT_LT((pixelColour(image, x, row) - kStraddleColour * scene.shade[std::size_t(face)]).cwiseAbs().maxCoeff(), 1e-6);
      ++tinted;
    }
  EXPECT_GT(tinted, 100);

  // From the far side the seam is behind the surface: not drawn.
  const ViewOptions back = viewFrom(m.mesh, -Vec3::UnitX(), Vec3::UnitZ(), 128);
  const Image hidden = drawView(View::Seams, m.input(), back);
  for (int row = 0; row < 128; ++row)
    for (int x = 0; x < 128; ++x) ASSERT_FALSE(near(pixelColour(hidden, x, row), wrap)) << x << ", " << row;
}

TEST(SeamsView, MarksPolesAndTheSeamOfASphere) {
  const Mapped m = mapWith(meshes::latLongSphere(16, 8), projector(param::SurfaceKind::Sphere));
  ASSERT_EQ(m.judgement.summary.poleVertices, (std::vector<int>{0, int(m.mesh.vertexCount()) - 1}));
  const ViewOptions o = viewFrom(m.mesh, Vec3(1, 0, 1), Vec3::UnitZ(), 128);
  const Image image = drawView(View::Seams, m.input(), o);
  const Vec2 pole = projectToImage(o, m.mesh.positions[0]);
  EXPECT_TRUE(near(pixelColour(image, int(pole.x()), int(pole.y())), kPoleVertexColour));
  // The seam edge from the equator's +x vertex up to the next ring (vertex 1 + 3 * 16 and 1 + 2 * 16).
  const Vec2 seam = projectToImage(o, 0.5 * (m.mesh.positions[1 + 3 * 16] + m.mesh.positions[1 + 2 * 16]));
  EXPECT_TRUE(near(pixelColour(image, int(seam.x()), int(seam.y())), kWrapSeamColour));
  // Pole faces in their status colour (times the shade) around the pole.
  const Vec2 nearPole = projectToImage(o, Vec3(-0.15, -0.1, 1.0).normalized());  // 10 degrees from the pole
  const Vec3 c = pixelColour(image, int(nearPole.x()), int(nearPole.y()));
  EXPECT_NEAR(c.x(), 0.0, 1e-6);  // cyan: no red
  EXPECT_GT(c.y(), 0.3);
  EXPECT_NEAR(c.y(), c.z(), 1e-6);
}

// A sphere at 2^500 or 2^-500 (about 1e150, 1e-150), framed by its bounding sphere, gives the views
// of the same sphere at unit scale: positions, camera and eye coordinates all scale by one power of
// two. (Before, the views that colour faces drew nothing there: the set-up's products of clip
// coordinates overflowed or underflowed, and every face's shade fell to 0.35.)
TEST(Heatmaps, ASphereAt2To500Or2ToMinus500GivesTheUnitScaleViews) {
  const auto mapped = [](double scale) {
    Mesh mesh = meshes::latLongSphere(16, 8);
    for (Vec3& p : mesh.positions) p *= scale;
    return mapWith(std::move(mesh), projector(param::SurfaceKind::Sphere));
  };
  const Mapped unit = mapped(1.0);
  const ViewOptions o = viewFrom(unit.mesh, Vec3(1, 0.4, 0.7), Vec3::UnitZ(), 96);
  for (View view : {View::Stretch, View::Angle, View::Seams, View::Checker}) {
    const Image reference = drawView(view, unit.input(), o);
    std::size_t covered = 0;
    for (int row = 0; row < 96; ++row)
      for (int x = 0; x < 96; ++x) covered += !near(pixelColour(reference, x, row), Vec3::Zero());
    EXPECT_GT(covered, 3000u) << toString(view);
    for (const double scale : {0x1p500, 0x1p-500}) {
      const Mapped m = mapped(scale);
      const ViewOptions scaled = viewFrom(m.mesh, Vec3(1, 0.4, 0.7), Vec3::UnitZ(), 96);
      EXPECT_EQ(drawView(view, m.input(), scaled).pixels, reference.pixels) << toString(view) << " at " << scale;
    }
  }
}

// ---- uverror ----

TEST(UvError, IsZeroForALinearMap) {
  const Mapped m = planarPlane(8);
  const ViewOptions o = viewFrom(m.mesh, Vec3(0.3, -0.2, 1.0), Vec3::UnitY(), 96);
  const UvErrorMap map = uvErrorMap(m.input(), o);
  EXPECT_EQ(map.texels.channels, 1);
  EXPECT_EQ(map.texels.channelNames, (std::vector<std::string>{"uverror"}));
  EXPECT_GT(map.pixels, 96u * 96u / 3);
  EXPECT_EQ(map.invalidPixels, 0u);
  EXPECT_LT(map.max, 1e-9);
  std::size_t background = 0;
  for (float e : map.texels.pixels) {
    ASSERT_TRUE(e == -1.0f || (e >= 0.0f && e < 1e-9f));
    background += e == -1.0f;
  }
  EXPECT_EQ(background + map.pixels, 96u * 96u);
}

TEST(UvError, IsLargestAtThePolesOfASphere) {
  const Mapped m = mapWith(meshes::latLongSphere(24, 12), projector(param::SurfaceKind::Sphere));
  ASSERT_TRUE(m.wrapsU);
  ViewOptions o = viewFrom(m.mesh, Vec3(0.4, 0.3, 1.0), Vec3::UnitY(), 128);
  const render::Texture texture = render::checkerTexture(512, 8);
  o.render.texture = &texture;
  const UvErrorMap map = uvErrorMap(m.input(), o);
  EXPECT_EQ(map.invalidPixels, 0u);
  EXPECT_GT(map.max, 1.0);  // texels of 512 x 512
  EXPECT_GT(map.mean, 0.0);
  EXPECT_LT(map.mean, 0.2 * map.max);
  int bestX = 0, bestRow = 0;
  for (int row = 0; row < 128; ++row)
    for (int x = 0; x < 128; ++x)
      if (map.texels.at(x, row, 0) > map.texels.at(bestX, bestRow, 0)) bestX = x, bestRow = row;
  // The north pole's cap (the first ring lies 15 degrees from it) spans about 10 pixels here.
  const Vec2 pole = projectToImage(o, m.mesh.positions[0]);
  EXPECT_LT((Vec2(bestX + 0.5, bestRow + 0.5) - pole).norm(), 12.0) << bestX << ", " << bestRow << " pole " << pole.transpose();

  const Image image = drawView(View::UvError, m.input(), o);
  EXPECT_GT(image.height, 128);
  EXPECT_EQ(pixelColour(image, 0, 0), o.render.background);
}

// The mesh with texgen's (s, t, r, q) drawn under `o`'s camera, and texgen evaluated per pixel as
// apps/uvtk/mapped_mesh.cpp evaluates it.
Mapped texgenMapped(Mesh mesh, texgen::TexgenMode mode, const ViewOptions& o) {
  texgen::TexgenOptions options;
  for (int c = 0; c < 3; ++c) options.coordinates[std::size_t(c)] = {mode, Vec4::Zero()};
  options.modelviewAtPlanes = options.modelviewAtDraw = o.render.camera.viewFromWorld * o.render.worldFromObject;
  texgen::TexgenResult generated = texgen::generateTexcoords(mesh, options);
  Mapped m;
  m.mesh = std::move(mesh);
  m.uv = std::move(generated.uv);
  m.q = std::move(generated.q);
  m.analyse();
  m.exact = render::PixelMapping{
      [options](const Vec3& p, const Vec3& n, std::int32_t) { return texgen::texgenAt(p, n, options); }, false, true};
  return m;
}

TEST(UvError, OfACubeMapIsZeroForTheNormalMapOfAFlatQuad) {
  const Mesh plane = meshes::planeGrid(4, 4, 2.0, 2.0);
  ViewOptions o = viewFrom(plane, Vec3(0.3, -0.2, 1.0), Vec3::UnitY(), 64);
  const render::CubeTexture cube = render::cubeCheckerTexture(64);
  o.render.cubeTexture = &cube;
  // One normal everywhere: interpolated or evaluated, the direction is the same.
  const Mapped m = texgenMapped(plane, texgen::TexgenMode::NormalMap, o);
  const UvErrorMap map = uvErrorMap(m.input(), o);
  EXPECT_GT(map.pixels, 64u * 64u / 4);
  EXPECT_EQ(map.invalidPixels, 0u);
  EXPECT_LT(map.max, 1e-4);
}

// REFLECTION_MAP per vertex is only an approximation of the reflection vector per pixel: on a
// sphere its error falls with the square of the triangles' size, it is measured in texels of the
// bound cube map's face, and pixels whose two lookups select adjacent faces are compared across
// the shared edge, so no pixel counts as an outlier of a whole face.
TEST(UvError, OfACubeMapReflectionFallsWithTheTrianglesAndCrossesFaceEdges) {
  const render::CubeTexture cube64 = render::cubeCheckerTexture(64), cube128 = render::cubeCheckerTexture(128);
  const auto errorOf = [&](int slices, const render::CubeTexture& cube) {
    const Mesh sphere = meshes::latLongSphere(slices, slices / 2);
    ViewOptions o = viewFrom(sphere, Vec3(0.3, 0.4, 1.0), Vec3::UnitY(), 128);
    o.render.cubeTexture = &cube;
    const Mapped m = texgenMapped(sphere, texgen::TexgenMode::ReflectionMap, o);
    const UvErrorMap map = uvErrorMap(m.input(), o);
    EXPECT_EQ(map.invalidPixels, 0u);
    EXPECT_GT(map.pixels, 128u * 128u / 3);
    return map;
  };
  const UvErrorMap coarse = errorOf(16, cube64), fine = errorOf(32, cube64), coarse128 = errorOf(16, cube128);
  EXPECT_GT(coarse.mean, 0.05);
  EXPECT_GT(coarse.mean, 2.5 * fine.mean);  // half the size, about a quarter of the error
  EXPECT_NEAR(coarse128.mean / coarse.mean, 2.0, 1e-3);  // texels of 128 x 128 faces, not 64 x 64
  // A direction across a face edge compared on one face's plane: within a few texels, never the
  // tens of texels a lookup on the wrong face would differ by.
  EXPECT_LT(coarse.max, 8.0);
}

TEST(UvError, FlagsPixelsWithoutAValueAndNeedsTheExactMapping) {
  Mapped m = planarPlane();
  // The exact mapping has no value on face 0.
  const render::PixelMapping plane = *m.exact;
  m.exact->texcoordAt = [plane](const Vec3& p, const Vec3& n, std::int32_t face) {
    return face == 0 ? Vec4(std::numeric_limits<double>::quiet_NaN(), 0, 0, 1) : plane.texcoordAt(p, n, face);
  };
  const ViewOptions o = viewFrom(m.mesh, Vec3::UnitZ(), Vec3::UnitY(), 64, true);
  const UvErrorMap map = uvErrorMap(m.input(), o);
  const Scene scene = rasterizeScene(m.mesh, o.render);
  std::size_t faceZero = 0;
  for (int row = 0; row < 64; ++row)
    for (int x = 0; x < 64; ++x)
      if (scene.visible.face[scene.visible.index(x, row)] == 0) {
        ASSERT_EQ(map.texels.at(x, row, 0), -2.0f);
        ++faceZero;
      }
  EXPECT_GT(faceZero, 0u);
  EXPECT_EQ(map.invalidPixels, faceZero);
  EXPECT_TRUE(std::isfinite(map.max) && std::isfinite(map.mean));
  const Image image = drawView(View::UvError, m.input(), o);
  for (float value : image.pixels) ASSERT_TRUE(std::isfinite(value));

  m.exact.reset();
  EXPECT_THROW(uvErrorMap(m.input(), o), UsageError);
  EXPECT_THROW(drawView(View::UvError, m.input(), o), UsageError);
}

// ---- layout ----

// Flat triangles whose UVs are their (x, y): every face isometric, the fill the colour of 1.
Mapped flatTriangles(const std::vector<Vec2>& corners) {
  Mapped m;
  for (const Vec2& c : corners) {
    m.mesh.positions.push_back({c.x(), c.y(), 0.0});
    m.uv.uv.push_back(c);
  }
  for (int f = 0; 3 * f < int(corners.size()); ++f) m.mesh.triangles.push_back({3 * f, 3 * f + 1, 3 * f + 2});
  m.uv.faceFlags.assign(m.mesh.triangles.size(), kFaceOk);
  m.analyse();
  return m;
}

// The image pixel whose centre is nearest to a UV point.
std::pair<int, int> layoutPixel(const analysis::UvGrid& grid, const Vec2& uv) {
  const Vec2 p = layoutImagePoint(grid, uv);
  return {int(std::floor(p.x())), int(std::floor(p.y()))};
}

TEST(LayoutView, OverlapsAreHatchedAndFillsHaveTheMeasureColour) {
  // Unit right triangles at the origin and moved by (1/4, 1/4), plus a copy of the first: the
  // region near the origin is covered once, the lens of both twice, (0.3, 0.3) three times.
  const Mapped m = flatTriangles({{0, 0}, {1, 0}, {0, 1}, {0.25, 0.25}, {1.25, 0.25}, {0.25, 1.25}, {0, 0}, {1, 0}, {0, 1}});
  ViewOptions o;
  o.layoutSize = 200;
  const Image image = drawView(View::Layout, m.input(), o);
  EXPECT_GE(image.width, 2 * kLegendPadding + kBarLength);  // widened by the legend
  EXPECT_GT(image.height, 200);
  const analysis::UvGrid grid = layoutGrid(m.judgement.summary.uvBounds, 200);
  EXPECT_NEAR(grid.bounds.min().x(), -1.25 / 32.0, 1e-15);
  EXPECT_NEAR(grid.bounds.max().y(), 1.25 + 1.25 / 32.0, 1e-15);
  const Vec3 fill = paletteColour(Palette::Sequential, 0.0);

  auto expectRegion = [&](const Vec2& lo, const Vec2& hi, int count) {
    int hatched = 0;
    const auto [x0, row1] = layoutPixel(grid, lo);
    const auto [x1, row0] = layoutPixel(grid, hi);
    for (int row = row0; row <= row1; ++row)
      for (int x = x0; x <= x1; ++x) {
        const std::optional<Vec3> hatch = overlapHatch(count, x, row);
        ASSERT_TRUE(near(pixelColour(image, x, row), hatch ? *hatch : fill)) << x << ", " << row << " count " << count;
        hatched += hatch.has_value();
      }
    if (count >= 2) {
      EXPECT_GT(hatched, 0);
    }
  };
  expectRegion({0.02, 0.02}, {0.2, 0.2}, 2);   // the first triangle and its copy
  expectRegion({1.02, 0.28}, {1.1, 0.34}, 1);  // the moved triangle only
  expectRegion({0.3, 0.3}, {0.55, 0.4}, 3);    // all three
  const auto [outsideX, outsideRow] = layoutPixel(grid, {1.2, 1.2});
  EXPECT_TRUE(near(pixelColour(image, outsideX, outsideRow), kLayoutBackground));
}

TEST(LayoutView, ASquareSplitInTwoIsFilledOnceAndTheSeamIsDrawnOnBothSides) {
  // The square [0, 1]^2 as two triangles: no overlap anywhere, not even on the diagonal.
  const Mapped square = flatTriangles({{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}});
  ViewOptions o;
  o.layoutSize = 128;
  const Image image = drawView(View::Layout, square.input(), o);
  const analysis::UvGrid grid = layoutGrid(square.judgement.summary.uvBounds, 128);
  const Vec3 fill = paletteColour(Palette::Sequential, 0.0);
  const auto [x0, row1] = layoutPixel(grid, {0.01, 0.01});
  const auto [x1, row0] = layoutPixel(grid, {0.99, 0.99});
  for (int row = row0; row <= row1; ++row)
    for (int x = x0; x <= x1; ++x) ASSERT_TRUE(near(pixelColour(image, x, row), fill)) << x << ", " << row;
  // The frame of the unit square, one pixel wide, at u = 0.
  const auto [frameX, frameRow] = layoutPixel(grid, {0.0, 0.5});
  EXPECT_TRUE(near(pixelColour(image, frameX, frameRow), kFrameColour));

  // Two triangles sharing the edge (1, 2), the second a whole turn along u: a wrap seam drawn at
  // both UV places of the edge.
  Mapped seam;
  seam.mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  seam.mesh.triangles = {{0, 1, 2}, {2, 1, 3}};
  seam.uv.uv = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 0}, {2, 1}};
  seam.uv.faceFlags.assign(2, kFaceOk);
  seam.analyse();
  const Image layout = drawView(View::Layout, seam.input(), o);
  const analysis::UvGrid seamGrid = layoutGrid(seam.judgement.summary.uvBounds, 128);
  for (const Vec2& midpoint : {Vec2(0.5, 0.5), Vec2(1.5, 0.5)}) {
    const auto [x, row] = layoutPixel(seamGrid, midpoint);
    EXPECT_TRUE(near(pixelColour(layout, x, row), kWrapSeamColour)) << midpoint.transpose();
  }
  o.layoutFill = View::Seams;
  EXPECT_THROW(drawView(View::Layout, seam.input(), o), UsageError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::views
