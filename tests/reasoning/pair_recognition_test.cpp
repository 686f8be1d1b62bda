#include "reasoning/pair_recognition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <utility>

#include "reasoning/analysis.h"
#include "test_assembly.h"

namespace mechanist {
namespace {

using testing::MakeAssembly;
using testing::MakeFeature;
using testing::MakePart;
using K = FeatureKind;
using V = Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;

Recognition Recognize(const Assembly& a) { return RecognizePairs(a, InitialState(a)); }

Feature Shaft(double d, double length, V origin = V::Zero(), V axis = V::UnitZ()) {
  return MakeFeature("s", K::kShaft, origin, axis, [&](Feature& f) {
    f.diameter = d;
    f.length = length;
  });
}

Feature Hole(double d, double length, V origin = V(0, 0, 10), V axis = -V::UnitZ()) {
  return MakeFeature("h", K::kHole, origin, axis, [&](Feature& f) {
    f.diameter = d;
    f.length = length;
  });
}

/// The single pair of a recognition (a copy: recognitions here are temporaries).
Pair Only(const Recognition& r) {
  EXPECT_EQ(r.pairs.size(), 1u);
  return r.pairs.empty() ? Pair{} : r.pairs.front();
}

const Diagnostic* FindDiagnostic(const Recognition& r, const std::string& code,
                                 const std::string& text = "") {
  for (const Diagnostic& d : r.diagnostics) {
    if (d.code == code && d.message.find(text) != std::string::npos) return &d;
  }
  return nullptr;
}

bool HasDiagnostic(const Recognition& r, const std::string& code, const std::string& text = "") {
  return FindDiagnostic(r, code, text) != nullptr;
}

/// Diagnostics other than part_unconnected (which every pairless test part gets).
std::size_t NearMisses(const Recognition& r) {
  std::size_t n = 0;
  for (const Diagnostic& d : r.diagnostics) n += d.code != "part_unconnected" ? 1 : 0;
  return n;
}

// A 5 mm shaft entering a hole from above: both axes along -z, the shaft's free end down.
Assembly ShaftInHole(double shaft_d, double hole_d, bool retained_hole = false,
                     V shaft_offset = V::Zero(), double tilt = 0.0) {
  Feature s = Shaft(shaft_d, 20, V(0, 0, 15) + shaft_offset, V(std::sin(tilt), 0, -std::cos(tilt)));
  Feature h = Hole(hole_d, 10);
  h.retained = retained_hole;
  return MakeAssembly({MakePart("block", {h}, RigidTransform(), true), MakePart("pin", {s})});
}

TEST(PairRecognition, ShaftInHoleIsCylindricalRevoluteOrPressFit) {
  const Pair c = Only(Recognize(ShaftInHole(5.0, 5.02)));
  EXPECT_EQ(c.type, PairType::kCylindrical);
  EXPECT_EQ(*c.dof, 2);
  EXPECT_EQ(c.a.part, 1u);  // the convex feature first
  EXPECT_EQ(Only(Recognize(ShaftInHole(5.0, 5.02, true))).type, PairType::kRevolute);
  const Pair press = Only(Recognize(ShaftInHole(5.1, 5.0)));
  EXPECT_EQ(press.type, PairType::kFixed);
  EXPECT_EQ(press.fastening, PairFastening::kPressFit);
  // Within the tolerance (0.05 mm) a slightly larger shaft is a transition fit, not a press fit.
  EXPECT_EQ(Only(Recognize(ShaftInHole(5.04, 5.0))).type, PairType::kCylindrical);
}

TEST(PairRecognition, ShaftInHoleNegatives) {
  // Each condition of the table violated once.
  EXPECT_TRUE(Recognize(ShaftInHole(5.0, 5.0, false, V(0.2, 0, 0))).pairs.empty());     // offset
  EXPECT_TRUE(Recognize(ShaftInHole(5.0, 5.0, false, V::Zero(), 0.05)).pairs.empty());  // angle
  EXPECT_TRUE(Recognize(ShaftInHole(5.0, 5.0, false, V(0, 0, 20))).pairs.empty());  // not engaged
  EXPECT_TRUE(Recognize(ShaftInHole(3.0, 5.0)).pairs.empty());  // passes through, no contact
  // Far thicker than the hole, the convex surface surrounds it (a bearing's outer ring about its
  // inner ring's bore): no press fit (it used to be one), no near miss.
  const Recognition around = Recognize(ShaftInHole(8.0, 5.0));
  EXPECT_TRUE(around.pairs.empty());
  EXPECT_EQ(NearMisses(around), 0u);
  EXPECT_EQ(Only(Recognize(ShaftInHole(5.2, 5.0))).fastening, PairFastening::kPressFit);
  // Blind hole entered the wrong way round.
  Feature s = Shaft(5, 20, V(0, 0, -5), V::UnitZ());
  const Assembly reversed = MakeAssembly(
      {MakePart("block", {Hole(5, 10)}, RigidTransform(), true), MakePart("pin", {s})});
  const Recognition r = Recognize(reversed);
  EXPECT_TRUE(r.pairs.empty());
  EXPECT_TRUE(HasDiagnostic(r, "feature_sense_reversed"));
  // A through hole accepts either sense.
  Feature through = Hole(5, 10);
  through.through = true;
  EXPECT_EQ(Only(Recognize(MakeAssembly(
                     {MakePart("block", {through}, RigidTransform(), true), MakePart("pin", {s})})))
                .type,
            PairType::kCylindrical);
}

TEST(PairRecognition, ShaftNearMissesNameTheQuantity) {
  const Recognition big = Recognize(ShaftInHole(5.2, 5.0, true));
  EXPECT_TRUE(big.pairs.empty());
  const Diagnostic* larger = FindDiagnostic(big, "shaft_larger_than_hole", "5.2 mm");
  ASSERT_NE(larger, nullptr);
  EXPECT_EQ(larger->features, (std::vector<std::string>{"pin/s", "block/h"}));
  EXPECT_EQ(larger->parts, (std::vector<std::string>{"pin", "block"}));
  // What follows for the designer: the two are not joined.
  EXPECT_NE(larger->message.find("; so no pair joins them"), std::string::npos) << larger->message;
  const Recognition offset = Recognize(ShaftInHole(5.0, 5.0, false, V(0.3, 0, 0)));
  EXPECT_TRUE(HasDiagnostic(offset, "axes_not_collinear", "offset 0.3 mm"));
  const Recognition tilt = Recognize(ShaftInHole(5.0, 5.0, false, V::Zero(), 1.0 * kPi / 180));
  EXPECT_TRUE(HasDiagnostic(tilt, "axes_not_collinear", "angle 1 deg"));
  // Far beyond the near-miss window: silence.
  EXPECT_EQ(NearMisses(Recognize(ShaftInHole(5.0, 5.0, false, V(3, 0, 0)))), 0u);
}

Feature Thread(double d, double pitch, double length, V origin, V axis, Fastening fastening,
               int starts = 1, Hand hand = Hand::kRight) {
  return MakeFeature("t", K::kThread, origin, axis, [&](Feature& f) {
    f.diameter = d;
    f.pitch = pitch;
    f.length = length;
    f.fastening = fastening;
    f.starts = starts;
    f.hand = hand;
  });
}

Feature Tapped(double d, double pitch, double length, V origin, V axis, int starts = 1,
               Hand hand = Hand::kRight) {
  return MakeFeature("th", K::kTappedHole, origin, axis, [&](Feature& f) {
    f.diameter = d;
    f.pitch = pitch;
    f.length = length;
    f.starts = starts;
    f.hand = hand;
  });
}

Recognition ScrewIn(const Feature& thread, const Feature& tapped) {
  return Recognize(MakeAssembly(
      {MakePart("nut", {tapped}, RigidTransform(), true), MakePart("screw", {thread})}));
}

TEST(PairRecognition, ThreadInTappedHoleIsScrewOrFixed) {
  const V up = V::UnitZ();
  const Pair loose = Only(ScrewIn(Thread(8, 1.25, 20, V::Zero(), up, Fastening::kLoose),
                                  Tapped(8, 1.25, 8, V(0, 0, 5), up)));
  EXPECT_EQ(loose.type, PairType::kScrew);
  EXPECT_DOUBLE_EQ(*loose.travel_per_revolution, 1.25);
  const Pair lead =
      Only(ScrewIn(Thread(8, 1.5, 20, V::Zero(), up, Fastening::kLoose, 3, Hand::kLeft),
                   Tapped(8, 1.5, 8, V(0, 0, 5), up, 3, Hand::kLeft)));
  EXPECT_DOUBLE_EQ(*lead.travel_per_revolution, -4.5);  // 3 starts x 1.5, left hand
  const Pair tight = Only(ScrewIn(Thread(8, 1.25, 20, V::Zero(), up, Fastening::kTight),
                                  Tapped(8, 1.25, 8, V(0, 0, 5), up)));
  EXPECT_EQ(tight.type, PairType::kFixed);
  EXPECT_EQ(tight.fastening, PairFastening::kTight);
}

TEST(PairRecognition, ThreadMismatchesAreNearMisses) {
  const V up = V::UnitZ();
  const Recognition m3_in_m4 = ScrewIn(Thread(3, 0.5, 10, V::Zero(), up, Fastening::kTight),
                                       Tapped(4, 0.7, 8, V(0, 0, 2), up));
  EXPECT_TRUE(m3_in_m4.pairs.empty());
  EXPECT_TRUE(HasDiagnostic(m3_in_m4, "thread_mismatch", "thread M3, tapped hole M4"));
  EXPECT_TRUE(
      HasDiagnostic(m3_in_m4, "thread_mismatch", "pitch: thread 0.5 mm, tapped hole 0.7 mm"));
  EXPECT_TRUE(
      HasDiagnostic(ScrewIn(Thread(4, 0.7, 10, V::Zero(), up, Fastening::kTight, 1, Hand::kLeft),
                            Tapped(4, 0.7, 8, V(0, 0, 2), up)),
                    "thread_mismatch", "hand: thread left, tapped hole right"));
  EXPECT_TRUE(HasDiagnostic(ScrewIn(Thread(4, 0.7, 10, V::Zero(), up, Fastening::kTight, 2),
                                    Tapped(4, 0.7, 8, V(0, 0, 2), up)),
                            "thread_mismatch", "starts: thread 2"));
}

TEST(PairRecognition, ThreadInPlainHole) {
  const V down = -V::UnitZ();
  const Feature t = Thread(6, 1, 20, V(0, 0, 15), down, Fastening::kTight);
  auto in_hole = [&](double d) {
    Feature h = Hole(d, 10);
    return Recognize(
        MakeAssembly({MakePart("plate", {h}, RigidTransform(), true), MakePart("bolt", {t})}));
  };
  EXPECT_EQ(Only(in_hole(6.6)).type,
            PairType::kCylindrical);  // clearance hole, no nut: not clamped
  const Recognition small = in_hole(5.0);
  EXPECT_TRUE(small.pairs.empty());
  EXPECT_TRUE(HasDiagnostic(small, "hole_smaller_than_thread", "5 mm"));
}

// A bolt down through two plates into a nut under them.
Assembly BoltedStack(Fastening fastening, std::vector<PairOverride> overrides = {}) {
  const V down = -V::UnitZ();
  Feature t = Thread(6, 1, 20, V(0, 0, 10), down, fastening);
  Feature h1 = Hole(6.6, 5, V(0, 0, 10)), h2 = Hole(6.6, 5, V(0, 0, 5));
  Feature nut = Tapped(6, 1, 5, V(0, 0, 0), down);
  return MakeAssembly({MakePart("bottom", {h2}, RigidTransform(), true), MakePart("top", {h1}),
                       MakePart("bolt", {t}), MakePart("nut", {nut})},
                      std::move(overrides));
}

TEST(PairRecognition, TightBoltClampsEveryPartItPassesThrough) {
  const Analysis tight = Analyze(BoltedStack(Fastening::kTight));
  ASSERT_EQ(tight.subassemblies.size(), 1u);
  EXPECT_EQ(tight.subassemblies[0].parts.size(), 4u);
  int clamps = 0;
  for (const Pair& p : tight.pairs) clamps += p.source == PairSource::kClamp ? 1 : 0;
  EXPECT_EQ(clamps, 2);
  // A loose thread is a screw pair and clamps nothing.
  const Analysis loose = Analyze(BoltedStack(Fastening::kLoose));
  EXPECT_EQ(loose.subassemblies.size(), 4u);  // bolt and nut make a screw pair: all separate
  // An override that forbids the bolt-nut pair (named nut first) leaves nothing to clamp.
  const FeatureRef bolt{2, 0}, nut{3, 0};
  const Analysis forbidden =
      Analyze(BoltedStack(Fastening::kTight, {PairOverride{{nut, bolt}, std::nullopt}}));
  EXPECT_EQ(forbidden.pairs.size(), 2u);
  for (const Pair& p : forbidden.pairs) EXPECT_EQ(p.type, PairType::kCylindrical);
}

Feature Face(const std::string& id, V origin, V normal, double size = 12) {
  return MakeFeature(id, K::kFace, origin, normal, [&](Feature& f) { f.width = f.height = size; });
}

// A clevis (ground) whose lugs span z 0..5 and 15..20, a lever between them (z 6..14, or
// 5..15 when `snug`), a tight bolt down from its head at z = 20 into a nut under the lugs.
Assembly Clevis(bool snug) {
  const V down = -V::UnitZ(), up = V::UnitZ();
  const double lever_bottom = snug ? 5 : 6, lever_top = snug ? 15 : 14;
  Feature upper = Hole(6.6, 5, V(0, 0, 20)), lower = Hole(6.6, 5, V(0, 0, 5));
  upper.id = "upper", lower.id = "lower";
  return MakeAssembly(
      {MakePart("clevis",
                {upper, lower, Face("top", V(0, 0, 20), up), Face("bottom", V(0, 0, 0), down),
                 Face("upper_inside", V(0, 0, 15), down), Face("lower_inside", V(0, 0, 5), up)},
                RigidTransform(), true),
       MakePart("lever",
                {Hole(6.6, lever_top - lever_bottom, V(0, 0, lever_top)),
                 Face("top", V(0, 0, lever_top), up), Face("bottom", V(0, 0, lever_bottom), down)}),
       MakePart("bolt", {Thread(6, 1, 25, V(0, 0, 20), down, Fastening::kTight),
                         Face("head", V(0, 0, 20), down)}),
       MakePart("nut", {Tapped(6, 1, 5, V(0, 0, 0), down), Face("top", V(0, 0, 0), up)})});
}

TEST(PairRecognition, ATightBoltClampsTheLugsItBearsOnNotTheLeverBetweenThem) {
  // Head and nut bear on the clevis; the lever, clear of both lugs, turns on the shank.
  const Recognition pivot = Recognize(Clevis(false));
  int clamps = 0;
  for (const Pair& p : pivot.pairs) {
    const bool lever = p.a.part == 1 || p.b.part == 1;
    if (p.source == PairSource::kClamp) ++clamps;
    if (lever) {
      EXPECT_EQ(p.type, PairType::kCylindrical);
    }
  }
  EXPECT_EQ(clamps, 2);                                      // both lugs
  EXPECT_EQ(Analyze(Clevis(false)).motion.mobility.dof, 2);  // the lever turns and slides
  // Snug between the lugs (faces touching), the lever is in the clamped stack.
  const Analysis snug = Analyze(Clevis(true));
  EXPECT_EQ(snug.subassemblies.size(), 1u);
  EXPECT_EQ(snug.motion.mobility.dof, 0);
}

TEST(PairRecognition, BodiesOfOneCadPartTouchingFaceToFaceAreOnePiece) {
  auto parts = [](const std::string& body_of_b) {
    Part a = MakePart("bar", {Face("end", V(0, 0, 0), V::UnitZ())}, RigidTransform(), true);
    Part b = MakePart("bar_solid2", {Face("end", V(0, 0, 0), -V::UnitZ())});
    a.body_of = "bar";
    b.body_of = body_of_b;
    return MakeAssembly({a, b});
  };
  const Recognition one = Recognize(parts("bar"));
  const Pair fixed = Only(one);
  EXPECT_EQ(fixed.type, PairType::kFixed);
  EXPECT_EQ(fixed.source, PairSource::kOnePart);
  EXPECT_TRUE(HasDiagnostic(one, "one_part", "bar, bar_solid2 are bodies of one CAD part, 'bar'"));
  // Solids of different parts touching are a planar pair, as always.
  EXPECT_EQ(Only(Recognize(parts(""))).type, PairType::kPlanar);
  EXPECT_EQ(Only(Recognize(parts("other"))).type, PairType::kPlanar);
}

TEST(PairRecognition, AFaceReachesNoFurtherThanItsPart) {
  // A 40 mm square plate's top face and a spacer's underside in its plane, the spacer 2 mm
  // beyond the plate's edge: the circles around the faces' extents (which do not say which
  // way the faces lie) overlap, the parts do not touch, and no planar pair joins them (the
  // Onshape reducer's disc and its cover's spacers). Over the plate's edge, they do.
  auto parts = [](double spacer_x) {
    Part plate = MakePart("plate",
                          {MakeFeature("top", K::kFace, V(0, 0, 5), V::UnitZ(),
                                       [](Feature& f) { f.width = f.height = 40; })},
                          RigidTransform(), true);
    plate.mesh = testing::Boxes({{V(-20, -20, 0), V(20, 20, 5)}});
    Part spacer = MakePart("spacer", {MakeFeature("under", K::kFace, V(spacer_x, 0, 5), -V::UnitZ(),
                                                  [](Feature& f) { f.width = f.height = 8; })});
    spacer.mesh = testing::Boxes({{V(spacer_x - 4, -4, 5), V(spacer_x + 4, 4, 10)}});
    return MakeAssembly({plate, spacer});
  };
  const Assembly apart = parts(26);
  EXPECT_LT((apart.part(1).features[0].origin - apart.part(0).features[0].origin).norm(),
            (std::hypot(40, 40) + std::hypot(8, 8)) / 2);
  EXPECT_TRUE(Recognize(apart).pairs.empty());
  EXPECT_EQ(Only(Recognize(parts(22))).type, PairType::kPlanar);
}

TEST(PairRecognition, SetscrewFixesTheShaftItBearsOn) {
  // A hub on a shaft along x; a setscrew down the hub's radial tapped hole to the shaft.
  Feature shaft = Shaft(6, 40, V(-20, 0, 0), V::UnitX());
  Feature bore = MakeFeature("bore", K::kHole, V(-5, 0, 0), V::UnitX(), [](Feature& f) {
    f.diameter = 6;
    f.length = 10;
    f.through = true;
  });
  Feature radial = Tapped(3, 0.5, 3, V(0, 0, 6), -V::UnitZ());
  radial.id = "radial";
  auto assembly = [&](double screw_length) {
    Feature screw = Thread(3, 0.5, screw_length, V(0, 0, 6), -V::UnitZ(), Fastening::kTight);
    return MakeAssembly({MakePart("shaft", {shaft}, RigidTransform(), true),
                         MakePart("hub", {bore, radial}), MakePart("setscrew", {screw})});
  };
  const Analysis reaching = Analyze(assembly(3.0));  // tip at z = 3: on the shaft's surface
  EXPECT_EQ(reaching.subassemblies.size(), 1u);
  bool found = false;
  for (const Pair& p : reaching.pairs) {
    if (p.source == PairSource::kSetscrew) {
      found = true;
      EXPECT_EQ(p.type, PairType::kFixed);
      EXPECT_EQ(p.a, (FeatureRef{0, 0}));
      EXPECT_EQ(p.b, (FeatureRef{1, 1}));
    }
  }
  EXPECT_TRUE(found);
  const Analysis short_screw = Analyze(assembly(2.0));  // tip 1 mm short of the shaft
  EXPECT_EQ(short_screw.subassemblies.size(), 2u);
}

Feature Gear(const std::string& id, int teeth, double module, V origin, V axis = V::UnitZ(),
             bool internal = false, double width = 10) {
  return MakeFeature(id, K::kGear, origin, axis, [&](Feature& f) {
    f.teeth = teeth;
    f.module = module;
    f.length = width;
    f.internal = internal;
  });
}

Recognition GearPair(const Feature& g1, const Feature& g2) {
  return Recognize(MakeAssembly({MakePart("g1", {g1}), MakePart("g2", {g2})}));
}

TEST(PairRecognition, ExternalAndInternalGearsWithExactRatios) {
  const Pair external = Only(GearPair(Gear("t", 17, 1, V::Zero()), Gear("t", 31, 1, V(24, 0, 0))));
  EXPECT_EQ(external.type, PairType::kGear);
  EXPECT_EQ(*external.ratio, Rational(-17, 31));  // w2 = -(z1/z2) w1
  EXPECT_FALSE(external.dof.has_value());
  // Centre distance along any direction in the plane.
  const double a = 1.5 * (20 + 30) / 2;
  const Pair diagonal =
      Only(GearPair(Gear("t", 20, 1.5, V::Zero()),
                    Gear("t", 30, 1.5, V(a / std::sqrt(2.0), a / std::sqrt(2.0), 0))));
  EXPECT_EQ(*diagonal.ratio, Rational(-2, 3));
  // Internal: planet of 10 in a ring of 40, distance m (40 - 10) / 2 = 15, same sense.
  const Pair internal =
      Only(GearPair(Gear("t", 10, 1, V(15, 0, 0)), Gear("t", 40, 1, V::Zero(), V::UnitZ(), true)));
  EXPECT_EQ(*internal.ratio, Rational(1, 4));  // ring per planet: +z_planet / z_ring
  // Axes of opposite sense: the ratio about each feature's own axis flips.
  EXPECT_EQ(
      *Only(GearPair(Gear("t", 17, 1, V::Zero()), Gear("t", 31, 1, V(24, 0, 10), -V::UnitZ())))
           .ratio,
      Rational(17, 31));
}

Feature Bevel(int teeth, double pitch_angle_deg, V axis, V apex = V::Zero(), double module = 2,
              double width = 8) {
  return MakeFeature("t", K::kBevelGear, apex, axis.normalized(), [&](Feature& f) {
    f.teeth = teeth;
    f.module = module;
    f.pitch_angle = pitch_angle_deg * kPi / 180;
    f.length = width;
  });
}

// Rolling without slip, checked on the vectors: at a point of the common pitch line (from the
// apex, at g1's pitch angle from its axis toward g2's), w1 a1 x p = (ratio w1) a2 x p.
void ExpectRollsOnPitchLine(const Feature& g1, const Feature& g2, const Rational& ratio) {
  const V side = (g2.axis - g2.axis.dot(g1.axis) * g1.axis).normalized();
  const V p = std::cos(g1.pitch_angle) * g1.axis + std::sin(g1.pitch_angle) * side;
  const V v1 = g1.axis.cross(p);
  const V v2 = ratio.ToDouble() * g2.axis.cross(p);
  EXPECT_LT((v1 - v2).norm(), 1e-12) << v1.transpose() << " vs " << v2.transpose();
}

TEST(PairRecognition, BevelGearsShareTheirApexAndRollOnTheirPitchCones) {
  // Square shafts: tan(pitch angle) = z1 / z2.
  const Feature pinion = Bevel(15, std::atan2(15, 30) * 180 / kPi, V::UnitZ());
  const Feature wheel = Bevel(30, std::atan2(30, 15) * 180 / kPi, V::UnitX());
  const Pair square = Only(GearPair(pinion, wheel));
  EXPECT_EQ(square.type, PairType::kBevelGear);
  EXPECT_EQ(*square.ratio, Rational(-1, 2));
  EXPECT_FALSE(square.dof.has_value());
  ExpectRollsOnPitchLine(pinion, wheel, *square.ratio);
  // Shafts 60 degrees apart: tan(pitch angle 1) = sin 60 / (z2 / z1 + cos 60).
  const double shaft = 60 * kPi / 180;
  const double gamma1 = std::atan2(std::sin(shaft), 30.0 / 20.0 + std::cos(shaft)) * 180 / kPi;
  const Feature g20 = Bevel(20, gamma1, V::UnitZ());
  const Feature g30 = Bevel(30, 60 - gamma1, V(std::sin(shaft), 0, std::cos(shaft)));
  const Pair acute = Only(GearPair(g20, g30));
  EXPECT_EQ(*acute.ratio, Rational(-2, 3));
  ExpectRollsOnPitchLine(g20, g30, *acute.ratio);
}

TEST(PairRecognition, DifferentialPinionMeshesBothSideGearsWhichDoNotMeshEachOther) {
  const Assembly differential = MakeAssembly({MakePart("left", {Bevel(16, 45, -V::UnitX())}),
                                              MakePart("pinion", {Bevel(16, 45, V::UnitZ())}),
                                              MakePart("right", {Bevel(16, 45, V::UnitX())})});
  const Recognition r = Recognize(differential);
  ASSERT_EQ(r.pairs.size(), 2u);
  for (const Pair& p : r.pairs) {
    EXPECT_EQ(p.type, PairType::kBevelGear);
    EXPECT_TRUE(p.a.part == 1 || p.b.part == 1) << "a pair without the pinion";
    EXPECT_EQ(*p.ratio, Rational(-1));
  }
  EXPECT_EQ(NearMisses(r), 0u);
}

TEST(PairRecognition, BevelGearNearMissesNameWhatIsOff) {
  const Feature pinion = Bevel(20, 45, V::UnitZ());
  const Recognition apex = GearPair(pinion, Bevel(20, 45, V::UnitX(), V(0, 0.5, 0)));
  EXPECT_TRUE(apex.pairs.empty());
  EXPECT_TRUE(HasDiagnostic(apex, "bevel_apex", "apexes are 0.5 mm apart"));
  const Recognition angles = GearPair(pinion, Bevel(20, 43.5, V::UnitX()));
  EXPECT_TRUE(angles.pairs.empty());
  EXPECT_TRUE(HasDiagnostic(angles, "bevel_pitch_angles", "45 deg + 43.5 deg = 88.5 deg"));
  const Recognition modules = GearPair(pinion, Bevel(20, 45, V::UnitX(), V::Zero(), 2.5));
  EXPECT_TRUE(HasDiagnostic(modules, "bevel_module_mismatch", "2 mm and 2.5 mm"));
  // 20 and 40 teeth both cut at 45 degrees: the cones touch, but the teeth sit 28 and 57 mm out.
  const Recognition cones = GearPair(pinion, Bevel(40, 45, V::UnitX()));
  EXPECT_TRUE(cones.pairs.empty());
  EXPECT_TRUE(HasDiagnostic(cones, "bevel_cone_distance", "28.2843 mm = 2 x 20 / (2 sin 45 deg)"));
  // 12 and 20 teeth both at 45 degrees with wide faces that overlap: the pitch circles would
  // roll at 1 : 1, not 12 : 20, so no pair either.
  const Recognition unequal = GearPair(Bevel(12, 45, V::UnitZ(), V::Zero(), 2, 12),
                                       Bevel(20, 45, V::UnitX(), V::Zero(), 2, 16));
  EXPECT_TRUE(unequal.pairs.empty());
  EXPECT_TRUE(HasDiagnostic(unequal, "bevel_cone_distance", "(required equal)"));
  // Two crown gears facing each other: one plane, no mesh and nothing to say.
  const Recognition crowns = GearPair(Bevel(30, 90, V::UnitZ()), Bevel(30, 90, -V::UnitZ()));
  EXPECT_TRUE(crowns.pairs.empty());
  EXPECT_EQ(NearMisses(crowns), 0u);
  Feature right = Bevel(20, 45, V::UnitZ()), also_right = Bevel(20, 45, V::UnitX());
  right.spiral_angle = also_right.spiral_angle = 35 * kPi / 180;
  EXPECT_TRUE(HasDiagnostic(GearPair(right, also_right), "bevel_spiral_mismatch", "35 deg"));
  also_right.spiral_angle = -right.spiral_angle;
  EXPECT_EQ(Only(GearPair(right, also_right)).type, PairType::kBevelGear);
}

TEST(PairRecognition, HelicalGearsMeshAtTheTransverseModulesDistance) {
  // 20 and 40 teeth, normal module 2, helix 15 degrees: centre distance 2 / cos(15 deg) x 60 / 2.
  const auto helical = [](int teeth, V origin, double helix_deg) {
    Feature f = Gear("t", teeth, 2, origin);
    f.helix_angle = helix_deg * kPi / 180;
    return f;
  };
  const double a = 2 / std::cos(15 * kPi / 180) * 60 / 2;
  const Pair pair = Only(GearPair(helical(20, V::Zero(), 15), helical(40, V(a, 0, 0), -15)));
  EXPECT_EQ(pair.type, PairType::kGear);
  EXPECT_EQ(*pair.ratio, Rational(-1, 2));
  // Two right-hand helices do not mesh externally: a near miss naming the helix angles.
  const Recognition same = GearPair(helical(20, V::Zero(), 15), helical(40, V(a, 0, 0), 15));
  EXPECT_TRUE(same.pairs.empty());
  EXPECT_TRUE(HasDiagnostic(same, "gear_helix_mismatch", "of opposite hands"));
  // 1.12 mm short of that distance (near the normal module's 60): a near miss with the formula.
  const Recognition spur = GearPair(helical(20, V::Zero(), 15), helical(40, V(61, 0, 0), -15));
  EXPECT_TRUE(spur.pairs.empty());
  EXPECT_TRUE(HasDiagnostic(spur, "gear_center_distance", "= 2 / cos(15 deg) x (20 + 40) / 2"));
}

TEST(PairRecognition, GearNearMisses) {
  const Recognition off = GearPair(Gear("t", 20, 1, V::Zero()), Gear("t", 10, 1, V(15.4, 0, 0)));
  EXPECT_TRUE(off.pairs.empty());
  EXPECT_TRUE(
      HasDiagnostic(off, "gear_center_distance", "centre distance 15.4 mm, required 15 mm"));
  EXPECT_TRUE(HasDiagnostic(off, "gear_center_distance", "off by 0.4 mm"));
  const Recognition module =
      GearPair(Gear("t", 20, 1, V::Zero()), Gear("t", 10, 1.25, V(15, 0, 0)));
  EXPECT_TRUE(module.pairs.empty());
  EXPECT_TRUE(HasDiagnostic(module, "gear_module_mismatch", "1 mm and 1.25 mm"));
  const double tilt = 1.0 * kPi / 180;
  const Recognition skew =
      GearPair(Gear("t", 20, 1, V::Zero()),
               Gear("t", 10, 1, V(15, 0, 0), V(0, std::sin(tilt), std::cos(tilt))));
  EXPECT_TRUE(skew.pairs.empty());
  EXPECT_TRUE(HasDiagnostic(skew, "gear_axes_not_parallel"));
  // Face widths apart along the axis: no pair, no near miss.
  EXPECT_TRUE(GearPair(Gear("t", 20, 1, V::Zero()), Gear("t", 10, 1, V(15, 0, 20))).pairs.empty());
  // Three modules off: silence.
  const Recognition far = GearPair(Gear("t", 20, 1, V::Zero()), Gear("t", 10, 1, V(18, 0, 0)));
  EXPECT_TRUE(far.pairs.empty());
  EXPECT_EQ(NearMisses(far), 0u);
}

Recognition WormDrive(Hand hand, double worm_y, double friction = 0.1, double pitch_diameter = 10,
                      double module_wheel = 1) {
  Feature worm = MakeFeature("worm", K::kWorm, V(-10, worm_y, 4), V::UnitX(), [&](Feature& f) {
    f.starts = 1;
    f.module = 1;
    f.pitch_diameter = pitch_diameter;
    f.length = 20;
    f.hand = hand;
  });
  Feature wheel = MakeFeature("teeth", K::kWormWheel, V::Zero(), V::UnitZ(), [&](Feature& f) {
    f.teeth = 40;
    f.module = module_wheel;
    f.length = 8;
  });
  return Recognize(
      MakeAssembly({MakePart("worm", {worm}), MakePart("wheel", {wheel})}, {}, friction));
}

TEST(PairRecognition, WormGearRatioFollowsHandAndSide) {
  const Pair below = Only(WormDrive(Hand::kRight, -25));
  EXPECT_EQ(below.type, PairType::kWormGear);
  EXPECT_EQ(*below.ratio, Rational(-1, 40));
  EXPECT_EQ(*Only(WormDrive(Hand::kRight, 25)).ratio, Rational(1, 40));
  EXPECT_EQ(*Only(WormDrive(Hand::kLeft, -25)).ratio, Rational(1, 40));
  EXPECT_EQ(*Only(WormDrive(Hand::kLeft, 25)).ratio, Rational(-1, 40));
}

TEST(PairRecognition, WormSelfLockingFollowsTheFrictionAngle) {
  // Lead angle atan(1 / 10) = 5.71 deg; friction angle atan(0.05) = 2.9, atan(0.15) = 8.5 deg.
  EXPECT_FALSE(Only(WormDrive(Hand::kRight, -25, 0.05)).self_locking);
  EXPECT_TRUE(Only(WormDrive(Hand::kRight, -25, 0.15)).self_locking);
}

TEST(PairRecognition, WormNearMisses) {
  EXPECT_TRUE(
      HasDiagnostic(WormDrive(Hand::kRight, -25.3), "worm_center_distance", "off by 0.3 mm"));
  EXPECT_TRUE(HasDiagnostic(WormDrive(Hand::kRight, -25, 0.1, 10, 1.25), "worm_module_mismatch"));
}

TEST(PairRecognition, RackAndPinionTravel) {
  // Pinion of 20 teeth, module 2 at the origin; rack along +x below it, pitch line at y = -20.
  Feature pinion = Gear("teeth", 20, 2, V(0, 0, -5));
  auto rack_at = [&](double y) {
    Feature rack = MakeFeature("rack", K::kRack, V(-50, y, 0), V::UnitX(), [](Feature& f) {
      f.module = 2;
      f.length = 100;
      f.normal = V::UnitY();
    });
    return Recognize(MakeAssembly({MakePart("pinion", {pinion}), MakePart("rack", {rack})}));
  };
  const Pair p = Only(rack_at(-20));
  EXPECT_EQ(p.type, PairType::kRackPinion);
  EXPECT_NEAR(*p.travel_per_revolution, kPi * 2 * 20, 1e-9);  // +x for a positive turn about +z
  EXPECT_TRUE(HasDiagnostic(rack_at(-20.5), "rack_pitch_line_distance", "off by 0.5 mm"));
}

TEST(PairRecognition, SlotsBallsAndFaces) {
  Feature slot = MakeFeature("slot", K::kSlot, V(0, 0, 0), V::UnitX(), [](Feature& f) {
    f.width = 4;
    f.length = 30;
    f.depth = 3;
    f.normal = -V::UnitZ();
  });
  Feature pin = Shaft(4, 10, V(10, 0, 5), -V::UnitZ());
  EXPECT_EQ(Only(Recognize(MakeAssembly({MakePart("guide", {slot}), MakePart("pin", {pin})}))).type,
            PairType::kPinSlot);
  Feature fat = Shaft(4.5, 10, V(10, 0, 5), -V::UnitZ());
  EXPECT_TRUE(
      HasDiagnostic(Recognize(MakeAssembly({MakePart("guide", {slot}), MakePart("pin", {fat})})),
                    "pin_wider_than_slot"));
  Feature key = MakeFeature("key", K::kKey, V(5, 0, 0), V::UnitX(), [](Feature& f) {
    f.width = 4;
    f.length = 10;
    f.normal = -V::UnitZ();
  });
  EXPECT_EQ(
      Only(Recognize(MakeAssembly({MakePart("guide", {slot}), MakePart("slider", {key})}))).type,
      PairType::kPrismatic);

  auto sphere = [](const std::string& id, K kind, double d, V at) {
    return MakeFeature(id, kind, at, V::UnitZ(), [d](Feature& f) { f.diameter = d; });
  };
  EXPECT_EQ(Only(Recognize(MakeAssembly({MakePart("a", {sphere("b", K::kBall, 10, V::Zero())}),
                                         MakePart("b", {sphere("s", K::kSocket, 10, V::Zero())})})))
                .type,
            PairType::kSpherical);
  EXPECT_TRUE(HasDiagnostic(
      Recognize(MakeAssembly({MakePart("a", {sphere("b", K::kBall, 10, V::Zero())}),
                              MakePart("b", {sphere("s", K::kSocket, 12, V::Zero())})})),
      "ball_socket_mismatch"));

  auto face = [](const std::string& id, V at, V normal) {
    return MakeFeature(id, K::kFace, at, normal, [](Feature& f) {
      f.width = 10;
      f.height = 10;
    });
  };
  EXPECT_EQ(
      Only(Recognize(MakeAssembly({MakePart("a", {face("top", V(0, 0, 1), V::UnitZ())}),
                                   MakePart("b", {face("bottom", V(3, 0, 1), -V::UnitZ())})})))
          .type,
      PairType::kPlanar);
  // Same-facing or separated faces: no pair.
  EXPECT_TRUE(Recognize(MakeAssembly({MakePart("a", {face("top", V(0, 0, 1), V::UnitZ())}),
                                      MakePart("b", {face("bottom", V(3, 0, 1), V::UnitZ())})}))
                  .pairs.empty());
  EXPECT_TRUE(Recognize(MakeAssembly({MakePart("a", {face("top", V(0, 0, 1), V::UnitZ())}),
                                      MakePart("b", {face("bottom", V(3, 0, 1.5), -V::UnitZ())})}))
                  .pairs.empty());
}

TEST(PairRecognition, EveryOtherConditionViolatedOnce) {
  // Worm: axes parallel instead of perpendicular; wheel beyond the worm's length.
  Feature wheel = MakeFeature("teeth", K::kWormWheel, V::Zero(), V::UnitZ(), [](Feature& f) {
    f.teeth = 40;
    f.module = 1;
    f.length = 8;
  });
  auto worm_at = [](V origin, V axis) {
    return MakeFeature("worm", K::kWorm, origin, axis, [](Feature& f) {
      f.module = 1;
      f.pitch_diameter = 10;
      f.length = 20;
    });
  };
  auto worm_pairs = [&](const Feature& worm) {
    return Recognize(MakeAssembly({MakePart("worm", {worm}), MakePart("wheel", {wheel})}))
        .pairs.size();
  };
  EXPECT_EQ(worm_pairs(worm_at(V(-10, -25, 4), V::UnitX())), 1u);
  EXPECT_EQ(worm_pairs(worm_at(V(0, -25, 0), V::UnitZ())), 0u);
  EXPECT_EQ(worm_pairs(worm_at(V(15, -25, 4), V::UnitX())), 0u);

  // Rack: pinion axis along the rack's normal; pinion on the back of the rack.
  auto rack_pairs = [](V gear_axis, V normal) {
    Feature pinion = Gear("teeth", 20, 2, V(0, 0, -5), gear_axis);
    Feature rack = MakeFeature("rack", K::kRack, V(-50, -20, 0), V::UnitX(), [&](Feature& f) {
      f.module = 2;
      f.length = 100;
      f.normal = normal;
    });
    return Recognize(MakeAssembly({MakePart("pinion", {pinion}), MakePart("rack", {rack})}))
        .pairs.size();
  };
  EXPECT_EQ(rack_pairs(V::UnitZ(), V::UnitY()), 1u);
  EXPECT_EQ(rack_pairs(V::UnitY(), V::UnitZ()), 0u);
  EXPECT_EQ(rack_pairs(V::UnitZ(), -V::UnitY()), 0u);

  // Pin in slot: pin along the slot's axis; pin beside the slot.
  Feature slot = MakeFeature("slot", K::kSlot, V(0, 0, 0), V::UnitX(), [](Feature& f) {
    f.width = 4;
    f.length = 30;
    f.depth = 3;
    f.normal = -V::UnitZ();
  });
  auto slot_pairs = [&](const Feature& other) {
    return Recognize(MakeAssembly({MakePart("guide", {slot}), MakePart("other", {other})}))
        .pairs.size();
  };
  EXPECT_EQ(slot_pairs(Shaft(4, 10, V(10, 0, 5), -V::UnitZ())), 1u);
  EXPECT_EQ(slot_pairs(Shaft(4, 10, V(10, 0, 0), V::UnitX())), 0u);
  EXPECT_EQ(slot_pairs(Shaft(4, 10, V(10, 1, 5), -V::UnitZ())), 0u);
  EXPECT_EQ(slot_pairs(Shaft(4, 10, V(40, 0, 5), -V::UnitZ())), 0u);  // beyond the slot's end

  // Key in slot: not parallel; normal reversed; key wider.
  auto key = [](V axis, V normal, double width) {
    return MakeFeature("key", K::kKey, V(5, 0, 0), axis, [&](Feature& f) {
      f.width = width;
      f.length = 10;
      f.normal = normal;
    });
  };
  EXPECT_EQ(slot_pairs(key(V::UnitX(), -V::UnitZ(), 4)), 1u);
  EXPECT_EQ(slot_pairs(key(V::UnitY(), -V::UnitZ(), 4)), 0u);
  EXPECT_EQ(slot_pairs(key(V::UnitX(), V::UnitZ(), 4)), 0u);
  EXPECT_TRUE(
      HasDiagnostic(Recognize(MakeAssembly({MakePart("guide", {slot}),
                                            MakePart("other", {key(V::UnitX(), -V::UnitZ(), 5)})})),
                    "key_wider_than_slot"));

  // Ball and socket: centres apart.
  auto sphere = [](const std::string& id, K kind, V at) {
    return MakeFeature(id, kind, at, V::UnitZ(), [](Feature& f) { f.diameter = 10; });
  };
  const Recognition apart =
      Recognize(MakeAssembly({MakePart("a", {sphere("b", K::kBall, V::Zero())}),
                              MakePart("b", {sphere("s", K::kSocket, V(2, 0, 0))})}));
  EXPECT_TRUE(apart.pairs.empty());
  EXPECT_TRUE(HasDiagnostic(apart, "ball_socket_mismatch", "centres 2 mm apart"));
}

TEST(PairRecognition, OverridesForceOrForbidPairs) {
  Feature s = Shaft(5, 20, V(0, 0, 15), -V::UnitZ());
  const std::vector<Part> parts = {MakePart("block", {Hole(5, 10)}, RigidTransform(), true),
                                   MakePart("pin", {s})};
  const FeatureRef pin{1, 0}, hole{0, 0};
  const Recognition forbidden =
      Recognize(MakeAssembly(parts, {PairOverride{{pin, hole}, std::nullopt}}));
  EXPECT_TRUE(forbidden.pairs.empty());
  const Pair glued =
      Only(Recognize(MakeAssembly(parts, {PairOverride{{hole, pin}, PairType::kFixed}})));
  EXPECT_EQ(glued.type, PairType::kFixed);
  EXPECT_EQ(glued.source, PairSource::kOverride);
  EXPECT_EQ(glued.a, pin);  // the convex feature first, whatever the override's order
}

// A hinge whose pin the file leaves out: a fork's two cheeks (holes of `fork_d` through z in
// [0, 3] and [8, 11]) and a knuckle between them (a hole of `knuckle_d` through z in
// [3 + gap, 8 - gap]), all on the z axis; `pin` adds a shaft through all three.
Assembly Hinge(double fork_d, double knuckle_d, double gap = 0.0, bool pin = false) {
  const auto hole = [](const char* id, double d, double z0, double z1) {
    return MakeFeature(id, K::kHole, V(0, 0, z0), V::UnitZ(),
                       [&](Feature& f) { f.diameter = d, f.length = z1 - z0, f.through = true; });
  };
  std::vector<Part> parts = {
      MakePart("fork", {hole("cheek_a", fork_d, 0, 3), hole("cheek_b", fork_d, 8, 11)},
               RigidTransform(), true),
      MakePart("lever", {hole("knuckle", knuckle_d, 3 + gap, 8 - gap)})};
  if (pin) parts.push_back(MakePart("pin", {Shaft(knuckle_d, 11, V(0, 0, -0.5))}));
  return MakeAssembly(parts);
}

TEST(PairRecognition, CoaxialEmptyHolesOfTwoPartsAreAnImpliedPin) {
  // The knuckle's press-fit bore (3.2) between the fork's running holes (3.45): a revolute
  // pair per cheek, sourced implied_pin, and one info diagnostic naming the holes and the pin.
  const Recognition hinge = Recognize(Hinge(3.45, 3.2));
  ASSERT_EQ(hinge.pairs.size(), 2u);
  for (const Pair& p : hinge.pairs) {
    EXPECT_EQ(p.type, PairType::kRevolute);
    EXPECT_EQ(p.source, PairSource::kImpliedPin);
    EXPECT_EQ(*p.dof, 1);
  }
  const Diagnostic* d = FindDiagnostic(hinge, "implied_pin");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->severity, Severity::kInfo);
  EXPECT_EQ(d->parts, (std::vector<std::string>{"fork", "lever"}));
  EXPECT_NE(d->message.find("a pin of about 3.2 mm"), std::string::npos) << d->message;
  EXPECT_NE(d->message.find("fork/cheek_a, fork/cheek_b, lever/knuckle"), std::string::npos)
      << d->message;
  // The lever turns about the pin's axis: one freedom.
  EXPECT_EQ(Analyze(Hinge(3.45, 3.2)).motion.mobility.dof, 1);
  // A small axial clearance between the faces is still a hinge, and so is a gap a rod of the
  // holes' size bridges (knuckles spaced apart on one rod, as in the robot hand's palm); a gap
  // wider than the holes is not.
  EXPECT_EQ(Recognize(Hinge(3.45, 3.2, 0.4)).pairs.size(), 2u);
  EXPECT_EQ(Recognize(Hinge(3.45, 3.2, 1.5)).pairs.size(), 2u);
  EXPECT_TRUE(Recognize(Hinge(1.2, 1.1, 1.5)).pairs.empty());
  // A thinner rod on the axis (a bolt in a bearing's bore, whose recesses are holes too):
  // nothing missing bridges the gap.
  std::vector<Part> rod = Hinge(3.45, 3.2, 1.5).parts();
  rod.push_back(MakePart("rod", {Shaft(2.0, 11, V(0, 0, -0.5))}));
  EXPECT_FALSE(HasDiagnostic(Recognize(MakeAssembly(rod)), "implied_pin"));
  // Holes of unlike sizes are not one pivot (a 3 mm hole beside a 5 mm one).
  EXPECT_TRUE(Recognize(Hinge(5.0, 3.0)).pairs.empty());
  // With the pin modelled, the pin makes the pairs and no pin is implied.
  const Recognition pinned = Recognize(Hinge(3.45, 3.2, 0.0, true));
  EXPECT_FALSE(pinned.pairs.empty());
  for (const Pair& p : pinned.pairs) EXPECT_NE(p.source, PairSource::kImpliedPin);
  EXPECT_FALSE(HasDiagnostic(pinned, "implied_pin"));
  // An override of type none forbids an implied pin like any pair.
  std::vector<Part> parts = Hinge(3.45, 3.2).parts();
  const Recognition forbidden = Recognize(
      MakeAssembly(parts, {PairOverride{{FeatureRef{0, 0}, FeatureRef{1, 0}}, std::nullopt},
                           PairOverride{{FeatureRef{0, 1}, FeatureRef{1, 0}}, std::nullopt}}));
  EXPECT_TRUE(forbidden.pairs.empty());
  EXPECT_FALSE(HasDiagnostic(forbidden, "implied_pin"));
  // So does the file's "infer": {"implied_pins": false}, for all of them.
  AssemblySpec off;
  off.parts = Hinge(3.45, 3.2).parts();
  off.inference.implied_pins = false;
  const Recognition none = Recognize(Assembly(std::move(off)));
  EXPECT_TRUE(none.pairs.empty());
  EXPECT_FALSE(HasDiagnostic(none, "implied_pin"));
}

// Two plates, each with empty through holes on the z axis (`d0`) and on an axis `apart` mm
// along x (`d1`), listed in that order or (`b_first`) the other: a pin the file leaves out in
// each pair of holes, as dowels or (in the robot hand) tendon channels through a palm and its
// forearm.
Assembly DowelledPlates(double d0, double d1, double apart, bool b_first = false) {
  const auto plate = [&](const char* name, double z0, bool ground) {
    const auto hole = [&](const char* id, double d, double x) {
      return MakeFeature(id, K::kHole, V(x, 0, z0), V::UnitZ(),
                         [&](Feature& f) { f.diameter = d, f.length = 3, f.through = true; });
    };
    std::vector<Feature> holes = {hole("a", d0, 0), hole("b", d1, apart)};
    if (b_first) std::swap(holes[0], holes[1]);
    return MakePart(name, holes, RigidTransform(), ground);
  };
  return MakeAssembly({plate("base", 0, true), plate("cover", 3, false)});
}

TEST(PairRecognition, ImpliedPinsApartHoldThePartsFixed) {
  // Pins on two parallel axes 28 mm apart let neither plate turn: one fixed pair, and one info
  // naming all four holes and both pins.
  const Recognition dowelled = Recognize(DowelledPlates(1.5, 8.9, 28));
  const Pair p = Only(dowelled);
  EXPECT_EQ(p.type, PairType::kFixed);
  EXPECT_EQ(p.source, PairSource::kImpliedPin);
  EXPECT_EQ(*p.dof, 0);
  const Diagnostic* d = FindDiagnostic(dowelled, "implied_pin");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->severity, Severity::kInfo);
  EXPECT_NE(d->message.find("held together by pins"), std::string::npos) << d->message;
  EXPECT_NE(d->message.find("base/a, base/b, cover/a, cover/b"), std::string::npos) << d->message;
  EXPECT_NE(d->message.find("pins of about 1.5 mm and 8.9 mm on 2 axes"), std::string::npos)
      << d->message;
  EXPECT_EQ(Analyze(DowelledPlates(1.5, 8.9, 28)).motion.mobility.dof, 0);
  // The fixed pair stands on the same holes whatever the file's order.
  const Pair swapped = Only(Recognize(DowelledPlates(1.5, 8.9, 28, true)));
  const Assembly listed_b_first = DowelledPlates(1.5, 8.9, 28, true);
  EXPECT_EQ(listed_b_first.FeatureName(swapped.a), "base/a");
  EXPECT_EQ(listed_b_first.FeatureName(swapped.b), "cover/a");
  // Pins alike are named once.
  const Recognition pinned_alike = Recognize(DowelledPlates(1.5, 1.5, 28));
  const Diagnostic* alike = FindDiagnostic(pinned_alike, "implied_pin");
  ASSERT_NE(alike, nullptr);
  EXPECT_NE(alike->message.find("pins of about 1.5 mm on 2 axes"), std::string::npos)
      << alike->message;
  // With one pin forbidden, the other is a hinge.
  std::vector<Part> parts = DowelledPlates(1.5, 8.9, 28).parts();
  const Recognition hinged =
      Recognize(MakeAssembly(parts, {PairOverride{{FeatureRef{0, 1}, FeatureRef{1, 1}}, {}}}));
  EXPECT_EQ(Only(hinged).type, PairType::kRevolute);
  const Diagnostic* one = FindDiagnostic(hinged, "implied_pin");
  ASSERT_NE(one, nullptr);
  EXPECT_NE(one->message.find("turn on a pin of about 1.5 mm"), std::string::npos) << one->message;
  // Crossing pins (along z, and along x 20 mm away) hold the plates too.
  const auto hole = [](const char* id, V at, V axis) {
    return MakeFeature(id, K::kHole, at, axis,
                       [&](Feature& f) { f.diameter = 3, f.length = 3, f.through = true; });
  };
  const Recognition crossed = Recognize(MakeAssembly(
      {MakePart("base", {hole("a", V(0, 0, 0), V::UnitZ()), hole("c", V(0, 20, 10), V::UnitX())},
                RigidTransform(), true),
       MakePart("cover",
                {hole("a", V(0, 0, 3), V::UnitZ()), hole("c", V(3, 20, 10), V::UnitX())})}));
  EXPECT_EQ(Only(crossed).type, PairType::kFixed);
}

