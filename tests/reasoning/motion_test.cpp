// Motion analysis against textbook answers: gear trains (simple, idler, compound), planetary
// and differential trains, rack and pinion, multi-start lead screw, worm drive and its
// a gear triangle jam, free motions; scale and renaming change no ratio. The examples' motion
// (worm back-drive, reversal, three planets) is tested in tests/io/motion_examples_test.cpp.

#include "reasoning/motion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "kernel/mesh/mesh_builder.h"
#include "reasoning/analysis.h"
#include "reasoning/motion_run.h"
#include "reasoning/pair_graph.h"
#include "reasoning/pair_recognition.h"
#include "test_assembly.h"

namespace mechanist {
namespace {

using testing::MakeFeature;
using testing::MakePart;
using K = FeatureKind;
const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

/// Parts and drivers built in code: gears on shafts turning in a ground frame's bearings.
class Builder {
 public:
  Builder() { frame_ = MakePart("frame", {}, RigidTransform(), true); }

  /// A gear part at (x, y) with gear features {teeth, z0} and a shaft (diameter 4, at
  /// z in [shaft_z, shaft_z + 10]) in a frame hole; `retained`: revolute, else cylindrical.
  Builder& Gear(const std::string& id, double x, double y,
                std::vector<std::pair<int, double>> gears, double module = 1, bool retained = true,
                double shaft_z = -20) {
    std::vector<Feature> f;
    for (std::size_t i = 0; i < gears.size(); ++i) {
      f.push_back(MakeFeature(i == 0 ? "teeth" : "teeth" + std::to_string(i + 1), K::kGear,
                              {0, 0, gears[i].second}, kZ, [&](Feature& g) {
                                g.teeth = gears[i].first;
                                g.module = module;
                                g.length = 5;
                              }));
    }
    f.push_back(MakeFeature("shaft", K::kShaft, {0, 0, shaft_z}, kZ, [&](Feature& s) {
      s.diameter = 4;
      s.length = 10;
      s.retained = retained;
    }));
    parts_.push_back(MakePart(id, f, RigidTransform::Translation({x, y, 0})));
    frame_.features.push_back(
        MakeFeature("bearing_" + id, K::kHole, {x, y, shaft_z}, kZ, [](Feature& h) {
          h.diameter = 4;
          h.length = 10;
          h.through = true;
        }));
    return *this;
  }
  Builder& Part(mechanist::Part p) {
    parts_.push_back(std::move(p));
    return *this;
  }
  Builder& FrameFeature(Feature f) {
    frame_.features.push_back(std::move(f));
    return *this;
  }
  Builder& Drive(const std::string& part, const std::string& feature, double rate = 1,
                 bool rotation = true) {
    drives_.push_back({part, feature, rate, rotation});
    return *this;
  }
  Builder& Override(const std::string& a, const std::string& b, PairType type) {
    overrides_.push_back({a, b, type});
    return *this;
  }
  Builder& Friction(double mu) {
    friction_ = mu;
    return *this;
  }
  Assembly Build() const {
    AssemblySpec spec;
    spec.name = "test";
    spec.friction = friction_;
    spec.parts = parts_;
    spec.parts.insert(spec.parts.begin(), frame_);
    auto ref = [&](const std::string& path) {
      const auto slash = path.find('/');
      for (std::size_t p = 0; p < spec.parts.size(); ++p) {
        if (spec.parts[p].id != path.substr(0, slash)) continue;
        for (std::size_t f = 0; f < spec.parts[p].features.size(); ++f) {
          if (spec.parts[p].features[f].id == path.substr(slash + 1)) return FeatureRef{p, f};
        }
      }
      ADD_FAILURE() << "no feature " << path;
      return FeatureRef{};
    };
    for (const Drive_& d : drives_) {
      Driver driver;
      driver.id = d.part;
      driver.feature = ref(d.part + "/" + d.feature);
      driver.rate = d.rate;
      driver.motion = d.rotation ? Driver::Motion::kRotation : Driver::Motion::kTranslation;
      spec.drivers.push_back(driver);
    }
    for (const auto& o : overrides_) {
      spec.overrides.push_back({{ref(o.a), ref(o.b)}, o.type});
    }
    return Assembly(std::move(spec));
  }

