// Adjustments solved on the robot hand's worm drive with its motor swung out of mesh, checked
// against the drive's plane geometry: swinging the motor by phi about +z through bolt a at
// (-35, -20) puts the worm's axis (through (-15, -25) along x before the swing) at
// 20 cos(phi) - 35 sin(phi) + 5 mm from the wheel's axis; the file swings it by -3 degrees.

#include "reasoning/adjustment.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "io/adjusted_file_writer.h"
#include "io/adjustment_report.h"
#include "io/input_error.h"
#include "io/load_assembly.h"
#include "reasoning/analysis.h"
#include "text_edit.h"

namespace mechanist {
namespace {

using testing::ReadText;
using testing::Replace;

const std::string kSwung =
    std::string(MECHANIST_SOURCE_DIR) + "/examples/robot_hand_worm_adjust/assembly.json";
const std::string kWorm =
    std::string(MECHANIST_SOURCE_DIR) + "/examples/robot_hand_worm/assembly.json";

double Deg(double d) { return d * M_PI / 180.0; }

// The worm's distance from the wheel's axis after a net swing phi about +z.
double WormDistance(double phi) { return 20 * std::cos(phi) - 35 * std::sin(phi) + 5; }

AdjustmentSummary Solve(const Assembly& a) { return SolveAdjustments(a, Analyze(a).pairs); }

TEST(Adjustment, SwingsTheMotorUntilTheWormMeshesAndTheWheelTurns) {
  const Assembly swung = LoadAssembly(kSwung);
  const AdjustmentSummary s = Solve(swung);
  EXPECT_EQ(s.solver.status, LeastSquaresSummary::Status::kConverged) << s.solver.message;
  ASSERT_EQ(s.adjustments.size(), 1u);
  EXPECT_TRUE(s.adjustments[0].used);
  // The hole's axis points down: -3 degrees about it is +3 about +z, undoing the swing.
  EXPECT_NEAR(s.adjustments[0].value, Deg(-3.0), 1e-9);
  EXPECT_EQ(s.adjustments[0].active, AdjustmentOutcome::Bound::kNone);
  EXPECT_NEAR(s.before[0].distance, WormDistance(Deg(-3.0)) - 25.0, 1e-9);
  EXPECT_FALSE(s.before[0].met);
  EXPECT_TRUE(s.after[0].met);
  EXPECT_NEAR(s.after[0].distance, 0.0, 1e-9);
  EXPECT_TRUE(s.all_met);
  // The motor and what it holds move; the housing and the wheel stay.
  std::vector<std::string> carried;
  for (const std::size_t p : s.adjustments[0].carried) carried.push_back(swung.part(p).id);
  EXPECT_EQ(carried, (std::vector<std::string>{"motor_body", "bolt_a", "bolt_b", "motor_shaft",
                                               "worm_sleeve", "worm", "setscrew"}));
  // Locked, the drive is the original example's: the worm gear pair and its exact ratio.
  const Assembly adjusted = ApplyAdjustments(swung, s);
  const Assembly original = LoadAssembly(kWorm);
  for (std::size_t p = 0; p < adjusted.parts().size(); ++p) {
    EXPECT_TRUE(adjusted.part(p).X_WP.IsNearlyEqualTo(original.part(p).X_WP, 1e-6, 1e-8))
        << adjusted.part(p).id;
  }
  const Analysis an = Analyze(adjusted);
  const auto wheel = adjusted.FindFeature("worm_wheel/teeth");
  EXPECT_EQ(an.motion.ForExpectations()->features[wheel->part][wheel->feature].rotation.ToString(),
            "-1/40");
  EXPECT_NEAR(adjusted.adjustments()[0].lower, Deg(-7.0), 1e-9);
  EXPECT_NEAR(adjusted.adjustments()[0].upper, Deg(13.0), 1e-9);
}

TEST(Adjustment, AnInfeasibleGoalStopsAtTheBoundAndTheNearMissSuggestsTheAdjustment) {
  const Assembly a = LoadAssemblyText(
      Replace(ReadText(kSwung), R"("range": [-10, 10])", R"("range": [-2.5, 10])"), kSwung);
  const AdjustmentSummary s = Solve(a);
  EXPECT_NEAR(s.adjustments[0].value, Deg(-2.5), 1e-9);
  EXPECT_EQ(s.adjustments[0].active, AdjustmentOutcome::Bound::kLower);
  EXPECT_FALSE(s.all_met);
  EXPECT_FALSE(s.after[0].met);
  // Net swing -0.5 degrees about +z.
  EXPECT_NEAR(s.after[0].distance, WormDistance(Deg(-0.5)) - 25.0, 1e-9);
  std::ostringstream text;
  WriteAdjustmentSummary(a, s, text);
  EXPECT_NE(text.str().find("NOT met"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("motor_swing is held at its lower bound"), std::string::npos)
      << text.str();
  // 0.3 mm off is a near miss; the diagnostic names the adjustment that can fix it.
  const Analysis an = Analyze(ApplyAdjustments(a, s));
  bool suggested = false;
  for (const Diagnostic& d : an.diagnostics) {
    suggested =
        suggested || (d.code == "worm_center_distance" &&
                      d.message.find("adjustment motor_swing can fix this") != std::string::npos);
  }
  EXPECT_TRUE(suggested);
}

TEST(Adjustment, AGoalAlreadyMetStaysAndASpareAdjustmentIsLeftAlone) {
  const std::string text = Replace(ReadText(kWorm), R"(  "drivers": [)", R"(  "adjustments": [
    {"id": "motor_swing", "moves": "motor_body", "rotate_about": "housing/motor_hole_a",
     "range": [-10, 10]},
    {"id": "whole_shift", "moves": "housing", "translate_along": "housing/wheel_bearing",
     "range": [-2, 2]}],
  "goals": [{"mesh": ["worm_wheel/teeth", "worm/worm"]}],
  "drivers": [)");
  const Assembly a = LoadAssemblyText(text, kWorm);
  const AdjustmentSummary s = Solve(a);
  EXPECT_TRUE(s.before[0].met);
  EXPECT_TRUE(s.all_met);
  EXPECT_NEAR(s.adjustments[0].value, 0.0, 1e-9);
  // Moving the housing carries the motor and the wheel alike: no goal depends on it.
  EXPECT_FALSE(s.adjustments[1].used);
  EXPECT_EQ(s.adjustments[1].value, 0.0);
  std::ostringstream out;
  WriteAdjustmentSummary(a, s, out);
  EXPECT_NE(out.str().find("whole_shift: translate housing along housing/wheel_bearing: no goal "
                           "depends on it, left at 0"),
            std::string::npos)
      << out.str();
}

TEST(Adjustment, SwingsABevelGearUntilItsAxisMeetsThePinionsAtTheSumOfThePitchAngles) {
  // A 15-tooth pinion up +z and a 30-tooth gear tilted 85 degrees from it about y: square
  // shafts need 90 (atan(1/2) + atan(2)). Swinging the gear about +y through the common apex
  // by +5 degrees meets the goal.
  const double tilt = Deg(85);
  const std::string text = fmt::format(R"({{"mechanist": 1, "parts": [
    {{"id": "frame", "ground": true, "features": [
      {{"id": "pinion", "kind": "bevel_gear", "origin": [0, 0, 0], "axis": [0, 0, 1],
       "teeth": 15, "module": 2, "pitch_angle": {}, "length": 6}},
      {{"id": "pivot", "kind": "hole", "origin": [0, 0, 0], "axis": [0, 1, 0], "diameter": 5,
       "length": 5}}]}},
    {{"id": "gear", "features": [
      {{"id": "teeth", "kind": "bevel_gear", "origin": [0, 0, 0], "axis": [{}, 0, {}],
       "teeth": 30, "module": 2, "pitch_angle": {}, "length": 6}}]}}],
  "adjustments": [{{"id": "swing", "moves": "gear", "rotate_about": "frame/pivot",
                   "range": [-10, 10]}}],
  "goals": [{{"mesh": ["gear/teeth", "frame/pinion"]}}]}})",
                                       std::atan(0.5) * 180 / M_PI, std::sin(tilt), std::cos(tilt),
                                       std::atan(2.0) * 180 / M_PI);
  const Assembly a = LoadAssemblyText(text, kWorm);
  const AdjustmentSummary s = Solve(a);
  EXPECT_FALSE(s.before[0].met);
  EXPECT_NEAR(s.before[0].angle, Deg(5), 1e-9);
  ASSERT_TRUE(s.all_met);
  EXPECT_NEAR(s.adjustments[0].value, Deg(5), 1e-9);
  const Analysis an = Analyze(ApplyAdjustments(a, s));
  ASSERT_EQ(an.pairs.size(), 1u);
  EXPECT_EQ(an.pairs[0].type, PairType::kBevelGear);
  std::ostringstream out;
  WriteAdjustmentSummary(a, s, out);
  EXPECT_NE(out.str().find("apexes apart by 0.0000 mm, axes off by 5.0000 deg"), std::string::npos)
      << out.str();
}

