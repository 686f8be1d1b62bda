// Rolling bearings as they are sold (rings and balls): recognised as a revolute pair between
// the rings, the balls held with the outer ring; on a sketch with a 6002's dimensions and on
// the Fusion 360 rotary pendulum of ../shared/data/real, whose SKF 6002 has 9 separate balls.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "io/load_assembly.h"
#include "io/occt/step_fixtures.h"
#include "kernel/mesh/mesh_builder.h"
#include "reasoning/analysis.h"

namespace mechanist {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A 6002 (15 x 32 x 9) drawn by its features, axis z: the inner ring's bore and its two lands
// beside the raceway, the outer ring's outside and its two lands, and `balls` balls of 4.762
// mm on a 23.5 mm pitch circle in z = 0, the first moved by `off` mm across the circle.
// How the sketch's rolling elements are drawn: balls, rollers 5 mm long (a shaft and its
// two end faces) along the bearing's axis or along radii, or two round end faces 5 mm apart
// and nothing else: tapered rollers (4.4 and 5.1 mm ends) tilted 15 deg towards the axis or
// sideways (their axes then miss it), or barrel rollers (equal ends) tilted towards it or
// along it.
enum class Elements {
  kBalls,
  kRollersAlongTheAxis,
  kRollersAlongRadii,
  kTaperedRollers,
  kSkewedTaperedRollers,
  kEqualEnds,
  kEqualEndsAlongTheAxis
};

// With `washers` > 0 the rings are a thrust bearing's washers instead: the shaft washer
// (bore 15 mm) below the elements and the housing washer (bore 16 mm) above, each 3 mm thick,
// their 32 mm faces towards the elements `washers` mm from their plane.
std::string Sketch(int balls, double off = 0.0, Elements kind = Elements::kBalls,
                   double washers = 0.0) {
  std::string elements;
  for (int k = 0; k < balls; ++k) {
    const double a = 2 * kPi * k / balls, r = 11.75 + (k == 0 ? off : 0.0);
    const Eigen::Vector3d c(r * std::cos(a), r * std::sin(a), 0);
    if (kind == Elements::kBalls) {
      // Each ball's axis along its radius: a ball's axis means nothing to a bearing.
      elements += fmt::format(
          R"(, {{"id": "ball{}", "features": [{{"id": "ball", "kind": "ball",
            "origin": [{}, {}, 0], "axis": [{}, {}, 0], "diameter": 4.762}}]}})",
          k + 1, c.x(), c.y(), std::cos(a), std::sin(a));
      continue;
    }
    const Eigen::Vector3d radial(std::cos(a), std::sin(a), 0), across(-std::sin(a), std::cos(a), 0);
    const double tilt = 15 * kPi / 180;
    const Eigen::Vector3d u =
        kind == Elements::kRollersAlongTheAxis || kind == Elements::kEqualEndsAlongTheAxis
            ? Eigen::Vector3d::UnitZ()
        : kind == Elements::kRollersAlongRadii ? radial
        : kind == Elements::kSkewedTaperedRollers
            ? Eigen::Vector3d(std::cos(tilt) * Eigen::Vector3d::UnitZ() + std::sin(tilt) * across)
            : Eigen::Vector3d(std::cos(tilt) * Eigen::Vector3d::UnitZ() + std::sin(tilt) * radial);
    const Eigen::Vector3d o = c - 2.5 * u, e = c + 2.5 * u;
    if (kind != Elements::kRollersAlongTheAxis && kind != Elements::kRollersAlongRadii) {
      const bool equal = kind == Elements::kEqualEnds || kind == Elements::kEqualEndsAlongTheAxis;
      const double small = equal ? 5.1 : 4.4;
      elements += fmt::format(
          R"(, {{"id": "roller{}", "features": [
            {{"id": "small_end", "kind": "face", "origin": [{}, {}, {}], "axis": [{}, {}, {}],
             "width": {}, "height": {}}},
            {{"id": "large_end", "kind": "face", "origin": [{}, {}, {}], "axis": [{}, {}, {}],
             "width": 5.1, "height": 5.1}}]}})",
          k + 1, o.x(), o.y(), o.z(), -u.x(), -u.y(), -u.z(), small, small, e.x(), e.y(), e.z(),
          u.x(), u.y(), u.z());
      continue;
    }
    elements += fmt::format(
        R"(, {{"id": "roller{}", "features": [
          {{"id": "roll", "kind": "shaft", "origin": [{}, {}, {}], "axis": [{}, {}, {}],
           "diameter": 4.762, "length": 5}},
          {{"id": "end_a", "kind": "face", "origin": [{}, {}, {}], "axis": [{}, {}, {}]}},
          {{"id": "end_b", "kind": "face", "origin": [{}, {}, {}], "axis": [{}, {}, {}]}}]}})",
        k + 1, o.x(), o.y(), o.z(), u.x(), u.y(), u.z(), o.x(), o.y(), o.z(), -u.x(), -u.y(),
        -u.z(), e.x(), e.y(), e.z(), u.x(), u.y(), u.z());
  }
  if (washers > 0) {
    // A washer from z = `low` to `low` + 3: its bore, its outside (32 mm), its raceway face
    // towards the elements (at z = `raceway`, normal `facing` z) and its back face.
    auto washer = [](const char* id, bool ground, double bore, double low, double raceway,
                     double facing) {
      return fmt::format(R"({{"id": "{}", "ground": {}, "features": [
      {{"id": "bore", "kind": "hole", "origin": [0, 0, {}], "axis": [0, 0, 1], "diameter": {},
       "length": 3, "through": true}},
      {{"id": "outside", "kind": "shaft", "origin": [0, 0, {}], "axis": [0, 0, 1],
       "diameter": 32, "length": 3}},
      {{"id": "raceway", "kind": "face", "origin": [0, 0, {}], "axis": [0, 0, {}], "width": 32,
       "height": 32}},
      {{"id": "back", "kind": "face", "origin": [0, 0, {}], "axis": [0, 0, {}], "width": 32,
       "height": 32}}]}})",
                         id, ground, low, bore, low, raceway, facing, 2 * low + 3 - raceway,
                         -facing);
    };
    return fmt::format(R"({{"mechanist": 1, "parts": [{}, {}{}]}})",
                       washer("housing_washer", true, 16, washers, washers, -1),
                       washer("shaft_washer", false, 15, -washers - 3, -washers, 1), elements);
  }
  return fmt::format(R"({{"mechanist": 1, "parts": [
    {{"id": "outer", "ground": true, "features": [
      {{"id": "outside", "kind": "shaft", "origin": [0, 0, -4.5], "axis": [0, 0, 1],
       "diameter": 32, "length": 9}},
      {{"id": "land_a", "kind": "hole", "origin": [0, 0, -4.5], "axis": [0, 0, 1],
       "diameter": 26.7, "length": 2.6, "through": true}},
      {{"id": "land_b", "kind": "hole", "origin": [0, 0, 1.9], "axis": [0, 0, 1],
       "diameter": 26.7, "length": 2.6, "through": true}}]}},
    {{"id": "inner", "features": [
      {{"id": "bore", "kind": "hole", "origin": [0, 0, -4.5], "axis": [0, 0, 1],
       "diameter": 15, "length": 9, "through": true}},
      {{"id": "land_a", "kind": "shaft", "origin": [0, 0, -4.5], "axis": [0, 0, 1],
       "diameter": 20.5, "length": 2.6}},
      {{"id": "land_b", "kind": "shaft", "origin": [0, 0, 1.9], "axis": [0, 0, 1],
       "diameter": 20.5, "length": 2.6}}]}}{}]}})",
                     elements);
}