 private:
  struct Drive_ {
    std::string part, feature;
    double rate;
    bool rotation;
  };
  struct Override_ {
    std::string a, b;
    PairType type;
  };
  mechanist::Part frame_;
  std::vector<mechanist::Part> parts_;
  std::vector<Drive_> drives_;
  std::vector<Override_> overrides_;
  double friction_ = 0.1;
};

/// The rate about (or along) a feature's axis in the expectations' motion.
ExactReal Rate(const Assembly& a, const Analysis& an, const std::string& path, bool rotation = true,
               const DrivenMotion* motion = nullptr) {
  const auto f = a.FindFeature(path);
  EXPECT_TRUE(f.has_value()) << path;
  if (!motion) motion = an.motion.ForExpectations();
  EXPECT_NE(motion, nullptr);
  const FeatureRate& r = motion->features[f->part][f->feature];
  return rotation ? r.rotation : r.translation;
}

std::string Exact(const ExactReal& r) {
  return r.is_exact() ? r.ToString() : "inexact " + r.ToString();
}

bool HasCode(const Analysis& an, const std::string& code) {
  for (const Diagnostic& d : an.diagnostics) {
    if (d.code == code) return true;
  }
  return false;
}

TEST(Motion, SimplePairTurnsBackwardsInTheToothRatio) {
  const Assembly a = Builder()
                         .Gear("g1", 0, 0, {{20, 0}})
                         .Gear("g2", 30, 0, {{40, 0}})
                         .Drive("g1", "teeth")
                         .Build();
  const Analysis an = Analyze(a);
  EXPECT_EQ(Exact(Rate(a, an, "g2/teeth")), "-1/2");
  EXPECT_EQ(an.motion.mobility.dof, 1);
  EXPECT_EQ(an.motion.mobility.redundant, 0);
  EXPECT_FALSE(HasCode(an, "free_motion"));
}

TEST(Motion, IdlerChangesDirectionNotRatio) {
  const Assembly a = Builder()
                         .Gear("g1", 0, 0, {{20, 0}})
                         .Gear("idler", 17.5, 0, {{15, 0}})
                         .Gear("g3", 40, 0, {{30, 0}})
                         .Drive("g1", "teeth")
                         .Build();
  const Analysis an = Analyze(a);
  EXPECT_EQ(Exact(Rate(a, an, "g3/teeth")), "2/3");
  EXPECT_EQ(Exact(Rate(a, an, "idler/teeth")), "-4/3");
}

TEST(Motion, CompoundTrainMultipliesStageRatios) {
  // 20 -> 40, then 10 on the same shaft -> 30: (-20/40) (-10/30) = 1/6.
  const Assembly a = Builder()
                         .Gear("g1", 0, 0, {{20, 0}})
                         .Gear("g23", 30, 0, {{40, 0}, {10, 10}})
                         .Gear("g4", 50, 0, {{30, 10}})
                         .Drive("g1", "teeth")
                         .Build();
  const Analysis an = Analyze(a);
  EXPECT_EQ(Exact(Rate(a, an, "g4/teeth")), "1/6");
  EXPECT_EQ(Exact(Rate(a, an, "g23/teeth2")), "-1/2");
}

TEST(Motion, ThrustFacesDoingTheirJobAreNoJam) {
  // A gear on a cylindrical fit, its hub's face resting on the frame's seat: the face contact
  // holds the fit's slide, the fit holds the contact's slides. Both are how a thrust face
  // works: no jam (a warning for each used to be given); the gear still turns.
  const auto face = [](const std::string& id, double z, Eigen::Vector3d normal) {
    return MakeFeature(id, K::kFace, {0, 0, z}, normal, [](Feature& f) {
      f.width = 10;
      f.height = 10;
    });
  };
  Builder b;
  b.Gear("g1", 0, 0, {{20, 0}}, 1, /*retained=*/false).Drive("g1", "teeth");
  b.FrameFeature(face("seat", -10, kZ));
  Assembly with_seat = b.Build();
  AssemblySpec spec = with_seat.spec();
  for (mechanist::Part& p : spec.parts) {
    if (p.id == "g1") p.features.push_back(face("hub", -10, -kZ));
  }
  const Assembly a(spec);
  const Analysis an = Analyze(a);
  int planar = 0;
  for (const Pair& p : an.pairs) planar += p.type == PairType::kPlanar;
  ASSERT_EQ(planar, 1);
  EXPECT_FALSE(HasCode(an, "jam"));
  EXPECT_EQ(Exact(Rate(a, an, "g1/teeth")), "1");
}

TEST(Motion, APartLocatedByTwoPinsIsNoJam) {
  // A plate on two dowel pins in the frame: each pin's fit would let it turn, the other pin
  // holds it. Contacts alone lock it: the plate is located, not jammed (the Fusion 360
  // pendulum's motor had such a warning). Three gears meshing in a ring still jam (below).
  const auto pin = [](const std::string& id, double x, K kind) {
    return MakeFeature(id, kind, {x, 0, -20}, kZ, [](Feature& f) {
      f.diameter = 4;
      f.length = 10;
      f.through = true;
    });
  };
  Builder b;
  b.Part(MakePart("plate", {pin("pin_1", 0, K::kShaft), pin("pin_2", 20, K::kShaft)}))
      .FrameFeature(pin("dowel_1", 0, K::kHole))
      .FrameFeature(pin("dowel_2", 20, K::kHole));
  const Analysis an = Analyze(b.Build());
  ASSERT_EQ(an.pairs.size(), 2u);
  EXPECT_EQ(an.motion.mobility.dof, 1);  // the slide along the pins
  EXPECT_FALSE(HasCode(an, "jam"));
}

TEST(Motion, RedundantFaceContactsAreSaidOncePerTwoParts) {
  // A block standing on the frame with three feet: the second and third contacts repeat what
  // the first one constrains; one finding for the block and the frame, not one per foot.
  const auto face = [](const std::string& id, double x, Eigen::Vector3d normal) {
    return MakeFeature(id, K::kFace, {x, 0, 0}, normal, [](Feature& f) {
      f.width = 4;
      f.height = 4;
    });
  };
  Builder b;
  for (int k = 0; k < 3; ++k) b.FrameFeature(face("pad" + std::to_string(k), 10.0 * k, kZ));
  b.Part(
      MakePart("block", {face("foot0", 0, -kZ), face("foot1", 10, -kZ), face("foot2", 20, -kZ)}));
  const Assembly a = b.Build();
  const Analysis an = Analyze(a);
  EXPECT_EQ(an.motion.mobility.redundant, 6);
  int findings = 0;
  for (const Diagnostic& d : an.diagnostics) {
    if (d.code != "redundant_constraints") continue;
    ++findings;
    EXPECT_NE(d.message.find("face contacts of"), std::string::npos) << d.message;
    EXPECT_NE(d.message.find("(2): 6 of their constraints are implied"), std::string::npos)
        << d.message;
    EXPECT_EQ(d.features.size(), 4u);
  }
  EXPECT_EQ(findings, 1);
}

TEST(Motion, AlikeRedundantFaceContactsOfOnePartWithSeveralAreOneFinding) {
  // Three blocks standing on the frame with three feet each say the same: one finding naming
  // the three. A fourth block on two feet says something else, on its own.
  const auto face = [](const std::string& id, double x, double y, Eigen::Vector3d normal) {
    return MakeFeature(id, K::kFace, {x, y, 0}, normal, [](Feature& f) {
      f.width = 4;
      f.height = 4;
    });
  };
  Builder b;
  for (int block = 0; block < 4; ++block) {
    const double y = 50.0 * block;
    const int feet = block < 3 ? 3 : 2;
    std::vector<Feature> features;
    for (int k = 0; k < feet; ++k) {
      const std::string n = std::to_string(block) + "_" + std::to_string(k);
      b.FrameFeature(face("pad" + n, 10.0 * k, y, kZ));
      features.push_back(face("foot" + n, 10.0 * k, y, -kZ));
    }
    b.Part(MakePart("block" + std::to_string(block), std::move(features)));
  }
  const Analysis an = Analyze(b.Build());
  EXPECT_EQ(an.motion.mobility.redundant, 3 * 6 + 3);
  std::vector<std::string> messages;
  for (const Diagnostic& d : an.diagnostics) {
    if (d.code == "redundant_constraints") messages.push_back(d.message);
  }
  ASSERT_EQ(messages.size(), 2u);
  EXPECT_NE(messages[0].find("face contacts of frame with 3 parts, block0, block1 and block2 (2 "
                             "each): 6 of each one's constraints are implied"),
            std::string::npos)
      << messages[0];
  EXPECT_NE(messages[1].find("face contact of block3 and frame (1): 3 of their constraints"),
            std::string::npos)
      << messages[1];
}

TEST(Motion, GearTriangleJams) {
  const Assembly a = Builder()
                         .Gear("g1", 0, 0, {{20, 0}})
                         .Gear("g2", 20, 0, {{20, 0}})
                         .Gear("g3", 10, 10 * std::sqrt(3.0), {{20, 0}})
                         .Drive("g1", "teeth")
                         .Build();
  const Analysis an = Analyze(a);
  EXPECT_EQ(an.motion.mobility.dof, 0);
  EXPECT_TRUE(HasCode(an, "jam"));
  EXPECT_TRUE(HasCode(an, "driver_locked"));
  ASSERT_FALSE(an.motion.driven.front().possible);
}

// Two planetary stages stacked on one axis, the first carrier's output pressed into the
// second sun: each stage divides by 1 + 60/20 = 4. The stages' carrier pins lie on the same
// lines; a pin of one stage must not be taken as carrying the other stage's planet axis.
Assembly TwoStagePlanetary() {
  const double kPi = 3.14159265358979323846;
  auto gear = [](const std::string& id, int teeth, Eigen::Vector3d at, bool internal) {
    return MakeFeature(id, K::kGear, at, kZ, [&](Feature& g) {
      g.teeth = teeth, g.module = 1, g.length = 8, g.internal = internal;
    });
  };
  // Bearings are retained (revolute pairs); the press fit of an output in a sun is not.
  auto cylinder = [](const std::string& id, K kind, Eigen::Vector3d at, Eigen::Vector3d axis,
                     double diameter, double length, bool retained = true) {
    return MakeFeature(id, kind, at, axis, [&](Feature& f) {
      f.diameter = diameter, f.length = length, f.retained = retained;
    });
  };
  std::vector<mechanist::Part> parts = {MakePart(
      "frame",
      {cylinder("axle_in", K::kShaft, {0, 0, -4}, kZ, 6, 10), gear("ring0", 60, {0, 0, 0}, true),
       gear("ring1", 60, {0, 0, 30}, true), cylinder("axle0", K::kShaft, {0, 0, 11.5}, -kZ, 6, 3),
       cylinder("axle1", K::kShaft, {0, 0, 41.5}, -kZ, 6, 3)},
      RigidTransform(), true)};
  for (int s = 0; s < 2; ++s) {
    const std::string n = std::to_string(s);
    const RigidTransform at = RigidTransform::Translation({0, 0, 30.0 * s});
    parts.push_back(
        MakePart("sun" + n,
                 {gear("teeth", 20, {0, 0, 0}, false),
                  cylinder("bore", K::kHole, {0, 0, 0}, kZ, s == 0 ? 6.02 : 5.9, 8, s == 0)},
                 at));
    std::vector<Feature> carrier = {cylinder("center", K::kHole, {0, 0, 12}, -kZ, 6.02, 4),
                                    cylinder("output", K::kShaft, {0, 0, 12}, kZ, 6, 22, false)};
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d p(20 * std::cos(2 * kPi * j / 3), 20 * std::sin(2 * kPi * j / 3), 0);
      carrier.push_back(cylinder("pin" + std::to_string(j), K::kShaft,
                                 p + Eigen::Vector3d(0, 0, 10), -kZ, 4, 10));
      parts.push_back(
          MakePart("planet" + n + std::to_string(j),
                   {gear("teeth", 20, p, false),
                    cylinder("bore", K::kHole, p + Eigen::Vector3d(0, 0, 8), -kZ, 4.02, 8)},
                   at));
    }
    parts.push_back(MakePart("carrier" + n, carrier, at));
  }
  AssemblySpec spec;
  spec.name = "two stages";
  spec.parts = parts;
  Driver motor;
  motor.id = "motor";
  motor.feature = {1, 0};  // sun0/teeth
  spec.drivers = {motor};
  return Assembly(std::move(spec));
}

TEST(Motion, StackedPlanetaryStagesMultiply) {
  const Assembly a = TwoStagePlanetary();
  const Analysis an = Analyze(a);
  EXPECT_EQ(an.motion.mobility.dof, 1);
  EXPECT_EQ(an.motion.mobility.redundant, 4);
  // The carriers' axes point down (-z): a positive sun turns them negatively about them.
  EXPECT_EQ(Exact(Rate(a, an, "carrier0/center")), "-1/4");
  EXPECT_EQ(Exact(Rate(a, an, "sun1/teeth")), "1/4");
  EXPECT_EQ(Exact(Rate(a, an, "carrier1/center")), "-1/16");
  // Relative to its carrier a planet turns -(20/20)(w_sun - w_carrier): 1/16 - 3/16 absolute.
  EXPECT_EQ(Exact(Rate(a, an, "planet10/teeth")), "-1/8");
}

// The world axes that recognition hands to the motion analysis (so that it need not read
// every feature again) give the same motion as the axes the model computes itself.
TEST(Motion, AxesFromRecognitionGiveTheSameMotionAsComputedOnes) {
  const Assembly a = TwoStagePlanetary();
  Recognition r = RecognizePairs(a, InitialState(a));
  const auto graph = std::make_shared<const PairGraph>(a, r.pairs);
  ASSERT_EQ(r.axes_W.size(), a.feature_count());
  EXPECT_THROW(AnalyzeMotion(a, r.pairs, graph, std::vector<AxisSegment>(3)),
               std::invalid_argument);
  const MotionAnalysis given = AnalyzeMotion(a, r.pairs, graph, r.axes_W);
  const MotionAnalysis computed = AnalyzeMotion(a, r.pairs, graph);
  EXPECT_EQ(given.mobility.dof, computed.mobility.dof);
  EXPECT_EQ(given.mobility.redundant, computed.mobility.redundant);
  ASSERT_EQ(given.driven.size(), computed.driven.size());
  for (std::size_t d = 0; d < given.driven.size(); ++d) {
    for (std::size_t p = 0; p < a.parts().size(); ++p) {
      const PartMotion &x = given.driven[d].parts[p], &y = computed.driven[d].parts[p];
      EXPECT_EQ(x.kind, y.kind) << a.part(p).id;
      EXPECT_EQ(Exact(x.rotation), Exact(y.rotation)) << a.part(p).id;
      EXPECT_EQ(x.axis_W, y.axis_W) << a.part(p).id;
    }
  }
}

TEST(Motion, DifferentialAddsItsInputsByWillis) {
  // Sun 20 and ring 40 both driven; the carrier turns at (20 w_s + 40 w_r) / 60.
  Builder b;
  b.Gear("sun", 0, 0, {{20, 0}}, 1, true, -20)
      .Gear("carrier", 0, 0, {}, 1, true, -40)
      .Gear("ring", 0, 0, {{40, 0}}, 1, true, -60);
  b.Part(
      MakePart("planet",
               {MakeFeature("teeth", K::kGear, {0, 0, 0}, kZ,
                            [](Feature& g) { g.teeth = 10, g.module = 1, g.length = 5; }),
                MakeFeature("pin", K::kShaft, {0, 0, -8}, kZ,
                            [](Feature& s) { s.diameter = 3, s.length = 3, s.retained = true; })},
               RigidTransform::Translation({15, 0, 0})));
  const Assembly base = b.Build();
  // The ring is internal and the carrier needs a bore for the planet's pin: edit the spec.
  AssemblySpec spec;
  spec.name = "differential";
  spec.parts = base.parts();
  for (mechanist::Part& p : spec.parts) {
    if (p.id == "ring") p.features[0].internal = true;
    if (p.id == "carrier") {
      p.features.push_back(MakeFeature("pin_bore", K::kHole, {15, 0, -8}, kZ, [](Feature& h) {
        h.diameter = 3, h.length = 3, h.through = true;
      }));
    }
  }
  auto driver = [&](const std::string& part, double rate) {
    Driver d;
    d.id = part;
    for (std::size_t p = 0; p < spec.parts.size(); ++p) {
      if (spec.parts[p].id == part) d.feature = {p, 0};
    }
    d.rate = rate;
    return d;
  };
  spec.drivers = {driver("sun", 1), driver("ring", 2)};
  const Assembly a(spec);
  const Analysis an = Analyze(a);
  EXPECT_EQ(an.motion.mobility.dof, 2);
  ASSERT_EQ(an.motion.driven.size(), 3u);
  EXPECT_EQ(Exact(Rate(a, an, "carrier/shaft", true, &an.motion.driven[0])), "1/3");
  EXPECT_EQ(Exact(Rate(a, an, "carrier/shaft", true, &an.motion.driven[1])), "2/3");
  EXPECT_EQ(Exact(Rate(a, an, "carrier/shaft")), "5/3");
  // Relative to the carrier the planet turns -(20/10)(1 - 1/3) per unit sun rate.
  EXPECT_EQ(Exact(Rate(a, an, "planet/teeth", true, &an.motion.driven[0])), "-1");
  // Both drivers reversed: every rate of the combined motion negated, exactly.
  spec.drivers = {driver("sun", -1), driver("ring", -2)};
  const Assembly reversed(spec);
  const Analysis back = Analyze(reversed);
  const DrivenMotion &forward = an.motion.driven.back(), &backward = back.motion.driven.back();
  for (std::size_t p = 0; p < forward.features.key_count(); ++p) {
    for (std::size_t k = 0; k < forward.features[p].size(); ++k) {
      ASSERT_TRUE(forward.features[p][k].rotation.is_exact()) << a.part(p).id;
      EXPECT_EQ(*backward.features[p][k].rotation.exact(),
                -*forward.features[p][k].rotation.exact())
          << a.part(p).id;
    }
  }
  EXPECT_EQ(Exact(Rate(reversed, back, "carrier/shaft")), "-5/3");

  // The ring held by a brake (rate 0, spec "Drivers"): the carrier turns at 20 / 60 of the sun,
  // the ring stays still, and the brake alone runs nothing.
  spec.drivers = {driver("sun", 2), driver("ring", 0)};
  const Assembly held(spec);
  const Analysis braked = Analyze(held);
  ASSERT_EQ(braked.motion.driven.size(), 3u);
  EXPECT_EQ(Exact(Rate(held, braked, "carrier/shaft")), "2/3");
  EXPECT_EQ(Exact(Rate(held, braked, "ring/teeth")), "0");
  EXPECT_EQ(Exact(Rate(held, braked, "carrier/shaft", true, &braked.motion.driven[0])), "1/3");
  const MotionRun brake = PlanRun(held, braked, 1, std::nullopt);
  EXPECT_FALSE(brake.possible);
  EXPECT_NE(brake.reason.find("held"), std::string::npos) << brake.reason;
  EXPECT_TRUE(PlanRun(held, braked, std::nullopt, std::nullopt).possible);
}

TEST(Motion, RackTravelsPiTimesPitchDiameterPerRevolution) {
  Builder b;
  b.Gear("pinion", 0, 0, {{20, 0}});
  b.Part(MakePart(
      "rack", {MakeFeature("teeth", K::kRack, {-20, -10, 0}, Eigen::Vector3d::UnitX(),
                           [](Feature& r) {
                             r.module = 1, r.length = 40, r.normal = {0, 1, 0};
                           }),
               MakeFeature("key", K::kKey, {-20, -20, 0}, Eigen::Vector3d::UnitX(), [](Feature& k) {
                 k.width = 4, k.length = 40, k.normal = {0, -1, 0};
               })}));
  b.FrameFeature(
      MakeFeature("way", K::kSlot, {-40, -20, 0}, Eigen::Vector3d::UnitX(), [](Feature& s) {
        s.width = 4, s.length = 80, s.depth = 2, s.normal = {0, 1, 0};
      }));
  b.Override("rack/key", "frame/way", PairType::kPrismatic).Drive("pinion", "teeth");
  const Assembly a = b.Build();
  const Analysis an = Analyze(a);
  const ExactReal v = Rate(a, an, "rack/teeth", false);
  EXPECT_FALSE(v.is_exact());  // pi
  EXPECT_NEAR(v.value(), 20 * M_PI, 1e-9);
  EXPECT_EQ(an.motion.mobility.dof, 1);
}

TEST(Motion, TwoStartLeadScrewAdvancesItsNutByTheLead) {
  Builder b;
  b.Gear("spindle", 0, 0, {});
  b.Part(MakePart("nut", {MakeFeature("thread", K::kTappedHole, {0, 0, 10}, kZ,
                                      [](Feature& t) {
                                        t.diameter = 8, t.pitch = 1.5, t.starts = 2, t.length = 10,
                                        t.through = true;
                                      }),
                          MakeFeature("key", K::kKey, {10, 0, 10}, kZ, [](Feature& k) {
                            k.width = 3, k.length = 10, k.normal = {1, 0, 0};
                          })}));
  b.FrameFeature(MakeFeature("way", K::kSlot, {10, 0, 0}, kZ, [](Feature& s) {
    s.width = 3, s.length = 40, s.depth = 2, s.normal = {-1, 0, 0};
  }));
  const Assembly base = b.Build();
  AssemblySpec spec;
  spec.parts = base.parts();
  for (mechanist::Part& p : spec.parts) {
    if (p.id == "spindle") {
      p.features.push_back(MakeFeature("thread", K::kThread, {0, 0, 0}, kZ, [](Feature& t) {
        t.diameter = 8, t.pitch = 1.5, t.starts = 2, t.length = 30, t.fastening = Fastening::kLoose;
      }));
    }
  }
  const std::size_t spindle = 1, nut = 2;
  spec.overrides.push_back({{FeatureRef{nut, 1}, FeatureRef{0, 1}}, PairType::kPrismatic});
  Driver d;
  d.id = "crank";
  d.feature = {spindle, 1};
  spec.drivers = {d};
  const Assembly a(spec);
  const Analysis an = Analyze(a);
  EXPECT_EQ(Exact(Rate(a, an, "nut/thread", false)), "-3");
  EXPECT_EQ(an.motion.mobility.dof, 1);
}

// A lead screw turning in the frame's bearing through a nut that a key holds from turning,
// the thread left out: the screw's turn and the nut's slide are two motions, and the warning
// names the fit. `nut_keyed`: the nut's key slides in the frame's way; `threads`: a loose thread
// and its nut's tapped hole on the same axis; `lead`: a screw override on the plain fit.
Assembly LeadScrew(bool nut_keyed, bool threads, std::optional<double> lead) {
  Builder b;
  b.Part(MakePart("screw", {MakeFeature("shaft", K::kShaft, {0, 0, 0}, kZ,
                                        [&](Feature& s) { s.diameter = 8, s.length = 100; })}));
  std::vector<Feature> nut = {MakeFeature("bore", K::kHole, {0, 0, 50}, kZ, [](Feature& h) {
    h.diameter = 8, h.length = 10, h.through = true;
  })};
  if (nut_keyed) {
    nut.push_back(MakeFeature("key", K::kKey, {10, 0, 50}, kZ, [](Feature& k) {
      k.width = 3, k.length = 10, k.normal = {1, 0, 0};
    }));
  }
  if (threads) {
    nut.push_back(MakeFeature("thread", K::kTappedHole, {0, 0, 50}, kZ, [](Feature& t) {
      t.diameter = 8, t.pitch = 2, t.length = 10, t.through = true;
    }));
  }
  b.Part(MakePart("nut", nut));
  b.FrameFeature(MakeFeature("bearing", K::kHole, {0, 0, 0}, kZ, [](Feature& h) {
    h.diameter = 8, h.length = 10, h.through = true, h.retained = true;
  }));
  b.FrameFeature(MakeFeature("way", K::kSlot, {10, 0, 0}, kZ, [](Feature& s) {
    s.width = 3, s.length = 100, s.depth = 2, s.normal = {-1, 0, 0};
  }));
  Assembly base = b.Build();
  AssemblySpec spec;
  spec.parts = base.parts();
  if (threads) {
    spec.parts[1].features.push_back(
        MakeFeature("thread", K::kThread, {0, 0, 0}, kZ, [](Feature& t) {
          t.diameter = 8, t.pitch = 2, t.length = 100, t.fastening = Fastening::kLoose;
        }));
  }
  const FeatureRef shaft{1, 0}, bore{2, 0};
  if (nut_keyed)
    spec.overrides.push_back({{FeatureRef{2, 1}, FeatureRef{0, 1}}, PairType::kPrismatic});
  if (lead) {
    PairOverride o{{shaft, bore}, PairType::kScrew};
    o.lead = *lead;
    spec.overrides.push_back(o);
  }
  Driver d;
  d.id = "motor";
  d.feature = shaft;
  d.rate = 1;
  spec.drivers = {d};
  return Assembly(std::move(spec));
}

TEST(Motion, AScrewTurningInPlaceThroughANutThatSlidesIsAnUnthreadedNut) {
  const Assembly plain = LeadScrew(true, false, std::nullopt);
  const Analysis an = Analyze(plain);
  const auto found = std::find_if(an.diagnostics.begin(), an.diagnostics.end(),
                                  [](const Diagnostic& d) { return d.code == "unthreaded_nut"; });
  ASSERT_NE(found, an.diagnostics.end());
  EXPECT_EQ(found->severity, Severity::kWarning);
  EXPECT_EQ(found->features, (std::vector<std::string>{"screw/shaft", "nut/bore"}));
  EXPECT_NE(found->message.find(R"({"pair": ["screw/shaft", "nut/bore"], "type": "screw")"),
            std::string::npos)
      << found->message;
  EXPECT_EQ(an.motion.mobility.dof, 2);
  EXPECT_EQ(Exact(Rate(plain, an, "nut/bore", false)), "0");  // the motor leaves it still

  // The override's lead couples them, exactly: a right-hand 8 mm lead moves the screw 8 mm
  // into the nut per turn, so the nut comes 8 mm back along the common axis.
  const Assembly coupled = LeadScrew(true, false, 8.0);
  const Analysis with_lead = Analyze(coupled);
  EXPECT_FALSE(HasCode(with_lead, "unthreaded_nut"));
  EXPECT_EQ(with_lead.motion.mobility.dof, 1);
  EXPECT_EQ(Exact(Rate(coupled, with_lead, "nut/bore", false)), "-8");

  // A modelled thread already ties them; a nut that may turn is no nut held on its way.
  const Analysis threaded = Analyze(LeadScrew(true, true, std::nullopt));
  EXPECT_FALSE(HasCode(threaded, "unthreaded_nut"));
  EXPECT_EQ(threaded.motion.mobility.dof, 1);
  EXPECT_FALSE(HasCode(Analyze(LeadScrew(false, false, std::nullopt)), "unthreaded_nut"));
}

TEST(Motion, ScaleAndNamesChangeNoRatio) {
  auto train = [](double s, const std::string& prefix) {
    return Builder()
        .Gear(prefix + "1", 0, 0, {{20, 0}}, s)
        .Gear(prefix + "23", 30 * s, 0, {{40, 0}, {10, 10}}, s)
        .Gear(prefix + "4", 50 * s, 0, {{30, 10}}, s)
        .Drive(prefix + "1", "teeth")
        .Build();
  };
  const Assembly a = train(1, "g"), b = train(2.5, "wheel_");
  const Analysis aa = Analyze(a), ab = Analyze(b);
  EXPECT_EQ(Exact(Rate(a, aa, "g4/teeth")), Exact(Rate(b, ab, "wheel_4/teeth")));
  EXPECT_EQ(aa.motion.mobility.dof, ab.motion.mobility.dof);
}

TEST(Motion, FreeMotionsAreSaidOncePerPartAndOnceForPartsAlike) {
  // Two blocks resting on one seat of the frame slide and turn on it alike: one finding for
  // both, with all three freedoms. With a driver it is a warning; without (a CAD export), the
  // mechanism's own motions, an info.
  const auto foot = [](const std::string& id, double x) {
    return MakePart(id,
                    {MakeFeature("foot", K::kFace, {0, 0, 0}, -kZ,
                                 [](Feature& f) {
                                   f.width = 4;
                                   f.height = 4;
                                 })},
                    RigidTransform::Translation({x, 0, 0}));
  };
  const Feature seat = MakeFeature("seat", K::kFace, {0, 0, 0}, kZ, [](Feature& f) {
    f.width = 100;
    f.height = 100;
  });
  for (const bool driven : {false, true}) {
    Builder b;
    b.Part(foot("block_1", 10)).Part(foot("block_2", 20)).FrameFeature(seat);
    if (driven) b.Gear("g1", -40, 0, {{20, 0}}).Drive("g1", "teeth");
    // The frame's mesh holds its seat (a face reaches no further than its part).
    AssemblySpec spec = b.Build().spec();
    spec.parts[0].mesh = testing::Boxes({{{-50, -50, -1}, {50, 50, 0}}});
    const Analysis an = Analyze(Assembly(std::move(spec)));
    EXPECT_EQ(an.motion.mobility.free_motions.size(), 6u);
    std::vector<const Diagnostic*> found;
    for (const Diagnostic& d : an.diagnostics) {
      if (d.code == "free_motion") found.push_back(&d);
    }
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0]->severity, driven ? Severity::kWarning : Severity::kInfo);
    EXPECT_EQ(found[0]->parts, (std::vector<std::string>{"block_1", "block_2"}));
    const std::string& m = found[0]->message;
    // On a face a block turns about its normal, wherever it is, and slides across it.
    EXPECT_NE(m.find("2 parts, block_1 and block_2, each turns about frame/seat's normal (planar "
                     "pair), slides along (0, 1, 0) on frame/seat (planar pair) and slides along "
                     "(1, 0, 0) on frame/seat (planar pair)"),
              std::string::npos)
        << m;
    // Held by nothing but their faces: what fastens them is what the file leaves out.
    EXPECT_EQ(an.motion.mobility.on_faces, 6);
    EXPECT_EQ(m.find("held by face contacts alone") != std::string::npos, !driven) << m;
  }
}

