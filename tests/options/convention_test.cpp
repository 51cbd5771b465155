// --convention blender|assimp|notes: hand-computed values, and the per-corner UVs Blender 3.4.1 and
// assimp 5.2.5 wrote themselves (tests/data/peers/README.md), reproduced through the point API.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "uvtk/point.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

using point::Mapping;
using point::Result;
using point::Status;
using point::Vector3;

constexpr double kPi = 3.14159265358979323846;

// A box [-1, 3] x [-2, 2] x [0, 4]: centre (1, 0, 2).
const std::vector<Vector3> kBox = {{-1, -2, 0}, {3, 2, 4}};

Vector3 offCentre(double dx, double dy, double dz) { return {1 + dx, dy, 2 + dz}; }

TEST(ConventionBlender, SphereTurnsFromMinusYCounterClockwiseAboutTheBoxCentre) {
  const Mapping m("--projector sphere --convention blender", kBox);
  // u = (1 - atan2(x, y)/pi)/2, v = 1 - acos(z/|p|)/pi of p = P - centre.
  EXPECT_DOUBLE_EQ(m.at(offCentre(1, 0, 0)).u, 0.25);
  EXPECT_DOUBLE_EQ(m.at(offCentre(0, 1, 0)).u, 0.5);
  EXPECT_DOUBLE_EQ(m.at(offCentre(-1, 0, 0)).u, 0.75);
  const Result seam = m.at(offCentre(0, -3, 0));
  EXPECT_EQ(seam.status, Status::OnSeam);
  EXPECT_EQ(seam.u, 0.0);
  const Result diagonal = m.at(offCentre(1, 1, std::sqrt(2.0)));  // azimuth 45 degrees, polar angle 45 degrees
  EXPECT_NEAR(diagonal.u, 0.375, 1e-15);
  EXPECT_NEAR(diagonal.v, 0.75, 1e-15);
  const Result pole = m.at(offCentre(0, 0, -2));
  EXPECT_EQ(pole.status, Status::Pole);
  EXPECT_EQ(pole.v, 0.0);
}

TEST(ConventionBlender, CylinderVIsHalfTheCentredHeightPlusOneInObjectUnits) {
  const Mapping m("--projector cylinder --convention blender", kBox);
  const Result a = m.at(offCentre(0, 1, 0.5));
  EXPECT_DOUBLE_EQ(a.u, 0.5);
  EXPECT_DOUBLE_EQ(a.v, 0.75);  // (0.5 + 1)/2
  const Result b = m.at(offCentre(5, 0, -1));
  EXPECT_DOUBLE_EQ(b.u, 0.25);
  EXPECT_DOUBLE_EQ(b.v, 0.0);
  EXPECT_DOUBLE_EQ(m.at(offCentre(0, 1, 3)).v, 2.0);  // no fit to the height: v leaves [0, 1]
  EXPECT_EQ(a.period[0], 1.0);                        // v is scaled by the UV transform, u's period is not
}

TEST(ConventionBlender, CenterGivesThePivotOfA3dView) {
  const Mapping m("--projector sphere --convention blender --center 10,20,30", kBox);
  EXPECT_DOUBLE_EQ(m.at({11, 20, 30}).u, 0.25);
  EXPECT_DOUBLE_EQ(m.at({10, 21, 30}).u, 0.5);
}

TEST(ConventionAssimp, SphereAboutPlusYWithTheSeamOnMinusZ) {
  const Mapping m("--projector sphere --convention assimp", kBox);
  // u = (atan2(x, z) + pi)/(2 pi), v = (asin(y) + pi/2)/pi of the unit vector from the box centre.
  const Result front = m.at(offCentre(0, 0, 1));
  EXPECT_DOUBLE_EQ(front.u, 0.5);
  EXPECT_DOUBLE_EQ(front.v, 0.5);
  EXPECT_DOUBLE_EQ(m.at(offCentre(1, 0, 0)).u, 0.75);
  EXPECT_DOUBLE_EQ(m.at(offCentre(-1, 0, 0)).u, 0.25);
  const Result back = m.at(offCentre(0, 0.5, -std::sqrt(0.75)));
  EXPECT_EQ(back.status, Status::OnSeam);
  EXPECT_EQ(back.u, 0.0);
  EXPECT_NEAR(back.v, (std::asin(0.5) + kPi / 2) / kPi, 1e-15);  // 2/3
  const Result top = m.at(offCentre(0, 1, 0));
  EXPECT_EQ(top.status, Status::Pole);
  EXPECT_EQ(top.v, 1.0);
}

