// The screw-in-a-plain-hole heuristic of CAD imports without modelled threads: a head and a
// shank whose tip ends inside another part's hole is screwed there and clamps what it passes;
// a motor with its shaft, a stepped shaft and a screw whose tip comes out of the last hole,
// wider than it, are not.

#include "reasoning/fastener_inference.h"

#include <gtest/gtest.h>

#include "kernel/mesh/mesh_builder.h"
#include "reasoning/analysis.h"
#include "test_assembly.h"

namespace mechanist {
namespace {

using testing::MakeFeature;
using testing::MakePart;
const Eigen::Vector3d kDown(0, 0, -1);

// The closed cylinders (radius, z0, z1) about the z axis, as one mesh.
std::shared_ptr<const TriangleMesh> Cylinders(const std::vector<std::array<double, 3>>& cylinders) {
  auto mesh = std::make_shared<TriangleMesh>();
  for (const auto& [r, z0, z1] : cylinders) {
    const TriangleMesh c =
        ExtrudeRegion(Region2d{CircleRing(Eigen::Vector2d::Zero(), r, 32), {}}, z0, z1);
    const auto base = static_cast<std::int32_t>(mesh->vertices.size());
    mesh->vertices.insert(mesh->vertices.end(), c.vertices.begin(), c.vertices.end());
    for (const auto& f : c.faces) mesh->faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  }
  return mesh;
}

Feature Cylinder(const std::string& id, FeatureKind kind, double z_top, double diameter,
                 double length) {
  return MakeFeature(id, kind, {0, 0, z_top}, kDown, [&](Feature& f) {
    f.diameter = diameter;
    f.length = length;
    f.through = kind == FeatureKind::kHole;
  });
}

// A screw (head 8 x 3 above z = 10, shank 4 down to z = 10 - shank), a cover (clearance hole
// 4.4, z 5 to 10) and a housing, ground, with a plain hole of 4.2 from z = 5 down to
// z = 5 - depth.
std::vector<Part> Parts(double shank, double depth, double head_length = 3,
                        double head_diameter = 8) {
  Part screw = MakePart(
      "screw", {Cylinder("head", FeatureKind::kShaft, 10 + head_length, head_diameter, head_length),
                Cylinder("shank", FeatureKind::kShaft, 10, 4, shank)});
  screw.mesh = Cylinders({{head_diameter / 2, 10, 10 + head_length}, {2, 10 - shank, 10}});
  return {screw, MakePart("cover", {Cylinder("bore", FeatureKind::kHole, 10, 4.4, 5)}),
          MakePart("housing", {Cylinder("hole", FeatureKind::kHole, 5, 4.2, depth)},
                   RigidTransform(), true)};
}

std::vector<Diagnostic> Infer(std::vector<Part>* parts) {
  return InferScrewsInPlainHoles(parts, 0.05, 0.5 * 3.14159265358979 / 180,
                                 [](std::size_t, std::size_t) { return true; });
}

TEST(ScrewsInPlainHoles, AScrewEndingInAHousingsHoleIsScrewedThereAndClampsTheCover) {
  std::vector<Part> parts = Parts(16, 15);
  const std::vector<Diagnostic> found = Infer(&parts);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].code, "screw_in_plain_hole");
  EXPECT_EQ(found[0].parts, (std::vector<std::string>{"screw", "housing"}));
  const Feature& hole = parts[2].features[0];
  EXPECT_EQ(hole.kind, FeatureKind::kTappedHole);
  EXPECT_DOUBLE_EQ(hole.diameter, 4.0);
  EXPECT_EQ(hole.fastening, Fastening::kTight);
  EXPECT_EQ(parts[0].features[1].kind, FeatureKind::kThread);
  EXPECT_DOUBLE_EQ(parts[0].features[1].pitch, 0.7);         // M4 coarse
  EXPECT_EQ(parts[1].features[0].kind, FeatureKind::kHole);  // the cover's clearance hole
  // Screw and cover are fastened to the housing: one rigid body.
  const Analysis an = Analyze(testing::MakeAssembly(parts));
  EXPECT_EQ(an.motion.mobility.dof, 0);
}

TEST(ScrewsInPlainHoles, ScrewsThatReadAlikeAreOneFinding) {
  // Two screws through the cover's clearance holes into the housing's plain holes, 20 mm
  // apart, and a third into a wider hole of the housing: one finding for the two alike.
  const auto build = [] {
    std::vector<Part> parts = Parts(16, 15);
    Part second = parts[0], third = parts[0];
    second.id = "screw_2";
    second.X_WP = RigidTransform::Translation({20, 0, 0});
    third.id = "screw_3";
    third.X_WP = RigidTransform::Translation({40, 0, 0});
    parts[1].features.push_back(Cylinder("bore_2", FeatureKind::kHole, 10, 4.4, 5));
    parts[1].features.back().origin.x() = 20;
    for (auto [id, x, diameter] : {std::tuple{"hole_2", 20.0, 4.2}, {"hole_3", 40.0, 4.4}}) {
      parts[2].features.push_back(Cylinder(id, FeatureKind::kHole, 5, diameter, 15));
      parts[2].features.back().origin.x() = x;
    }
    parts.push_back(second);
    parts.push_back(third);
    return parts;
  };
  std::vector<Part> parts = build();
  const std::vector<Diagnostic> found = Infer(&parts);
  // The file's order of parts changes nothing.
  std::vector<Part> reversed = build();
  std::reverse(reversed.begin(), reversed.end());
  const std::vector<Diagnostic> found_reversed = Infer(&reversed);
  ASSERT_EQ(found_reversed.size(), found.size());
  for (std::size_t k = 0; k < found.size(); ++k) {
    EXPECT_EQ(found_reversed[k].message, found[k].message);
  }
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].message,
            "2 parts, 'screw', 'screw_2' (each a head and a 4 mm shank) end, one each, in "
            "'housing/hole', 'housing/hole_2' (4.2 mm): taken as screwed into them, tight threads "
            "of pitch 0.7 mm (heuristic: the file models no thread)");
  EXPECT_EQ(found[0].parts, (std::vector<std::string>{"screw", "screw_2", "housing"}));
  EXPECT_EQ(found[0].features, (std::vector<std::string>{"screw/shank", "housing/hole",
                                                         "screw_2/shank", "housing/hole_2"}));
  EXPECT_EQ(found[1].message.rfind("part 'screw_3' (a head and a 4 mm shank) ends in "
                                   "'housing/hole_3' (4.4 mm): taken as screwed into it, a tight "
                                   "thread",
                                   0),
            0u)
      << found[1].message;
}