TEST(Adjustment, SeveralAdjustmentsWorkTogether) {
  // Lifting the wheel along its axis only moves its mid-plane off the worm's axis: the swing
  // does the work and the lift stays at zero.
  const std::string text = Replace(ReadText(kSwung), R"("range": [-10, 10]}
  ],)",
                                   R"("range": [-10, 10]},
    {"id": "wheel_lift", "moves": "wheel_shaft", "translate_along": "housing/wheel_bearing",
     "range": [-1, 1]}
  ],)");
  const Assembly a = LoadAssemblyText(text, kSwung);
  const AdjustmentSummary s = Solve(a);
  ASSERT_EQ(s.adjustments.size(), 2u);
  EXPECT_TRUE(s.adjustments[0].used && s.adjustments[1].used);
  EXPECT_NEAR(s.adjustments[0].value, Deg(-3.0), 1e-8);
  EXPECT_NEAR(s.adjustments[1].value, 0.0, 1e-8);
  EXPECT_TRUE(s.all_met);
  std::vector<std::string> lifted;
  for (const std::size_t p : s.adjustments[1].carried) lifted.push_back(a.part(p).id);
  EXPECT_EQ(lifted, (std::vector<std::string>{"worm_wheel", "wheel_shaft"}));
}

TEST(Adjustment, ConflictingGoalsAreReportedAsNotMet) {
  // Bolt b's hole moved 1 mm: lining bolt b up with it asks for another swing than the mesh.
  std::string text = Replace(ReadText(kSwung), R"("at": [-15, -15], "diameter": 5)",
                             R"("at": [-15, -14], "diameter": 5)");
  text = Replace(text, R"("goals": [{"mesh": ["worm/worm", "worm_wheel/teeth"]}])",
                 R"("goals": [{"mesh": ["worm/worm", "worm_wheel/teeth"]},
            {"coaxial": ["housing/motor_hole_b", "bolt_b/thread"]}])");
  const AdjustmentSummary s = Solve(LoadAssemblyText(text, kSwung));
  EXPECT_NE(s.solver.status, LeastSquaresSummary::Status::kFailure) << s.solver.message;
  EXPECT_FALSE(s.all_met);
  EXPECT_FALSE(s.after[0].met && s.after[1].met);
  EXPECT_EQ(s.adjustments[0].active, AdjustmentOutcome::Bound::kNone);  // a compromise
}

