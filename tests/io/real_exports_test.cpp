// The seven real CAD exports of ../shared/data/real as `mechanist analyze` reports them: the
// ground chosen, and every warning the report prints, each one a designer would act on or a
// known recognition miss (named below, with the truth it misses). A new warning on any of them
// fails here, as does a lost one.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "io/load_assembly.h"
#include "kernel/collision/collision_model.h"
#include "reasoning/analysis.h"
#include "reasoning/assembly_plan.h"
#include "reasoning/expectation_check.h"

namespace mechanist {
namespace {

struct Expected {
  std::string file;  // under ../shared/data/real
  std::string ground;
  // "code: the first part it names", sorted.
  std::vector<std::string> warnings;
  // What the later recognisers find on this file: cycloidal discs and pin rings, screws
  // taken as screwed into plain holes, loose-fit pairs. No file has a spring.
  int cycloid_features = 0, plain_hole_screws = 0, loose_fits = 0;
  // Bearings modelled as one solid (the `bearing` findings that say so).
  int solid_bearings = 0;
  // Pins in holes (a cycloidal reducer's output mechanism).
  int pins_in_holes = 0;
  // Pairs of parts whose only slide the parts around stop within a small play (SeatParts).
  int seated_pairs = 0;
  // The mobility, where the test states it (a negative value: not stated here).
  int mobility = -1;
  // Of its free motions, the idle spins of round parts (a spacer, a bearing, a bare shaft).
  int idle = 0;
  // Hubs fixed by a setscrew the file leaves out (an empty radial hole into the bore).
  int setscrew_holes = 0;
  // Parts in no pair fixed to the part they are sunk into.
  int embedded = 0;
  // Hubs held by nothing but a shaft that turns in a bearing, fixed to it.
  int bearing_shafts = 0;
  // Pairs on pins the file leaves out (implied_pin): revolute, or one fixed pair for two parts
  // pinned on two or more axes.
  int implied_pins = 0;
  // Floating parts fixed where they stand centred on another part's axis (centred).
  int centred = 0;
};

std::vector<Expected> Cases() {
  return {
      // Truth: the bracket (body1) is ground and the arm (body2) turns on its pin: mobility 1
      // (tested below). The two instances are unnamed: named by their products.
      {"revolute_pin_solidedge_chrono/assembly.stp", "Assem1.body1", {}},
      // Truth: the housing with its 7 integral ring pins. No warning: the input with its disc
      // and the output ring, and the placeholder ring, turn freely (the file has no driver).
      {"cycloid_7pin_6lobe_onshape/Full Assembly.step",
       "Full_Assembly.Outer_Pin_Shell",
       {},
       2,
       2,
       0,
       0,
       1,
       0,
       2,
       1},
      // The print-in-place hinge: its pin stubs, 0.3 mm clear of the bores, are the lid's
      // only guide (loose fits), so no warning.
      {"hinge_clamshell_build123d/clamshell_full.step", "COMPOUND_solid2", {}, 0, 0, 6},
      // A near miss a designer checks (a shaft 0.07 mm off its hole's axis), and the lead
      // screw's missing thread. Fourteen M5 screws end in nuts or tap-drilled holes, eight
      // of them two at each of the channel's four core holes, one from each end plate. The
      // carriage plate stands wedged against the load cell (seated). The lead screw's two collars
      // have empty setscrew holes (M5 tap drill, 4.2
      // mm): fixed to it. The axle bolts clamp the wheels' one-solid bearings through their
      // bores, so the four V-wheels turn on them; two of the bolts run through eccentric
      // spacers in the carriage plate, which they clamp between head and spacer. The two
      // washers on the lead screw (8.5 mm holes on 8 mm), held by face contacts alone, turn
      // on it (loose fits). The nut block's two M5 screws come out through their captive
      // nuts' tap-drilled holes: screwed there, they clamp the block and its spacers to the
      // carriage plate (before, seating held them along their holes within 0.14 mm, and the
      // spacers were idle spins). The push rod, touching nothing, stands centred in its load
      // cell's 12 mm hole (8 mm in 12): fixed there, and the probe, resting on the rod's end
      // with the rod centred in its own 12 mm hole, to the rod (centred; before, the rod
      // floated, 6, and the probe turned and slid on its end, 3). 10, where the truth has 1
      // (5 with the wheels' spins): the lead screw turns apart from the carriage (its thread
      // is not modelled: the unthreaded_nut warning names the nut's bore and the override
      // that couples them). Eight of them are idle spins: the four wheels, the two washers,
      // and the two bearings of the lead screw in their seats. No implied pin: each wheel's
      // bore beside its one-solid bearing's is the bearing's business (eight such pins
      // before).
      {"lead_screw_linear_actuator_onshape/Assembly.step",
       "Assembly_1._C_V",
       {"axes_not_collinear: Assembly_1.p____V", "unthreaded_nut: Assembly_1.p____V"},
       0,
       16,
       2,
       10,
       0,
       1,
       10,
       8,
       2,
       0,
       0,
       0,
       2},
      // Every finger hinge is found (the palm's fold included), so no warning. The thumb's M4
      // pivot screw ends in its nut's hole (drawn at the minor diameter). 22 where the truth
      // has 16: the five servos rest in the forearm's pockets with 1.4 to 27 mm of room along
      // x, and the thumb's knuckle has 2.5 mm between the palm's cheeks, more than a seat's
      // play (kMaxSeatPlay), so their slides stay. 30 implied pins: the finger hinges (two
      // knuckles each, mostly), and one fixed pair for the forearm's holes into the palm on two
      // axes 28.5 mm apart (a 1.5 mm tendon channel and an 8.94 mm bore), the truth's fixed
      // joint.
      {"robot_hand_finger_hinges_onshape/Assembly 1.step",
       "Assembly_1.FOREARM",
       {},
       0,
       1,
       0,
       0,
       0,
       0,
       22,
       0,
       0,
       0,
       0,
       30},
      // The motor's connector is in no pair, sunk 2.1 mm into the motor's end cap: fixed to
      // it, so no warning. The motor's four long M3 screws (cross-recessed pan heads) run
      // through the tap-drilled stator into the flange. The pendulum rod's hub, held by
      // nothing but the joint rod, which turns in the SKF 6002, turns with it; so does the
      // motor mount on the motor's pilot boss, coaxial with the motor's bearings: the truth's
      // 2 (4 before, 10 before the connector was fixed).
      {"rotary_pendulum_ball_bearing_fusion/Assembly.step",
       "Assembly_v14.base_link_v4_1.NEMA_v6_1.Middle_part_1",
       {},
       0,
       4,
       0,
       2,
       0,
       0,
       2,
       0,
       0,
       1,
       2},
      // The file has the two gears and no frame or shafts: each turns on an axle of the
      // implied frame through its bore, so no warning.
      {"spur_pair_20T_40T_solidworks/ISO standard Spur Gear Drive (2-1 ratio).STEP",
       "implied_frame",
       {}},
  };
}

void PrintTo(const Expected& e, std::ostream* os) { *os << e.file; }

// Per file (as Expected::file): its free motions other than idle spins, sorted, each as the
// part that makes it (the largest of the parts moving together) and the motion, in the
// report's words.
const std::map<std::string, std::vector<std::string>>& FreeMotions() {
  static const auto* motions = new std::map<std::string, std::vector<std::string>>{
      // The truth's revolute of the arm on the bracket's pin.
      {"revolute_pin_solidedge_chrono/assembly.stp",
       {"Assem1.body2 turns about Assem1.body1/hole_3's axis"}},
      // The input with its disc and the output ring; the placeholder's spin is idle. (Said of
      // the output ring before the disc's face stopped reaching the cover's spacers beside it.)
      {"cycloid_7pin_6lobe_onshape/Full Assembly.step",
       {"Full_Assembly.Input_Shaft turns about Full_Assembly.Top_centering_cover/hole_2's axis"}},
      // The lid (solid 1, which the file names COMPOUND) on the base's printed pins.
      {"hinge_clamshell_build123d/clamshell_full.step",
       {"COMPOUND turns about COMPOUND_solid2/shaft_10's axis"}},
      // The carriage's slide, and the lead screw's turn (its washers turn with it; before, the
      // turn was said of one of them).
      {"lead_screw_linear_actuator_onshape/Assembly.step",
       {"Assembly_1.0__V slides along (0, 1, 0) on Assembly_1._C_V/face_115",
        "Assembly_1.p____V turns about Assembly_1.P___V/hole_3's axis"}},
      // Sixteen turns (the truth's 15 joints with Ring1 and Pinky1 apart, the thumb's base on
      // its pivot screw among them), the thumb base's slide along that screw, and the servos'
      // slides in their pockets.
      {"robot_hand_finger_hinges_onshape/Assembly 1.step",
       {"Assembly_1.Index1 turns about Assembly_1.Palm/hole_6's axis",
        "Assembly_1.Index2 turns about Assembly_1.Index1/hole_3's axis",
        "Assembly_1.Index3 turns about Assembly_1.Index2/hole_2's axis",
        "Assembly_1.Middle1 turns about Assembly_1.Palm/hole_7's axis",
        "Assembly_1.Middle2 turns about Assembly_1.Middle1/hole_3's axis",
        "Assembly_1.Middle3 turns about Assembly_1.Middle2/hole_2's axis",
        "Assembly_1.Pinky1 turns about Assembly_1.Palm/hole_2's axis",
        "Assembly_1.Pinky2 turns about Assembly_1.Pinky1/hole_1's axis",
        "Assembly_1.Pinky3 turns about Assembly_1.Pinky2/hole_3's axis",
        "Assembly_1.Ring1 turns about Assembly_1.Palm/hole_1's axis",
        "Assembly_1.Ring2 turns about Assembly_1.Ring1/hole_3's axis",
        "Assembly_1.Ring3 turns about Assembly_1.Ring2/hole_3's axis",
        "Assembly_1.Ring4 turns about Assembly_1.Ring3/hole_2's axis",
        "Assembly_1.Servo_MG996R slides along (1, 0, 0) on Assembly_1.FOREARM/face_12",
        "Assembly_1.Servo_MG996R_2 slides along (1, 0, 0) on Assembly_1.FOREARM/face_12",
        "Assembly_1.Servo_MG996R_3 slides along (1, 0, 0) on Assembly_1.FOREARM/face_12",
        "Assembly_1.Servo_MG996R_4 slides along (1, 0, 0) on Assembly_1.FOREARM/face_12",
        "Assembly_1.Servo_MG996R_5 slides along (1, 0, 0) on Assembly_1.FOREARM/face_12",
        "Assembly_1.Thumb1 slides along "
        "Assembly_1.Hex_socket_head_cap_screw_M4x0_70_x_45/shaft_2's axis",
        "Assembly_1.Thumb1 turns about Assembly_1.Hex_socket_head_cap_screw_M4x0_70_x_45/shaft_2's "
        "axis",
        "Assembly_1.Thumb2 turns about Assembly_1.Thumb1/hole_3's axis",
        "Assembly_1.Thumb3 turns about Assembly_1.Thumb2/hole_1's axis"}},
      // The truth's two revolutes: the arm (BarLink) on the stepper's bearings, and the
      // pendulum's rod in the SKF 6002 (before, said of the bearing's inner ring).
      {"rotary_pendulum_ball_bearing_fusion/Assembly.step",
       {"Assembly_v14.BarLink_v9_1_solid2 turns about "
        "Assembly_v14.base_link_v4_1.NEMA_v6_1.Bearing_1/hole_1's axis",
        "Assembly_v14.PendulumRod_v6_1_solid2 turns about "
        "Assembly_v14.BarLink_v9_1.SKF_6002_v4_1.SKF_6002_or_1_solid11/hole_1's axis"}},
      // The gear pair on the implied frame's axles.
      {"spur_pair_20T_40T_solidworks/ISO standard Spur Gear Drive (2-1 ratio).STEP",
       {"ISO_standard_Spur_Gear_Drive__2-1_ratio_.spur_gear_iso_ISO_-_Spur_gear_2M_40T_20PA_"
        "15FW_---S40A75H50L20_0N turns about implied_frame/axle_1's axis"}},
  };
  return *motions;
}

// The screws that `screw_in_plain_hole` findings take as screwed into plain holes (a finding
// names several alike): their shanks, threads now.
int PlainHoleScrews(const Assembly& a) {
  int screws = 0;
  for (const Diagnostic& d : a.findings()) {
    if (d.code != "screw_in_plain_hole") continue;
    for (const std::string& name : d.features) {
      screws += a.feature(*a.FindFeature(name)).kind == FeatureKind::kThread;
    }
  }
  return screws;
}

class RealExports : public ::testing::TestWithParam<Expected> {};

TEST_P(RealExports, GroundAndWarningsAreTheOnesADesignerActsOn) {
  const Expected& e = GetParam();
  const Assembly a = LoadAssembly(std::filesystem::path(MECHANIST_SHARED_DATA) / "real" / e.file);
  std::vector<std::string> grounds;
  for (const Part& p : a.parts()) {
    if (p.ground) grounds.push_back(p.id);
  }
  EXPECT_EQ(grounds, std::vector<std::string>{e.ground});
  const Analysis an = Analyze(a);
  std::vector<std::string> warnings;
  for (const Diagnostic& d : an.diagnostics) {
    if (d.severity == Severity::kInfo) continue;
    warnings.push_back(d.code + ": " + (d.parts.empty() ? "" : d.parts.front()));
    EXPECT_NE(d.severity, Severity::kError) << d.message;
  }
  std::sort(warnings.begin(), warnings.end());
  EXPECT_EQ(warnings, e.warnings);
  std::vector<std::string> motions;
  for (const FreeMotion& f : an.motion.mobility.free_motions) {
    if (!f.idle) motions.push_back(a.part(f.part).id + " " + f.freedom);
  }
  std::sort(motions.begin(), motions.end());
  EXPECT_EQ(motions, FreeMotions().at(e.file));
  int cycloid_features = 0, loose_fits = 0;
  for (const Part& p : a.parts()) {
    EXPECT_FALSE(p.compliant) << p.id;
    for (const Feature& f : p.features) {
      cycloid_features +=
          f.kind == FeatureKind::kCycloidDisc || f.kind == FeatureKind::kPinRing ? 1 : 0;
    }
  }
  int pins_in_holes = 0;
  for (const Pair& p : an.pairs) {
    loose_fits += p.source == PairSource::kLooseFit ? 1 : 0;
    pins_in_holes += p.type == PairType::kPinsInHoles ? 1 : 0;
  }
  EXPECT_EQ(pins_in_holes, e.pins_in_holes);
  EXPECT_EQ(cycloid_features, e.cycloid_features);
  EXPECT_EQ(PlainHoleScrews(a), e.plain_hole_screws);
  EXPECT_EQ(loose_fits, e.loose_fits);
  const int solid_bearings = static_cast<int>(
      std::count_if(an.diagnostics.begin(), an.diagnostics.end(), [](const Diagnostic& d) {
        return d.code == "bearing" && d.message.find("modelled as one solid") != std::string::npos;
      }));
  EXPECT_EQ(solid_bearings, e.solid_bearings);
  EXPECT_EQ(std::count_if(an.pairs.begin(), an.pairs.end(),
                          [](const Pair& p) { return p.source == PairSource::kSeated; }),
            e.seated_pairs);
  if (e.mobility >= 0) {
    EXPECT_EQ(an.motion.mobility.dof, e.mobility);
  }
  EXPECT_EQ(an.motion.mobility.idle, e.idle);
  EXPECT_EQ(std::count_if(an.pairs.begin(), an.pairs.end(),
                          [](const Pair& p) { return p.source == PairSource::kSetscrewHole; }),
            e.setscrew_holes);
  EXPECT_EQ(std::count_if(an.pairs.begin(), an.pairs.end(),
                          [](const Pair& p) { return p.source == PairSource::kEmbedded; }),
            e.embedded);
  EXPECT_EQ(std::count_if(an.pairs.begin(), an.pairs.end(),
                          [](const Pair& p) { return p.source == PairSource::kBearingShaft; }),
            e.bearing_shafts);
  EXPECT_EQ(std::count_if(an.pairs.begin(), an.pairs.end(),
                          [](const Pair& p) { return p.source == PairSource::kImpliedPin; }),
            e.implied_pins);
  EXPECT_EQ(std::count_if(an.pairs.begin(), an.pairs.end(),
                          [](const Pair& p) { return p.source == PairSource::kCentred; }),
            e.centred);
}

// Truth: the carriage advances 8 mm per turn of the lead screw (the firmware's lead), the
// thread is not in the file. The override the warning proposes, written next to an `import`
// of the unchanged file, couples them with that ratio exactly, and the two motions become one.
TEST(RealExports, TheLeadScrewsOverrideCouplesItsCarriageByTheLeadExactly) {
  const std::filesystem::path step = std::filesystem::path(MECHANIST_SHARED_DATA) /
                                     "real/lead_screw_linear_actuator_onshape/Assembly.step";
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "mechanist_real_exports_lead_screw";
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "coupled.json";
  std::ofstream(file) << R"({"mechanist": 1, "import": ")"
                      << std::filesystem::absolute(step).string() << R"(",
    "overrides": [{"pair": ["Assembly_1.p____V/shaft_1", "Assembly_1.P___V/hole_3"],
                   "type": "screw", "lead": 8}],
    "drivers": [{"id": "motor", "part": "Assembly_1.p____V", "feature": "shaft_1"}],
    "expect": [{"part": "Assembly_1.P___V", "feature": "hole_3", "ratio": "-8"},
               {"part": "Assembly_1.0E_V", "feature": "face_11", "ratio": "-8"},
               {"mobility": 9}]})";
  const Assembly a = LoadAssembly(file);
  const Analysis an = Analyze(a);
  std::filesystem::remove_all(dir);
  for (const ExpectationResult& r : CheckExpectations(a, an)) {
    EXPECT_TRUE(r.passed) << r.what << ": " << r.detail;
  }
  EXPECT_FALSE(std::any_of(an.diagnostics.begin(), an.diagnostics.end(),
                           [](const Diagnostic& d) { return d.code == "unthreaded_nut"; }));
}