TEST(PairRecognition, HolesALittleOutOfLineAreOneImpliedPin) {
  // A fork's cheeks 0.08 mm apart across, each within the length tolerance of the knuckle's
  // hole between them: one pin, a hinge, not two pins that hold the lever.
  const auto hole = [](const char* id, double x, double z0) {
    return MakeFeature(id, K::kHole, V(x, 0, z0), V::UnitZ(),
                       [&](Feature& f) { f.diameter = 3.2, f.length = 3, f.through = true; });
  };
  // Either part's name first: the pairs' order must not decide it.
  for (const char* lever : {"lever", "a_lever"}) {
    const Recognition hinge =
        Recognize(MakeAssembly({MakePart("fork", {hole("cheek_a", 0, 0), hole("cheek_b", 0.08, 6)},
                                         RigidTransform(), true),
                                MakePart(lever, {hole("knuckle", 0.04, 3)})}));
    ASSERT_EQ(hinge.pairs.size(), 2u) << lever;
    for (const Pair& p : hinge.pairs) EXPECT_EQ(p.type, PairType::kRevolute) << lever;
    const Diagnostic* knuckle = FindDiagnostic(hinge, "implied_pin");
    ASSERT_NE(knuckle, nullptr);
    EXPECT_NE(knuckle->message.find("turn on a pin of about 3.2 mm"), std::string::npos)
        << knuckle->message;
  }
}