TEST(Motion, APartOnAShaftWithAThrustFaceIsNotHeldByFacesAlone) {
  // The gear's hub rests on the frame's seat, but its fit on the shaft is a pair of another
  // kind: its turn is the mechanism's, not a part lying loose on a face.
  const Feature seat = MakeFeature("seat", K::kFace, {0, 0, -10}, kZ, [](Feature& f) {
    f.width = 10;
    f.height = 10;
  });
  Builder b;
  b.Gear("g1", 0, 0, {{20, 0}}, 1, /*retained=*/false);
  b.FrameFeature(seat);
  AssemblySpec spec = b.Build().spec();
  for (mechanist::Part& p : spec.parts) {
    if (p.id == "g1") {
      p.features.push_back(MakeFeature("hub", K::kFace, {0, 0, -10}, -kZ, [](Feature& f) {
        f.width = 10;
        f.height = 10;
      }));
    }
  }
  const Analysis an = Analyze(Assembly(std::move(spec)));
  EXPECT_EQ(an.motion.mobility.dof, 1);
  EXPECT_EQ(an.motion.mobility.on_faces, 0);
  for (const Diagnostic& d : an.diagnostics) {
    if (d.code != "free_motion") continue;
    EXPECT_EQ(d.message.find("face contacts alone"), std::string::npos) << d.message;
    EXPECT_NE(d.message.find("a motion the mechanism allows"), std::string::npos) << d.message;
  }
}

