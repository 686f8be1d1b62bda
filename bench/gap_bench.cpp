// Gap search benchmark: an assembly of hollow spherical shells (about one million triangles,
// each shell enclosing a void) decomposed at one voxel size by mechanist's FindGaps and, when
// OpenVDB is available, by OpenVDB's mesh-to-level-set conversion (its mesh to volume plus its
// sign flood fill) at the same voxel size. Each run happens in a child process, so that its
// peak resident memory is its own. Prints times, memory and the gaps found against the
// analytic void volume.
//
// Usage: gap_bench [voxel_mm = 0.2] [repeats = 3]
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/mesh/mesh_builder.h"
#include "reasoning/gap_search.h"

#ifdef MECHANIST_HAVE_OPENVDB
#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>
#include <tbb/global_control.h>
#endif

namespace {

using mechanist::TriangleMesh;

constexpr int kRings = 63, kSegments = 124;
constexpr double kOuter = 10.0, kInner = 8.0, kSpacing = 22.0;
constexpr int kNx = 4, kNy = 4, kNz = 2;

// A UV sphere, outward (or inward when `inward`), appended to `m`.
void AppendSphere(TriangleMesh& m, double radius, bool inward) {
  TriangleMesh sphere = mechanist::MakeUvSphere(radius, kRings, kSegments);
  if (inward) {
    for (auto& f : sphere.faces) std::swap(f[1], f[2]);
  }
  m.Append(sphere);
}

// The exact volume of the inner polyhedron (the tessellated void), by the divergence theorem.
double VoidVolume() {
  TriangleMesh m;
  AppendSphere(m, kInner, false);
  return m.SignedVolume();
}

mechanist::Assembly MakeShells() {
  auto shell = std::make_shared<TriangleMesh>();
  AppendSphere(*shell, kOuter, false);
  AppendSphere(*shell, kInner, true);
  mechanist::AssemblySpec spec;
  spec.name = "shells";
  for (int i = 0; i < kNx * kNy * kNz; ++i) {
    mechanist::Part p;
    p.id = "shell" + std::to_string(i);
    p.mesh = shell;
    p.mesh_source = "bench:shell";
    p.X_WP = mechanist::RigidTransform(
        Eigen::Matrix3d::Identity(),
        kSpacing * Eigen::Vector3d(i % kNx, (i / kNx) % kNy, i / (kNx * kNy)));
    spec.parts.push_back(std::move(p));
  }
  return mechanist::Assembly(std::move(spec));
}

struct Figures {
  double seconds = 0;        // best of the repeats
  double peak_mib = 0;       // peak resident memory of the child process
  double structure_mib = 0;  // the result structure's own size
  double gap_volume = 0;     // total reported gap volume, mm^3
  double gap_error = 0;
  double gaps = 0;
};

// Runs `work` in a child process; the child writes its Figures through a pipe.
Figures InChild(const std::function<Figures()>& work) {
  int fds[2];
  if (pipe(fds) != 0) std::abort();
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    Figures f = work();
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    f.peak_mib = usage.ru_maxrss / 1024.0;
    if (write(fds[1], &f, sizeof f) != static_cast<ssize_t>(sizeof f)) _exit(1);
    _exit(0);
  }
  close(fds[1]);
  Figures f;
  if (read(fds[0], &f, sizeof f) != static_cast<ssize_t>(sizeof f)) std::abort();
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return f;
}

