// Separate pins held in a housing's holes become the housing's pin ring: evenly on one circle,
// one diameter, on the host that holds the most of them; never from written features.

#include "reasoning/pin_ring_inference.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_assembly.h"

namespace mechanist {
namespace {

using testing::MakeFeature;
using testing::MakePart;
using V = Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;

// `count` pins of 4 mm, 20 long from z = 0, on a 30 mm circle about z, each a part; a host
// per entry of `hosts` with a 4 mm hole under every pin (from z = `z` to z + 5).
std::vector<Part> Pins(int count, const std::vector<std::pair<std::string, double>>& hosts) {
  std::vector<Part> parts;
  for (const auto& [id, z] : hosts) {
    std::vector<Feature> holes;
    for (int k = 0; k < count; ++k) {
      const double a = 2 * kPi * k / count;
      holes.push_back(MakeFeature("hole_" + std::to_string(k + 1), FeatureKind::kHole,
                                  V(15 * std::cos(a), 15 * std::sin(a), z), V::UnitZ(),
                                  [](Feature& f) {
                                    f.diameter = 4;
                                    f.length = 5;
                                  }));
    }
    parts.push_back(MakePart(id, holes));
  }
  for (int k = 0; k < count; ++k) {
    const double a = 2 * kPi * k / count;
    parts.push_back(
        MakePart("pin" + std::to_string(k + 1),
                 {MakeFeature("shaft", FeatureKind::kShaft, V::Zero(), V::UnitZ(),
                              [](Feature& f) {
                                f.diameter = 4;
                                f.length = 20;
                              })},
                 RigidTransform::Translation(V(15 * std::cos(a), 15 * std::sin(a), 0))));
  }
  return parts;
}

const auto kAll = [](std::size_t, std::size_t) { return true; };

TEST(InferPinRingsOfParts, PinsHeldByTwoPartsRingTheFirstOfThem) {
  // A housing (holes at z 0..5) and a cover (z 15..20) both hold the 5 pins: the ring goes
  // to the housing, the first in the file, once.
  std::vector<Part> parts = Pins(5, {{"housing", 0.0}, {"cover", 15.0}});
  const std::vector<Diagnostic> found = InferPinRingsOfParts(&parts, 0.05, 0.01, kAll);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].code, "pin_ring_of_parts");
  EXPECT_EQ(found[0].features, std::vector<std::string>{"housing/pins_1"});
  ASSERT_TRUE(parts[0].FindFeature("pins_1").has_value());
  EXPECT_FALSE(parts[1].FindFeature("pins_1").has_value());
  const Feature& ring = parts[0].features.back();
  EXPECT_EQ(ring.teeth, 5);
  EXPECT_NEAR(ring.diameter, 30, 1e-9);
  EXPECT_NEAR(ring.pin_diameter, 4, 1e-9);
  EXPECT_NEAR(ring.length, 20, 1e-9);
  EXPECT_LT(ring.origin.norm(), 1e-9);
}

TEST(InferPinRingsOfParts, NotFromWrittenFeaturesNorFromTwoPins) {
  std::vector<Part> written = Pins(5, {{"housing", 0.0}});
  EXPECT_TRUE(InferPinRingsOfParts(&written, 0.05, 0.01, [](std::size_t, std::size_t) {
                return false;
              }).empty());
  std::vector<Part> two = Pins(2, {{"housing", 0.0}});
  EXPECT_TRUE(InferPinRingsOfParts(&two, 0.05, 0.01, kAll).empty());
  // One pin of six thicker than the others: the five of one diameter leave a gap, no ring.
  std::vector<Part> odd = Pins(6, {{"housing", 0.0}});
  odd[1].features[0].diameter = 4.2;
  EXPECT_TRUE(InferPinRingsOfParts(&odd, 0.05, 0.01, kAll).empty());
  // Alternate pins of two diameters: two rings of three, each of one diameter.
  std::vector<Part> mixed = Pins(6, {{"housing", 0.0}});
  for (std::size_t p = 1; p < mixed.size(); p += 2) mixed[p].features[0].diameter = 4.2;
  const std::vector<Diagnostic> rings = InferPinRingsOfParts(&mixed, 0.05, 0.01, kAll);
  ASSERT_EQ(rings.size(), 2u);
  EXPECT_EQ(rings[1].features, std::vector<std::string>{"housing/pins_2"});
  EXPECT_EQ(mixed[0].features.back().teeth, 3);
}

}  // namespace
}  // namespace mechanist
