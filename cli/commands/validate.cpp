#include <iostream>

#include "cli/commands.h"
#include "io/info_report.h"
#include "kernel/assembly/assembly_check.h"

namespace mechanist::cli {

Command ValidateCommand() {
  Command c;
  c.name = "validate";
  c.help = "Read everything, print diagnostics; exit 0 if valid";
  c.run = [](Session& s) {
    const auto diagnostics = CheckAssembly(*s.assembly);
    WriteDiagnostics(diagnostics, std::cout);
    std::size_t features = 0;
    for (const Part& part : s.assembly->parts()) features += part.features.size();
    std::cout << s.file << ": valid (" << s.assembly->parts().size() << " parts, " << features
              << " features, " << diagnostics.size() << " diagnostics)\n";
    return kExitOk;
  };
  return c;
}

}  // namespace mechanist::cli
