// The load pipeline (io/load_assembly.h): read, recognise what the file does not write, read
// the relations against those features, place, infer fasteners, adjust; each step's findings.

#include "io/load_assembly.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/assembly_reader.h"
#include "io/input_error.h"
#include "io/occt/step_fixtures.h"
#include "io/stl_writer.h"
#include "kernel/features/part_library.h"
#include "reasoning/analysis.h"
#include "spring_mesh.h"

namespace mechanist {
namespace {

const std::filesystem::path kAs1 =
    std::filesystem::path(MECHANIST_SHARED_DATA) / "step" / "as1_pe_203.stp";

std::vector<std::string> Codes(const Assembly& a) {
  std::vector<std::string> codes;
  for (const Diagnostic& d : a.findings()) codes.push_back(d.code);
  return codes;
}

int CountCode(const Assembly& a, const std::string& code) {
  int n = 0;
  for (const Diagnostic& d : a.findings()) n += d.code == code;
  return n;
}

class LoadAssemblyTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // One folder per test: ctest runs them in parallel processes.
    dir_ = std::filesystem::temp_directory_path() /
           (std::string("mechanist_load_assembly_") +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
    HexBoltSpec bolt;
    bolt.diameter = 6;
    bolt.length = 20;
    HexNutSpec nut;
    nut.diameter = 6;
    std::ofstream(dir_ / "bolt.stl", std::ios::binary) << BinaryStl(MakeLibraryPart(bolt).mesh);
    std::ofstream(dir_ / "nut.stl", std::ios::binary) << BinaryStl(MakeLibraryPart(nut).mesh);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path dir_;
};

TEST_F(LoadAssemblyTest, RelationsNameRecognisedFeaturesAndNutsAreFoundWherePlaced) {
  // The nut has no pose: it is placed by its recognised hole on the bolt's recognised shaft,
  // and only then, at its place, found to be a nut on the bolt.
  const std::string text = R"({"mechanist": 1, "parts": [
    {"id": "bolt", "mesh": "bolt.stl", "ground": true},
    {"id": "nut", "mesh": "nut.stl",
     "place": {"insert": "nut/hole", "into": "bolt/shaft", "depth": 10}}]})";
  const Assembly a = LoadAssemblyText(text, dir_ / "a.json");
  EXPECT_EQ(Codes(a), (std::vector<std::string>{"features_recognised", "nut_on_bolt"}));
  const Part& nut = a.part(*a.FindPart("nut"));
  EXPECT_GT(nut.X_WP.translation().norm(), 1.0) << "moved onto the bolt";
  EXPECT_EQ(nut.features[*nut.FindFeature("hole")].kind, FeatureKind::kTappedHole);
}

TEST_F(LoadAssemblyTest, AReferenceToAFeatureNeitherWrittenNorRecognisedIsAnErrorAtItsPointer) {
  const std::string text = R"({"mechanist": 1, "parts": [
    {"id": "bolt", "mesh": "bolt.stl", "ground": true}],
    "drivers": [{"part": "bolt", "feature": "shaft_9", "rate": 1}]})";
  try {
    LoadAssemblyText(text, dir_ / "b.json");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.pointer(), "/drivers/0/feature");
    EXPECT_NE(e.detail().find("found \"shaft_9\""), std::string::npos) << e.detail();
  }
}

TEST_F(LoadAssemblyTest, AFasteningTheFileSetsIsNeverReinterpreted) {
  const Assembly as1 = LoadAssembly(kAs1);
  EXPECT_EQ(CountCode(as1, "nut_on_bolt"), 8);
  // The file makes one bolt's shank loose: it stays a loose shank, and its nut is no nut.
  const std::string bolt = "AS1_PE_ASM.L_BRACKET_ASSEMBLY.NUT_BOLT_ASSEMBLY.BOLT";
  const Assembly loose = LoadAssemblyText(
      R"({"mechanist": 1, "import": ")" + kAs1.string() + R"(", "parts": [{"id": ")" + bolt +
          R"(", "features": [{"id": "shaft_1", "fastening": "loose"}]}]})",
      dir_ / "c.json");
  const Part& b = loose.part(*loose.FindPart(bolt));
  const Feature& shank = b.features[*b.FindFeature("shaft_1")];
  EXPECT_EQ(shank.kind, FeatureKind::kShaft);
  EXPECT_EQ(shank.fastening, Fastening::kLoose);
  EXPECT_EQ(CountCode(loose, "nut_on_bolt"), 7);
}