int CountSource(const Analysis& an, PairSource source) {
  int n = 0;
  for (const Pair& p : an.pairs) n += p.source == source;
  return n;
}

const Diagnostic* Find(const Analysis& an, const std::string& code) {
  for (const Diagnostic& d : an.diagnostics) {
    if (d.code == code) return &d;
  }
  return nullptr;
}

TEST(Bearing, RingsAndBallsAreOneRevoluteBearing) {
  const Assembly a = LoadAssemblyText(Sketch(9), "bearing.json");
  const Analysis an = Analyze(a);
  // The rings turn on each other; each ball is held with the outer ring and adds no freedom.
  ASSERT_EQ(CountSource(an, PairSource::kBearing), 10);
  int revolute = 0;
  for (const Pair& p : an.pairs) {
    EXPECT_EQ(p.source, PairSource::kBearing) << a.FeatureName(p.a) << " " << a.FeatureName(p.b);
    if (p.type == PairType::kRevolute) {
      ++revolute;
      EXPECT_EQ(a.FeatureName(p.a), "inner/land_a");  // the lands, closest to the balls
      EXPECT_EQ(a.FeatureName(p.b), "outer/land_a");
    } else {
      EXPECT_EQ(p.type, PairType::kFixed);
      EXPECT_EQ(a.PartId(p.b.part), "outer");
    }
  }
  EXPECT_EQ(revolute, 1);
  EXPECT_EQ(an.motion.mobility.dof, 1);  // the inner ring's turn
  const Diagnostic* bearing = Find(an, "bearing");
  ASSERT_NE(bearing, nullptr);
  EXPECT_NE(bearing->message.find("15 x 32 x 9 mm"), std::string::npos) << bearing->message;
  EXPECT_NE(bearing->message.find("9 balls of 4.762 mm on a 23.5 mm pitch circle"),
            std::string::npos)
      << bearing->message;
  EXPECT_EQ(Find(an, "part_unconnected"), nullptr);
}

// The pairs of an analysis as "type source a b" with the features' names, sorted.
std::vector<std::string> PairNames(const Assembly& a, const Analysis& an) {
  std::vector<std::string> names;
  for (const Pair& p : an.pairs) {
    names.push_back(fmt::format("{} {} {} {}", ToString(p.type), ToString(p.source),
                                a.FeatureName(p.a), a.FeatureName(p.b)));
  }
  std::sort(names.begin(), names.end());
  return names;
}

// The assemblies that `write` (a fixture writer) puts in a STEP file: as written, and with
// `nurbs` also that file copied with every surface a B-spline (else the first again). Written
// in a temporary folder named after the running test, removed once read.
std::pair<Assembly, Assembly> LoadFixtures(
    const std::function<void(const std::filesystem::path&)>& write, bool nurbs) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      (std::string("mechanist_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::filesystem::create_directories(dir);
  write(dir / "bearing.step");
  if (nurbs) testing::WriteNurbsCopy(dir / "bearing.step", dir / "nurbs.step");
  std::pair<Assembly, Assembly> read{LoadAssembly(dir / "bearing.step"),
                                     LoadAssembly(dir / (nurbs ? "nurbs.step" : "bearing.step"))};
  std::filesystem::remove_all(dir);
  return read;
}

// The assembly that `write` (a fixture writer) puts in a STEP file.
Assembly LoadFixture(const std::function<void(const std::filesystem::path&)>& write) {
  return LoadFixtures(write, false).first;
}

// The analysis's `bearing` info, checked to begin with `begins` and to hold `holds`; nothing
// (and a failure) when there is none.
const Diagnostic* ExpectBearing(const Analysis& an, const std::string& begins,
                                const std::string& holds) {
  const Diagnostic* bearing = Find(an, "bearing");
  EXPECT_NE(bearing, nullptr);
  if (!bearing) return nullptr;
  EXPECT_EQ(bearing->message.rfind(begins, 0), 0u) << bearing->message;
  EXPECT_NE(bearing->message.find(holds), std::string::npos) << bearing->message;
  return bearing;
}

// Checks an assembly that is one bearing and nothing else: one revolute pair, every pair of
// source bearing, every part in it, mobility 1 (the rings' turn).
void ExpectOneBearingAlone(const Assembly& a, const Analysis& an) {
  int revolute = 0;
  for (const Pair& p : an.pairs) {
    EXPECT_EQ(p.source, PairSource::kBearing) << a.FeatureName(p.a) << " " << a.FeatureName(p.b);
    revolute += p.type == PairType::kRevolute;
  }
  EXPECT_EQ(revolute, 1);
  // The revolute pair, and each element held with the outer ring.
  EXPECT_EQ(an.pairs.size(), a.parts().size() - 1);
  const Diagnostic* bearing = Find(an, "bearing");
  ASSERT_NE(bearing, nullptr);
  EXPECT_EQ(bearing->parts.size(), a.parts().size());
  EXPECT_EQ(an.motion.mobility.dof, 1);
  EXPECT_EQ(Find(an, "part_unconnected"), nullptr);
}

// Loads the assembly `write` puts in a STEP file, checks it has `parts` parts and is one
// bearing alone (ExpectOneBearingAlone) whose info begins with `begins` and holds `holds`.
void ExpectLoneBearingFixture(const std::function<void(const std::filesystem::path&)>& write,
                              std::size_t parts, const std::string& begins,
                              const std::string& holds) {
  const Assembly a = LoadFixture(write);
  ASSERT_EQ(a.parts().size(), parts);
  const Analysis an = Analyze(a);
  ExpectBearing(an, begins, holds);
  ExpectOneBearingAlone(a, an);
}

TEST(Bearing, ABallBearingModelledInOpenCascadeIsFoundAsWrittenAndAsBSplines) {
  // A vendor-style model: rings with toroidal raceways and nine separate balls. Written again
  // with every surface a B-spline (balls, raceways, lands), it must give the same bearing.
  const std::pair<Assembly, Assembly> read = LoadFixtures(
      [](const std::filesystem::path& file) { testing::WriteBallBearingStep(file, 9); }, true);
  const Assembly& exact = read.first;
  const Assembly& nurbs = read.second;
  const Analysis an_exact = Analyze(exact), an_nurbs = Analyze(nurbs);
  for (const auto* an : {&an_exact, &an_nurbs}) {
    const Diagnostic* bearing = Find(*an, "bearing");
    ASSERT_NE(bearing, nullptr);
    EXPECT_NE(bearing->message.find("15 x 32 x 9 mm"), std::string::npos) << bearing->message;
    EXPECT_NE(bearing->message.find("9 balls of 4.762 mm on a 23.5 mm pitch circle"),
              std::string::npos)
        << bearing->message;
    EXPECT_EQ(CountSource(*an, PairSource::kBearing), 10);  // the rings' revolute, nine balls
    EXPECT_EQ(an->motion.mobility.dof, 1);
    EXPECT_EQ(Find(*an, "part_unconnected"), nullptr);
  }
  EXPECT_EQ(PairNames(nurbs, an_nurbs), PairNames(exact, an_exact));
  // The B-spline copy says what its free-form faces were taken as: on a ball, one sphere; on
  // the inner ring, the raceway's torus besides its planes and cylinders.
  ASSERT_EQ(nurbs.parts().size(), 11u);
  auto converted = [&](std::size_t part) {
    for (const std::string& n : nurbs.part(part).notes) {
      if (n.find("taken as exact surfaces") != std::string::npos) return n;
    }
    return std::string();
  };
  EXPECT_NE(converted(0).find("1 torus"), std::string::npos) << converted(0);
  EXPECT_NE(converted(2).find("1 sphere"), std::string::npos) << converted(2);
  for (std::size_t p = 0; p < nurbs.parts().size(); ++p) {
    EXPECT_EQ(nurbs.part(p).features.size(), exact.part(p).features.size()) << nurbs.part(p).id;
  }
}

TEST(Bearing, ACageBetweenTheRingsIsHeldWithTheOuterRing) {
  // Between the lands beside the balls; where the rings were found by their bore and outside
  // (tapered and spherical roller bearings), between those. Each cage is written last.
  const struct {
    std::function<void(const std::filesystem::path&)> write;
    const char* kind;
    std::size_t parts;
  } cases[] = {
      {[](const std::filesystem::path& file) { testing::WriteBallBearingStep(file, 9, 1, true); },
       "a ball bearing, 15 x 32 x 9 mm: ", 12},
      {[](const std::filesystem::path& file) {
         testing::WriteTaperedRollerBearingStep(file, {.cage = true});
       },
       "a tapered roller bearing, 25 x 52 x 16 mm: ", 18},
      {[](const std::filesystem::path& file) {
         testing::WriteSphericalRollerBearingStep(file, true);
       },
       "a double-row spherical roller bearing, 25 x 52 x 18 mm: ", 31}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.kind);
    const Assembly a = LoadFixture(c.write);
    ASSERT_EQ(a.parts().size(), c.parts);
    const Analysis an = Analyze(a);
    const Diagnostic* bearing = ExpectBearing(
        an, c.kind, "(between the rings: a cage, seal or shield) is held with the outer ring too");
    ASSERT_NE(bearing, nullptr);
    EXPECT_EQ(bearing->parts.back(), a.part(c.parts - 1).id);
    ExpectOneBearingAlone(a, an);  // e.g. the 6002: rings, 9 balls and the cage, 11 pairs
  }
}

