// IsRoundAbout against shapes whose symmetry is known by construction: tessellated solids of
// revolution (round about their axis only), prisms and toothed outlines (n-fold, never round).
#include "kernel/collision/rotational_symmetry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>

#include "kernel/mesh/mesh_builder.h"

namespace mechanist {
namespace {

const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

// A solid about the z axis, r = radius(theta) between z = -5 and 5, with a bore of radius 2.
CollisionMesh Solid(std::function<double(double)> radius, int segments) {
  RadialGrid grid;
  grid.radius = [radius](double theta, double) { return radius(theta); };
  grid.angular_segments = segments;
  grid.axial_segments = 1;
  grid.z0 = -5;
  grid.z1 = 5;
  grid.bore_radius = 2;
  grid.bore_segments = segments;
  return CollisionMesh(std::make_shared<TriangleMesh>(MakeRadialGridSolid(grid)));
}

TEST(RotationalSymmetry, AWasherIsRoundAboutItsAxisOnly) {
  // 96 facets: a chord's sagitta is 10 (1 - cos(pi / 96)) = 0.005 mm.
  const CollisionMesh washer = Solid([](double) { return 10.0; }, 96);
  EXPECT_TRUE(IsRoundAbout(washer, Eigen::Vector3d::Zero(), kZ, 0.02));
  EXPECT_TRUE(IsRoundAbout(washer, Eigen::Vector3d(0, 0, 7), -kZ, 0.02));  // any point on it
  EXPECT_FALSE(IsRoundAbout(washer, Eigen::Vector3d(0.5, 0, 0), kZ, 0.02));
  EXPECT_FALSE(IsRoundAbout(washer, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0.1, 1), 0.02));
  EXPECT_FALSE(IsRoundAbout(washer, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 0.02));
  EXPECT_FALSE(IsRoundAbout(washer, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.02));
  // Coarser than the tolerance: 12 facets leave 0.34 mm between a turned corner and a face.
  EXPECT_FALSE(
      IsRoundAbout(Solid([](double) { return 10.0; }, 12), Eigen::Vector3d::Zero(), kZ, 0.02));
}

TEST(RotationalSymmetry, SymmetricPatternsAreNotRound) {
  // A hexagon (a nut) and gears of 6 to 120 teeth on a 20 mm pitch radius, their teeth 2
  // modules deep (module 40 / teeth), sampled finely enough that a round solid would pass at
  // the tolerance the motion analysis gives a part of this size (0.2% of its 57 mm diagonal).
  constexpr double kTolerance = 0.11;
  EXPECT_FALSE(
      IsRoundAbout(Solid([](double) { return 10.0; }, 6), Eigen::Vector3d::Zero(), kZ, kTolerance));
  for (int teeth : {6, 17, 20, 40, 79, 120}) {
    const double module = 40.0 / teeth;
    const CollisionMesh gear =
        Solid([=](double theta) { return 20.0 + module * std::cos(teeth * theta); }, 16 * teeth);
    EXPECT_FALSE(IsRoundAbout(gear, Eigen::Vector3d::Zero(), kZ, kTolerance)) << teeth << " teeth";
  }
  // The same outline without teeth is round at that tolerance.
  EXPECT_TRUE(IsRoundAbout(Solid([](double) { return 20.0; }, 16 * 120), Eigen::Vector3d::Zero(),
                           kZ, kTolerance));
}

TEST(RotationalSymmetry, ALeverDoesNotReachEquallyAroundItsPivot) {
  // A 40 x 10 x 5 lever whose pivot is 5 mm from one end: 35 mm one way, 5 mm the others.
  Region2d r;
  r.outer = {{-5, -5}, {35, -5}, {35, 5}, {-5, 5}};
  const TriangleMesh lever = ExtrudeRegion(r, 0, 5);
  EXPECT_FALSE(ReachesEquallyAround(lever, Eigen::Vector3d::Zero(), kZ, 0.1));
  EXPECT_FALSE(IsRoundAbout(CollisionMesh(std::make_shared<TriangleMesh>(lever)),
                            Eigen::Vector3d::Zero(), kZ, 0.1));
  // The washer reaches 10 mm all round its axis, not round a line 1 mm beside it.
  const CollisionMesh washer = Solid([](double) { return 10.0; }, 96);
  EXPECT_TRUE(ReachesEquallyAround(washer.mesh(), Eigen::Vector3d::Zero(), kZ, 0.02));
  EXPECT_FALSE(ReachesEquallyAround(washer.mesh(), Eigen::Vector3d(1, 0, 0), kZ, 0.02));
}

TEST(RotationalSymmetry, ASphereIsRoundAboutEveryLineThroughItsCentre) {
  const CollisionMesh ball(std::make_shared<TriangleMesh>(MakeUvSphere(5, 64, 128)));
  EXPECT_TRUE(IsRoundAbout(ball, Eigen::Vector3d::Zero(), kZ, 0.02));
  // About another line through the centre, vertices turn off the poles' rings by up to the
  // facets' sagitta in both directions: 5 (1 - cos(pi / 64)) = 0.006 mm.
  EXPECT_TRUE(IsRoundAbout(ball, Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1, 0), 0.02));
  EXPECT_FALSE(IsRoundAbout(ball, Eigen::Vector3d(0.2, 0, 0), kZ, 0.02));
}

}  // namespace
}  // namespace mechanist