TEST_F(LoadAssemblyTest, GearsOnAStepSolidsTessellationGoAfterItsExactFeatures) {
  testing::WriteSpurGearPairStep(dir_ / "pair.step", 10, 27, 1.5);
  // Imported: each solid gets its teeth after its faces and bore.
  const Assembly imported = LoadAssembly(dir_ / "pair.step");
  EXPECT_EQ(Codes(imported), (std::vector<std::string>{"tessellation_gears", "implied_frame"}));
  ASSERT_EQ(imported.parts().size(), 3u);
  for (const Part& p : imported.parts()) {
    if (!p.HasGeometry()) continue;  // the frame implied for the gears
    std::vector<std::string> ids;
    for (const Feature& f : p.features) ids.push_back(f.id);
    EXPECT_EQ(ids, (std::vector<std::string>{"face_1", "face_2", "hole_1", "teeth"})) << p.id;
    EXPECT_EQ(p.features.back().kind, FeatureKind::kGear) << p.id;
  }
  // One part whose mesh is the file: each solid's teeth after its own features, prefixed.
  const Assembly whole = LoadAssemblyText(
      R"({"mechanist": 1, "parts": [{"id": "pair", "mesh": "pair.step"}]})", dir_ / "d.json");
  const Part& pair = whole.part(0);
  std::vector<std::string> ids;
  for (const Feature& f : pair.features) ids.push_back(f.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"solid1_face_1", "solid1_face_2", "solid1_hole_1",
                                           "solid1_teeth", "solid2_face_1", "solid2_face_2",
                                           "solid2_hole_1", "solid2_teeth"}));
  ASSERT_EQ(pair.notes.empty(), false);
  EXPECT_EQ(pair.notes.back().rfind("solid2: teeth: ", 0), 0u) << pair.notes.back();
}

TEST_F(LoadAssemblyTest, AdjustingIsTheLastStepAndOnlyWhenAsked) {
  const std::filesystem::path file =
      std::filesystem::path(MECHANIST_SOURCE_DIR) / "examples/robot_hand_worm_adjust/assembly.json";
  const Assembly as_written = LoadAssembly(file);
  AdjustmentSummary summary;
  const Assembly adjusted = LoadAssembly(file, {.adjust = true, .adjustments = &summary});
  ASSERT_EQ(summary.adjustments.size(), 1u);
  EXPECT_NEAR(summary.adjustments[0].value, -3.0 * 3.14159265358979 / 180, 1e-6);
  EXPECT_TRUE(summary.all_met);
  // The motor swings; as written, it stays where the file puts it.
  const std::size_t motor = *adjusted.FindPart("motor_body");
  EXPECT_GT(
      (adjusted.part(motor).X_WP.translation() - as_written.part(motor).X_WP.translation()).norm(),
      0.1);
}

TEST_F(LoadAssemblyTest, AHelicalSpringMeshIsCompliantAndAddsNoFreedom) {
  // A coil of 12 mm, wire 1.5 mm, 7 turns of pitch 4, between a frame's seat and a plunger
  // whose rod slides in the frame's bore: recognised from its mesh alone, it is compliant, so
  // the plunger keeps the two freedoms of its rod and the spring adds none.
  std::ofstream(dir_ / "spring.stl", std::ios::binary)
      << BinaryStl(testing::SpringMesh(6, 1.5, 4, 7));
  const std::string frame_and_plunger = R"(
    {"id": "frame", "ground": true, "features": [
      {"id": "bore", "kind": "hole", "origin": [0, 0, 0], "axis": [0, 0, 1], "diameter": 4,
       "length": 10, "through": true}]},
    {"id": "plunger", "pose": {"position": [0, 0, 30]}, "features": [
      {"id": "rod", "kind": "shaft", "origin": [0, 0, 0], "axis": [0, 0, -1], "diameter": 4,
       "length": 35}]})";
  const Assembly with = LoadAssemblyText(R"({"mechanist": 1, "parts": [)" + frame_and_plunger +
                                             R"(, {"id": "spring", "mesh": "spring.stl"}]})",
                                         dir_ / "a.json");
  const Part& spring = with.part(*with.FindPart("spring"));
  EXPECT_TRUE(spring.compliant);
  const auto found =
      std::find_if(with.findings().begin(), with.findings().end(),
                   [](const Diagnostic& d) { return d.code == "spring_recognised"; });
  ASSERT_NE(found, with.findings().end());
  EXPECT_EQ(found->parts, std::vector<std::string>{"spring"});
  // Measured on the mesh (its wire a 12-gon): the coil and pitch to 4 digits, 7 turns within
  // a hundredth.
  EXPECT_NE(found->message.find("coil 12 mm, wire 1.529 mm, 6.99 turns of pitch 4 mm, right "
                                "hand"),
            std::string::npos)
      << found->message;
  const Assembly without = LoadAssemblyText(
      R"({"mechanist": 1, "parts": [)" + frame_and_plunger + "]}", dir_ / "b.json");
  EXPECT_EQ(Analyze(with).motion.mobility.dof, 2);
  EXPECT_EQ(Analyze(without).motion.mobility.dof, 2);
}

}  // namespace
}  // namespace mechanist