TEST(Bearing, BallsFusedWithTheirCageInOneSolidAreTheBearingsBallSet) {
  // Three solids: each ball's sphere, less the band inside the cage, is still a ball feature;
  // the part of nine balls is held with the outer ring once.
  const Assembly a = LoadFixture(testing::WriteThreeSolidBallBearingStep);
  ASSERT_EQ(a.parts().size(), 3u);
  const Analysis an = Analyze(a);
  const Diagnostic* bearing =
      ExpectBearing(an, "a ball bearing, 15 x 32 x 9 mm: ",
                    "on 9 balls of 4.762 mm on a 23.5 mm pitch circle (a revolute pair");
  ASSERT_NE(bearing, nullptr);
  EXPECT_EQ(bearing->parts.size(), 3u);
  ExpectOneBearingAlone(a, an);  // 2 pairs: the rings' revolute, the ball set held
  EXPECT_EQ(an.pairs.size(), 2u);
}

TEST(Bearing, TwoBallBearingsSideBySideAreTwoBearings) {
  // Their balls are neighbours (9 mm apart across the bearings), so they make one set, which
  // lies on no one circle: split into rows, each row finds its own rings.
  const Assembly a = LoadFixture(
      [](const std::filesystem::path& file) { testing::WriteBallBearingStep(file, 9, 2); });
  const Analysis an = Analyze(a);
  std::vector<const Diagnostic*> bearings;
  for (const Diagnostic& d : an.diagnostics) {
    if (d.code == "bearing") bearings.push_back(&d);
  }
  ASSERT_EQ(bearings.size(), 2u);
  for (const Diagnostic* bearing : bearings) {
    EXPECT_EQ(bearing->message.rfind("a ball bearing, 15 x 32 x 9 mm: ", 0), 0u)
        << bearing->message;
    EXPECT_NE(bearing->message.find("on 9 balls of 4.762 mm on a 23.5 mm pitch circle"),
              std::string::npos)
        << bearing->message;
    EXPECT_EQ(bearing->parts.size(), 11u);
  }
  EXPECT_NE(bearings[0]->parts[0], bearings[1]->parts[0]);  // each its own inner ring
  EXPECT_EQ(CountSource(an, PairSource::kBearing), 20);     // two rings' revolutes, 18 balls
  EXPECT_EQ(Find(an, "part_unconnected"), nullptr);
}

TEST(Bearing, CylindricalRollersBetweenTwoRingsAreARollerBearing) {
  const Assembly a = LoadFixture(testing::WriteRollerBearingStep);
  const Analysis an = Analyze(a);
  ExpectBearing(an, "a cylindrical roller bearing, 25 x 52 x 15 mm: ",
                "on 13 rollers of 6.5 x 8 mm on a 38.5 mm pitch circle");
  ExpectOneBearingAlone(a, an);  // 13 rollers: 15 parts, 14 pairs
}

TEST(Bearing, TaperedRollersBetweenACupAndAConeAreATaperedRollerBearing) {
  // Raceways and rollers are cones, which give no feature: the rollers are found by their
  // flat ends, the rings by the bore inside them and the outside cylinder outside them. As
  // B-splines throughout, the same.
  const std::pair<Assembly, Assembly> read = LoadFixtures(
      [](const std::filesystem::path& file) { testing::WriteTaperedRollerBearingStep(file); },
      true);
  const Assembly& exact = read.first;
  const Assembly& nurbs = read.second;
  const Analysis an_exact = Analyze(exact), an_nurbs = Analyze(nurbs);
  for (const auto* an : {&an_exact, &an_nurbs}) {
    ExpectBearing(*an, "a tapered roller bearing, 25 x 52 x 16 mm: ",
                  "on 15 rollers of 6.6 x 12 mm at 15 deg to its axis on a 39 mm pitch circle");
  }
  ASSERT_EQ(exact.parts().size(), 17u);
  ExpectOneBearingAlone(exact, an_exact);
  EXPECT_EQ(PairNames(nurbs, an_nurbs), PairNames(exact, an_exact));
}

TEST(Bearing, TaperedRollersWithADomedLargeEndAreMeasuredOnTheirMeshes) {
  // One flat end each: its normal is the roller's axis, the mesh gives its length and large
  // end. With their ends flat, the same bearing reads "6.6 x 12 mm ... on a 39 mm pitch
  // circle"; the dome (0.0775 mm) lengthens each roller, and moves its middle 0.039 mm along
  // its axis, 0.01 mm outward at 15 deg: 12.1 mm, and 39.02 mm across.
  ExpectLoneBearingFixture(
      [](const std::filesystem::path& file) {
        testing::WriteTaperedRollerBearingStep(file, {.domed_rollers = true});
      },
      17, "a tapered roller bearing, 25 x 52 x 16 mm: ",
      "on 15 rollers of 6.6 x 12.1 mm at 15 deg to its axis on a 39.02 mm pitch circle");
}

