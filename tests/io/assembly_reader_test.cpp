#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/input_error.h"
#include "io/load_assembly.h"

namespace mechanist {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// A temporary folder with a cube mesh, for files that name meshes.
class AssemblyReaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        std::filesystem::temp_directory_path() /
        ("mechanist_reader_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_ / "meshes");
    std::ofstream cube(dir_ / "meshes" / "cube.obj");
    cube << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
            "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  Assembly Parse(const std::string& text) { return LoadAssemblyText(text, dir_ / "a.json"); }

  /// Parses `text` expecting an InputError at `pointer` whose message contains `contains`;
  /// returns it for further checks.
  InputError ExpectError(const std::string& text, const std::string& pointer,
                         const std::string& contains) {
    try {
      Parse(text);
    } catch (const InputError& e) {
      EXPECT_EQ(e.pointer(), pointer) << e.what();
      EXPECT_NE(std::string(e.what()).find(contains), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("a.json"), std::string::npos) << e.what();
      return e;
    }
    ADD_FAILURE() << "no error for: " << text;
    return InputError("", "", 0, 0, "");
  }

  /// A one-part file with `part` members added after the id and mesh.
  static std::string OnePart(const std::string& members, const std::string& top = "") {
    return R"({"mechanist": 1, )" + top + R"("parts": [{"id": "p", "mesh": "meshes/cube.obj")" +
           (members.empty() ? "" : ", " + members) + "}]}";
  }

  std::filesystem::path dir_;
};

TEST_F(AssemblyReaderTest, ReadsMinimalFileWithDefaults) {
  const Assembly a = Parse(OnePart(""));
  ASSERT_EQ(a.parts().size(), 1u);
  const Part& p = a.part(0);
  EXPECT_EQ(p.id, "p");
  EXPECT_EQ(p.mesh->faces.size(), 12u);
  EXPECT_NEAR(p.mesh->SignedVolume(), 1.0, 1e-12);
  // No part is ground: the largest (the only one) is taken as ground, and the load says so.
  EXPECT_TRUE(p.ground);
  ASSERT_EQ(a.findings().size(), 1u);
  EXPECT_EQ(a.findings()[0].code, "ground_chosen");
  EXPECT_TRUE(p.X_WP.IsNearlyEqualTo(RigidTransform(), 0, 0));
  EXPECT_EQ(a.units().length, "mm");
  EXPECT_DOUBLE_EQ(a.tolerance().length, 0.05);
  EXPECT_NEAR(a.tolerance().angle, 0.5 * kPi / 180, 1e-15);
  EXPECT_DOUBLE_EQ(a.friction(), 0.1);
}

TEST_F(AssemblyReaderTest, ReadsTheInferSwitchesEachOnWhenNotGiven) {
  const Inference given =
      Parse(OnePart("", R"("infer": {"implied_pins": false, "seated_parts": false, )"
                        R"("embedded_parts": false, "centred_parts": false}, )"))
          .inference();
  EXPECT_FALSE(given.implied_pins);
  EXPECT_TRUE(given.implied_frame);
  EXPECT_FALSE(given.seated_parts);
  EXPECT_FALSE(given.embedded_parts);
  EXPECT_FALSE(given.centred_parts);
  const Inference defaults = Parse(OnePart("")).inference();
  EXPECT_TRUE(defaults.implied_pins && defaults.implied_frame && defaults.seated_parts &&
              defaults.embedded_parts && defaults.centred_parts);
  ExpectError(OnePart("", R"("infer": {"seated_parts": 0}, )"), "/infer/seated_parts",
              "expected true or false");
}

TEST_F(AssemblyReaderTest, AcceptsCommentsAndExtra) {
  const Assembly a = Parse(R"(// leading comment
    {"mechanist": 1, /* block
    comment */ "extra": {"anything": [1, 2]},
     "parts": [{"id": "p", "mesh": "meshes/cube.obj", "extra": "kept and ignored"}]})");
  EXPECT_EQ(a.parts().size(), 1u);
}

TEST_F(AssemblyReaderTest, ConvertsUnitsToMillimetresAndRadians) {
  const Assembly a = Parse(OnePart(
      R"("pose": {"position": [1, 2, 3], "rotation": {"axis": [0, 0, 2], "angle": 1.5707963267948966}},
         "features": [{"id": "s", "kind": "shaft", "origin": [0, 0, 0.5], "axis": [0, 0, 3],
                       "diameter": 0.25, "length": 1}])",
      R"("units": {"length": "in", "angle": "rad"}, "tolerance": {"length": 0.001, "angle": 0.01},)"));
  EXPECT_NEAR(a.part(0).mesh->SignedVolume(), std::pow(25.4, 3), 1e-6);
  EXPECT_TRUE(a.part(0).X_WP.translation().isApprox(Eigen::Vector3d(25.4, 50.8, 76.2)));
  const Eigen::Vector3d x_W = a.part(0).X_WP.RotateDirection(Eigen::Vector3d::UnitX());
  EXPECT_TRUE(x_W.isApprox(Eigen::Vector3d::UnitY(), 1e-12));
  const Feature& s = a.part(0).features[0];
  EXPECT_DOUBLE_EQ(s.diameter, 6.35);
  EXPECT_DOUBLE_EQ(s.origin.z(), 12.7);
  EXPECT_TRUE(s.axis.isApprox(Eigen::Vector3d::UnitZ()));  // normalised
  EXPECT_DOUBLE_EQ(a.tolerance().length, 0.0254);
  EXPECT_DOUBLE_EQ(a.tolerance().angle, 0.01);
}

