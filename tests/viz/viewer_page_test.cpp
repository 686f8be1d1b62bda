// The viewer page: the mechanism's data it carries (the drivers' paths are the ones StateAt
// uses), and the page itself in headless Chromium (tests/viz/viewer_browser.js): no console
// error, no network request, a picture that changes with the driver, poses equal to StateAt,
// a drag of the worm drive's motor shaft turning the wheel by -9 degrees a revolution, and a
// part held by tight bolts naming them.

#include "viz/viewer_page.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "io/load_assembly.h"
#include "io/text_edit.h"
#include "kernel/collision/collision_model.h"
#include "reasoning/analysis.h"
#include "reasoning/assembly_plan.h"
#include "reasoning/motion_run.h"
#include "reasoning/operation_check.h"
#include "run_command.h"

namespace mechanist {
namespace {

using nlohmann::json;

const std::string kWorm =
    std::string(MECHANIST_SOURCE_DIR) + "/examples/robot_hand_worm/assembly.json";

json PageData(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"mechanist-data\">";
  const std::size_t begin = html.find(open);
  EXPECT_NE(begin, std::string::npos);
  const std::size_t end = html.find("</script>", begin);
  return json::parse(html.substr(begin + open.size(), end - begin - open.size()));
}

ScrewPath PathOf(const json& screws) {
  ScrewPath path;
  for (const json& m : screws) {
    ScrewMotion s;
    s.point_W = Eigen::Vector3d(m["point"][0], m["point"][1], m["point"][2]);
    s.axis_W = Eigen::Vector3d(m["axis"][0], m["axis"][1], m["axis"][2]);
    s.turns_per_unit = m["turns"];
    s.travel_per_unit = m["travel"];
    path.screws.push_back(s);
  }
  return path;
}

// Column-major, as the page's matrices.
json Matrix(const RigidTransform& X) {
  const Eigen::Matrix4d m = X.matrix();
  return json(std::vector<double>(m.data(), m.data() + 16));
}

TEST(ViewerPage, CarriesTheDriversPathsThatStateAtUses) {
  const Assembly assembly = LoadAssembly(kWorm);
  const Analysis analysis = Analyze(assembly);
  const json data = PageData(ViewerHtml(assembly, analysis));
  ASSERT_EQ(data["parts"].size(), assembly.parts().size());
  ASSERT_EQ(data["drivers"].size(), 1u);
  EXPECT_EQ(data["pairs"].size(), analysis.pairs.size());
  // One mesh per mesh source (library parts generate one each).
  EXPECT_EQ(data["meshes"].size(), assembly.parts().size());
  const MotionRun run = PlanRun(assembly, analysis, 0, std::nullopt);
  for (const double s : {0.0, 0.37, 1.0}) {
    const AssemblyState state = StateAt(assembly, run, s);
    for (std::size_t p = 0; p < assembly.parts().size(); ++p) {
      const json& paths = data["drivers"][0]["paths"];
      const std::string key = std::to_string(p);
      const RigidTransform X = paths.contains(key)
                                   ? PathOf(paths[key]).At(s) * assembly.part(p).X_WP
                                   : assembly.part(p).X_WP;
      EXPECT_LT((X.matrix() - state.X_WP[p].matrix()).norm(), 1e-12) << p << " at " << s;
    }
  }
  // The motor shaft's drag turns; the motor body's is held by its two tight bolts.
  const auto motor_body = assembly.FindPart("motor_body").value();
  const json& held = data["drags"][motor_body]["turn"];
  EXPECT_FALSE(held["possible"]);
  ASSERT_EQ(held["holding"].size(), 2u);
  for (const json& i : held["holding"]) {
    EXPECT_EQ(analysis.pairs[i.get<std::size_t>()].fastening, PairFastening::kTight);
  }
  EXPECT_TRUE(data["drags"][assembly.FindPart("motor_shaft").value()]["turn"]["possible"]);
  // The file's expectations, evaluated as `mechanist check` does: all nine pass.
  ASSERT_EQ(data["expectations"].size(), assembly.expectations().size());
  for (const json& e : data["expectations"]) EXPECT_TRUE(e["passed"]) << e.dump();
}

// The oracle of a drag's range: every pair of parts swept (SweepPaths), the first contact
// ahead (and behind, unless a turn meets nothing ahead) of parts that no free motion moves
// (those yield: their contacts are no stops). Also says whether a yielding part was met.
struct RangeOracle {
  std::optional<OperationClash> ahead, behind;
  bool met_yielding = false;
};
RangeOracle OracleRange(const Assembly& assembly, const Analysis& analysis,
                        const CollisionModel& collision, const std::vector<ScrewPath>& paths,
                        double amount, bool turn) {
  std::vector<bool> yields(assembly.parts().size(), false);
  for (const FreeMotion& f : analysis.motion.mobility.free_motions) {
    yields[f.part] = true;
    for (const std::size_t p : f.parts) yields[p] = true;
  }
  RangeOracle oracle;
  const auto first = [&](double sense) -> std::optional<OperationClash> {
    std::vector<ScrewPath> run = paths;
    for (ScrewPath& path : run) {
      for (ScrewMotion& m : path.screws) {
        m.turns_per_unit *= sense;
        m.travel_per_unit *= sense;
      }
    }
    std::optional<OperationClash> stop;
    for (const OperationClash& c : SweepPaths(assembly, analysis, collision, run, amount).clashes) {
      const bool yielding = yields[c.part_a] || yields[c.part_b];
      oracle.met_yielding = oracle.met_yielding || yielding;
      if (!yielding && !stop) stop = c;
    }
    return stop;
  };
  oracle.ahead = first(1.0);
  if (oracle.ahead || !turn) oracle.behind = first(-1.0);
  return oracle;
}

// Drags that move the parts alike (the parts of one rigid body) share one range search; the
// searches run on every core, the progress reported one call at a time, 0 then a step per
// search up to 1; each drag shows the range of the oracle above (its time and parts). On the worm
// drive, and on pushed_by_contact, whose part a turns freely: dragging what meets it is not stopped
// by it.
TEST(ViewerPage, SearchesEachDistinctDragOnceWithItsProgress) {
  bool met_yielding = false;
  for (const std::string name : {"robot_hand_worm", "pushed_by_contact"}) {
    SCOPED_TRACE(name);
    const Assembly assembly =
        LoadAssembly(std::string(MECHANIST_SOURCE_DIR) + "/examples/" + name + "/assembly.json");
    const Analysis analysis = Analyze(assembly);
    ViewerOptions options;
    options.plan = false;
    std::vector<double> fractions;
    std::atomic<int> inside{0};
    bool overlapped = false;
    options.range_progress = [&](double fraction) {
      overlapped = overlapped || inside++ > 0;
      fractions.push_back(fraction);
      std::this_thread::sleep_for(std::chrono::milliseconds(2));  // time for another to come
      --inside;
    };
    const json data = PageData(ViewerHtml(assembly, analysis, options));
    const CollisionModel collision(assembly);
    const double reach = data["reach_mm"];
    std::set<std::string> motions;
    int drags = 0;
    for (std::size_t p = 0; p < assembly.parts().size(); ++p) {
      for (const bool turn : {true, false}) {
        const json& drag = data["drags"][p].value(turn ? "turn" : "slide", json());
        if (!drag.contains("paths")) continue;
        ++drags;
        motions.insert(fmt::format("{} {}", turn, drag["paths"].dump()));
        std::vector<ScrewPath> paths(assembly.parts().size());
        for (const auto& [part, screws] : drag["paths"].items()) {
          paths[std::stoul(part)] = PathOf(screws);
        }
        const RangeOracle range =
            OracleRange(assembly, analysis, collision, paths, turn ? 1.0 : reach, turn);
        met_yielding = met_yielding || range.met_yielding;
        SCOPED_TRACE(fmt::format("{} {}", assembly.part(p).id, turn ? "turn" : "slide"));
        for (const auto& [side, contact] :
             {std::pair{"ahead", range.ahead}, {"behind", range.behind}}) {
          ASSERT_EQ(drag[side].is_null(), !contact.has_value()) << side;
          if (contact) {
            EXPECT_NEAR(drag[side]["at"].get<double>(), contact->at, 1e-12) << side;
            EXPECT_EQ(drag[side]["parts"], json::array({contact->part_a, contact->part_b})) << side;
          }
        }
      }
    }
    EXPECT_GE(drags, static_cast<int>(motions.size()));
    ASSERT_EQ(fractions.size(), motions.size() + 1);  // 0, then one per search
    EXPECT_EQ(fractions.front(), 0.0);
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    ASSERT_FALSE(fractions.empty());
    EXPECT_EQ(fractions.back(), 1.0);
    EXPECT_FALSE(overlapped);
    if (name == "robot_hand_worm") {
      EXPECT_GT(drags, static_cast<int>(motions.size()));  // some drags move alike
    }
  }
  EXPECT_TRUE(met_yielding);  // the oracle met a part that yields, which the viewer skips
}

TEST(ViewerPage, RunsSeveralDriversAlsoAllTogether) {
  // The planetary differential sketch: two drivers, then both at their rates.
  const Assembly assembly = LoadAssembly(std::string(MECHANIST_SOURCE_DIR) +
                                         "/examples/planetary_differential_sketch/assembly.json");
  const Analysis analysis = Analyze(assembly);
  ASSERT_EQ(assembly.drivers().size(), 2u);
  const json drivers = PageData(ViewerHtml(assembly, analysis))["drivers"];
  ASSERT_EQ(drivers.size(), 3u);
  EXPECT_FALSE(drivers[0]["together"]);
  EXPECT_TRUE(drivers[2]["together"]);
  EXPECT_EQ(drivers[2]["id"], "all together");
  const MotionRun run = PlanRun(assembly, analysis, std::nullopt, std::nullopt);
  EXPECT_EQ(drivers[2]["amount"], run.amount);
  const double s = 0.4 * run.amount;
  const AssemblyState state = StateAt(assembly, run, s);
  for (std::size_t p = 0; p < assembly.parts().size(); ++p) {
    const json& paths = drivers[2]["paths"];
    const std::string key = std::to_string(p);
    const RigidTransform X = paths.contains(key) ? PathOf(paths[key]).At(s) * assembly.part(p).X_WP
                                                 : assembly.part(p).X_WP;
    EXPECT_LT((X.matrix() - state.X_WP[p].matrix()).norm(), 1e-12) << p;
  }
}

TEST(ViewerPage, ShowsClashesAtRestAndEnclosedGaps) {
  // Two plates overlapping by 3 mm: a clash, its parts and a point inside both.
  const Assembly clash = LoadAssemblyText(R"({"mechanist": 1, "parts": [
    {"id": "a", "ground": true,
     "library": {"kind": "plate", "length": 20, "width": 20, "thickness": 5}},
    {"id": "b", "library": {"kind": "plate", "length": 20, "width": 20, "thickness": 5},
     "pose": {"position": [5, 0, 2]}}]})",
                                          "clash.json");
  const json data = PageData(ViewerHtml(clash, Analyze(clash)));
  ASSERT_EQ(data["clashes"].size(), 1u);
  EXPECT_EQ(data["clashes"][0]["parts"], json({0, 1}));
  EXPECT_GT(data["clashes"][0]["depth"].get<double>(), 1.0);
  EXPECT_TRUE(data["gaps"].empty());  // not asked for
  // The sealed enclosure's cavity at 2 mm voxels, as `mechanist gaps` reports it.
  const Assembly sealed =
      LoadAssembly(std::string(MECHANIST_SOURCE_DIR) + "/examples/sealed_enclosure/assembly.json");
  ViewerOptions options;
  options.gap_voxel = 2.0;
  const json gaps = PageData(ViewerHtml(sealed, Analyze(sealed), options))["gaps"];
  ASSERT_EQ(gaps.size(), 1u);
  EXPECT_NEAR(gaps[0]["volume"].get<double>(), 184680.0, gaps[0]["error"].get<double>());
  EXPECT_FALSE(gaps[0]["triangles"].get<std::string>().empty());
}

