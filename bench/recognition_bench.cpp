// Pair recognition and subassemblies on synthetic assemblies of growing size: rows of cells,
// each cell a ground plate with a bearing and a tapped hole, a shaft turning in the bearing,
// a gear pressed on the shaft (meshing with the next cell's gear: a gear chain per row), and
// a cover clamped to the plate by a tight bolt. Prints time per size and the growth factor.
//
// Usage: recognition_bench [max_parts]   (default 100000)

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "kernel/assembly.h"
#include "kernel/assembly_state.h"
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

Assembly Synthetic(int cells) {
  auto cube = std::make_shared<TriangleMesh>();
  for (int i = 0; i < 8; ++i) cube->vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  cube->faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  const std::shared_ptr<const TriangleMesh> mesh = cube;
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ(), down = -up;
  AssemblySpec spec;
  spec.parts.reserve(static_cast<std::size_t>(cells) * kPartsPerCell);
  auto part = [&](const std::string& id, std::vector<Feature> features, Eigen::Vector3d at,
                  bool ground = false) {
    Part p;
    p.id = id;
    p.mesh = mesh;
    p.mesh_source = "bench:cube";
    p.X_WP = RigidTransform::Translation(at);
    p.ground = ground;
    p.features = std::move(features);
    spec.parts.push_back(std::move(p));
  };
  for (int c = 0; c < cells; ++c) {
    // Gears of 20 teeth, module 2: neighbours 40 mm apart along x mesh.
    const Eigen::Vector3d at(40.0 * (c % kCellsPerRow), 100.0 * (c / kCellsPerRow), 0);
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
  return Assembly(std::move(spec));
}

}  // namespace
}  // namespace mechanist

int main(int argc, char** argv) {
  using namespace mechanist;
  const int max_parts = argc > 1 ? std::atoi(argv[1]) : 100000;
  std::printf("%10s %10s %10s %14s %12s %10s\n", "parts", "pairs", "subassem.", "recognise_ms",
              "graph_ms", "growth");
  double previous = 0;
  for (int parts = 1000; parts <= max_parts; parts *= 10) {
    const Assembly assembly = Synthetic(parts / kPartsPerCell);
    const AssemblyState state = InitialState(assembly);
    double best_recognise = 1e30, best_graph = 1e30;
    std::size_t pair_count = 0, groups = 0;
    for (int repeat = 0; repeat < 3; ++repeat) {
      const auto t0 = std::chrono::steady_clock::now();
      const Recognition r = RecognizePairs(assembly, state);
      const auto t1 = std::chrono::steady_clock::now();
      groups = PairGraph(assembly, r.pairs).Subassemblies().size();
      const auto t2 = std::chrono::steady_clock::now();
      pair_count = r.pairs.size();
      best_recognise =
          std::min(best_recognise, std::chrono::duration<double, std::milli>(t1 - t0).count());
      best_graph = std::min(best_graph, std::chrono::duration<double, std::milli>(t2 - t1).count());
    }
    const double total = best_recognise + best_graph;
    // Expected per cell: revolute, press fit, tight thread, clamp, and a gear mesh per
    // neighbour in the row.
    const int cells = parts / kPartsPerCell;
    const int rows = (cells + kCellsPerRow - 1) / kCellsPerRow;
    const std::size_t expected = 4 * static_cast<std::size_t>(cells) + (cells - rows);
    std::printf("%10d %10zu %10zu %14.1f %12.1f %10s%s\n", parts, pair_count, groups,
                best_recognise, best_graph,
                previous > 0 ? (std::to_string(total / previous).substr(0, 5) + "x").c_str() : "-",
                pair_count == expected ? "" : "  (unexpected pair count!)");
    previous = total;
  }
  return 0;
}