TEST(Bearing, DomesWithOneFlatFaceOnTheCircleAreNoRollers) {
  // The capped rollers replaced by hemispheres on the same flat faces, domed into the part:
  // they taper off, so they are no rollers, and there is no bearing.
  const Assembly a = LoadFixture([](const std::filesystem::path& file) {
    testing::WriteTaperedRollerBearingStep(file, {.domed_rollers = true});
  });
  ASSERT_EQ(a.parts().size(), 17u);
  ASSERT_NE(Find(Analyze(a), "bearing"), nullptr);
  AssemblySpec domes = a.spec();
  for (std::size_t i = 2; i < domes.parts.size(); ++i) {  // the rollers, after the rings
    Part& part = domes.parts[i];
    ASSERT_EQ(part.features.size(), 1u);
    const Feature& end = part.features[0];  // in the part's frame
    const Eigen::Vector3d n = end.axis.normalized();
    const Eigen::Vector3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
    TriangleMesh dome = MakeUvSphere(end.width / 2, 12, 24);
    for (Eigen::Vector3d& v : dome.vertices) {
      const double z = std::min(v.z(), 0.0);  // the lower half, its top flattened
      v = end.origin + v.x() * e1 + v.y() * e2 + z * n;
    }
    part.mesh = std::make_shared<const TriangleMesh>(std::move(dome));
  }
  EXPECT_EQ(Find(Analyze(Assembly(domes)), "bearing"), nullptr);
}

TEST(Bearing, TaperedRollersOnARacewayCutIntoAShaftTurnItInTheCup) {
  // No inner ring: the shaft's cylinders lie 8 mm beyond the rollers' plane; its mesh, the
  // raceway, reaches them. The size is the shaft's diameter (not its 5 mm centre hole's: a
  // shaft is no ring), the cup's outside and width.
  const Assembly a = LoadFixture([](const std::filesystem::path& file) {
    testing::WriteTaperedRollerBearingStep(file, {.raceway_on_shaft = true});
  });
  ASSERT_EQ(a.parts().size(), 17u);
  const Analysis an = Analyze(a);
  const Diagnostic* bearing =
      ExpectBearing(an, "a tapered roller bearing, 25 x 52 x 12.5 mm: ",
                    "on 15 rollers of 6.6 x 12 mm at 15 deg to its axis on a 39 mm pitch circle");
  ASSERT_NE(bearing, nullptr);
  EXPECT_EQ(bearing->parts[0], a.part(0).id);  // the shaft, written first
  ExpectOneBearingAlone(a, an);
  // The same shaft 40 mm along its axis, its raceway away from the rollers: no bearing.
  AssemblySpec moved = a.spec();
  moved.parts[0].X_WP = RigidTransform::Translation({0, 0, 40}) * moved.parts[0].X_WP;
  EXPECT_EQ(Find(Analyze(Assembly(moved)), "bearing"), nullptr);
}

TEST(Bearing, TwoRowsOfBallsOrBarrelRollersBetweenTheSameRingsAreOneDoubleRowBearing) {
  // The rows' elements are neighbours, so they make one set, which lies on no one circle: it
  // is split into its rows, and the rows between the same rings are one bearing.
  const struct {
    void (*write)(const std::filesystem::path&);
    const char* kind;
    const char* rows;
  } cases[] = {
      {testing::WriteDoubleRowBallBearingStep, "a double-row ball bearing, 25 x 52 x 20 mm: ",
       "on 2 rows of 12 balls of 7.144 mm on a 38.5 mm pitch circle"},
      {[](const std::filesystem::path& file) { testing::WriteSphericalRollerBearingStep(file); },
       "a double-row spherical roller bearing, 25 x 52 x 18 mm: ",
       "on 2 rows of 14 rollers of 6 x 7 mm (at their ends) at 13 deg to its axis on a "
       "39 mm pitch circle"},
      // Its outer raceway, a sphere, gives no feature: the outer ring is found by its outside.
      {testing::WriteSelfAligningBallBearingStep,
       "a double-row self-aligning ball bearing, 25 x 52 x 15 mm: ",
       "on 2 rows of 13 balls of 7.144 mm on a 38.5 mm pitch circle"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.kind);
    const Assembly a = LoadFixture(c.write);
    const Analysis an = Analyze(a);
    ExpectBearing(an, c.kind, c.rows);
    ExpectOneBearingAlone(a, an);
  }
}

TEST(Bearing, BallsOnALandInAHousingsWideBoreAreNoSelfAligningBearing) {
  // The self-aligning bearing's outer ring given a 46.5 mm bore around the balls, too wide to
  // be their raceway: the part around them has a bore, so it is no spherical raceway's ring.
  const Assembly a = LoadFixture(testing::WriteSelfAligningBallBearingStep);
  ASSERT_NE(Find(Analyze(a), "bearing"), nullptr);
  AssemblySpec wide = a.spec();
  Part& outer = wide.parts.back();  // written last
  Feature bore;
  bore.id = "wide_bore";
  bore.kind = FeatureKind::kHole;
  bore.origin = outer.X_WP.inverse() * Eigen::Vector3d(0, 0, -7.5);
  bore.axis = outer.X_WP.inverse().RotateDirection(Eigen::Vector3d::UnitZ());
  bore.diameter = 46.5;
  bore.length = 15;
  bore.through = true;
  outer.features.push_back(bore);
  EXPECT_EQ(Find(Analyze(Assembly(wide)), "bearing"), nullptr);
}

TEST(Bearing, BallsBetweenTwoGroovedWashersAreAThrustBearing) {
  const Assembly a = LoadFixture(
      [](const std::filesystem::path& file) { testing::WriteThrustBallBearingStep(file); });
  const Analysis an = Analyze(a);
  const Diagnostic* bearing =
      ExpectBearing(an, "a thrust ball bearing, 25 x 42 x 11 mm: ",
                    " on 12 balls of 6.35 mm on a 33.5 mm pitch circle (a revolute pair; the "
                    "balls are held with the housing washer");
  ASSERT_NE(bearing, nullptr);
  EXPECT_EQ(bearing->features[0].find("/hole_1"), bearing->features[0].size() - 7);  // bores
  ExpectOneBearingAlone(a, an);  // 12 balls: 14 parts, 13 pairs
  // With a cage between the washers, the cage is held with the housing washer too.
  ExpectLoneBearingFixture(
      [](const std::filesystem::path& file) { testing::WriteThrustBallBearingStep(file, true); },
      15, "a thrust ball bearing, 25 x 42 x 11 mm: ",
      "(between the rings: a cage, seal or shield) is held with the housing washer too");
}

TEST(Bearing, NeedlesInADrawnCupOnAShaftAreANeedleBearingAndTheShaftTurnsInIt) {
  // No inner ring: the needles run on the shaft itself, which turns in the cup.
  const Assembly a = LoadFixture(testing::WriteNeedleBearingStep);
  const Analysis an = Analyze(a);
  const Diagnostic* bearing = ExpectBearing(an, "a needle roller bearing, 12 x 19 x 12 mm: ",
                                            "on 18 needles of 2 x 10 mm on a 14 mm pitch circle");
  ASSERT_NE(bearing, nullptr);
  ASSERT_EQ(bearing->parts.size(), 20u);
  const Pair* turning = nullptr;
  for (const Pair& p : an.pairs) {
    if (p.type == PairType::kRevolute) turning = &p;
  }
  ASSERT_NE(turning, nullptr);
  EXPECT_EQ(a.PartId(turning->a.part), bearing->parts[0]);  // the shaft
  EXPECT_EQ(a.FeatureName(turning->a), bearing->features[0]);
  EXPECT_EQ(an.motion.mobility.dof, 1);
}

