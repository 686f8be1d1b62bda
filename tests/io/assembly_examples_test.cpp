// Interference, assembly plans and fastener checks on the examples and on variants of the
// bracket example with a design mistake put in.
#include <gtest/gtest.h>

#include <filesystem>

#include "io/load_assembly.h"
#include "kernel/assembly/assembly_check.h"
#include "kernel/assembly/assembly_state.h"
#include "kernel/collision/collision_model.h"
#include "reasoning/adjustment.h"
#include "reasoning/analysis.h"
#include "reasoning/assembly_plan.h"
#include "reasoning/expectation_check.h"
#include "reasoning/interference.h"
#include "reasoning/operation_check.h"
#include "text_edit.h"

namespace mechanist {
namespace {

const std::string kBracket =
    std::string(MECHANIST_SOURCE_DIR) + "/examples/bracket_plate_bolt_nut/assembly.json";

using testing::ReadText;
using testing::Replace;

const Diagnostic* Find(const Analysis& an, const std::string& code) {
  for (const Diagnostic& d : an.diagnostics) {
    if (d.code == code) return &d;
  }
  return nullptr;
}

TEST(AssemblyExamples, EveryExampleIsFreeOfClashesAssemblableAndRunsClear) {
  int examples = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(MECHANIST_SOURCE_DIR) + "/examples")) {
    const auto file = entry.path() / "assembly.json";
    if (!std::filesystem::exists(file)) continue;
    ++examples;
    // With adjustments and goals, as the commands see it: solved and locked.
    const Assembly a = Adjusted(LoadAssembly(file));
    const Analysis an = Analyze(a);
    const CollisionModel model(a);
    for (const PartContact& c : FindContacts(a, InitialState(a), model, an.pairs)) {
      EXPECT_NE(c.verdict, ContactVerdict::kClash)
          << file << ": " << a.part(c.part_a).id << " and " << a.part(c.part_b).id;
    }
    const AssemblyPlan plan = PlanAssembly(a, an, model);
    if (plan.assemblable) {
      EXPECT_TRUE(plan.unplaced.empty()) << file;
      std::size_t placed = plan.base.size() + plan.steps.size();
      for (const auto& s : plan.steps) placed += s.carried.size();
      EXPECT_EQ(placed, a.parts().size()) << file << ": every part is placed once";
    }
    // Whether it can be assembled is each example's own expectation.
    for (const ExpectationResult& r : CheckExpectations(a, an, &plan)) {
      EXPECT_TRUE(r.passed) << file << " " << r.pointer << ": " << r.what << ": " << r.detail;
    }
    // Running: nothing collides over the driver's amount.
    if (!a.drivers().empty()) {
      const OperationCheck run = CheckOperation(a, an, model, std::nullopt, std::nullopt);
      EXPECT_TRUE(run.possible) << file << ": " << run.reason;
      EXPECT_TRUE(run.clashes.empty()) << file << ": " << a.part(run.clashes[0].part_a).id
                                       << " hits " << a.part(run.clashes[0].part_b).id;
      EXPECT_TRUE(run.undecided.empty()) << file;
      // A sketch of features-only parts has nothing to sweep.
      EXPECT_EQ(run.pairs_swept > 0, PartsWithoutGeometry(a).size() < a.parts().size()) << file;
    }
  }
  EXPECT_EQ(examples, 14);
}

