// Assembly sequences on blocks of unit cubes: a found sequence re-checked insertion by
// insertion with the kernel's sweep (an oracle independent of the planner's search), and a
// part walled in by ground parts reported as unplaced with its blockers.
#include "reasoning/assembly_plan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "kernel/collision/collision_model.h"
#include "kernel/collision/translational_sweep.h"
#include "reasoning/analysis.h"
#include "test_assembly.h"

namespace mechanist {
namespace {

using testing::MakeAssembly;
using testing::MakePart;

// A 3 x 3 x 3 block of unit cubes, face to face; `ground(i, j, k)` says which are ground.
Assembly Block(const std::function<bool(int, int, int)>& ground) {
  std::vector<Part> parts;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        parts.push_back(MakePart("c" + std::to_string(i) + std::to_string(j) + std::to_string(k),
                                 {}, RigidTransform::Translation({1.0 * i, 1.0 * j, 1.0 * k}),
                                 ground(i, j, k)));
      }
    }
  }
  return MakeAssembly(std::move(parts));
}

TEST(AssemblyPlan, FoundSequenceIsClearInsertionByInsertion) {
  const Assembly a = Block([](int i, int j, int k) { return i + j + k == 0; });
  const Analysis an = Analyze(a);
  const CollisionModel model(a);
  const AssemblyPlan plan = PlanAssembly(a, an, model);
  ASSERT_TRUE(plan.assemblable);
  EXPECT_FALSE(plan.from_steps);
  EXPECT_TRUE(plan.clashes.empty());
  ASSERT_EQ(plan.base.size(), 1u);
  ASSERT_EQ(plan.steps.size(), 26u);
  // Replay: each part travels from far away along its direction to its place without a
  // blocking contact against the parts placed before it.
  std::vector<std::size_t> placed = plan.base;
  for (const InsertionStep& s : plan.steps) {
    EXPECT_NEAR(std::abs(s.direction_W.maxCoeff() + s.direction_W.minCoeff()), 1.0, 1e-12)
        << "cubes leave along principal directions";
    const RigidTransform X_start =
        RigidTransform::Translation(-10.0 * s.direction_W) * a.part(s.part).X_WP;
    for (const std::size_t o : placed) {
      SweepOptions options;
      options.max_travel = 10.0 - 1e-9;
      options.min_approach = std::sin(a.tolerance().angle);
      EXPECT_FALSE(FirstBlockingContact(model.part_mesh(s.part), X_start, model.part_mesh(o),
                                        a.part(o).X_WP, s.direction_W, options))
          << a.part(s.part).id << " hits " << a.part(o).id;
    }
    placed.push_back(s.part);
  }
}

// The progress: 0 first, a step per cube removed (26 of them), 1 last, never decreasing; a cube
// that cannot leave counts once it is found so.
TEST(AssemblyPlan, ProgressCountsThePartsPlaced) {
  std::vector<double> fractions;
  const auto record = [&](double fraction) { fractions.push_back(fraction); };
  const Assembly a = Block([](int i, int j, int k) { return i + j + k == 0; });
  PlanAssembly(a, Analyze(a), CollisionModel(a), record);
  ASSERT_EQ(fractions.size(), 28u);
  EXPECT_EQ(fractions.front(), 0.0);
  EXPECT_NEAR(fractions[13], 13.0 / 26, 1e-12);
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));

  fractions.clear();
  const Assembly walled = Block([](int i, int j, int k) { return !(i == 1 && j == 1 && k == 1); });
  PlanAssembly(walled, Analyze(walled), CollisionModel(walled), record);
  EXPECT_EQ(fractions, (std::vector<double>{0.0, 1.0, 1.0}));
}

TEST(AssemblyPlan, PartWalledInByGroundCannotBePlaced) {
  const Assembly a = Block([](int i, int j, int k) { return !(i == 1 && j == 1 && k == 1); });
  const AssemblyPlan plan = PlanAssembly(a, Analyze(a), CollisionModel(a));
  EXPECT_FALSE(plan.assemblable);
  EXPECT_TRUE(plan.steps.empty());
  ASSERT_EQ(plan.unplaced.size(), 1u);
  const InsertionStep& u = plan.unplaced.front();
  EXPECT_EQ(a.part(u.part).id, "c111");
  ASSERT_FALSE(u.clear);
  ASSERT_EQ(u.blocked_by.size(), 1u);
  // It touches its neighbour at once: the whole travel is lost.
  EXPECT_NEAR(u.blocked_by.front().short_by, 0.0, 1e-12);
}

TEST(AssemblyPlan, OverlappingCubesAreAClash) {
  const Assembly a =
      MakeAssembly({MakePart("base", {}, RigidTransform(), true),
                    MakePart("bad", {}, RigidTransform::Translation({0.5, 0.25, 0}))});
  const AssemblyPlan plan = PlanAssembly(a, Analyze(a), CollisionModel(a));
  EXPECT_FALSE(plan.assemblable);
  ASSERT_EQ(plan.clashes.size(), 1u);
  EXPECT_EQ(plan.clashes.front().verdict, ContactVerdict::kClash);
  EXPECT_NEAR(plan.clashes.front().measure.depth, 0.5, 1e-9);
}

}  // namespace
}  // namespace mechanist
