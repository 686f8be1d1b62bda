// STEP import of the AS1 assembly (../shared/data/step, written by Pro/ENGINEER, nobody here):
// its product structure, its bolts and nuts, and the conclusion that it is one rigid, bolted
// assembly.

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include "cycloid_outline.h"
#include "io/feature_report.h"
#include "io/info_report.h"
#include "io/input_error.h"
#include "io/load_assembly.h"
#include "io/occt/step_fixtures.h"
#include "io/step_reader.h"
#include "kernel/features/part_library.h"
#include "kernel/mesh/mesh_builder.h"
#include "kernel/mesh/mesh_check.h"
#include "kernel/support/number_format.h"
#include "reasoning/analysis.h"

namespace mechanist {
namespace {

const std::filesystem::path kAs1 =
    std::filesystem::path(MECHANIST_SHARED_DATA) / "step" / "as1_pe_203.stp";

int Count(const Assembly& a, const std::string& product) {
  int n = 0;
  for (const Part& p : a.parts()) {
    const std::string last = p.id.substr(p.id.rfind('.') + 1);
    n += last.rfind(product, 0) == 0;
  }
  return n;
}

TEST(StepImport, As1KeepsItsProductStructureAndSharesItsProducts) {
  const Assembly a = LoadAssembly(kAs1);
  ASSERT_EQ(a.parts().size(), 18u);
  EXPECT_EQ(Count(a, "BOLT"), 6);
  EXPECT_EQ(Count(a, "NUT"), 8);
  EXPECT_EQ(Count(a, "L-BRACKET"), 2);
  ASSERT_TRUE(a.FindPart("AS1_PE_ASM.PLATE").has_value());
  ASSERT_TRUE(a.FindPart("AS1_PE_ASM.ROD.ROD").has_value());
  ASSERT_TRUE(a.FindPart("AS1_PE_ASM.L_BRACKET_ASSEMBLY_2.NUT_BOLT_ASSEMBLY_3.BOLT").has_value());
  // Instances of one product share one mesh; every mesh is closed (faces welded).
  std::set<const TriangleMesh*> meshes;
  for (const Part& p : a.parts()) meshes.insert(p.mesh.get());
  EXPECT_EQ(meshes.size(), 5u);  // plate, bracket, bolt, nut, rod
  for (const TriangleMesh* mesh : meshes) {
    const MeshCheck check = CheckMesh(*mesh);
    EXPECT_TRUE(check.closed() && check.consistently_oriented());
    EXPECT_GT(check.signed_volume, 0.0);
  }
  // The plate's six bolt holes, the bolts' shanks through them.
  const Part& plate = a.part(*a.FindPart("AS1_PE_ASM.PLATE"));
  int holes = 0;
  for (const Feature& f : plate.features) holes += f.kind == FeatureKind::kHole;
  EXPECT_EQ(holes, 6);
}

// The reading's progress: one call at a time, never decreasing, a step after each of AS1's 5
// products (meshed once for all their instances), 1 at the end; the same through LoadAssembly,
// which names the file.
TEST(StepImport, ProgressFollowsTheReadingToItsEnd) {
  std::vector<double> fractions;
  std::atomic<int> inside{0};
  bool overlapped = false;
  const std::vector<StepSolid> solids = ReadStep(kAs1, nullptr, [&](double fraction) {
    overlapped = overlapped || inside++ > 0;
    fractions.push_back(fraction);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));  // time for another call to come
    --inside;
  });
  ASSERT_EQ(solids.size(), 18u);
  EXPECT_FALSE(overlapped);
  ASSERT_FALSE(fractions.empty());
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()))
      << ::testing::PrintToString(fractions);
  EXPECT_GT(fractions.front(), 0.0);
  EXPECT_EQ(fractions.back(), 1.0);
  const auto under_way = std::count_if(fractions.begin(), fractions.end(),
                                       [&](double f) { return f > fractions.front() && f < 1; });
  EXPECT_GE(under_way, 4) << ::testing::PrintToString(fractions);

  std::set<std::filesystem::path> named;
  double last = 0;
  LoadAssembly(kAs1, {.reading = [&](const std::filesystem::path& file, double fraction) {
                 named.insert(file);
                 last = fraction;
               }});
  ASSERT_EQ(named.size(), 1u);
  EXPECT_TRUE(std::filesystem::equivalent(*named.begin(), kAs1));
  EXPECT_EQ(last, 1.0);
}

// A file that parses but gives no shape: the progress stops short of the end.
TEST(StepImport, ProgressStopsShortWhenTheReadingFails) {
  std::vector<double> fractions;
  EXPECT_THROW(
      ReadStep(std::filesystem::path(MECHANIST_SOURCE_DIR) / "tests/data/bad/step_no_solid.step",
               nullptr, [&](double fraction) { fractions.push_back(fraction); }),
      std::runtime_error);
  ASSERT_FALSE(fractions.empty());  // parsed
  EXPECT_LT(fractions.back(), 1.0);
}

TEST(StepImport, As1IsOneRigidBoltedAssembly) {
  const Assembly a = LoadAssembly(kAs1);
  // Every nut is found on its bolt or on the rod, and their cylinders become tight threads.
  int nuts = 0;
  for (const Diagnostic& d : a.findings()) nuts += d.code == "nut_on_bolt";
  EXPECT_EQ(nuts, 8);
  for (const Part& p : a.parts()) {
    if (p.id.find("BOLT") == std::string::npos || p.id.find(".BOLT") == std::string::npos) continue;
    int threads = 0;
    for (const Feature& f : p.features) threads += f.kind == FeatureKind::kThread;
    EXPECT_EQ(threads, 1) << p.id;
  }
  const Analysis an = Analyze(a);
  ASSERT_EQ(an.subassemblies.size(), 1u);
  EXPECT_EQ(an.subassemblies[0].parts.size(), 18u);
  int fixed = 0, clamps = 0;
  for (const Pair& p : an.pairs) {
    fixed += p.type == PairType::kFixed;
    clamps += p.source == PairSource::kClamp;
  }
  EXPECT_EQ(fixed - clamps, 8);  // each nut on its thread
  EXPECT_GE(clamps, 14);         // plate and bracket by each bolt, brackets by the rod
}

TEST(StepImport, AnImportingFileAddsGroundAndNamesBadImports) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_step";
  std::filesystem::create_directories(dir);
  const std::string grounded = R"({"mechanist": 1, "import": ")" + kAs1.string() +
                               R"(", "parts": [{"id": "AS1_PE_ASM.PLATE", "ground": true}]})";
  const Analysis an = Analyze(LoadAssemblyText(grounded, dir / "a.json"));
  EXPECT_EQ(an.motion.mobility.dof, 0);
  EXPECT_TRUE(an.subassemblies[0].ground);
  // A feature's fastening set by name.
  const std::string bolt = "AS1_PE_ASM.L_BRACKET_ASSEMBLY.NUT_BOLT_ASSEMBLY.BOLT";
  const Assembly loose = LoadAssemblyText(
      R"({"mechanist": 1, "import": ")" + kAs1.string() + R"(", "parts": [{"id": ")" + bolt +
          R"(", "features": [{"id": "shaft_1", "fastening": "loose"}]}]})",
      dir / "d.json");
  const Part& b = loose.part(*loose.FindPart(bolt));
  EXPECT_EQ(b.features[*b.FindFeature("shaft_1")].fastening, Fastening::kLoose);
  // A part whose mesh is the STEP file: one rigid body with every solid's features.
  const Assembly whole = LoadAssemblyText(
      R"({"mechanist": 1, "parts": [{"id": "as1", "mesh": ")" + kAs1.string() + R"("}]})",
      dir / "e.json");
  ASSERT_EQ(whole.parts().size(), 1u);
  EXPECT_TRUE(whole.part(0).FindFeature("solid1_hole_1").has_value());
  EXPECT_GT(whole.part(0).features.size(), 100u);
  try {
    LoadAssemblyText(R"({"mechanist": 1, "import": "missing.stp"})", dir / "b.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.pointer(), "/import");
  }
  // A new id adds a part (with a pose, not a place).
  const Assembly more = LoadAssemblyText(
      R"({"mechanist": 1, "import": ")" + kAs1.string() +
          R"(", "parts": [{"id": "base", "ground": true, "pose": {"position": [0, -600, 0]},
            "library": {"kind": "plate", "length": 100, "width": 100, "thickness": 5}}]})",
      dir / "c.json");
  EXPECT_EQ(more.parts().size(), 19u);
  EXPECT_TRUE(more.part(*more.FindPart("base")).ground);
  // A new part placed by its features onto an imported one: a pin of the plate hole's
  // diameter inserted 3 mm into it lies on the hole's axis and turns in it.
  const Assembly as1 =
      LoadAssemblyText(R"({"mechanist": 1, "import": ")" + kAs1.string() + R"("})", dir / "f.json");
  const FeatureRef hole = *as1.FindFeature("AS1_PE_ASM.PLATE/hole_1");
  const Feature& h = as1.feature(hole);
  const AxisSegment hole_W = h.WorldAxis(as1.part(hole.part).X_WP);
  const Assembly pinned = LoadAssemblyText(
      R"({"mechanist": 1, "import": ")" + kAs1.string() +
          R"(", "parts": [{"id": "pin", "library": {"kind": "shaft", "diameter": )" +
          std::to_string(h.diameter) + R"(, "length": 40},
            "place": {"insert": "pin/shaft", "into": "AS1_PE_ASM.PLATE/hole_1", "depth": 3}}]})",
      dir / "g.json");
  const Part& pin = pinned.part(*pinned.FindPart("pin"));
  const AxisSegment pin_W = pin.features[0].WorldAxis(pin.X_WP);
  EXPECT_NEAR(std::abs(pin_W.direction.dot(hole_W.direction)), 1.0, 1e-9);
  const Eigen::Vector3d d = pin_W.origin - hole_W.origin;
  EXPECT_LT((d - d.dot(hole_W.direction) * hole_W.direction).norm(), 1e-6);
  const Analysis with_pin = Analyze(pinned);
  bool turns = false;
  for (const Pair& p : with_pin.pairs) {
    turns |= (p.a.part == *pinned.FindPart("pin") || p.b.part == *pinned.FindPart("pin")) &&
             (p.type == PairType::kCylindrical || p.type == PairType::kRevolute);
  }
  EXPECT_TRUE(turns);
  // Its errors name the entry's place.
  try {
    LoadAssemblyText(R"({"mechanist": 1, "import": ")" + kAs1.string() +
                         R"(", "parts": [{"id": "pin", "library": {"kind": "shaft", "diameter": 5,
                      "length": 20}, "place": {"insert": "pin/shaft",
                      "into": "AS1_PE_ASM.PLATE/no_such_hole"}}]})",
                     dir / "c.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.pointer(), "/parts/0/place/into");
  }
}