TEST(RealExports, TheRobotHandsThumbTurnsOnItsPivotScrew) {
  // Truth: the thumb's base pivots on a modelled M4 x 45 socket head screw with a nut. The
  // screw's head and nut bear on the palm, which it clamps; the thumb, between the palm's lugs,
  // turns on its shank.
  const Assembly a = LoadAssembly(std::filesystem::path(MECHANIST_SHARED_DATA) /
                                  "real/robot_hand_finger_hinges_onshape/Assembly 1.step");
  const Analysis an = Analyze(a);
  const std::string screw = "Assembly_1.Hex_socket_head_cap_screw_M4x0_70_x_45";
  int thumb = 0, palm = 0;
  for (const Pair& p : an.pairs) {
    if (a.part(p.a.part).id != screw) continue;
    const std::string other = a.part(p.b.part).id;
    if (other == "Assembly_1.Thumb1") {
      EXPECT_EQ(p.type, PairType::kCylindrical);
      ++thumb;
    } else if (other == "Assembly_1.Palm" && p.type == PairType::kFixed) {
      EXPECT_EQ(p.source, PairSource::kClamp);
      ++palm;
    }
  }
  EXPECT_EQ(thumb, 2);  // its two lugs
  EXPECT_EQ(palm, 1);
}

TEST(RealExports, ThePendulumsMultiBodyPartsAreOnePieceEach) {
  // Truth: the arm bar and the pendulum rod are each one part, exported by Fusion 360 as two
  // solids of one component that touch face to face.
  const Assembly a = LoadAssembly(std::filesystem::path(MECHANIST_SHARED_DATA) /
                                  "real/rotary_pendulum_ball_bearing_fusion/Assembly.step");
  const Analysis an = Analyze(a);
  std::vector<std::string> one_part;
  for (const Pair& p : an.pairs) {
    if (p.source != PairSource::kOnePart) continue;
    EXPECT_EQ(p.type, PairType::kFixed);
    one_part.push_back(a.part(p.a.part).id + " + " + a.part(p.b.part).id);
  }
  EXPECT_EQ(one_part, (std::vector<std::string>{
                          "Assembly_v14.BarLink_v9_1 + Assembly_v14.BarLink_v9_1_solid2",
                          "Assembly_v14.PendulumRod_v6_1 + Assembly_v14.PendulumRod_v6_1_solid2"}));
}

