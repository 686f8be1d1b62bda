#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/diagnostic.h"
#include "reasoning/motion.h"
#include "reasoning/pair.h"
#include "reasoning/pair_graph.h"

namespace mechanist {

/// What the reasoning concludes about an assembly at its file poses.
struct Analysis {
  std::vector<Pair> pairs;
  std::vector<Subassembly> subassemblies;
  std::vector<std::size_t> subassembly_of;  ///< per part: index into `subassemblies`
  /// The pair graph of `pairs` (adjacency, reachability); shared by copies of the analysis.
  std::shared_ptr<const PairGraph> graph;
  /// Mobility and the drivers' motion; its findings are moved into `diagnostics`.
  MotionAnalysis motion;
  /// Description checks (meshes, features), recognition's near misses and the motion
  /// analysis' findings, in DiagnosticLess order.
  std::vector<Diagnostic> diagnostics;
  /// The parts of each rolling bearing recognised (Recognition::bearings).
  std::vector<std::vector<std::size_t>> bearings;
};

/// Recognises the pairs at the file's poses, groups the parts into subassemblies and analyses
/// the motion.
Analysis Analyze(const Assembly& assembly);

/// As Analyze, with `extra` pairs (couplings found otherwise, such as by the running
/// mechanism's sweep) added to the recognised ones before subassemblies and motion.
Analysis Analyze(const Assembly& assembly, const std::vector<Pair>& extra);

}  // namespace mechanist