TEST(ConventionAssimp, CylinderVRunsOverTheBoxAlongY) {
  const Mapping m("--projector cylinder --convention assimp", kBox);
  const Result r = m.at(offCentre(1, 1, 0));
  EXPECT_DOUBLE_EQ(r.u, 0.75);
  EXPECT_DOUBLE_EQ(r.v, 0.75);  // (y - ymin)/(ymax - ymin) = (1 + 2)/4
}

// ---- --convention notes: the lecture notes' worked examples ----

TEST(ConventionNotes, CubeGivesTheNotesWorkedExample) {
  // "The vector (-0.2, 0.5, -0.84) selects the -Z face; (-0.2, 0.5) gets mapped to (0.38, 0.80)":
  // major axis |z| = 0.84, direct convention on -Z: s = (x/|z| + 1)/2, t = (y/|z| + 1)/2.
  const Mapping m("--projector cube --convention notes");  // no mesh: nothing is fitted
  const Result r = m.at({-0.2, 0.5, -0.84});
  EXPECT_EQ(r.status, Status::Ok) << r.reason;
  EXPECT_EQ(r.w, 5.0);  // -Z in the faces layout (+X -X +Y -Y +Z -Z)
  EXPECT_NEAR(r.u, 8.0 / 21.0, 1e-15);   // (1 - 0.2/0.84)/2 = 0.380952...
  EXPECT_NEAR(r.v, 67.0 / 84.0, 1e-15);  // (1 + 0.5/0.84)/2 = 0.797619...
  EXPECT_NEAR(r.u, 0.38, 0.005);
  EXPECT_NEAR(r.v, 0.80, 0.005);
  // Exactly the long form the preset stands for.
  const Result longForm =
      Mapping("--projector cube --cube-convention direct --fit none --omap centroid --cube-layout faces").at(
          {-0.2, 0.5, -0.84});
  EXPECT_EQ(r.u, longForm.u);
  EXPECT_EQ(r.v, longForm.v);
  EXPECT_EQ(r.w, longForm.w);
  // The direction from the origin selects the face, whatever the length: the point scaled by 3.
  const Result far = m.at({-0.6, 1.5, -2.52});
  EXPECT_EQ(far.w, 5.0);
  EXPECT_NEAR(far.u, 8.0 / 21.0, 1e-15);
  EXPECT_NEAR(far.v, 67.0 / 84.0, 1e-15);
}

TEST(ConventionNotes, CubeUsesTheRemainingCoordinatesInXYZOrderOnEveryFace) {
  const Mapping m("--projector cube --convention notes");
  // +X: (y, z); -Y: (x, z); +Z: (x, y); each divided by the major component's magnitude.
  const Result px = m.at({2, 1, -1});
  EXPECT_EQ(px.w, 0.0);
  EXPECT_DOUBLE_EQ(px.u, 0.75);  // (1/2 + 1)/2
  EXPECT_DOUBLE_EQ(px.v, 0.25);  // (-1/2 + 1)/2
  const Result ny = m.at({1, -4, 2});
  EXPECT_EQ(ny.w, 3.0);
  EXPECT_DOUBLE_EQ(ny.u, 0.625);
  EXPECT_DOUBLE_EQ(ny.v, 0.75);
  const Result pz = m.at({0.5, -0.5, 1});
  EXPECT_EQ(pz.w, 4.0);
  EXPECT_DOUBLE_EQ(pz.u, 0.75);
  EXPECT_DOUBLE_EQ(pz.v, 0.25);
}

TEST(ConventionNotes, SphereIsSeed004InObjectCoordinates) {
  // s = atan2(y, x)/(2 pi) in (-1/2, 1/2], t = acos(z)/pi (t = 0 at +z), of the direction from the origin.
  const Mapping m("--projector sphere --convention notes");
  const Result a = m.at({0, 2, 0});
  EXPECT_DOUBLE_EQ(a.u, 0.25);
  EXPECT_DOUBLE_EQ(a.v, 0.5);
  const Result b = m.at({0, -1, 1});  // azimuth -90 degrees, polar angle 45 degrees
  EXPECT_NEAR(b.u, -0.25, 1e-15);
  EXPECT_NEAR(b.v, 0.25, 1e-15);
  const Result top = m.at({0, 0, 3});
  EXPECT_EQ(top.status, Status::Pole);
  EXPECT_EQ(top.v, 0.0);
}

