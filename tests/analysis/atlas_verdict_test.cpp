// The atlas's verdict (issue "atlas", point 3): on every kind of mesh the judgement finds no
// flipped face, no overlap, no invalid corner, no face collapsed in UV, and the gutter met between
// charts and at the border (measured on the layout); it passes outright
// wherever the mesh itself has no face of zero area (which the judgement warns of, whatever the UVs).
#include <gtest/gtest.h>

#include "analysis/judgement.h"
#include "analysis/texel_layout.h"
#include "param/atlas_meshes.h"
#include "param/projector.h"

namespace uvtk::analysis {
namespace {
namespace UVTK_TEST_FILE {

TEST(AtlasVerdict, PassesOnMeshesOfEveryKind) {
  std::size_t passed = 0, meshes = 0;
  for (const test::NamedMesh& named : test::atlasMeshes()) {
    SCOPED_TRACE(named.name);
    param::ProjectorOptions o;
    o.surface = param::SurfaceKind::Atlas;
    const param::Projection p = param::project(named.mesh, o);
    const Judgement j = judge(p.mesh, p.uv);
    ++meshes;
    EXPECT_EQ(j.invalidFaces, 0u);
    EXPECT_EQ(j.statusCount(FaceStatus::Flipped), 0u);
    EXPECT_EQ(j.statusCount(FaceStatus::ZeroAreaUv), 0u);
    EXPECT_EQ(j.summary.overlap.overlappedPixels, 0u);
    const Gutters g = measureGutters(p.mesh, p.uv, p.atlas->chartOfFace, 1024, 1024);  // the gutter met
    EXPECT_GE(g.betweenCharts, o.atlas.marginTexels - 1e-6);
    EXPECT_GE(g.toBorder, o.atlas.marginTexels - 1e-6);
    if (p.atlas->degenerateFaces == 0) {
      EXPECT_EQ(j.verdict, Verdict::Pass) << j.reasonsText();
      passed += j.verdict == Verdict::Pass;
    } else {
      EXPECT_NE(j.verdict, Verdict::Fail) << j.reasonsText();
    }
  }
  EXPECT_GE(meshes, 20u);
  EXPECT_GE(passed, 20u);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::analysis