// A disc about the part's z axis with `sides` facets (10 mm radius, a 2 mm bore): round at
// 96 facets, a hexagonal nut at 6.
std::shared_ptr<const TriangleMesh> Disc(int sides) {
  RadialGrid grid;
  grid.radius = [](double, double) { return 10.0; };
  grid.angular_segments = sides;
  grid.axial_segments = 1;
  grid.z0 = -5;
  grid.z1 = 5;
  grid.bore_radius = 2;
  grid.bore_segments = sides;
  return std::make_shared<TriangleMesh>(MakeRadialGridSolid(grid));
}

// A driven gear g1 and two parts s1, s2 alone on the frame's shafts (their teeth meet
// nothing), with the meshes given.
Analysis SpinningParts(int g1_sides, int s1_sides, int s2_sides) {
  AssemblySpec spec = Builder()
                          .Gear("g1", 0, 0, {{20, 0}})
                          .Gear("s1", 100, 0, {{20, 0}})
                          .Gear("s2", -100, 0, {{20, 0}})
                          .Drive("g1", "teeth")
                          .Build()
                          .spec();
  for (mechanist::Part& p : spec.parts) {
    if (p.id == "g1") p.mesh = Disc(g1_sides);
    if (p.id == "s1") p.mesh = Disc(s1_sides);
    if (p.id == "s2") p.mesh = Disc(s2_sides);
  }
  return Analyze(Assembly(std::move(spec)));
}