TEST_F(AssemblyReaderTest, ThreePoseFormsAgree) {
  // 90 degrees about z, then translation (1, 2, 3).
  const char* forms[] = {
      R"("pose": {"position": [1, 2, 3], "rotation": {"axis": [0, 0, 1], "angle": 90}})",
      R"("pose": {"position": [1, 2, 3], "quaternion": [1.4142135623730951, 0, 0, 1.4142135623730951]})",
      R"("pose": {"matrix": [[0, -1, 0, 1], [1, 0, 0, 2], [0, 0, 1, 3], [0, 0, 0, 1]]})",
  };
  const RigidTransform expected(
      Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
      Eigen::Vector3d(1, 2, 3));
  for (const char* form : forms) {
    const Assembly a = Parse(OnePart(form));
    EXPECT_TRUE(a.part(0).X_WP.IsNearlyEqualTo(expected, 1e-12, 1e-12)) << form;
  }
}

TEST_F(AssemblyReaderTest, ReadsEveryFeatureKindWithDefaults) {
  const Assembly a = Parse(OnePart(R"("features": [
    {"id": "sh", "kind": "shaft", "origin": [0,0,0], "axis": [0,0,1], "diameter": 5, "length": 10},
    {"id": "ho", "kind": "hole", "origin": [0,0,0], "axis": [0,0,1], "diameter": 5, "length": 10, "through": true, "retained": true},
    {"id": "th", "kind": "thread", "origin": [0,0,0], "axis": [0,0,1], "diameter": 3, "pitch": 0.5, "length": 8},
    {"id": "tp", "kind": "tapped_hole", "origin": [0,0,0], "axis": [0,0,1], "diameter": 3, "pitch": 0.5, "length": 8, "starts": 2, "hand": "left"},
    {"id": "sl", "kind": "slot", "origin": [0,0,0], "axis": [1,0,0], "width": 4, "length": 20, "depth": 3, "normal": [0,0,-1]},
    {"id": "ke", "kind": "key", "origin": [0,0,0], "axis": [1,0,0], "width": 4, "length": 20, "normal": [0,0,1]},
    {"id": "ge", "kind": "gear", "origin": [0,0,0], "axis": [0,0,1], "teeth": 20, "module": 1, "length": 5, "internal": true},
    {"id": "wo", "kind": "worm", "origin": [0,0,0], "axis": [1,0,0], "module": 1, "pitch_diameter": 10, "length": 20},
    {"id": "ww", "kind": "worm_wheel", "origin": [0,0,0], "axis": [0,0,1], "teeth": 40, "module": 1, "length": 8},
    {"id": "ra", "kind": "rack", "origin": [0,0,0], "axis": [1,0,0], "module": 1, "length": 50, "normal": [0,1,0]},
    {"id": "ba", "kind": "ball", "origin": [0,0,0], "diameter": 10},
    {"id": "so", "kind": "socket", "origin": [0,0,0], "axis": [0,0,1], "diameter": 10},
    {"id": "fa", "kind": "face", "origin": [0,0,0], "axis": [0,0,1]}])"));
  const auto& f = a.part(0).features;
  ASSERT_EQ(f.size(), 13u);
  EXPECT_EQ(f[0].kind, FeatureKind::kShaft);
  EXPECT_FALSE(f[0].retained);
  EXPECT_TRUE(f[1].through && f[1].retained);
  EXPECT_EQ(f[2].starts, 1);
  EXPECT_EQ(f[2].hand, Hand::kRight);
  EXPECT_EQ(f[2].fastening, Fastening::kTight);
  EXPECT_EQ(f[3].starts, 2);
  EXPECT_EQ(f[3].hand, Hand::kLeft);
  EXPECT_TRUE(f[4].normal.isApprox(-Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE(f[6].internal);
  EXPECT_EQ(f[6].teeth, 20);
  EXPECT_EQ(f[7].starts, 1);
  EXPECT_DOUBLE_EQ(f[7].pitch_diameter, 10);
  EXPECT_EQ(f[10].kind, FeatureKind::kBall);
  EXPECT_EQ(a.FeatureName(*a.FindFeature("p/fa")), "p/fa");
}

TEST_F(AssemblyReaderTest, ReadsDriversAdjustmentsGoalsStepsOverridesExpectations) {
  const Assembly a = Parse(R"({"mechanist": 1, "units": {"length": "cm"},
    "parts": [
      {"id": "a", "mesh": "meshes/cube.obj", "ground": true, "group": "g/1", "features": [
        {"id": "h", "kind": "hole", "origin": [0,0,0], "axis": [0,0,1], "diameter": 1, "length": 1}]},
      {"id": "b", "mesh": "meshes/cube.obj", "features": [
        {"id": "s", "kind": "shaft", "origin": [0,0,0], "axis": [0,0,1], "diameter": 1, "length": 1}]}],
    "drivers": [{"id": "m", "part": "b", "feature": "s", "relative_to": "a", "motion": "translation", "rate": 2, "amount": 3},
                {"part": "b", "feature": "s"}],
    "adjustments": [{"id": "swing", "moves": "b", "rotate_about": "a/h", "range": [-15, 15]},
                    {"id": "slide", "moves": "b", "translate_along": "a/h", "range": [0, 2]}],
    "goals": [{"coaxial": ["a/h", "b/s"]}, {"coaxial": ["b/s", "a/h"]}],
    "steps": [{"insert": "b/s", "into": "a/h"}],
    "overrides": [{"pair": ["a/h", "b/s"], "type": "fixed"}, {"pair": ["a/h", "b/s"], "type": "none"}],
    "expect": [
      {"part": "b", "feature": "s", "ratio": "-1/40"},
      {"part": "b", "ratio": 0.025},
      {"part": "b", "ratio": -3},
      {"part": "b", "ratio": "2/4"},
      {"part": "a", "moves": false},
      {"mobility": 1},
      {"pair": ["a/h", "b/s"], "type": "cylindrical"},
      {"same_subassembly": ["a", "b"]},
      {"assemblable": true},
      {"diagnostic": "near_miss", "parts": ["a"]}]})");
  EXPECT_EQ(a.part(0).group, "g/1");
  ASSERT_EQ(a.drivers().size(), 2u);
  EXPECT_EQ(a.drivers()[0].motion, Driver::Motion::kTranslation);
  EXPECT_DOUBLE_EQ(a.drivers()[0].rate, 20);  // 2 cm/s
  EXPECT_DOUBLE_EQ(a.drivers()[0].amount, 30);
  EXPECT_EQ(*a.drivers()[0].relative_to, 0u);
  EXPECT_EQ(a.drivers()[1].id, "b/s");
  EXPECT_EQ(a.drivers()[1].motion, Driver::Motion::kRotation);
  EXPECT_DOUBLE_EQ(a.drivers()[1].rate, 1);
  EXPECT_FALSE(a.drivers()[1].relative_to.has_value());
  EXPECT_NEAR(a.adjustments()[0].lower, -15 * kPi / 180, 1e-15);
  EXPECT_DOUBLE_EQ(a.adjustments()[1].upper, 20);  // 2 cm
  EXPECT_EQ(a.goals()[1].kind, Goal::Kind::kCoaxial);
  EXPECT_EQ(a.steps()[0].into.part, 0u);
  EXPECT_EQ(*a.overrides()[0].type, PairType::kFixed);
  EXPECT_FALSE(a.overrides()[1].type.has_value());
  const auto& e = a.expectations();
  ASSERT_EQ(e.size(), 10u);
  EXPECT_TRUE(e[0].ratio.exact);
  EXPECT_EQ(e[0].ratio.numerator, -1);
  EXPECT_EQ(e[0].ratio.denominator, 40);
  EXPECT_EQ(e[0].pointer, "/expect/0");
  EXPECT_FALSE(e[1].ratio.exact);
  EXPECT_DOUBLE_EQ(e[1].ratio.value, 0.025);
  EXPECT_TRUE(e[2].ratio.exact);
  EXPECT_EQ(e[2].ratio.numerator, -3);
  EXPECT_EQ(e[3].ratio.numerator, 1);  // reduced
  EXPECT_EQ(e[3].ratio.denominator, 2);
  EXPECT_EQ(e[4].kind, Expectation::Kind::kMoves);
  EXPECT_FALSE(e[4].flag);
  EXPECT_EQ(e[5].mobility, 1);
  EXPECT_EQ(*e[6].pair_type, PairType::kCylindrical);
  EXPECT_EQ(e[7].parts.size(), 2u);
  EXPECT_TRUE(e[8].flag);
  EXPECT_EQ(e[9].diagnostic, "near_miss");
}

// A lead screw whose thread the file leaves out is coupled to its nut by a screw override
// with the lead, in the file's length units and signed by hand.
TEST_F(AssemblyReaderTest, ReadsAScrewOverridesLeadAndRejectsOneWithoutIt) {
  const std::string parts =
      R"({"mechanist": 1, "units": {"length": "cm"}, "parts": [
      {"id": "a", "mesh": "meshes/cube.obj", "features": [
        {"id": "h", "kind": "hole", "origin": [0,0,0], "axis": [0,0,1], "diameter": 1, "length": 1}]},
      {"id": "b", "mesh": "meshes/cube.obj", "features": [
        {"id": "s", "kind": "shaft", "origin": [0,0,0], "axis": [0,0,1], "diameter": 1, "length": 3},
        {"id": "t", "kind": "thread", "origin": [0,0,0], "axis": [0,0,1], "diameter": 1, "pitch": 0.1, "length": 3}]}], )";
  const Assembly a = Parse(parts + R"("overrides": [
      {"pair": ["b/s", "a/h"], "type": "screw", "lead": -0.8},
      {"pair": ["b/t", "a/h"], "type": "screw"}]})");
  ASSERT_EQ(a.overrides().size(), 2u);
  EXPECT_EQ(*a.overrides()[0].type, PairType::kScrew);
  EXPECT_DOUBLE_EQ(*a.overrides()[0].lead, -8.0);   // mm, a left-hand thread
  EXPECT_FALSE(a.overrides()[1].lead.has_value());  // the thread's own
  ExpectError(parts + R"("overrides": [{"pair": ["b/s", "a/h"], "type": "screw"}]})",
              "/overrides/0", "expected \"lead\"");
  ExpectError(parts + R"("overrides": [{"pair": ["b/s", "a/h"], "type": "fixed", "lead": 1}]})",
              "/overrides/0/lead", "only with type \"screw\", found type \"fixed\"");
  ExpectError(parts + R"("overrides": [{"pair": ["b/s", "a/h"], "type": "screw", "lead": 0}]})",
              "/overrides/0/lead", "nonzero");
}

