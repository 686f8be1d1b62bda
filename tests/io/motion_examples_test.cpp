// The examples' motion: the worm drive's back-drive, reversing a driver, a three-planet train.

#include <gtest/gtest.h>

#include "io/load_assembly.h"
#include "kernel/collision/collision_model.h"
#include "reasoning/analysis.h"
#include "reasoning/motion_run.h"
#include "reasoning/operation_check.h"
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
  const Assembly locked = LoadAssemblyText(text, kWorm);
  const Analysis an = Analyze(locked);
  ASSERT_EQ(an.motion.driven.size(), 1u);
  EXPECT_FALSE(an.motion.driven[0].possible);
  EXPECT_NE(an.motion.driven[0].reason.find("not back-drivable"), std::string::npos)
      << an.motion.driven[0].reason;
  // Without friction the lead angle exceeds the friction angle: the wheel drives the worm.
  const Assembly free =
      LoadAssemblyText(Replace(text, R"("friction": 0.15)", R"("friction": 0.01)"), kWorm);
  const Analysis an_free = Analyze(free);
  ASSERT_TRUE(an_free.motion.driven[0].possible) << an_free.motion.driven[0].reason;
  EXPECT_EQ(Exact(Rate(free, an_free, "worm/worm")), "-40");
}

TEST(Motion, ReversingTheDriverNegatesEveryRate) {
  const std::string path =
      std::string(MECHANIST_SOURCE_DIR) + "/examples/planetary_gear_set/assembly.json";
  const std::string text = ReadText(path);
  const Assembly forward = LoadAssemblyText(text, path);
  const Assembly backward = LoadAssemblyText(Replace(text, R"("rate": 1)", R"("rate": -1)"), path);
  const Analysis f = Analyze(forward), b = Analyze(backward);
  // The reported ratios are per unit driver rate, the same whichever way the driver turns.
  ASSERT_EQ(f.motion.driven.size(), 1u);
  ASSERT_EQ(b.motion.driven.size(), 1u);
  const DrivenMotion& mf = f.motion.driven.front();
  const DrivenMotion& mb = b.motion.driven.front();
  for (std::size_t p = 0; p < mf.features.key_count(); ++p) {
    for (std::size_t k = 0; k < mf.features[p].size(); ++k) {
      ASSERT_TRUE(mf.features[p][k].rotation.is_exact());
      EXPECT_EQ(*mb.features[p][k].rotation.exact(), *mf.features[p][k].rotation.exact());
    }
  }
  // The run goes the other way: every joint screw of every part at the negated rate.
  const MotionRun rf = PlanRun(forward, f, std::nullopt, std::nullopt);
  const MotionRun rb = PlanRun(backward, b, std::nullopt, std::nullopt);
  std::size_t turning = 0;
  for (std::size_t p = 0; p < forward.parts().size(); ++p) {
    const std::vector<ScrewMotion>& sf = rf.paths[p].screws;
    const std::vector<ScrewMotion>& sb = rb.paths[p].screws;
    ASSERT_EQ(sf.size(), sb.size()) << forward.part(p).id;
    for (std::size_t k = 0; k < sf.size(); ++k) {
      EXPECT_EQ(sb[k].axis_W, sf[k].axis_W) << forward.part(p).id;
      EXPECT_EQ(sb[k].turns_per_unit, -sf[k].turns_per_unit) << forward.part(p).id;
      EXPECT_EQ(sb[k].travel_per_unit, -sf[k].travel_per_unit) << forward.part(p).id;
      turning += sf[k].turns_per_unit != 0.0;
    }
  }
  EXPECT_GE(turning, 5u);  // the sun, three planets and the carrier
}

TEST(Motion, ThreePlanetsAreTwoRedundantConstraintsNotALock) {
  const std::string path =
      std::string(MECHANIST_SOURCE_DIR) + "/examples/planetary_gear_set/assembly.json";
  const Analysis an = Analyze(LoadAssembly(path));
  EXPECT_EQ(an.motion.mobility.dof, 1);
  EXPECT_EQ(an.motion.mobility.redundant, 2);
  EXPECT_FALSE(HasCode(an, "jam"));
}

