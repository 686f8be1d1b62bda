// The mechanist command line. Exit codes: 0 success, 1 the check or analysis found failures,
// 2 bad input or usage, 3 internal error.

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <optional>
#include <string>

#include "io/analysis_report.h"
#include "io/assembly_reader.h"
#include "io/assembly_report.h"
#include "io/atomic_file.h"
#include "io/gap_report.h"
#include "io/gap_volume_writer.h"
#include "io/info_report.h"
#include "io/input_error.h"
#include "kernel/assembly_check.h"
#include "kernel/assembly_state.h"
#include "kernel/collision_model.h"
#include "reasoning/analysis.h"
#include "reasoning/assembly_plan.h"
#include "reasoning/drag.h"
#include "reasoning/expectation_check.h"
#include "reasoning/gap_search.h"
#include "reasoning/operation_check.h"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitFailures = 1;
constexpr int kExitUsage = 2;
constexpr int kExitInternal = 3;

int Validate(const std::string& file) {
  const mechanist::Assembly assembly = mechanist::ReadAssembly(file);
  const auto diagnostics = mechanist::CheckAssembly(assembly);
  mechanist::WriteDiagnostics(diagnostics, std::cout);
  std::size_t features = 0;
  for (const mechanist::Part& part : assembly.parts()) features += part.features.size();
  std::cout << file << ": valid (" << assembly.parts().size() << " parts, " << features
            << " features, " << diagnostics.size() << " diagnostics)\n";
  return kExitOk;
}

int Info(const std::string& file) {
  const mechanist::Assembly assembly = mechanist::ReadAssembly(file);
  mechanist::WriteInfo(assembly, std::cout);
  const auto diagnostics = mechanist::CheckAssembly(assembly);
  if (!diagnostics.empty()) std::cout << "diagnostics: " << diagnostics.size() << "\n";
  mechanist::WriteDiagnostics(diagnostics, std::cout);
  return kExitOk;
}

/// Outputs are written only after the whole analysis succeeded, each atomically.
int Analyze(const std::string& file, const std::string& json, const std::string& dot) {
  const mechanist::Assembly assembly = mechanist::ReadAssembly(file);
  const mechanist::Analysis analysis = mechanist::Analyze(assembly);
  mechanist::WriteAnalysisSummary(assembly, analysis, std::cout);
  if (!json.empty()) {
    mechanist::WriteFileAtomically(json, mechanist::AnalysisJson(assembly, analysis), file);
  }
  if (!dot.empty()) {
    mechanist::WriteFileAtomically(dot, mechanist::AnalysisDot(assembly, analysis), file);
  }
  return kExitOk;
}

int Drag(const std::string& file, const std::string& part, const std::string& feature,
         bool translate) {
  const mechanist::Assembly assembly = mechanist::ReadAssembly(file);
  const auto index = assembly.FindPart(part);
  if (!index) {
    throw mechanist::InputError(file, "", 0, 0,
                                "--part: expected a part id, found \"" + part + "\"");
  }
  mechanist::DragRequest request;
  request.part = *index;
  request.rotate = !translate;
  if (!feature.empty()) {
    const auto f = assembly.FindFeature(part + "/" + feature);
    if (!f) {
      throw mechanist::InputError(
          file, "", 0, 0,
          "--feature: expected a feature of part " + part + ", found \"" + feature + "\"");
    }
    request.feature = f->feature;
  }
  const mechanist::Analysis analysis = mechanist::Analyze(assembly);
  const mechanist::DragResult result = mechanist::Drag(assembly, analysis, request);
  mechanist::WriteDragReport(assembly, analysis, result, request.rotate, std::cout);
  return result.motion.possible ? kExitOk : kExitFailures;
}

int Interference(const std::string& file, const std::string& json) {
  const mechanist::Assembly assembly = mechanist::ReadAssembly(file);
  const mechanist::Analysis analysis = mechanist::Analyze(assembly);
  const mechanist::CollisionModel model(assembly);
  const auto contacts =
      mechanist::FindContacts(assembly, mechanist::InitialState(assembly), model, analysis.pairs);
  mechanist::WriteInterferenceSummary(assembly, analysis, contacts, std::cout);
  if (!json.empty()) {
    mechanist::WriteFileAtomically(json, mechanist::InterferenceJson(assembly, analysis, contacts),
                                   file);
  }
  for (const auto& c : contacts) {
    if (c.verdict == mechanist::ContactVerdict::kClash) return kExitFailures;
  }
  return kExitOk;
}

