// The frame implied for gears exported alone (no frame, shafts or pins): an axle through each
// gear's bore on a features-only ground part, and a revolute pair on it; nothing when a part
// is ground, a shaft fills a bore, or a part carries no gear.

#include "reasoning/implied_frame.h"

#include <gtest/gtest.h>

#include "reasoning/analysis.h"
#include "test_assembly.h"

namespace mechanist {
namespace {

using testing::MakeFeature;
using testing::MakePart;

// A spur gear of `teeth`, module 2, 10 mm wide, about part z, with a bore of `bore` mm.
Part Gear(const std::string& id, int teeth, double bore, const Eigen::Vector3d& p_WO) {
  return MakePart(
      id,
      {MakeFeature("teeth", FeatureKind::kGear, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                   [&](Feature& f) {
                     f.teeth = teeth;
                     f.module = 2.0;
                     f.length = 10.0;
                   }),
       MakeFeature("bore", FeatureKind::kHole, Eigen::Vector3d(0, 0, -5), Eigen::Vector3d::UnitZ(),
                   [&](Feature& f) {
                     f.diameter = bore;
                     f.length = 10.0;
                   })},
      RigidTransform::Translation(p_WO));
}

AssemblySpec TwoGears() {
  AssemblySpec spec;
  spec.name = "gears alone";
  spec.parts = {Gear("gear", 40, 20.0, Eigen::Vector3d::Zero()),
                Gear("pinion", 20, 12.0, Eigen::Vector3d(60, 0, 0))};
  return spec;
}

TEST(ImplyGearFrame, HoldsEachGearOnAnAxleThroughItsBore) {
  AssemblySpec spec = TwoGears();
  const std::vector<Diagnostic> found = ImplyGearFrame(&spec);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].code, "implied_frame");
  EXPECT_EQ(found[0].severity, Severity::kInfo);
  EXPECT_EQ(found[0].parts, (std::vector<std::string>{"gear", "pinion", "implied_frame"}));
  EXPECT_NE(found[0].message.find("'pinion' (12 mm bore)"), std::string::npos) << found[0].message;
  ASSERT_EQ(spec.parts.size(), 3u);
  const Part& frame = spec.parts[2];
  EXPECT_EQ(frame.id, "implied_frame");
  EXPECT_TRUE(frame.ground);
  EXPECT_FALSE(frame.HasGeometry());
  ASSERT_EQ(frame.features.size(), 2u);
  const Feature& axle = frame.features[1];
  EXPECT_EQ(axle.id, "axle_2");
  EXPECT_EQ(axle.kind, FeatureKind::kShaft);
  EXPECT_EQ(axle.diameter, 12.0);
  EXPECT_TRUE(axle.origin.isApprox(Eigen::Vector3d(60, 0, -5)));
  EXPECT_TRUE(axle.axis.isApprox(Eigen::Vector3d::UnitZ()));
  ASSERT_EQ(spec.overrides.size(), 2u);
  EXPECT_EQ(spec.overrides[1].features[0], FeatureRef(2, 1));
  EXPECT_EQ(spec.overrides[1].features[1], FeatureRef(1, 1));
  EXPECT_EQ(spec.overrides[1].type, PairType::kRevolute);
  EXPECT_TRUE(spec.overrides[1].implied_frame);

  // The train then moves as its frame would let it: one freedom, the gear pair at -2 from
  // the gear to the pinion (-z_gear / z_pinion), each gear on its axle.
  const Analysis an = Analyze(Assembly(std::move(spec)));
  EXPECT_EQ(an.motion.mobility.dof, 1);
  int revolutes = 0, gears = 0;
  for (const Pair& p : an.pairs) {
    if (p.type == PairType::kRevolute) {
      ++revolutes;
      EXPECT_EQ(p.source, PairSource::kImpliedFrame);
    }
    if (p.type == PairType::kGear) {
      ++gears;
      ASSERT_TRUE(p.ratio.has_value());
      EXPECT_EQ(p.ratio->ToString(), "-2");
    }
  }
  EXPECT_EQ(revolutes, 2);
  EXPECT_EQ(gears, 1);
}

TEST(ImplyGearFrame, NotWhenAPartIsGroundAShaftFillsABoreOrAPartHasNoGear) {
  AssemblySpec grounded = TwoGears();
  grounded.parts[0].ground = true;
  EXPECT_TRUE(ImplyGearFrame(&grounded).empty());
  EXPECT_EQ(grounded.parts.size(), 2u);

  AssemblySpec filled = TwoGears();
  filled.parts[1].features.push_back(MakeFeature("shaft", FeatureKind::kShaft,
                                                 Eigen::Vector3d(-60, 0, -20),
                                                 Eigen::Vector3d::UnitZ(), [](Feature& f) {
                                                   f.diameter = 20.0;
                                                   f.length = 30.0;
                                                 }));
  EXPECT_TRUE(ImplyGearFrame(&filled).empty());  // the pinion's shaft runs in the gear's bore

  AssemblySpec plate = TwoGears();
  plate.parts.push_back(MakePart("plate", {}));
  EXPECT_TRUE(ImplyGearFrame(&plate).empty());
  EXPECT_TRUE(plate.overrides.empty());

  AssemblySpec one = TwoGears();
  one.parts.pop_back();
  EXPECT_TRUE(ImplyGearFrame(&one).empty());

  AssemblySpec off = TwoGears();  // the file's "infer": {"implied_frame": false}
  off.inference.implied_frame = false;
  EXPECT_TRUE(ImplyGearFrame(&off).empty());
  EXPECT_EQ(off.parts.size(), 2u);
}

}  // namespace
}  // namespace mechanist