TEST(ScrewsInPlainHoles, AHeadThatIsNoCylinderAndHolesDrilledAtTheTapSize) {
  // A domed or cross-recessed head gives no cylinder: only the mesh shows it (8 wide over 3 at
  // one end, the tip 4 wide). The shank runs through a stator into a housing, both drilled at
  // the M4 tap size (3.3 mm): threaded in both, so all three are one piece.
  std::vector<Part> parts = Parts(16, 15);
  parts[0].features.erase(parts[0].features.begin());  // the head's cylinder is not found
  parts[1] = MakePart("stator", {Cylinder("bore", FeatureKind::kHole, 10, 3.3, 5)});
  parts[2].features[0].diameter = 3.3;
  const std::vector<Diagnostic> found = Infer(&parts);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].parts, (std::vector<std::string>{"screw", "housing", "stator"}));
  EXPECT_EQ(found[0].features,
            (std::vector<std::string>{"screw/shank", "housing/hole", "stator/bore"}));
  EXPECT_NE(found[0].message.find("ends in 'housing/hole' (3.3 mm)"), std::string::npos)
      << found[0].message;
  EXPECT_NE(found[0].message.find("also threaded through 'stator/bore' (3.3 mm)"),
            std::string::npos)
      << found[0].message;
  for (const Part* p : {&parts[1], &parts[2]}) {
    EXPECT_EQ(p->features[0].kind, FeatureKind::kTappedHole) << p->id;
    EXPECT_DOUBLE_EQ(p->features[0].diameter, 4.0) << p->id;
  }
  EXPECT_EQ(Analyze(testing::MakeAssembly(parts)).motion.mobility.dof, 0);
  // A hole under 75% of the shank is no tap drill: nothing is inferred.
  std::vector<Part> narrow = Parts(16, 15);
  narrow[0].features.erase(narrow[0].features.begin());
  narrow[2].features[0].diameter = 2.9;
  EXPECT_TRUE(Infer(&narrow).empty());
}

TEST(ScrewsInPlainHoles, ALongHoleTakesAScrewAtEachEnd) {
  // The housing's hole runs 60 mm (z 5 to -55), like an extrusion's core: the first screw taps
  // it from the top, and a second one, turned over under the housing (its head's underside at
  // z = -55, its tip at -39), is screwed into the same hole from below.
  std::vector<Part> parts = Parts(16, 60);
  Part below = parts[0];
  below.id = "screw_below";
  below.X_WP = RigidTransform::Translation({0, 0, -45}) *
               RigidTransform::AxisAngle(Eigen::Vector3d::UnitX(), 3.14159265358979);
  parts.push_back(below);
  const std::vector<Diagnostic> found = Infer(&parts);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[1].parts, (std::vector<std::string>{"screw_below", "housing"}));
  EXPECT_EQ(parts[3].features[1].kind, FeatureKind::kThread);
  EXPECT_EQ(Analyze(testing::MakeAssembly(parts)).motion.mobility.dof, 0);
}

TEST(ScrewsInPlainHoles, AScrewComingOutThroughANarrowerHoleIsScrewedThere) {
  // The tip comes out 5 mm past a hole drilled at the M4 tap size (3.3 mm, z 5 to -1), as
  // through a nut: the shank can only pass it threaded.
  std::vector<Part> parts = Parts(16, 6);
  parts[2].features[0].diameter = 3.3;
  const std::vector<Diagnostic> found = Infer(&parts);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NE(found[0].message.find("comes out through the narrower 'housing/hole' (3.3 mm)"),
            std::string::npos)
      << found[0].message;
  EXPECT_EQ(parts[2].features[0].kind, FeatureKind::kTappedHole);
  EXPECT_EQ(Analyze(testing::MakeAssembly(parts)).motion.mobility.dof, 0);
}

TEST(ScrewsInPlainHoles, OnlyScrewsThatEndInsideTheirLastHole) {
  // The tip comes out of the housing's hole (z -6 below its end at -1), wider than the
  // shank: a pin, not a screw.
  std::vector<Part> through = Parts(16, 6);
  EXPECT_TRUE(Infer(&through).empty());
  // A stepped shaft: its wide part longer than its diameter.
  std::vector<Part> stepped = Parts(16, 15, 12);
  EXPECT_TRUE(Infer(&stepped).empty());
  // A motor: a body far wider than its shaft.
  std::vector<Part> motor = Parts(16, 15, 3, 40);
  EXPECT_TRUE(Infer(&motor).empty());
  // A head, but the body around it wider still (the part is not within the head's cylinder).
  std::vector<Part> flanged = Parts(16, 15);
  flanged[0].mesh = Cylinders({{4, 10, 13}, {2, -6, 10}, {9, 13, 14}});
  EXPECT_TRUE(Infer(&flanged).empty());
}

}  // namespace
}  // namespace mechanist
