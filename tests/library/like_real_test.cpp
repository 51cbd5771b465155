// The library on meshes like real ones (meshes/generators.h: a torus knot, a long bone, a bumpy
// scan, an open scanned patch with a ragged boundary; also scaled far from 1): every projector and
// seam mode gives one finite (s, t) per corner, states that agree with the reasons, a verdict, and
// a file that reads back to the same numbers; texgen's q is divided out as `uvtk texgen` does.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "meshes/generators.h"
#include "scratch_dir.h"
#include "uvtk/uvtk.h"

namespace uvtk::api {
namespace {
namespace UVTK_TEST_FILE {

class LikeRealTest : public ScratchDirTest {};

Mesh publicMesh(const uvtk::Mesh& engine, double scale = 1.0) {
  Mesh mesh;
  for (const auto& p : engine.positions) mesh.positions.push_back({scale * p.x(), scale * p.y(), scale * p.z()});
  mesh.triangles = engine.triangles;
  return mesh;
}

std::vector<std::pair<std::string, Mesh>> likeReal() {
  return {{"knot", publicMesh(meshes::torusKnot(2, 3, 96, 8))},
          {"bone", publicMesh(meshes::bone(40, 12))},
          {"blob", publicMesh(meshes::bumpyBlob(2))},
          {"patch", publicMesh(meshes::scannedPatch(2))},
          {"tiny patch", publicMesh(meshes::scannedPatch(2), 1e-150)},
          {"huge bone", publicMesh(meshes::bone(40, 12), 1e150)}};
}

void expectConsistent(const Mapping& m, const std::string& what) {
  const std::size_t faces = m.mesh.triangles.size();
  ASSERT_EQ(m.uv.size(), 3 * faces) << what;
  ASSERT_EQ(m.state.size(), 3 * faces) << what;
  ASSERT_EQ(m.faceFlags.size(), faces) << what;
  for (std::size_t c = 0; c < m.uv.size(); ++c) {
    EXPECT_TRUE(std::isfinite(m.uv[c][0]) && std::isfinite(m.uv[c][1])) << what << " corner " << c;
    EXPECT_EQ(m.state[c] == CornerState::Invalid, m.invalidReason[c] != InvalidReason::Valid) << what << " corner " << c;
    if (m.state[c] == CornerState::Invalid) {
      EXPECT_TRUE(m.faceFlags[c / 3] & kFaceInvalid) << what << " corner " << c;
    }
  }
  EXPECT_TRUE(m.verdict.status == "pass" || m.verdict.status == "warn" || m.verdict.status == "fail") << what;
  EXPECT_EQ(m.verdict.status == "pass", m.verdict.reasons.empty()) << what;
}

TEST_F(LikeRealTest, EveryProjectorGivesConsistentCornersAndReadsBackExactly) {
  const std::vector<std::string> options = {"--projector sphere --seam cut",
                                            "--projector cylinder --fit obb --caps",
                                            "--projector cube --fit pca",
                                            "--projector plane --omap normal",
                                            "--projector sphere --omap centroid --seam-place auto"};
  for (const auto& [name, mesh] : likeReal())
    for (const std::string& line : options) {
      const std::string what = name + " " + line;
      const Mapping m = map(mesh, MapOptions::parse(line));
      expectConsistent(m, what);
      writeMesh(path("m.obj"), m);
      const Mesh back = readMesh(path("m.obj"));
      ASSERT_EQ(back.triangles.size(), m.mesh.triangles.size()) << what;
      EXPECT_EQ(back.positions, m.mesh.positions) << what;
      for (std::size_t c = 0; c < m.uv.size(); ++c) {
        // A corner without a valid UV comes back without one (the writer lists its face).
        const int index = back.cornerTexcoords[c / 3][c % 3];
        ASSERT_EQ(index < 0, m.invalidReason[c] != InvalidReason::Valid) << what << " corner " << c;
        if (index < 0) continue;
        const Vector3& t = back.texcoords[std::size_t(index)];
        ASSERT_EQ(t[0], m.uv[c][0]) << what << " corner " << c;
        ASSERT_EQ(t[1], m.uv[c][1]) << what << " corner " << c;
      }
    }
}

TEST_F(LikeRealTest, TheVerdictDoesNotDependOnTheScale) {
  const Mesh bone = publicMesh(meshes::bone(40, 12)), huge = publicMesh(meshes::bone(40, 12), 0x1p400);
  const Mapping a = map(bone, MapOptions::parse("--projector cylinder --caps")),
                b = map(huge, MapOptions::parse("--projector cylinder --caps"));
  EXPECT_EQ(a.verdict.status, b.verdict.status);
  EXPECT_EQ(a.uv, b.uv);  // a power of two scales exactly, and the fit undoes it
}

TEST_F(LikeRealTest, TexgensQIsDividedOutInTheFileAsUvtkTexgenDoes) {
  const Mesh patch = publicMesh(meshes::scannedPatch(2));
  const Mapping m = texgen(patch, TexgenOptions::parse("--s object_linear:1,0,0,0 --t object_linear:0,1,0,0 "
                                                       "--q object_linear:0,0,0,2"));
  expectConsistent(m, "texgen");
  ASSERT_EQ(m.q.size(), m.uv.size());
  writeMesh(path("t.obj"), m);
  const Mesh back = readMesh(path("t.obj"));
  for (std::size_t c = 0; c < m.uv.size(); ++c) {
    EXPECT_EQ(m.q[c], 2.0);
    const Vector3& t = back.texcoords[std::size_t(back.cornerTexcoords[c / 3][c % 3])];
    EXPECT_EQ(t[0], m.uv[c][0] / 2.0) << c;
    EXPECT_EQ(t[1], m.uv[c][1] / 2.0) << c;
    const Vector3& p = patch.positions[std::size_t(patch.triangles[c / 3][c % 3])];
    EXPECT_EQ(m.uv[c][0], p[0]);  // s = x, undivided in memory
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::api