TEST(PairRecognition, ALooseShaftGuidesOnlyAPartNothingElseHolds) {
  // 4.6 in 5 (8% of the hole): too loose to touch, but the pin is in no other pair, so the fit
  // guides it (a print-in-place hinge's pins are printed so).
  const Recognition loose = Recognize(ShaftInHole(4.6, 5.0));
  const Pair p = Only(loose);
  EXPECT_EQ(p.type, PairType::kCylindrical);
  EXPECT_EQ(p.source, PairSource::kLooseFit);
  const Diagnostic* d = FindDiagnostic(loose, "loose_fit");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->severity, Severity::kInfo);
  EXPECT_NE(d->message.find("0.2 mm of radial clearance"), std::string::npos) << d->message;
  EXPECT_FALSE(HasDiagnostic(loose, "part_unconnected"));
  // Beyond 10% it passes through.
  EXPECT_TRUE(Recognize(ShaftInHole(4.4, 5.0)).pairs.empty());
  // A pin held by a fit of its own: the loose one makes no pair.
  Feature held = Shaft(5.0, 20, V(20, 0, 15), -V::UnitZ());
  held.id = "s2";
  Feature seat = Hole(5.02, 10, V(20, 0, 10));
  seat.id = "h2";
  Feature loose_shaft = Shaft(4.6, 20, V(0, 0, 15), -V::UnitZ());
  const Recognition both =
      Recognize(MakeAssembly({MakePart("block", {Hole(5.0, 10), seat}, RigidTransform(), true),
                              MakePart("pin", {loose_shaft, held})}));
  ASSERT_EQ(both.pairs.size(), 1u);
  EXPECT_EQ(both.pairs[0].source, PairSource::kRecognised);
  // A knuckle between two stubs entering its bore from both ends cannot slide off: revolute.
  Feature low = Shaft(4.6, 1, V(0, 0, -0.5), V::UnitZ());
  Feature high = Shaft(4.6, 1, V(0, 0, 10.5), -V::UnitZ());
  high.id = "s2";
  Feature bore = Hole(5.0, 10);
  bore.through = true;
  const Assembly knuckle = MakeAssembly(
      {MakePart("frame", {low, high}, RigidTransform(), true), MakePart("leaf", {bore})});
  const Recognition hinge = Recognize(knuckle);
  ASSERT_EQ(hinge.pairs.size(), 2u);
  for (const Pair& q : hinge.pairs) EXPECT_EQ(q.type, PairType::kRevolute);
  EXPECT_EQ(Analyze(knuckle).motion.mobility.dof, 1);
}

