// The simulator model and its URDF and MJCF text: links, joints, exact couplings, loops, mass
// and movable ranges, against the analysis and textbook values. The files are loaded by the
// real simulators in tests/io/simulators/.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "io/load_assembly.h"
#include "io/mjcf_writer.h"
#include "io/urdf_writer.h"
#include "kernel/collision/collision_model.h"
#include "kernel/collision/mesh_distance.h"
#include "reasoning/analysis.h"
#include "reasoning/motion_run.h"
#include "reasoning/simulation_model.h"
#include "text_edit.h"

namespace mechanist {
namespace {

constexpr double kTwoPi = 6.283185307179586;

std::string Example(const std::string& name) {
  return std::string(MECHANIST_SOURCE_DIR) + "/examples/" + name + "/assembly.json";
}

const SimLink& Link(const SimulationModel& m, const std::string& name) {
  for (const SimLink& l : m.links) {
    if (l.name == name) return l;
  }
  ADD_FAILURE() << "no link " << name;
  return m.links.front();
}

std::size_t JointIndex(const SimulationModel& m, const std::string& name) {
  for (std::size_t k = 0; k < m.joints.size(); ++k) {
    if (m.joints[k].name == name) return k;
  }
  ADD_FAILURE() << "no joint " << name;
  return 0;
}

TEST(SimulationModel, WormDriveIsTwoHingesCoupledAtMinusOneFortieth) {
  const Assembly a = LoadAssembly(Example("robot_hand_worm"));
  const Analysis an = Analyze(a);
  const SimulationModel m = BuildSimulationModel(a, an);
  ASSERT_EQ(m.links.size(), 3u);
  EXPECT_EQ(m.links[0].name, "housing");  // the largest part of the ground subassembly
  EXPECT_TRUE(m.links[0].ground);
  ASSERT_EQ(m.joints.size(), 2u);
  const std::size_t worm = JointIndex(m, "worm_hinge");
  const std::size_t wheel = JointIndex(m, "worm_wheel_hinge");
  EXPECT_EQ(m.joints[worm].kind, SimJoint::Kind::kHinge);
  // The worm turns about the motor shaft's axis, x through (0, -25, 4) mm.
  EXPECT_TRUE(m.joints[worm].axis_W.cwiseAbs().isApprox(Eigen::Vector3d::UnitX()));
  EXPECT_TRUE(Link(m, "worm").p_WL.isApprox(Eigen::Vector3d(-0.03, -0.025, 0.004), 1e-12));
  ASSERT_EQ(m.couplings.size(), 1u);
  const SimCoupling& c = m.couplings.front();
  ASSERT_EQ(c.terms.size(), 2u);
  // wheel = r * worm in the joints' own senses; the analysis says -1/40 about the features'.
  const double r = c.terms[0].first == wheel ? -c.terms[1].second / c.terms[0].second
                                             : -c.terms[0].second / c.terms[1].second;
  const double sense = m.joints[wheel].axis_W.z() * m.joints[worm].axis_W.x();
  EXPECT_NEAR(r * sense, -1.0 / 40, 1e-15);
  ASSERT_EQ(m.actuators.size(), 1u);
  ASSERT_EQ(m.actuators[0].terms.size(), 1u);
  EXPECT_EQ(m.actuators[0].terms[0].first, worm);
  EXPECT_NEAR(std::abs(m.actuators[0].rate), kTwoPi, 1e-12);

  const std::string urdf = UrdfText(a, an, m, "meshes");
  EXPECT_NE(urdf.find("<mimic joint=\"worm_hinge\" multiplier=\"-0.025\""), std::string::npos)
      << urdf;
  EXPECT_NE(urdf.find("filename=\"meshes/worm_wheel.stl\""), std::string::npos);
  const std::string mjcf = MjcfText(a, an, m);
  EXPECT_NE(mjcf.find("worm_wheel_hinge = -0.025 * worm_hinge"), std::string::npos) << mjcf;
  EXPECT_NE(mjcf.find("<joint joint=\"worm_hinge\" coef=\"0.025\"/>"), std::string::npos) << mjcf;
  EXPECT_NE(mjcf.find("<velocity name=\"motor\" joint=\"worm_hinge\""), std::string::npos);
}

TEST(SimulationModel, PlanetsCoupleToTheirCarrierAndTheSunThroughATendon) {
  const Assembly a = LoadAssembly(Example("planetary_gear_set"));
  const Analysis an = Analyze(a);
  const SimulationModel m = BuildSimulationModel(a, an);
  // ring (ground), carrier, three planets, sun.
  ASSERT_EQ(m.links.size(), 6u);
  EXPECT_EQ(m.couplings.size(), 6u);
  int two = 0, three = 0;
  for (const SimCoupling& c : m.couplings) {
    two += c.terms.size() == 2;    // planet and ring: the planet's hinge and the carrier's
    three += c.terms.size() == 3;  // planet and sun: planet, carrier and sun
  }
  EXPECT_EQ(two, 3);
  EXPECT_EQ(three, 3);
  for (const SimLink& l : m.links) {
    if (l.name.rfind("planet", 0) == 0) {
      EXPECT_EQ(m.links[*l.parent].name, "carrier");
    }
  }
  const std::string mjcf = MjcfText(a, an, m);
  EXPECT_NE(mjcf.find("<tendon tendon1=\"coupling_"), std::string::npos);
  // URDF has one mimic per joint and none of three joints: those are said in comments.
  const std::string urdf = UrdfText(a, an, m, "meshes");
  EXPECT_NE(urdf.find("coupling not expressed in URDF (gear pair planet_1/teeth + sun/teeth"),
            std::string::npos)
      << urdf;
}

TEST(SimulationModel, ScrewIsAHingeAndASlideAdvancingTheLead) {
  const Assembly a = LoadAssembly(Example("diaphragm_valve"));
  const Analysis an = Analyze(a);
  const SimulationModel m = BuildSimulationModel(a, an);
  // The tree prefers the screw (one freedom) to the cylindrical fits beside it.
  const std::size_t hinge = JointIndex(m, "spindle_hinge");
  const std::size_t slide = JointIndex(m, "spindle_slide");
  ASSERT_EQ(an.pairs[*m.joints[hinge].pair].type, PairType::kScrew);
  bool found = false;
  for (const SimCoupling& c : m.couplings) {
    if (c.terms.size() != 2 || c.terms[0].first != slide) continue;
    found = true;
    EXPECT_EQ(c.terms[1].first, hinge);
    EXPECT_NEAR(-c.terms[1].second / c.terms[0].second, 1.5e-3 / kTwoPi, 1e-15);
  }
  EXPECT_TRUE(found);
  // The spindle turns in the compressor: a loop, closed by two points of its axis.
  bool revolute_loop = false;
  for (const SimLoop& loop : m.loops) {
    if (an.pairs[loop.pair].type == PairType::kRevolute) {
      revolute_loop = true;
      EXPECT_EQ(loop.anchors_W.size(), 2u);
    }
  }
  EXPECT_TRUE(revolute_loop);
}

TEST(SimulationModel, LinkMassIsDensityTimesTheVolumeOfItsClosedMeshes) {
  const Assembly a = LoadAssembly(Example("connecting_rod"));
  const Analysis an = Analyze(a);
  SimulationOptions options;
  options.density = 2700;
  const SimulationModel m = BuildSimulationModel(a, an, options);
  const SimLink& rod = Link(m, "rod");  // the rod, its cap, bolts and nuts
  EXPECT_EQ(rod.parts.size(), 6u);
  double volume = 0.0;
  for (const std::size_t p : rod.parts) volume += std::abs(a.part(p).mesh->SignedVolume());
  EXPECT_NEAR(rod.mass, 2700 * volume * 1e-9, 1e-12);
  EXPECT_FALSE(rod.default_inertia);
  // The inertia is a tensor of a solid: symmetric, positive, and meeting the triangle
  // inequality that simulators check.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(rod.I_Cm);
  const Eigen::Vector3d p = eig.eigenvalues();
  EXPECT_GT(p.minCoeff(), 0.0);
  EXPECT_GE(p(0) + p(1), p(2));
  options.density = 0.0;
  EXPECT_THROW(BuildSimulationModel(a, an, options), std::invalid_argument);
}

TEST(SimulationModel, FeaturesOnlyPartsGetTheDefaultInertiaAndHeldDriversABrake) {
  const Assembly a = LoadAssembly(Example("planetary_differential_sketch"));
  const Analysis an = Analyze(a);
  const SimulationModel m = BuildSimulationModel(a, an);
  for (const SimLink& l : m.links) {
    if (l.ground) continue;
    EXPECT_TRUE(l.default_inertia) << l.name;
    EXPECT_EQ(l.mass, kDefaultMass);
    EXPECT_TRUE(l.visuals.empty());
  }
  EXPECT_TRUE(m.meshes.empty());
  const std::string mjcf = MjcfText(a, an, m, {.mesh_dir = "meshes", .drive = true});
  EXPECT_NE(mjcf.find("<joint name=\"brake\" joint1=\"ring_hinge\" polycoef=\"0 0 0 0 0\""),
            std::string::npos)
      << mjcf;
  EXPECT_EQ(mjcf.find("<velocity name=\"brake\""), std::string::npos);
  EXPECT_NE(mjcf.find("<key name=\"drive\" ctrl=\""), std::string::npos);
}

TEST(SimulationModel, AHeldSideGearOnATurningCarrierIsHeldAsTheSumOfBothHinges) {
  // The bevel differential's left gear turns in the carrier, the carrier in the housing: held
  // still, carrier + side gear about x is zero, a tendon of both hinges.
  const Assembly a = LoadAssembly(Example("bevel_differential_sketch"));
  const Analysis an = Analyze(a);
  const SimulationModel m = BuildSimulationModel(a, an);
  ASSERT_EQ(m.actuators.size(), 2u);
  const SimActuator& held = m.actuators[1];
  EXPECT_EQ(held.rate, 0.0);
  ASSERT_EQ(held.terms.size(), 2u);
  EXPECT_EQ(m.joints[held.terms[0].first].name, "left_gear_hinge");
  EXPECT_EQ(m.joints[held.terms[1].first].name, "carrier_hinge");
  // Both about the driver's axis (-x): the side gear's hinge and the carrier's as analysed.
  for (const auto& [j, coefficient] : held.terms) {
    EXPECT_EQ(coefficient, m.joints[j].axis_W.x() < 0 ? 1.0 : -1.0) << m.joints[j].name;
  }
  const std::string mjcf = MjcfText(a, an, m, {.mesh_dir = "meshes"});
  EXPECT_NE(mjcf.find("<tendon name=\"held_wheel\" tendon1=\"held_wheel_drive\""),
            std::string::npos)
      << mjcf;
  EXPECT_EQ(m.actuators[0].terms.size(), 1u);  // the carrier's own hinge
}

TEST(SimulationModel, MovableRangeEndsWhereTheSweptPartsTouch) {
  // The pushed_by_contact arm's lug meets block b after about 74 degrees. There b turns with
  // shaft a, which nothing holds, so the lug pushes it along and no stop is found; with a
  // fixed to the ground, b stops the arm both ways, and at each end of the range the two parts
  // are within the contact tolerance.
  const std::string file = Example("pushed_by_contact");
  const Assembly free_a = LoadAssembly(file);
  const Analysis free_an = Analyze(free_a);
  const CollisionModel free_collision(free_a);
  SimulationOptions free_options;
  free_options.collision = &free_collision;
  const SimulationModel pushed = BuildSimulationModel(free_a, free_an, free_options);
  EXPECT_FALSE(pushed.joints[JointIndex(pushed, "d_arm_hinge")].upper);
  const Assembly a =
      LoadAssemblyText(testing::Replace(testing::ReadText(file), R"({"id": "a", "library")",
                                        R"({"id": "a", "ground": true, "library")"),
                       file);
  const Analysis an = Analyze(a);
  const CollisionModel collision(a);
  SimulationOptions options;
  options.collision = &collision;
  const SimulationModel m = BuildSimulationModel(a, an, options);
  const SimJoint& arm = m.joints[JointIndex(m, "d_arm_hinge")];
  ASSERT_TRUE(arm.lower && arm.upper) << "no range";
  EXPECT_LT(*arm.lower, 0.0);
  EXPECT_GT(*arm.upper, 0.0);
  ASSERT_TRUE(arm.upper_contact);
  // Oracle: turn the arm's subassembly by the limit about the joint axis and measure.
  for (const double q : {*arm.lower, *arm.upper}) {
    const auto& contact = q > 0 ? *arm.upper_contact : *arm.lower_contact;
    const std::size_t moving =
        an.subassembly_of[contact.first] == an.subassembly_of[a.FindPart("d").value()]
            ? contact.first
            : contact.second;
    const std::size_t still = moving == contact.first ? contact.second : contact.first;
    auto distance_at = [&](double angle) {
      const RigidTransform X =
          RigidTransform::AxisAngleAbout(1e3 * arm.p_W, arm.axis_W, angle) * a.part(moving).X_WP;
      return SurfaceDistance(collision.part_mesh(moving), X, collision.part_mesh(still),
                             a.part(still).X_WP, 10.0);
    };
    EXPECT_LE(distance_at(q), a.tolerance().length) << q;
    EXPECT_GT(distance_at(0.9 * q), a.tolerance().length) << q;
  }
}

TEST(SimulationModel, OutputIsDeterministic) {
  const Assembly a = LoadAssembly(Example("planetary_gear_set"));
  const Analysis an = Analyze(a);
  const SimulationModel m1 = BuildSimulationModel(a, an);
  const SimulationModel m2 = BuildSimulationModel(a, an);
  EXPECT_EQ(MjcfText(a, an, m1), MjcfText(a, an, m2));
  EXPECT_EQ(UrdfText(a, an, m1, "m"), UrdfText(a, an, m2, "m"));
}

}  // namespace
}  // namespace mechanist
