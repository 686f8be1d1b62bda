// FindContacts on a pin line-on-line in a block's bore, both tessellated as a mesher does: the
// pin's vertices on its circle, the bore's facets chords inside it, so that the meshes overlap
// by the bore's sagitta r (1 - cos(pi / n)) where a pin vertex meets a chord's middle.

#include "reasoning/interference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "kernel/collision/collision_model.h"
#include "kernel/mesh/mesh_builder.h"
#include "reasoning/analysis.h"
#include "test_assembly.h"

namespace mechanist {
namespace {

using testing::MakeAssembly;
using testing::MakeFeature;
using testing::MakePart;

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 10.0;  // the pin's and the bore's, mm

// The sagitta of a regular n-gon's sides inscribed in the bore's circle, mm.
double Sagitta(int n) { return kRadius * (1 - std::cos(kPi / n)); }

// A 40 mm block (z 0..20, ground) with a bore of `bore_segments` facets whose mesh is said to
// lie within `deviation` mm of its surface, and of its circles within the sagitta of an
// `angle` (Part::mesh_angle), and a 48-facet pin (z -5..25) in it; the pin's vertex at 15
// degrees meets the middle of a 12-facet bore's side.
Assembly PinInBore(int bore_segments, double deviation, double angle = 0.0) {
  const Ring2d square = {{-20, -20}, {20, -20}, {20, 20}, {-20, 20}};
  Part block = MakePart("block",
                        {MakeFeature("bore", FeatureKind::kHole, {0, 0, 0}, {0, 0, 1},
                                     [](Feature& f) {
                                       f.diameter = 2 * kRadius;
                                       f.length = 20;
                                     })},
                        RigidTransform(), true);
  block.mesh = std::make_shared<const TriangleMesh>(
      ExtrudeRegion({square, {CircleRing({0, 0}, kRadius, bore_segments)}}, 0, 20));
  block.mesh_deviation = deviation;
  block.mesh_angle = angle;
  Part pin = MakePart(
      "pin", {MakeFeature("shaft", FeatureKind::kShaft, {0, 0, -5}, {0, 0, 1}, [&](Feature& f) {
        f.diameter = 2 * kRadius;
        f.length = 30;
      })});
  pin.mesh = std::make_shared<const TriangleMesh>(
      ExtrudeRegion({CircleRing({0, 0}, kRadius, 48), {}}, -5, 25));
  return MakeAssembly({block, pin});
}

// The verdict on the block and the pin, after checking that they are the only contact.
ContactVerdict Verdict(const Assembly& a) {
  const Analysis an = Analyze(a);
  EXPECT_EQ(an.pairs.size(), 1u);  // the pin in its bore
  const CollisionModel model(a);
  const std::vector<PartContact> contacts = FindContacts(a, InitialState(a), model, an.pairs);
  EXPECT_EQ(contacts.size(), 1u);
  return contacts.empty() ? ContactVerdict::kTouching : contacts.front().verdict;
}

TEST(Interference, ALineOnLinePinTouchesItsBoreWithinTheMeshesDeviation) {
  // The bore's mesh within its sagitta of the surface: the overlap is the tessellation's.
  EXPECT_EQ(Verdict(PinInBore(12, Sagitta(12))), ContactVerdict::kTouching);
  // A mesh said to be the geometry (a mesh file's): the same overlap is a clash.
  EXPECT_EQ(Verdict(PinInBore(12, 0.0)), ContactVerdict::kClash);
}

TEST(Interference, AnOverlapDeeperThanTheDeviationIsAClash) {
  // A hexagonal bore (sagitta 1.34 mm) said to lie within 0.34 mm of its surface.
  EXPECT_EQ(Verdict(PinInBore(6, Sagitta(12))), ContactVerdict::kClash);
}

TEST(Interference, ABoresOverlapIsBoundByTheMeshersAngle) {
  // A block said to lie within 5 mm of its faces (a large part's deflection), meshed at 0.3
  // rad: a 20 mm bore's facets lie within 0.11 mm of its circle, and the 0.34 mm overlap of
  // its 12 facets is a clash. Meshed at 30 degrees (12 facets), they lie within 0.34 mm.
  EXPECT_EQ(Verdict(PinInBore(12, 5.0, 0.3)), ContactVerdict::kClash);
  EXPECT_EQ(Verdict(PinInBore(12, 5.0, 2 * kPi / 12)), ContactVerdict::kTouching);
}

}  // namespace
}  // namespace mechanist