TEST(RealExports, TheSolidEdgePinGivesItsTruthsMobility) {
  const Assembly a = LoadAssembly(std::filesystem::path(MECHANIST_SHARED_DATA) /
                                  "real/revolute_pin_solidedge_chrono/assembly.stp");
  EXPECT_EQ(Analyze(a).motion.mobility.dof, 1);
}

TEST(RealExports, TheSolidEdgePinTouchesItsBoreAndGoesIn) {
  // Truth: a r 20 mm pin in a r 20 mm bore (zero clearance), chamfered at both ends. The
  // bracket's mesh (241 mm across) lies within 0.24 mm of its faces: the pin's vertices, on
  // its circle, overlap the bore's facets and meet its chamfer's just beyond the bore.
  const Assembly a = LoadAssembly(std::filesystem::path(MECHANIST_SHARED_DATA) /
                                  "real/revolute_pin_solidedge_chrono/assembly.stp");
  const Analysis an = Analyze(a);
  const CollisionModel model(a);
  const std::vector<PartContact> contacts = FindContacts(a, InitialState(a), model, an.pairs);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts.front().verdict, ContactVerdict::kTouching);
  const AssemblyPlan plan = PlanAssembly(a, an, model);
  EXPECT_TRUE(plan.assemblable);
  ASSERT_EQ(plan.steps.size(), 1u);
  EXPECT_EQ(a.part(plan.steps.front().part).id, "Assem1.body2");
}