TEST(StepImport, AFeatureAddedToAnImportedPartIsInItsOwnFrameWhichInfoPrints) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_step";
  std::filesystem::create_directories(dir);
  const std::string bolt = "AS1_PE_ASM.L_BRACKET_ASSEMBLY.NUT_BOLT_ASSEMBLY.BOLT";
  const Assembly as1 =
      LoadAssemblyText(R"({"mechanist": 1, "import": ")" + kAs1.string() + R"("})", dir / "h.json");
  const RigidTransform X_WB = as1.part(*as1.FindPart(bolt)).X_WP;
  ASSERT_FALSE(X_WB.rotation().isIdentity(1e-6));  // a placement that turns the bolt
  // A hole wanted at p_W along d_W in the world, written in the bolt's frame as the README
  // says: R^T (p_W - position).
  const Eigen::Vector3d p_W(10, 20, 30), d_W = Eigen::Vector3d(1, 2, 2) / 3;
  const Eigen::Vector3d p_B = X_WB.rotation().transpose() * (p_W - X_WB.translation());
  const Eigen::Vector3d d_B = X_WB.rotation().transpose() * d_W;
  const Assembly marked = LoadAssemblyText(
      fmt::format(R"({{"mechanist": 1, "import": "{}", "parts": [{{"id": "{}", "features": [
          {{"id": "marker", "kind": "hole", "origin": [{:.17g}, {:.17g}, {:.17g}],
            "axis": [{:.17g}, {:.17g}, {:.17g}], "diameter": 3, "length": 2}}]}}]}})",
                  kAs1.string(), bolt, p_B.x(), p_B.y(), p_B.z(), d_B.x(), d_B.y(), d_B.z()),
      dir / "i.json");
  const FeatureRef marker = *marked.FindFeature(bolt + "/marker");
  const AxisSegment marker_W = marked.feature(marker).WorldAxis(marked.part(marker.part).X_WP);
  EXPECT_LT((marker_W.origin - p_W).norm(), 1e-9);
  EXPECT_LT((marker_W.direction - d_W).norm(), 1e-9);
  std::ostringstream info;
  WriteInfo(marked, info);
  const Eigen::AngleAxisd turn(X_WB.rotation());
  const std::string pose = fmt::format(
      ", pose: position ({}, {}, {}) mm, rotation {} deg about",
      FormatNumber(X_WB.translation().x()), FormatNumber(X_WB.translation().y()),
      FormatNumber(X_WB.translation().z()), FormatNumber(turn.angle() * 180 / std::numbers::pi));
  EXPECT_NE(info.str().find(pose), std::string::npos) << info.str();
  EXPECT_NE(info.str().find("marker: hole at (10, 20, 30) axis (0.333333, 0.666667, 0.666667)"),
            std::string::npos)
      << info.str();
}

TEST(StepImport, OpenCascadesMessagesBecomeFindingsNeverOutput) {
  // AS1 with a product category that refers to an entity the file does not have: Open
  // CASCADE's reader complains ("Unresolved Reference") and reads the rest.
  std::ifstream in(kAs1, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  std::string step = text.str();
  const std::string relationship = "#2878=PRODUCT_CATEGORY_RELATIONSHIP('','',#2876,#2877);";
  const auto at = step.find(relationship);
  ASSERT_NE(at, std::string::npos);
  step.replace(at, relationship.size(),
               "#2878=PRODUCT_CATEGORY_RELATIONSHIP('','',#999998,#2877);");
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "mechanist_step_messages";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "dangling.stp", std::ios::binary) << step;
  ::testing::internal::CaptureStdout();
  const Assembly a = LoadAssembly(dir / "dangling.stp");
  const std::string printed = ::testing::internal::GetCapturedStdout();
  EXPECT_EQ(printed, "");
  EXPECT_EQ(a.parts().size(), 18u);
  // The reader's two reports (the reference, and the count of such) are one warning.
  std::vector<std::string> messages;
  for (const Diagnostic& d : a.findings()) {
    if (d.code != "step_reader") continue;
    EXPECT_EQ(d.severity, Severity::kWarning);
    messages.push_back(d.message);
  }
  EXPECT_EQ(messages,
            std::vector<std::string>{
                "dangling.stp: 1 reference to entities the file does not define (#2878 "
                "PRODUCT_CATEGORY_RELATIONSHIP refers to #999998): it is damaged or cut short, "
                "and what uses them is missing from the parts read"});
  // The file read as it is gives no such finding.
  const Assembly intact = LoadAssembly(kAs1);
  for (const Diagnostic& d : intact.findings()) EXPECT_NE(d.code, "step_reader");
  std::filesystem::remove_all(dir);
}

// The gear features of an imported assembly's parts, by part id, and its gear pairs.
struct Gears {
  std::map<std::string, const Feature*> of_part;
  std::vector<const Pair*> pairs;
  Gears(const Assembly& a, const Analysis& an) {
    for (const Part& p : a.parts()) {
      for (const Feature& f : p.features) {
        if (f.kind == FeatureKind::kGear) {
          EXPECT_FALSE(of_part.count(p.id)) << "two gears on " << p.id;
          of_part[p.id] = &f;
        }
      }
    }
    for (const Pair& pair : an.pairs) {
      if (pair.type == PairType::kGear) pairs.push_back(&pair);
    }
  }
};

// The first feature of `kind` on `part`, or null.
const Feature* FeatureOfKind(const Part& part, FeatureKind kind) {
  for (const Feature& f : part.features) {
    if (f.kind == kind) return &f;
  }
  return nullptr;
}

// The pairs of `type` in `an`.
std::vector<const Pair*> PairsOfType(const Analysis& an, PairType type) {
  std::vector<const Pair*> found;
  for (const Pair& p : an.pairs) {
    if (p.type == type) found.push_back(&p);
  }
  return found;
}

// The pairs of an analysis as "type a b" with the features' names, sorted.
std::vector<std::string> PairNames(const Assembly& a, const Analysis& an) {
  std::vector<std::string> names;
  for (const Pair& p : an.pairs) {
    names.push_back(std::string(ToString(p.type)) + " " + a.FeatureName(p.a) + " " +
                    a.FeatureName(p.b));
  }
  std::sort(names.begin(), names.end());
  return names;
}

TEST(StepImport, As1WithEverySurfaceABSplineGivesTheSamePairs) {
  // Some exporters and healing steps write every surface as a B-spline: its planes and
  // cylinders must still give faces, shafts and holes, and the same rigid, bolted assembly.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_nurbs";
  std::filesystem::create_directories(dir);
  testing::WriteNurbsCopy(kAs1, dir / "as1_nurbs.stp");
  const Assembly original = LoadAssembly(kAs1);
  const Assembly nurbs = LoadAssembly(dir / "as1_nurbs.stp");
  ASSERT_EQ(nurbs.parts().size(), original.parts().size());
  for (std::size_t p = 0; p < nurbs.parts().size(); ++p) {
    EXPECT_EQ(nurbs.part(p).id, original.part(p).id);
    EXPECT_EQ(nurbs.part(p).features.size(), original.part(p).features.size()) << nurbs.part(p).id;
    bool converted = false;
    for (const std::string& n : nurbs.part(p).notes) {
      converted = converted || n.find("taken as exact surfaces") != std::string::npos;
    }
    EXPECT_TRUE(converted) << nurbs.part(p).id;
  }
  const Analysis an_original = Analyze(original), an_nurbs = Analyze(nurbs);
  EXPECT_EQ(PairNames(nurbs, an_nurbs), PairNames(original, an_original));
  EXPECT_EQ(an_nurbs.subassemblies.size(), 1u);
  std::filesystem::remove_all(dir);
}

// The pairs of an analysis without the parts' names: each part by the centre of its mesh in
// the world (to 0.01 mm), each feature by its id within its solid.
std::vector<std::string> PairsUpToNames(const Assembly& a, const Analysis& an) {
  auto part = [&](std::size_t p) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    const TriangleMesh& mesh = *a.part(p).mesh;
    for (const Eigen::Vector3d& v : mesh.vertices) centre += v / mesh.vertices.size();
    const Eigen::Vector3d c = a.part(p).X_WP * centre;
    return fmt::format("({:.2f}, {:.2f}, {:.2f})", c.x() + 0.0, c.y() + 0.0, c.z() + 0.0);
  };
  std::vector<std::string> names;
  for (const Pair& p : an.pairs) {
    std::array<std::string, 2> ends = {part(p.a.part) + "/" + a.feature(p.a).id,
                                       part(p.b.part) + "/" + a.feature(p.b).id};
    std::sort(ends.begin(), ends.end());
    names.push_back(
        fmt::format("{} {} {} {}", ToString(p.type), ToString(p.source), ends[0], ends[1]));
  }
  std::sort(names.begin(), names.end());
  return names;
}

// The parts' ids, in order.
std::vector<std::string> PartIds(const Assembly& a) {
  std::vector<std::string> ids;
  for (const Part& part : a.parts()) ids.push_back(part.id);
  return ids;
}