template <typename F>
double Seconds(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  const double voxel = argc > 1 ? std::atof(argv[1]) : 0.2;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
  const mechanist::Assembly assembly = MakeShells();
  std::size_t triangles = 0;
  for (const auto& p : assembly.parts()) triangles += p.mesh->faces.size();
  rusage base{};
  getrusage(RUSAGE_SELF, &base);
  std::printf("gap_bench: %zu shells, %zu triangles, voxel %.3g mm, best of %d\n",
              assembly.parts().size(), triangles, voxel, repeats);
  std::printf("  analytic void volume: %zu x %.6g mm^3 = %.6g mm^3\n", assembly.parts().size(),
              VoidVolume(), VoidVolume() * assembly.parts().size());
  std::printf("  process baseline (assembly in memory): %.1f MiB\n", base.ru_maxrss / 1024.0);

  const Figures ours = InChild([&] {
    Figures f;
    f.seconds = 1e300;
    for (int r = 0; r < repeats; ++r) {
      mechanist::GapSearch search;
      mechanist::GapSearchOptions options;
      options.voxel = voxel;
      f.seconds = std::min(f.seconds, Seconds([&] { search = FindGaps(assembly, options); }));
      f.structure_mib = search.octree->MemoryBytes() / 1048576.0;
      f.gaps = static_cast<double>(search.gaps.size());
      f.gap_volume = f.gap_error = 0;
      for (const auto& g : search.gaps) {
        f.gap_volume += g.volume;
        f.gap_error += g.volume_error;
      }
    }
    return f;
  });
  std::printf(
      "  mechanist FindGaps (1 thread):   %8.3f s, peak RSS %7.1f MiB, octree %7.1f MiB; "
      "%g gaps, %.6g +/- %.3g mm^3\n",
      ours.seconds, ours.peak_mib, ours.structure_mib, ours.gaps, ours.gap_volume, ours.gap_error);

#ifdef MECHANIST_HAVE_OPENVDB
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> tris;
  for (const auto& part : assembly.parts()) {
    const auto offset = static_cast<unsigned>(points.size());
    for (const auto& v : part.mesh->vertices) {
      const Eigen::Vector3d w = part.X_WP * v;
      points.emplace_back(static_cast<float>(w.x()), static_cast<float>(w.y()),
                          static_cast<float>(w.z()));
    }
    for (const auto& f : part.mesh->faces) {
      tris.emplace_back(offset + f[0], offset + f[1], offset + f[2]);
    }
  }
  openvdb::initialize();
  const auto vdb = [&](int threads) {
    return InChild([&] {
      tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
      Figures f;
      f.seconds = 1e300;
      for (int r = 0; r < repeats; ++r) {
        openvdb::FloatGrid::Ptr grid;
        const auto transform = openvdb::math::Transform::createLinearTransform(voxel);
        f.seconds = std::min(f.seconds, Seconds([&] {
                               grid = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(
                                   *transform, points, tris, 3.0f);
                             }));
        f.structure_mib = grid->memUsage() / 1048576.0;
      }
      return f;
    });
  };
  const Figures vdb1 = vdb(1), vdb2 = vdb(2);
  std::printf("  OpenVDB meshToLevelSet (1 thread): %6.3f s, peak RSS %7.1f MiB, grid %7.1f MiB\n",
              vdb1.seconds, vdb1.peak_mib, vdb1.structure_mib);
  std::printf("  OpenVDB meshToLevelSet (2 threads): %5.3f s, peak RSS %7.1f MiB, grid %7.1f MiB\n",
              vdb2.seconds, vdb2.peak_mib, vdb2.structure_mib);
  std::printf(
      "  time ratio mechanist / OpenVDB: %.2f (1 thread), %.2f (2 threads); "
      "peak memory above baseline: %.2f, %.2f; structure: %.2f\n",
      ours.seconds / vdb1.seconds, ours.seconds / vdb2.seconds,
      (ours.peak_mib - base.ru_maxrss / 1024.0) / (vdb1.peak_mib - base.ru_maxrss / 1024.0),
      (ours.peak_mib - base.ru_maxrss / 1024.0) / (vdb2.peak_mib - base.ru_maxrss / 1024.0),
      ours.structure_mib / vdb1.structure_mib);
#else
  std::printf(
      "  OpenVDB not found at configure time: no comparison (apt install libopenvdb-dev)\n");
#endif
  return 0;
}