TEST_F(AssemblyReaderTest, SharesOneMeshBetweenInstances) {
  const Assembly a = Parse(R"({"mechanist": 1, "parts": [
    {"id": "a", "mesh": "meshes/cube.obj"}, {"id": "b", "mesh": "meshes/../meshes/cube.obj"}]})");
  EXPECT_EQ(a.part(0).mesh.get(), a.part(1).mesh.get());
}

TEST_F(AssemblyReaderTest, ReadsLibraryPartsWithUnits) {
  const Assembly a = Parse(R"({"mechanist": 1, "units": {"length": "cm"}, "parts": [
    {"id": "g", "library": {"kind": "spur_gear", "teeth": 20, "module": 0.1, "face_width": 0.5},
     "features": [{"id": "extra_face", "kind": "face", "origin": [0, 0, 0], "axis": [0, 0, -1]}]}]})");
  const Part& g = a.part(0);
  EXPECT_EQ(g.mesh_source, "library:spur_gear");
  const auto teeth = g.FindFeature("teeth");
  ASSERT_TRUE(teeth.has_value());
  EXPECT_DOUBLE_EQ(g.features[*teeth].module, 1.0);
  EXPECT_EQ(g.features[*teeth].teeth, 20);
  EXPECT_TRUE(g.FindFeature("extra_face").has_value());
  EXPECT_NEAR(g.mesh->Bounds().size().z(), 5.0, 1e-9);
}