std::vector<std::uint8_t> Base64Bytes(const std::string& text) {
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<std::uint8_t> bytes;
  std::uint32_t bits = 0;
  int count = 0;
  for (const char c : text) {
    if (c == '=') break;
    bits = bits << 6 | static_cast<std::uint32_t>(alphabet.find(c));
    count += 6;
    if (count >= 8) {
      count -= 8;
      bytes.push_back(static_cast<std::uint8_t>(bits >> count & 0xff));
    }
  }
  return bytes;
}

template <typename T>
std::vector<T> Values(const std::string& base64) {
  const std::vector<std::uint8_t> bytes = Base64Bytes(base64);
  std::vector<T> values(bytes.size() / sizeof(T));
  std::memcpy(values.data(), bytes.data(), values.size() * sizeof(T));
  return values;
}

TEST(ViewerPage, StoresEachMeshOnceQuantisedWithinHalfAStep) {
  const Assembly assembly = LoadAssembly(kWorm);
  const json data = PageData(ViewerHtml(assembly, Analyze(assembly)));
  for (std::size_t p = 0; p < assembly.parts().size(); ++p) {
    const TriangleMesh& mesh = *assembly.part(p).mesh;
    const json& m = data["meshes"][data["parts"][p]["mesh"].get<std::size_t>()];
    const std::vector<std::uint16_t> q = Values<std::uint16_t>(m["positions"]);
    ASSERT_EQ(q.size(), 3 * mesh.vertices.size());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      for (int k = 0; k < 3; ++k) {
        const double step = m["step"][k];
        const double x = m["min"][k].get<double>() + q[3 * v + k] * step;
        EXPECT_LE(std::abs(x - mesh.vertices[v][k]), 0.5 * step + 1e-12) << p << " " << v;
      }
    }
    ASSERT_EQ(m["index_bytes"], 2);  // every part here has fewer than 65,536 vertices
    const std::vector<std::uint16_t> indices = Values<std::uint16_t>(m["indices"]);
    ASSERT_EQ(indices.size(), 3 * mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
      for (int k = 0; k < 3; ++k) EXPECT_EQ(indices[3 * f + k], mesh.faces[f][k]);
    }
  }
}

