// Pair recognition, subassemblies and the whole analysis (recognition, graph, motion,
// mobility) on synthetic assemblies of growing size. Each cell is a ground plate with a
// bearing and a tapped hole, a shaft turning in the bearing, a gear pressed on the shaft, and
// a cover clamped to the plate by a tight bolt; the first gear is driven. Layouts: rows of 200
// cells 100 mm apart (a gear chain per row; undriven rows are free motions), one chain of
// all cells, and a square grid whose gears mesh with all four neighbours (closed loops,
// redundant meshes), and a planetary array (stages of ring, sun, three planets on a carrier
// whose output drives the next sun). Prints times per size and the growth factor of the full
// analysis, warm (after an analysis of the same assembly) and cold (after the caches are
// flushed): medians and minima of 11 rounds, each round running every size in turn.
//
// Usage: recognition_bench [--default-heap] [max_parts]   (default 100000)
//        recognition_bench --grid-once N    one analysis of the grid layout of N parts, untimed
//        recognition_bench --grid-setup N   only its setup (for valgrind: the difference of the
//                                           two is the analysis)
//
// The heap keeps the memory that an analysis frees for the next one (mallopt), as a program
// that analyses many times would: by default glibc returns large blocks to the system, and
// each run then pays a page fault for every page it touches again (12-15 us each on the
// project's virtual machine), which swamps the analysis above about 10,000 parts and varies
// from run to run. --default-heap measures with glibc's defaults.

#include <malloc.h>  // mallopt

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "reasoning/analysis.h"
#include "reasoning/pair_graph.h"
#include "reasoning/pair_recognition.h"

