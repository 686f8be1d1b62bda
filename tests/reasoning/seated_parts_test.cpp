// Slides that the parts around stop within a small play (SeatParts, through Analyze): a block
// in a pocket and a link on a pin between cheeks, built from boxes with the gaps known, so the
// play each must report is the sum of the two gaps.

#include "reasoning/seated_parts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "reasoning/analysis.h"
#include "test_assembly.h"

namespace mechanist {
namespace {

using testing::MakeFeature;
using K = FeatureKind;
using Box = std::array<Eigen::Vector3d, 2>;  // min, max corners

// Closed boxes in one mesh, in world coordinates (the parts stand at the identity).
std::shared_ptr<const TriangleMesh> Boxes(const std::vector<Box>& boxes) {
  auto mesh = std::make_shared<TriangleMesh>();
  for (const Box& b : boxes) {
    const int first = static_cast<int>(mesh->vertices.size());
    for (int i = 0; i < 8; ++i) {
      mesh->vertices.emplace_back(i & 1 ? b[1].x() : b[0].x(), i & 2 ? b[1].y() : b[0].y(),
                                  i & 4 ? b[1].z() : b[0].z());
    }
    for (const auto& [i, j, k] : std::vector<std::array<int, 3>>{{0, 2, 1},
                                                                 {1, 2, 3},
                                                                 {4, 5, 6},
                                                                 {5, 7, 6},
                                                                 {0, 1, 4},
                                                                 {1, 5, 4},
                                                                 {2, 6, 3},
                                                                 {3, 6, 7},
                                                                 {0, 4, 2},
                                                                 {2, 4, 6},
                                                                 {1, 3, 5},
                                                                 {3, 7, 5}}) {
      mesh->faces.push_back({first + i, first + j, first + k});
    }
  }
  return mesh;
}

Part MeshPart(const std::string& id, std::vector<Feature> features, std::vector<Box> boxes,
              bool ground = false) {
  Part p;
  p.id = id;
  p.mesh = Boxes(boxes);
  p.mesh_source = "test:" + id;
  p.ground = ground;
  p.features = std::move(features);
  return p;
}

Feature Face(const std::string& id, Eigen::Vector3d origin, Eigen::Vector3d normal, double width,
             double height) {
  return MakeFeature(id, K::kFace, origin, normal, [&](Feature& f) {
    f.width = width;
    f.height = height;
  });
}

// A 10 mm block on a tray's floor, against its side wall (x = 0), between two end walls
// `before` and `after` mm clear of it along y: only the slide along y is left by the faces.
Assembly BlockInPocket(double before, double after, bool infer = true) {
  AssemblySpec spec;
  spec.name = "pocket";
  spec.inference.seated_parts = infer;
  spec.parts.push_back(MeshPart(
      "tray",
      {Face("floor", {5, 10, 0}, {0, 0, 1}, 60, 60), Face("wall", {0, 10, 2.5}, {1, 0, 0}, 60, 5)},
      {{Eigen::Vector3d(-5, -20, -5), Eigen::Vector3d(30, 40, 0)},
       {Eigen::Vector3d(-5, -20, 0), Eigen::Vector3d(0, 40, 5)},
       {Eigen::Vector3d(1, -20, 0), Eigen::Vector3d(9, -before, 5)},
       {Eigen::Vector3d(1, 10 + after, 0), Eigen::Vector3d(9, 40, 5)}},
      /*ground=*/true));
  spec.parts.push_back(MeshPart(
      "block",
      {Face("bottom", {5, 5, 0}, {0, 0, -1}, 10, 10), Face("side", {0, 5, 2.5}, {-1, 0, 0}, 10, 5)},
      {{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 10, 10)}}));
  return Assembly(std::move(spec));
}

// A square link (a 2.02 mm bore, drawn square) on a 2 mm pin along y, between the fork's two
// cheeks `gap` mm clear of it on each side.
Assembly LinkOnPin(double gap) {
  AssemblySpec spec;
  spec.name = "fork";
  spec.parts.push_back(MeshPart("fork",
                                {MakeFeature("pin", K::kShaft, {0, -10, 0}, {0, 1, 0},
                                             [](Feature& f) {
                                               f.diameter = 2;
                                               f.length = 20;
                                             })},
                                {{Eigen::Vector3d(-1, -10, -1), Eigen::Vector3d(1, 10, 1)},
                                 {Eigen::Vector3d(-6, 2 + gap, -6), Eigen::Vector3d(6, 6, 6)},
                                 {Eigen::Vector3d(-6, -6, -6), Eigen::Vector3d(6, -2 - gap, 6)}},
                                /*ground=*/true));
  const double r = 1.01;
  spec.parts.push_back(MeshPart("link",
                                {MakeFeature("bore", K::kHole, {0, -2, 0}, {0, 1, 0},
                                             [](Feature& f) {
                                               f.diameter = 2.02;
                                               f.length = 4;
                                               f.through = true;
                                             })},
                                {{Eigen::Vector3d(-5, -2, -5), Eigen::Vector3d(-r, 2, 5)},
                                 {Eigen::Vector3d(r, -2, -5), Eigen::Vector3d(5, 2, 5)},
                                 {Eigen::Vector3d(-r, -2, -5), Eigen::Vector3d(r, 2, -r)},
                                 {Eigen::Vector3d(-r, -2, r), Eigen::Vector3d(r, 2, 5)}}));
  return Assembly(std::move(spec));
}

std::vector<const Diagnostic*> WithCode(const Analysis& an, const std::string& code) {
  std::vector<const Diagnostic*> found;
  for (const Diagnostic& d : an.diagnostics) {
    if (d.code == code) found.push_back(&d);
  }
  return found;
}

int CountSource(const Analysis& an, PairSource source, PairType type) {
  return static_cast<int>(std::count_if(an.pairs.begin(), an.pairs.end(), [&](const Pair& p) {
    return p.source == source && p.type == type;
  }));
}

TEST(SeatedParts, ABlockInAPocketWithLittlePlayIsSeated) {
  const Assembly a = BlockInPocket(0.2, 0.3);
  const Analysis an = Analyze(a);
  EXPECT_EQ(an.motion.mobility.dof, 0);
  EXPECT_EQ(CountSource(an, PairSource::kSeated, PairType::kFixed), 1);
  EXPECT_EQ(std::count_if(an.pairs.begin(), an.pairs.end(),
                          [](const Pair& p) { return p.type == PairType::kPlanar; }),
            0);
  const std::vector<const Diagnostic*> seated = WithCode(an, "seated");
  ASSERT_EQ(seated.size(), 1u);
  EXPECT_EQ(seated[0]->severity, Severity::kInfo);
  EXPECT_EQ(seated[0]->parts, (std::vector<std::string>{"block", "tray"}));
  // The play is the two gaps' sum.
  EXPECT_NE(seated[0]->message.find("within 0.5 mm"), std::string::npos) << seated[0]->message;
  EXPECT_TRUE(WithCode(an, "free_motion").empty());
}

TEST(SeatedParts, ABlockWithRoomToSlideOrOnlyOneStopKeepsItsSlide) {
  for (const auto& [before, after] : {std::pair{0.6, 0.6}, std::pair{0.2, 30.0}}) {
    const Analysis an = Analyze(BlockInPocket(before, after));
    EXPECT_EQ(an.motion.mobility.dof, 1) << before << " " << after;
    EXPECT_TRUE(WithCode(an, "seated").empty());
    EXPECT_EQ(CountSource(an, PairSource::kSeated, PairType::kFixed), 0);
  }
}

TEST(SeatedParts, TheFilesInferSwitchLeavesTheSlide) {
  const Analysis an = Analyze(BlockInPocket(0.2, 0.3, /*infer=*/false));
  EXPECT_EQ(an.motion.mobility.dof, 1);
  EXPECT_TRUE(WithCode(an, "seated").empty());
}

TEST(SeatedParts, ABlockOnAFloorAloneIsNotSeated) {
  // Without the side wall the faces leave two slides and a turn: nothing to settle.
  AssemblySpec spec = BlockInPocket(0.2, 0.3).spec();
  spec.parts[1].features.pop_back();
  const Analysis an = Analyze(Assembly(std::move(spec)));
  EXPECT_EQ(an.motion.mobility.dof, 3);
  EXPECT_TRUE(WithCode(an, "seated").empty());
}

TEST(SeatedParts, BlocksInTwoPocketsAreEachSeated) {
  // Two candidates, swept at once (on two cores where there are two): each seated, with its
  // own play, reported per tray in the order of the parts.
  AssemblySpec spec = BlockInPocket(0.2, 0.3).spec();
  const Assembly second = BlockInPocket(0.1, 0.15);
  for (Part p : second.spec().parts) {
    p.id += "_2";
    p.X_WP = RigidTransform::Translation({100, 0, 0});
    spec.parts.push_back(p);
  }
  const Analysis an = Analyze(Assembly(std::move(spec)));
  EXPECT_EQ(an.motion.mobility.dof, 0);
  EXPECT_EQ(CountSource(an, PairSource::kSeated, PairType::kFixed), 2);
  const std::vector<const Diagnostic*> seated = WithCode(an, "seated");
  ASSERT_EQ(seated.size(), 2u);
  EXPECT_EQ(seated[0]->parts, (std::vector<std::string>{"block", "tray"}));
  EXPECT_NE(seated[0]->message.find("within 0.5 mm"), std::string::npos) << seated[0]->message;
  EXPECT_EQ(seated[1]->parts, (std::vector<std::string>{"block_2", "tray_2"}));
  EXPECT_NE(seated[1]->message.find("within 0.25 mm"), std::string::npos) << seated[1]->message;
}

TEST(SeatedParts, ABlockInAPocketOfASlidingTrayIsSeatedOnce) {
  // The tray slides on a base (a planar pair), so both it and the block move: the block on
  // the tray and the tray on the block are both candidates, with the same pairs. The first
  // seats them; the second is not taken again.
  AssemblySpec spec = BlockInPocket(0.2, 0.3).spec();
  spec.parts[0].ground = false;
  spec.parts[0].features.push_back(Face("underside", {5, 10, -5}, {0, 0, -1}, 60, 60));
  spec.parts.push_back(MeshPart("base", {Face("top", {5, 10, -5}, {0, 0, 1}, 100, 100)},
                                {{Eigen::Vector3d(-40, -40, -10), Eigen::Vector3d(60, 60, -5)}},
                                /*ground=*/true));
  const Analysis an = Analyze(Assembly(std::move(spec)));
  EXPECT_EQ(CountSource(an, PairSource::kSeated, PairType::kFixed), 1);
  const std::vector<const Diagnostic*> seated = WithCode(an, "seated");
  ASSERT_EQ(seated.size(), 1u);
  EXPECT_EQ(seated[0]->parts, (std::vector<std::string>{"block", "tray"}));
  EXPECT_EQ(an.motion.mobility.dof, 3) << "the tray's slides and turn on the base";
}

TEST(SeatedParts, ALinkOnAPinBetweenCheeksTurnsOnly) {
  const Analysis held = Analyze(LinkOnPin(0.25));
  EXPECT_EQ(held.motion.mobility.dof, 1);
  EXPECT_EQ(CountSource(held, PairSource::kSeated, PairType::kRevolute), 1);
  const std::vector<const Diagnostic*> retained = WithCode(held, "retained");
  ASSERT_EQ(retained.size(), 1u);
  EXPECT_EQ(retained[0]->parts, (std::vector<std::string>{"link", "fork"}));
  EXPECT_NE(retained[0]->message.find("within 0.5 mm"), std::string::npos) << retained[0]->message;

  const Analysis loose = Analyze(LinkOnPin(2.0));
  EXPECT_EQ(loose.motion.mobility.dof, 2);
  EXPECT_TRUE(WithCode(loose, "retained").empty());
}

}  // namespace
}  // namespace mechanist
