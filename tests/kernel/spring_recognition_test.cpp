// Helical springs recognised from their meshes: swept wires of known coil, wire, pitch and
// hand, turned to an arbitrary pose, open or closely wound; a tube, a washer and a gear are
// none.

#include "kernel/features/spring_recognition.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kernel/features/part_library.h"
#include "kernel/mesh/mesh_builder.h"
#include "spring_mesh.h"

namespace mechanist {
namespace {

TEST(SpringRecognition, SweptWiresGiveTheirCoilWirePitchAndHand) {
  struct Case {
    double R, d, p, turns;
    bool right;
  };
  const RigidTransform X(
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(2, -1, 1).normalized()).toRotationMatrix(),
      Eigen::Vector3d(5, 8, -3));
  for (const Case c :
       {Case{6, 1.5, 4, 8, true}, Case{10, 2, 3, 5.5, false}, Case{4, 0.8, 2.5, 12, true}}) {
    TriangleMesh mesh = testing::SpringMesh(c.R, c.d, c.p, c.turns, c.right);
    for (Eigen::Vector3d& v : mesh.vertices) v = X * v;
    const std::optional<HelicalSpring> s = RecognizeHelicalSpring(mesh);
    ASSERT_TRUE(s.has_value()) << c.R << " " << c.p;
    const Eigen::Vector3d axis = X.RotateDirection(Eigen::Vector3d::UnitZ());
    EXPECT_NEAR(std::abs(s->axis.dot(axis)), 1.0, 1e-3);
    EXPECT_NEAR(s->mean_diameter, 2 * c.R, 0.05 * c.d);
    EXPECT_NEAR(s->wire_diameter, c.d, 0.05 * c.d);
    EXPECT_NEAR(s->pitch, c.p, 0.01 * c.p);
    EXPECT_NEAR(s->turns, c.turns, 0.05);
    EXPECT_EQ(s->hand == Hand::kRight, c.right);  // whichever way the axis was found
  }
}

TEST(SpringRecognition, TubesWashersAndGearsAreNoSpring) {
  Region2d tube{CircleRing(Eigen::Vector2d::Zero(), 7, 48),
                {CircleRing(Eigen::Vector2d::Zero(), 5, 48)}};
  EXPECT_FALSE(RecognizeHelicalSpring(ExtrudeRegion(tube, 0, 30)).has_value());
  EXPECT_FALSE(RecognizeHelicalSpring(ExtrudeRegion(tube, 0, 1)).has_value());
  SpurGearSpec gear;
  gear.teeth = 30;
  gear.module = 1;
  gear.face_width = 8;
  gear.bore_diameter = 8;
  EXPECT_FALSE(RecognizeHelicalSpring(MakeLibraryPart(gear).mesh).has_value());
}

TEST(SpringRecognition, ACloselyWoundCoilIsASpring) {
  // An extension spring: its coils touch (pitch = wire), or overlap a little in the model.
  for (const double p : {1.5, 1.45}) {
    const std::optional<HelicalSpring> s =
        RecognizeHelicalSpring(testing::SpringMesh(6, 1.5, p, 8, false));
    ASSERT_TRUE(s.has_value()) << p;
    EXPECT_NEAR(s->mean_diameter, 12, 0.05 * 1.5);
    EXPECT_NEAR(s->wire_diameter, 1.5, 0.05 * 1.5);
    EXPECT_NEAR(s->pitch, p, 0.01 * p);
    EXPECT_NEAR(s->turns, 8, 0.05);
    EXPECT_EQ(s->hand, Hand::kLeft);
  }
}

}  // namespace
}  // namespace mechanist
