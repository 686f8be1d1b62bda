// Floating parts centred on another part's axis (CentreFloatingParts), on kinematic sketches
// without meshes, so that only the features say where a part stands.

#include "reasoning/centred_parts.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "reasoning/analysis.h"
#include "reasoning/pair_recognition.h"
#include "test_assembly.h"

namespace mechanist {
namespace {

using testing::MakeFeature;
using testing::MakePart;

Feature Round(const std::string& id, FeatureKind kind, Eigen::Vector3d origin, Eigen::Vector3d axis,
              double diameter, double length) {
  return MakeFeature(id, kind, origin, axis, [&](Feature& f) {
    f.diameter = diameter;
    f.length = length;
    f.through = kind == FeatureKind::kHole;
  });
}

Feature Face(const std::string& id, Eigen::Vector3d origin, Eigen::Vector3d normal, double size) {
  return MakeFeature(id, FeatureKind::kFace, origin, normal, [&](Feature& f) {
    f.width = size;
    f.height = size;
  });
}

Part Sketch(const std::string& id, std::vector<Feature> features, bool ground = false,
            Eigen::Vector3d at = Eigen::Vector3d::Zero()) {
  Part p =
      MakePart(id, std::move(features), RigidTransform(Eigen::Matrix3d::Identity(), at), ground);
  p.mesh = nullptr;  // features only
  p.mesh_source.clear();
  return p;
}

// A load cell (ground) with a 12 mm hole along y; an 8 mm push rod standing 7 mm into it,
// centred, touching nothing; a probe whose 12 mm hole takes the rod's other end, resting on
// the rod's end face. `rod_offset` moves the rod off the axis along x.
AssemblySpec PushRod(double rod_offset = 0.0) {
  AssemblySpec spec;
  spec.name = "push rod";
  spec.parts = {
      Sketch("cell", {Round("hole", FeatureKind::kHole, {0, 0, 0}, {0, 1, 0}, 12, 13)}, true),
      Sketch("rod",
             {Round("shaft", FeatureKind::kShaft, {0, -173, 0}, {0, 1, 0}, 8, 180),
              Face("end", {0, -173, 0}, {0, -1, 0}, 8)},
             false, {rod_offset, 0, 0}),
      Sketch("probe", {Round("hole", FeatureKind::kHole, {0, -151.5, 0}, {0, -1, 0}, 12, 21.5),
                       Face("seat", {0, -173, 0}, {0, 1, 0}, 12)})};
  return spec;
}

std::vector<const Pair*> Centred(const Analysis& analysis) {
  std::vector<const Pair*> out;
  for (const Pair& p : analysis.pairs) {
    if (p.source == PairSource::kCentred) out.push_back(&p);
  }
  return out;
}

std::vector<std::string> Messages(const Analysis& analysis, const std::string& code) {
  std::vector<std::string> out;
  for (const Diagnostic& d : analysis.diagnostics) {
    if (d.code == code) out.push_back(d.message);
  }
  return out;
}

TEST(CentredParts, AFloatingRodCentredInAHoleIsFixedThereAndAProbeOnItToTheRod) {
  const Assembly assembly(PushRod());
  const Analysis analysis = Analyze(assembly);
  const std::vector<const Pair*> centred = Centred(analysis);
  ASSERT_EQ(centred.size(), 2u);
  for (const Pair* p : centred) {
    EXPECT_EQ(p->type, PairType::kFixed);
    EXPECT_EQ(assembly.FeatureName(p->a), "rod/shaft");  // the shaft first
  }
  EXPECT_EQ(assembly.FeatureName(centred[0]->b), "cell/hole");
  EXPECT_EQ(assembly.FeatureName(centred[1]->b), "probe/hole");
  EXPECT_EQ(analysis.motion.mobility.dof, 0);
  // In report order: by features, the rod's (cell/hole) before the probe's (probe/hole).
  const std::vector<std::string> infos = Messages(analysis, "centred");
  ASSERT_EQ(infos.size(), 2u);
  EXPECT_NE(infos[0].find(
                "part 'rod' is held to the rest by nothing but face contacts, but rod/shaft (8 mm) "
                "stands centred in cell/hole (12 mm), 2 mm of radial clearance"),
            std::string::npos)
      << infos[0];
  EXPECT_NE(
      infos[1].find("part 'probe' is held to the rest by nothing but face contacts, but probe/hole "
                    "(12 mm) stands centred on rod/shaft (8 mm), 2 mm of radial clearance"),
      std::string::npos)
      << infos[1];
}

TEST(CentredParts, ARodInNoPairIsNoLongerReportedUnconnected) {
  AssemblySpec spec = PushRod();
  spec.parts.pop_back();  // no probe: the rod touches nothing
  const Assembly assembly(std::move(spec));
  ASSERT_EQ(RecognizePairs(assembly).diagnostics.size(), 1u);  // part_unconnected: rod
  const Analysis analysis = Analyze(assembly);
  EXPECT_TRUE(Messages(analysis, "part_unconnected").empty());
  const std::vector<std::string> infos = Messages(analysis, "centred");
  ASSERT_EQ(infos.size(), 1u);
  EXPECT_NE(infos[0].find("part 'rod' is held to the rest by no pair, but"), std::string::npos)
      << infos[0];
  EXPECT_EQ(analysis.motion.mobility.dof, 0);
}

TEST(CentredParts, TheFileCanTurnItOff) {
  AssemblySpec spec = PushRod();
  spec.inference.centred_parts = false;
  const Analysis analysis = Analyze(Assembly(std::move(spec)));
  EXPECT_TRUE(Centred(analysis).empty());
  // The rod floats (6); the probe rests on its end (3).
  EXPECT_EQ(analysis.motion.mobility.dof, 9);
}

TEST(CentredParts, ARodOffTheHolesAxisIsNotCentred) {
  // 0.2 mm off, four times the length tolerance: the probe's hole still takes the rod.
  const Assembly assembly(PushRod(0.2));
  const Analysis analysis = Analyze(assembly);
  EXPECT_TRUE(Centred(analysis).empty());
  EXPECT_EQ(analysis.motion.mobility.dof, 9);
}

TEST(CentredParts, ASleeveLooseBetweenATurningShaftAndItsHousingIsFixedToOneOfThem) {
  // The journal slides and turns in the housing's bore; the sleeve stands centred both on the
  // journal (14 mm on 10 mm) and in the housing's counterbore (16 mm in 20 mm). Fixed to both,
  // it would lock the journal.
  AssemblySpec spec;
  spec.name = "sleeve";
  spec.parts = {
      Sketch("housing",
             {Round("bore", FeatureKind::kHole, {0, 0, 0}, {0, 0, 1}, 10, 40),
              Round("counterbore", FeatureKind::kHole, {0, 0, 40}, {0, 0, 1}, 20, 10)},
             true),
      Sketch("journal", {Round("shaft", FeatureKind::kShaft, {0, 0, 0}, {0, 0, 1}, 10, 60)}),
      Sketch("sleeve", {Round("hole", FeatureKind::kHole, {0, 0, 42}, {0, 0, 1}, 14, 6),
                        Round("shaft", FeatureKind::kShaft, {0, 0, 42}, {0, 0, 1}, 16, 6)})};
  const Analysis analysis = Analyze(Assembly(std::move(spec)));
  EXPECT_EQ(Centred(analysis).size(), 1u);
  EXPECT_EQ(analysis.motion.mobility.dof, 2);  // the journal's cylindrical pair
}

}  // namespace
}  // namespace mechanist