namespace mechanist {
namespace {

constexpr int kPartsPerCell = 5;
constexpr int kCellsPerRow = 200;

Feature Make(const std::string& id, FeatureKind kind, Eigen::Vector3d origin,
             Eigen::Vector3d axis) {
  Feature f;
  f.id = id;
  f.kind = kind;
  f.origin = origin;
  f.axis = axis;
  return f;
}

// One box mesh for every part, large enough to hold every feature origin of the cells and
// stages below (the description checks would otherwise report each feature as outside its
// part, which real assemblies do not do).
std::shared_ptr<const TriangleMesh> BenchBox() {
  auto box = std::make_shared<TriangleMesh>();
  for (int i = 0; i < 8; ++i) {
    box->vertices.emplace_back((i & 1) ? 21 : -21, (i & 2) ? 31 : -21, (i & 4) ? 31 : -5);
  }
  box->faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return box;
}

// Appends a part with the bench box mesh at a translation.
void AddBenchPart(AssemblySpec* spec, const std::string& id, std::vector<Feature> features,
                  const Eigen::Vector3d& at, bool ground) {
  static const std::shared_ptr<const TriangleMesh> mesh = BenchBox();
  Part p;
  p.id = id;
  p.mesh = mesh;
  p.mesh_source = "bench:box";
  p.X_WP = RigidTransform::Translation(at);
  p.ground = ground;
  p.features = std::move(features);
  spec->parts.push_back(std::move(p));
}

Assembly Synthetic(int cells, int per_row, double row_pitch) {
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ(), down = -up;
  AssemblySpec spec;
  spec.parts.reserve(static_cast<std::size_t>(cells) * kPartsPerCell);
  auto part = [&](const std::string& id, std::vector<Feature> features, Eigen::Vector3d at,
                  bool ground = false) {
    AddBenchPart(&spec, id, std::move(features), at, ground);
  };
  for (int c = 0; c < cells; ++c) {
    // Gears of 20 teeth, module 2: neighbours 40 mm apart along x mesh.
    const Eigen::Vector3d at(40.0 * (c % per_row), row_pitch * (c / per_row), 0);
    const std::string n = std::to_string(c);
    Feature bearing = Make("bearing", FeatureKind::kHole, {0, 0, 10}, down);
    bearing.diameter = 6.02, bearing.length = 10, bearing.retained = true;
    Feature tapped = Make("tapped", FeatureKind::kTappedHole, {0, 30, 10}, down);
    tapped.diameter = 6, tapped.pitch = 1, tapped.length = 10;
    part("plate" + n, {bearing, tapped}, at, true);
    Feature shaft = Make("shaft", FeatureKind::kShaft, {0, 0, 30}, down);
    shaft.diameter = 6, shaft.length = 30;
    part("shaft" + n, {shaft}, at);
    Feature teeth = Make("teeth", FeatureKind::kGear, {0, 0, 15}, up);
    teeth.teeth = 20, teeth.module = 2, teeth.length = 8;
    Feature bore = Make("bore", FeatureKind::kHole, {0, 0, 15}, up);
    bore.diameter = 5.9, bore.length = 8, bore.through = true;
    part("gear" + n, {teeth, bore}, at);
    Feature cover_hole = Make("hole", FeatureKind::kHole, {0, 30, 15}, down);
    cover_hole.diameter = 6.6, cover_hole.length = 5;
    part("cover" + n, {cover_hole}, at);
    Feature thread = Make("thread", FeatureKind::kThread, {0, 30, 15}, down);
    thread.diameter = 6, thread.pitch = 1, thread.length = 12;
    part("bolt" + n, {thread}, at);
  }
  Driver motor;
  motor.id = "motor";
  motor.feature = {2, 0};  // gear0/teeth
  spec.drivers.push_back(motor);
  return Assembly(std::move(spec));
}

// A planetary array: gearboxes of ten stages stacked along z, side by side 200 mm apart. A
// stage is a fixed ring gear (60 teeth), a sun (20), three planets (20) on pins of a carrier
// that turns on a short ground axle, and the carrier's output shaft pressed into the next
// stage's sun; the first sun of each gearbox turns on its own ground axle. Seven parts a
// stage; the first gearbox is driven (it divides by 4^10), the others are free motions.
// Every stage closes three gear loops: two redundant constraints a stage.
constexpr int kPartsPerStage = 7;

Assembly PlanetaryArray(int stages) {
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ(), down = -up;
  AssemblySpec spec;
  spec.parts.reserve(static_cast<std::size_t>(stages) * kPartsPerStage + 1);
  auto part = [&](const std::string& id, std::vector<Feature> features, Eigen::Vector3d at,
                  bool ground = false) {
    AddBenchPart(&spec, id, std::move(features), at, ground);
  };
  auto gear = [&](const std::string& id, int teeth, Eigen::Vector3d at, bool internal) {
    Feature g = Make(id, FeatureKind::kGear, at, up);
    g.teeth = teeth, g.module = 1, g.length = 8, g.internal = internal;
    return g;
  };
  auto cylinder = [&](const std::string& id, FeatureKind kind, Eigen::Vector3d at,
                      Eigen::Vector3d axis, double diameter, double length, bool retained) {
    Feature f = Make(id, kind, at, axis);
    f.diameter = diameter, f.length = length, f.retained = retained;
    return f;
  };
  constexpr int kStagesPerBox = 10;
  const double kPi = 3.14159265358979323846;
  int sun0 = 0;
  for (int s = 0; s < stages; ++s) {
    const std::string n = std::to_string(s);
    const int k = s % kStagesPerBox;
    const Eigen::Vector3d z(200.0 * (s / kStagesPerBox), 0, 30.0 * k);
    if (k == 0) {
      Feature input = cylinder("shaft", FeatureKind::kShaft, {0, 0, -4}, up, 6, 10, true);
      part("input_axle" + n, {input}, z, true);
    }
    part("ring" + n, {gear("teeth", 60, {0, 0, 0}, true)}, z, true);
    // The first sun turns on the input axle; the others are pressed on the previous output.
    if (s == 0) sun0 = static_cast<int>(spec.parts.size());
    part("sun" + n,
         {gear("teeth", 20, {0, 0, 0}, false),
          cylinder("bore", FeatureKind::kHole, {0, 0, 0}, up, k == 0 ? 6.02 : 5.9, 8, false)},
         z);
    std::vector<Feature> carrier = {
        cylinder("center", FeatureKind::kHole, {0, 0, 12}, down, 6.02, 4, true),
        cylinder("output", FeatureKind::kShaft, {0, 0, 12}, up, 6, 22, false)};
    for (int j = 0; j < 3; ++j) {
      const double a = 2 * kPi * j / 3;
      const Eigen::Vector3d at(20 * std::cos(a), 20 * std::sin(a), 0);
      const std::string pj = std::to_string(j);
      carrier.push_back(cylinder("pin" + pj, FeatureKind::kShaft, at + Eigen::Vector3d(0, 0, 10),
                                 down, 4, 10, true));
      part("planet" + n + "_" + pj,
           {gear("teeth", 20, at, false),
            cylinder("bore", FeatureKind::kHole, at + Eigen::Vector3d(0, 0, 8), down, 4.02, 8,
                     true)},
           z);
    }
    part("carrier" + n, std::move(carrier), z);
    part("axle" + n, {cylinder("shaft", FeatureKind::kShaft, {0, 0, 11.5}, down, 6, 3, true)}, z,
         true);
  }
  Driver motor;
  motor.id = "motor";
  motor.feature = {static_cast<std::size_t>(sun0), 0};  // sun0/teeth
  spec.drivers.push_back(motor);
  return Assembly(std::move(spec));
}

constexpr int kRuns = 11;

// Writes a buffer larger than the caches, so that what a run reads next comes from memory.
void EvictCaches() {
  static std::vector<char> buffer(512u << 20);
  for (std::size_t i = 0; i < buffer.size(); i += 64) buffer[i] = static_cast<char>(buffer[i] + 1);
  volatile char sink = buffer[buffer.size() / 2];
  (void)sink;
}

double Minimum(std::vector<double> v) { return *std::min_element(v.begin(), v.end()); }

double Median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

}  // namespace
}  // namespace mechanist