// The finite path of a planet: it orbits with the carrier (sun 20, ring 40 fixed: the carrier
// turns 1/3 of the sun) and turns -1 revolution per sun revolution about its own centre
// (Willis: 1/3 - (20/10)(1 - 1/3)); the path must place it exactly there.
TEST(Motion, PlanetPathOrbitsWithTheCarrierAndSpinsOnItsPin) {
  const std::string path =
      std::string(MECHANIST_SOURCE_DIR) + "/examples/planetary_gear_set/assembly.json";
  const Assembly a = LoadAssembly(path);
  const Analysis an = Analyze(a);
  const std::size_t planet = *a.FindPart("planet_1");
  const ScrewPath& p = an.motion.ForExpectations()->parts[planet].path;
  ASSERT_EQ(p.screws.size(), 2u) << "carrier about the axle, planet about its pin";
  const double kPi = 3.14159265358979323846;
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  for (const double s : {0.1, 0.37, 0.75, 1.0, 2.5}) {
    const RigidTransform expected =
        RigidTransform::AxisAngleAbout(Eigen::Vector3d::Zero(), z, 2 * kPi * s / 3) *
        RigidTransform::AxisAngleAbout({15, 0, 0}, z, 2 * kPi * (-1 - 1.0 / 3) * s);
    EXPECT_TRUE(p.At(s).IsNearlyEqualTo(expected, 1e-9, 1e-9)) << "s = " << s;
  }
  // A part on a fixed axis has a single screw: the sun turns once per unit.
  const ScrewPath& sun = an.motion.ForExpectations()->parts[*a.FindPart("sun")].path;
  ASSERT_EQ(sun.screws.size(), 1u);
  EXPECT_NEAR(sun.screws[0].turns_per_unit * sun.screws[0].axis_W.z(), 1.0, 1e-12);
}

// A post in the planets' orbit: the running mechanism's sweep finds the first planet to reach
// it where the orbit geometry says (centres 15 mm from the axis, the post 60 degrees round,
// tip radius 6 and post radius 2: 2 * 15 * sin(a / 2) = 8 at a carrier angle a short of 60).
TEST(Motion, SweepFindsAPlanetHittingAPostInItsOrbit) {
  const std::string path =
      std::string(MECHANIST_SOURCE_DIR) + "/examples/planetary_gear_set/assembly.json";
  const std::string with_post = Replace(ReadText(path), R"(    {"id": "sun",)",
                                        R"(    {"id": "post", "ground": true,
     "library": {"kind": "shaft", "diameter": 4, "length": 8, "segments": 48},
     "pose": {"position": [7.5, 12.990381056766580, 1]}},
    {"id": "sun",)");
  const Assembly a = LoadAssemblyText(with_post, path);
  const Analysis an = Analyze(a);
  const OperationCheck check = CheckOperation(a, an, CollisionModel(a), std::nullopt, 0.5);
  ASSERT_FALSE(check.clashes.empty());
  const OperationClash& first = check.clashes.front();
  EXPECT_EQ(a.part(first.part_a).id + "+" + a.part(first.part_b).id, "planet_1+post");
  const double kPi = 3.14159265358979323846;
  const double carrier_angle = kPi / 3 - 2 * std::asin(8.0 / 30.0);
  const double expected = carrier_angle / (2 * kPi) * 3;  // the carrier turns 1/3 of the sun
  // Teeth: the tips reach radius 6 only on a tooth, so the contact can come a little later.
  EXPECT_GE(first.at, expected - 1e-3);
  EXPECT_LE(first.at, expected + 0.02);
}

// The seeds' case: shaft d's lug meets block b, which (clamped to shaft a with nut c) nothing
// drives: b is carried along, and a, b, c and d then turn together. The lug (radius 2, 25 from
// the axis, starting at -90 degrees) reaches b's side (y = -5) when its centre is at y = -7.
TEST(Motion, SweepCarriesAFreePartThatIsPushed) {
  const std::string path =
      std::string(MECHANIST_SOURCE_DIR) + "/examples/pushed_by_contact/assembly.json";
  const Assembly a = LoadAssembly(path);
  const Analysis an = Analyze(a);
  EXPECT_EQ(an.motion.mobility.dof, 2) << "the driver's freedom and the free a, b, c";
  const OperationCheck check = CheckOperation(a, an, CollisionModel(a), std::nullopt, std::nullopt);
  EXPECT_TRUE(check.clashes.empty());
  ASSERT_EQ(check.inferred.size(), 1u);
  const InferredCoupling& push = check.inferred.front();
  EXPECT_EQ(a.part(push.pusher).id, "lug");
  EXPECT_EQ(a.part(push.pushed).id, "b");
  EXPECT_TRUE(push.carried);
  const double kPi = 3.14159265358979323846;
  EXPECT_NEAR(push.at, (kPi / 2 - std::asin(7.0 / 25.0)) / (2 * kPi), 2e-3);
  ASSERT_TRUE(check.after.has_value());
  EXPECT_EQ(check.after->motion.mobility.dof, 1);
  const DrivenMotion* after = check.after->motion.ForExpectations();
  const auto shaft = a.FindFeature("a/shaft");
  EXPECT_EQ(Exact(after->features[shaft->part][shaft->feature].rotation), "1");
}