TEST(Bearing, ElementsOffTheirCircleTooFewOrAcrossTheAxisAreNoBearing) {
  // A ball 0.5 mm off the pitch circle (ten times the length tolerance): no circle, no bearing.
  const Analysis off = Analyze(LoadAssemblyText(Sketch(9, 0.5), "off.json"));
  EXPECT_EQ(CountSource(off, PairSource::kBearing), 0);
  EXPECT_EQ(Find(off, "bearing"), nullptr);
  // Two balls are no pitch circle.
  const Analysis two = Analyze(LoadAssemblyText(Sketch(2), "two.json"));
  EXPECT_EQ(CountSource(two, PairSource::kBearing), 0);
  // Four balls, 16.6 mm apart (3.5 diameters), are.
  const Analysis four = Analyze(LoadAssemblyText(Sketch(4), "four.json"));
  EXPECT_EQ(CountSource(four, PairSource::kBearing), 5);
  // Rollers along the axis between the same rings are a roller bearing; the same rollers
  // turned to lie along radii are none (the rings hold no thrust bearing's washers).
  const Analysis along =
      Analyze(LoadAssemblyText(Sketch(9, 0, Elements::kRollersAlongTheAxis), "along.json"));
  EXPECT_EQ(CountSource(along, PairSource::kBearing), 10);
  ExpectBearing(along,
                "a cylindrical roller bearing, 15 x 32 x 9 mm: ", "9 rollers of 4.762 x 5 mm");
  const Analysis radial =
      Analyze(LoadAssemblyText(Sketch(9, 0, Elements::kRollersAlongRadii), "radial.json"));
  EXPECT_EQ(CountSource(radial, PairSource::kBearing), 0);
  EXPECT_EQ(Find(radial, "bearing"), nullptr);
  // The rollers along radii between two washers whose faces touch them are a thrust bearing;
  // with the faces 0.6 mm off the rollers, none.
  const Analysis thrust =
      Analyze(LoadAssemblyText(Sketch(9, 0, Elements::kRollersAlongRadii, 2.381), "thrust.json"));
  EXPECT_EQ(CountSource(thrust, PairSource::kBearing), 10);
  ExpectBearing(thrust, "a thrust cylindrical roller bearing, 15 x 32 x 10.762 mm: ",
                "shaft_washer turns against housing_washer on 9 rollers of 4.762 x 5 mm on a "
                "23.5 mm pitch circle");
  EXPECT_EQ(thrust.motion.mobility.dof, 1);
  const Analysis apart =
      Analyze(LoadAssemblyText(Sketch(9, 0, Elements::kRollersAlongRadii, 2.981), "apart.json"));
  EXPECT_EQ(CountSource(apart, PairSource::kBearing), 0);
  // Tapered rollers tilted towards the axis are a tapered roller bearing, barrel rollers (two
  // equal ends) a spherical roller bearing; tilted sideways, their axes miss the bearing's and
  // they are none.
  const Analysis tapered =
      Analyze(LoadAssemblyText(Sketch(9, 0, Elements::kTaperedRollers), "tapered.json"));
  EXPECT_EQ(CountSource(tapered, PairSource::kBearing), 10);
  ExpectBearing(tapered, "a tapered roller bearing, 15 x 32 x 9 mm: ",
                "inner turns in outer on 9 rollers of 4.8 x 5 mm at 15 deg to its axis");
  const Analysis barrels =
      Analyze(LoadAssemblyText(Sketch(9, 0, Elements::kEqualEnds), "barrels.json"));
  EXPECT_EQ(CountSource(barrels, PairSource::kBearing), 10);
  ExpectBearing(barrels, "a spherical roller bearing, 15 x 32 x 9 mm: ",
                "inner turns in outer on 9 rollers of 5.1 x 5 mm (at their ends) at 15 deg to "
                "its axis");
  const Analysis along_barrels = Analyze(
      LoadAssemblyText(Sketch(9, 0, Elements::kEqualEndsAlongTheAxis), "along_barrels.json"));
  ExpectBearing(along_barrels, "a barrel roller bearing, 15 x 32 x 9 mm: ",
                "inner turns in outer on 9 rollers of 5.1 x 5 mm (at their ends) on a 23.5 mm "
                "pitch circle");
  const Analysis skewed =
      Analyze(LoadAssemblyText(Sketch(9, 0, Elements::kSkewedTaperedRollers), "skewed.json"));
  EXPECT_EQ(CountSource(skewed, PairSource::kBearing), 0);
  EXPECT_EQ(Find(skewed, "bearing"), nullptr);
}

// A housing (ground) with a 10 mm bore, a ring 10 x 5 x 4 mm in it (its ends one flat face
// each, or two: `rings`), and a 5 mm shaft through the ring; the shaft has a flat 0.5 mm deep
// over z `flat_from` to `flat_from` + 6 (none when NaN).
Assembly RingOnShaft(bool rings, double flat_from = std::nan("")) {
  const std::string ends = rings ? R"(,
      {"id": "outer_top", "kind": "face", "origin": [4, 0, 4], "axis": [0, 0, 1], "width": 2, "height": 2},
      {"id": "inner_top", "kind": "face", "origin": [3, 0, 4], "axis": [0, 0, 1], "width": 1, "height": 1},
      {"id": "outer_bottom", "kind": "face", "origin": [4, 0, 0], "axis": [0, 0, -1], "width": 2, "height": 2},
      {"id": "inner_bottom", "kind": "face", "origin": [3, 0, 0], "axis": [0, 0, -1], "width": 1, "height": 1})"
                                 : R"(,
      {"id": "top", "kind": "face", "origin": [3.5, 0, 4], "axis": [0, 0, 1], "width": 2, "height": 2},
      {"id": "bottom", "kind": "face", "origin": [3.5, 0, 0], "axis": [0, 0, -1], "width": 2, "height": 2})";
  const std::string flat =
      std::isnan(flat_from)
          ? ""
          : fmt::format(
                R"(, {{"id": "flat", "kind": "face", "origin": [2, 0, {}], "axis": [1, 0, 0],
                              "width": 3, "height": 6}})",
                flat_from + 3);
  return LoadAssemblyText(fmt::format(R"({{"mechanist": 1, "parts": [
    {{"id": "housing", "ground": true, "features": [
      {{"id": "bore", "kind": "hole", "origin": [0, 0, 0], "axis": [0, 0, 1], "diameter": 10,
       "length": 4, "through": true}}]}},
    {{"id": "ring", "features": [
      {{"id": "outside", "kind": "shaft", "origin": [0, 0, 0], "axis": [0, 0, 1], "diameter": 10,
       "length": 4}},
      {{"id": "bore", "kind": "hole", "origin": [0, 0, 0], "axis": [0, 0, 1], "diameter": 5,
       "length": 4, "through": true}}{}]}},
    {{"id": "shaft", "features": [
      {{"id": "shaft", "kind": "shaft", "origin": [0, 0, -10], "axis": [0, 0, 1], "diameter": 5,
       "length": 30}}{}]}}]}})",
                                      ends, flat),
                          "ring.json");
}

