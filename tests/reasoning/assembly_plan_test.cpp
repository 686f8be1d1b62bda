// Assembly sequences on blocks of unit cubes: a found sequence re-checked insertion by
// insertion with the kernel's sweep (an oracle independent of the planner's search), the
// order of the disassembly against an oracle for cubes on a grid, a part walled in by
// ground parts reported as unplaced with its blockers, and a lever in a fork whose pin the
// file leaves out, which goes in across the pin's axis, also when the fork stands at an angle
// to the world's axes, and that pin, which goes in after them from an end that no part covers
// and, in place, stands in the way of a part and a pin put in after it.
#include "reasoning/assembly_plan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "kernel/collision/collision_model.h"
#include "kernel/collision/translational_sweep.h"
#include "reasoning/analysis.h"
#include "reasoning/expectation_check.h"
#include "test_assembly.h"

namespace mechanist {
namespace {

using testing::Boxes;
using testing::MakeAssembly;
using testing::MakePart;

// An n x n x n block of unit cubes, face to face, named cIJK and listed in that order;
// `ground(i, j, k)` says which are ground.
Assembly Block(const std::function<bool(int, int, int)>& ground, int n = 3) {
  std::vector<Part> parts;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
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

// The disassembly goes in passes over the parts in their order, each part tried with the
// parts left by those before it. The oracle, for cubes on a grid: a cube leaves along the first
// of +x, -x, +y, -y, +z, -z (the planner's order for parts without features) whose ray holds
// no cube still there (a cube slides past its face-to-face neighbours). The block is chosen so
// that a cube waits for one after it: two passes remove parts, and one cube is walled in.
TEST(AssemblyPlan, DisassemblyGoesInPassesOverThePartsInOrder) {
  constexpr int n = 4;
  const auto ground = [](int i, int j, int k) { return (i + 2 * j + 4 * k) % 3 == 1; };
  using Cell = std::array<int, 3>;
  const std::array<Cell, 6> directions = {
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
  std::vector<Cell> cells;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) cells.push_back({i, j, k});
    }
  }
  std::set<Cell> present(cells.begin(), cells.end());
  std::vector<std::pair<std::string, Cell>> removals;  // cube and the way it leaves
  int removing_passes = 0;
  for (bool progress = true; progress;) {
    progress = false;
    for (const Cell& c : cells) {
      if (ground(c[0], c[1], c[2]) || !present.count(c)) continue;
      for (const Cell& d : directions) {
        bool free = true;
        for (int t = 1; t <= n; ++t) {
          free = free && !present.count({c[0] + t * d[0], c[1] + t * d[1], c[2] + t * d[2]});
        }
        if (!free) continue;
        present.erase(c);
        removals.emplace_back(
            "c" + std::to_string(c[0]) + std::to_string(c[1]) + std::to_string(c[2]), d);
        progress = true;
        break;
      }
    }
    removing_passes += progress ? 1 : 0;
  }
  std::vector<std::string> walled_in;
  for (const Cell& c : cells) {
    if (!ground(c[0], c[1], c[2]) && present.count(c)) {
      walled_in.push_back("c" + std::to_string(c[0]) + std::to_string(c[1]) + std::to_string(c[2]));
    }
  }
  ASSERT_EQ(removing_passes, 2) << "the block no longer makes a cube wait";
  ASSERT_EQ(walled_in.size(), 1u);

