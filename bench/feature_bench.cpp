// Feature recognition benchmark, best of 3: RecognizeFeatures on a 400-tooth library gear and
// on one mesh of 180 library gears side by side (about a million triangles, 360 outlines); the
// STEP import and analysis of AS1 (../shared/data/step).
//
// Usage: feature_bench
#include <algorithm>
#include <chrono>
#include <cstdio>

#include "io/load_assembly.h"
#include "kernel/features/feature_recognition.h"
#include "kernel/features/part_library.h"
#include "reasoning/analysis.h"

namespace {

void Time(const char* name, const mechanist::TriangleMesh& mesh) {
  double best = 1e300;
  std::size_t features = 0;
  for (int run = 0; run < 3; ++run) {
    const auto start = std::chrono::steady_clock::now();
    features = mechanist::RecognizeFeatures(mesh).features.size();
    best = std::min(
        best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::printf("%-40s %9zu triangles %4zu features %8.3f s\n", name, mesh.faces.size(), features,
              best);
  std::fflush(stdout);
}

// A module-1 spur gear 10 mm wide.
mechanist::TriangleMesh Gear(int teeth, double bore, int segments) {
  mechanist::SpurGearSpec spec;
  spec.teeth = teeth;
  spec.module = 1;
  spec.face_width = 10;
  spec.bore_diameter = bore;
  spec.segments = segments;
  return mechanist::MakeLibraryPart(spec).mesh;
}

}  // namespace

int main() {
  Time("spur gear, 400 teeth", Gear(400, 100, 2000));
  // 30 x 6 gears side by side are one prismatic mesh with 360 outlines (teeth and bores).
  const mechanist::TriangleMesh one = Gear(30, 10, 600);
  mechanist::TriangleMesh field;
  for (int i = 0; i < 30; ++i) {
    for (int j = 0; j < 6; ++j) {
      mechanist::TriangleMesh copy = one;
      for (Eigen::Vector3d& v : copy.vertices) v += Eigen::Vector3d(40.0 * i, 40.0 * j, 0.0);
      field.Append(copy);
    }
  }
  Time("180 gears side by side (one mesh)", field);
  // STEP import of AS1 (product structure, triangulation, features from the faces, the nut
  // heuristic) and its whole analysis.
  double best = 1e300;
  std::size_t subassemblies = 0;
  for (int run = 0; run < 3; ++run) {
    const auto start = std::chrono::steady_clock::now();
    const mechanist::Assembly as1 =
        mechanist::LoadAssembly(MECHANIST_SHARED_DATA "/step/as1_pe_203.stp");
    subassemblies = mechanist::Analyze(as1).subassemblies.size();
    best = std::min(
        best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::printf("%-40s %zu subassembly, import + analysis %8.3f s\n", "AS1 (STEP, 18 solids)",
              subassemblies, best);
  return 0;
}