int main(int argc, char** argv) {
  using namespace mechanist;
  if (argc == 3 &&
      (std::string(argv[1]) == "--grid-once" || std::string(argv[1]) == "--grid-setup")) {
    const int cells = std::atoi(argv[2]) / kPartsPerCell;
    const Assembly assembly = Synthetic(cells, static_cast<int>(std::ceil(std::sqrt(cells))), 40.0);
    if (std::string(argv[1]) == "--grid-once") {
      std::printf("%zu pairs\n", Analyze(assembly).pairs.size());
    }
    return 0;
  }
  bool default_heap = false;
  if (argc > 1 && std::string(argv[1]) == "--default-heap") {
    default_heap = true;
    --argc, ++argv;
  }
  if (!default_heap) {
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    mallopt(M_TOP_PAD, 64 << 20);
  }
  std::printf("heap: %s\n", default_heap ? "glibc defaults" : "freed memory kept (mallopt)");
  const int max_parts = argc > 1 ? std::atoi(argv[1]) : 100000;
  struct Layout {
    const char* name;
    int per_row;  // 0: all cells in one row; -1: a square grid; -2: a planetary array
    double row_pitch;
  };
  for (const Layout layout : {Layout{"rows", kCellsPerRow, 100.0}, Layout{"chain", 0, 100.0},
                              Layout{"grid", -1, 40.0}, Layout{"planetary", -2, 0.0}}) {
    std::printf("layout %s\n%9s %8s %9s %8s %7s %6s %9s | %8s %7s %8s %7s | %8s %7s %8s %7s\n",
                layout.name, "parts", "pairs", "subassem.", "recog_ms", "graph", "dof", "redundant",
                "warm_ms", "growth", "warm_min", "growth", "cold_ms", "growth", "cold_min",
                "growth");
    struct Size {
      Size(int n, Assembly a) : parts(n), assembly(std::move(a)) {}
      int parts;
      Assembly assembly;
      std::vector<double> recognise_ms, graph_ms, all_ms, cold_ms;
      std::size_t pair_count = 0, groups = 0;
      int dof = 0, redundant = 0;
    };
    std::vector<Size> sizes;
    for (int parts = 1000; parts <= max_parts; parts *= 10) {
      const int cells = parts / kPartsPerCell;
      const int per_row = layout.per_row > 0    ? layout.per_row
                          : layout.per_row == 0 ? cells
                                                : static_cast<int>(std::ceil(std::sqrt(cells)));
      sizes.emplace_back(parts, layout.per_row == -2 ? PlanetaryArray(parts / kPartsPerStage)
                                                     : Synthetic(cells, per_row, layout.row_pitch));
    }
    auto ms = [](auto a, auto b) {
      return std::chrono::duration<double, std::milli>(b - a).count();
    };
    // The median of the same number of runs at every size (a best of many runs of a small
    // size against a best of few of a large one would flatter the small size), and the sizes
    // in turn within each round, so that a slower spell of the shared host falls on all sizes
    // alike instead of on whichever size it happens to meet.
    for (int round = 0; round < kRuns; ++round) {
      for (Size& size : sizes) {
        const Assembly& assembly = size.assembly;
        // Warm: an analysis first (untimed), so that the one timed after recognition and the
        // graph finds this size's data and freed memory in the cache as in a run of analyses
        // of one assembly, whatever size ran before it.
        { const Analysis warm_up = Analyze(assembly); }
        const auto t0 = std::chrono::steady_clock::now();
        const Recognition r = RecognizePairs(assembly);
        const auto t1 = std::chrono::steady_clock::now();
        size.groups = PairGraph(assembly, r.pairs).Subassemblies().size();
        const auto t2 = std::chrono::steady_clock::now();
        const Analysis analysis = Analyze(assembly);
        const auto t3 = std::chrono::steady_clock::now();
        size.pair_count = r.pairs.size();
        size.dof = analysis.motion.mobility.dof;
        size.redundant = analysis.motion.mobility.redundant;
        size.recognise_ms.push_back(ms(t0, t1));
        size.graph_ms.push_back(ms(t1, t2));
        size.all_ms.push_back(ms(t2, t3));
        // The same analysis with the caches flushed first, as after other work.
        EvictCaches();
        const auto t4 = std::chrono::steady_clock::now();
        const Analysis cold = Analyze(assembly);
        size.cold_ms.push_back(ms(t4, std::chrono::steady_clock::now()));
      }
    }
    // Medians, and minima: the host's other work only ever adds time (the same analysis of
    // 10,000 parts takes 7 to 13 ms on a busy host), so the fastest of the runs is the best
    // estimate of the analysis' own cost, and a run of 100,000 parts, longer, is the less
    // likely to meet no interference (which only makes its growth look larger).
    const Size* previous = nullptr;
    for (const Size& size : sizes) {
      auto growth = [&](double (*stat)(std::vector<double>), const std::vector<double> Size::*ms) {
        return previous ? std::to_string(stat(size.*ms) / stat(previous->*ms)).substr(0, 5) + "x"
                        : std::string("-");
      };
      std::printf("%9d %8zu %9zu %8.1f %7.1f %6d %9d | %8.1f %7s %8.1f %7s | %8.1f %7s %8.1f %7s\n",
                  size.parts, size.pair_count, size.groups, Median(size.recognise_ms),
                  Median(size.graph_ms), size.dof, size.redundant, Median(size.all_ms),
                  growth(Median, &Size::all_ms).c_str(), Minimum(size.all_ms),
                  growth(Minimum, &Size::all_ms).c_str(), Median(size.cold_ms),
                  growth(Median, &Size::cold_ms).c_str(), Minimum(size.cold_ms),
                  growth(Minimum, &Size::cold_ms).c_str());
      previous = &size;
    }
  }
  return 0;
}
