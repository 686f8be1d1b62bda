// The exported models in the real simulators: check_urdf (liburdfdom-tools) parses every
// URDF, and MuJoCo 2.2.2 loads every MJCF, runs its drivers for a simulated second and moves
// every part at the analysis' exact ratio (within 0.5%), with closed loops staying assembled.

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/load_assembly.h"
#include "reasoning/adjustment.h"
#include "reasoning/analysis.h"
#include "reasoning/simulation_model.h"
#include "run_command.h"

namespace mechanist {
namespace {

constexpr double kTwoPi = 6.283185307179586;

using testing::CommandResult;
using testing::RunCommand;

std::filesystem::path Folder(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("mechanist_simulators_" + std::to_string(::getpid())) / name;
  std::filesystem::create_directories(dir);
  return dir;
}

// A rack and pinion drawn as a kinematic sketch: a 20-tooth module-1 pinion turning in a
// frame drives a rack sliding in the frame's slot, pi * 20 mm per revolution.
const char* kRackSketch = R"({
  "mechanist": 1, "name": "rack and pinion sketch",
  "parts": [
    {"id": "frame", "ground": true, "features": [
      {"id": "bearing", "kind": "hole", "origin": [0, 0, -10], "axis": [0, 0, 1],
       "diameter": 6, "length": 10, "through": true},
      {"id": "guide", "kind": "slot", "origin": [-60, 16, 0], "axis": [1, 0, 0],
       "width": 4.1, "length": 120, "depth": 2, "normal": [0, 0, 1]}]},
    {"id": "pinion", "features": [
      {"id": "teeth", "kind": "gear", "origin": [0, 0, 0], "axis": [0, 0, 1],
       "teeth": 20, "module": 1, "length": 5},
      {"id": "shaft", "kind": "shaft", "origin": [0, 0, -10], "axis": [0, 0, 1],
       "diameter": 6, "length": 10, "retained": true}]},
    {"id": "rack", "features": [
      {"id": "teeth", "kind": "rack", "origin": [-50, 10, 0], "axis": [1, 0, 0],
       "module": 1, "length": 100, "normal": [0, -1, 0]},
      {"id": "key", "kind": "key", "origin": [-10, 16, 0], "axis": [1, 0, 0],
       "width": 4, "length": 20, "normal": [0, 0, 1]}]}
  ],
  "drivers": [{"id": "crank", "part": "pinion", "feature": "teeth", "motion": "rotation",
               "rate": 0.25}]
})";

struct Case {
  std::string name;
  std::filesystem::path file;
  std::string options;  ///< more export options
};

std::vector<Case> Cases() {
  std::vector<Case> cases;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(MECHANIST_SOURCE_DIR) + "/examples")) {
    cases.push_back({entry.path().filename().string(), entry.path() / "assembly.json", ""});
  }
  std::sort(cases.begin(), cases.end(),
            [](const Case& x, const Case& y) { return x.name < y.name; });
  const auto rack = Folder("rack_sketch") / "assembly.json";
  std::ofstream(rack) << kRackSketch;
  cases.push_back({"rack_sketch", rack, ""});
  // Real CAD exports: a Solid Edge pin joint (with the swept check's ranges) and the Onshape
  // robot hand (26 links, open meshes; the ranges skipped to keep the suite fast).
  const std::string real = std::string(MECHANIST_SHARED_DATA) + "/real/";
  cases.push_back(
      {"real_revolute_pin_solidedge", real + "revolute_pin_solidedge_chrono/assembly.stp", ""});
  cases.push_back({"real_robot_hand_onshape",
                   real + "robot_hand_finger_hinges_onshape/Assembly 1.step", "--no-limits"});
  return cases;
}

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class Simulators : public ::testing::TestWithParam<Case> {};