TEST(StepImport, TheLengthUnitsAFileDeclaresAreNamed) {
  const std::filesystem::path real = std::filesystem::path(MECHANIST_SHARED_DATA) / "real";
  for (const auto& [file, unit] :
       {std::pair{kAs1, "inch"},
        std::pair{real / "revolute_pin_solidedge_chrono/assembly.stp", "metre"},
        std::pair{real / "hinge_clamshell_build123d/clamshell_full.step", "millimetre"}}) {
    std::vector<std::string> units;
    ReadStep(file, nullptr, {}, &units);
    EXPECT_EQ(units, std::vector<std::string>{unit}) << file;
  }
  // Some solids' representations in inches, the rest in millimetres: both.
  const std::filesystem::path mixed =
      std::filesystem::temp_directory_path() / "mechanist_mixed_units.stp";
  testing::WriteStepVariant(kAs1, mixed, testing::StepVariant::kMixedUnits);
  std::vector<std::string> units;
  ReadStep(mixed, nullptr, {}, &units);
  std::filesystem::remove(mixed);
  std::sort(units.begin(), units.end());
  EXPECT_EQ(units, (std::vector<std::string>{"inch", "millimetre"}));
}

TEST(StepImport, As1InInchesFlatNestedInPartFilesOrMixedUnitsGivesTheSamePairsUpToNames) {
  // The same product as other exporters write it: lengths in inches, a flat compound of
  // unnamed solids, the assembly inside three more levels of unnamed assemblies, one file per
  // part beside the assembly's, some parts in inches and the rest in millimetres, one file
  // in which some solids' representations declare inches and the rest millimetres, or the
  // schemas of older and newer exporters (AP203, AP242).
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_variants";
  std::filesystem::create_directories(dir);
  const Assembly original = LoadAssembly(kAs1);
  const Analysis an_original = Analyze(original);
  const std::vector<std::string> expected = PairsUpToNames(original, an_original);
  ASSERT_GT(expected.size(), 20u);
  for (const auto& [variant, name] : {std::pair{testing::StepVariant::kInches, "inches"},
                                      std::pair{testing::StepVariant::kFlat, "flat"},
                                      std::pair{testing::StepVariant::kNested, "nested"},
                                      std::pair{testing::StepVariant::kPartFiles, "parts"},
                                      std::pair{testing::StepVariant::kMixedUnits, "mixed"},
                                      std::pair{testing::StepVariant::kAp203, "ap203"},
                                      std::pair{testing::StepVariant::kAp242, "ap242"}}) {
    SCOPED_TRACE(name);
    const std::filesystem::path file = dir / (std::string(name) + ".stp");
    const std::vector<std::string> part_files = testing::WriteStepVariant(kAs1, file, variant);
    if (variant == testing::StepVariant::kMixedUnits) {
      std::ifstream in(file);
      const std::string text((std::istreambuf_iterator<char>(in)), {});
      EXPECT_NE(text.find("CONVERSION_BASED_UNIT('INCH'"), std::string::npos);
    }
    if (variant == testing::StepVariant::kAp203 || variant == testing::StepVariant::kAp242) {
      std::ifstream in(file);
      const std::string text((std::istreambuf_iterator<char>(in)), {});
      EXPECT_NE(text.find(variant == testing::StepVariant::kAp203
                              ? "FILE_SCHEMA(('CONFIG_CONTROL_DESIGN'"
                              : "'AP242_MANAGED_MODEL_BASED_3D_ENGINEERING_MIM_LF"),
                std::string::npos)
          << text.substr(text.find("FILE_SCHEMA"), 120);
    }
    if (variant == testing::StepVariant::kPartFiles) {
      // Units of their own: the part files alternate, so both units are there.
      ASSERT_GE(part_files.size(), 2u);
      const auto has_inches = [&](const std::string& part) {
        std::ifstream in(dir / part);
        const std::string text((std::istreambuf_iterator<char>(in)), {});
        return text.find("CONVERSION_BASED_UNIT('INCH'") != std::string::npos;
      };
      EXPECT_TRUE(has_inches(part_files[0]));
      EXPECT_FALSE(has_inches(part_files[1]));
    }
    const Assembly a = LoadAssembly(file);
    ASSERT_EQ(a.parts().size(), original.parts().size());
    const Analysis an = Analyze(a);
    EXPECT_EQ(PairsUpToNames(a, an), expected);
    EXPECT_EQ(an.subassemblies.size(), 1u);
    EXPECT_EQ(an.motion.mobility.dof, an_original.motion.mobility.dof);
    if (variant == testing::StepVariant::kAp203 || variant == testing::StepVariant::kAp242) {
      EXPECT_EQ(PartIds(a), PartIds(original));  // names are kept
    }
    if (variant == testing::StepVariant::kInches) {
      // Names are kept; the plate's bolt holes are still 6 holes of the same size in mm.
      const auto plate = a.FindPart("AS1_PE_ASM.PLATE");
      ASSERT_TRUE(plate.has_value());
      EXPECT_EQ(a.part(*plate).features.size(),
                original.part(*original.FindPart("AS1_PE_ASM.PLATE")).features.size());
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(StepImport, AnAssemblysPartFileThatCannotBeReadIsAnErrorNamingIt) {
  // A multi-file export with a part file missing, or damaged, would lose parts unseen (the
  // bolts without their nuts turn free): the import fails, naming the file and its entity.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_parts";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "as1.stp";
  const std::vector<std::string> parts =
      testing::WriteStepVariant(kAs1, file, testing::StepVariant::kPartFiles);
  ASSERT_GE(parts.size(), 3u);
  std::filesystem::remove(dir / parts[0]);
  std::ofstream(dir / parts[2]) << "ISO-10303-21;\nHEADER;\n";  // cut short
  try {
    LoadAssembly(file);
    FAIL() << "no error";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("2 cannot be read"), std::string::npos) << what;
    EXPECT_NE(what.find("'" + parts[0] + "' (#"), std::string::npos) << what;
    EXPECT_NE(
        what.find("DOCUMENT_FILE; looked for at " + (dir / parts[0]).string() + ": no such file)"),
        std::string::npos)
        << what;
    EXPECT_NE(what.find((dir / parts[2]).string() + ": not readable as STEP)"), std::string::npos)
        << what;
    EXPECT_EQ(what.find(parts[1]), std::string::npos) << what;
  }
  std::filesystem::remove_all(dir);
}

TEST(StepImport, GearTeethWithFreeFormFlanksAreFoundOnTheSolidsTessellation) {
  // Our own fixture: a pinion of 6, 8 or 10 teeth (undercut: its flanks run radially below
  // the base circle) meshing a 27-tooth gear, module 1.5, their involute flanks drawn as
  // B-spline curves, so that the exact faces give no feature.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_step_gears";
  std::filesystem::create_directories(dir);
  for (const int pinion : {6, 8, 10}) {
    testing::WriteSpurGearPairStep(dir / "pair.step", pinion, 27, 1.5);
    const Assembly a = LoadAssembly(dir / "pair.step");
    ASSERT_EQ(a.parts().size(), 3u);  // the two gears and the frame implied for them
    EXPECT_EQ(a.parts().back().id, "implied_frame");
    const Analysis an = Analyze(a);
    const Gears g(a, an);
    ASSERT_EQ(g.of_part.size(), 2u) << pinion;
    std::vector<int> teeth;
    for (const auto& [part, f] : g.of_part) {
      teeth.push_back(f->teeth);
      EXPECT_EQ(f->module, 1.5) << part;
      EXPECT_NEAR(std::abs(f->axis.z()), 1.0, 1e-9) << part;
      EXPECT_FALSE(f->internal) << part;
    }
    std::sort(teeth.begin(), teeth.end());
    EXPECT_EQ(teeth, (std::vector<int>{pinion, 27}));
    ASSERT_EQ(g.pairs.size(), 1u) << pinion;
    const Rational ratio = *g.pairs[0]->ratio;
    const bool pinion_first = a.feature(g.pairs[0]->a).teeth == pinion;
    EXPECT_EQ(ratio, pinion_first ? Rational(-pinion, 27) : Rational(-27, pinion));
    // The flanks are free-form faces; the notes say so, and how the teeth were found.
    for (const Part& p : a.parts()) {
      if (!p.HasGeometry()) continue;  // the implied frame
      bool free_form = false, found = false;
      for (const std::string& n : p.notes) {
        free_form = free_form || n.find("free-form face") != std::string::npos;
        found = found || n.find("(found on the solid's tessellation)") != std::string::npos;
      }
      EXPECT_TRUE(free_form && found) << p.id;
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(StepImport, HelicalGearsWithLoftedFlanksMeshWithOppositeHands) {
  // Our own fixture: a 12-tooth right-hand pinion and a 30-tooth left-hand gear, normal module
  // 2, helix 20 degrees, flanks lofted as B-spline surfaces: the sections give each helix.
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "mechanist_step_helical";
  std::filesystem::create_directories(dir);
  const double helix = 20 * M_PI / 180;
  testing::WriteHelicalGearPairStep(dir / "pair.step", 12, 30, 2.0, helix);
  const Assembly a = LoadAssembly(dir / "pair.step");
  ASSERT_EQ(a.parts().size(), 3u);  // the two gears and the frame implied for them
  EXPECT_EQ(a.parts().back().id, "implied_frame");
  const Analysis an = Analyze(a);
  const Gears g(a, an);
  ASSERT_EQ(g.of_part.size(), 2u);
  for (const auto& [part, f] : g.of_part) {
    EXPECT_EQ(f->module, 2.0) << part;
    EXPECT_NEAR(std::abs(f->axis.z()), 1.0, 1e-9) << part;
    // Right hand for the pinion, left for the gear, whichever way the axis came out.
    EXPECT_NEAR(f->helix_angle, f->teeth == 12 ? helix : -helix, 0.2 * M_PI / 180)
        << part << " " << f->teeth;
    EXPECT_NEAR(f->length, 10.0, 0.5) << part;
  }
  ASSERT_EQ(g.pairs.size(), 1u);
  const bool pinion_first = a.feature(g.pairs[0]->a).teeth == 12;
  EXPECT_EQ(*g.pairs[0]->ratio, pinion_first ? Rational(-2, 5) : Rational(-5, 2));
  std::filesystem::remove_all(dir);
}

TEST(StepImport, WormsFromStepSolidsDriveTheirWheels) {
  // Our own fixture: a worm of module 2 (pitch diameter 20) along x, lofted through its
  // transverse sections (B-spline faces), over a 30-tooth spur gear about z. The worm's
  // starts, hand, axial module and pitch diameter come from its tessellation, and the wheel
  // turns starts / 30 per worm turn. Oracle for the sign: a right-hand worm turning
  // positively about +x screws itself along +x through the wheel's teeth, so it pushes the
  // teeth nearest it (at -y from the wheel's axis) along -x: the wheel turns negatively
  // about +z; a left hand the other way.
  struct Case {
    int starts;
    bool right;
  };
  for (const Case c : {Case{1, true}, Case{2, false}}) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_worm";
    std::filesystem::create_directories(dir);
    testing::WriteWormAndWheelStep(dir / "worm.step", c.starts, c.right, 30, 2.0);
    const Assembly a = LoadAssembly(dir / "worm.step");
    const Analysis an = Analyze(a);
    const std::vector<const Pair*> worm_gears = PairsOfType(an, PairType::kWormGear);
    ASSERT_EQ(worm_gears.size(), 1u) << c.starts << ::testing::PrintToString(PairNames(a, an));
    const Pair& pair = *worm_gears[0];
    const Feature& worm = a.feature(pair.a);
    ASSERT_EQ(worm.kind, FeatureKind::kWorm);
    EXPECT_EQ(worm.starts, c.starts);
    EXPECT_EQ(worm.hand, c.right ? Hand::kRight : Hand::kLeft) << c.starts;
    EXPECT_EQ(worm.module, 2.0) << c.starts;
    EXPECT_NEAR(worm.pitch_diameter, 20.0, 0.1) << c.starts;
    const Eigen::Vector3d u_worm = a.part(pair.a.part).X_WP.RotateDirection(worm.axis);
    const Eigen::Vector3d u_wheel =
        a.part(pair.b.part).X_WP.RotateDirection(a.feature(pair.b).axis);
    EXPECT_GT(std::abs(u_worm.x()), 1 - 1e-6) << c.starts;
    EXPECT_GT(std::abs(u_wheel.z()), 1 - 1e-6) << c.starts;
    EXPECT_EQ(a.feature(pair.b).teeth, 30);
    const int sign = (c.right ? -1 : 1) * (u_worm.x() > 0 ? 1 : -1) * (u_wheel.z() > 0 ? 1 : -1);
    EXPECT_EQ(*pair.ratio, Rational(sign * c.starts, 30)) << c.starts;
    std::filesystem::remove_all(dir);
  }
}

TEST(StepImport, StraightBevelGearsFromStepSolidsMeshAtRightAngles) {
  // A 15- and a 30-tooth bevel gear, module 2, shafts at right angles, flanks as B-splines:
  // found on the solids' tessellation with their teeth, module, pitch angles (26.57 and 63.43
  // degrees) and common apex, and their bevel_gear pair at -1/2.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_bevel";
  std::filesystem::create_directories(dir);
  testing::WriteBevelGearPairStep(dir / "bevel.step", 15, 30, 2.0);
  const Assembly a = LoadAssembly(dir / "bevel.step");
  ASSERT_EQ(a.parts().size(), 3u);  // the two gears and the frame implied for them
  EXPECT_EQ(a.parts().back().id, "implied_frame");
  const double kDeg = std::numbers::pi / 180;
  const std::array<int, 2> teeth = {15, 30};
  const std::array<Eigen::Vector3d, 2> axes = {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX()};
  for (std::size_t p = 0; p < 2; ++p) {
    const Feature* gear = FeatureOfKind(a.part(p), FeatureKind::kBevelGear);
    ASSERT_NE(gear, nullptr) << ::testing::PrintToString(a.part(p).notes);
    EXPECT_EQ(gear->teeth, teeth[p]);
    EXPECT_EQ(gear->module, 2.0);
    EXPECT_NEAR(gear->pitch_angle, std::atan2(teeth[p], teeth[1 - p]), 0.02 * kDeg);
    const AxisSegment axis = gear->WorldAxis(a.part(p).X_WP);
    EXPECT_NEAR(axis.direction.dot(axes[p]), 1.0, 1e-4);  // from the apex into the gear
    EXPECT_NEAR(axis.origin.norm(), 0.0, 0.005);
  }
  const Analysis an = Analyze(a);
  const std::vector<const Pair*> bevel = PairsOfType(an, PairType::kBevelGear);
  ASSERT_EQ(bevel.size(), 1u) << ::testing::PrintToString(PairNames(a, an));
  const bool pinion_first = a.feature(bevel[0]->a).teeth == 15;
  EXPECT_EQ(*bevel[0]->ratio, pinion_first ? Rational(-1, 2) : Rational(-2));
  std::filesystem::remove_all(dir);
}

TEST(StepImport, SpiralBevelGearsFromStepSolidsMeshWithOppositeHands) {
  // The 15- and 30-tooth bevel pair with teeth at a 35 degree spiral angle, right hand on the
  // pinion and left on the gear (built as such: the oracle): each measured at 35 degrees with
  // its hand, and their bevel_gear pair at -1/2. Both right-handed, they are no pair: a near
  // miss names the spiral.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_spiral";
  std::filesystem::create_directories(dir);
  const double kDeg = std::numbers::pi / 180;
  testing::WriteBevelGearPairStep(dir / "spiral.step", 15, 30, 2.0, 35 * kDeg, -35 * kDeg);
  const Assembly a = LoadAssembly(dir / "spiral.step");
  ASSERT_EQ(a.parts().size(), 3u);
  const std::array<int, 2> teeth = {15, 30};
  const std::array<double, 2> spiral = {35 * kDeg, -35 * kDeg};
  for (std::size_t p = 0; p < 2; ++p) {
    const Feature* gear = FeatureOfKind(a.part(p), FeatureKind::kBevelGear);
    ASSERT_NE(gear, nullptr) << ::testing::PrintToString(a.part(p).notes);
    EXPECT_EQ(gear->teeth, teeth[p]);
    EXPECT_EQ(gear->module, 2.0);
    EXPECT_NEAR(gear->pitch_angle, std::atan2(teeth[p], teeth[1 - p]), 0.05 * kDeg);
    EXPECT_NEAR(gear->spiral_angle, spiral[p], 0.25 * kDeg);
  }
  // `mechanist features --json` gives the spiral angle, in degrees.
  const std::string json = FeatureJson(RecogniseAssemblyFeatures(a));
  EXPECT_NE(json.find("\"spiral_angle\": 34.9"), std::string::npos) << json;
  EXPECT_NE(json.find("\"spiral_angle\": -34.8"), std::string::npos) << json;
  const Analysis an = Analyze(a);
  const std::vector<const Pair*> bevel = PairsOfType(an, PairType::kBevelGear);
  ASSERT_EQ(bevel.size(), 1u) << ::testing::PrintToString(PairNames(a, an));
  const bool pinion_first = a.feature(bevel[0]->a).teeth == 15;
  EXPECT_EQ(*bevel[0]->ratio, pinion_first ? Rational(-1, 2) : Rational(-2));
  testing::WriteBevelGearPairStep(dir / "same.step", 15, 30, 2.0, 35 * kDeg, 35 * kDeg);
  const Assembly same = LoadAssembly(dir / "same.step");
  const Analysis an_same = Analyze(same);
  for (const Pair& p : an_same.pairs) EXPECT_NE(p.type, PairType::kBevelGear);
  EXPECT_TRUE(std::any_of(an_same.diagnostics.begin(), an_same.diagnostics.end(),
                          [](const Diagnostic& d) { return d.code == "bevel_spiral_mismatch"; }))
      << ::testing::PrintToString(PairNames(same, an_same));
  std::filesystem::remove_all(dir);
}

TEST(StepImport, ARingGearCutIntoAHousingMeshesWithItsPinion) {
  // A 36-tooth ring gear cut into a bolted housing block (module 2) and a 12-tooth pinion
  // inside it: the internal gear is one feature of the housing, beside its bolt holes, and the
  // pair turns the pinion's way at +12/36 = 1/3 (internal) or +3.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_ring";
  std::filesystem::create_directories(dir);
  testing::WriteRingGearHousingStep(dir / "ring.step", 36, 12, 2.0);
  const Assembly a = LoadAssembly(dir / "ring.step");
  ASSERT_EQ(a.parts().size(), 2u);
  const Part& housing = a.part(0);
  const Feature* ring = nullptr;
  int holes = 0;
  for (const Feature& f : housing.features) {
    if (f.kind == FeatureKind::kGear) ring = &f;
    holes += f.kind == FeatureKind::kHole;
  }
  ASSERT_NE(ring, nullptr) << ::testing::PrintToString(housing.notes);
  EXPECT_TRUE(ring->internal);
  EXPECT_EQ(ring->teeth, 36);
  EXPECT_EQ(ring->module, 2.0);
  EXPECT_EQ(holes, 4);
  const Analysis an = Analyze(a);
  const std::vector<const Pair*> gears = PairsOfType(an, PairType::kGear);
  ASSERT_EQ(gears.size(), 1u) << ::testing::PrintToString(PairNames(a, an));
  const bool pinion_first = a.feature(gears[0]->a).teeth == 12;
  EXPECT_EQ(*gears[0]->ratio, pinion_first ? Rational(1, 3) : Rational(3));
  std::filesystem::remove_all(dir);
}

TEST(StepImport, ARackAndPinionFromStepSolidsMakeTheirPair) {
  // Our own fixture: an 18-tooth pinion (module 2, B-spline flanks) on a 12-tooth rack whose
  // faces are all planes. The rack's teeth are found on its tessellation as the pinion's are;
  // one pinion turn moves it by pi m z = 36 pi mm.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_step_rack";
  std::filesystem::create_directories(dir);
  testing::WriteRackAndPinionStep(dir / "rack.step", 18, 2.0, 12);
  const Assembly a = LoadAssembly(dir / "rack.step");
  ASSERT_EQ(a.parts().size(), 2u);
  const Analysis an = Analyze(a);
  const Pair* pair = nullptr;
  for (const Pair& p : an.pairs) {
    if (p.type == PairType::kRackPinion) pair = &p;
  }
  ASSERT_NE(pair, nullptr);
  const Feature& rack = a.feature(pair->b);
  EXPECT_EQ(rack.kind, FeatureKind::kRack);
  EXPECT_EQ(rack.module, 2.0);
  EXPECT_NEAR(std::abs(a.part(pair->b.part).X_WP.RotateDirection(rack.axis).x()), 1.0, 1e-9);
  EXPECT_EQ(a.feature(pair->a).teeth, 18);
  EXPECT_NEAR(std::abs(*pair->travel_per_revolution), 36 * M_PI, 1e-6);
  std::filesystem::remove_all(dir);
}

TEST(StepImport, TheSolidWorksSpurPairMeshesAtMinusOneHalf) {
  // ../shared/data/real: SolidWorks Toolbox gears, flanks as many small cylinder patches; the
  // truth: 40 and 20 teeth, module 2, centre distance 60, ratio -1/2 from the pinion.
  const Assembly a = LoadAssembly(std::filesystem::path(MECHANIST_SHARED_DATA) / "real" /
                                  "spur_pair_20T_40T_solidworks" /
                                  "ISO standard Spur Gear Drive (2-1 ratio).STEP");
  // The gears and the frame implied for them (the file has neither frame nor shafts).
  ASSERT_EQ(a.parts().size(), 3u);
  const Analysis an = Analyze(a);
  EXPECT_EQ(an.motion.mobility.dof, 1);  // the truth's: the gears on fixed axes
  const Gears g(a, an);
  ASSERT_EQ(g.of_part.size(), 2u);
  for (const auto& [part, f] : g.of_part) EXPECT_EQ(f->module, 2.0) << part;
  ASSERT_EQ(g.pairs.size(), 1u);
  const Pair& pair = *g.pairs[0];
  const int teeth_a = a.feature(pair.a).teeth, teeth_b = a.feature(pair.b).teeth;
  EXPECT_EQ(std::min(teeth_a, teeth_b), 20);
  EXPECT_EQ(std::max(teeth_a, teeth_b), 40);
  EXPECT_EQ(*pair.ratio, Rational(-teeth_a, teeth_b));
  // SolidWorks leaves the instances' names blank, which Open CASCADE reads as their
  // identifiers ("NAUO1"): the gears are named by their products, which say which is which.
  for (const FeatureRef& gear : {pair.a, pair.b}) {
    const std::string id(a.PartId(gear.part));
    EXPECT_NE(id.find(fmt::format("Spur_gear_2M_{}T", a.feature(gear).teeth)), std::string::npos)
        << id;
  }
  // No tiny shafts or holes from the flank patches: each gear keeps its bore.
  for (const Part& p : a.parts()) {
    if (!p.HasGeometry()) continue;  // the implied frame
    int cylinders = 0;
    for (const Feature& f : p.features) {
      cylinders += f.kind == FeatureKind::kShaft || f.kind == FeatureKind::kHole;
    }
    EXPECT_EQ(cylinders, 1) << p.id;
  }
}

TEST(StepImport, NoGearIsFoundOnTheRealExportsThatHaveNone) {
  // The other real exports: pins, bearings, a cycloidal disc with its lobes and a pin ring
  // (not involute gears), a lead screw, hinges.
  for (const char* file : {"cycloid_7pin_6lobe_onshape/Full Assembly.step",
                           "rotary_pendulum_ball_bearing_fusion/Assembly.step",
                           "revolute_pin_solidedge_chrono/assembly.stp",
                           "hinge_clamshell_build123d/clamshell_full.step",
                           "lead_screw_linear_actuator_onshape/Assembly.step",
                           "robot_hand_finger_hinges_onshape/Assembly 1.step"}) {
    const Assembly a = LoadAssembly(std::filesystem::path(MECHANIST_SHARED_DATA) / "real" / file);
    for (const Part& p : a.parts()) {
      for (const Feature& f : p.features) {
        EXPECT_NE(f.kind, FeatureKind::kGear) << file << ": " << p.id;
        EXPECT_NE(f.kind, FeatureKind::kBevelGear) << file << ": " << p.id;
        EXPECT_NE(f.kind, FeatureKind::kWorm) << file << ": " << p.id;
        EXPECT_NE(f.kind, FeatureKind::kRack) << file << ": " << p.id;
      }
    }
  }
}

TEST(StepImport, AlikeConesOfAPartAreOneNote) {
  // The Solid Edge bracket's and arm's bores are countersunk at both ends: one note each.
  const Assembly a = LoadAssembly(std::filesystem::path(MECHANIST_SHARED_DATA) / "real" /
                                  "revolute_pin_solidedge_chrono/assembly.stp");
  const auto& notes = a.part(*a.FindPart("Assem1.body1")).notes;
  EXPECT_EQ(std::count(notes.begin(), notes.end(),
                       "countersink of hole_3 (2 alike): 90 deg, diameter 40 to 44 mm"),
            1)
      << ::testing::PrintToString(notes);
  for (const Part& p : a.parts()) {
    std::vector<std::string> sorted = p.notes;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << p.id;
  }
}

TEST(StepImport, TheRobotHandsFingerHingesTurnOnImpliedPins) {
  // ../shared/data/real: the hinge rods are not in the CAD; each hinge is a knuckle's bore
  // between a fork's two cheeks. The truth lists 15 revolutes with their axes.
  const std::filesystem::path dir =
      std::filesystem::path(MECHANIST_SHARED_DATA) / "real" / "robot_hand_finger_hinges_onshape";
  const Assembly a = LoadAssembly(dir / "Assembly 1.step");
  const Analysis an = Analyze(a);
  std::ifstream in(dir / "truth.json");
  const nlohmann::json truth = nlohmann::json::parse(in);
  std::vector<std::string> found, missed;
  for (const auto& joint : truth["truth"]["joints"]) {
    if (joint["type"] != "revolute") continue;
    const std::string x = "Assembly_1." + joint["parts"][0].get<std::string>();
    // "Ring1+Pinky1": both turn on that hinge.
    std::vector<std::string> ys;
    std::stringstream names(joint["parts"][1].get<std::string>());
    for (std::string name; std::getline(names, name, '+');) ys.push_back("Assembly_1." + name);
    const Eigen::Vector3d u(joint["axis_direction"][0], joint["axis_direction"][1],
                            joint["axis_direction"][2]);
    const Eigen::Vector3d p(joint["axis_point_mm"][0], joint["axis_point_mm"][1],
                            joint["axis_point_mm"][2]);
    bool hinges = true;
    for (const std::string& y : ys) {
      bool hinge = false;
      for (const Pair& pair : an.pairs) {
        const std::string pa(a.PartId(pair.a.part)), pb(a.PartId(pair.b.part));
        if (pair.type != PairType::kRevolute || !((pa == x && pb == y) || (pa == y && pb == x))) {
          continue;
        }
        EXPECT_EQ(pair.source, PairSource::kImpliedPin) << x << " " << y;
        const AxisSegment axis = a.feature(pair.a).WorldAxis(a.part(pair.a.part).X_WP);
        // The truth's directions and points are given to two digits.
        EXPECT_GT(std::abs(axis.direction.dot(u.normalized())), 0.999) << x << " " << y;
        const Eigen::Vector3d d = p - axis.origin;
        EXPECT_LT((d - d.dot(axis.direction) * axis.direction).norm(), 0.6) << x << " " << y;
        hinge = true;
      }
      hinges = hinges && hinge;
    }
    (hinges ? found : missed).push_back(x + " " + joint["parts"][1].get<std::string>());
  }
  // 14 of the 15 finger hinges, the palm's fold among them (its holes in the palm, Ring1 and
  // Pinky1 stand 3.7 mm apart: a rod bridges gaps of up to its diameter). The thumb's base turns
  // on its M4 screw (tested in real_exports_test) as a cylindrical pair: the screw, 4 mm in
  // 4.4 mm holes, does not locate it along the axis.
  EXPECT_EQ(found.size(), 14u);
  EXPECT_EQ(missed, (std::vector<std::string>{"Assembly_1.Palm Thumb1"}));
}

// The Solid Edge export of ../shared/data/real with `from` replaced by `to`, written to
// dir/damaged.stp.
std::filesystem::path WriteDamagedStep(const std::filesystem::path& dir, const std::string& from,
                                       const std::string& to) {
  std::ifstream in(std::filesystem::path(MECHANIST_SHARED_DATA) / "real" /
                       "revolute_pin_solidedge_chrono" / "assembly.stp",
                   std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  std::string step = text.str();
  const auto at = step.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) step.replace(at, from.size(), to);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "damaged.stp", std::ios::binary) << step;
  return dir / "damaged.stp";
}

TEST(StepImport, AFileCutShortIsOneWarningNamingTheFirstMissingEntities) {
  // The Solid Edge export's first 1500 lines, closed again: the second body's geometry is
  // gone, and 127 references of the rest point at nothing; its product is named.
  std::ifstream in(std::filesystem::path(MECHANIST_SHARED_DATA) / "real" /
                   "revolute_pin_solidedge_chrono" / "assembly.stp");
  std::string step;
  std::string line;
  for (int k = 0; k < 1500 && std::getline(in, line); ++k) step += line + "\n";
  step += "ENDSEC;\nEND-ISO-10303-21;\n";
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_cut";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "cut.stp", std::ios::binary) << step;
  const Assembly a = LoadAssembly(dir / "cut.stp");
  std::vector<const Diagnostic*> found;
  for (const Diagnostic& d : a.findings()) {
    if (d.code == "step_reader") found.push_back(&d);
  }
  ASSERT_EQ(found.size(), 2u);
  const std::string& m = found[0]->message;
  EXPECT_EQ(found[0]->severity, Severity::kWarning);
  EXPECT_EQ(m.rfind("cut.stp: 127 references to entities the file does not define (#1394 LINE "
                    "refers to #1512; ",
                    0),
            0u)
      << m;
  EXPECT_NE(m.find("; ...): it is damaged or cut short"), std::string::npos) << m;
  EXPECT_EQ(found[1]->severity, Severity::kWarning);
  EXPECT_EQ(found[1]->message,
            "cut.stp: a product instance holds no solid (its shape may be among what the file "
            "lacks): body2");
  std::filesystem::remove_all(dir);
}

// The Solid Edge export without the 30 faces of its second body's shell: that solid is read
// with no face, so its part has no geometry, and a warning names it.
TEST(StepImport, ASolidWhoseFacesAreAllMissingIsNamed) {
  std::ifstream in(std::filesystem::path(MECHANIST_SHARED_DATA) / "real" /
                   "revolute_pin_solidedge_chrono" / "assembly.stp");
  std::string step;
  std::string line;
  const std::regex body2_face(R"(^#(29[89]|3[01][0-9]|32[0-7]) = ADVANCED_FACE)");
  int dropped = 0;
  while (std::getline(in, line)) {
    if (std::regex_search(line, body2_face)) {
      ++dropped;
      continue;
    }
    step += line + "\n";
  }
  ASSERT_EQ(dropped, 30);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_faceless";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "faceless.stp", std::ios::binary) << step;
  const Assembly a = LoadAssembly(dir / "faceless.stp");
  ASSERT_EQ(a.parts().size(), 2u);
  EXPECT_EQ(a.part(1).id, "Assem1.body2");
  EXPECT_FALSE(a.part(1).HasGeometry());
  std::vector<std::string> found;
  for (const Diagnostic& d : a.findings()) {
    if (d.code == "step_reader") found.push_back(d.message);
  }
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].rfind("faceless.stp: 30 references to entities the file does not define "
                           "(#216 CLOSED_SHELL refers to #298; ",
                           0),
            0u)
      << found[0];
  EXPECT_EQ(found[1],
            "faceless.stp: a solid has no face that could be read, so it is left without "
            "geometry: Assem1.body2");
  std::filesystem::remove_all(dir);
}

TEST(StepImport, AFileThatCrashesOpenCascadeIsAnErrorAndTheProcessGoesOn) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "mechanist_step_damaged";
  // Without the entity `#259 = SURFACE_SIDE_STYLE`, which a surface style refers to: Open
  // CASCADE 7.6 dereferences the missing entity and takes a segmentation fault while it reads
  // the colours.
  const std::filesystem::path file =
      WriteDamagedStep(dir, "#259 = SURFACE_SIDE_STYLE( '', ( #425 ) );", "");
  try {
    LoadAssembly(file);
    ADD_FAILURE() << "read a damaged file";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("damaged.stp"), std::string::npos) << what;
    EXPECT_NE(what.find("Open CASCADE failed reading it (OSD_SIGSEGV"), std::string::npos) << what;
    // The entity that refers to the missing one.
    EXPECT_NE(what.find("; it has 1 reference to entities the file does not define (#169 "
                        "SURFACE_STYLE_USAGE refers to #259): it is damaged or cut short"),
              std::string::npos)
        << what;
    EXPECT_EQ(e.line(), 0) << what;  // no line of a made-up import file
  }
  // An oriented edge that is its own edge: the reader recurses until the stack overflows, and
  // the signal is caught on a stack of its own.
  try {
    LoadAssembly(WriteDamagedStep(dir, "#330 = ORIENTED_EDGE( '', *, *, #587",
                                  "#330 = ORIENTED_EDGE( '', *, *, #330"));
    ADD_FAILURE() << "read an edge that is its own";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Open CASCADE failed reading it"), std::string::npos)
        << e.what();
  }
  // The process goes on, and reads a sound file as before.
  EXPECT_EQ(LoadAssembly(kAs1).parts().size(), 18u);
  std::filesystem::remove_all(dir);
}

