// Dragging a part as a hand on it would: about its axis' own line where the pairs allow it (a
// finger's middle segment about its own hinge, not with the finger about the knuckle), else
// at the rate the pairs give (a planet spun about its pin orbits at Willis' ratio), and, by
// default, on the joint its subassembly moves on when the part has no pair of its own.

#include "reasoning/drag.h"

#include <gtest/gtest.h>

#include "reasoning/analysis.h"
#include "test_assembly.h"

namespace mechanist {
namespace {

using testing::MakeAssembly;
using testing::MakeFeature;
using testing::MakePart;
using K = FeatureKind;
const Eigen::Vector3d kX = Eigen::Vector3d::UnitX();
const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

// A shaft (convex) or a through hole of diameter 4 and length 10 from `origin` along `axis`.
Feature Round(const std::string& id, K kind, const Eigen::Vector3d& origin,
              const Eigen::Vector3d& axis) {
  return MakeFeature(id, kind, origin, axis, [&](Feature& f) {
    f.diameter = 4;
    f.length = 10;
    f.retained = kind == K::kShaft;
    f.through = kind == K::kHole;
  });
}

std::size_t PartIndex(const Assembly& a, const std::string& id) {
  for (std::size_t p = 0; p < a.parts().size(); ++p) {
    if (a.part(p).id == id) return p;
  }
  ADD_FAILURE() << "no part " << id;
  return 0;
}

// The distance of point p from the line through `origin` along the unit `axis`.
double FromLine(const Eigen::Vector3d& p, const Eigen::Vector3d& origin,
                const Eigen::Vector3d& axis) {
  const Eigen::Vector3d d = p - origin;
  return (d - d.dot(axis) * axis).norm();
}

// A finger on a frame: a knuckle hinge along x at y = 0 and a middle hinge at y = 20.
Assembly Finger() {
  return MakeAssembly({
      MakePart("frame", {Round("knuckle", K::kHole, {-5, 0, 0}, kX)}, RigidTransform(), true),
      MakePart("proximal", {Round("knuckle_pin", K::kShaft, {-5, 0, 0}, kX),
                            Round("hinge", K::kHole, {-5, 20, 0}, kX)}),
      MakePart("middle", {Round("hinge_pin", K::kShaft, {-5, 20, 0}, kX)}),
  });
}

TEST(Drag, TurnsAPartAboutItsOwnHingeNotAParallelOne) {
  const Assembly a = Finger();
  const Analysis an = Analyze(a);
  ASSERT_EQ(an.motion.mobility.dof, 2);
  const std::size_t middle = PartIndex(a, "middle");
  const DragResult r = Drag(a, an, {middle, std::nullopt, true});
  ASSERT_TRUE(r.motion.possible) << r.motion.reason;
  EXPECT_EQ(a.FeatureName(r.axis), "middle/hinge_pin");
  EXPECT_EQ(r.part_freedoms, 2);
  // Turning the whole finger about the knuckle would turn the middle segment about x at the
  // same rate; the hand on it turns it about its own hinge, and the proximal segment stays.
  EXPECT_EQ(r.motion.parts[PartIndex(a, "proximal")].kind, MotionKind::kNone);
  const PartMotion& m = r.motion.parts[middle];
  EXPECT_EQ(m.kind, MotionKind::kRotation);
  EXPECT_NEAR(FromLine(m.point_W, {0, 20, 0}, kX), 0.0, 1e-9);
  EXPECT_TRUE(m.rotation.is_exact()) << m.rotation.ToString();
  EXPECT_EQ(m.rotation.ToString(), "1");
  ASSERT_EQ(r.absorbing_pairs.size(), 1u);
  const Pair& hinge = an.pairs[r.absorbing_pairs[0]];
  EXPECT_TRUE(hinge.a.part == middle || hinge.b.part == middle);
}

TEST(Drag, APartWithoutAPairOfItsOwnMovesOnItsSubassemblysJoint) {
  // A rod fixed in a hub's socket; the hub turns in the frame's bearing about z. The rod's
  // only pair is with the hub, in its own subassembly: dragged, it turns with the hub.
  const Assembly a = MakeAssembly(
      {MakePart("frame", {Round("bearing", K::kHole, {0, 0, -10}, kZ)}, RigidTransform(), true),
       MakePart("hub", {Round("journal", K::kShaft, {0, 0, -10}, kZ),
                        Round("socket", K::kHole, {5, 0, 0}, kX)}),
       MakePart("rod", {Round("spigot", K::kShaft, {5, 0, 0}, kX)})},
      {{{FeatureRef{1, 1}, FeatureRef{2, 0}}, PairType::kFixed}});
  const Analysis an = Analyze(a);
  const std::size_t rod = PartIndex(a, "rod");
  ASSERT_EQ(an.subassembly_of[rod], an.subassembly_of[PartIndex(a, "hub")]);
  const DragResult r = Drag(a, an, {rod, std::nullopt, true});
  ASSERT_TRUE(r.motion.possible) << r.motion.reason;
  EXPECT_EQ(r.part, rod);
  EXPECT_EQ(a.FeatureName(r.axis), "hub/journal");
  const PartMotion& m = r.motion.parts[rod];
  EXPECT_EQ(m.kind, MotionKind::kRotation);
  EXPECT_NEAR(std::abs(m.axis_W.dot(kZ)), 1.0, 1e-12);
  EXPECT_NEAR(FromLine(m.point_W, {0, 0, 0}, kZ), 0.0, 1e-9);
  // Asked for its own spigot's axis, about which the rod cannot turn: blocked, held by the
  // hub's bearing.
  const DragResult held = Drag(a, an, {rod, 0, true});
  EXPECT_FALSE(held.motion.possible);
  EXPECT_EQ(held.holding_pairs.size(), 1u);
}

TEST(Drag, APlanetSpunAboutItsPinStillOrbitsAtWillisRatio) {
  // A 60-tooth ring fixed in the frame, a carrier turning about z, a 20-tooth planet on the
  // carrier's pin 20 mm out. The planet cannot turn about its own line with the ring held, so
  // that condition gives way: it turns once while the carrier turns -1/2 (Willis: w_p - w_c =
  // (0 - w_c) 60 / 20).
  auto gear = [](const std::string& id, const Eigen::Vector3d& origin, int teeth, bool internal) {
    return MakeFeature(id, K::kGear, origin, kZ, [&](Feature& g) {
      g.teeth = teeth;
      g.module = 1;
      g.length = 5;
      g.internal = internal;
    });
  };
  const Assembly a = MakeAssembly({
      MakePart("frame",
               {gear("ring", {0, 0, 0}, 60, true), Round("bearing", K::kHole, {0, 0, -20}, kZ)},
               RigidTransform(), true),
      MakePart("carrier", {Round("journal", K::kShaft, {0, 0, -20}, kZ),
                           Round("pin", K::kShaft, {20, 0, -10}, kZ)}),
      MakePart("planet",
               {gear("teeth", {20, 0, 0}, 20, false), Round("bore", K::kHole, {20, 0, -10}, kZ)}),
  });
  const Analysis an = Analyze(a);
  ASSERT_EQ(an.motion.mobility.dof, 1);
  const DragResult r = Drag(a, an, {PartIndex(a, "planet"), std::nullopt, true});
  ASSERT_TRUE(r.motion.possible) << r.motion.reason;
  const auto journal = a.FindFeature("carrier/journal");
  ASSERT_TRUE(journal.has_value());
  const ExactReal carrier = r.motion.features[journal->part][journal->feature].rotation;
  EXPECT_TRUE(carrier.is_exact()) << carrier.ToString();
  EXPECT_EQ(carrier.ToString(), "-1/2");
}

}  // namespace
}  // namespace mechanist