TEST_F(AssemblyReaderTest, ReadsPlacementsAndRejectsCycles) {
  const std::string parts = R"("parts": [
    {"id": "plate", "mesh": "meshes/cube.obj", "features": [
      {"id": "h", "kind": "hole", "origin": [0,0,1], "axis": [0,0,-1], "diameter": 3, "length": 1, "through": true}]},
    {"id": "pin", "mesh": "meshes/cube.obj", "place": {"insert": "pin/s", "into": "plate/h", "depth": 0.5},
     "features": [{"id": "s", "kind": "shaft", "origin": [0,0,0], "axis": [0,0,1], "diameter": 3, "length": 1}]}])";
  const Assembly a = Parse(R"({"mechanist": 1, )" + parts + "}");
  ASSERT_EQ(a.part(1).placement.size(), 1u);
  EXPECT_EQ(a.part(1).placement[0].kind, PlacementCondition::Kind::kInsert);
  EXPECT_DOUBLE_EQ(*a.part(1).placement[0].depth, 0.5);
  // Solved on reading: the pin's shaft 0.5 mm down the hole, pointing down it.
  EXPECT_LT((a.part(1).X_WP * Eigen::Vector3d(0, 0, 0) - Eigen::Vector3d(0, 0, 0.5)).norm(), 1e-12);
  EXPECT_LT((a.part(1).X_WP.RotateDirection({0, 0, 1}) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-12);
  // Conditions that cannot all hold name the part's place.
  ExpectError(R"({"mechanist": 1, "parts": [
    {"id": "plate", "mesh": "meshes/cube.obj", "features": [
      {"id": "h", "kind": "hole", "origin": [0,0,1], "axis": [0,0,-1], "diameter": 3, "length": 1},
      {"id": "top", "kind": "face", "origin": [0,0,1], "axis": [0,0,1]}]},
    {"id": "pin", "mesh": "meshes/cube.obj",
     "place": [{"insert": "pin/s", "into": "plate/h", "depth": 0.5}, {"against": "pin/f", "on": "plate/top"}],
     "features": [{"id": "s", "kind": "shaft", "origin": [0,0,0], "axis": [0,0,1], "diameter": 3, "length": 1},
                  {"id": "f", "kind": "face", "origin": [0,0,0], "axis": [0,0,-1]}]}]})",
              "/parts/1/place", "cannot all hold");

  ExpectError(R"({"mechanist": 1, "parts": [
    {"id": "a", "mesh": "meshes/cube.obj", "place": {"insert": "a/s", "into": "b/s"},
     "features": [{"id": "s", "kind": "shaft", "origin": [0,0,0], "axis": [0,0,1], "diameter": 3, "length": 1}]},
    {"id": "b", "mesh": "meshes/cube.obj", "place": {"insert": "b/s", "into": "a/s"},
     "features": [{"id": "s", "kind": "shaft", "origin": [0,0,0], "axis": [0,0,1], "diameter": 3, "length": 1}]}]})",
              "/parts/0/place", "cycle");
  ExpectError(R"({"mechanist": 1, )" + parts.substr(0, parts.find("\"insert\": \"pin/s\"")) +
                  R"("insert": "plate/h", "into": "plate/h"}, "features": []}]})",
              "/parts/1/place/insert", "placed part");
}