TEST(ViewerPage, CarriesTheAssemblySequence) {
  const Assembly assembly =
      LoadAssembly(std::string(MECHANIST_SOURCE_DIR) + "/examples/pushed_by_contact/assembly.json");
  const Analysis analysis = Analyze(assembly);
  const json sequence = PageData(ViewerHtml(assembly, analysis))["assembly"];
  const AssemblyPlan plan = PlanAssembly(assembly, analysis, CollisionModel(assembly));
  EXPECT_EQ(sequence["assemblable"], plan.assemblable);
  ASSERT_EQ(sequence["steps"].size(), plan.steps.size() + plan.unplaced.size());
  for (std::size_t k = 0; k < sequence["steps"].size(); ++k) {
    const json& step = sequence["steps"][k];
    const bool placed = k < plan.steps.size();
    const InsertionStep& expected = placed ? plan.steps[k] : plan.unplaced[k - plan.steps.size()];
    EXPECT_EQ(step["part"], expected.part);
    EXPECT_EQ(step["placed"], placed);
    EXPECT_EQ(step["clear"], expected.clear);
    EXPECT_EQ(step["travel"], expected.travel);
    ASSERT_EQ(step["blocked_by"].size(), expected.blocked_by.size());
    for (std::size_t o = 0; o < expected.blocked_by.size(); ++o) {
      EXPECT_EQ(step["blocked_by"][o]["part"], expected.blocked_by[o].part);
      EXPECT_EQ(step["blocked_by"][o]["travel"], expected.blocked_by[o].travel);
      EXPECT_EQ(step["blocked_by"][o]["clash_at_rest"], expected.blocked_by[o].clash_at_rest);
      EXPECT_EQ(step["blocked_by"][o]["held_by"].is_null(), !expected.blocked_by[o].held_by);
    }
  }
  // Not planned when not asked for: the stepper says so.
  ViewerOptions options;
  options.plan = false;
  EXPECT_TRUE(PageData(ViewerHtml(assembly, analysis, options))["assembly"].is_null());
}

