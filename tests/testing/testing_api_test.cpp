// The C++ mechanism-testing API, used as a GoogleTest user would.

#include <gtest/gtest.h>

#include "mechanist/testing.h"

namespace mechanist {
namespace {

using mechanist::testing::Mechanism;

std::string Example(const std::string& name) {
  return std::string(MECHANIST_SOURCE_DIR) + "/examples/" + name + "/assembly.json";
}

TEST(TestingApi, ExamplesReadLikeTheirReadmes) {
  const Mechanism hand = Mechanism::Load(Example("robot_hand_worm"));
  EXPECT_TRUE(HasRatio(hand, "worm_wheel/teeth", "-1/40"));
  EXPECT_TRUE(HasRatio(hand, "worm_wheel/teeth", "-0.025"));
  EXPECT_TRUE(HasPair(hand, "worm_wheel/teeth", "worm/worm", PairType::kWormGear));
  EXPECT_TRUE(HasMobility(hand, 1));
  EXPECT_TRUE(InSameSubassembly(hand, {"motor_shaft", "worm_sleeve", "setscrew", "worm"}));
  EXPECT_TRUE(Moves(hand, "worm_wheel"));
  EXPECT_TRUE(Moves(hand, "housing", false));
  const Mechanism planets = Mechanism::Load(Example("planetary_gear_set"));
  EXPECT_TRUE(HasRatio(planets, "carrier/center", "1/3"));
  EXPECT_TRUE(HasDiagnostic(planets, "redundant_constraints", {"planet_2", "sun"}));
  const Mechanism differential = Mechanism::Load(Example("bevel_differential_sketch"));
  EXPECT_TRUE(HasPair(differential, "right_gear/teeth", "pinion/teeth", PairType::kBevelGear));
  EXPECT_FALSE(HasPair(differential, "left_gear/teeth", "right_gear/teeth"));
  EXPECT_TRUE(HasRatio(differential, "right_gear/teeth", "2"));
  EXPECT_TRUE(HasMobility(differential, 2));
  EXPECT_TRUE(IsAssemblable(hand));
  const ::testing::AssertionResult not_expected = IsAssemblable(hand, false);
  EXPECT_FALSE(not_expected);
  EXPECT_NE(std::string(not_expected.message()).find("found assemblable"), std::string::npos)
      << not_expected.message();
}

TEST(TestingApi, FailuresSayWhatWasFound) {
  const Mechanism hand = Mechanism::Load(Example("robot_hand_worm"));
  const ::testing::AssertionResult wrong = HasRatio(hand, "worm_wheel/teeth", "1/40");
  EXPECT_FALSE(wrong);
  EXPECT_NE(std::string(wrong.message()).find("found -1/40"), std::string::npos) << wrong.message();
  const ::testing::AssertionResult missing = HasMobility(hand, 2);
  EXPECT_FALSE(missing);
  EXPECT_NE(std::string(missing.message()).find("found 1"), std::string::npos);
  EXPECT_FALSE(HasRatio(hand, "worm_wheel/nothing", "1"));
  EXPECT_FALSE(Moves(hand, "no_such_part"));
  EXPECT_FALSE(HasRatio(hand, "worm_wheel/teeth", "one fortieth"));
}

}  // namespace
}  // namespace mechanist
