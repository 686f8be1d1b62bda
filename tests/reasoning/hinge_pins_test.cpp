// Hinge pins that the file leaves out, grouped from the implied-pin pairs: two wheels on the
// coaxial end holes of a frame whose ears stand apart with air between them ride one rod (the
// Onshape robot hand's ring and little fingers on one rod through the palm); with a web of the
// frame on the axis between the ears, each wheel has a stub pin of its own. The oracle is the
// construction: which part material lies on the axis.
#include "reasoning/hinge_pins.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "kernel/assembly/assembly_state.h"
#include "kernel/collision/collision_model.h"
#include "reasoning/analysis.h"
#include "test_assembly.h"

namespace mechanist {
namespace {

using V = Eigen::Vector3d;

Feature Hole(const char* id, double diameter, double z0, double z1) {
  return testing::MakeFeature(id, FeatureKind::kHole, V(5, 5, z0), V::UnitZ(), [&](Feature& f) {
    f.diameter = diameter, f.length = z1 - z0, f.through = true;
  });
}

// A ground frame with ears at z 0..5 and 35..40 (holes on the line x = y = 5) joined by a wall
// off the axis (x -5..0), and, when `web`, a block on the axis at z 10..30; a wheel below the
// lower ear and one above the upper, each with its hole on the same line.
Assembly Frame(bool web) {
  std::vector<std::pair<V, V>> frame = {
      {V(0, 0, 0), V(10, 10, 5)}, {V(0, 0, 35), V(10, 10, 40)}, {V(-5, 0, 0), V(0, 10, 40)}};
  if (web) frame.push_back({V(0, 0, 10), V(10, 10, 30)});
  Part f = testing::MakePart("frame", {Hole("ear_a", 3.45, 0, 5), Hole("ear_b", 3.45, 35, 40)},
                             RigidTransform(), true);
  f.mesh = testing::Boxes(frame);
  Part a = testing::MakePart("wheel_a", {Hole("bore", 3.2, -10, 0)});
  a.mesh = testing::Boxes({{V(0, 0, -10), V(10, 10, 0)}});
  Part b = testing::MakePart("wheel_b", {Hole("bore", 3.2, 40, 50)});
  b.mesh = testing::Boxes({{V(0, 0, 40), V(10, 10, 50)}});
  return testing::MakeAssembly({f, a, b});
}

std::vector<HingePin> PinsOf(const Assembly& a) {
  return FindHingePins(a, Analyze(a), InitialState(a), CollisionModel(a));
}

std::vector<std::string> HoleNames(const Assembly& a, const HingePin& pin) {
  std::vector<std::string> names;
  for (const FeatureRef& h : pin.holes) names.push_back(a.FeatureName(h));
  return names;
}

TEST(HingePins, EarsWithAirBetweenCarryOneRod) {
  const Assembly open = Frame(false);
  const std::vector<HingePin> pins = PinsOf(open);
  ASSERT_EQ(pins.size(), 1u);
  EXPECT_EQ(HoleNames(open, pins[0]), (std::vector<std::string>{"frame/ear_a", "frame/ear_b",
                                                                "wheel_a/bore", "wheel_b/bore"}));
  EXPECT_DOUBLE_EQ(pins[0].diameter, 3.2);
  EXPECT_TRUE(pins[0].ends_W[0].isApprox(V(5, 5, -10), 1e-12));
  EXPECT_TRUE(pins[0].ends_W[1].isApprox(V(5, 5, 50), 1e-12));
  EXPECT_EQ(pins[0].parts.size(), 3u);
}

TEST(HingePins, AWebOnTheAxisBetweenTheHolesMakesTwoPins) {
  const Assembly webbed = Frame(true);
  const std::vector<HingePin> pins = PinsOf(webbed);
  ASSERT_EQ(pins.size(), 2u);
  EXPECT_EQ(HoleNames(webbed, pins[0]), (std::vector<std::string>{"frame/ear_a", "wheel_a/bore"}));
  EXPECT_EQ(HoleNames(webbed, pins[1]), (std::vector<std::string>{"frame/ear_b", "wheel_b/bore"}));
  EXPECT_TRUE(pins[0].ends_W[1].isApprox(V(5, 5, 5), 1e-12));
}

}  // namespace
}  // namespace mechanist
