#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "io/assembly_report.h"
#include "reasoning/operation_check.h"

namespace mechanist::cli {

Command SweepCommand() {
  struct Options {
    std::string driver, json;
    double amount = -1;  // -1: the driver's own amount
  };
  auto o = std::make_shared<Options>();
  Command c;
  c.name = "sweep";
  c.help = "Run the mechanism and report parts that collide while it moves; exit 1 if any";
  c.input = Input::kAdjusted;
  c.analysis = true;
  c.collision = true;
  c.options = {
      Option("--driver", &o->driver, "run only this driver (default: all at their rates)"),
      Option("--amount", &o->amount,
             "how far: driver revolutions or length units (default: the driver's amount)")
          .Bounded(Bound::kNonNegative),
      Option("--json", &o->json, "write the JSON report to this file").Output(),
  };
  c.run = [o](Session& s) {
    const std::optional<std::size_t> driver = DriverIndex(s.file, *s.assembly, o->driver);
    const OperationCheck check =
        CheckOperation(*s.assembly, *s.analysis, *s.collision, driver,
                       o->amount >= 0 ? std::optional<double>(o->amount) : std::nullopt);
    WriteOperationSummary(*s.assembly, check, std::cout);
    if (!o->json.empty()) s.Report(o->json, OperationJson(*s.assembly, check));
    bool jam = false;
    for (const auto& i : check.inferred) jam = jam || !i.carried;
    return check.clashes.empty() && check.undecided.empty() && !jam ? kExitOk : kExitFailures;
  };
  return c;
}

}  // namespace mechanist::cli