TEST_F(AssemblyReaderTest, SyntaxErrorsNameLineAndColumn) {
  const InputError e = ExpectError("{\"mechanist\": 1,\n  \"parts\": [,]}", "", "invalid JSON");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 13);
  const InputError dup =
      ExpectError("{\"mechanist\": 1, \"mechanist\": 1}", "/mechanist", "duplicate key");
  EXPECT_EQ(dup.line(), 1);
  ExpectError("{\"mechanist\": 1 /* open", "", "unterminated");
  ExpectError("", "", "end of the file");
}

TEST_F(AssemblyReaderTest, UnknownKeysAreErrorsWithLine) {
  const InputError e = ExpectError(
      "{\"mechanist\": 1, \"parts\": [{\"id\": \"p\", \"mesh\": \"meshes/cube.obj\",\n"
      " \"features\": [{\"id\": \"s\", \"kind\": \"shaft\", \"origin\": [0,0,0], \"axis\": "
      "[0,0,1],\n"
      "   \"diamter\": 5, \"length\": 3}]}]}",
      "/parts/0/features/0/diamter", "unknown key \"diamter\"");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.column(), 15);
  ExpectError(R"({"mechanist": 1, "part": []})", "/part", "unknown key");
}

TEST_F(AssemblyReaderTest, RejectsBadValues) {
  ExpectError(R"({"parts": []})", "/", "format version");
  ExpectError(R"({"mechanist": 2, "parts": []})", "/mechanist", "version 1");
  ExpectError(R"({"mechanist": 1})", "/", "\"parts\"");
  ExpectError(OnePart("", R"("units": {"length": "furlong"},)"), "/units/length", "mm, cm, m, in");
  ExpectError(OnePart("", R"("friction": -1,)"), "/friction", ">= 0");
  ExpectError(OnePart("", R"("import": "x.step",)"), "/import",
              "cannot import \"x.step\": no such file");
  ExpectError(OnePart(R"("ground": "yes")"), "/parts/0/ground", "true or false");
  // Numbers far beyond any assembly (found by scripts/mutation_run.py: a quaternion or an axis
  // of 1e308 overflowed its normalisation, a plate 1e308 thick the broad phase).
  ExpectError(OnePart(R"("pose": {"quaternion": [1, 0, 1e308, 0]})"), "/parts/0/pose/quaternion/2",
              "magnitude at most 1e12");
  ExpectError(OnePart(R"("pose": {"rotation": {"axis": [-1e308, 0, 0], "angle": 90}})"),
              "/parts/0/pose/rotation/axis/0", "magnitude at most 1e12");
  ExpectError(R"({"mechanist": 1, "parts": [{"id": "p", "library": {"kind": "plate", "length": 80,
      "width": 70, "thickness": 1e308}}]})",
              "/parts/0/library/thickness", "magnitude at most 1e12");
  ExpectError(R"({"mechanist": 1, "parts": [{"id": "a b", "mesh": "meshes/cube.obj"}]})",
              "/parts/0/id", "letters, digits");
  ExpectError(R"({"mechanist": 1, "parts": [{"id": "p", "mesh": "meshes/cube.obj"},
                                              {"id": "p", "mesh": "meshes/cube.obj"}]})",
              "/parts/1/id", "duplicate part id");
  const std::string shaft = R"({"id": "s", "kind": "shaft", "origin": [0,0,0], "axis": [0,0,1], )";
  ExpectError(OnePart(R"("features": [)" + shaft + R"("diameter": -5, "length": 3}])"),
              "/parts/0/features/0/diameter", "positive length, found the number -5");
  ExpectError(OnePart(R"("features": [)" + shaft + R"("diameter": "5", "length": 3}])"),
              "/parts/0/features/0/diameter", "found the string \"5\"");
  ExpectError(OnePart(R"("features": [)" + shaft + R"("length": 3}])"), "/parts/0/features/0",
              "\"diameter\"");
  ExpectError(
      OnePart(
          R"("features": [{"id": "s", "kind": "shaft", "origin": [0,0,0], "axis": [0,0,0], "diameter": 1, "length": 1}])"),
      "/parts/0/features/0/axis", "non-zero direction");
  ExpectError(
      OnePart(R"("features": [{"id": "s", "kind": "spline", "origin": [0,0,0], "axis": [0,0,1]}])"),
      "/parts/0/features/0/kind", "worm_wheel");
  ExpectError(OnePart(R"("features": [)" + shaft + R"("diameter": 1, "length": 1}, )" + shaft +
                      R"("diameter": 1, "length": 1}])"),
              "/parts/0/features/1/id", "duplicate feature id");
  ExpectError(
      OnePart(
          R"("features": [{"id": "g", "kind": "gear", "origin": [0,0,0], "axis": [0,0,1], "teeth": 2.5, "module": 1, "length": 1}])"),
      "/parts/0/features/0/teeth", "positive whole number");
  ExpectError(
      OnePart(
          R"("features": [{"id": "k", "kind": "key", "origin": [0,0,0], "axis": [1,0,0], "width": 1, "length": 1, "normal": [1,0,0]}])"),
      "/parts/0/features/0/normal", "perpendicular");
  ExpectError(
      OnePart(
          R"("features": [{"id": "t", "kind": "thread", "origin": [0,0,0], "axis": [0,0,1], "diameter": 3, "pitch": 0.5, "length": 1, "hand": "up"}])"),
      "/parts/0/features/0/hand", "right, left");
}

