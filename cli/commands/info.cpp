#include <iostream>

#include "cli/commands.h"
#include "io/info_report.h"
#include "kernel/assembly/assembly_check.h"

namespace mechanist::cli {

Command InfoCommand() {
  Command c;
  c.name = "info";
  c.help = "Parts, triangle counts, features, bounding boxes, units, drivers";
  c.run = [](Session& s) {
    WriteInfo(*s.assembly, std::cout);
    const auto diagnostics = CheckAssembly(*s.assembly);
    if (!diagnostics.empty()) std::cout << "diagnostics: " << diagnostics.size() << "\n";
    WriteDiagnostics(diagnostics, std::cout);
    return kExitOk;
  };
  return c;
}

}  // namespace mechanist::cli