TEST_P(Simulators, ExportedModelsLoadAndMoveAtTheAnalysisRatios) {
  const Case& c = GetParam();
  const auto dir = Folder(c.name);
  const CommandResult exported =
      RunCommand(std::string(MECHANIST_EXE) + " export '" + c.file.string() + "' --urdf '" +
                 (dir / "model.urdf").string() + "' --mjcf '" + (dir / "model.xml").string() +
                 "' --drive " + c.options);
  ASSERT_EQ(exported.exit_code, 0) << exported.out;

  const CommandResult urdf =
      RunCommand(std::string(CHECK_URDF) + " '" + (dir / "model.urdf").string() + "'");
  EXPECT_EQ(urdf.exit_code, 0) << urdf.out;
  EXPECT_NE(urdf.out.find("Successfully Parsed XML"), std::string::npos) << urdf.out;

  char error[1000] = "";
  mjModel* m = mj_loadXML((dir / "model.xml").c_str(), nullptr, error, sizeof error);
  ASSERT_NE(m, nullptr) << error;
  mjData* d = mj_makeData(m);
  if (m->nkey > 0) mj_resetDataKeyframe(m, d, 0);
  const int steps = static_cast<int>(std::lround(1.0 / m->opt.timestep));
  for (int k = 0; k < steps; ++k) mj_step(m, d);

  // The analysis, as the command sees the file (adjustments solved and locked).
  if (c.file.extension() != ".json") return;  // STEP files: nothing drives them
  const Assembly assembly = Adjusted(LoadAssembly(c.file));
  const Analysis analysis = Analyze(assembly);
  const SimulationModel model = BuildSimulationModel(assembly, analysis);
  const DrivenMotion* motion = analysis.motion.ForExpectations();
  auto body_of = [&](std::size_t part) {
    for (std::size_t l = 0; l < model.links.size(); ++l) {
      for (const std::size_t p : model.links[l].parts) {
        if (p == part) return l == 0 ? 0 : mj_name2id(m, mjOBJ_BODY, model.links[l].name.c_str());
      }
    }
    return -1;
  };
  // The rate of a part about (or along) its analysed axis: rad/s or m/s. The axis is the
  // file pose's, carried along by the parent link's turn since then (a differential's pinion
  // spins about an axis that turns with the carrier; link frames start with the world's axes).
  auto rate_of = [&](std::size_t part, const PartMotion& pm) {
    const int body = body_of(part);
    EXPECT_GE(body, 0) << assembly.part(part).id;
    mjtNum v[6];
    mj_objectVelocity(m, d, mjOBJ_BODY, body, v, 0);
    const Eigen::Vector3d omega(v[0], v[1], v[2]);
    const Eigen::Vector3d velocity(v[3], v[4], v[5]);
    const int parent = body > 0 ? m->body_parentid[body] : 0;
    const Eigen::Matrix3d R_WParent =
        Eigen::Map<const Eigen::Matrix<mjtNum, 3, 3, Eigen::RowMajor>>(d->xmat + 9 * parent);
    const Eigen::Vector3d axis_W = R_WParent * pm.axis_W;
    return pm.kind == MotionKind::kTranslation ? velocity.dot(axis_W) : omega.dot(axis_W);
  };
  if (motion && motion->possible && assembly.drivers().size() >= 1) {
    // The reference: the first running driver's part, simulated, against its analysed rate.
    std::optional<std::size_t> reference;
    double reference_rate = 0.0;
    for (std::size_t p = 0; p < assembly.parts().size() && !reference; ++p) {
      const PartMotion& pm = motion->parts[p];
      const bool turns = pm.kind == MotionKind::kRotation || pm.kind == MotionKind::kScrew;
      if (!turns || pm.rotation.value() == 0.0) continue;
      reference = p;
      reference_rate = rate_of(p, pm) / (kTwoPi * pm.rotation.value());
    }
    ASSERT_TRUE(reference) << "no turning part";
    EXPECT_GT(std::abs(reference_rate), 0.5 * std::abs(assembly.drivers()[0].rate))
        << "the driver did not come up to speed";
    int checked = 0;
    for (std::size_t p = 0; p < assembly.parts().size(); ++p) {
      const PartMotion& pm = motion->parts[p];
      if (assembly.IsCompliant(p)) continue;
      const double simulated = pm.kind == MotionKind::kNone ? 0.0 : rate_of(p, pm);
      double expected = 0.0;
      if (pm.kind == MotionKind::kRotation || pm.kind == MotionKind::kScrew) {
        expected = kTwoPi * pm.rotation.value() * reference_rate;
      } else if (pm.kind == MotionKind::kTranslation) {
        expected = 1e-3 * pm.translation.value() * reference_rate;
      }
      const double scale = pm.kind == MotionKind::kTranslation ? std::abs(expected)
                                                               : std::abs(kTwoPi * reference_rate);
      EXPECT_NEAR(simulated, expected, 0.005 * std::max(std::abs(expected), 1e-3 * scale))
          << c.name << ": " << assembly.part(p).id << " (" << ToString(pm.kind) << ")";
      ++checked;
    }
    EXPECT_GT(checked, 0);
  }
  // Loops closed by connect constraints stay assembled.
  for (int r = 0; r < d->nefc; ++r) {
    if (d->efc_type[r] != mjCNSTR_EQUALITY || m->eq_type[d->efc_id[r]] != mjEQ_CONNECT) continue;
    EXPECT_LT(std::abs(d->efc_pos[r]), 1e-4) << c.name << ": loop constraint " << r;
  }
  mj_deleteData(d);
  mj_deleteModel(m);
}

INSTANTIATE_TEST_SUITE_P(Examples, Simulators, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return info.param.name;
                         });

}  // namespace
}  // namespace mechanist