// Reached only if Open CASCADE's crash met this handler instead of its own: the test ends
// there (returning would fault again forever).
void HandlerOfTheCaller(int) { _exit(99); }

TEST(StepImport, ACallersCrashHandlerGivesWayWhileOpenCascadeReadsAndComesBackAfter) {
  // A sanitizer or a fuzzer holds the crash signals before any file is read.
  struct sigaction own = {};
  struct sigaction previous = {};
  own.sa_handler = HandlerOfTheCaller;
  ASSERT_EQ(sigaction(SIGSEGV, &own, &previous), 0);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "mechanist_step_handler";
  EXPECT_THROW(
      LoadAssembly(WriteDamagedStep(dir, "#259 = SURFACE_SIDE_STYLE( '', ( #425 ) );", "")),
      InputError);
  struct sigaction after = {};
  sigaction(SIGSEGV, nullptr, &after);
  EXPECT_EQ(after.sa_handler, &HandlerOfTheCaller);
  sigaction(SIGSEGV, &previous, nullptr);
  std::filesystem::remove_all(dir);
}

TEST(StepImport, AFaceTurnedOverOrASolidInsideOutIsHealedAsTheReaderWould) {
  // Healing first leaves out the orientation checks; the mesh shows when they were needed
  // (two faces running along an edge the same way, a negative volume), and the solid is then
  // healed thoroughly: each box comes out as the sound one, outward, 6000 mm^3, its faces
  // facing out.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_boxes";
  std::filesystem::create_directories(dir);
  testing::WriteMisorientedBoxesStep(dir / "boxes.step");
  const std::vector<StepSolid> solids = ReadStep(dir / "boxes.step");
  ASSERT_EQ(solids.size(), 3u);
  for (std::size_t k = 0; k < solids.size(); ++k) {
    SCOPED_TRACE(k);
    const MeshCheck check = CheckMesh(*solids[k].mesh);
    EXPECT_TRUE(check.ok()) << ::testing::PrintToString(check.Problems());
    EXPECT_NEAR(check.signed_volume, 6000, 1e-6);
    ASSERT_EQ(solids[k].features.size(), 6u);
    for (const Feature& f : solids[k].features) {
      EXPECT_EQ(f.kind, FeatureKind::kFace) << f.id;
      // Outward: from the box's centre towards the face.
      const Eigen::Vector3d centre(50.0 * k + 5, 10, 15);
      EXPECT_GT(f.axis.dot(f.origin - centre), 0) << f.id;
    }
  }
  std::filesystem::remove_all(dir);
}