TEST(ConventionNotes, LeavesTheRayFreeButOwnsTheFormulasAndThePlacement) {
  // --omap reflection looks the notes' cube up by the reflected vector: at the eye's height a
  // flat mirror facing +z sends the view from (0, 0, 5) back along +z, the +Z face's centre.
  const Result reflected =
      Mapping("--projector cube --convention notes --omap reflection --at-infinity --eye 0,0,5").at({0, 0, 0}, {0, 0, 1});
  EXPECT_EQ(reflected.w, 4.0);
  EXPECT_DOUBLE_EQ(reflected.u, 0.5);
  EXPECT_DOUBLE_EQ(reflected.v, 0.5);
  for (const char* options : {"--projector cube --convention notes --cube-convention gl",
                              "--projector cube --convention notes --fit bbox",
                              "--projector cube --convention notes --center 1,0,0",
                              "--projector sphere --convention notes --sphere-preset glu",
                              "--projector cylinder --convention notes", "--projector plane --convention notes"}) {
    try {
      Mapping m(options);
      ADD_FAILURE() << options << ": accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("--convention"), std::string::npos) << e.what();
    }
  }
}

TEST(Convention, RejectsWhatItSetsAndSurfacesTheToolDoesNotHave) {
  for (const char* options :
       {"--projector sphere --convention blender --fit bbox", "--projector sphere --convention assimp --seam-place 90",
        "--projector sphere --convention assimp --center 0,0,0",
        "--projector cylinder --convention blender --uv-scale 2,2", "--projector plane --convention blender",
        "--projector cube --convention assimp"}) {
    try {
      Mapping m(options, kBox);
      ADD_FAILURE() << options << ": accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("--convention"), std::string::npos) << e.what();
    }
  }
}

// ---- The tools' own output ----

struct PeerCorner {
  int face = 0;
  Vector3 position{};
  double u = 0.0, v = 0.0;
};

std::vector<PeerCorner> readPeerCsv(const std::string& name) {
  std::ifstream in(std::string(UVTK_TEST_DATA_DIR) + "/peers/" + name);
  EXPECT_TRUE(in) << name;
  std::vector<PeerCorner> corners;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<double> fields;
    std::stringstream row(line);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(std::stod(field));
    corners.push_back({static_cast<int>(fields[0]), {fields[3], fields[4], fields[5]}, fields[6], fields[7]});
  }
  return corners;
}

std::vector<Vector3> positionsOf(const std::vector<PeerCorner>& corners) {
  std::set<Vector3> unique;
  for (const PeerCorner& c : corners) unique.insert(c.position);
  return {unique.begin(), unique.end()};
}

// The tools compute in float: about 1e-7 from uvtk's double.
constexpr double kFloatTolerance = 5e-7;

struct Agreement {
  std::size_t corners = 0, poles = 0, beyond = 0;
  std::set<int> facesBeyond;
  double maxError = 0.0;
};

Agreement compare(const Mapping& m, const std::vector<PeerCorner>& corners) {
  Agreement a;
  for (const PeerCorner& c : corners) {
    const Result expected = m.at(c.position);
    EXPECT_NE(expected.status, Status::Invalid) << expected.reason;
    ++a.corners;
    if (expected.status == Status::Pole) ++a.poles;
    const double error = point::uvError(c.u, c.v, expected);
    if (error > kFloatTolerance) {
      ++a.beyond;
      a.facesBeyond.insert(c.face);
    } else {
      a.maxError = std::max(a.maxError, error);
    }
  }
  return a;
}

TEST(ConventionBlender, ReproducesBlenderOnAnOffCentreMesh) {
  for (const char* projector : {"sphere", "cylinder"}) {
    const std::vector<PeerCorner> corners = readPeerCsv(std::string("blender_offcentre_") + projector + ".csv");
    const Mapping m(std::string("--projector ") + projector + " --convention blender", positionsOf(corners));
    const Agreement a = compare(m, corners);
    EXPECT_EQ(a.corners, 240u);
    EXPECT_EQ(a.beyond, 0u) << projector;
    EXPECT_LT(a.maxError, 2e-7) << projector;
  }
}

