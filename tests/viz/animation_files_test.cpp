// The animation's files (glTF binary, ParaView series) read back with readers written here
// from the formats' specifications, against the poses the motion analysis computes.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>

#include "io/load_assembly.h"
#include "io/text_edit.h"
#include "reasoning/analysis.h"
#include "reasoning/animation.h"
#include "reasoning/gap_search.h"
#include "reasoning/motion_run.h"
#include "viz/gltf_writer.h"
#include "viz/vtp_series_writer.h"

namespace mechanist {
namespace {

const std::string kWorm =
    std::string(MECHANIST_SOURCE_DIR) + "/examples/robot_hand_worm/assembly.json";

std::uint32_t Word(const std::string& bytes, std::size_t at) {
  std::uint32_t w = 0;
  std::memcpy(&w, bytes.data() + at, 4);
  return w;
}

// A GLB file split into its JSON and binary chunks, checked against the container rules.
struct Glb {
  nlohmann::json doc;
  std::string bin;

  explicit Glb(const std::string& bytes) {
    EXPECT_EQ(Word(bytes, 0), 0x46546C67u);
    EXPECT_EQ(Word(bytes, 4), 2u);
    EXPECT_EQ(Word(bytes, 8), bytes.size());
    const std::uint32_t json_length = Word(bytes, 12);
    EXPECT_EQ(Word(bytes, 16), 0x4E4F534Au);
    EXPECT_EQ(json_length % 4, 0u);
    doc = nlohmann::json::parse(bytes.substr(20, json_length));
    const std::size_t bin_at = 20 + json_length;
    const std::uint32_t bin_length = Word(bytes, bin_at);
    EXPECT_EQ(Word(bytes, bin_at + 4), 0x004E4942u);
    EXPECT_EQ(bin_at + 8 + bin_length, bytes.size());
    bin = bytes.substr(bin_at + 8, bin_length);
    EXPECT_GE(bin_length, doc["buffers"][0]["byteLength"].get<std::size_t>());
  }