  const Assembly a = Block(ground, n);
  const AssemblyPlan plan = PlanAssembly(a, Analyze(a), CollisionModel(a));
  ASSERT_EQ(plan.steps.size(), removals.size());
  for (std::size_t s = 0; s < removals.size(); ++s) {
    // Steps are insertions: the removals reversed, each along the opposite way.
    const InsertionStep& step = plan.steps[removals.size() - 1 - s];
    EXPECT_EQ(a.part(step.part).id, removals[s].first) << "removal " << s;
    const Cell& d = removals[s].second;
    EXPECT_EQ(step.direction_W, -Eigen::Vector3d(d[0], d[1], d[2])) << removals[s].first;
  }
  std::vector<std::string> unplaced;
  for (const InsertionStep& u : plan.unplaced) unplaced.push_back(a.part(u.part).id);
  EXPECT_EQ(unplaced, walled_in);
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

// A cube boxed in by ground blocks at different gaps: its best attempt is the direction with
// the widest gap, +z (4.5; +x 2, +y 1, -x and -z 0), not -y, where a long thin bar stops it
// after 4 beside a block that would stop it after 5: the obstacles' boxes are met in that
// order, but the bar's box is left last, so a search that ranked obstacles by anything but
// where their boxes are first met could stop at the block.
TEST(AssemblyPlan, BestAttemptGoesWhereTheGapIsWidest) {
  const auto block = [](const std::string& id, const Eigen::Vector3d& lo,
                        const Eigen::Vector3d& hi) {
    Part part = MakePart(id, {}, RigidTransform(), true);
    auto mesh = std::make_shared<TriangleMesh>(*part.mesh);
    for (Eigen::Vector3d& v : mesh->vertices) v = lo + v.cwiseProduct(hi - lo);
    part.mesh = mesh;
    return part;
  };
  const Assembly a =
      MakeAssembly({block("bar", {0, -15, 0}, {0.4, -4, 1}), block("y5", {0.6, -6, 0}, {1, -5, 1}),
                    block("x2", {3, 0, 0}, {4, 1, 1}), block("x0", {-1, 0, 0}, {0, 1, 1}),
                    block("y1", {0, 2, 0}, {1, 3, 1}), block("z4.5", {0, 0, 5.5}, {1, 1, 6.5}),
                    block("z0", {0, 0, -1}, {1, 1, 0}), MakePart("m", {}, RigidTransform())});
  const AssemblyPlan plan = PlanAssembly(a, Analyze(a), CollisionModel(a));
  ASSERT_EQ(plan.unplaced.size(), 1u);
  const InsertionStep& u = plan.unplaced.front();
  EXPECT_EQ(a.part(u.part).id, "m");
  EXPECT_EQ(u.direction_W, Eigen::Vector3d(0, 0, -1)) << "inserted against its way out, +z";
  ASSERT_EQ(u.blocked_by.size(), 1u);
  EXPECT_EQ(a.part(u.blocked_by[0].part).id, "z4.5");
  EXPECT_NEAR(u.blocked_by[0].short_by, 4.5, 1e-9);
}

// A through hole `id` of diameter d (mm) from `at` along the unit `axis` for `length` mm.
Feature ThroughHole(const char* id, const Eigen::Vector3d& at, const Eigen::Vector3d& axis,
                    double d, double length) {
  return testing::MakeFeature(id, FeatureKind::kHole, at, axis, [&](Feature& f) {
    f.diameter = d, f.length = length, f.through = true;
  });
}

// A hinge whose pin the file leaves out (the Onshape robot hand's finger joints), at X_WF: a
// lever whose 10 mm knuckle sits between the two cheeks of a ground fork, reaching `length`
// along +x out of it, the fork also closed behind (-x) and, when `closed_sides`, on +-y; the
// knuckle's bore and the cheeks' holes coaxial on z.
std::vector<Part> Hinge(const RigidTransform& X_WF, bool closed_sides, double length = 10) {
  using V = Eigen::Vector3d;
  const auto hole = [](const char* id, double d, double z0, double z1) {
    return ThroughHole(id, V(5, 5, z0), V::UnitZ(), d, z1 - z0);
  };
  Part fork =
      MakePart("fork", {hole("cheek_a", 3.45, -5, 0), hole("cheek_b", 3.45, 10, 15)}, X_WF, true);
  std::vector<std::pair<V, V>> walls = {
      {V(0, 0, -5), V(10, 10, 0)}, {V(0, 0, 10), V(10, 10, 15)}, {V(-5, -5, -5), V(0, 15, 15)}};
  if (closed_sides) {
    walls.push_back({V(0, -5, -5), V(20, 0, 15)});
    walls.push_back({V(0, 10, -5), V(20, 15, 15)});
  }
  fork.mesh = Boxes(walls);
  Part lever = MakePart("lever", {hole("knuckle", 3.2, 0, 10)}, X_WF);
  lever.mesh = Boxes({{V(0, 0, 0), V(length, 10, 10)}});
  return {fork, lever};
}

// The pin goes in once both parts are in place, so it does not hold the lever while it is
// placed: the lever goes in across the axis, from +x, the first way out that is clear (along
// the axis the cheeks stop it at once). A pin that is modelled does hold it (HeldAcross; its
// mesh is only its ends in the cheeks, out of the lever's way): then the lever cannot leave
// but along the pin's axis, where the cheeks stop it.
TEST(AssemblyPlan, AnImpliedPinGoesInAfterThePartsItJoins) {
  const Assembly hinge = MakeAssembly(Hinge(RigidTransform(), false));
  const Analysis an = Analyze(hinge);
  ASSERT_FALSE(an.pairs.empty());
  for (const Pair& p : an.pairs) ASSERT_EQ(p.source, PairSource::kImpliedPin);
  const AssemblyPlan plan = PlanAssembly(hinge, an, CollisionModel(hinge));
  EXPECT_TRUE(plan.assemblable);
  ASSERT_EQ(plan.steps.size(), 1u);
  EXPECT_EQ(hinge.part(plan.steps[0].part).id, "lever");
  EXPECT_TRUE(plan.steps[0].clear);
  EXPECT_EQ(plan.steps[0].direction_W, Eigen::Vector3d(-1, 0, 0));
  // Then the pin, through the cheeks and the knuckle (contacts in their holes are its fit: the
  // fork's mesh models no hole), from below, the first hole's axis' sense.
  ASSERT_EQ(plan.steps[0].pins.size(), 1u);
  const PinInsertion& pin_in = plan.steps[0].pins[0];
  std::vector<std::string> holes;
  for (const FeatureRef& h : pin_in.holes) holes.push_back(hinge.FeatureName(h));
  EXPECT_EQ(holes, (std::vector<std::string>{"fork/cheek_a", "fork/cheek_b", "lever/knuckle"}));
  EXPECT_DOUBLE_EQ(pin_in.diameter, 3.2);
  EXPECT_TRUE(pin_in.ends_W[0].isApprox(Eigen::Vector3d(5, 5, -5), 1e-12));
  EXPECT_TRUE(pin_in.ends_W[1].isApprox(Eigen::Vector3d(5, 5, 15), 1e-12));
  EXPECT_TRUE(pin_in.clear);
  EXPECT_EQ(pin_in.direction_W, Eigen::Vector3d(0, 0, 1));
  EXPECT_TRUE(plan.base_pins.empty());

  std::vector<Part> parts = Hinge(RigidTransform(), false);
  const Feature shaft = testing::MakeFeature("shaft", FeatureKind::kShaft,
                                             Eigen::Vector3d(5, 5, -5), Eigen::Vector3d::UnitZ(),
                                             [](Feature& f) { f.diameter = 3.2, f.length = 20; });
  Part pin = MakePart("pin", {shaft}, RigidTransform(), true);
  pin.mesh = Boxes({{Eigen::Vector3d(4, 4, -5), Eigen::Vector3d(6, 6, 0)},
                    {Eigen::Vector3d(4, 4, 10), Eigen::Vector3d(6, 6, 15)}});
  parts.push_back(pin);
  const Assembly pinned = MakeAssembly(parts);
  const Analysis pinned_an = Analyze(pinned);
  bool lever_on_pin = false;
  for (const Pair& p : pinned_an.pairs) {
    EXPECT_NE(p.source, PairSource::kImpliedPin);
    lever_on_pin =
        lever_on_pin || (pinned.part(p.a.part).id == "pin" && pinned.part(p.b.part).id == "lever");
  }
  EXPECT_TRUE(lever_on_pin);
  const AssemblyPlan held = PlanAssembly(pinned, pinned_an, CollisionModel(pinned));
  EXPECT_FALSE(held.assemblable);
  ASSERT_EQ(held.unplaced.size(), 1u);
  EXPECT_EQ(pinned.part(held.unplaced[0].part).id, "lever");
}

// The hinge with its pin modelled, and a blind hole along x in the lever's end its first
// feature, so that its first way out is across the pin (-x, then +x): the pin's fit holds it
// there (HeldAcross), as the cheeks do along the pin, and its attempt names the fit.
TEST(AssemblyPlan, AnAttemptAcrossAModelledPinNamesItsFit) {
  std::vector<Part> parts = Hinge(RigidTransform(), false);
  parts[1].features.insert(
      parts[1].features.begin(),
      testing::MakeFeature("end", FeatureKind::kHole, Eigen::Vector3d(10, 5, 5),
                           -Eigen::Vector3d::UnitX(),
                           [](Feature& f) { f.diameter = 2, f.length = 3; }));
  Part pin = MakePart("pin",
                      {testing::MakeFeature("shaft", FeatureKind::kShaft, Eigen::Vector3d(5, 5, -5),
                                            Eigen::Vector3d::UnitZ(),
                                            [](Feature& f) { f.diameter = 3.2, f.length = 20; })},
                      RigidTransform(), true);
  pin.mesh = Boxes({{Eigen::Vector3d(4, 4, -5), Eigen::Vector3d(6, 6, 0)},
                    {Eigen::Vector3d(4, 4, 10), Eigen::Vector3d(6, 6, 15)}});
  parts.push_back(pin);
  const Assembly a = MakeAssembly(parts);
  const AssemblyPlan plan = PlanAssembly(a, Analyze(a), CollisionModel(a));
  ASSERT_EQ(plan.unplaced.size(), 1u);
  const InsertionStep& u = plan.unplaced.front();
  EXPECT_EQ(a.part(u.part).id, "lever");
  EXPECT_EQ(std::abs(u.direction_W.x()), 1.0);  // across the pin
  bool held = false;
  for (const InsertionObstacle& o : u.blocked_by) {
    if (a.part(o.part).id != "pin") continue;
    ASSERT_TRUE(o.held_by.has_value());
    EXPECT_EQ(a.FeatureName(*o.held_by), "pin/shaft");
    EXPECT_EQ(o.short_by, 0.0);
    held = true;
  }
  EXPECT_TRUE(held);
}

// Ground caps over the pin's ends. One cap: the pin goes in from the other end. Both: it
// cannot go in, so the lever cannot be placed either (the pin would have to come out before
// it), though its own way in is clear; the attempt shows the pin stopped by the cap nearest
// its place. With the lever ground too, the pin goes in before the first step.
TEST(AssemblyPlan, AHingePinGoesInFromAnOpenEnd) {
  using V = Eigen::Vector3d;
  const auto cap = [](const char* id, double z0, double z1) {
    Part part = MakePart(id, {}, RigidTransform(), true);
    part.mesh = Boxes({{V(0, 0, z0), V(10, 10, z1)}});
    return part;
  };
  std::vector<Part> parts = Hinge(RigidTransform(), false);
  parts.push_back(cap("cap_below", -8, -5));
  const Assembly one_cap = MakeAssembly(parts);
  const AssemblyPlan plan = PlanAssembly(one_cap, Analyze(one_cap), CollisionModel(one_cap));
  EXPECT_TRUE(plan.assemblable);
  ASSERT_EQ(plan.steps.size(), 1u);
  ASSERT_EQ(plan.steps[0].pins.size(), 1u);
  EXPECT_TRUE(plan.steps[0].pins[0].clear);
  EXPECT_EQ(plan.steps[0].pins[0].direction_W, V(0, 0, -1));
  // The same with the file's steps (the lever's knuckle onto cheek_a): the pin goes in after
  // the lever's step, however that step goes.
  AssemblySpec spec;
  spec.name = "stepped";
  spec.parts = parts;
  spec.steps = {{FeatureRef{1, 0}, FeatureRef{0, 0}}};
  const Assembly stepped(std::move(spec));
  const AssemblyPlan checked = PlanAssembly(stepped, Analyze(stepped), CollisionModel(stepped));
  EXPECT_TRUE(checked.from_steps);
  EXPECT_TRUE(checked.base_pins.empty());
  ASSERT_EQ(checked.steps.size(), 1u);
  ASSERT_EQ(checked.steps[0].pins.size(), 1u);
  EXPECT_TRUE(checked.steps[0].pins[0].clear);
  EXPECT_EQ(checked.steps[0].pins[0].direction_W, V(0, 0, -1));

  parts.push_back(cap("cap_above", 15, 17));
  const Assembly capped = MakeAssembly(parts);
  const AssemblyPlan stuck = PlanAssembly(capped, Analyze(capped), CollisionModel(capped));
  EXPECT_FALSE(stuck.assemblable);
  EXPECT_TRUE(stuck.steps.empty());
  ASSERT_EQ(stuck.unplaced.size(), 1u);
  const InsertionStep& lever = stuck.unplaced[0];
  EXPECT_EQ(capped.part(lever.part).id, "lever");
  EXPECT_TRUE(lever.clear);
  ASSERT_EQ(lever.pins.size(), 1u);
  EXPECT_FALSE(lever.pins[0].clear);
  ASSERT_EQ(lever.pins[0].blocked_by.size(), 1u);
  // The pin (z -5 to 15 in place) meets cap_below's underside (z -8) 23 mm short of its place
  // from below, cap_above's top (z 17) 22 mm short from above.
  EXPECT_EQ(lever.pins[0].direction_W, V(0, 0, -1));
  EXPECT_EQ(capped.part(lever.pins[0].blocked_by[0].part).id, "cap_above");
  EXPECT_NEAR(lever.pins[0].blocked_by[0].short_by, 22.0, 1e-9);

  parts[1].ground = true;
  const Assembly all_ground = MakeAssembly(parts);
  const AssemblyPlan based =
      PlanAssembly(all_ground, Analyze(all_ground), CollisionModel(all_ground));
  EXPECT_TRUE(based.steps.empty());
  EXPECT_FALSE(based.assemblable);
  ASSERT_EQ(based.base_pins.size(), 1u);
  EXPECT_FALSE(based.base_pins[0].clear);
  Expectation assemblable;
  assemblable.kind = Expectation::Kind::kAssemblable;
  assemblable.flag = true;
  const ExpectationResult said =
      CheckExpectation(all_ground, Analyze(all_ground), assemblable, &based);
  EXPECT_FALSE(said.passed);
  EXPECT_EQ(said.detail,
            "found not assemblable: 0 clashes, 0 blocked insertions, 1 pin the file leaves out "
            "blocked");
}

// The hinge closed on +-y too, so that its only way out is across the pin, along the lever
// (x in the fork's frame). Turned 30 degrees about the pin (z), no world axis is that way, nor
// any world axis turned square to the pin: the way from the pin to the lever's middle is.
// Tilted 20 degrees about y with the lever's middle on the pin, the world's x turned square to
// the pin is.
TEST(AssemblyPlan, APartOnAPivotLeavesAcrossItsAxis) {
  const double degree = std::acos(-1.0) / 180;
  for (const auto& [X_WF, length] :
       {std::pair{RigidTransform::AxisAngle(Eigen::Vector3d::UnitZ(), 30 * degree), 20.0},
        std::pair{RigidTransform::AxisAngle(Eigen::Vector3d::UnitY(), 20 * degree), 10.0}}) {
    const Assembly hinge = MakeAssembly(Hinge(X_WF, true, length));
    const AssemblyPlan plan = PlanAssembly(hinge, Analyze(hinge), CollisionModel(hinge));
    EXPECT_TRUE(plan.assemblable);
    ASSERT_EQ(plan.steps.size(), 1u);
    EXPECT_TRUE(plan.steps[0].clear);
    EXPECT_TRUE(
        plan.steps[0].direction_W.isApprox(-X_WF.RotateDirection(Eigen::Vector3d::UnitX()), 1e-12))
        << plan.steps[0].direction_W.transpose();
  }
}

// A block behind the pin of a hinge: the fork closed on +-y, its cheeks' holes 10 mm apart
// (z -5..0 and 10..15), the lever's knuckle only 7 mm thick (z 0..7), and a block in the 3 mm
// between the knuckle and cheek_b, between the fork's back wall and the pin (x 0..3; the pin,
// 3.2 mm, stands at x 3.4..6.6). The block's only way out is along +x, across the pin's line: it
// leaves after the pin, so it goes in before the lever and the pin, though it comes first in
// the file. Without the pin in its way (the lever's hole moved off the cheeks' axis, so that
// no pin joins them) it goes in last, the pass over the parts in order taking it out first.
TEST(AssemblyPlan, APinInPlaceIsInTheWayOfThePartsAfterIt) {
  using V = Eigen::Vector3d;
  const auto plan_for = [](const V& knuckle_at) {
    const auto hole = [](const char* id, const V& at, double d, double length) {
      return ThroughHole(id, at, V::UnitZ(), d, length);
    };
    Part fork = MakePart(
        "fork", {hole("cheek_a", V(5, 5, -5), 3.45, 5), hole("cheek_b", V(5, 5, 10), 3.45, 5)},
        RigidTransform(), true);
    fork.mesh = Boxes({{V(0, 0, -5), V(10, 10, 0)},
                       {V(0, 0, 10), V(10, 10, 15)},
                       {V(-5, -5, -5), V(0, 15, 15)},
                       {V(0, -5, -5), V(20, 0, 15)},
                       {V(0, 10, -5), V(20, 15, 15)}});
    Part block = MakePart("block", {}, RigidTransform());
    block.mesh = Boxes({{V(0, 0, 7), V(3, 10, 10)}});
    Part lever = MakePart("lever", {hole("knuckle", knuckle_at, 3.2, 7)}, RigidTransform());
    lever.mesh = Boxes({{V(0, 0, 0), V(10, 10, 7)}});
    const Assembly a = MakeAssembly({fork, block, lever});
    const AssemblyPlan plan = PlanAssembly(a, Analyze(a), CollisionModel(a));
    std::vector<std::string> order;
    for (const InsertionStep& s : plan.steps) {
      order.push_back(a.part(s.part).id + (s.pins.empty() ? "" : " then its pin"));

      EXPECT_TRUE(s.clear) << a.part(s.part).id;
    }
    EXPECT_TRUE(plan.assemblable);
    EXPECT_TRUE(plan.unplaced.empty());
    return order;
  };
  EXPECT_EQ(plan_for(V(5, 5, 0)), (std::vector<std::string>{"block", "lever then its pin"}));
  EXPECT_EQ(plan_for(V(5, 8, 0)), (std::vector<std::string>{"lever", "block"}));
}

// Two pins the file leaves out that cross: the hinge's pin on z, and one on x through a hole
// across the lever's knuckle and a ground link beside it (x 10..15), whose line runs through
// the first pin. Both go in after the lever, in the order of their first holes' names: the
// hinge's pin first, clear, then the cross pin, which no end lets in: from -x the fork's back
// wall stops it, from +x the hinge's pin, nearer its place (its leading end meets the pin's
// side at x 6.6 over the 24-sided pin's flats and corners). The lever cannot be placed.
TEST(AssemblyPlan, APinInPlaceStopsAPinThatCrossesIt) {
  using V = Eigen::Vector3d;
  std::vector<Part> parts = Hinge(RigidTransform(), false);
  const auto hole = [](const char* id, const V& at, double d, double length) {
    return ThroughHole(id, at, V::UnitX(), d, length);
  };
  parts[1].features.push_back(hole("cross", V(0, 5, 5), 3.2, 10));
  Part link = MakePart("link", {hole("eye", V(10, 5, 5), 3.45, 5)}, RigidTransform(), true);
  link.mesh = Boxes({{V(10, 0, 0), V(15, 10, 10)}});
  parts.push_back(link);
  const Assembly a = MakeAssembly(parts);
  const AssemblyPlan plan = PlanAssembly(a, Analyze(a), CollisionModel(a));
  EXPECT_FALSE(plan.assemblable);
  EXPECT_TRUE(plan.steps.empty());
  ASSERT_EQ(plan.unplaced.size(), 1u);
  const InsertionStep& lever = plan.unplaced[0];
  EXPECT_EQ(a.part(lever.part).id, "lever");
  ASSERT_EQ(lever.pins.size(), 2u);
  EXPECT_TRUE(lever.pins[0].clear);
  EXPECT_EQ(a.FeatureName(lever.pins[1].holes.front()), "lever/cross");
  ASSERT_FALSE(lever.pins[1].clear);
  EXPECT_TRUE(lever.pins[1].direction_W.isApprox(V(-1, 0, 0), 1e-12));
  const InsertionObstacle& stop = lever.pins[1].blocked_by.front();
  EXPECT_EQ(stop.pin, lever.pins[0].holes);
  EXPECT_GE(stop.short_by, 5 + 1.6 * std::cos(std::acos(-1.0) / 24) - 1e-9);
  EXPECT_LE(stop.short_by, 6.6 + 1e-9);
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
  // Its way out is free (a sweep sees only the contacts it enters), but the insertion ends in
  // the clash: not clear, stopped at its place by the base, where they clash.
  ASSERT_EQ(plan.steps.size(), 1u);
  const InsertionStep& step = plan.steps.front();
  EXPECT_FALSE(step.clear);
  ASSERT_EQ(step.blocked_by.size(), 1u);
  EXPECT_EQ(a.part(step.blocked_by.front().part).id, "base");
  EXPECT_TRUE(step.blocked_by.front().clash_at_rest);
  EXPECT_EQ(step.blocked_by.front().short_by, 0.0);
  EXPECT_EQ(step.blocked_by.front().travel, step.travel);
}

// A tub, ground and open on top, its inside [-10, 10] x [0, 10] x [0, 20] (mm).
Part Tub() {
  using V = Eigen::Vector3d;
  Part tub = MakePart("tub", {}, RigidTransform(), true);
  tub.mesh = Boxes({{V(-15, -5, -5), V(15, 15, 0)},
                    {V(-15, -5, 0), V(-10, 15, 20)},
                    {V(10, -5, 0), V(15, 15, 20)},
                    {V(-10, -5, 0), V(10, 0, 20)},
                    {V(-10, 10, 0), V(10, 15, 20)}});
  return tub;
}

// Whether `part` travels from `travel` mm back along d into its place without a blocking
// contact with `obstacle` (the kernel's sweep: an oracle apart from the planner's search).
bool Clear(const Assembly& a, const CollisionModel& model, std::size_t part, std::size_t obstacle,
           const Eigen::Vector3d& d, double travel) {
  SweepOptions options;
  options.max_travel = travel - 1e-9;
  options.min_approach = std::sin(a.tolerance().angle);
  const RigidTransform X_start = RigidTransform::Translation(-travel * d) * a.part(part).X_WP;
  return !FirstBlockingContact(model.part_mesh(part), X_start, model.part_mesh(obstacle),
                               a.part(obstacle).X_WP, d, options);
}

// Two parts in the tub that hook into each other: `x`, a block with a shelf reaching right,
// and `y`, a C around that shelf whose top reaches back over x. Each holds the other down, and
// the tub holds them sideways, so neither can leave alone; together they lift out. Apart from
// the tub, x slides out of y's C along -x (y, the larger, is the sub-assembly's base): the
// sub-assembly is put together apart, x into y along +x, then lowered into the tub.
TEST(AssemblyPlan, PartsThatHoldEachOtherGoInAsASubAssembly) {
  using V = Eigen::Vector3d;
  Part x = MakePart("x", {});
  x.mesh = Boxes({{V(-10, 0, 0), V(0, 10, 10)}, {V(0, 0, 8), V(4.5, 10, 10)}});
  Part y = MakePart("y", {});
  y.mesh = Boxes(
      {{V(0.5, 0, 0), V(10, 10, 7)}, {V(5, 0, 7), V(10, 10, 11)}, {V(-5, 0, 11), V(10, 10, 13)}});
  const Assembly a = MakeAssembly({Tub(), x, y});
  const CollisionModel model(a);
  // Alone, each is stopped on its way out of the tub by the other.
  EXPECT_FALSE(Clear(a, model, 1, 2, V(0, 0, -1), 30));
  EXPECT_FALSE(Clear(a, model, 2, 1, V(0, 0, -1), 30));
  const AssemblyPlan plan = PlanAssembly(a, Analyze(a), model);
  EXPECT_TRUE(plan.assemblable);
  EXPECT_TRUE(plan.unplaced.empty());
  ASSERT_EQ(plan.steps.size(), 2u);
  const InsertionStep& apart = plan.steps[0];
  const InsertionStep& in = plan.steps[1];
  EXPECT_EQ(a.part(apart.part).id, "x");
  EXPECT_EQ(apart.apart_for, std::optional<std::size_t>(1));
  EXPECT_FALSE(apart.subassembly);
  EXPECT_EQ(apart.direction_W, V(1, 0, 0));
  EXPECT_TRUE(apart.clear);
  EXPECT_TRUE(Clear(a, model, 1, 2, apart.direction_W, apart.travel)) << "x into y, y alone";
  EXPECT_TRUE(in.subassembly);
  EXPECT_FALSE(in.apart_for);
  EXPECT_EQ(a.part(in.part).id, "y");
  EXPECT_EQ(in.carried, std::vector<std::size_t>({1}));
  EXPECT_EQ(in.direction_W, V(0, 0, -1));
  EXPECT_TRUE(in.clear);
  EXPECT_TRUE(Clear(a, model, 1, 0, in.direction_W, in.travel)) << "x, with y, into the tub";
  EXPECT_TRUE(Clear(a, model, 2, 0, in.direction_W, in.travel)) << "y, with x, into the tub";
}

// A part shut in a box (y), both in the tub: they lift out together, but the part cannot be
// put into the box, which stays the sub-assembly's base; its attempt is unplaced, apart for
// the sub-assembly's step, stopped by the box where it stands.
TEST(AssemblyPlan, APartShutInASubAssemblyIsUnplacedApartForIt) {
  using V = Eigen::Vector3d;
  Part box = MakePart("box", {});
  box.mesh = Boxes({{V(-6, 0, 0), V(6, 10, 2)},
                    {V(-6, 0, 8), V(6, 10, 10)},
                    {V(-6, 0, 2), V(-4, 10, 8)},
                    {V(4, 0, 2), V(6, 10, 8)},
                    {V(-4, 0, 2), V(4, 2, 8)},
                    {V(-4, 8, 2), V(4, 10, 8)}});
  Part inside = MakePart("inside", {});
  inside.mesh = Boxes({{V(-4, 2, 2), V(4, 8, 8)}});
  const Assembly a = MakeAssembly({Tub(), box, inside});
  const AssemblyPlan plan = PlanAssembly(a, Analyze(a), CollisionModel(a));
  EXPECT_FALSE(plan.assemblable);
  ASSERT_EQ(plan.steps.size(), 1u);
  EXPECT_TRUE(plan.steps[0].subassembly);
  EXPECT_EQ(a.part(plan.steps[0].part).id, "box");
  EXPECT_EQ(plan.steps[0].carried, std::vector<std::size_t>({2}));
  EXPECT_TRUE(plan.steps[0].clear);
  ASSERT_EQ(plan.unplaced.size(), 1u);
  const InsertionStep& shut = plan.unplaced[0];
  EXPECT_EQ(a.part(shut.part).id, "inside");
  EXPECT_EQ(shut.apart_for, std::optional<std::size_t>(0));
  ASSERT_FALSE(shut.blocked_by.empty());
  EXPECT_EQ(a.part(shut.blocked_by[0].part).id, "box");
  EXPECT_NEAR(shut.blocked_by[0].short_by, 0.0, 1e-9);
}

}  // namespace
}  // namespace mechanist