TEST(ConventionBlender, ReproducesBlendersMedianPivotGivenAsCenter) {
  const std::vector<PeerCorner> corners = readPeerCsv("blender_offcentre_sphere_median.csv");
  // Median Point: the mean of the faces' centroids (not of the vertices), in float as Blender sums
  // it (BM_face_calc_center_median, then the sum times 1/faces).
  std::map<int, std::vector<Vector3>> faces;
  for (const PeerCorner& c : corners) faces[c.face].push_back(c.position);
  float sum[3] = {0, 0, 0};
  for (const auto& [face, points] : faces) {
    float centroid[3] = {0, 0, 0};
    for (const Vector3& p : points)
      for (int k = 0; k < 3; ++k) centroid[k] += static_cast<float>(p[k]);
    for (int k = 0; k < 3; ++k) sum[k] += centroid[k] * (1.0f / static_cast<float>(points.size()));
  }
  Vector3 pivot{};
  for (int k = 0; k < 3; ++k) pivot[k] = sum[k] * (1.0f / static_cast<float>(faces.size()));
  char center[128];
  std::snprintf(center, sizeof center, "%.17g,%.17g,%.17g", pivot[0], pivot[1], pivot[2]);
  const Mapping m(std::string("--projector sphere --convention blender --center ") + center);
  const Agreement a = compare(m, corners);
  EXPECT_EQ(a.beyond, 0u);
  // The bounding-box centre is visibly not that pivot.
  const Agreement box = compare(Mapping("--projector sphere --convention blender", positionsOf(corners)), corners);
  EXPECT_GT(box.beyond, 200u);
}

TEST(ConventionBlender, AtPolesBlenderWritesUZeroOrOneAndTheCylinderZeroZero) {
  const std::vector<PeerCorner> sphere = readPeerCsv("blender_icosphere_sphere.csv");
  const Agreement s = compare(Mapping("--projector sphere --convention blender", positionsOf(sphere)), sphere);
  EXPECT_EQ(s.corners, 3840u);
  EXPECT_EQ(s.poles, 12u);  // the six faces around each pole; only v is compared there
  EXPECT_EQ(s.beyond, 0u);

  const std::vector<PeerCorner> cylinder = readPeerCsv("blender_cylinder_capped_cylinder.csv");
  const Mapping m("--projector cylinder --convention blender", positionsOf(cylinder));
  std::size_t axis = 0;
  for (const PeerCorner& c : cylinder) {
    const Result expected = m.at(c.position);
    if (expected.status == Status::Pole) {  // map_to_tube leaves v = 0 on the axis, whatever the height
      ++axis;
      EXPECT_TRUE(c.u == 0.0 || c.u == 1.0) << c.u;  // 0, or 1 after its seam fix
      EXPECT_EQ(c.v, 0.0);
    } else {
      EXPECT_LE(point::uvError(c.u, c.v, expected), kFloatTolerance);
    }
  }
  EXPECT_GT(axis, 0u);
}

TEST(ConventionAssimp, ReproducesAssimpExceptWhereItsSeamFixSnapsU) {
  struct Case {
    const char* file;
    const char* options;
    std::size_t corners, poles, snappedFaces;
  };
  for (const Case& c : {Case{"assimp_offcentre_sphere.csv", "--projector sphere --convention assimp", 240, 0, 0},
                        Case{"assimp_offcentre_cylinder.csv", "--projector cylinder --convention assimp", 240, 0, 0},
                        Case{"assimp_icosphere_sphere.csv", "--projector sphere --convention assimp", 3840, 12, 16}}) {
    const std::vector<PeerCorner> corners = readPeerCsv(c.file);
    const Agreement a = compare(Mapping(c.options, positionsOf(corners)), corners);
    EXPECT_EQ(a.corners, c.corners) << c.file;
    EXPECT_EQ(a.poles, c.poles) << c.file;
    EXPECT_EQ(a.facesBeyond.size(), c.snappedFaces) << c.file;
    // RemoveUVSeams writes exactly 0 or 1 into the faces it changes.
    std::set<int> snapped;
    for (const PeerCorner& corner : corners)
      if (corner.u == 0.0 || corner.u == 1.0) snapped.insert(corner.face);
    for (int face : a.facesBeyond) EXPECT_TRUE(snapped.count(face)) << c.file << " face " << face;
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
