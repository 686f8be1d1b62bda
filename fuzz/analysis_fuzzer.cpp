// libFuzzer harness of the whole analysis: the input is an STL mesh (ASCII or binary), made a
// part resting on a ground plate with a bore, and the assembly is loaded (features recognised
// from the mesh, fasteners, ground), analysed (pairs, graph, motion) and reported as
// `analyze --json` reports it.
#include <sstream>

#include "fuzz/fuzz_input.h"
#include "io/analysis_report.h"
#include "io/load_assembly.h"
#include "reasoning/analysis.h"

namespace {

constexpr std::string_view kAssembly = R"({
  "mechanist": 1,
  "parts": [
    {"id": "plate", "ground": true,
     "library": {"kind": "plate", "length": 80, "width": 80, "thickness": 5,
                 "holes": [{"id": "bore", "at": [0, 0], "diameter": 10}]}},
    {"id": "part", "mesh": "part.stl", "pose": {"position": [0, 0, 5]}}
  ]
})";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  mechanist::fuzz::WriteInput(data, size, "part.stl");
  mechanist::fuzz::ExpectOnlyInputErrors([&] {
    const mechanist::Assembly assembly =
        mechanist::LoadAssemblyText(kAssembly, mechanist::fuzz::Folder() / "assembly.json");
    const mechanist::Analysis analysis = mechanist::Analyze(assembly);
    std::ostringstream summary;
    mechanist::WriteAnalysisSummary(assembly, analysis, summary);
    mechanist::AnalysisJson(assembly, analysis);
  });
  return 0;
}
