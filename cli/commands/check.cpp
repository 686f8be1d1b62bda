#include <iostream>
#include <optional>

#include "cli/commands.h"
#include "io/analysis_report.h"
#include "reasoning/assembly_plan.h"
#include "reasoning/expectation_check.h"

namespace mechanist::cli {

Command CheckCommand() {
  Command c;
  c.name = "check";
  c.help = "Evaluate the file's expect entries; exit 1 if any fails";
  c.input = Input::kAdjusted;
  c.analysis = true;
  c.run = [](Session& s) {
    const Assembly& assembly = *s.assembly;
    // The assembly plan sweeps every part; it runs only when an entry asks for it.
    std::optional<AssemblyPlan> plan;
    for (const auto& e : assembly.expectations()) {
      if (e.kind == Expectation::Kind::kAssemblable && !plan) {
        plan = PlanAssembly(assembly, *s.analysis, CollisionModel(assembly));
      }
    }
    const auto results = CheckExpectations(assembly, *s.analysis, plan ? &*plan : nullptr);
    WriteCheckResults(results, std::cout);
    for (const auto& r : results) {
      if (!r.passed) return kExitFailures;
    }
    return kExitOk;
  };
  return c;
}

}  // namespace mechanist::cli