TEST_F(AssemblyReaderTest, RejectsImproperPoses) {
  ExpectError(OnePart(R"("pose": {"matrix": [[-1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]})"),
              "/parts/0/pose/matrix", "determinant -1");
  ExpectError(OnePart(R"("pose": {"matrix": [[2,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]})"),
              "/parts/0/pose/matrix", "proper rotation");
  ExpectError(OnePart(R"("pose": {"matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,1,1]]})"),
              "/parts/0/pose/matrix/3", "last row");
  ExpectError(OnePart(R"("pose": {"quaternion": [0,0,0,0]})"), "/parts/0/pose/quaternion",
              "non-zero quaternion");
  ExpectError(OnePart(R"("pose": {"rotation": {"axis": [0,0,0], "angle": 3}})"),
              "/parts/0/pose/rotation/axis", "non-zero direction");
  ExpectError(OnePart(R"("pose": {"position": [0, 0]})"), "/parts/0/pose/position", "3 numbers");
  ExpectError(
      OnePart(R"("pose": {"rotation": {"axis": [0,0,1], "angle": 3}, "quaternion": [1,0,0,0]})"),
      "/parts/0/pose", "both");
}

TEST_F(AssemblyReaderTest, RejectsDanglingReferences) {
  const std::string part_a =
      R"({"mechanist": 1, "parts": [{"id": "a", "mesh": "meshes/cube.obj", "features": [
      {"id": "h", "kind": "hole", "origin": [0,0,0], "axis": [0,0,1], "diameter": 1, "length": 1}]},
      {"id": "b", "mesh": "meshes/cube.obj"}], )";
  ExpectError(part_a + R"("goals": [{"mesh": ["a/h", "worm/teeth"]}]})", "/goals/0/mesh/1",
              "no part \"worm\"");
  ExpectError(part_a + R"("goals": [{"mesh": ["a/h", "b/teeth"]}]})", "/goals/0/mesh/1",
              "has no feature \"teeth\"");
  ExpectError(part_a + R"("steps": [{"insert": "a/h", "into": "bh"}]})", "/steps/0/into",
              "\"part/feature\"");
  ExpectError(part_a + R"("drivers": [{"part": "c", "feature": "h"}]})", "/drivers/0/part",
              "no part \"c\"");
  ExpectError(part_a + R"("drivers": [{"part": "a", "feature": "x"}]})", "/drivers/0/feature",
              "found \"x\"");
  ExpectError(
      part_a +
          R"("adjustments": [{"id": "j", "moves": "b", "rotate_about": "a/h", "range": [5, 1]}]})",
      "/adjustments/0/range", "lower <= upper");
  ExpectError(part_a + R"("overrides": [{"pair": ["a/h", "a/h"], "type": "fixed"}]})",
              "/overrides/0/pair", "two different parts");
  ExpectError(part_a + R"("overrides": [{"pair": ["a/h"], "type": "glued"}]})", "/overrides/0/pair",
              "two features");
  ExpectError(part_a + R"("expect": [{"part": "a", "ratio": "1/0"}]})", "/expect/0/ratio",
              "denominator");
  ExpectError(part_a + R"("expect": [{"part": "a", "ratio": "fast"}]})", "/expect/0/ratio", "p/q");
  ExpectError(part_a + R"("expect": [{"same_subassembly": ["a", "z"]}]})",
              "/expect/0/same_subassembly/1", "no part \"z\"");
  ExpectError(part_a + R"("expect": [{"works": true}]})", "/expect/0", "expected an expectation");
}

