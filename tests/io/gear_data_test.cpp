// Feature recognition on gear meshes that nobody here wrote (../shared/data/gears, generated
// by BOSL2), against their manifest; and assemblies of those STL files alone, without a single
// written feature, whose gear and rack pairs and ratios must come out.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/load_assembly.h"
#include "io/mesh_reader.h"
#include "kernel/features/feature_recognition.h"
#include "reasoning/analysis.h"

namespace mechanist {
namespace {

const std::filesystem::path kGears = std::filesystem::path(MECHANIST_SHARED_DATA) / "gears";

Eigen::Vector3d Vec(const nlohmann::json& j) {
  return Eigen::Vector3d(j[0].get<double>(), j[1].get<double>(), j[2].get<double>());
}

TEST(GearData, EveryManifestPartIsRecognisedWithItsTruth) {
  std::ifstream in(kGears / "manifest.json");
  ASSERT_TRUE(in) << "missing " << kGears;
  const nlohmann::json manifest = nlohmann::json::parse(in);
  int checked = 0;
  for (const auto& part : manifest["parts"]) {
    const std::filesystem::path file = kGears / part["file"].get<std::string>();
    if (!std::filesystem::exists(file)) continue;
    SCOPED_TRACE(file.string());
    ++checked;
    const MeshFeatures found = RecognizeFeatures(ReadMesh(file));
    const bool rack = part["kind"] == "rack";
    const RecognizedFeature* teeth = nullptr;
    for (const RecognizedFeature& r : found.features) {
      if (r.feature.kind == (rack ? FeatureKind::kRack : FeatureKind::kGear)) teeth = &r;
    }
    ASSERT_NE(teeth, nullptr);
    const Feature& f = teeth->feature;
    const double module = part["module"];
    EXPECT_LE(std::abs(f.module - module), 0.01 * module);
    const Eigen::Vector3d axis = Vec(part["axis_direction"]).normalized();
    EXPECT_GT(std::abs(f.axis.dot(axis)), 1 - 1e-9);
    if (rack) {
      // Teeth pointing +z, the pitch line on the x axis.
      EXPECT_GT(f.normal.dot(Eigen::Vector3d::UnitZ()), 1 - 1e-9);
      EXPECT_NEAR(f.origin.z(), 0.0, 1e-3);
      EXPECT_EQ(std::lround(f.length / (M_PI * f.module)), part["teeth"].get<long>());
    } else {
      EXPECT_EQ(f.teeth, part["teeth"].get<int>());
      const Eigen::Vector3d d = Vec(part["axis_origin"]) - f.origin;
      EXPECT_LT((d - d.dot(f.axis) * f.axis).norm(), 1e-4);
      EXPECT_NEAR(f.length, part["face_width"].get<double>(), 1e-4);
      const RecognizedFeature* bore = nullptr;
      for (const RecognizedFeature& r : found.features) {
        if (r.feature.id == "bore") bore = &r;
      }
      ASSERT_NE(bore, nullptr);
      EXPECT_NEAR(bore->feature.diameter, part["bore_diameter"].get<double>(), 1e-3);
    }
  }
  EXPECT_EQ(checked, 6);
}

// An assembly file of STL parts only, written to a temporary folder.
Assembly StlAssembly(const std::string& name, const std::vector<std::string>& files) {
  std::string text = R"({"mechanist": 1, "name": ")" + name + R"(", "parts": [)";
  for (std::size_t i = 0; i < files.size(); ++i) {
    text += std::string(i ? ", " : "") + R"({"id": "p)" + std::to_string(i + 1) +
            R"(", "mesh": ")" + (kGears / files[i]).string() + "\"}";
  }
  text += "]}";
  return LoadAssemblyText(text, std::filesystem::temp_directory_path() / (name + ".json"));
}

TEST(GearData, StlPartsAloneMeshAsGearAndRackPairs) {
  const Assembly spur = StlAssembly(
      "spur", {"spur_pair/spur_pair_gear_A_z17_m1.stl", "spur_pair/spur_pair_gear_B_z31_m1.stl"});
  const Analysis a = Analyze(spur);
  // The gear pair and each gear's revolute on the frame implied for them (no shafts).
  ASSERT_EQ(a.pairs.size(), 3u);
  const auto gear = std::find_if(a.pairs.begin(), a.pairs.end(),
                                 [](const Pair& p) { return p.type == PairType::kGear; });
  ASSERT_NE(gear, a.pairs.end());
  ASSERT_TRUE(gear->ratio.has_value());
  EXPECT_EQ(gear->ratio->ToString(), "-17/31");

  const Assembly rack = StlAssembly("rack", {"rack_pinion/rack_pinion_pinion_z20_m1.stl",
                                             "rack_pinion/rack_pinion_rack_m1_19t.stl"});
  const Analysis r = Analyze(rack);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_EQ(r.pairs[0].type, PairType::kRackPinion);
  ASSERT_TRUE(r.pairs[0].travel_per_revolution.has_value());
  // One revolution of the 20-tooth pinion moves the rack pi m z = 20 pi mm.
  EXPECT_NEAR(std::abs(*r.pairs[0].travel_per_revolution), 20 * M_PI, 1e-9);
}

}  // namespace
}  // namespace mechanist