// A concave spherical face (its face reversed) holding more than half a ball is a socket. (Its
// area, which tells it from a cap, is positive however the face is turned, so the reader heals
// it once: measured while writing this test, not checked by it.)
TEST(StepImport, ASphericalCupIsASocket) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_socket";
  std::filesystem::create_directories(dir);
  testing::WriteSocketBlockStep(dir / "cup.step", 10);
  const std::vector<StepSolid> solids = ReadStep(dir / "cup.step");
  ASSERT_EQ(solids.size(), 1u);
  std::vector<const Feature*> sockets;
  for (const Feature& f : solids[0].features) {
    if (f.kind == FeatureKind::kSocket) sockets.push_back(&f);
    EXPECT_NE(f.kind, FeatureKind::kBall) << f.id;
  }
  ASSERT_EQ(sockets.size(), 1u);
  EXPECT_EQ(sockets[0]->id, "socket_1");
  EXPECT_NEAR(sockets[0]->diameter, 10, 1e-9);
  EXPECT_NEAR((sockets[0]->origin - Eigen::Vector3d(10, 10, 18)).norm(), 0, 1e-9);
  std::filesystem::remove_all(dir);
}

// A solid's faces are meshed about as closely as the reader asks, 1/1000 of the solid's size,
// measured at every triangle's centroid and every edge's midpoint against the rounded cylinder
// the faces were made of: as exact surfaces (the fillets tori), and converted to B-splines as
// some exporters write every surface. Open CASCADE's mesher checks the same points inside
// B-spline faces (ControlSurfaceDeflection) and leaves 1.42 times the deflection on their
// fillets here (the tori's own grid 1.05 times); without that check, which would save a
// seventh of the robot hand's time, it left 16 times (0.90 mm on a 40 mm puck).
class PuckMesh : public ::testing::TestWithParam<bool> {};