  // The floats of accessor `index`, after checking that it lies inside its view and buffer.
  std::vector<float> Floats(int index) const {
    const auto& accessor = doc["accessors"][index];
    EXPECT_EQ(accessor["componentType"], 5126);
    const auto& view = doc["bufferViews"][accessor["bufferView"].get<int>()];
    const std::map<std::string, int> width = {{"SCALAR", 1}, {"VEC3", 3}, {"VEC4", 4}};
    const std::size_t count =
        accessor["count"].get<std::size_t>() * width.at(accessor["type"].get<std::string>());
    const std::size_t offset = view["byteOffset"].get<std::size_t>();
    EXPECT_EQ(offset % 4, 0u);
    EXPECT_LE(count * 4, view["byteLength"].get<std::size_t>());
    EXPECT_LE(offset + count * 4, bin.size());
    std::vector<float> values(count);
    std::memcpy(values.data(), bin.data() + offset, count * 4);
    return values;
  }
};

struct Worm {
  Assembly assembly = LoadAssembly(kWorm);
  Analysis analysis = Analyze(assembly);
  MotionRun run = PlanRun(assembly, analysis, std::nullopt, std::nullopt);
  std::size_t wheel = *assembly.FindPart("worm_wheel");
};

// The rotation angle (degrees, right-hand about +z) that takes R0 to R1.
double TurnAboutZ(const Eigen::Matrix3d& R0, const Eigen::Matrix3d& R1) {
  const Eigen::AngleAxisd d(R1 * R0.transpose());
  return d.angle() * d.axis().z() * 180.0 / M_PI;
}

TEST(MotionRun, FramesSpanTheDriversAmountAndTheWheelTurnsMinusNineDegrees) {
  const Worm w;
  ASSERT_TRUE(w.run.possible) << w.run.reason;
  EXPECT_EQ(w.run.amount, 1.0);
  const Animation animation = SampleRun(w.assembly, w.run, 121);
  EXPECT_EQ(animation.s.front(), 0.0);
  EXPECT_EQ(animation.s.back(), 1.0);
  // Frame 0 is the file; after one driver revolution the 40-tooth wheel is at -1/40 rev.
  for (std::size_t p = 0; p < w.assembly.parts().size(); ++p) {
    EXPECT_TRUE(animation.states[0].X_WP[p].IsNearlyEqualTo(w.assembly.part(p).X_WP, 1e-12, 1e-12));
  }
  const Eigen::Matrix3d& R0 = animation.states[0].X_WP[w.wheel].rotation();
  EXPECT_NEAR(TurnAboutZ(R0, animation.states[120].X_WP[w.wheel].rotation()), -9.0, 1e-9);
  EXPECT_NEAR(TurnAboutZ(R0, animation.states[60].X_WP[w.wheel].rotation()), -4.5, 1e-9);
  EXPECT_EQ(animation.labels[60], "motor_shaft 180.0 deg");
  // Ground parts stay.
  const std::size_t housing = *w.assembly.FindPart("housing");
  EXPECT_TRUE(
      animation.states[120].X_WP[housing].IsNearlyEqualTo(w.assembly.part(housing).X_WP, 0.0, 0.0));
}

TEST(MotionRun, AShorterAmountAndANegativeRate) {
  const Worm w;
  const MotionRun half = PlanRun(w.assembly, w.analysis, 0, 0.5);
  EXPECT_EQ(half.amount, 0.5);
  const AssemblyState end = StateAt(w.assembly, half, 0.5);
  EXPECT_NEAR(TurnAboutZ(w.assembly.part(w.wheel).X_WP.rotation(), end.X_WP[w.wheel].rotation()),
              -4.5, 1e-9);
  // Reversing the driver's rate runs every part backwards: the wheel turns +4.5 degrees.
  const Assembly reversed = LoadAssemblyText(
      testing::Replace(testing::ReadText(kWorm), R"("rate": 1.0)", R"("rate": -1.0)"), kWorm);
  const MotionRun back = PlanRun(reversed, Analyze(reversed), std::nullopt, 0.5);
  EXPECT_NEAR(TurnAboutZ(w.assembly.part(w.wheel).X_WP.rotation(),
                         StateAt(reversed, back, 0.5).X_WP[w.wheel].rotation()),
              4.5, 1e-9);
  EXPECT_THROW(PlanRun(w.assembly, w.analysis, 3, std::nullopt), std::invalid_argument);
  EXPECT_THROW(PlanRun(w.assembly, w.analysis, 0, -1.0), std::invalid_argument);
  EXPECT_THROW(SampleRun(w.assembly, half, 0), std::invalid_argument);
}

TEST(GltfAnimation, KeyframesAreTheComputedPosesAndTheStillPartsSitAtTheirs) {
  const Worm w;
  const std::size_t frames = 25;
  const double fps = 12.0;
  const Animation animation = SampleRun(w.assembly, w.run, frames);
  const Glb glb(GlbAnimation(w.assembly, w.analysis, animation, fps));
  const auto& doc = glb.doc;
  EXPECT_EQ(doc["asset"]["version"], "2.0");
  const auto& nodes = doc["nodes"];
  ASSERT_EQ(nodes.size(), w.assembly.parts().size() + 1);
  EXPECT_EQ(nodes[0]["children"].size(), w.assembly.parts().size());
  EXPECT_EQ(nodes[0]["scale"][0], 1e-3);
  // Every mesh's positions have bounds and indices inside the vertex count.
  for (const auto& mesh : doc["meshes"]) {
    const auto& primitive = mesh["primitives"][0];
    const auto& position = doc["accessors"][primitive["attributes"]["POSITION"].get<int>()];
    EXPECT_TRUE(position.contains("min") && position.contains("max"));
    const auto& indices = doc["accessors"][primitive["indices"].get<int>()];
    const auto& view = doc["bufferViews"][indices["bufferView"].get<int>()];
    std::vector<std::uint32_t> index(indices["count"].get<std::size_t>());
    std::memcpy(index.data(), glb.bin.data() + view["byteOffset"].get<std::size_t>(),
                index.size() * 4);
    for (const std::uint32_t i : index) ASSERT_LT(i, position["count"].get<std::uint32_t>());
  }
  ASSERT_EQ(doc["animations"].size(), 1u);
  const auto& a = doc["animations"][0];
  std::set<std::size_t> animated;
  for (const auto& channel : a["channels"]) {
    const std::size_t node = channel["target"]["node"];
    const std::size_t part = node - 1;
    ASSERT_LT(part, w.assembly.parts().size());
    EXPECT_EQ(nodes[node]["name"], w.assembly.part(part).id);
    animated.insert(part);
    const auto& sampler = a["samplers"][channel["sampler"].get<int>()];
    EXPECT_EQ(sampler["interpolation"], "LINEAR");
    const std::vector<float> times = glb.Floats(sampler["input"]);
    ASSERT_EQ(times.size(), frames);
    const std::vector<float> values = glb.Floats(sampler["output"]);
    for (std::size_t k = 0; k < frames; ++k) {
      EXPECT_FLOAT_EQ(times[k], static_cast<float>(k / fps));
      const RigidTransform& X = animation.states[k].X_WP[part];
      if (channel["target"]["path"] == "translation") {
        const Eigen::Vector3d p(values[3 * k], values[3 * k + 1], values[3 * k + 2]);
        EXPECT_LT((p - X.translation()).norm(), 1e-4 * (1 + X.translation().norm()));
      } else {
        const Eigen::Quaterniond q(values[4 * k + 3], values[4 * k], values[4 * k + 1],
                                   values[4 * k + 2]);
        EXPECT_NEAR(std::abs(q.dot(Eigen::Quaterniond(X.rotation()))), 1.0, 1e-6);
        if (k > 0) {  // consecutive keys on one side: the interpolation takes the short way
          const Eigen::Quaterniond previous(values[4 * k - 1], values[4 * k - 4], values[4 * k - 3],
                                            values[4 * k - 2]);
          EXPECT_GT(q.dot(previous), 0.0);
        }
      }
    }
  }
  // Exactly the moving parts are animated, the others sit at their file poses.
  for (std::size_t p = 0; p < w.assembly.parts().size(); ++p) {
    EXPECT_EQ(animated.count(p) == 1, !w.run.paths[p].still()) << w.assembly.part(p).id;
    const auto& t = nodes[p + 1]["translation"];
    const Eigen::Vector3d p_W(t[0], t[1], t[2]);
    EXPECT_LT((p_W - w.assembly.part(p).X_WP.translation()).norm(), 1e-9);
  }
  EXPECT_TRUE(animated.count(w.wheel));
  // Deterministic.
  EXPECT_EQ(GlbAnimation(w.assembly, w.analysis, animation, fps),
            GlbAnimation(w.assembly, w.analysis, animation, fps));
  EXPECT_THROW(GlbAnimation(w.assembly, w.analysis, animation, 0.0), std::invalid_argument);
}

TEST(GltfAnimation, AFeaturesOnlyPartIsDrawnByItsFeatureLines) {
  const Assembly a = LoadAssembly(std::string(MECHANIST_SOURCE_DIR) +
                                  "/examples/planetary_differential_sketch/assembly.json");
  const Analysis an = Analyze(a);
  const Animation animation = SampleRun(a, PlanRun(a, an, std::nullopt, std::nullopt), 3);
  const Glb glb(GlbAnimation(a, an, animation, 10.0));
  const auto& doc = glb.doc;
  for (std::size_t p = 0; p < a.parts().size(); ++p) {
    const auto& node = doc["nodes"][p + 1];
    ASSERT_TRUE(node.contains("mesh")) << a.part(p).id;
    const auto& primitive = doc["meshes"][node["mesh"].get<int>()]["primitives"][0];
    EXPECT_EQ(primitive["mode"], 1) << a.part(p).id;  // LINES
    const auto& position = doc["accessors"][primitive["attributes"]["POSITION"].get<int>()];
    const auto& indices = doc["accessors"][primitive["indices"].get<int>()];
    // An axis is one segment; a gear adds its pitch circle of 72.
    std::size_t segments = 0;
    for (const Feature& f : a.part(p).features) {
      segments += 1 + (f.kind == FeatureKind::kGear ? 72 : 0);
    }
    EXPECT_EQ(indices["count"].get<std::size_t>(), 2 * segments) << a.part(p).id;
    // The carrier's pin bore lies 15 mm off its axis: the lines reach it.
    if (a.part(p).id == "carrier") {
      EXPECT_NEAR(position["max"][0].get<double>(), 15.0, 1e-6);
    }
  }
}

std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The raw bytes of the appended DataArray `name` of a VTK XML file.
std::string AppendedArray(const std::string& file, const std::string& name) {
  const std::regex array("Name=\"" + name + "\"[^>]*offset=\"([0-9]+)\"");
  std::smatch m;
  EXPECT_TRUE(std::regex_search(file, m, array)) << name;
  if (m.empty()) return {};
  // The raw data start after the underscore that follows the AppendedData tag.
  const std::size_t data = file.find('_', file.find("<AppendedData encoding=\"raw\">")) + 1;
  const std::size_t at = data + std::stoull(m[1]);
  std::uint64_t size = 0;
  std::memcpy(&size, file.data() + at, 8);
  return file.substr(at + 8, size);
}

TEST(VtpSeries, TheCollectionReferencesEveryFrameAndEachFrameHoldsThePoses) {
  const Worm w;
  const std::size_t frames = 7;
  const Animation animation = SampleRun(w.assembly, w.run, frames);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "mechanist_vtp_series_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  WriteVtpSeries(dir / "motion.pvd", w.assembly, w.analysis, animation);
  const std::string pvd = ReadFile(dir / "motion.pvd");
  const std::regex dataset("<DataSet timestep=\"([^\"]+)\" part=\"0\" file=\"([^\"]+)\"/>");
  std::size_t k = 0;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), dataset);
       it != std::sregex_iterator(); ++it, ++k) {
    ASSERT_LT(k, frames);
    EXPECT_DOUBLE_EQ(std::stod((*it)[1]), animation.s[k]);
    const std::filesystem::path file = dir / (*it)[2].str();
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    const std::string vtp = ReadFile(file);
    // Points: every part's vertices at this frame's pose, in part order.
    const std::string points = AppendedArray(vtp, "Points");
    const std::string part = AppendedArray(vtp, "part");
    const std::string subassembly = AppendedArray(vtp, "subassembly");
    std::size_t vertex = 0, triangles = 0;
    for (std::size_t p = 0; p < w.assembly.parts().size(); ++p) {
      const TriangleMesh& mesh = *w.assembly.part(p).mesh;
      for (const Eigen::Vector3d& v : mesh.vertices) {
        Eigen::Vector3f p_W;
        std::memcpy(p_W.data(), points.data() + 12 * vertex++, 12);
        const Eigen::Vector3d truth = animation.states[k].X_WP[p] * v;
        ASSERT_LT((p_W.cast<double>() - truth).norm(), 1e-6 * (1 + truth.norm()));
      }
      for (std::size_t f = 0; f < mesh.faces.size(); ++f, ++triangles) {
        std::int32_t id = 0, group = 0;
        std::memcpy(&id, part.data() + 4 * triangles, 4);
        std::memcpy(&group, subassembly.data() + 4 * triangles, 4);
        ASSERT_EQ(id, static_cast<std::int32_t>(p));
        ASSERT_EQ(group, static_cast<std::int32_t>(w.analysis.subassembly_of[p]));
      }
    }
    EXPECT_EQ(points.size(), 12 * vertex);
    EXPECT_EQ(part.size(), 4 * triangles);
    EXPECT_NE(vtp.find("NumberOfPolys=\"" + std::to_string(triangles) + "\""), std::string::npos);
  }
  EXPECT_EQ(k, frames);
  // Nothing else was written, and no temporary file is left.
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    files += entry.is_regular_file();
  }
  EXPECT_EQ(files, frames + 1);
}