TEST(Bearing, ARingWithBothRingsEndsIsABearingOfOneSolidAndTheShaftTurnsInIt) {
  const Analysis bearing = Analyze(RingOnShaft(true));
  for (const Pair& p : bearing.pairs) {
    if (p.type == PairType::kPlanar) continue;
    EXPECT_EQ(p.source, PairSource::kBearing);
    const bool seat = p.b.part == 0;
    EXPECT_EQ(p.type, seat ? PairType::kFixed : PairType::kRevolute);
  }
  const Diagnostic* info = Find(bearing, "bearing");
  ASSERT_NE(info, nullptr);
  EXPECT_NE(info->message.find("one solid, 5 x 10 x 4 mm: ring fitted (fixed) in housing, shaft "
                               "turning in its bore"),
            std::string::npos)
      << info->message;
  EXPECT_EQ(bearing.motion.mobility.dof, 1);
  // A spacer (one face at each end) is no bearing: it turns in the housing, the shaft in it.
  const Analysis spacer = Analyze(RingOnShaft(false));
  EXPECT_EQ(Find(spacer, "bearing"), nullptr);
  for (const Pair& p : spacer.pairs) EXPECT_EQ(p.type, PairType::kCylindrical);
}

TEST(Bearing, AHubOnAShaftsFlatIsFixedToIt) {
  // The spacer on a shaft with a flat under its bore (z 0..4): fixed; a flat beside it: not.
  const Analysis on = Analyze(RingOnShaft(false, -2));
  const Diagnostic* flat = Find(on, "shaft_flat");
  ASSERT_NE(flat, nullptr);
  EXPECT_NE(flat->message.find("ring sits on the flat shaft/flat of shaft/shaft"),
            std::string::npos)
      << flat->message;
  int fixed = 0;
  for (const Pair& p : on.pairs) fixed += p.source == PairSource::kShaftFlat;
  EXPECT_EQ(fixed, 1);
  const Analysis beside = Analyze(RingOnShaft(false, 6));
  EXPECT_EQ(Find(beside, "shaft_flat"), nullptr);
}

// A V-wheel on an eccentric spacer, as a carriage plate carries it (axis z, the bolt on the
// z axis): an M5 bolt whose head bears on the plate's underside (z 0; none when `head_on_plate`
// is false) runs through an eccentric spacer, whose boss (0.8 mm off the bolt) fills the
// plate's 7.2 mm hole and whose shoulder sits on the plate (z 6), then through two bearings
// of one solid (5 x 10 x 4, z 10..14 and 15..19) with a shim between their inner rings, into
// a nut (z 19). The wheel holds the bearings' outsides, a shoulder between their outer rings.
Assembly VWheel(bool head_on_plate) {
  auto bearing = [](const std::string& id, double z) {
    return fmt::format(R"({{"id": "{0}", "features": [
      {{"id": "outside", "kind": "shaft", "origin": [0, 0, {1}], "axis": [0, 0, 1], "diameter": 10, "length": 4}},
      {{"id": "bore", "kind": "hole", "origin": [0, 0, {1}], "axis": [0, 0, 1], "diameter": 5, "length": 4, "through": true}},
      {{"id": "inner_bottom", "kind": "face", "origin": [2.8, 0, {1}], "axis": [0, 0, -1], "width": 0.5, "height": 0.5}},
      {{"id": "outer_bottom", "kind": "face", "origin": [4.5, 0, {1}], "axis": [0, 0, -1], "width": 1, "height": 1}},
      {{"id": "inner_top", "kind": "face", "origin": [2.8, 0, {2}], "axis": [0, 0, 1], "width": 0.5, "height": 0.5}},
      {{"id": "outer_top", "kind": "face", "origin": [4.5, 0, {2}], "axis": [0, 0, 1], "width": 1, "height": 1}}]}})",
                       id, z, z + 4);
  };
  const std::string plate_bottom = head_on_plate ? R"(,
      {"id": "bottom", "kind": "face", "origin": [0, 0, 0], "axis": [0, 0, -1], "width": 8, "height": 8})"
                                                 : "";
  return LoadAssemblyText(
      fmt::format(R"({{"mechanist": 1, "parts": [
    {{"id": "plate", "ground": true, "features": [
      {{"id": "hole", "kind": "hole", "origin": [0.8, 0, 0], "axis": [0, 0, 1], "diameter": 7.2, "length": 6, "through": true}},
      {{"id": "top", "kind": "face", "origin": [0.8, 0, 6], "axis": [0, 0, 1], "width": 8, "height": 8}}{}]}},
    {{"id": "bolt", "features": [
      {{"id": "thread", "kind": "thread", "origin": [0, 0, 0], "axis": [0, 0, 1], "diameter": 5, "pitch": 0.8, "length": 26}},
      {{"id": "head", "kind": "face", "origin": [0, 0, 0], "axis": [0, 0, 1], "width": 8, "height": 8}}]}},
    {{"id": "spacer", "features": [
      {{"id": "boss", "kind": "shaft", "origin": [0.8, 0, 2], "axis": [0, 0, 1], "diameter": 7.2, "length": 4}},
      {{"id": "bore", "kind": "hole", "origin": [0, 0, 2], "axis": [0, 0, 1], "diameter": 5, "length": 8, "through": true}},
      {{"id": "shoulder", "kind": "face", "origin": [0.8, 0, 6], "axis": [0, 0, -1], "width": 10, "height": 10}},
      {{"id": "top", "kind": "face", "origin": [0, 0, 10], "axis": [0, 0, 1], "width": 4, "height": 4}}]}},
    {},
    {{"id": "shim", "features": [
      {{"id": "hole", "kind": "hole", "origin": [0, 0, 14], "axis": [0, 0, 1], "diameter": 5, "length": 1, "through": true}},
      {{"id": "bottom", "kind": "face", "origin": [0, 0, 14], "axis": [0, 0, -1], "width": 4, "height": 4}},
      {{"id": "top", "kind": "face", "origin": [0, 0, 15], "axis": [0, 0, 1], "width": 4, "height": 4}}]}},
    {},
    {{"id": "nut", "features": [
      {{"id": "thread", "kind": "tapped_hole", "origin": [0, 0, 19], "axis": [0, 0, 1], "diameter": 5, "pitch": 0.8, "length": 4, "through": true}},
      {{"id": "bottom", "kind": "face", "origin": [0, 0, 19], "axis": [0, 0, -1], "width": 4, "height": 4}}]}},
    {{"id": "wheel", "features": [
      {{"id": "seat_a", "kind": "hole", "origin": [0, 0, 10], "axis": [0, 0, 1], "diameter": 10, "length": 4, "through": true}},
      {{"id": "seat_b", "kind": "hole", "origin": [0, 0, 15], "axis": [0, 0, 1], "diameter": 10, "length": 4, "through": true}},
      {{"id": "shoulder_low", "kind": "face", "origin": [4.5, 0, 14], "axis": [0, 0, -1], "width": 1, "height": 1}},
      {{"id": "shoulder_high", "kind": "face", "origin": [4.5, 0, 15], "axis": [0, 0, 1], "width": 1, "height": 1}}]}}]}})",
                  plate_bottom, bearing("bearing_a", 10), bearing("bearing_b", 15)),
      "vwheel.json");
}