TEST_P(PuckMesh, FacesAreMeshedCloseToTheirSurface) {
  const bool bspline = GetParam();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    (bspline ? "mechanist_puck_bspline" : "mechanist_puck");
  std::filesystem::create_directories(dir);
  constexpr double kRadius = 20, kHeight = 10, kFillet = 3;
  testing::WritePuckStep(dir / "puck.step", kRadius, kHeight, kFillet, bspline);
  const std::vector<StepSolid> solids = ReadStep(dir / "puck.step");
  ASSERT_EQ(solids.size(), 1u);
  // Read as written: the B-spline puck's faces are free-form (and fitted as exact surfaces).
  const bool fitted =
      std::any_of(solids[0].notes.begin(), solids[0].notes.end(), [](const std::string& n) {
        return n.find("free-form faces taken as exact surfaces") != std::string::npos;
      });
  EXPECT_EQ(fitted, bspline) << ::testing::PrintToString(solids[0].notes);
  const TriangleMesh& mesh = *solids[0].mesh;
  // Every face meshed: the area of the discs, the side and the two quarter-round fillets, to
  // 1% (the chords' shortfall; the smallest face, a fillet, is 16% of it).
  constexpr double kPi = std::numbers::pi;
  const double disc = kRadius - kFillet, side = kHeight - 2 * kFillet;
  const double area = 2 * kPi * disc * disc + 2 * kPi * kRadius * side +
                      2 * 2 * kPi * kFillet * (disc * kPi / 2 + kFillet);
  EXPECT_NEAR(mesh.Area(), area, 0.01 * area);
  // Distance from the puck's surface: in the plane through the axis, from a rectangle of
  // half-sizes (kRadius, kHeight / 2) with corners rounded by kFillet (signed distance).
  auto off_surface = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector2d q =
        Eigen::Vector2d(std::hypot(p.x(), p.y()), std::abs(p.z() - kHeight / 2)) -
        Eigen::Vector2d(kRadius - kFillet, kHeight / 2 - kFillet);
    return std::abs(q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0) - kFillet);
  };
  double worst_vertex = 0, worst = 0;
  for (const Eigen::Vector3d& v : mesh.vertices) {
    worst_vertex = std::max(worst_vertex, off_surface(v));
  }
  for (const TriangleMesh::Face& f : mesh.faces) {
    const Eigen::Vector3d& a = mesh.vertices[f[0]];
    const Eigen::Vector3d& b = mesh.vertices[f[1]];
    const Eigen::Vector3d& c = mesh.vertices[f[2]];
    for (const Eigen::Vector3d& p : {Eigen::Vector3d((a + b + c) / 3), Eigen::Vector3d((a + b) / 2),
                                     Eigen::Vector3d((b + c) / 2), Eigen::Vector3d((c + a) / 2)}) {
      worst = std::max(worst, off_surface(p));
    }
  }
  const double size = std::hypot(2 * kRadius, 2 * kRadius, kHeight);
  EXPECT_LT(worst_vertex, 1e-4);  // the nodes lie on the surface
  EXPECT_LE(worst, 2 * 1e-3 * size) << "deflection " << 1e-3 * size;
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(StepImport, PuckMesh, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return info.param ? "BSpline" : "Analytic";
                         });