TEST(PairRecognition, AWasherBetweenTwoFacesTurnsOnItsLooseShaft) {
  // A washer (8.5 mm hole, 1.15 thick) on an 8 mm shaft between two faces of the frame: the
  // faces alone leave it a turn and two slides across the shaft, which the loose shaft takes
  // away.
  const auto face = [](const char* id, double z, double nz) {
    return MakeFeature(id, K::kFace, V(0, 0, z), V(0, 0, nz), [](Feature& f) {
      f.width = 12;
      f.height = 12;
    });
  };
  Feature bore = Hole(8.5, 1.15, V(0, 0, 1.15));
  bore.through = true;
  const Assembly washer =
      MakeAssembly({MakePart("frame",
                             {Shaft(8.0, 20, V(0, 0, -10), V::UnitZ()), face("below", 0, 1),
                              face("above", 1.15, -1)},
                             RigidTransform(), true),
                    MakePart("washer", {bore, face("bottom", 0, -1), face("top", 1.15, 1)})});
  const Recognition r = Recognize(washer);
  int loose = 0;
  for (const Pair& p : r.pairs) {
    if (p.source != PairSource::kLooseFit) continue;
    EXPECT_EQ(p.type, PairType::kCylindrical);
    ++loose;
  }
  EXPECT_EQ(loose, 1);
  const Diagnostic* d = FindDiagnostic(r, "loose_fit");
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->message.find("0.25 mm of radial clearance and face contacts"), std::string::npos)
      << d->message;
  EXPECT_EQ(Analyze(washer).motion.mobility.dof, 1);
}