TEST(RealExports, TheReducersSpacersGoInWithTheCoverTheyAreStuckIn) {
  // The Onshape reducer's two tiny spacers lie 0.55 mm deep in the top cover (as exported):
  // neither can leave the assembly alone, nor the cover alone, and the cover cannot leave
  // while they are there; the three leave as one. So the cover goes in as a sub-assembly with
  // them, and their attempts to go into it apart say the clash at rest holds them, not a
  // contact on the way.
  const Assembly a = LoadAssembly(std::filesystem::path(MECHANIST_SHARED_DATA) /
                                  "real/cycloid_7pin_6lobe_onshape/Full Assembly.step");
  const AssemblyPlan plan = PlanAssembly(a, Analyze(a), CollisionModel(a));
  int stuck = 0;
  for (const InsertionStep& u : plan.unplaced) {
    if (a.part(u.part).id.find("Tiny_spacer") == std::string::npos) continue;
    ASSERT_TRUE(u.apart_for);
    const InsertionStep& in = plan.steps.at(*u.apart_for);
    EXPECT_TRUE(in.subassembly);
    EXPECT_TRUE(in.clear);
    EXPECT_EQ(a.part(in.part).id, "Full_Assembly.Top_centering_cover");
    EXPECT_EQ(std::count(in.carried.begin(), in.carried.end(), u.part), 1);
    for (const InsertionObstacle& o : u.blocked_by) {
      if (a.part(o.part).id != "Full_Assembly.Top_centering_cover") continue;
      EXPECT_TRUE(o.clash_at_rest);
      EXPECT_NEAR(o.short_by, 0.0, a.tolerance().length);
      ++stuck;
    }
  }
  EXPECT_EQ(stuck, 2);
}

