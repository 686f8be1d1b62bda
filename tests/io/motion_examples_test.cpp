// The examples' motion: the worm drive's back-drive, reversing a driver, a three-planet train.

#include <gtest/gtest.h>

#include "io/assembly_reader.h"
#include "reasoning/analysis.h"
#include "text_edit.h"

namespace mechanist {
namespace {

bool HasCode(const Analysis& an, const std::string& code) {
  for (const Diagnostic& d : an.diagnostics) {
    if (d.code == code) return true;
  }
  return false;
}

ExactReal Rate(const Assembly& a, const Analysis& an, const std::string& path) {
  const auto f = a.FindFeature(path);
  EXPECT_TRUE(f.has_value()) << path;
  return an.motion.ForExpectations()->features[f->part][f->feature].rotation;
}

std::string Exact(const ExactReal& r) {
  return r.is_exact() ? r.ToString() : "inexact " + r.ToString();
}

using testing::ReadText;
using testing::Replace;

const std::string kWorm =
    std::string(MECHANIST_SOURCE_DIR) + "/examples/robot_hand_worm/assembly.json";

TEST(Motion, SelfLockingWormCannotBeDrivenFromItsWheel) {
  const std::string text = Replace(ReadText(kWorm), R"("part": "motor_shaft", "feature": "shaft")",
                                   R"("part": "worm_wheel", "feature": "teeth")");
  const Assembly locked = ParseAssembly(text, kWorm);
  const Analysis an = Analyze(locked);
  ASSERT_EQ(an.motion.driven.size(), 2u);
  EXPECT_FALSE(an.motion.driven[0].possible);
  EXPECT_NE(an.motion.driven[0].reason.find("not back-drivable"), std::string::npos)
      << an.motion.driven[0].reason;
  // Without friction the lead angle exceeds the friction angle: the wheel drives the worm.
  const Assembly free =
      ParseAssembly(Replace(text, R"("friction": 0.15)", R"("friction": 0.01)"), kWorm);
  const Analysis an_free = Analyze(free);
  ASSERT_TRUE(an_free.motion.driven[0].possible) << an_free.motion.driven[0].reason;
  EXPECT_EQ(Exact(Rate(free, an_free, "worm/worm")), "-40");
}

TEST(Motion, ReversingTheDriverNegatesEveryRate) {
  const std::string path =
      std::string(MECHANIST_SOURCE_DIR) + "/examples/planetary_gear_set/assembly.json";
  const std::string text = ReadText(path);
  const Assembly forward = ParseAssembly(text, path);
  const Assembly backward = ParseAssembly(Replace(text, R"("rate": 1)", R"("rate": -1)"), path);
  const Analysis f = Analyze(forward), b = Analyze(backward);
  const DrivenMotion& mf = f.motion.driven.back();
  const DrivenMotion& mb = b.motion.driven.back();
  for (std::size_t p = 0; p < mf.features.size(); ++p) {
    for (std::size_t k = 0; k < mf.features[p].size(); ++k) {
      ASSERT_TRUE(mf.features[p][k].rotation.is_exact());
      EXPECT_EQ(*mb.features[p][k].rotation.exact(), -*mf.features[p][k].rotation.exact());
    }
  }
}

TEST(Motion, ThreePlanetsAreTwoRedundantConstraintsNotALock) {
  const std::string path =
      std::string(MECHANIST_SOURCE_DIR) + "/examples/planetary_gear_set/assembly.json";
  const Analysis an = Analyze(ReadAssembly(path));
  EXPECT_EQ(an.motion.mobility.dof, 1);
  EXPECT_EQ(an.motion.mobility.redundant, 2);
  EXPECT_FALSE(HasCode(an, "jam"));
}

}  // namespace
}  // namespace mechanist