// A ram driven down the axis of a shaft that turns freely in its bearing: the push has nothing
// along the shaft's only freedom (a turn), so the drive jams at the contact, 8 mm down.
TEST(Motion, SweepFindsAJamWhenThePushCannotBeYielded) {
  const std::string text = R"({"mechanist": 1, "parts": [
    {"id": "base", "ground": true,
     "library": {"kind": "plate", "length": 60, "width": 60, "thickness": 5,
                 "holes": [{"id": "bearing", "at": [0, 0], "diameter": 8.02}]}},
    {"id": "guide", "ground": true,
     "library": {"kind": "plate", "length": 60, "width": 60, "thickness": 5,
                 "holes": [{"id": "bore", "at": [0, 0], "diameter": 10.02}]},
     "pose": {"position": [0, 0, 35]}},
    {"id": "shaft", "library": {"kind": "shaft", "diameter": 8, "length": 30, "retained": true},
     "pose": {"position": [0, 0, -10]}},
    {"id": "ram", "library": {"kind": "shaft", "diameter": 10, "length": 15},
     "pose": {"position": [0, 0, 43], "rotation": {"axis": [1, 0, 0], "angle": 180}}}],
    "drivers": [{"id": "press", "part": "ram", "feature": "shaft", "motion": "translation",
                 "amount": 10}]})";
  const Assembly a = LoadAssemblyText(text, "ram.json");
  const Analysis an = Analyze(a);
  const OperationCheck check = CheckOperation(a, an, CollisionModel(a), std::nullopt, std::nullopt);
  ASSERT_EQ(check.inferred.size(), 1u);
  EXPECT_FALSE(check.inferred.front().carried);
  EXPECT_NEAR(check.inferred.front().at, 8.0, 0.06);
  EXPECT_FALSE(check.after.has_value());
  EXPECT_EQ(check.amount, 10.0);
  // The same in centimetres: the driver's amount and the contact in the file's units.
  std::string cm = text;
  cm.replace(cm.find(R"({"mechanist": 1,)"), 16, R"({"mechanist": 1, "units": {"length": "cm"},)");
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {R"("length": 60, "width": 60, "thickness": 5)",
            R"("length": 6, "width": 6, "thickness": 0.5)"},
           {R"("diameter": 8.02)", R"("diameter": 0.802)"},
           {R"("diameter": 10.02)", R"("diameter": 1.002)"},
           {R"([0, 0, 35])", R"([0, 0, 3.5])"},
           {R"("diameter": 8, "length": 30)", R"("diameter": 0.8, "length": 3)"},
           {R"([0, 0, -10])", R"([0, 0, -1])"},
           {R"("diameter": 10, "length": 15)", R"("diameter": 1, "length": 1.5)"},
           {R"([0, 0, 43])", R"([0, 0, 4.3])"},
           {R"("amount": 10)", R"("amount": 1)"}}) {
    for (auto at = cm.find(from); at != std::string::npos; at = cm.find(from, at + to.size())) {
      cm.replace(at, from.size(), to);
    }
  }
  const Assembly b = LoadAssemblyText(cm, "ram_cm.json");
  const OperationCheck in_cm =
      CheckOperation(b, Analyze(b), CollisionModel(b), std::nullopt, std::nullopt);
  EXPECT_DOUBLE_EQ(in_cm.amount, 1.0);
  ASSERT_EQ(in_cm.inferred.size(), 1u);
  EXPECT_NEAR(in_cm.inferred.front().at, 0.8, 0.006);
}

}  // namespace
}  // namespace mechanist
