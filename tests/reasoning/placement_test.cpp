// Placement by features: closed forms against hand-computed poses, meshes against the pair
// recognition that must then find the pair, least squares for several conditions, and errors.

#include "reasoning/placement.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kernel/assembly/assembly_state.h"
#include "reasoning/pair_recognition.h"
#include "test_assembly.h"

namespace mechanist {
namespace {

using testing::MakeFeature;
using testing::MakePart;

PlacementCondition Condition(PlacementCondition::Kind kind, std::size_t feature, FeatureRef target,
                             double angle = 0.0, std::optional<double> depth = std::nullopt) {
  PlacementCondition c;
  c.kind = kind;
  c.feature = feature;
  c.target = target;
  c.angle = angle;
  c.depth = depth;
  return c;
}

Feature Gear(const std::string& id, int teeth, const Eigen::Vector3d& origin = {0, 0, 0},
             const Eigen::Vector3d& axis = {0, 0, 1}) {
  return MakeFeature(id, FeatureKind::kGear, origin, axis, [teeth](Feature& f) {
    f.teeth = teeth;
    f.module = 1.0;
    f.length = 10.0;
  });
}

std::vector<Pair> PairsOf(AssemblySpec spec) {
  const Assembly a(std::move(spec));
  return RecognizePairs(a, InitialState(a)).pairs;
}

TEST(Placement, InsertPutsTheFeatureOnTheTargetsAxisAtDepthAndAngle) {
  AssemblySpec spec;
  // A hole at (5, 0, 2) pointing -z in a plate turned 90 degrees about z.
  spec.parts.push_back(MakePart("plate",
                                {MakeFeature("h", FeatureKind::kHole, {5, 0, 2}, {0, 0, -1},
                                             [](Feature& f) { f.length = 2; })},
                                RigidTransform::AxisAngle({0, 0, 1}, M_PI / 2), true));
  spec.parts.push_back(MakePart("pin", {MakeFeature("s", FeatureKind::kShaft, {0, 0, 1}, {0, 0, 1},
                                                    [](Feature& f) { f.length = 6; })}));
  spec.parts[1].placement = {
      Condition(PlacementCondition::Kind::kInsert, 0, {0, 0}, M_PI / 2, 1.5)};
  ResolvePlacements(&spec);
  const RigidTransform& X = spec.parts[1].X_WP;
  // The hole's world origin is (0, 5, 2), its axis -z.
  EXPECT_LT((X * Eigen::Vector3d(0, 0, 1) - Eigen::Vector3d(0, 5, 0.5)).norm(), 1e-12);
  EXPECT_LT((X.RotateDirection({0, 0, 1}) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-12);
  // Opposite axes: a half turn about the part's x, then the angle about the target's axis;
  // -z after the half turn maps the part's x to x, then 90 degrees about -z takes it to -y.
  EXPECT_LT((X.RotateDirection({1, 0, 0}) - Eigen::Vector3d(0, -1, 0)).norm(), 1e-12);
}

TEST(Placement, MeshedGearsAreRecognisedAsTheirPairs) {
  AssemblySpec spec;
  spec.parts.push_back(MakePart("g1", {Gear("teeth", 20, {0, 0, 3})},
                                RigidTransform::AxisAngle({1, 0, 0}, 0.3), true));
  spec.parts.push_back(MakePart("g2", {Gear("teeth", 12)}));
  spec.parts.push_back(MakePart("ring", {Gear("teeth", 50)}));
  spec.parts[2].features[0].internal = true;
  spec.parts[1].placement = {Condition(PlacementCondition::Kind::kMesh, 0, {0, 0}, M_PI / 2)};
  spec.parts[2].placement = {Condition(PlacementCondition::Kind::kMesh, 0, {1, 0})};
  ResolvePlacements(&spec);
  const RigidTransform& X1 = spec.parts[0].X_WP;
  const RigidTransform& X2 = spec.parts[1].X_WP;
  // At 90 degrees: along g1's local y, 16 mm from its axis, mid-faces coplanar.
  const Eigen::Vector3d mid1 = X1 * Eigen::Vector3d(0, 0, 8);
  const Eigen::Vector3d mid2 = X2 * Eigen::Vector3d(0, 0, 5);
  EXPECT_LT((mid2 - (mid1 + 16 * X1.RotateDirection({0, 1, 0}))).norm(), 1e-9);
  const std::vector<Pair> pairs = PairsOf(spec);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].type, PairType::kGear);
  EXPECT_EQ(pairs[1].type, PairType::kGear);  // the ring around g2, (50 - 12) / 2 from it
}

TEST(Placement, HelicalGearsMeshAtTheTransverseModulesDistance) {
  AssemblySpec spec;
  Feature left = Gear("teeth", 20), right = Gear("teeth", 40);
  left.helix_angle = 0.3;
  right.helix_angle = -0.3;
  spec.parts.push_back(MakePart("g1", {left}, RigidTransform(), true));
  spec.parts.push_back(MakePart("g2", {right}));
  spec.parts[1].placement = {Condition(PlacementCondition::Kind::kMesh, 0, {0, 0})};
  ResolvePlacements(&spec);
  EXPECT_NEAR(spec.parts[1].X_WP.translation().norm(), 30 / std::cos(0.3), 1e-9);
  const std::vector<Pair> pairs = PairsOf(spec);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].type, PairType::kGear);
}