TEST(Bearing, AVWheelTurnsOnItsBearingsAndItsBoltClampsThePlateThroughItsSpacer) {
  const Analysis wheel = Analyze(VWheel(true));
  // The plate, between the bolt's head and the spacer's shoulder, is clamped though the bolt
  // runs through the spacer's boss, not through the plate's hole.
  int plate_clamps = 0;
  for (const Pair& p : wheel.pairs) {
    if (p.source != PairSource::kClamp) continue;
    plate_clamps += p.a.part == 0 || p.b.part == 0 ? 1 : 0;
  }
  EXPECT_EQ(plate_clamps, 1);
  // The bolt clamps the bearings' bores, so the wheel turns on their outsides.
  int seats = 0;
  for (const Pair& p : wheel.pairs) {
    if (p.source != PairSource::kBearing) continue;
    EXPECT_EQ(p.type, PairType::kRevolute);
    ++seats;
  }
  EXPECT_EQ(seats, 2);
  const Diagnostic* info = Find(wheel, "bearing");
  ASSERT_NE(info, nullptr);
  EXPECT_NE(info->message.find("5 x 10 x 4 mm: bearing_a clamped through its bore by bolt, "
                               "wheel turning on it"),
            std::string::npos)
      << info->message;
  // The wheel's turn alone.
  EXPECT_EQ(wheel.motion.mobility.dof, 1);
  // Without the head on the plate, nothing presses the plate: the stack turns in it (its
  // shoulder on the plate holds it along the axis), and the wheel on the stack.
  const Analysis loose = Analyze(VWheel(false));
  for (const Pair& p : loose.pairs) {
    if (p.source == PairSource::kClamp) {
      EXPECT_FALSE(p.a.part == 0 || p.b.part == 0);
    }
  }
  EXPECT_EQ(loose.motion.mobility.dof, 2);
}

// A shaft collar (bore 8, outside 14, 7 long) on a ground rod, with a hole of 4.2 mm across
// its axis at mid-length whose ends lie `inner` and 7 mm from the rod's axis, `offset` mm
// beside it; `extra`: more parts.
Assembly CollarOnRod(double inner, double offset, const std::string& extra = "") {
  return LoadAssemblyText(fmt::format(R"({{"mechanist": 1, "parts": [
    {{"id": "rod", "ground": true, "features": [
      {{"id": "shaft", "kind": "shaft", "origin": [0, 0, -10], "axis": [0, 0, 1], "diameter": 8,
       "length": 30}}]}},
    {{"id": "collar", "features": [
      {{"id": "bore", "kind": "hole", "origin": [0, 0, 0], "axis": [0, 0, 1], "diameter": 8,
       "length": 7, "through": true}},
      {{"id": "outside", "kind": "shaft", "origin": [0, 0, 0], "axis": [0, 0, 1], "diameter": 14,
       "length": 7}},
      {{"id": "setscrew", "kind": "hole", "origin": [{}, {}, 3.5], "axis": [1, 0, 0],
       "diameter": 4.2, "length": {}, "through": true}}]}}{}]}})",
                                      inner, offset, 7 - inner, extra),
                          "collar.json");
}

TEST(Bearing, AShaftCollarWithAnEmptySetscrewHoleIsFixedToItsShaft) {
  // The hole's inner end at 3.4 mm, inside the 4 mm bore (a drilled hole meets a bore on a
  // saddle curve, closer than the bore's radius at its sides): a setscrew's hole.
  const Analysis collar = Analyze(CollarOnRod(3.4, 0));
  EXPECT_EQ(CountSource(collar, PairSource::kSetscrewHole), 1);
  EXPECT_EQ(collar.motion.mobility.dof, 0);
  const Diagnostic* info = Find(collar, "setscrew_hole");
  ASSERT_NE(info, nullptr);
  EXPECT_NE(info->message.find("collar sits on rod/shaft with an empty radial hole "
                               "collar/setscrew (4.2 mm) into its bore"),
            std::string::npos)
      << info->message;
  // A blind hole that stops short of the bore, and one beside the axis (a bolt hole through a
  // clamp collar's ear), leave it on the shaft: it turns and slides.
  for (const Assembly& a : {CollarOnRod(5, 0), CollarOnRod(3.4, 2.5)}) {
    const Analysis an = Analyze(a);
    EXPECT_EQ(CountSource(an, PairSource::kSetscrewHole), 0);
    EXPECT_EQ(an.motion.mobility.dof, 2);
  }
  // Held in a housing too, it is a bushing with an oil hole: the rod turns in it.
  const Analysis bushing = Analyze(CollarOnRod(3.4, 0, R"(,
    {"id": "housing", "ground": true, "features": [
      {"id": "bore", "kind": "hole", "origin": [0, 0, 0], "axis": [0, 0, 1], "diameter": 14,
       "length": 7, "through": true}]})"));
  EXPECT_EQ(CountSource(bushing, PairSource::kSetscrewHole), 0);
  // A pin in the hole is modelled: what it does is the pin's pairs' to say.
  const Analysis pinned = Analyze(CollarOnRod(3.4, 0, R"(,
    {"id": "pin", "features": [
      {"id": "pin", "kind": "shaft", "origin": [3.4, 0, 3.5], "axis": [1, 0, 0], "diameter": 4.2,
       "length": 3.6}]})"));
  EXPECT_EQ(CountSource(pinned, PairSource::kSetscrewHole), 0);
}

// A lever on a 5 mm shaft (axis z, z -5..25; the lever's hub z 10..15, line to line), the
// shaft in a bearing of one solid (5 x 10 x 4, z 0..4) fitted in a ground housing, or, with
// `bearing` false, straight in the housing's 5 mm hole; `extra`: more parts; `overrides`: the
// file's overrides.
Assembly LeverOnShaft(bool bearing, const std::string& extra = "",
                      const std::string& overrides = "[]") {
  const std::string housing = bearing ? R"({"id": "housing", "ground": true, "features": [
      {"id": "seat", "kind": "hole", "origin": [0, 0, 0], "axis": [0, 0, 1], "diameter": 10, "length": 4, "through": true}]},
    {"id": "bearing", "features": [
      {"id": "outside", "kind": "shaft", "origin": [0, 0, 0], "axis": [0, 0, 1], "diameter": 10, "length": 4},
      {"id": "bore", "kind": "hole", "origin": [0, 0, 0], "axis": [0, 0, 1], "diameter": 5, "length": 4, "through": true},
      {"id": "inner_bottom", "kind": "face", "origin": [2.8, 0, 0], "axis": [0, 0, -1], "width": 0.5, "height": 0.5},
      {"id": "outer_bottom", "kind": "face", "origin": [4.5, 0, 0], "axis": [0, 0, -1], "width": 1, "height": 1},
      {"id": "inner_top", "kind": "face", "origin": [2.8, 0, 4], "axis": [0, 0, 1], "width": 0.5, "height": 0.5},
      {"id": "outer_top", "kind": "face", "origin": [4.5, 0, 4], "axis": [0, 0, 1], "width": 1, "height": 1}]})"
                                      : R"({"id": "housing", "ground": true, "features": [
      {"id": "bore", "kind": "hole", "origin": [0, 0, 0], "axis": [0, 0, 1], "diameter": 5, "length": 4, "through": true}]})";
  return LoadAssemblyText(fmt::format(R"({{"mechanist": 1, "parts": [
    {},
    {{"id": "shaft", "features": [
      {{"id": "shaft", "kind": "shaft", "origin": [0, 0, -5], "axis": [0, 0, 1], "diameter": 5, "length": 30}}]}},
    {{"id": "lever", "features": [
      {{"id": "hub", "kind": "hole", "origin": [0, 0, 10], "axis": [0, 0, 1], "diameter": 5, "length": 5, "through": true}},
      {{"id": "eye", "kind": "hole", "origin": [30, 0, 10], "axis": [0, 0, 1], "diameter": 5, "length": 5, "through": true}}]}}{}],
    "overrides": {}}})",
                                      housing, extra, overrides),
                          "lever.json");
}