TEST_F(AssemblyReaderTest, RejectsBadMeshesAndLibraryParameters) {
  ExpectError(R"({"mechanist": 1, "parts": [{"id": "p", "mesh": "meshes/missing.stl"}]})",
              "/parts/0/mesh", "missing.stl");
  std::ofstream(dir_ / "meshes" / "bad.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n";
  ExpectError(R"({"mechanist": 1, "parts": [{"id": "p", "mesh": "meshes/bad.obj"}]})",
              "/parts/0/mesh", "bad.obj");
  ExpectError(R"({"mechanist": 1, "parts": [{"id": "p", "library": {"kind": "sprocket"}}]})",
              "/parts/0/library/kind", "spur_gear");
  ExpectError(
      R"({"mechanist": 1, "parts": [{"id": "p", "library": {"kind": "shaft", "diameter": 3}}]})",
      "/parts/0/library", "\"length\"");
  ExpectError(
      R"({"mechanist": 1, "parts": [{"id": "p", "library": {"kind": "spur_gear", "teeth": 20, "module": 1, "face_width": 5, "bore_diameter": 40}}]})",
      "/parts/0/library", "bore_diameter");
  ExpectError(
      R"({"mechanist": 1, "parts": [{"id": "p", "library": {"kind": "shaft", "diameter": 3, "length": 5},
     "features": [{"id": "shaft", "kind": "face", "origin": [0,0,0], "axis": [0,0,1]}]}]})",
      "/parts/0/features/0/id", "library part defines it");
}