TEST(Placement, BevelGearMeetsItsPartnerApexOnApex) {
  // A 15-tooth pinion on a tilted part meshed at polar angle 90 degrees by a 30-tooth gear: the
  // pitch angles atan(1/2) and atan(2) sum to a square shaft angle.
  const auto bevel = [](int teeth, double pitch_angle, const Eigen::Vector3d& apex) {
    return MakeFeature("teeth", FeatureKind::kBevelGear, apex, {0, 0, 1}, [=](Feature& f) {
      f.teeth = teeth;
      f.module = 2;
      f.pitch_angle = pitch_angle;
      f.length = 6;
    });
  };
  AssemblySpec spec;
  spec.parts.push_back(MakePart("pinion", {bevel(15, std::atan(0.5), {1, 2, 3})},
                                RigidTransform::AxisAngle({1, 1, 0}, 0.4), true));
  spec.parts.push_back(MakePart("gear", {bevel(30, std::atan(2.0), {0, 0, -4})}));
  spec.parts[1].placement = {Condition(PlacementCondition::Kind::kMesh, 0, {0, 0}, M_PI / 2)};
  ResolvePlacements(&spec);
  const RigidTransform& X1 = spec.parts[0].X_WP;
  const RigidTransform& X2 = spec.parts[1].X_WP;
  EXPECT_LT((X2 * Eigen::Vector3d(0, 0, -4) - X1 * Eigen::Vector3d(1, 2, 3)).norm(), 1e-9);
  // Square to the pinion's axis, toward its local y (polar 90 degrees from its local x).
  EXPECT_LT((X2.RotateDirection({0, 0, 1}) - X1.RotateDirection({0, 1, 0})).norm(), 1e-9);
  const std::vector<Pair> pairs = PairsOf(spec);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].type, PairType::kBevelGear);
  EXPECT_EQ(*pairs[0].ratio, Rational(-2));  // gear/teeth before pinion/teeth: -30/15
}

