#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "io/analysis_report.h"

namespace mechanist::cli {

Command AnalyzeCommand() {
  struct Options {
    std::string json, dot;
  };
  auto o = std::make_shared<Options>();
  Command c;
  c.name = "analyze";
  c.help = "Recognise pairs and subassemblies; print a summary, optionally write reports";
  c.input = Input::kAdjusted;
  c.analysis = true;
  c.options = {
      Option("--json", &o->json, "write the JSON report to this file").Output(),
      Option("--dot", &o->dot, "write the pair graph as Graphviz DOT to this file").Output(),
  };
  c.run = [o](Session& s) {
    WriteAnalysisSummary(*s.assembly, *s.analysis, std::cout);
    if (!o->json.empty()) s.Report(o->json, AnalysisJson(*s.assembly, *s.analysis));
    if (!o->dot.empty()) s.Report(o->dot, AnalysisDot(*s.assembly, *s.analysis));
    return kExitOk;
  };
  return c;
}

}  // namespace mechanist::cli
