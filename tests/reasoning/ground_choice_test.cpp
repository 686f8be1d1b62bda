// The ground chosen when a file fixes no part: the largest mesh volume, the first in the file
// among equals, never a compliant part; nothing changes when a part is ground.

#include "reasoning/ground_choice.h"

#include <gtest/gtest.h>

#include "kernel/mesh/mesh_builder.h"
#include "test_assembly.h"

namespace mechanist {
namespace {

using testing::MakePart;

Part Sphere(const std::string& id, double radius) {
  Part p = MakePart(id, {});
  p.mesh = std::make_shared<TriangleMesh>(MakeUvSphere(radius, 12, 24));
  return p;
}

TEST(ChooseGround, TakesTheLargestVolumeNotTheFirst) {
  // Volumes: the cube 1, the sphere of radius 1 about 4.2, that of radius 0.5 about 0.52.
  std::vector<Part> parts{MakePart("a_cube", {}), Sphere("b_big", 1.0), Sphere("c_small", 0.5)};
  const std::vector<Diagnostic> found = ChooseGround(&parts);
  EXPECT_FALSE(parts[0].ground);
  EXPECT_TRUE(parts[1].ground);
  EXPECT_FALSE(parts[2].ground);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].severity, Severity::kInfo);
  EXPECT_EQ(found[0].code, "ground_chosen");
  EXPECT_EQ(found[0].parts, std::vector<std::string>{"b_big"});
  EXPECT_NE(found[0].message.find("'b_big', the largest"), std::string::npos) << found[0].message;
}

TEST(ChooseGround, AFilesGroundStands) {
  std::vector<Part> parts{Sphere("big", 1.0), MakePart("base", {}, RigidTransform(), true)};
  EXPECT_TRUE(ChooseGround(&parts).empty());
  EXPECT_FALSE(parts[0].ground);
  EXPECT_TRUE(parts[1].ground);
}

TEST(ChooseGround, EqualVolumesTakeTheFirstAndSpringsAreNeverGround) {
  std::vector<Part> parts{Sphere("spring", 2.0), MakePart("x", {}), MakePart("y", {})};
  parts[0].compliant = true;
  ChooseGround(&parts);
  EXPECT_FALSE(parts[0].ground);
  EXPECT_TRUE(parts[1].ground);
  EXPECT_FALSE(parts[2].ground);
}

TEST(ChooseGround, FeaturesOnlyPartsTakeTheFirst) {
  std::vector<Part> parts{MakePart("sun", {}), MakePart("carrier", {})};
  for (Part& p : parts) p.mesh = std::make_shared<TriangleMesh>();
  ChooseGround(&parts);
  EXPECT_TRUE(parts[0].ground);
  EXPECT_FALSE(parts[1].ground);
}

TEST(ChooseGround, NoPartsNoFinding) {
  std::vector<Part> parts;
  EXPECT_TRUE(ChooseGround(&parts).empty());
}

}  // namespace
}  // namespace mechanist