TEST(Placement, WormWheelAndRackMeshWithTheirPartners) {
  AssemblySpec spec;
  spec.parts.push_back(MakePart("worm",
                                {MakeFeature("w", FeatureKind::kWorm, {-10, 0, 0}, {1, 0, 0},
                                             [](Feature& f) {
                                               f.module = 1;
                                               f.pitch_diameter = 10;
                                               f.length = 20;
                                             }),
                                 Gear("pinion", 16, {0, 40, 0}, {0, 0, 1})},
                                RigidTransform(), true));
  spec.parts.push_back(MakePart(
      "wheel", {MakeFeature("t", FeatureKind::kWormWheel, {0, 0, 0}, {0, 0, 1}, [](Feature& f) {
        f.teeth = 30;
        f.module = 1;
        f.length = 6;
      })}));
  spec.parts.push_back(
      MakePart("rack", {MakeFeature("r", FeatureKind::kRack, {0, 0, 0}, {1, 0, 0}, [](Feature& f) {
                 f.module = 1;
                 f.length = 60;
                 f.normal = {0, 0, 1};
               })}));
  spec.parts[1].placement = {Condition(PlacementCondition::Kind::kMesh, 0, {0, 0}, 0.7)};
  spec.parts[2].placement = {Condition(PlacementCondition::Kind::kMesh, 0, {0, 1}, 2.0)};
  ResolvePlacements(&spec);
  std::vector<PairType> types;
  for (const Pair& p : PairsOf(spec)) types.push_back(p.type);
  std::sort(types.begin(), types.end());
  std::vector<PairType> expected = {PairType::kWormGear, PairType::kRackPinion};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(types, expected);
}

// A ground plate (a hole at (10, 0, 5) pointing down, its top at z = 5) and a bracket with a
// hole at (3, 0, 4) pointing down and its bottom at z = 0, to be placed.
AssemblySpec PlateAndBracket() {
  AssemblySpec spec;
  spec.parts.push_back(MakePart("plate",
                                {MakeFeature("hole", FeatureKind::kHole, {10, 0, 5}, {0, 0, -1},
                                             [](Feature& f) { f.length = 5; }),
                                 MakeFeature("top", FeatureKind::kFace, {0, 0, 5}, {0, 0, 1})},
                                RigidTransform(), true));
  spec.parts.push_back(
      MakePart("bracket", {MakeFeature("hole", FeatureKind::kHole, {3, 0, 4}, {0, 0, -1},
                                       [](Feature& f) { f.length = 4; }),
                           MakeFeature("bottom", FeatureKind::kFace, {0, 0, 0}, {0, 0, -1})}));
  return spec;
}

TEST(Placement, SeveralConditionsAreSolvedTogether) {
  AssemblySpec spec = PlateAndBracket();
  spec.parts[1].placement = {Condition(PlacementCondition::Kind::kInsert, 0, {0, 0}, 0.4),
                             Condition(PlacementCondition::Kind::kAgainst, 1, {0, 1})};
  ResolvePlacements(&spec);
  const RigidTransform& X = spec.parts[1].X_WP;
  // The bottom on z = 5, the holes on one axis, the turn about it kept from the insert (0.4
  // about the plate hole's axis, -z).
  EXPECT_NEAR((X * Eigen::Vector3d(0, 0, 0)).z(), 5.0, 1e-9);
  EXPECT_LT((X * Eigen::Vector3d(3, 0, 4) - Eigen::Vector3d(10, 0, 9)).norm(), 1e-9);
  EXPECT_NEAR(std::atan2(X.RotateDirection({1, 0, 0}).y(), X.RotateDirection({1, 0, 0}).x()), -0.4,
              1e-9);
}

TEST(Placement, UnsatisfiableConditionsAndImpossibleMeshesNameThePart) {
  AssemblySpec spec = PlateAndBracket();
  // 2 mm deep into the plate's hole, yet on the plate's top: 6 mm apart.
  spec.parts[1].placement = {Condition(PlacementCondition::Kind::kInsert, 0, {0, 0}, 0.0, 2.0),
                             Condition(PlacementCondition::Kind::kAgainst, 1, {0, 1})};
  try {
    ResolvePlacements(&spec);
    FAIL() << "the conditions contradict each other";
  } catch (const PlacementError& e) {
    EXPECT_EQ(e.part(), 1u);
    EXPECT_NE(std::string(e.what()).find("\"bracket\" cannot all hold"), std::string::npos)
        << e.what();
  }
  spec.parts[1].placement = {Condition(PlacementCondition::Kind::kMesh, 0, {0, 0})};
  try {
    ResolvePlacements(&spec);
    FAIL() << "a hole cannot mesh";
  } catch (const PlacementError& e) {
    EXPECT_EQ(e.part(), 1u);
    EXPECT_NE(std::string(e.what()).find("cannot mesh a hole with a hole"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace mechanist