TEST(StepImport, ConesAreNamedInNotesAndSpheresAreBalls) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_cones";
  std::filesystem::create_directories(dir);
  testing::WriteConesAndBallStep(dir / "cones.step");
  const std::vector<StepSolid> solids = ReadStep(dir / "cones.step");
  ASSERT_EQ(solids.size(), 3u);
  auto has = [](const StepSolid& s, const std::string& text) {
    return std::any_of(s.notes.begin(), s.notes.end(),
                       [&](const std::string& n) { return n == text; });
  };
  auto feature = [](const StepSolid& s, const std::string& id) -> const Feature* {
    for (const Feature& f : s.features) {
      if (f.id == id) return &f;
    }
    return nullptr;
  };
  // The block: its hole below the countersink, the countersink named after it.
  const Feature* hole = feature(solids[0], "hole_1");
  ASSERT_NE(hole, nullptr);
  EXPECT_NEAR(hole->diameter, 6, 1e-9);
  EXPECT_NEAR(hole->length, 7, 1e-6);
  EXPECT_TRUE(has(solids[0], "countersink of hole_1: 90 deg, diameter 6 to 12 mm"))
      << ::testing::PrintToString(solids[0].notes);
  // The pin: its point, 2 atan(2.5 / 5) = 53.1301 degrees.
  ASSERT_NE(feature(solids[1], "shaft_1"), nullptr);
  EXPECT_TRUE(has(solids[1], "conical end of shaft_1: 53.1301 deg, diameter 0 to 5 mm"))
      << ::testing::PrintToString(solids[1].notes);
  // The ball: a `ball` feature (the format's sphere) at its centre, no note.
  ASSERT_EQ(solids[2].features.size(), 1u);
  const Feature& ball = solids[2].features[0];
  EXPECT_EQ(ball.kind, FeatureKind::kBall);
  EXPECT_EQ(ball.id, "ball_1");
  EXPECT_NEAR(ball.diameter, 10, 1e-9);
  EXPECT_NEAR((ball.origin - Eigen::Vector3d(0, 60, 5)).norm(), 0, 1e-9);
  EXPECT_TRUE(solids[2].notes.empty()) << ::testing::PrintToString(solids[2].notes);
  // `mechanist features` lists the notes of imported parts.
  const Assembly a = LoadAssembly(dir / "cones.step");
  std::ostringstream listing;
  WriteFeatureReport(RecogniseAssemblyFeatures(a), listing);
  EXPECT_NE(listing.str().find("note: countersink of hole_1"), std::string::npos) << listing.str();
  // A part whose mesh is the STEP file keeps its solids' notes, named by solid.
  const Assembly whole = LoadAssemblyText(
      R"({"mechanist": 1, "parts": [{"id": "all", "mesh": "cones.step"}]})", dir / "w.json");
  const std::vector<std::string>& notes = whole.part(0).notes;
  EXPECT_NE(std::find(notes.begin(), notes.end(),
                      "solid1: countersink of hole_1: 90 deg, diameter 6 to 12 mm"),
            notes.end())
      << ::testing::PrintToString(notes);
  // With every surface a B-spline, the cones, the ball and the rest are fitted back: the same
  // features (to the fit's 1 um) and the same notes, plus one saying what was fitted.
  testing::WriteNurbsCopy(dir / "cones.step", dir / "cones_nurbs.step");
  const std::vector<StepSolid> nurbs = ReadStep(dir / "cones_nurbs.step");
  ASSERT_EQ(nurbs.size(), solids.size());
  for (std::size_t k = 0; k < solids.size(); ++k) {
    ASSERT_EQ(nurbs[k].features.size(), solids[k].features.size()) << k;
    for (std::size_t i = 0; i < solids[k].features.size(); ++i) {
      const Feature &f = nurbs[k].features[i], &g = solids[k].features[i];
      EXPECT_EQ(f.id, g.id);
      EXPECT_EQ(f.kind, g.kind) << f.id;
      EXPECT_NEAR(f.diameter, g.diameter, 1e-3) << f.id;
      EXPECT_NEAR(f.length, g.length, 1e-3) << f.id;
      EXPECT_NEAR((f.origin - g.origin).norm(), 0, 1e-3) << f.id;
      EXPECT_NEAR(std::abs(f.axis.dot(g.axis)), 1, 1e-6) << f.id;
    }
    std::vector<std::string> fitted;
    for (const std::string& n : nurbs[k].notes) {
      if (n.find("taken as exact surfaces") == std::string::npos) fitted.push_back(n);
    }
    EXPECT_EQ(fitted, solids[k].notes) << k;
  }
  auto fitted_as = [](const StepSolid& s) {
    for (const std::string& n : s.notes) {
      if (n.find("taken as exact surfaces") != std::string::npos) return n;
    }
    return std::string();
  };
  // Each says what its faces were taken as, and within what (to 0.1 um, rounded up).
  const std::vector<std::string> fitted_notes = {
      "8 free-form faces taken as exact surfaces: 6 planes, 1 cylinder, 1 cone (within ",
      "3 free-form faces taken as exact surfaces: 1 plane, 1 cylinder, 1 cone (within ",
      "1 free-form face taken as exact surfaces: 1 sphere (within "};
  for (std::size_t k = 0; k < nurbs.size(); ++k) {
    EXPECT_EQ(fitted_as(nurbs[k]).rfind(fitted_notes[k], 0), 0u) << fitted_as(nurbs[k]);
  }
}

// A binary STL of `mesh`.
void WriteStl(const TriangleMesh& mesh, const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::binary);
  const std::string header(80, ' ');
  out.write(header.data(), 80);
  const auto count = static_cast<std::uint32_t>(mesh.faces.size());
  out.write(reinterpret_cast<const char*>(&count), 4);
  for (const TriangleMesh::Face& f : mesh.faces) {
    float values[12] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i < 3; ++i)
        values[3 + 3 * k + i] = static_cast<float>(mesh.vertices[f[k]][i]);
    }
    out.write(reinterpret_cast<const char*>(values), sizeof values);
    const std::uint16_t attribute = 0;
    out.write(reinterpret_cast<const char*>(&attribute), 2);
  }
}

TEST(MeshRecognition, AWormAndAGearAsSTLsMakeTheirWormGearPair) {
  // A single-start worm (module 1.5, pitch diameter 15) along z and a 30-tooth gear of its
  // module turning about y, its mid-plane through the worm's axis at the centre distance
  // (15 + 1.5 x 30) / 2 = 30 mm: both recognised from their meshes alone, and their worm_gear
  // pair at 1/30.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_worm_stl";
  std::filesystem::create_directories(dir);
  WormSpec worm;
  worm.module = 1.5;
  worm.pitch_diameter = 15;
  worm.length = 40;
  worm.bore_diameter = 5;
  SpurGearSpec wheel;
  wheel.teeth = 30;
  wheel.module = 1.5;
  wheel.face_width = 8;
  wheel.bore_diameter = 8;
  WriteStl(MakeLibraryPart(worm).mesh, dir / "worm.stl");
  WriteStl(MakeLibraryPart(wheel).mesh, dir / "wheel.stl");
  const std::string text = R"({"mechanist": 1, "parts": [
    {"id": "worm", "mesh": "worm.stl"},
    {"id": "wheel", "mesh": "wheel.stl",
     "pose": {"position": [30, -4, 20], "quaternion": [0.7071067811865476, -0.7071067811865476, 0, 0]}}]})";
  const Assembly a = LoadAssemblyText(text, dir / "a.json");
  const Analysis an = Analyze(a);
  const std::vector<const Pair*> worm_gears = PairsOfType(an, PairType::kWormGear);
  ASSERT_EQ(worm_gears.size(), 1u) << ::testing::PrintToString(PairNames(a, an));
  EXPECT_EQ(a.PartId(worm_gears[0]->a.part), "worm");
  EXPECT_EQ(a.feature(worm_gears[0]->a).starts, 1);
  // Right-hand worm about +z, wheel about +y on its +x side: (u_wheel x n) . u_worm =
  // (y x x) . z = -1, so the wheel turns -1/30 per worm turn (see "Recognition").
  EXPECT_GT(a.feature(worm_gears[0]->a).axis.z(), 1 - 1e-6);
  EXPECT_GT(a.feature(worm_gears[0]->b).axis.z(), 1 - 1e-6);  // in the wheel's frame
  EXPECT_EQ(*worm_gears[0]->ratio, Rational(-1, 30));
  std::filesystem::remove_all(dir);
}

