#include "reasoning/analysis.h"

#include <algorithm>

#include "kernel/assembly_check.h"
#include "kernel/assembly_state.h"
#include "reasoning/adjustment.h"
#include "reasoning/fastener_check.h"
#include "reasoning/pair_recognition.h"

namespace mechanist {

Analysis Analyze(const Assembly& assembly) { return Analyze(assembly, {}); }

Analysis Analyze(const Assembly& assembly, const std::vector<Pair>& extra) {
  Analysis analysis;
  Recognition recognition = RecognizePairs(assembly, InitialState(assembly));
  analysis.pairs = std::move(recognition.pairs);
  analysis.pairs.insert(analysis.pairs.end(), extra.begin(), extra.end());
  analysis.subassemblies = PairGraph(assembly, analysis.pairs).Subassemblies();
  analysis.subassembly_of.assign(assembly.parts().size(), 0);
  for (std::size_t s = 0; s < analysis.subassemblies.size(); ++s) {
    for (std::size_t part : analysis.subassemblies[s].parts) analysis.subassembly_of[part] = s;
  }
  analysis.motion = AnalyzeMotion(assembly, analysis.pairs, analysis.subassemblies,
                                  analysis.subassembly_of, std::move(recognition.axes_W));
  analysis.diagnostics = CheckAssembly(assembly);
  const auto fasteners = CheckFasteners(assembly, analysis.pairs);
  const std::vector<Diagnostic>* findings[] = {&recognition.diagnostics, &fasteners,
                                               &analysis.motion.diagnostics};
  for (const std::vector<Diagnostic>* found : findings) {
    analysis.diagnostics.insert(analysis.diagnostics.end(), found->begin(), found->end());
  }
  SuggestAdjustments(assembly, analysis.pairs, &analysis.diagnostics);
  std::sort(analysis.diagnostics.begin(), analysis.diagnostics.end(), DiagnosticLess);
  return analysis;
}

}  // namespace mechanist
