#pragma once

#include <cstddef>
#include <vector>

#include "kernel/assembly.h"
#include "kernel/diagnostic.h"
#include "reasoning/pair.h"
#include "reasoning/pair_graph.h"

namespace mechanist {

/// What the reasoning concludes about an assembly at its file poses.
struct Analysis {
  std::vector<Pair> pairs;
  std::vector<Subassembly> subassemblies;
  std::vector<std::size_t> subassembly_of;  ///< per part: index into `subassemblies`
  /// Description checks (meshes, features) and recognition's near misses, in DiagnosticLess order.
  std::vector<Diagnostic> diagnostics;
};

/// Recognises the pairs at the file's poses and groups the parts into subassemblies.
Analysis Analyze(const Assembly& assembly);

}  // namespace mechanist
