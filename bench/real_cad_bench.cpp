// Real CAD exports benchmark, median of 3 per file: the import (LoadAssembly: STEP reading,
// tessellation, recognition) and the analysis (pairs, motion, diagnostics) of every STEP file
// of ../shared/data/real, with its parts, pairs and mobility. Goal (issue 24): each file under
// 2 s in all on the 2-core machine. Then, not in that total, the clash check at rest
// (`mechanist interference`: the collision model and FindContacts), with the contacts found,
// and the assembly plan (`mechanist assemble` once the model is built: PlanAssembly), with
// the steps it places and the parts it leaves unplaced. A second table splits the import at
// the reader's progress reports (StepProgress): Open CASCADE's parsing of the file, its
// transfer of the shapes, the solids' healing, triangulation and features from their faces (in
// parallel: its processor time, all threads, beside), and what follows the reading (features
// recognised on the tessellation, fastener and pin inference). The
// heap is set as the command line sets it (KeepFreedHeapForReuse). The runs after a process's first
// find the heap grown already: for a user's time, time `mechanist analyze FILE` as a whole process
// (farm-bench).
//
// Usage: real_cad_bench
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "io/load_assembly.h"
#include "kernel/assembly/assembly_state.h"
#include "kernel/collision/collision_model.h"
#include "kernel/support/heap_tuning.h"
#include "reasoning/analysis.h"
#include "reasoning/assembly_plan.h"
#include "reasoning/interference.h"

namespace {

using Clock = std::chrono::steady_clock;

// The seconds from `from` to `to`.
double Seconds(Clock::time_point from, Clock::time_point to = Clock::now()) {
  return std::chrono::duration<double>(to - from).count();
}

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The import in one run, s: in all and by phase (see the file's comment).
struct ImportPhases {
  double total = 0.0;
  double parse = 0.0, transfer = 0.0, solids = 0.0, solids_cpu = 0.0, after = 0.0;
};

// The median of one of the runs' `phase`.
double Median(const std::vector<ImportPhases>& runs, double ImportPhases::*phase) {
  std::vector<double> v;
  for (const ImportPhases& run : runs) v.push_back(run.*phase);
  return Median(v);
}

// LoadAssembly of `file`, its phases timed from the reader's progress reports: the first comes
// once the file is parsed, the second once the shapes are transferred, the last once the
// reading is done.
mechanist::Assembly TimedLoad(const std::filesystem::path& file, ImportPhases* phases) {
  const Clock::time_point start = Clock::now();
  std::vector<std::pair<Clock::time_point, std::clock_t>> reports;
  mechanist::LoadOptions options;
  options.reading = [&](const std::filesystem::path&, double) {
    reports.emplace_back(Clock::now(), std::clock());
  };
  mechanist::Assembly assembly = mechanist::LoadAssembly(file, options);
  const Clock::time_point end = Clock::now();
  phases->total = Seconds(start, end);
  if (reports.size() >= 3) {
    phases->parse = Seconds(start, reports[0].first);
    phases->transfer = Seconds(reports[0].first, reports[1].first);
    phases->solids = Seconds(reports[1].first, reports.back().first);
    phases->solids_cpu = double(reports.back().second - reports[1].second) / CLOCKS_PER_SEC;
    phases->after = Seconds(reports.back().first, end);
  }
  return assembly;
}

}  // namespace

int main() {
  mechanist::KeepFreedHeapForReuse();  // as the command line does
  const std::filesystem::path real = std::filesystem::path(MECHANIST_SHARED_DATA) / "real";
  std::vector<std::filesystem::path> files;
  for (const auto& dir : std::filesystem::directory_iterator(real)) {
    if (!dir.is_directory()) continue;
    for (const auto& f : std::filesystem::directory_iterator(dir.path())) {
      std::string ext = f.path().extension().string();
      std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
      if (ext == ".step" || ext == ".stp") files.push_back(f.path());
    }
  }
  std::sort(files.begin(), files.end());
  std::printf("%-40s %6s %6s %9s %9s %9s %9s %10s %9s %7s %9s %10s\n", "file", "parts", "pairs",
              "mobility", "import s", "analyse s", "total s", "contacts", "clash s", "placed",
              "unplaced", "assemble s");
  std::vector<std::pair<std::string, std::vector<ImportPhases>>> phases_of;
  for (const std::filesystem::path& file : files) {
    const std::string name = file.parent_path().filename().string().substr(0, 40);
    std::vector<ImportPhases>& phases = phases_of.emplace_back(name, 3).second;
    std::vector<double> analyse, clash, assemble;
    std::size_t parts = 0, pairs = 0, contacts = 0, placed = 0, unplaced = 0;
    int mobility = 0;
    for (int run = 0; run < 3; ++run) {
      const mechanist::Assembly a = TimedLoad(file, &phases[run]);
      auto start = Clock::now();
      const mechanist::Analysis an = mechanist::Analyze(a);
      analyse.push_back(Seconds(start));
      parts = a.parts().size();
      pairs = an.pairs.size();
      mobility = an.motion.mobility.dof;
      start = Clock::now();
      const mechanist::CollisionModel model(a);
      contacts = mechanist::FindContacts(a, mechanist::InitialState(a), model, an.pairs).size();
      clash.push_back(Seconds(start));
      start = Clock::now();
      const mechanist::AssemblyPlan plan = mechanist::PlanAssembly(a, an, model);
      assemble.push_back(Seconds(start));
      placed = plan.steps.size();
      unplaced = plan.unplaced.size();
    }
    const double i = Median(phases, &ImportPhases::total), n = Median(analyse);
    std::printf("%-40s %6zu %6zu %9d %9.2f %9.2f %9.2f %10zu %9.2f %7zu %9zu %10.2f\n",
                name.c_str(), parts, pairs, mobility, i, n, i + n, contacts, Median(clash), placed,
                unplaced, Median(assemble));
    std::fflush(stdout);
  }
  std::printf("\nimport's phases, median s\n%-40s %9s %9s %9s %9s %9s\n", "file", "parse",
              "transfer", "solids", "solids cpu", "after");
  for (const auto& [name, phases] : phases_of) {
    std::printf("%-40s %9.2f %9.2f %9.2f %10.2f %9.2f\n", name.c_str(),
                Median(phases, &ImportPhases::parse), Median(phases, &ImportPhases::transfer),
                Median(phases, &ImportPhases::solids), Median(phases, &ImportPhases::solids_cpu),
                Median(phases, &ImportPhases::after));
  }
  return 0;
}