TEST(AssemblyExamples, BoltLargerThanThePlateHoleIsAClashAndBlocksItsStep) {
  const std::string text = Replace(ReadText(kBracket), R"("at": [-30, 0], "diameter": 6.6)",
                                   R"("at": [-30, 0], "diameter": 5)");
  const Assembly a = LoadAssemblyText(text, kBracket);
  const Analysis an = Analyze(a);
  const AssemblyPlan plan = PlanAssembly(a, an, CollisionModel(a));
  EXPECT_FALSE(plan.assemblable);
  ASSERT_EQ(plan.clashes.size(), 1u);
  EXPECT_EQ(a.part(plan.clashes[0].part_a).id + "+" + a.part(plan.clashes[0].part_b).id,
            "plate+bolt_left");
  EXPECT_NEAR(plan.clashes[0].measure.depth, 0.5, 0.05);
  ASSERT_EQ(plan.steps.size(), 2u);
  EXPECT_FALSE(plan.steps[0].clear);
  ASSERT_EQ(plan.steps[0].blocked_by.size(), 1u);
  const InsertionObstacle& o = plan.steps[0].blocked_by[0];
  EXPECT_EQ(a.part(o.part).id, "plate");
  // The bolt's tip (z = 9 - 16 in place) meets the plate's top (z = 5) 12 mm short.
  EXPECT_NEAR(o.short_by, 12.0, 1e-9);
  EXPECT_NEAR(o.travel + o.short_by, plan.steps[0].travel, 1e-9);
  EXPECT_TRUE(plan.steps[1].clear);
  const auto results = CheckExpectations(a, an, &plan);
  EXPECT_FALSE(results.back().passed) << "the example expects assemblable true";
}

TEST(AssemblyExamples, StepIntoAPartNotYetPlacedHitsWhatIsInTheWay) {
  // Insert the left bracket after its bolt: the bolt (in place) stands in the bracket's way.
  const std::string text = Replace(ReadText(kBracket),
                                   R"("steps": [
    {"insert": "bolt_left/thread", "into": "bracket_left/base_hole1"},)",
                                   R"("steps": [
    {"insert": "bolt_left/thread", "into": "plate/hole_left"},
    {"insert": "bracket_left/base_bottom", "into": "plate/top"},)");
  const Assembly a = LoadAssemblyText(text, kBracket);
  const AssemblyPlan plan = PlanAssembly(a, Analyze(a), CollisionModel(a));
  ASSERT_EQ(plan.steps.size(), 3u);
  EXPECT_TRUE(plan.steps[0].clear);
  EXPECT_FALSE(plan.steps[1].clear);
  ASSERT_FALSE(plan.steps[1].blocked_by.empty());
  EXPECT_EQ(a.part(plan.steps[1].blocked_by[0].part).id, "bolt_left");
  EXPECT_FALSE(plan.assemblable);
}

