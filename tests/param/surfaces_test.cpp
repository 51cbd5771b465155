// Each intermediate surface resolving each kind of probe, against hand-computed hit points.
#include "param/surfaces.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace uvtk::param {
namespace {
namespace UVTK_TEST_FILE {

Probe foot(const Vec3& p) { return {Probe::Kind::Foot, p, Vec3::Zero()}; }
Probe central(const Vec3& p) { return {Probe::Kind::Central, p, Vec3::Zero()}; }
Probe ray(const Vec3& p, const Vec3& d) { return {Probe::Kind::Ray, p, d}; }

TEST(FirstNonNegativeRoot, ReturnsTheNearestHitInFront) {
  // t^2 - 3t + 2 = (t - 1)(t - 2)
  EXPECT_DOUBLE_EQ(*firstNonNegativeRoot<double>(1, -3, 2, 1), 1.0);
  // (t + 1)(t - 2): the root behind is skipped
  EXPECT_DOUBLE_EQ(*firstNonNegativeRoot<double>(1, -1, -2, 1), 2.0);
  // (t + 1)(t + 2): both behind
  EXPECT_FALSE(firstNonNegativeRoot<double>(1, 3, 2, 1));
  // no real root
  EXPECT_FALSE(firstNonNegativeRoot<double>(1, 0, 1, 1));
  // a = 0: linear, or parallel
  EXPECT_DOUBLE_EQ(*firstNonNegativeRoot<double>(0, 2, -4, 1), 2.0);
  EXPECT_FALSE(firstNonNegativeRoot<double>(0, 0, 1, 1));
}

TEST(FirstNonNegativeRoot, TreatsAnOriginOnTheSurfaceAsTheHit) {
  // c = -1e-17: just inside by rounding, the ray heading inwards; the hit is the origin itself.
  EXPECT_EQ(*firstNonNegativeRoot<double>(1, -2, -1e-17, 1), 0.0);
}

TEST(PlaneSurface, ResolvesEveryProbeKind) {
  const PlaneSurface plane;
  EXPECT_EQ(*plane.resolve(foot({2, 3, 4})), Vec3(2, 3, 0));
  EXPECT_EQ(*plane.resolve(central({2, 4, 2})), Vec3(1, 2, 1));  // (x/z, y/z)
  EXPECT_FALSE(plane.resolve(central({2, 4, 0})));
  EXPECT_FALSE(plane.resolve(central({2, 4, -1})));
  // t = -pz/nz = -4/-2 = 2: (1 + 2, 1 + 0, 0)
  EXPECT_EQ(*plane.resolve(ray({1, 1, 4}, {1, 0, -2})), Vec3(3, 1, 0));
  EXPECT_EQ(plane.resolve(ray({1, 1, 4}, {1, 0, 0})).reason, kCornerMiss);  // parallel
  EXPECT_EQ(plane.uvAt({0.25, 0.5, 0}), Vec2(0.25, 0.5));
}

// A ray is not its line: the crossing at t = -pz/nz < 0 lies behind the point (§4).
TEST(PlaneSurface, ARayWhoseLineCrossesOnlyBehindItsOriginIsBehind) {
  const PlaneSurface plane;
  // from z = 4 heading up: the line meets z = 0 at t = -2
  EXPECT_EQ(plane.resolve(ray({1, 1, 4}, {1, 0, 2})).reason, kCornerBehind);
  EXPECT_EQ(plane.resolve(ray({1, 1, -4}, {0, 0, -1})).reason, kCornerBehind);
  // an origin on the plane to rounding hits at itself, whichever way the ray points
  EXPECT_EQ(*plane.resolve(ray({1, 1, 1e-17}, {0, 0, 1})), Vec3(1, 1, 0));
  const TwoPlaneSurface two(Vec4(1, 0, 0, 0), Vec4(0, 1, 0, 0));
  EXPECT_EQ(two.resolve(ray({1, 1, 4}, {1, 0, 2})).reason, kCornerBehind);
}

// B = [0, 2]^3: centre 1, largest half-extent 1, reach kSensibleRange = 2: |q - 1| <= 2 per coordinate.
TEST(SensibleRange, AHitIsOutOfRangeBeyondTwiceTheLargestHalfExtentFromTheCentre) {
  const SensibleRangeT<double> range(Eigen::AlignedBox3d(Vec3(0, 0, 0), Vec3(2, 2, 2)));
  EXPECT_EQ(range.reach, 2.0);
  EXPECT_TRUE(range.contains(Vec3(3, -1, 1)));
  EXPECT_FALSE(range.contains(Vec3(3.0000001, 1, 1)));
  EXPECT_FALSE(range.contains(Vec3(1, 1, -1.0000001)));
  EXPECT_EQ(judgeHit(hitAt<double>(Vec3(4, 1, 1)), range), kCornerOutOfRange);
  EXPECT_EQ(judgeHit(sameUvAs<double>(Vec3(4, 1, 1)), range), kCornerValid);  // radial: scale-free
  EXPECT_EQ(judgeHit(hitAt<double>(Vec3(INFINITY, 1, 1)), range), kCornerNotFinite);
  EXPECT_EQ(judgeHit(noHit<double>(kCornerBehind), range), kCornerBehind);
  // without a box there is no range check
  EXPECT_EQ(judgeHit(hitAt<double>(Vec3(1e300, 1, 1)), SensibleRangeT<double>()), kCornerValid);
}

TEST(TwoPlaneSurface, GivesTrueSignedDistances) {
  const TwoPlaneSurface s(Vec4(0, 0, 2, -2), Vec4(3, 4, 0, 0));  // z = 1 and 3x + 4y = 0
  EXPECT_DOUBLE_EQ(s.uvAt({0, 0, 3}).x(), 2.0);
  EXPECT_DOUBLE_EQ(s.uvAt({1, 2, 0}).y(), (3.0 + 8.0) / 5.0);
}

TEST(TwoPlaneSurface, WithThePlanesXAndYEqualsThePlaneProjector) {
  const TwoPlaneSurface two(Vec4(1, 0, 0, 0), Vec4(0, 1, 0, 0));
  const PlaneSurface plane;
  EXPECT_EQ(two.axis, Vec3(0, 0, 1));
  for (const Probe& p : {foot({0.3, -2, 5}), central({0.3, -2, 5}), ray({0.3, -2, 5}, {0.1, 0.2, -0.7})}) {
    const Vec2 a = two.uvAt(*two.resolve(p)), b = plane.uvAt(*plane.resolve(p));
    EXPECT_DOUBLE_EQ(a.x(), b.x());
    EXPECT_DOUBLE_EQ(a.y(), b.y());
  }
}

TEST(TwoPlaneSurface, RejectsZeroNormalsAndParallelPlanes) {
  EXPECT_THROW(TwoPlaneSurface(Vec4(0, 0, 0, 1), Vec4(0, 1, 0, 0)), UsageError);
  EXPECT_THROW(TwoPlaneSurface(Vec4(1, 0, 0, 0), Vec4(-2, 0, 0, 5)), UsageError);
}

TEST(CylinderSurface, ResolvesEveryProbeKind) {
  const CylinderSurface c;
  EXPECT_EQ(c.uvAt(*c.resolve(foot({0, 2, 0.5}))), Vec2(0.25, 0.5));
  // centroid: the ray from the origin meets rho = 1 at v = z/rho
  EXPECT_EQ(c.uvAt(*c.resolve(central({0, 2, 3}))), Vec2(0.25, 1.5));
  EXPECT_FALSE(c.resolve(central({0, 0, 3})));
  // from inside along +x: exits at x = 1
  EXPECT_TRUE(c.resolve(ray({0.5, 0, 0.2}, {1, 0, 0}))->isApprox(Vec3(1, 0, 0.2)));
  // from outside heading in: enters at x = 1 (t = 1)
  EXPECT_TRUE(c.resolve(ray({2, 0, 0}, {-1, 0, 0.5}))->isApprox(Vec3(1, 0, 0.5)));
  // from outside heading away (its line meets the side only behind), or parallel to the axis: misses
  EXPECT_EQ(c.resolve(ray({2, 0, 0}, {1, 0, 0})).reason, kCornerMiss);
  EXPECT_EQ(c.resolve(ray({2, 0, 0}, {0, 0, 1})).reason, kCornerMiss);
}

TEST(SphereSurface, ResolvesEveryProbeKind) {
  const SphereSurface s;
  EXPECT_EQ(s.uvAt(*s.resolve(foot({0, 0, -5}))).y(), 0.0);
  EXPECT_FALSE(s.resolve(foot({0, 0, 0})));
  EXPECT_FALSE(s.resolve(central({0, 0, 0})));
  EXPECT_TRUE(s.resolve(ray({0, 0, 0}, {0, 2, 0}))->isApprox(Vec3(0, 1, 0)));
  EXPECT_TRUE(s.resolve(ray({0, -3, 0}, {0, 1, 0}))->isApprox(Vec3(0, -1, 0)));
  EXPECT_EQ(s.resolve(ray({0, -3, 0}, {1, 0, 0})).reason, kCornerMiss);
  EXPECT_EQ(s.resolve(ray({0, -3, 0}, {0, -1, 0})).reason, kCornerMiss);  // only its line meets it, behind
  // a ray tangent to the sphere touches it once
  EXPECT_TRUE(s.resolve(ray({-2, 1, 0}, {1, 0, 0}))->isApprox(Vec3(0, 1, 0), 1e-8));
}

TEST(CubeSurface, ChoosesFacesPerProbeKind) {
  const CubeSurface cube;
  EXPECT_EQ(*cube.chooseFace(foot({0.9, 0, 0}), Vec3(0, 0, -1)), CubeFace::NegZ);  // box mapping: the normal
  EXPECT_EQ(*cube.chooseFace(central({0.1, -0.5, 0.2}), Vec3::Zero()), CubeFace::NegY);
  EXPECT_FALSE(cube.chooseFace(central({0, 0, 0}), Vec3::Zero()));
  EXPECT_EQ(*cube.chooseFace(ray({0, 0, 0}, {0.2, 0.1, 1}), Vec3::Zero()), CubeFace::PosZ);    // exit from inside
  EXPECT_EQ(*cube.chooseFace(ray({5, 0.5, 0}, {-1, 0, 0}), Vec3::Zero()), CubeFace::PosX);    // entry from outside
  EXPECT_FALSE(cube.chooseFace(ray({5, 5, 0}, {-1, 0, 0}), Vec3::Zero()));                   // passes by
}

TEST(CubeSurface, ProjectsCornersOntoTheChosenFacePlane) {
  const CubeSurface cube;
  const auto st = [&](const Probe& probe, CubeFace f) { return cube.faceSt(*cube.projectOnFace(probe, f), f); };
  // Foot: orthographic, (sc + 1)/2 of the point itself; +Z: sc = x, tc = -y
  EXPECT_EQ(*cube.projectOnFace(foot({0.5, 0.5, 0.2}), CubeFace::PosZ), Vec3(0.5, 0.5, 1));
  EXPECT_TRUE(st(foot({0.5, 0.5, 0.2}), CubeFace::PosZ).isApprox(Vec2(0.75, 0.25)));
  // Central: divided by the face axis component
  EXPECT_TRUE(st(central({0.25, 0.25, 0.5}), CubeFace::PosZ).isApprox(Vec2(0.75, 0.25)));
  EXPECT_EQ(cube.projectOnFace(central({0.25, 0.25, -0.5}), CubeFace::PosZ).reason, kCornerMiss);
  // Ray from the origin along (0.5, 0.5, 1) meets z = 1 at (0.5, 0.5)
  EXPECT_TRUE(st(ray({0, 0, 0}, {0.5, 0.5, 1}), CubeFace::PosZ).isApprox(Vec2(0.75, 0.25)));
  EXPECT_EQ(cube.projectOnFace(ray({0, 0, 0}, {1, 0, 0}), CubeFace::PosZ).reason, kCornerMiss);  // parallel
  // heading away from z = 1: its line meets the plane at t = -1 only
  EXPECT_EQ(cube.projectOnFace(ray({0, 0, 0}, {0, 0, -1}), CubeFace::PosZ).reason, kCornerBehind);
}

TEST(ReflectionRay, MirrorsTheViewAboutTheNormal) {
  const ReflectionRay r{Vec3(0, 0, 5), false};
  // V = (0,0,-1) at the point (0,0,1) with N = (0,0,1): R = V - 2 (N.V) N = (0,0,1)
  const Probe p = r.probe({Vec3(0, 0, 1), Vec3(0, 0, 1)});
  EXPECT_EQ(p.kind, Probe::Kind::Ray);
  EXPECT_TRUE(p.direction.isApprox(Vec3(0, 0, 1)));
  // 45 degrees: V = (1,0,-1)/sqrt2 at N = (0,0,1) gives R = (1,0,1)/sqrt2
  const ReflectionRay far{Vec3(-1, 0, 1), true};
  const Probe q = far.probe({Vec3(0, 0, 0), Vec3(0, 0, 1)});
  EXPECT_EQ(q.kind, Probe::Kind::Central);
  EXPECT_TRUE(q.point.isApprox(Vec3(1, 0, 1) / std::sqrt(2.0)));
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::param