TEST(PairRecognition, ACompliantPartJoinsNoPairAndSaysWhatItConnects) {
  // A spring whose end coils sit on the spigots of a frame and of a plunger whose rod runs in
  // the frame's bore: compliant, it joins nothing and moves with nothing, and the plunger keeps
  // the two freedoms of its rod in the bore.
  const auto cylinder = [](const char* id, K kind, double d, double z0, double length) {
    return MakeFeature(id, kind, V(0, 0, z0), V::UnitZ(), [&](Feature& f) {
      f.diameter = d, f.length = length, f.through = kind == K::kHole;
    });
  };
  const auto assembly = [&](bool compliant) {
    Part spring = MakePart("spring", {cylinder("coil_low", K::kHole, 6, 0, 3),
                                      cylinder("coil_high", K::kHole, 6, 17, 3)});
    spring.compliant = compliant;
    return MakeAssembly(
        {MakePart("frame",
                  {cylinder("spigot", K::kShaft, 6, -5, 8), cylinder("bore", K::kHole, 4, -30, 20)},
                  RigidTransform(), true),
         MakePart("plunger", {cylinder("spigot", K::kShaft, 6, 16, 8),
                              cylinder("rod", K::kShaft, 4, -30, 20)}),
         spring});
  };
  EXPECT_EQ(Recognize(assembly(false)).pairs.size(), 3u);  // both coils on spigots, the rod
  const Assembly soft = assembly(true);
  const Recognition r = Recognize(soft);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_EQ(r.pairs[0].type, PairType::kCylindrical);
  const Diagnostic* d = FindDiagnostic(r, "compliant_part");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->severity, Severity::kInfo);
  EXPECT_NE(d->message.find("part 'spring' is compliant"), std::string::npos) << d->message;
  EXPECT_NE(d->message.find("it connects frame, plunger"), std::string::npos) << d->message;
  EXPECT_EQ(d->parts, (std::vector<std::string>{"spring", "frame", "plunger"}));
  EXPECT_FALSE(HasDiagnostic(r, "part_unconnected"));
  // The spring adds no freedom and no free motion: the rod's two are the mechanism's.
  const Analysis an = Analyze(soft);
  EXPECT_EQ(an.motion.mobility.dof, 2);
  for (const Diagnostic& diag : an.diagnostics) {
    if (diag.code != "free_motion" && diag.code != "part_unconnected" && diag.code != "jam") {
      continue;
    }
    for (const std::string& part : diag.parts) EXPECT_NE(part, "spring") << diag.message;
  }
}