std::vector<const Diagnostic*> WithCode(const Analysis& an, const std::string& code) {
  std::vector<const Diagnostic*> found;
  for (const Diagnostic& d : an.diagnostics) {
    if (d.code == code) found.push_back(&d);
  }
  return found;
}

TEST(Motion, AFreeTurnIsNamedByTheAxisItTurnsAbout) {
  // The hub resting on the seat and the shaft in its bore both let the gear turn; the face
  // does not say where the turn's axis is (it would be the face's normal through the face's
  // centre, 3 mm off), the bore does.
  const Feature seat = MakeFeature("seat", K::kFace, {3, 0, -10}, kZ, [](Feature& f) {
    f.width = 10;
    f.height = 10;
  });
  Builder b;
  b.Gear("g1", 0, 0, {{20, 0}}, 1, /*retained=*/false).FrameFeature(seat);
  AssemblySpec spec = b.Build().spec();
  spec.parts[1].features.push_back(MakeFeature("hub", K::kFace, {0, 0, -10}, -kZ, [](Feature& f) {
    f.width = 10;
    f.height = 10;
  }));
  const Analysis an = Analyze(Assembly(std::move(spec)));
  ASSERT_EQ(an.motion.mobility.free_motions.size(), 1u);
  EXPECT_EQ(an.motion.mobility.free_motions[0].freedom, "turns about frame/bearing_g1's axis");
  const auto free = WithCode(an, "free_motion");
  ASSERT_EQ(free.size(), 1u);
  EXPECT_NE(free[0]->message.find("g1 turns about frame/bearing_g1's axis (cylindrical pair)"),
            std::string::npos)
      << free[0]->message;
}