TEST(RealExports, TheReducersCapScrewsLeaveTheCoverTheirHeadsRestOn) {
  // The Onshape reducer's two 10-32 button head screws: each mesh is closed but for edges where
  // four of its faces meet. Taken for two-sided sheets, their heads' touch on the top cover
  // blocked them in every direction ("cannot be placed"); as solids they leave it. Nothing
  // stops them on the way; only their clashes at rest (0.07 mm into a spacer, as exported).
  const Assembly a = LoadAssembly(std::filesystem::path(MECHANIST_SHARED_DATA) /
                                  "real/cycloid_7pin_6lobe_onshape/Full Assembly.step");
  const CollisionModel model(a);
  const AssemblyPlan plan = PlanAssembly(a, Analyze(a), model);
  int placed = 0;
  for (const InsertionStep& s : plan.steps) {
    if (a.part(s.part).id.find("Socket_button_head_cap_screw") == std::string::npos) continue;
    EXPECT_FALSE(model.part_mesh(s.part).closed());
    EXPECT_TRUE(model.part_mesh(s.part).oriented());
    EXPECT_FALSE(s.clear);
    ASSERT_FALSE(s.blocked_by.empty());
    for (const InsertionObstacle& o : s.blocked_by) {
      EXPECT_TRUE(o.clash_at_rest) << a.part(o.part).id;
      EXPECT_EQ(o.short_by, 0.0);
    }
    ++placed;
  }
  EXPECT_EQ(placed, 2);
}