TEST(PairRecognition, CycloidDiscInItsPinRingCouplesLikeAnInternalGear) {
  // A 10-lobe disc 1.5 mm off the axis of an 11-pin ring: a cycloidal coupling at +10/11 (the
  // ring's rate per unit disc rate relative to the eccentric, as an internal gear pair).
  const auto assembly = [](int lobes, int pins, double offset) {
    return MakeAssembly({MakePart("housing",
                                  {MakeFeature("pins", K::kPinRing, V::Zero(), V::UnitZ(),
                                               [&](Feature& f) {
                                                 f.teeth = pins, f.diameter = 60,
                                                 f.pin_diameter = 6;
                                                 f.length = 10;
                                               })},
                                  RigidTransform(), true),
                         MakePart("disc", {MakeFeature("lobes", K::kCycloidDisc, V(0, offset, 0),
                                                       V::UnitZ(), [&](Feature& f) {
                                                         f.teeth = lobes, f.eccentricity = 1.5,
                                                         f.length = 10;
                                                       })})});
  };
  const Pair c = Only(Recognize(assembly(10, 11, 1.5)));
  EXPECT_EQ(c.type, PairType::kCycloidal);
  EXPECT_EQ(*c.ratio, Rational(10, 11));
  EXPECT_FALSE(c.dof.has_value());
  // Near misses name the quantity that is off.
  const Recognition pins = Recognize(assembly(10, 12, 1.5));
  EXPECT_TRUE(pins.pairs.empty());
  EXPECT_TRUE(HasDiagnostic(pins, "cycloid_pin_count", "12 pins for 10 lobes"));
  const Recognition off = Recognize(assembly(10, 11, 1.7));
  EXPECT_TRUE(off.pairs.empty());
  EXPECT_TRUE(HasDiagnostic(off, "cycloid_eccentricity", "required its eccentricity 1.5 mm"));
  EXPECT_TRUE(Recognize(assembly(10, 11, 5.0)).pairs.empty());  // far off: no pair, no note
}

