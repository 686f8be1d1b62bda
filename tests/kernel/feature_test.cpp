// A feature's derived sizes against textbook formulas: pitch radii (transverse for helical
// gears), a bevel gear's outer cone distance, and the distances at which features mesh.

#include "kernel/features/feature.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace mechanist {
namespace {

Feature Gear(int teeth, double module, double helix = 0.0, bool internal = false) {
  Feature f;
  f.kind = FeatureKind::kGear;
  f.teeth = teeth;
  f.module = module;
  f.helix_angle = helix;
  f.internal = internal;
  return f;
}

TEST(Feature, PitchRadiiAndConeDistances) {
  EXPECT_DOUBLE_EQ(Gear(20, 2).PitchRadius(), 20.0);
  // Helical: the transverse module m / cos(b); 30 teeth of module 2 at 20 degrees.
  const double b = 20 * std::numbers::pi / 180;
  EXPECT_NEAR(Gear(30, 2, b).PitchRadius(), 30.0 / std::cos(b), 1e-12);
  Feature bevel = Gear(20, 2);
  bevel.kind = FeatureKind::kBevelGear;
  bevel.pitch_angle = std::numbers::pi / 6;
  EXPECT_NEAR(bevel.OuterConeDistance(), 40.0, 1e-12);  // 2 x 20 / (2 sin 30 deg)
}

TEST(Feature, MeshCentreDistancesInEitherOrder) {
  EXPECT_DOUBLE_EQ(MeshCentreDistance(Gear(17, 1), Gear(31, 1)), 24.0);
  EXPECT_DOUBLE_EQ(MeshCentreDistance(Gear(10, 1), Gear(40, 1, 0, true)), 15.0);
  const double b = 15 * std::numbers::pi / 180;
  EXPECT_NEAR(MeshCentreDistance(Gear(20, 2, b), Gear(40, 2, -b)), 60 / std::cos(b), 1e-12);
  Feature worm;
  worm.kind = FeatureKind::kWorm;
  worm.module = 1;
  worm.pitch_diameter = 10;
  const Feature wheel = Gear(40, 1);
  EXPECT_DOUBLE_EQ(MeshCentreDistance(worm, wheel), 25.0);  // (10 + 40) / 2
  EXPECT_DOUBLE_EQ(MeshCentreDistance(wheel, worm), 25.0);
  Feature rack;
  rack.kind = FeatureKind::kRack;
  rack.module = 1;
  EXPECT_DOUBLE_EQ(MeshCentreDistance(Gear(20, 1), rack), 10.0);
  EXPECT_DOUBLE_EQ(MeshCentreDistance(rack, Gear(20, 1)), 10.0);
}

}  // namespace
}  // namespace mechanist