TEST(Motion, RoundPartsTurningAloneAreIdleSpinsSaidOnce) {
  const Analysis an = SpinningParts(96, 96, 96);
  const Mobility& mobility = an.motion.mobility;
  EXPECT_EQ(mobility.dof, 3);
  ASSERT_EQ(mobility.free_motions.size(), 2u);
  EXPECT_EQ(mobility.idle, 2);
  for (const FreeMotion& f : mobility.free_motions) {
    EXPECT_TRUE(f.idle);
    EXPECT_EQ(f.parts.size(), 1u);
  }
  // The driven gear is round too, but the driver turns it: no free motion.
  EXPECT_TRUE(WithCode(an, "free_motion").empty());
  const auto idle = WithCode(an, "idle_spin");
  ASSERT_EQ(idle.size(), 1u);
  EXPECT_EQ(idle[0]->severity, Severity::kInfo);
  EXPECT_NE(idle[0]->message.find("2 parts, s1 and s2, each turns idly about its own axis"),
            std::string::npos)
      << idle[0]->message;
  EXPECT_EQ(idle[0]->parts, (std::vector<std::string>{"s1", "s2"}));
}

TEST(Motion, APartThatIsNotRoundMakesAFreeMotionNotAnIdleSpin) {
  // s2 is a hexagon about its shaft: turning it changes the assembly's shape.
  const Analysis an = SpinningParts(96, 96, 6);
  const Mobility& mobility = an.motion.mobility;
  EXPECT_EQ(mobility.dof, 3);
  EXPECT_EQ(mobility.free_motions.size(), 2u);
  EXPECT_EQ(mobility.idle, 1);
  const auto idle = WithCode(an, "idle_spin");
  ASSERT_EQ(idle.size(), 1u);
  EXPECT_NE(idle[0]->message.find("s1 turns about frame/bearing_s1's axis (revolute pair), idly"),
            std::string::npos)
      << idle[0]->message;
  const auto free = WithCode(an, "free_motion");
  ASSERT_EQ(free.size(), 1u);
  EXPECT_EQ(free[0]->severity, Severity::kWarning);  // the file drives g1, not s2
  EXPECT_EQ(free[0]->parts, std::vector<std::string>{"s2"});
  // Stand-in cubes are no round parts either.
  EXPECT_EQ(Analyze(Builder().Gear("g1", 0, 0, {{20, 0}}).Build()).motion.mobility.idle, 0);
}

TEST(Motion, GearFreeToSlideOnItsShaftIsAFreeMotion) {
  const Assembly a = Builder()
                         .Gear("g1", 0, 0, {{20, 0}})
                         .Gear("g2", 30, 0, {{40, 0}}, 1, false)
                         .Drive("g1", "teeth")
                         .Build();
  const Analysis an = Analyze(a);
  EXPECT_EQ(an.motion.mobility.dof, 2);
  ASSERT_EQ(an.motion.mobility.free_motions.size(), 1u);
  EXPECT_EQ(a.part(an.motion.mobility.free_motions[0].part).id, "g2");
  EXPECT_NE(an.motion.mobility.free_motions[0].freedom.find("slides along"), std::string::npos);
  EXPECT_EQ(Exact(Rate(a, an, "g2/teeth")), "-1/2");
}

}  // namespace
}  // namespace mechanist
