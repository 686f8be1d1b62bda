#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "io/assembly_report.h"
#include "reasoning/assembly_plan.h"

namespace mechanist::cli {

Command AssembleCommand() {
  auto json = std::make_shared<std::string>();
  Command c;
  c.name = "assemble";
  c.help = "Check the file's steps, or find an assembly sequence; exit 1 if it cannot be assembled";
  c.input = Input::kAdjusted;
  c.analysis = true;
  c.collision = true;
  c.options = {
      Option("--json", json.get(), "write the JSON report to this file").Output(),
  };
  c.run = [json](Session& s) {
    const AssemblyPlan plan =
        PlanAssembly(*s.assembly, *s.analysis, *s.collision, Progress("assembly sequence"));
    WriteAssemblySummary(*s.assembly, *s.analysis, plan, std::cout);
    if (!json->empty()) s.Report(*json, AssemblyPlanJson(*s.assembly, *s.analysis, plan));
    return plan.assemblable ? kExitOk : kExitFailures;
  };
  return c;
}

}  // namespace mechanist::cli
