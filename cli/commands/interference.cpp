#include "reasoning/interference.h"

#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "io/assembly_report.h"
#include "kernel/assembly/assembly_state.h"

namespace mechanist::cli {

Command InterferenceCommand() {
  auto json = std::make_shared<std::string>();
  Command c;
  c.name = "interference";
  c.help = "Parts that penetrate in the assembled state; exit 1 if any clash";
  c.input = Input::kAdjusted;
  c.analysis = true;
  c.collision = true;
  c.options = {
      Option("--json", json.get(), "write the JSON report to this file").Output(),
  };
  c.run = [json](Session& s) {
    const auto contacts =
        FindContacts(*s.assembly, InitialState(*s.assembly), *s.collision, s.analysis->pairs);
    WriteInterferenceSummary(*s.assembly, *s.analysis, contacts, std::cout);
    if (!json->empty()) s.Report(*json, InterferenceJson(*s.assembly, *s.analysis, contacts));
    for (const auto& contact : contacts) {
      if (contact.verdict == ContactVerdict::kClash) return kExitFailures;
    }
    return kExitOk;
  };
  return c;
}

}  // namespace mechanist::cli
