#include "reasoning/analysis.h"

#include <iterator>
#include <memory>
#include <optional>
#include <vector>

#include "kernel/assembly/assembly_check.h"
#include "reasoning/adjustment.h"
#include "reasoning/centred_parts.h"
#include "reasoning/fastener_check.h"
#include "reasoning/pair_recognition.h"
#include "reasoning/seated_parts.h"

namespace mechanist {

Analysis Analyze(const Assembly& assembly) { return Analyze(assembly, {}); }

Analysis Analyze(const Assembly& assembly, const std::vector<Pair>& extra) {
  Analysis analysis;
  Recognition recognition = RecognizePairs(assembly);
  analysis.pairs = std::move(recognition.pairs);
  analysis.bearings = std::move(recognition.bearings);
  analysis.pairs.insert(analysis.pairs.end(), extra.begin(), extra.end());
  analysis.graph = std::make_shared<const PairGraph>(assembly, analysis.pairs);
  analysis.subassemblies = analysis.graph->Subassemblies();
  analysis.subassembly_of = analysis.graph->SubassemblyOf();
  analysis.motion = AnalyzeMotion(assembly, analysis.pairs, analysis.graph, recognition.axes_W);
  // Slides that the parts around stop within a play are no motion: the pairs change, and the
  // subassemblies and motion with them.
  // Then parts that float, centred on another's axis, are held there.
  auto regroup = [&](std::vector<Diagnostic>* found) {
    analysis.graph = std::make_shared<const PairGraph>(assembly, analysis.pairs);
    analysis.subassemblies = analysis.graph->Subassemblies();
    analysis.subassembly_of = analysis.graph->SubassemblyOf();
    recognition.diagnostics.insert(recognition.diagnostics.end(),
                                   std::make_move_iterator(found->begin()),
                                   std::make_move_iterator(found->end()));
  };
  Seating seating = SeatParts(assembly, analysis.motion, analysis.subassemblies,
                              analysis.subassembly_of, &analysis.pairs);
  if (seating.changed) regroup(&seating.diagnostics);
  Centring centring = CentreFloatingParts(assembly, analysis.subassemblies, analysis.subassembly_of,
                                          &analysis.pairs);
  if (centring.changed) {
    // The parts it fixed are in a pair now.
    std::erase_if(recognition.diagnostics,
                  [](const Diagnostic& d) { return d.code == "part_unconnected"; });
    if (std::optional<Diagnostic> unconnected = UnconnectedParts(assembly, analysis.pairs)) {
      recognition.diagnostics.push_back(std::move(*unconnected));
    }
    regroup(&centring.diagnostics);
  }
  if (seating.changed || centring.changed) {
    analysis.motion =
        AnalyzeMotion(assembly, analysis.pairs, analysis.graph, std::move(recognition.axes_W));
  }
  analysis.diagnostics = CheckAssembly(assembly);
  std::vector<Diagnostic> fasteners = CheckFasteners(assembly, analysis.pairs);
  std::vector<std::size_t> run_starts = {0};
  for (std::vector<Diagnostic>* found :
       {&recognition.diagnostics, &fasteners, &analysis.motion.diagnostics}) {
    run_starts.push_back(analysis.diagnostics.size());
    analysis.diagnostics.insert(analysis.diagnostics.end(), std::make_move_iterator(found->begin()),
                                std::make_move_iterator(found->end()));
    found->clear();
  }
  SuggestAdjustments(assembly, *analysis.graph, analysis.pairs, &analysis.diagnostics);
  SortDiagnosticRuns(&analysis.diagnostics, run_starts);
  return analysis;
}

}  // namespace mechanist