TEST_F(AssemblyReaderTest, ReadsFeaturesOnlyPartsAndHeldDrivers) {
  // Before: "expected \"mesh\" or \"library\", found neither" and "expected a non-zero rate".
  const Assembly a = Parse(R"({"mechanist": 1, "parts": [
      {"id": "frame", "ground": true, "features": [
        {"id": "h", "kind": "hole", "origin": [0,0,0], "axis": [0,0,1], "diameter": 4,
         "length": 5, "through": true}]},
      {"id": "pin", "features": [
        {"id": "s", "kind": "shaft", "origin": [0,0,0], "axis": [0,0,1], "diameter": 4,
         "length": 5, "retained": true}]},
      {"id": "p", "mesh": "meshes/cube.obj"}],
    "drivers": [{"id": "brake", "part": "pin", "feature": "s", "rate": 0}]})");
  ASSERT_EQ(a.parts().size(), 3u);
  EXPECT_FALSE(a.part(0).HasGeometry());
  EXPECT_FALSE(a.part(1).HasGeometry());
  EXPECT_TRUE(a.part(2).HasGeometry());
  EXPECT_TRUE(a.part(0).mesh_source.empty());
  EXPECT_TRUE(a.part(0).mesh != nullptr && a.part(0).mesh->faces.empty());
  EXPECT_TRUE(a.MeshBox(0).empty());
  ASSERT_EQ(a.drivers().size(), 1u);
  EXPECT_EQ(a.drivers()[0].rate, 0.0);
  // `compliant` (a spring, belt or hose) is read, and must be true or false.
  EXPECT_TRUE(Parse(OnePart(R"("compliant": true)")).part(0).compliant);
  EXPECT_FALSE(Parse(OnePart("")).part(0).compliant);
  ExpectError(OnePart(R"("compliant": "yes")"), "/parts/0/compliant", "true or false");
  // A gear's helix angle (spec: `helix_angle`, in the file's angle unit), below 90 degrees.
  const std::string gear =
      R"("features": [{"id": "g", "kind": "gear", "origin": [0,0,0], "axis": [0,0,1], )"
      R"("teeth": 20, "module": 2, "length": 10, "helix_angle": )";
  EXPECT_NEAR(Parse(OnePart(gear + "-15}]")).part(0).features[0].helix_angle, -15 * kPi / 180,
              1e-12);
  ExpectError(OnePart(gear + "95}]"), "/parts/0/features/0/helix_angle", "between -90 and 90");
}

TEST_F(AssemblyReaderTest, ReadsBevelGears) {
  // spec: `bevel_gear` with its apex as origin; angles in the file's unit, lengths in its unit.
  const std::string bevel =
      R"("features": [{"id": "b", "kind": "bevel_gear", "origin": [0,0,0], "axis": [0,0,1], )"
      R"("teeth": 20, "module": 2, "length": 8, "pitch_angle": )";
  const Feature f = Parse(OnePart(bevel + R"(30, "spiral_angle": -35}])")).part(0).features[0];
  EXPECT_EQ(f.kind, FeatureKind::kBevelGear);
  EXPECT_EQ(f.teeth, 20);
  EXPECT_NEAR(f.pitch_angle, kPi / 6, 1e-12);
  EXPECT_NEAR(f.spiral_angle, -35 * kPi / 180, 1e-12);
  EXPECT_NEAR(f.OuterConeDistance(), 40.0, 1e-12);  // 2 x 20 / (2 sin 30 deg)
  const Feature inches =
      Parse(OnePart(bevel + "30}]", R"("units": {"length": "in"}, )")).part(0).features[0];
  EXPECT_NEAR(inches.module, 50.8, 1e-12);
  EXPECT_EQ(Parse(OnePart(bevel + "90}]")).part(0).features[0].spiral_angle, 0.0);  // a crown gear
  ExpectError(OnePart(bevel + "0}]"), "/parts/0/features/0/pitch_angle", "above 0 and at most 90");
  ExpectError(OnePart(bevel + "120}]"), "/parts/0/features/0/pitch_angle", "found the number 120");
  ExpectError(OnePart(bevel + R"(30, "spiral_angle": 90}])"), "/parts/0/features/0/spiral_angle",
              "between -90 and 90");
  // Teeth longer than the cone: 40 mm from apex to rim, face width 45.
  const std::string long_teeth =
      R"("features": [{"id": "b", "kind": "bevel_gear", "origin": [0,0,0], "axis": [0,0,1], )"
      R"("teeth": 20, "module": 2, "length": 45, "pitch_angle": 30}])";
  ExpectError(OnePart(long_teeth), "/parts/0/features/0/length", "outer cone distance 40");
  ExpectError(OnePart(R"("features": [{"id": "b", "kind": "bevel_gear", "origin": [0,0,0], )"
                      R"("axis": [0,0,1], "teeth": 20, "module": 2, "length": 8}])"),
              "/parts/0/features/0", "pitch_angle");
}

TEST_F(AssemblyReaderTest, NeverModifiesItsInput) {
  const std::filesystem::path file = dir_ / "in.json";
  const std::string text = OnePart("");
  std::ofstream(file) << text;
  const auto before = std::filesystem::last_write_time(file);
  LoadAssembly(file);
  std::ifstream in(file);
  const std::string after((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(after, text);
  EXPECT_EQ(std::filesystem::last_write_time(file), before);
  EXPECT_THROW(LoadAssembly(dir_ / "nothing.json"), InputError);
  EXPECT_THROW(LoadAssembly(dir_), InputError);
}

}  // namespace
}  // namespace mechanist