// An output flange with `pins` pins of 6 mm on a 40 mm circle about z, and a disc with as
// many 9 mm holes on the same circle shifted by `shift` (the eccentricity): the holes of a
// cycloidal disc on its eccentric. `stray` moves the first hole by that much more.
Assembly PinsInHoles(int pins, V shift, V stray = V::Zero()) {
  std::vector<Feature> pin_features, hole_features;
  for (int k = 0; k < pins; ++k) {
    const double a = 2 * kPi * k / pins;
    const V c(20 * std::cos(a), 20 * std::sin(a), 0);
    pin_features.push_back(Shaft(6, 24, c));
    pin_features.back().id = "pin" + std::to_string(k + 1);
    hole_features.push_back(Hole(9, 10, c + shift + (k == 0 ? stray : V(V::Zero())), V::UnitZ()));
    hole_features.back().id = "hole" + std::to_string(k + 1);
  }
  return MakeAssembly({MakePart("output", pin_features), MakePart("disc", hole_features)});
}

TEST(PairRecognition, PinsInHolesOffCentreAlikeCoupleTheirParts) {
  // Each pin touches its hole's wall (1.5 mm off its centre, the radial clearance), all in
  // the same direction: one coupling at 1 (the parts keep one orientation), named by the
  // first pin and its hole, and one info.
  const Recognition r = Recognize(PinsInHoles(6, V(0, 1.5, 0)));
  const Pair p = Only(r);
  EXPECT_EQ(p.type, PairType::kPinsInHoles);
  EXPECT_EQ(*p.ratio, Rational(1));
  EXPECT_EQ(p.a, (FeatureRef{0, 0}));
  EXPECT_EQ(p.b, (FeatureRef{1, 0}));
  EXPECT_TRUE(HasDiagnostic(r, "pins_in_holes",
                            "the 6 pins of output (6 mm on a 40 mm circle) "
                            "run in the 6 holes of disc (9 mm), 1.5 mm"));
  // Any direction of the offset, three pins at least.
  EXPECT_EQ(
      Only(Recognize(PinsInHoles(3, V(1.5, 0, 0) / std::sqrt(2.0) + V(0, 1.5, 0) / std::sqrt(2.0))))
          .type,
      PairType::kPinsInHoles);
  // None: pins centred in their holes (nothing makes them touch), one hole 0.2 mm further
  // off (its pin would not touch it), one hole 0.2 mm aside (touching, but off another way
  // than the others), offsets short of the clearance, two pins.
  EXPECT_TRUE(Recognize(PinsInHoles(6, V::Zero())).pairs.empty());
  EXPECT_TRUE(Recognize(PinsInHoles(6, V(0, 1.5, 0), V(0, 0.2, 0))).pairs.empty());
  EXPECT_TRUE(Recognize(PinsInHoles(6, V(0, 1.5, 0), V(0.2, 0, 0))).pairs.empty());
  EXPECT_TRUE(Recognize(PinsInHoles(6, V(0, 1.0, 0))).pairs.empty());
  EXPECT_TRUE(Recognize(PinsInHoles(2, V(0, 1.5, 0))).pairs.empty());
}