TEST(Adjustment, TheAdjustedFileReadsBackAsTheAdjustedAssembly) {
  const Assembly swung = LoadAssembly(kSwung);
  const AdjustmentSummary s = Solve(swung);
  const Assembly adjusted = ApplyAdjustments(swung, s);
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / "mechanist_adjust_test" / "adjusted.json";
  std::filesystem::create_directories(out.parent_path());
  const std::string text = AdjustedAssemblyText(swung, adjusted, out);
  const Assembly again = LoadAssemblyText(text, out);
  for (std::size_t p = 0; p < adjusted.parts().size(); ++p) {
    EXPECT_TRUE(again.part(p).X_WP.IsNearlyEqualTo(adjusted.part(p).X_WP, 1e-9, 1e-9))
        << adjusted.part(p).id;
  }
  EXPECT_NEAR(again.adjustments()[0].lower, adjusted.adjustments()[0].lower, 1e-9);
  // Solving the written file again finds nothing left to do.
  const AdjustmentSummary none = Solve(again);
  EXPECT_TRUE(none.before[0].met);
  EXPECT_NEAR(none.adjustments[0].value, 0.0, 1e-9);
}

TEST(Adjustment, LockingTightensTheLooseBoltTheMotorSwungOn) {
  // The motor hung on bolt a alone, loosely fastened so that it can be swung (Abe et al.,
  // section 3.5); bolt b sits in its wide hole and holds nothing to the housing. Locked, the
  // loose bolt is taken as tightened: it clamps the motor to the housing, which then carries
  // both the worm's and the wheel's axes.
  const std::string text = Replace(ReadText(kSwung), R"("pitch": 0.5, "length": 12},)",
                                   R"("pitch": 0.5, "length": 12, "fastening": "loose"},)");
  const Assembly swung = LoadAssemblyText(text, kSwung);
  const AdjustmentSummary s = Solve(swung);
  ASSERT_TRUE(s.all_met);
  ASSERT_EQ(s.adjustments[0].loosened.size(), 1u);
  EXPECT_EQ(swung.FeatureName(s.adjustments[0].loosened[0]), "bolt_a/thread");
  std::ostringstream report;
  WriteAdjustmentSummary(swung, s, report);
  EXPECT_NE(report.str().find("; locked, tightens bolt_a/thread"), std::string::npos)
      << report.str();
  const Assembly adjusted = ApplyAdjustments(swung, s);
  EXPECT_EQ(adjusted.feature(s.adjustments[0].loosened[0]).fastening, Fastening::kTight);
  const Analysis an = Analyze(adjusted);
  const auto wheel = adjusted.FindFeature("worm_wheel/teeth");
  EXPECT_EQ(an.motion.ForExpectations()->features[wheel->part][wheel->feature].rotation.ToString(),
            "-1/40");
  bool said = false;
  for (const Diagnostic& d : an.diagnostics) {
    EXPECT_NE(d.code, "coupling_without_carrier") << d.message;
    if (d.code == "adjustment_locked") {
      said = true;
      EXPECT_EQ(d.severity, Severity::kInfo);
      EXPECT_NE(d.message.find("motor_swing"), std::string::npos) << d.message;
      EXPECT_NE(d.message.find("bolt_a/thread is taken as tightened"), std::string::npos)
          << d.message;
    }
  }
  EXPECT_TRUE(said);
  // The written file has the bolt tight, and reads back as the locked assembly.
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / "mechanist_adjust_test" / "locked.json";
  std::filesystem::create_directories(out.parent_path());
  const Assembly again = LoadAssemblyText(AdjustedAssemblyText(swung, adjusted, out), out);
  EXPECT_EQ(again.feature(*again.FindFeature("bolt_a/thread")).fastening, Fastening::kTight);
  const Analysis an_again = Analyze(again);
  EXPECT_EQ(
      an_again.motion.ForExpectations()->features[wheel->part][wheel->feature].rotation.ToString(),
      "-1/40");
}

TEST(Adjustment, GoalsMustNameFeaturesThatCanMesh) {
  const std::string text =
      Replace(ReadText(kSwung), R"("goals": [{"mesh": ["worm/worm", "worm_wheel/teeth"]}])",
              R"("goals": [{"mesh": ["worm/worm", "wheel_shaft/shaft"]}])");
  try {
    LoadAssemblyText(text, kSwung);
    FAIL() << "a worm cannot mesh a shaft";
  } catch (const InputError& e) {
    EXPECT_EQ(e.pointer(), "/goals/0/mesh");
    EXPECT_NE(std::string(e.what()).find("worm and shaft"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mechanist