// pushed_by_contact with shaft a fixed to the ground: the motor's arm runs its lug into b.
Assembly PushedWithAFixed() {
  const std::string pushed =
      std::string(MECHANIST_SOURCE_DIR) + "/examples/pushed_by_contact/assembly.json";
  return LoadAssemblyText(testing::Replace(testing::ReadText(pushed), R"({"id": "a", "library")",
                                           R"({"id": "a", "ground": true, "library")"),
                          pushed);
}

TEST(ViewerPage, CarriesTheClashesOfEachDriversRun) {
  const Assembly assembly = PushedWithAFixed();
  const Analysis analysis = Analyze(assembly);
  const json driver = PageData(ViewerHtml(assembly, analysis))["drivers"][0];
  // As `mechanist sweep` finds them: the lug runs into b, which the ground holds.
  const OperationCheck sweep =
      CheckOperation(assembly, analysis, CollisionModel(assembly), 0, std::nullopt);
  ASSERT_FALSE(sweep.clashes.empty());
  ASSERT_EQ(driver["clashes"].size(), sweep.clashes.size());
  for (std::size_t k = 0; k < sweep.clashes.size(); ++k) {
    EXPECT_EQ(driver["clashes"][k]["at"], sweep.clashes[k].at);
    EXPECT_EQ(driver["clashes"][k]["parts"],
              json({sweep.clashes[k].part_a, sweep.clashes[k].part_b}));
  }
  // As the file stands, b is free and the lug pushes it along: no clash.
  const Assembly free =
      LoadAssembly(std::string(MECHANIST_SOURCE_DIR) + "/examples/pushed_by_contact/assembly.json");
  EXPECT_TRUE(PageData(ViewerHtml(free, Analyze(free)))["drivers"][0]["clashes"].empty());
  // Without the swept checks, no clashes of runs.
  ViewerOptions options;
  options.ranges = false;
  EXPECT_FALSE(PageData(ViewerHtml(assembly, analysis, options))["drivers"][0].contains("clashes"));
}