// The clevis latch: the file's only step drops the latch onto the base after everything
// else, the pin the file leaves out included, which lies across its way: its top (z 33)
// meets the latch's underside (z 5 in place) 28 mm short. Its holes name it.
TEST(AssemblyExamples, APinTheFileLeavesOutStopsAPartPutInAfterIt) {
  const Assembly a = LoadAssembly(std::string(MECHANIST_SOURCE_DIR) +
                                  "/examples/clevis_latch_blocked_by_pin/assembly.json");
  const AssemblyPlan plan = PlanAssembly(a, Analyze(a), CollisionModel(a));
  EXPECT_FALSE(plan.assemblable);
  ASSERT_EQ(plan.base_pins.size(), 1u);
  EXPECT_TRUE(plan.base_pins[0].clear);
  ASSERT_EQ(plan.steps.size(), 1u);
  EXPECT_EQ(a.part(plan.steps[0].part).id, "latch");
  ASSERT_EQ(plan.steps[0].blocked_by.size(), 1u);
  const InsertionObstacle& o = plan.steps[0].blocked_by[0];
  std::vector<std::string> holes;
  for (const FeatureRef& h : o.pin) holes.push_back(a.FeatureName(h));
  EXPECT_EQ(holes, (std::vector<std::string>{"cheek_a/pivot", "cheek_b/pivot", "lever/pivot"}));
  EXPECT_EQ(o.pin, plan.base_pins[0].holes);
  EXPECT_NEAR(o.short_by, 28.0, 1e-9);
  EXPECT_NEAR(o.p_W.z(), 33.0, 1e-9);
  // Without the pin (implied pins off), nothing stops it.
  const std::string file =
      std::string(MECHANIST_SOURCE_DIR) + "/examples/clevis_latch_blocked_by_pin/assembly.json";
  const Assembly no_pin =
      LoadAssemblyText(Replace(ReadText(file), R"("steps": [)", R"("infer": {"implied_pins": false},
  "steps": [)"),
                       file);
  const AssemblyPlan clear = PlanAssembly(no_pin, Analyze(no_pin), CollisionModel(no_pin));
  EXPECT_TRUE(clear.base_pins.empty());
  ASSERT_EQ(clear.steps.size(), 1u);
  EXPECT_TRUE(clear.steps[0].clear);
}

TEST(FastenerChecks, BoltTooShortForItsNutIsReportedWithTheShortfall) {
  const std::string text = ReadText(kBracket);
  const std::string bolt =
      R"({"id": "bolt_left", "library": {"kind": "hex_bolt", "diameter": 6, "pitch": 1, "length": 16})";
  // 12 mm: the tip is 3 mm into the 5.2 mm nut.
  const Assembly partial = LoadAssemblyText(
      Replace(text, bolt, Replace(bolt, R"("length": 16)", R"("length": 12)")), kBracket);
  const Analysis an = Analyze(partial);
  const Diagnostic* d = Find(an, "bolt_too_short");
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->message.find("engages 3 mm"), std::string::npos) << d->message;
  EXPECT_NE(d->message.find("2.2 mm too short"), std::string::npos) << d->message;
  // 8 mm: the tip stops 1 mm above the nut.
  const Assembly missing = LoadAssemblyText(
      Replace(text, bolt, Replace(bolt, R"("length": 16)", R"("length": 8)")), kBracket);
  const Analysis an2 = Analyze(missing);
  d = Find(an2, "bolt_too_short");
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->message.find("does not reach"), std::string::npos) << d->message;
  EXPECT_NE(d->message.find("6.2 mm too short"), std::string::npos) << d->message;
  EXPECT_EQ(Find(an2, "nut_without_bolt"), nullptr) << "the short bolt is named instead";
  EXPECT_EQ(Find(Analyze(LoadAssembly(kBracket)), "bolt_too_short"), nullptr);
}

TEST(FastenerChecks, NutWithoutBoltAndLooseOnlyFastening) {
  std::string text = ReadText(kBracket);
  text = Replace(
      text,
      R"(    {"id": "bolt_right", "library": {"kind": "hex_bolt", "diameter": 6, "pitch": 1, "length": 16},
     "place": [{"insert": "bolt_right/thread", "into": "bracket_right/base_hole1"},
               {"against": "bolt_right/head", "on": "bracket_right/base_top"}]},)",
      "");
  text = Replace(text, R"({"insert": "nut_right/thread", "into": "bolt_right/thread"})",
                 R"({"insert": "nut_right/thread", "into": "plate/hole_right"})");
  text = Replace(text, R"(,
    {"insert": "bolt_right/thread", "into": "bracket_right/base_hole1"})",
                 "");
  text = Replace(text, R"("bolt_left", "bolt_right",)", R"("bolt_left",)");
  text =
      Replace(text, R"({"pair": ["bolt_right/thread", "nut_right/thread"], "type": "fixed"},)", "");
  const Analysis an = Analyze(LoadAssemblyText(text, kBracket));
  const Diagnostic* d = Find(an, "nut_without_bolt");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->parts, std::vector<std::string>{"nut_right"});

  const std::string loose = Replace(
      ReadText(kBracket),
      R"({"id": "bolt_left", "library": {"kind": "hex_bolt", "diameter": 6, "pitch": 1, "length": 16},)",
      R"({"id": "bolt_left", "library": {"kind": "hex_bolt", "diameter": 6, "pitch": 1, "length": 16, "fastening": "loose"},)");
  const Analysis an2 = Analyze(LoadAssemblyText(loose, kBracket));
  d = Find(an2, "loose_fastening_only");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->parts, std::vector<std::string>{"bolt_left"});
}

}  // namespace
}  // namespace mechanist