TEST(VtpSeries, GapsAreAStaticSecondPartOfEveryTimeStep) {
  const Assembly assembly =
      LoadAssembly(std::string(MECHANIST_SOURCE_DIR) + "/examples/sealed_enclosure/assembly.json");
  const Analysis analysis = Analyze(assembly);
  const Animation animation =
      SampleRun(assembly, PlanRun(assembly, analysis, std::nullopt, std::nullopt), 3);
  GapSearchOptions options;
  options.voxel = 2.0;
  const GapSearch search = FindGaps(assembly, options);
  ASSERT_EQ(search.gaps.size(), 1u);
  std::vector<std::int32_t> gap_of_face;
  const TriangleMesh surface = GapSurface(search, &gap_of_face);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "mechanist_vtp_gaps_test";
  std::filesystem::remove_all(dir);
  WriteVtpSeries(dir / "run.pvd", assembly, analysis, animation, &surface, &gap_of_face);
  const std::string pvd = ReadFile(dir / "run.pvd");
  std::size_t gap_parts = 0;
  for (std::size_t at = pvd.find("part=\"1\" file=\"run/gaps.vtp\""); at != std::string::npos;
       at = pvd.find("part=\"1\" file=\"run/gaps.vtp\"", at + 1)) {
    ++gap_parts;
  }
  EXPECT_EQ(gap_parts, 3u);
  const std::string gap = AppendedArray(ReadFile(dir / "run" / "gaps.vtp"), "gap");
  ASSERT_EQ(gap.size(), 4 * surface.faces.size());
  for (std::size_t f = 0; f < surface.faces.size(); ++f) {
    std::int32_t number = 0;
    std::memcpy(&number, gap.data() + 4 * f, 4);
    ASSERT_EQ(number, 1);
  }
}

}  // namespace
}  // namespace mechanist
