// Viewer benchmark, part 1: writes the viewer page of a large assembly, timing the analysis and
// the page. 20 rows of 25 spur gears, each on its own grounded axle (1,000 parts), every gear
// a mesh of its own (different tooth counts and widths, nothing shared: the page's worst case),
// the gears of a row meshing in a train. Part 2, bench/viewer_bench.js, loads the page in
// headless Chromium and measures its load time and frame rate while a gear is dragged.
//
// Usage: viewer_bench OUT.html [rows = 20] [gears per row = 25]
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "kernel/assembly/assembly.h"
#include "kernel/features/part_library.h"
#include "reasoning/analysis.h"
#include "viz/viewer_page.h"

namespace {

double Seconds(const std::function<void()>& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

mechanist::Part MakePart(const std::string& id, const mechanist::LibrarySpec& spec,
                         const Eigen::Vector3d& p_WP, bool ground) {
  mechanist::LibraryPart generated = mechanist::MakeLibraryPart(spec);
  mechanist::Part part;
  part.id = id;
  part.mesh = std::make_shared<const mechanist::TriangleMesh>(std::move(generated.mesh));
  part.mesh_source = "library:" + mechanist::LibraryKindName(spec);
  part.features = std::move(generated.features);
  part.X_WP = mechanist::RigidTransform::Translation(p_WP);
  part.ground = ground;
  return part;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace mechanist;
  if (argc < 2) {
    std::fprintf(stderr, "usage: viewer_bench OUT.html [rows] [gears per row]\n");
    return 2;
  }
  const std::filesystem::path out = argv[1];
  const int rows = argc > 2 ? std::stoi(argv[2]) : 20;
  const int columns = argc > 3 ? std::stoi(argv[3]) : 25;
  constexpr double kModule = 2.0, kBore = 8.0;

  AssemblySpec spec;
  spec.name = "viewer benchmark";
  std::size_t triangles = 0;
  for (int r = 0; r < rows; ++r) {
    double x = 0;
    int previous_teeth = 0;
    for (int c = 0; c < columns; ++c) {
      // Tooth counts 12..20 and widths that differ from gear to gear: no two meshes alike.
      const int teeth = 12 + (7 * c + 3 * r) % 9;
      if (c > 0) x += kModule * (previous_teeth + teeth) / 2.0;
      previous_teeth = teeth;
      const Eigen::Vector3d at(x, r * kModule * 48.0, 0.0);
      SpurGearSpec gear;
      gear.teeth = teeth;
      gear.module = kModule;
      gear.face_width = 8.0 + 0.01 * (r * columns + c);
      gear.bore_diameter = kBore;
      ShaftSpec axle;
      axle.diameter = kBore;
      axle.length = 20.0 + 0.01 * (r * columns + c);
      axle.segments = 96;
      axle.retained = true;  // the gear turns on it and does not slide off
      const std::string name = std::to_string(r) + "_" + std::to_string(c);
      spec.parts.push_back(MakePart("gear_" + name, gear, at, false));
      spec.parts.push_back(MakePart("axle_" + name, axle, at - Eigen::Vector3d(0, 0, 6), true));
      triangles += spec.parts[spec.parts.size() - 2].mesh->faces.size() +
                   spec.parts.back().mesh->faces.size();
    }
  }
  const Assembly assembly(std::move(spec));
  std::printf("%zu parts, %zu triangles, every mesh its own\n", assembly.parts().size(), triangles);

  Analysis analysis;
  std::printf("analysis                 %8.3f s\n", Seconds([&] { analysis = Analyze(assembly); }));
  std::printf("mobility %d (a train per row)\n", analysis.motion.mobility.dof);
  // As `mechanist view` does above 100,000 triangles: no swept drag ranges, no assembly plan.
  ViewerOptions options;
  options.ranges = false;
  options.plan = false;
  std::string html;
  std::printf("page                     %8.3f s\n",
              Seconds([&] { html = ViewerHtml(assembly, analysis, options); }));
  std::ofstream(out, std::ios::binary) << html;
  // What the meshes would take as float32 positions and uint32 indices, base64-encoded.
  std::size_t vertices = 0;
  for (const Part& part : assembly.parts()) vertices += part.mesh->vertices.size();
  const double raw = (12.0 * vertices + 12.0 * triangles) * 4.0 / 3.0;
  std::printf("page size                %8.1f MB (meshes as float32 + uint32 would be %.1f MB)\n",
              html.size() / 1e6, raw / 1e6);
  return 0;
}
