#include <fmt/format.h>

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
    const auto counted = [](std::size_t n, const char* noun) {
      return fmt::format("{} {}{}", n, noun, n == 1 ? "" : "s");
    };
    std::cout << s.file << ": valid (" << counted(s.assembly->parts().size(), "part") << ", "
              << counted(features, "feature") << ", " << counted(diagnostics.size(), "diagnostic")
              << ")\n";
    return kExitOk;
  };
  return c;
}

}  // namespace mechanist::cli
