#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "io/adjusted_file_writer.h"
#include "io/adjustment_report.h"
#include "io/input_error.h"
#include "reasoning/adjustment.h"
#include "reasoning/pair_recognition.h"

namespace mechanist::cli {

Command AdjustCommand() {
  struct Options {
    std::string json, write;
  };
  auto o = std::make_shared<Options>();
  Command c;
  c.name = "adjust";
  c.help = "Solve the adjustments for the goals; exit 1 if a goal cannot be met";
  c.options = {
      Option("--json", &o->json, "write the JSON report to this file").Output(),
      Option("--write", &o->write, "write the adjusted assembly to this new file").Output(),
  };
  c.run = [o](Session& s) {
    const Assembly& assembly = *s.assembly;
    if (assembly.adjustments().empty()) {
      throw InputError(s.file, "/adjustments", 0, 0, "expected adjustments to solve, found none");
    }
    // The pairs as the file stands, before any adjustment moves a part.
    const AdjustmentSummary summary = SolveAdjustments(assembly, RecognizePairs(assembly).pairs);
    WriteAdjustmentSummary(assembly, summary, std::cout);
    if (!o->json.empty()) s.Report(o->json, AdjustmentJson(assembly, summary));
    if (!o->write.empty()) {
      const Assembly adjusted = ApplyAdjustments(assembly, summary);
      s.Report(o->write, AdjustedAssemblyText(assembly, adjusted, o->write));
    }
    return summary.all_met ? kExitOk : kExitFailures;
  };
  return c;
}

}  // namespace mechanist::cli