TEST(MeshRecognition, SpiralBevelGearsAsSTLsMakeTheirPair) {
  // The spiral bevel pair of the STEP test (35 degrees, right hand on the 15-tooth pinion,
  // left on the 30-tooth gear) as two STL files of their tessellations: the same spiral
  // angles from the meshes alone, and the pair at -1/2.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_spiral_stl";
  std::filesystem::create_directories(dir);
  const double kDeg = std::numbers::pi / 180;
  testing::WriteBevelGearPairStep(dir / "spiral.step", 15, 30, 2.0, 35 * kDeg, -35 * kDeg);
  const std::vector<StepSolid> solids = ReadStep(dir / "spiral.step");
  ASSERT_EQ(solids.size(), 2u);
  WriteStl(*solids[0].mesh, dir / "pinion.stl");
  WriteStl(*solids[1].mesh, dir / "gear.stl");
  const Assembly a = LoadAssemblyText(R"({"mechanist": 1, "parts": [
    {"id": "pinion", "mesh": "pinion.stl"}, {"id": "gear", "mesh": "gear.stl"}]})",
                                      dir / "a.json");
  const std::array<double, 2> spiral = {35 * kDeg, -35 * kDeg};
  for (std::size_t p = 0; p < 2; ++p) {
    const Feature* gear = FeatureOfKind(a.part(p), FeatureKind::kBevelGear);
    ASSERT_NE(gear, nullptr);
    EXPECT_NEAR(gear->spiral_angle, spiral[p], 0.25 * kDeg);
  }
  const Analysis an = Analyze(a);
  const std::vector<const Pair*> bevel = PairsOfType(an, PairType::kBevelGear);
  ASSERT_EQ(bevel.size(), 1u) << ::testing::PrintToString(PairNames(a, an));
  EXPECT_EQ(*bevel[0]->ratio,
            a.PartId(bevel[0]->a.part) == "pinion" ? Rational(-1, 2) : Rational(-2));
  std::filesystem::remove_all(dir);
}

TEST(MeshRecognition, SeparatePinsInAHousingAreItsPinRing) {
  // A housing (80 mm square, 10 thick) with seven 6 mm holes on a 50 mm circle, a 6 mm pin
  // (a part of its own, 25 long) pressed into each, and a 6-lobe cycloidal disc for them
  // (eccentricity 2) between z = 12 and 20 on the pins: the pins become the housing's pin
  // ring, and the disc makes its cycloidal pair with it. One pin 1 mm off the circle: none.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_pins";
  std::filesystem::create_directories(dir);
  for (const double stray : {0.0, 1.0}) {
    Region2d housing{{{-40, -40}, {40, -40}, {40, 40}, {-40, 40}}, {}};
    std::string parts = R"({"id": "housing", "mesh": "housing.stl"}, {"id": "disc", "mesh":
        "disc.stl", "pose": {"position": [0, 2, 0]}})";
    for (int k = 0; k < 7; ++k) {
      const double a = 2 * std::numbers::pi * k / 7, r = 25 + (k == 3 ? stray : 0.0);
      const Eigen::Vector2d c(r * std::cos(a), r * std::sin(a));
      housing.holes.push_back(CircleRing(c, 3, 48));
      parts += fmt::format(R"(, {{"id": "pin{}", "mesh": "pin.stl", "pose": {{"position": [{},
          {}, 0]}}}})",
                           k + 1, c.x(), c.y());
    }
    WriteStl(ExtrudeRegion(housing, 0, 10), dir / "housing.stl");
    WriteStl(ExtrudeRegion({CircleRing(Eigen::Vector2d::Zero(), 3, 48), {}}, 0, 25),
             dir / "pin.stl");
    Region2d disc{testing::CycloidOutline(7, 25, 3, 2, 720), {}};
    disc.holes.push_back(CircleRing(Eigen::Vector2d::Zero(), 5, 64));
    WriteStl(ExtrudeRegion(disc, 12, 20), dir / "disc.stl");
    const Assembly a =
        LoadAssemblyText(R"({"mechanist": 1, "parts": [)" + parts + "]}", dir / "reducer.json");
    const Part& h = a.part(*a.FindPart("housing"));
    const auto ring = h.FindFeature("pins_1");
    const Analysis an = Analyze(a);
    const auto cycloidal = std::count_if(an.pairs.begin(), an.pairs.end(), [](const Pair& p) {
      return p.type == PairType::kCycloidal;
    });
    if (stray > 0) {
      EXPECT_FALSE(ring.has_value());
      EXPECT_EQ(cycloidal, 0);
      continue;
    }
    ASSERT_TRUE(ring.has_value()) << ::testing::PrintToString(PairNames(a, an));
    const Feature& f = h.features[*ring];
    EXPECT_EQ(f.kind, FeatureKind::kPinRing);
    EXPECT_EQ(f.teeth, 7);
    EXPECT_NEAR(f.diameter, 50, 0.01);
    EXPECT_NEAR(f.pin_diameter, 6, 0.01);
    EXPECT_NEAR(f.length, 25, 0.01);
    EXPECT_LT(f.origin.head<2>().norm(), 0.01);
    EXPECT_EQ(cycloidal, 1) << ::testing::PrintToString(PairNames(a, an));
    EXPECT_EQ(std::count_if(a.findings().begin(), a.findings().end(),
                            [](const Diagnostic& d) { return d.code == "pin_ring_of_parts"; }),
              1);
  }
  std::filesystem::remove_all(dir);
}

TEST(NutOnBolt, MeshPartsAloneAreANutOnItsBolt) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_nut_stl";
  std::filesystem::create_directories(dir);
  HexBoltSpec bolt;
  bolt.diameter = 6;
  bolt.length = 20;
  HexNutSpec nut;
  nut.diameter = 6;
  WriteStl(MakeLibraryPart(bolt).mesh, dir / "bolt.stl");
  WriteStl(MakeLibraryPart(nut).mesh, dir / "nut.stl");
  const std::string text = R"({"mechanist": 1, "parts": [
    {"id": "bolt", "mesh": "bolt.stl"},
    {"id": "nut", "mesh": "nut.stl", "pose": {"position": [0, 0, 10]}}]})";
  const Assembly a = LoadAssemblyText(text, dir / "a.json");
  // What each step of the load did: recognition, the heuristic, then the ground chosen.
  ASSERT_EQ(a.findings().size(), 3u);
  EXPECT_EQ(a.findings()[0].code, "features_recognised");
  EXPECT_EQ(a.findings()[0].parts, (std::vector<std::string>{"bolt", "nut"}));
  EXPECT_EQ(a.findings()[1].code, "nut_on_bolt");
  EXPECT_EQ(a.findings()[2].code, "ground_chosen");
  EXPECT_EQ(a.findings()[2].parts, std::vector<std::string>{"bolt"});
  const Analysis an = Analyze(a);
  ASSERT_EQ(an.pairs.size(), 1u);
  EXPECT_EQ(an.pairs[0].type, PairType::kFixed);
  // Written features are never reinterpreted.
  const std::string written = R"({"mechanist": 1, "parts": [
    {"id": "bolt", "mesh": "bolt.stl", "features": [{"id": "s", "kind": "shaft", "origin": [0, 0, 0],
      "axis": [0, 0, 1], "diameter": 6, "length": 20}]},
    {"id": "nut", "mesh": "nut.stl", "pose": {"position": [0, 0, 10]}}]})";
  const Assembly w = LoadAssemblyText(written, dir / "b.json");
  ASSERT_EQ(w.findings().size(), 2u);
  EXPECT_EQ(w.findings()[0].code, "features_recognised");
  EXPECT_EQ(w.findings()[0].parts, std::vector<std::string>{"nut"});
  EXPECT_EQ(w.findings()[1].code, "ground_chosen");
  std::filesystem::remove_all(dir);
}

TEST(NutOnBolt, AnArmsSquareHubOnAMotorShaftIsNoNut) {
  // A 100 x 40 x 5 bar with a 5 mm bore on a 5 mm shaft: a 4-sided prism with one hole, but
  // twenty bores long (an M5 nut is under two across its corners and one thick).
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_arm_stl";
  std::filesystem::create_directories(dir);
  PlateSpec arm;
  arm.length = 100, arm.width = 40, arm.thickness = 5;
  arm.holes = {{"bore", Eigen::Vector2d(-40, 0), 5.0}};
  ShaftSpec shaft;
  shaft.diameter = 5, shaft.length = 30;
  WriteStl(MakeLibraryPart(arm).mesh, dir / "arm.stl");
  WriteStl(MakeLibraryPart(shaft).mesh, dir / "shaft.stl");
  const Assembly a = LoadAssemblyText(R"({"mechanist": 1, "parts": [
    {"id": "shaft", "mesh": "shaft.stl", "pose": {"position": [-40, 0, -10]}},
    {"id": "arm", "mesh": "arm.stl"}]})",
                                      dir / "a.json");
  for (const Diagnostic& d : a.findings()) EXPECT_NE(d.code, "nut_on_bolt") << d.message;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mechanist