int Assemble(const std::string& file, const std::string& json) {
  const mechanist::Assembly assembly = mechanist::ReadAssembly(file);
  const mechanist::Analysis analysis = mechanist::Analyze(assembly);
  const mechanist::CollisionModel model(assembly);
  const mechanist::AssemblyPlan plan = mechanist::PlanAssembly(assembly, analysis, model);
  mechanist::WriteAssemblySummary(assembly, analysis, plan, std::cout);
  if (!json.empty()) {
    mechanist::WriteFileAtomically(json, mechanist::AssemblyPlanJson(assembly, analysis, plan),
                                   file);
  }
  return plan.assemblable ? kExitOk : kExitFailures;
}

int Gaps(const std::string& file, double voxel, const std::string& json, const std::string& vtk) {
  const mechanist::Assembly assembly = mechanist::ReadAssembly(file);
  if (!(voxel > 0) || !std::isfinite(voxel)) {
    throw mechanist::InputError(file, "", 0, 0, "--voxel: expected a length > 0");
  }
  mechanist::GapSearchOptions options;
  options.voxel = voxel * assembly.units().mm_per_length;
  if (::isatty(STDERR_FILENO)) {
    options.progress = [last = -1](double fraction) mutable {
      const int percent = static_cast<int>(100 * fraction);
      if (percent == last) return;
      last = percent;
      std::fprintf(stderr, "\rdecomposing: %3d%%%s", percent, percent == 100 ? "\n" : "");
    };
  }
  mechanist::GapSearch search;
  try {
    search = mechanist::FindGaps(assembly, options);
  } catch (const std::invalid_argument& e) {
    throw mechanist::InputError(file, "", 0, 0, std::string("--voxel: ") + e.what());
  }
  mechanist::WriteGapSummary(assembly, search, std::cout);
  if (!vtk.empty()) mechanist::WriteGapVolume(vtk, search, file);
  if (!json.empty())
    mechanist::WriteFileAtomically(json, mechanist::GapJson(assembly, search), file);
  return kExitOk;
}

int Sweep(const std::string& file, const std::string& driver, double amount,
          const std::string& json) {
  const mechanist::Assembly assembly = mechanist::ReadAssembly(file);
  std::optional<std::size_t> index;
  if (!driver.empty()) {
    for (std::size_t d = 0; d < assembly.drivers().size(); ++d) {
      if (assembly.drivers()[d].id == driver) index = d;
    }
    if (!index) {
      throw mechanist::InputError(file, "", 0, 0,
                                  "--driver: expected a driver id, found \"" + driver + "\"");
    }
  }
  if (amount < 0 && amount != -1) {
    throw mechanist::InputError(file, "", 0, 0, "--amount: expected a number >= 0");
  }
  const mechanist::Analysis analysis = mechanist::Analyze(assembly);
  const mechanist::CollisionModel model(assembly);
  const mechanist::OperationCheck check = mechanist::CheckOperation(
      assembly, analysis, model, index, amount >= 0 ? std::optional<double>(amount) : std::nullopt);
  mechanist::WriteOperationSummary(assembly, check, std::cout);
  if (!json.empty()) {
    mechanist::WriteFileAtomically(json, mechanist::OperationJson(assembly, check), file);
  }
  bool jam = false;
  for (const auto& i : check.inferred) jam = jam || !i.carried;
  return check.clashes.empty() && check.undecided.empty() && !jam ? kExitOk : kExitFailures;
}