TEST(RealExports, ThePendulumsBallBearingGoesInAsOne) {
  // Truth: an SKF 6002 modelled with its two rings and nine balls (11 solids).
  const Assembly a = LoadAssembly(std::filesystem::path(MECHANIST_SHARED_DATA) /
                                  "real/rotary_pendulum_ball_bearing_fusion/Assembly.step");
  const Analysis an = Analyze(a);
  const AssemblyPlan plan = PlanAssembly(a, an, CollisionModel(a));
  const auto in_bearing = [&](std::size_t part) {
    return a.part(part).id.find(".SKF_6002_v4_1.") != std::string::npos;
  };
  std::vector<std::vector<std::string>> moved;  // per step or unplaced part: the bearing's parts
  for (const std::vector<InsertionStep>* steps : {&plan.steps, &plan.unplaced}) {
    for (const InsertionStep& s : *steps) {
      std::vector<std::string> ids;
      if (in_bearing(s.part)) ids.push_back(a.part(s.part).id);
      for (const std::size_t c : s.carried) {
        if (in_bearing(c)) ids.push_back(a.part(c).id);
      }
      if (!ids.empty()) moved.push_back(ids);
    }
  }
  ASSERT_EQ(moved.size(), 1u);
  EXPECT_EQ(moved.front().size(), 11u);
  ASSERT_EQ(an.bearings.size(), 1u);
  EXPECT_EQ(an.bearings.front().size(), 11u);
}