TEST(Bearing, ALeverHeldByNothingButAShaftThatTurnsInABearingTurnsWithIt) {
  const Analysis on_bearing = Analyze(LeverOnShaft(true));
  EXPECT_EQ(CountSource(on_bearing, PairSource::kBearingShaft), 1);
  const Diagnostic* info = Find(on_bearing, "bearing_shaft");
  ASSERT_NE(info, nullptr);
  EXPECT_NE(info->message.find("lever is held by nothing but shaft/shaft, on the axis of a "
                               "bearing between shaft and bearing: taken as fixed to it"),
            std::string::npos)
      << info->message;
  // The shaft turns in the bearing, the lever with it.
  EXPECT_EQ(on_bearing.motion.mobility.dof, 1);
  // In a plain hole the shaft itself turns and slides: the lever may be meant to turn on it.
  const Analysis plain = Analyze(LeverOnShaft(false));
  EXPECT_EQ(CountSource(plain, PairSource::kBearingShaft), 0);
  EXPECT_EQ(plain.motion.mobility.dof, 4);
  // A link pinned to the lever's eye holds it too: a rocker of a linkage, left turning.
  const Analysis linked = Analyze(LeverOnShaft(true, R"(,
    {"id": "pin", "features": [
      {"id": "pin", "kind": "shaft", "origin": [30, 0, 8], "axis": [0, 0, 1], "diameter": 5, "length": 9}]})"));
  EXPECT_EQ(CountSource(linked, PairSource::kBearingShaft), 0);
  // An override of type none forbids it (and the hub's pair with it).
  const Analysis forbidden = Analyze(
      LeverOnShaft(true, "", R"([{"pair": ["shaft/shaft", "lever/hub"], "type": "none"}])"));
  EXPECT_EQ(CountSource(forbidden, PairSource::kBearingShaft), 0);
  // A gear on the shaft too, meshing with a pinion that turns on a stub of a ground frame:
  // its teeth couple turns and hold nothing, so it turns with the shaft, and the mechanism
  // is the shaft's turn alone.
  const Analysis geared = Analyze(LeverOnShaft(true, R"(,
    {"id": "gear", "features": [
      {"id": "hub", "kind": "hole", "origin": [0, 0, 16], "axis": [0, 0, 1], "diameter": 5, "length": 5, "through": true},
      {"id": "teeth", "kind": "gear", "origin": [0, 0, 16], "axis": [0, 0, 1], "teeth": 40, "module": 1, "length": 5}]},
    {"id": "pinion", "features": [
      {"id": "hub", "kind": "hole", "origin": [-30, 0, 16], "axis": [0, 0, 1], "diameter": 5, "length": 5, "through": true, "retained": true},
      {"id": "teeth", "kind": "gear", "origin": [-30, 0, 16], "axis": [0, 0, 1], "teeth": 20, "module": 1, "length": 5}]},
    {"id": "frame", "ground": true, "features": [
      {"id": "stub", "kind": "shaft", "origin": [-30, 0, 14], "axis": [0, 0, 1], "diameter": 5, "length": 9}]})"));
  EXPECT_EQ(CountSource(geared, PairSource::kBearingShaft), 2);  // the lever and the gear
  int meshes = 0;
  for (const Pair& p : geared.pairs) meshes += p.type == PairType::kGear;
  EXPECT_EQ(meshes, 1);
  EXPECT_EQ(geared.motion.mobility.dof, 1);
}

TEST(Bearing, TheFusionPendulumsSkf6002IsFoundWithItsNineBalls) {
  // Truth: a deep-groove ball bearing, 9 balls of r about 2.36 on a pitch circle of r about
  // 11.7, races of bore r 7.5 and outside r 16 (an SKF 6002: 15 x 32 x 9).
  const Assembly a = LoadAssembly(std::filesystem::path(MECHANIST_SHARED_DATA) / "real" /
                                  "rotary_pendulum_ball_bearing_fusion" / "Assembly.step");
  const Analysis an = Analyze(a);
  const Diagnostic* bearing = Find(an, "bearing");
  ASSERT_NE(bearing, nullptr);
  EXPECT_NE(bearing->message.find("15 x 32 x 9 mm"), std::string::npos) << bearing->message;
  EXPECT_NE(bearing->message.find("9 balls of 4.762 mm"), std::string::npos) << bearing->message;
  EXPECT_EQ(bearing->parts.size(), 11u);  // two rings and nine balls
  // Its rings' revolute (the motor's two one-solid bearings give the others).
  const Pair* rings = nullptr;
  for (const Pair& p : an.pairs) {
    if (p.source == PairSource::kBearing && p.type == PairType::kRevolute &&
        std::string(a.PartId(p.a.part)).find("SKF_6002") != std::string::npos) {
      rings = &p;
    }
  }
  ASSERT_NE(rings, nullptr);
  EXPECT_NE(std::string(a.PartId(rings->a.part)).find("SKF_6002_or_1_solid10"), std::string::npos);
  EXPECT_NE(std::string(a.PartId(rings->b.part)).find("SKF_6002_or_1_solid11"), std::string::npos);
  // The truth's axis: x, with the arm's small yaw (y component 0.006).
  const AxisSegment axis = a.feature(rings->a).WorldAxis(a.part(rings->a.part).X_WP);
  EXPECT_NEAR(std::abs(axis.direction.x()), 1.0, 1e-3);
  EXPECT_NEAR(std::abs(axis.direction.y()), 0.006, 1e-3);
  // No ball is left unconnected.
  const Diagnostic* unconnected = Find(an, "part_unconnected");
  if (unconnected) {
    for (const std::string& part : unconnected->parts) {
      EXPECT_EQ(part.find("SKF_6002"), std::string::npos) << part;
    }
  }
  // Its rings are fitted: the outer in the arm's housing bore, the inner on the joint rod
  // (both r 16 and r 7.5 without clearance), so the rod turns with the inner ring.
  EXPECT_NE(bearing->message.find("its rings are fitted (fixed) to Assembly_v14.BarLink_v9_1 and "
                                  "Assembly_v14.JointRod_v4_1"),
            std::string::npos)
      << bearing->message;
}

TEST(Bearing, ThePendulumsMotorBearingsAreOneSolidEachAndItsShaftTurnsInThem) {
  // Truth: joint 1 is the arm turning about z with the stepper shaft; the motor's bearings are
  // single solids (5 x 10 x 5.9, both rings' end faces apart), fitted in its end plates; the
  // arm's hub sits on the shaft's flat.
  const Assembly a = LoadAssembly(std::filesystem::path(MECHANIST_SHARED_DATA) / "real" /
                                  "rotary_pendulum_ball_bearing_fusion" / "Assembly.step");
  const Analysis an = Analyze(a);
  int solid = 0;
  for (const Diagnostic& d : an.diagnostics) {
    if (d.code != "bearing" ||
        d.message.find("modelled as one solid, 5 x 10 x 5.9 mm") == std::string::npos) {
      continue;
    }
    ++solid;
    EXPECT_NE(d.message.find("Stepper_shaft_1 turning in its bore"), std::string::npos)
        << d.message;
  }
  EXPECT_EQ(solid, 2);
  int turns = 0, flats = 0;
  for (const Pair& p : an.pairs) {
    const std::string a_id(a.PartId(p.a.part));
    if (a_id.find("Stepper_shaft") == std::string::npos) continue;
    turns += p.type == PairType::kRevolute && p.source == PairSource::kBearing;
    flats += p.source == PairSource::kShaftFlat;
  }
  EXPECT_EQ(turns, 2);
  EXPECT_EQ(flats, 1);
}

}  // namespace
}  // namespace mechanist