TEST(PairRecognition, ForcedCouplingsGetTheSameParametersAsRecognisedOnes) {
  // Gears 2 mm too far apart to mesh, axes of opposite sense: forced into a gear pair, the
  // ratio is what recognition gives for opposite axes.
  const Feature g1 = Gear("t", 17, 1, V::Zero());
  const Feature g2 = Gear("t", 31, 1, V(26, 0, 10), -V::UnitZ());
  const Pair forced = Only(Recognize(
      MakeAssembly({MakePart("g1", {g1}), MakePart("g2", {g2})},
                   {PairOverride{{FeatureRef{0, 0}, FeatureRef{1, 0}}, PairType::kGear}})));
  EXPECT_EQ(forced.source, PairSource::kOverride);
  EXPECT_EQ(*forced.ratio, Rational(17, 31));
  // A worm gear forced with the wheel named first: the worm becomes `a`, and the ratio's sign
  // follows hand and side as for a recognised pair.
  const Recognition natural = WormDrive(Hand::kRight, -25);
  Feature worm = MakeFeature("worm", K::kWorm, V(-10, -25, 4), V::UnitX(), [](Feature& f) {
    f.module = 1;
    f.pitch_diameter = 10;
    f.length = 20;
  });
  Feature wheel = MakeFeature("teeth", K::kWormWheel, V::Zero(), V::UnitZ(), [](Feature& f) {
    f.teeth = 40;
    f.module = 1;
    f.length = 8;
  });
  const Pair worm_gear = Only(Recognize(
      MakeAssembly({MakePart("worm", {worm}), MakePart("wheel", {wheel})},
                   {PairOverride{{FeatureRef{1, 0}, FeatureRef{0, 0}}, PairType::kWormGear}})));
  EXPECT_EQ(worm_gear.a, (FeatureRef{0, 0}));
  EXPECT_EQ(*worm_gear.ratio, *Only(natural).ratio);
  EXPECT_EQ(worm_gear.self_locking, Only(natural).self_locking);
}

TEST(PairRecognition, RigidMotionOfTheWholeAssemblyChangesNothing) {
  const Assembly base = BoltedStack(Fastening::kTight);
  const Recognition reference = Recognize(base);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 20; ++trial) {
    const RigidTransform X =
        RigidTransform::Translation(V(u(random), u(random), u(random)) * 500) *
        RigidTransform::AxisAngle(V(u(random), u(random), u(random)), 3 * u(random));
    AssemblyState moved = InitialState(base);
    for (RigidTransform& X_WP : moved.X_WP) X_WP = X * X_WP;
    const Recognition r = RecognizePairs(base, moved);
    ASSERT_EQ(r.pairs.size(), reference.pairs.size());
    for (std::size_t i = 0; i < r.pairs.size(); ++i) {
      EXPECT_EQ(r.pairs[i].type, reference.pairs[i].type);
      EXPECT_EQ(r.pairs[i].a, reference.pairs[i].a);
      EXPECT_EQ(r.pairs[i].b, reference.pairs[i].b);
    }
  }
}

TEST(PairRecognition, WithoutAStateItRecognisesAtTheFilePoses) {
  // The same pairs, diagnostics and world axes as with the initial state; a state of the
  // wrong size is bad input.
  const Assembly a = BoltedStack(Fastening::kTight);
  const Recognition with_state = Recognize(a);
  const Recognition without = RecognizePairs(a);
  ASSERT_EQ(without.pairs.size(), with_state.pairs.size());
  for (std::size_t i = 0; i < without.pairs.size(); ++i) {
    EXPECT_EQ(without.pairs[i].type, with_state.pairs[i].type);
    EXPECT_EQ(without.pairs[i].a, with_state.pairs[i].a);
    EXPECT_EQ(without.pairs[i].b, with_state.pairs[i].b);
    EXPECT_EQ(without.pairs[i].source, with_state.pairs[i].source);
  }
  ASSERT_EQ(without.diagnostics.size(), with_state.diagnostics.size());
  for (std::size_t i = 0; i < without.diagnostics.size(); ++i) {
    EXPECT_EQ(without.diagnostics[i].message, with_state.diagnostics[i].message);
  }
  ASSERT_EQ(without.axes_W.size(), with_state.axes_W.size());
  for (std::size_t i = 0; i < without.axes_W.size(); ++i) {
    EXPECT_EQ(without.axes_W[i].origin, with_state.axes_W[i].origin);
    EXPECT_EQ(without.axes_W[i].direction, with_state.axes_W[i].direction);
  }
  AssemblyState short_state = InitialState(a);
  short_state.X_WP.pop_back();
  EXPECT_THROW(RecognizePairs(a, short_state), std::invalid_argument);
}

// Oracle for the broad phase: every candidate found by brute force over all feature pairs.
TEST(PairRecognition, GridBroadPhaseMatchesAllPairsOnRandomGearField) {
  std::mt19937 random(11);
  std::uniform_int_distribution<int> teeth(10, 40);
  std::uniform_real_distribution<double> coordinate(0, 300);
  // Each part is a unit cube with its gear at the part origin, placed by the part's pose: the
  // cubes then lie apart, as real parts do, and only the gears' broad phase is under test.
  std::vector<int> teeth_of;
  std::vector<V> p_WG;  // gear centres in the world
  for (int i = 0; i < 300; ++i) {
    teeth_of.push_back(teeth(random));
    p_WG.push_back(V(coordinate(random), coordinate(random), 0));
  }
  // Place some exact meshes so that there is something to find.
  for (int i = 0; i + 1 < 300; i += 10) {
    p_WG[i + 1] = p_WG[i] + V((teeth_of[i] + teeth_of[i + 1]) / 2.0, 0, 0);
  }
  std::vector<Part> parts;
  for (int i = 0; i < 300; ++i) {
    parts.push_back(MakePart("g" + std::to_string(i), {Gear("t", teeth_of[i], 1, V::Zero())},
                             RigidTransform::Translation(p_WG[i])));
  }
  const Recognition r = Recognize(MakeAssembly(parts));
  std::set<std::pair<std::size_t, std::size_t>> expected;
  for (std::size_t i = 0; i < 300; ++i) {
    for (std::size_t j = i + 1; j < 300; ++j) {
      const double d = (p_WG[i] - p_WG[j]).norm();
      if (std::abs(d - (teeth_of[i] + teeth_of[j]) / 2.0) <= 0.05) expected.insert({i, j});
    }
  }
  EXPECT_GE(expected.size(), 30u);
  // Cubes that happen to overlap are also fixed to each other (embedded parts): the gears only.
  std::set<std::pair<std::size_t, std::size_t>> found;
  for (const Pair& p : r.pairs) {
    if (p.type != PairType::kGear) continue;
    EXPECT_TRUE(found.insert(std::minmax(p.a.part, p.b.part)).second) << "found twice";
  }
  EXPECT_EQ(found, expected);
}

TEST(PairRecognition, GridBroadPhaseFindsEveryPairAcrossAHugeSparseAssembly) {
  // Small gear pairs scattered over a cube a kilometre wide: a grid of cells the size of the
  // features needs more key bits than an entry holds, so the cells grow; every pair is still
  // found exactly once.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(0, 1e6);
  std::vector<Part> parts;
  for (int i = 0; i < 40; ++i) {
    const V at(coordinate(random), coordinate(random), coordinate(random));
    parts.push_back(MakePart("a" + std::to_string(i), {Gear("t", 10, 1, at)}));
    parts.push_back(MakePart("b" + std::to_string(i), {Gear("t", 12, 1, at + V(11, 0, 0))}));
  }
  const Recognition r = Recognize(MakeAssembly(parts));
  ASSERT_EQ(r.pairs.size(), 40u);
  for (const Pair& p : r.pairs) {
    EXPECT_EQ(p.type, PairType::kGear);
    EXPECT_EQ(p.a.part + 1, p.b.part);  // a_i with b_i, nothing else
  }
}

}  // namespace
}  // namespace mechanist

namespace mechanist {
namespace {

TEST(Analysis, DiagnosticsDoNotDependOnThePartOrder) {
  auto open_mesh = std::make_shared<TriangleMesh>(*testing::UnitCube());
  open_mesh->faces.pop_back();
  auto part = [&](const std::string& id) {
    Part p = testing::MakePart(id, {});
    p.mesh = open_mesh;
    return p;
  };
  const Analysis ab = Analyze(testing::MakeAssembly({part("a"), part("b")}));
  const Analysis ba = Analyze(testing::MakeAssembly({part("b"), part("a")}));
  // mesh_not_closed and part_unconnected, each once for both parts (one mesh, no pairs).
  ASSERT_EQ(ab.diagnostics.size(), 2u);
  EXPECT_EQ(ab.diagnostics[0].parts, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(ab.diagnostics[1].parts, (std::vector<std::string>{"a", "b"}));
  for (std::size_t i = 0; i < ab.diagnostics.size(); ++i) {
    EXPECT_EQ(ab.diagnostics[i].code, ba.diagnostics[i].code);
    EXPECT_EQ(ab.diagnostics[i].parts, ba.diagnostics[i].parts);
  }
}

}  // namespace
}  // namespace mechanist