TEST(ViewerPage, SaysWhereThreeJsIsMissing) {
  const Assembly assembly = LoadAssembly(kWorm);
  ViewerOptions options;
  options.three_dir = "/nonexistent";
  try {
    ViewerHtml(assembly, Analyze(assembly), options);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("libjs-three"), std::string::npos) << e.what();
  }
}

// Runs tests/viz/viewer_browser.js on `page` in `dir` with `checks`: "" when every check
// passed, else what the script printed.
std::string RunBrowser(const std::filesystem::path& dir, const std::string& page,
                       const json& checks) {
  const auto checks_file = dir / (page + ".checks.json");
  std::ofstream(checks_file) << checks.dump();
  const auto run = testing::RunCommand(
      "NODE_PATH='" + std::string(MECHANIST_PUPPETEER) + "' '" + MECHANIST_NODE + "' '" +
      MECHANIST_SOURCE_DIR + "/tests/viz/viewer_browser.js' '" + MECHANIST_CHROMIUM + "' '" +
      (dir / page).string() + "' '" + checks_file.string() + "' '" + dir.string() + "'");
  const bool passed = run.exit_code == 0 && run.out.find("all checks passed") != std::string::npos;
  return passed ? "" : run.out;
}

TEST(ViewerPage, WorksInABrowser) {
  const std::string puppeteer = MECHANIST_PUPPETEER, chromium = MECHANIST_CHROMIUM;
  if (puppeteer.empty() || chromium.empty() || std::string(MECHANIST_NODE).empty()) {
    GTEST_SKIP() << "puppeteer-core, chromium or node not configured (scripts/test.sh does)";
  }
  const Assembly assembly = LoadAssembly(kWorm);
  const Analysis analysis = Analyze(assembly);
  const auto dir =
      std::filesystem::temp_directory_path() / ("mechanist_viewer_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "page.html") << ViewerHtml(assembly, analysis);
  // The poses the page must show at s = 0.37 of the motor's run: StateAt's.
  const double s = 0.37;
  const AssemblyState state = StateAt(assembly, PlanRun(assembly, analysis, 0, std::nullopt), s);
  json poses = json::object();
  for (std::size_t p = 0; p < assembly.parts().size(); ++p) {
    poses[assembly.part(p).id] = Matrix(state.X_WP[p]);
  }
  // The pair graph: a node per subassembly, an edge per pair joining two of them.
  std::size_t between = 0;
  for (const Pair& p : analysis.pairs) {
    between += analysis.subassembly_of[p.a.part] != analysis.subassembly_of[p.b.part];
  }
  const json checks = {{"poses", {{"driver", 0}, {"s", s}, {"parts", poses}}},
                       {"graph", {{"nodes", analysis.subassemblies.size()}, {"edges", between}}},
                       {"drag",
                        {{"part", "motor_shaft"},
                         {"turns", 1},
                         {"follower", "worm_wheel"},
                         {"axis", {0, 0, 1}},
                         {"degrees", -9}}},
                       {"held", "motor_body"},
                       // Large pages draw still parts from a cache while others move.
                       {"cache", {{"part", "motor_shaft"}, {"turns", 0.3}}},
                       // 200 px of a 400 px revolution: half a turn of the worm, 4.5 degrees
                       // of the wheel.
                       {"mouse",
                        {{"part", "worm"},
                         {"pixels", 200},
                         {"follower", "worm_wheel"},
                         {"axis", {0, 0, 1}},
                         {"degrees", 4.5}}}};
  EXPECT_EQ(RunBrowser(dir, "page.html", checks), "") << "worm drive";

  // A drag that stops, and a run into a clash: with shaft a fixed to the ground, the arm's
  // lug meets block b.
  const Assembly stopped = PushedWithAFixed();
  std::ofstream(dir / "stop.html") << ViewerHtml(stopped, Analyze(stopped));
  const json stop = {{"stop", {{"part", "d"}, {"turns", 0.5}, {"meets", {"b", "lug"}}}},
                     {"run", {{"driver", 0}, {"s", 0.5}, {"meets", {"b", "lug"}}}}};
  EXPECT_EQ(RunBrowser(dir, "stop.html", stop), "") << "a drag that stops";

  // A slide in inches: the page's poses are StateAt's in the file's length units.
  const Assembly slider = LoadAssemblyText(R"({"mechanist": 1, "units": {"length": "in"},
    "parts": [
      {"id": "frame", "ground": true,
       "library": {"kind": "plate", "length": 5, "width": 2, "thickness": 0.2},
       "pose": {"position": [-2, -0.4, -0.2]}, "features": [{"id": "guide", "kind": "slot",
        "origin": [0, 1.0, 0.2], "axis": [1, 0, 0], "width": 0.16, "length": 5, "depth": 0.08,
        "normal": [0, 0, 1]}]},
      {"id": "block", "library": {"kind": "plate", "length": 0.8, "width": 0.5, "thickness": 0.3},
       "pose": {"position": [-0.4, 0.35, 0]}, "features": [{"id": "key", "kind": "key", "origin": [0, 0.25, 0],
        "axis": [1, 0, 0], "width": 0.157, "length": 0.8, "normal": [0, 0, 1]}]}],
    "drivers": [{"id": "push", "part": "block", "feature": "key", "motion": "translation",
                 "rate": 1, "amount": 2}]})",
                                           dir / "slider.json");
  const Analysis slid = Analyze(slider);
  std::ofstream(dir / "slider.html") << ViewerHtml(slider, slid);
  const AssemblyState at = StateAt(slider, PlanRun(slider, slid, 0, std::nullopt), 0.5);
  ASSERT_NEAR((at.X_WP[1].translation() - slider.part(1).X_WP.translation()).norm(), 12.7,
              1e-9);  // half an inch
  const json slide = {
      {"poses",
       {{"driver", 0},
        {"s", 0.5},
        {"parts", {{"frame", Matrix(at.X_WP[0])}, {"block", Matrix(at.X_WP[1])}}}}}};
  EXPECT_EQ(RunBrowser(dir, "slider.html", slide), "") << "a slide in inches";

  // All drivers together: the planetary differential's two drivers at their rates.
  const Assembly differential = LoadAssembly(
      std::string(MECHANIST_SOURCE_DIR) + "/examples/planetary_differential_sketch/assembly.json");
  const Analysis both = Analyze(differential);
  std::ofstream(dir / "differential.html") << ViewerHtml(differential, both);
  const AssemblyState together =
      StateAt(differential, PlanRun(differential, both, std::nullopt, std::nullopt), 0.3);
  json together_poses = json::object();
  for (std::size_t p = 0; p < differential.parts().size(); ++p) {
    together_poses[differential.part(p).id] = Matrix(together.X_WP[p]);
  }
  const json all = {{"poses", {{"driver", 2}, {"s", 0.3}, {"parts", together_poses}}}};
  EXPECT_EQ(RunBrowser(dir, "differential.html", all), "") << "all drivers together";

  // The assembly stepper: as the file stands, shaft d (with its arm and lug) cannot go in; its
  // step stops where it meets the top. Block b and nut c go in as a sub-assembly: the nut set
  // on the block apart shows with the block alone, then both move in together.
  const Assembly blocked =
      LoadAssembly(std::string(MECHANIST_SOURCE_DIR) + "/examples/pushed_by_contact/assembly.json");
  std::ofstream(dir / "steps.html") << ViewerHtml(blocked, Analyze(blocked));
  const json step = {{"step", {{"part", "d"}, {"obstacle", "top"}}},
                     {"subassembly",
                      {{"part", "b"},
                       {"apart", "c"},
                       {"alone", {"b", "c"}},
                       {"shot", "viewer_subassembly_apart.png"}}}};
  EXPECT_EQ(RunBrowser(dir, "steps.html", step), "") << "a blocked insertion";

  // A pin the file leaves out in the way: the latch's step stops on it, and the pin, in place
  // since before the first step, is drawn in red.
  const Assembly latch = LoadAssembly(std::string(MECHANIST_SOURCE_DIR) +
                                      "/examples/clevis_latch_blocked_by_pin/assembly.json");
  std::ofstream(dir / "latch.html") << ViewerHtml(latch, Analyze(latch));
  const json on_pin = {{"step",
                        {{"part", "latch"},
                         {"obstacle", "the pin through cheek_a/pivot, cheek_b/pivot, lever/pivot"},
                         {"red_pins", 1},
                         {"shot", "viewer_step_pin.png"}}}};
  EXPECT_EQ(RunBrowser(dir, "latch.html", on_pin), "") << "a step blocked by a pin";

  // A real export (build123d's print-in-place hinge, ../shared/data/real): printed in place,
  // its lid cannot go in; the stepper shows where it meets the base.
  const Assembly hinge = LoadAssembly(std::string(MECHANIST_SHARED_DATA) +
                                      "/real/hinge_clamshell_build123d/clamshell_full.step");
  std::ofstream(dir / "hinge.html") << ViewerHtml(hinge, Analyze(hinge));
  const json printed = {{"step", {{"part", "COMPOUND"}, {"obstacle", "COMPOUND_solid2"}}}};
  EXPECT_EQ(RunBrowser(dir, "hinge.html", printed), "") << "a real STEP export";

  // The Onshape reducer's spacers lie 0.55 mm deep in its cover as exported: a spacer's row
  // says the clash holds it where it is, within the sub-assembly of the cover that they move
  // in with; put in apart, the spacer shows with the cover and the other spacer only. (The
  // drags' ranges, not looked at here, left out.)
  const Assembly reducer = LoadAssembly(std::string(MECHANIST_SHARED_DATA) +
                                        "/real/cycloid_7pin_6lobe_onshape/Full Assembly.step");
  ViewerOptions no_ranges;
  no_ranges.ranges = false;
  std::ofstream(dir / "reducer.html") << ViewerHtml(reducer, Analyze(reducer), no_ranges);
  const json stuck = {{"pins",
                       {{"part", "Full_Assembly.Tiny_spacer"},
                        {"before", 0},
                        {"after", 0},
                        {"error", true},
                        {"words",
                         {"apart, into the sub-assembly of step", "blocked by",
                          "where it is (they clash there)", "(cannot be placed)"}}}},
                      {"subassembly",
                       {{"part", "Full_Assembly.Top_centering_cover"},
                        {"apart", "Full_Assembly.Tiny_spacer"},
                        {"alone",
                         {"Full_Assembly.Top_centering_cover", "Full_Assembly.Tiny_spacer",
                          "Full_Assembly.Tiny_spacer_2"}}}}};
  EXPECT_EQ(RunBrowser(dir, "reducer.html", stuck), "") << "a part stuck by a clash at rest";

  // A lever in a clevis whose pin the file leaves out: the pin shows in place once the lever
  // is in, entering from cheek_a's side (the guard covers cheek_b's).
  const std::string clevis_file =
      std::string(MECHANIST_SOURCE_DIR) + "/examples/clevis_pin_left_out/assembly.json";
  const Assembly clevis = LoadAssembly(clevis_file);
  std::ofstream(dir / "clevis.html") << ViewerHtml(clevis, Analyze(clevis));
  const json pin = {{"pins",
                     {{"part", "lever"},
                      {"before", 0},
                      {"after", 1},
                      {"error", false},
                      {"words",
                       "then the pin through cheek_a/pivot, cheek_b/pivot, lever/pivot: "
                       "clear"}}}};
  EXPECT_EQ(RunBrowser(dir, "clevis.html", pin), "") << "a pin the file leaves out";

  // The same clevis with a second guard against cheek_a's outside: the pin can enter from
  // neither end, so the lever cannot be placed; its row says that only its pin keeps it out,
  // and no pin shows. Both ends stop the pin as near its place, so the attempt reported is the
  // first, along its first hole's axis (-x), which the guard on cheek_b's side stops.
  const std::string guarded_text =
      testing::Replace(testing::ReadText(clevis_file), R"(    {"id": "lever",)",
                       R"(    {"id": "guard_a", "ground": true,
     "library": {"kind": "plate", "length": 40, "width": 20, "thickness": 5},
     "pose": {"position": [-15, 0, 40], "rotation": {"axis": [0, 1, 0], "angle": 90}}},
    {"id": "lever",)");
  const Assembly guarded = LoadAssemblyText(guarded_text, clevis_file);
  std::ofstream(dir / "guarded.html") << ViewerHtml(guarded, Analyze(guarded));
  const json unplaced = {{"pins",
                          {{"part", "lever"},
                           {"before", 0},
                           {"after", 0},
                           {"error", true},
                           {"words",
                            {"clear; its pin through cheek_a/pivot, cheek_b/pivot, lever/pivot: "
                             "blocked by guard after",
                             "(cannot be placed)"}}}}};
  EXPECT_EQ(RunBrowser(dir, "guarded.html", unplaced), "") << "a pin that cannot go in";
}

}  // namespace
}  // namespace mechanist