TEST(RealExports, TheClamshellsLidTurnsOnItsPrintedPins) {
  // Truth: a revolute about y through x = 0, z = 10.2; mobility 1. The pins are stubs
  // (r 4.8) 0.3 mm clear of the knuckles' bores (r 5.1), entering each bore from both ends.
  const Assembly a = LoadAssembly(std::filesystem::path(MECHANIST_SHARED_DATA) /
                                  "real/hinge_clamshell_build123d/clamshell_full.step");
  const Analysis an = Analyze(a);
  EXPECT_EQ(an.motion.mobility.dof, 1);
  ASSERT_FALSE(an.pairs.empty());
  for (const Pair& p : an.pairs) {
    EXPECT_EQ(p.type, PairType::kRevolute);
    EXPECT_EQ(p.source, PairSource::kLooseFit);
    const AxisSegment axis = a.feature(p.a).WorldAxis(a.part(p.a.part).X_WP);
    EXPECT_NEAR(std::abs(axis.direction.y()), 1.0, 1e-9);
    EXPECT_NEAR(axis.origin.x(), 0.0, 1e-6);
    EXPECT_NEAR(axis.origin.z(), 10.2, 1e-6);
  }
}

TEST(RealExports, TheOnshapeReducersDiscRollsInItsPinRingAndTurnsTheOutput) {
  // Truth: a 6-lobe disc centred at (0, 2) on the input's eccentric (e = 2 mm) inside the
  // housing's 7 integral pins (r 3 on R 25): the disc turns -1/6 per turn of the input, and
  // the output ring's 6 pins (r 2 on R 16) in the disc's 6 holes (r 4) turn the output with
  // it: input to output -1/6. Mobility 1, 2 with the placeholder ring's idle spin.
  const std::filesystem::path file = std::filesystem::path(MECHANIST_SHARED_DATA) /
                                     "real/cycloid_7pin_6lobe_onshape/Full Assembly.step";
  const Assembly a = LoadAssemblyText(
      R"({"mechanist": 1, "import": ")" + file.string() +
          R"(", "drivers": [{"id": "in", "part": "Full_Assembly.Input_Shaft", "feature": "shaft_1"}]})",
      file.parent_path() / "reducer.json");
  const auto disc = a.FindFeature("Full_Assembly.Cycloidal_Disk/lobes");
  const auto pins = a.FindFeature("Full_Assembly.Outer_Pin_Shell/pins_1");
  ASSERT_TRUE(disc && pins);
  const Feature& d = a.feature(*disc);
  EXPECT_EQ(d.kind, FeatureKind::kCycloidDisc);
  EXPECT_EQ(d.teeth, 6);
  EXPECT_NEAR(d.eccentricity, 2.0, 0.005);
  EXPECT_NEAR((d.origin.head<2>() - Eigen::Vector2d(0, 2)).norm(), 0.0, 0.005);
  const Feature& p = a.feature(*pins);
  EXPECT_EQ(p.kind, FeatureKind::kPinRing);
  EXPECT_EQ(p.teeth, 7);
  EXPECT_NEAR(p.diameter, 50.0, 1e-6);
  EXPECT_NEAR(p.pin_diameter, 6.0, 1e-6);
  const Analysis an = Analyze(a);
  int cycloidal = 0;
  for (const Pair& pair : an.pairs) cycloidal += pair.type == PairType::kCycloidal;
  EXPECT_EQ(cycloidal, 1);
  // The output mechanism: one pins_in_holes coupling, the output ring's pins in the disc.
  std::vector<const Pair*> output;
  for (const Pair& pair : an.pairs) {
    if (pair.type == PairType::kPinsInHoles) output.push_back(&pair);
  }
  ASSERT_EQ(output.size(), 1u);
  EXPECT_EQ(a.PartId(output[0]->a.part), "Full_Assembly.Output_Ring");
  EXPECT_EQ(a.PartId(output[0]->b.part), "Full_Assembly.Cycloidal_Disk");
  EXPECT_EQ(an.motion.mobility.dof, 2);  // the input, and the placeholder's idle spin
  ASSERT_EQ(an.motion.mobility.idle, 1);
  for (const FreeMotion& f : an.motion.mobility.free_motions) {
    EXPECT_EQ(f.idle, a.PartId(f.part) == "Full_Assembly.Bearing_Placeholder") << f.freedom;
  }
  // The input's shaft_1 points down (-z): one turn of it is -1 about z, the disc's +1/6 to
  // rounding: the cover's screws (threads not modelled) hold it to the housing, so the input,
  // turning in the cover, carries both axes and the pair is in Willis' form. (Not carried as
  // an exact fraction: the eccentric's lever arms, multiples of 2 pi, enter the elimination.)
  EXPECT_EQ(PlainHoleScrews(a), 2);
  const FeatureRate& in = an.motion.driven.front().features[disc->part][disc->feature];
  EXPECT_NEAR(in.rotation.value(), 1.0 / 6.0, 1e-12);
  // The output ring turns with the disc: about its shaft_7 (+z), -1/6 of the input's turn
  // about +z (the driver's shaft_1 points down, so one driver turn is -1 about z).
  const auto out = a.FindFeature("Full_Assembly.Output_Ring/shaft_7");
  ASSERT_TRUE(out);
  EXPECT_NEAR(a.feature(*out).axis.z(), 1.0, 1e-9);
  const FeatureRate& ring = an.motion.driven.front().features[out->part][out->feature];
  EXPECT_NEAR(ring.rotation.value(), 1.0 / 6.0, 1e-12);
  // One info names the mechanism.
  EXPECT_EQ(std::count_if(an.diagnostics.begin(), an.diagnostics.end(),
                          [](const Diagnostic& d) { return d.code == "pins_in_holes"; }),
            1);
}

INSTANTIATE_TEST_SUITE_P(Files, RealExports, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<Expected>& info) {
                           const std::string& f = info.param.file;
                           return f.substr(0, f.find('_'));
                         });

}  // namespace
}  // namespace mechanist
