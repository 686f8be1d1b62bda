// Parts in no pair sunk into another part (pair recognition's embedded parts), on unit cubes
// placed so that each overlap's depth is known: a cube shifted by s along x overlaps its
// neighbour by 1 - s.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "reasoning/analysis.h"
#include "reasoning/pair_recognition.h"
#include "test_assembly.h"

namespace mechanist {
namespace {

using testing::MakeAssembly;
using testing::MakeFeature;
using testing::MakePart;

// A cube's top face: no two cubes' tops face each other, so they make no planar pair.
std::vector<Feature> Top() {
  return {MakeFeature("top", FeatureKind::kFace, {0.5, 0.5, 1}, {0, 0, 1}, [](Feature& f) {
    f.width = 1;
    f.height = 1;
  })};
}

Part Cube(const std::string& id, Eigen::Vector3d at, bool ground = false) {
  return MakePart(id, Top(), RigidTransform(Eigen::Matrix3d::Identity(), at), ground);
}

const Diagnostic* Find(const std::vector<Diagnostic>& diagnostics, const std::string& code) {
  const auto it = std::find_if(diagnostics.begin(), diagnostics.end(),
                               [&](const Diagnostic& d) { return d.code == code; });
  return it == diagnostics.end() ? nullptr : &*it;
}

TEST(EmbeddedParts, APartInNoPairSunkIntoAnotherIsFixedToIt) {
  // The connector goes 0.3 mm into the ground plate.
  const Assembly assembly =
      MakeAssembly({Cube("plate", {0, 0, 0}, /*ground=*/true), Cube("connector", {0.7, 0, 0})});
  const Recognition r = RecognizePairs(assembly);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_EQ(r.pairs[0].type, PairType::kFixed);
  EXPECT_EQ(r.pairs[0].source, PairSource::kEmbedded);
  EXPECT_EQ(assembly.PartId(r.pairs[0].a.part), "connector");
  EXPECT_EQ(assembly.PartId(r.pairs[0].b.part), "plate");
  const Diagnostic* info = Find(r.diagnostics, "embedded");
  ASSERT_NE(info, nullptr);
  EXPECT_EQ(info->severity, Severity::kInfo);
  EXPECT_NE(info->message.find("lies 0.3 mm deep in 'plate'"), std::string::npos) << info->message;
  EXPECT_EQ(Find(r.diagnostics, "part_unconnected"), nullptr);
  EXPECT_EQ(Analyze(assembly).motion.mobility.dof, 0);
}

TEST(EmbeddedParts, APartOnlyTouchingAnotherStaysUnconnected) {
  const Assembly assembly =
      MakeAssembly({Cube("plate", {0, 0, 0}, /*ground=*/true), Cube("connector", {1.0, 0, 0})});
  const Recognition r = RecognizePairs(assembly);
  EXPECT_TRUE(r.pairs.empty());
  EXPECT_NE(Find(r.diagnostics, "part_unconnected"), nullptr);
  EXPECT_EQ(Analyze(assembly).motion.mobility.dof, 6);
}

TEST(EmbeddedParts, APartSunkIntoTwoIsFixedToTheDeeper) {
  // 0.1 mm into the left block, 0.4 mm into the one behind.
  const Assembly assembly =
      MakeAssembly({Cube("left", {-0.9, 0, 0}, /*ground=*/true),
                    Cube("behind", {0, 0.6, 0}, /*ground=*/true), Cube("connector", {0, 0, 0})});
  const Recognition r = RecognizePairs(assembly);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_EQ(assembly.PartId(r.pairs[0].b.part), "behind");
  const Diagnostic* info = Find(r.diagnostics, "embedded");
  ASSERT_NE(info, nullptr);
  EXPECT_NE(info->message.find("0.4 mm deep in 'behind'"), std::string::npos) << info->message;
}

TEST(EmbeddedParts, PartsSunkIntoOneHostShareOneInfo) {
  const Assembly assembly = MakeAssembly(
      {Cube("plate", {0, 0, 0}, /*ground=*/true), Cube("a", {0.8, 0, 0}), Cube("b", {-0.6, 0, 0})});
  const Recognition r = RecognizePairs(assembly);
  ASSERT_EQ(r.pairs.size(), 2u);
  const Diagnostic* info = Find(r.diagnostics, "embedded");
  ASSERT_NE(info, nullptr);
  EXPECT_NE(info->message.find("parts 'a', 'b' are in no pair but lie up to 0.4 mm deep in "
                               "'plate'"),
            std::string::npos)
      << info->message;
  EXPECT_EQ(std::count_if(r.diagnostics.begin(), r.diagnostics.end(),
                          [](const Diagnostic& d) { return d.code == "embedded"; }),
            1);
}

TEST(EmbeddedParts, TheFileCanTurnItOff) {
  AssemblySpec spec;
  spec.name = "off";
  spec.parts = {Cube("plate", {0, 0, 0}, /*ground=*/true), Cube("connector", {0.7, 0, 0})};
  spec.inference.embedded_parts = false;
  const Recognition r = RecognizePairs(Assembly(std::move(spec)));
  EXPECT_TRUE(r.pairs.empty());
  EXPECT_NE(Find(r.diagnostics, "part_unconnected"), nullptr);
}

TEST(EmbeddedParts, APartThatIsInAPairIsLeftAsItIs) {
  // The connector sits on a pin of the plate and overlaps it: the pin, not the overlap, holds it.
  std::vector<Feature> plate = Top();
  plate.push_back(
      MakeFeature("pin", FeatureKind::kShaft, {0.85, 0.5, 0}, {0, 0, 1}, [](Feature& f) {
        f.diameter = 0.2;
        f.length = 1;
      }));
  std::vector<Feature> connector = Top();
  connector.push_back(
      MakeFeature("bore", FeatureKind::kHole, {0.15, 0.5, 0}, {0, 0, 1}, [](Feature& f) {
        f.diameter = 0.2;
        f.length = 1;
        f.through = true;
      }));
  const Assembly assembly = MakeAssembly(
      {MakePart("plate", plate, RigidTransform(), /*ground=*/true),
       MakePart("connector", connector,
                RigidTransform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.7, 0, 0)))});
  const Recognition r = RecognizePairs(assembly);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_NE(r.pairs[0].source, PairSource::kEmbedded);
  EXPECT_EQ(Find(r.diagnostics, "embedded"), nullptr);
}

}  // namespace
}  // namespace mechanist