int Check(const std::string& file) {
  const mechanist::Assembly assembly = mechanist::ReadAssembly(file);
  const mechanist::Analysis analysis = mechanist::Analyze(assembly);
  // The assembly plan sweeps every part; it runs only when an entry asks for it.
  std::optional<mechanist::AssemblyPlan> plan;
  for (const auto& e : assembly.expectations()) {
    if (e.kind == mechanist::Expectation::Kind::kAssemblable && !plan) {
      plan = mechanist::PlanAssembly(assembly, analysis, mechanist::CollisionModel(assembly));
    }
  }
  const auto results = mechanist::CheckExpectations(assembly, analysis, plan ? &*plan : nullptr);
  mechanist::WriteCheckResults(results, std::cout);
  for (const auto& r : results) {
    if (!r.passed) return kExitFailures;
  }
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "mechanist: reads a mechanical assembly and tells whether it can be assembled "
      "and how it moves"};
  app.set_version_flag("--version", std::string("mechanist ") + MECHANIST_VERSION);
  app.require_subcommand(1);

  std::string file;
  CLI::App* validate =
      app.add_subcommand("validate", "Read everything, print diagnostics; exit 0 if valid");
  validate->add_option("FILE", file, "assembly file (.json)")->required();
  CLI::App* info = app.add_subcommand(
      "info", "Parts, triangle counts, features, bounding boxes, units, drivers");
  info->add_option("FILE", file, "assembly file (.json)")->required();

  std::string json, dot;
  CLI::App* analyze = app.add_subcommand(
      "analyze", "Recognise pairs and subassemblies; print a summary, optionally write reports");
  analyze->add_option("FILE", file, "assembly file (.json)")->required();
  analyze->add_option("--json", json, "write the JSON report to this file");
  analyze->add_option("--dot", dot, "write the pair graph as Graphviz DOT to this file");
  CLI::App* check =
      app.add_subcommand("check", "Evaluate the file's expect entries; exit 1 if any fails");
  check->add_option("FILE", file, "assembly file (.json)")->required();

  CLI::App* interference = app.add_subcommand(
      "interference", "Parts that penetrate in the assembled state; exit 1 if any clash");
  interference->add_option("FILE", file, "assembly file (.json)")->required();
  interference->add_option("--json", json, "write the JSON report to this file");
  CLI::App* assemble = app.add_subcommand(
      "assemble",
      "Check the file's steps, or find an assembly sequence; exit 1 if it cannot be assembled");
  assemble->add_option("FILE", file, "assembly file (.json)")->required();
  assemble->add_option("--json", json, "write the JSON report to this file");

  std::string driver;
  double amount = -1;
  CLI::App* sweep = app.add_subcommand(
      "sweep", "Run the mechanism and report parts that collide while it moves; exit 1 if any");
  sweep->add_option("FILE", file, "assembly file (.json)")->required();
  sweep->add_option("--driver", driver, "run only this driver (default: all at their rates)");
  sweep
      ->add_option("--amount", amount,
                   "how far: driver revolutions or length units (default: the driver's amount)")
      ->check(CLI::NonNegativeNumber);
  sweep->add_option("--json", json, "write the JSON report to this file");

  double voxel = 0;
  std::string vtk;
  CLI::App* gaps = app.add_subcommand(
      "gaps", "Find the empty spaces enclosed between parts, with their volumes");
  gaps->add_option("FILE", file, "assembly file (.json)")->required();
  gaps->add_option("--voxel", voxel, "voxel edge, in the file's length units")->required();
  gaps->add_option("--json", json, "write the JSON report to this file");
  gaps->add_option("--vtk", vtk, "write the voxels as a VTK image (.vti) to this file");

  std::string part, feature;
  CLI::App* drag = app.add_subcommand(
      "drag", "Turn or push one part: what moves with it, and which pair absorbs the motion");
  drag->add_option("FILE", file, "assembly file (.json)")->required();
  drag->add_option("--part", part, "the part to drag")->required();
  drag->add_option("--feature", feature,
                   "the feature whose axis to use (default: its first in a pair)");
  bool rotate = false, translate = false;
  CLI::Option* rotate_flag = drag->add_flag("--rotate", rotate, "turn about the axis (default)");
  drag->add_flag("--translate", translate, "push along the axis")->excludes(rotate_flag);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitUsage;
  }

  try {
    if (*validate) return Validate(file);
    if (*info) return Info(file);
    if (*analyze) return Analyze(file, json, dot);
    if (*check) return Check(file);
    if (*interference) return Interference(file, json);
    if (*assemble) return Assemble(file, json);
    if (*sweep) return Sweep(file, driver, amount, json);
    if (*gaps) return Gaps(file, voxel, json, vtk);
    if (*drag) return Drag(file, part, feature, translate);
  } catch (const mechanist::InputError& e) {
    std::cerr << "mechanist: error: " << e.what() << "\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "mechanist: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return kExitUsage;
}
