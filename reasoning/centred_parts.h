#pragma once

#include <cstddef>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/diagnostic.h"
#include "reasoning/pair.h"
#include "reasoning/pair_graph.h"

namespace mechanist {

/// What CentreFloatingParts changed.
struct Centring {
  bool changed = false;
  /// One info `centred` per part fixed, naming its shaft, the hole and the radial clearance.
  std::vector<Diagnostic> diagnostics;
};

/// Fixes floating rigid bodies where they stand centred: a body (of `subassemblies`, with
/// `subassembly_of` per part, as PairGraph gives them) floats when it is not ground and no
/// pair but face contacts joins it to another body. A shaft of one body collinear with a
/// wider hole of another (within the length and angle tolerances, engaged along the axis
/// more than the length tolerance, thinner by more than it: a closer fit is a pair already,
/// which holds the body) places the one in the other as a CAD concentric mate does; nothing
/// else holds it, so what does (a thread drawn at the wrong size, an adapter, glue) is not in
/// the file. Where one body floats and the other is held,
/// the floating one is fixed to the held one (a `fixed` pair, source `centred`, shaft
/// first), and counts as held from then on, so that a part on the end of a fixed rod is fixed
/// to the rod in turn; candidates are taken by part and feature order, until no body is added.
/// Each floating body is fixed once: a sleeve loose between a turning shaft and its housing
/// is not made to lock them. Does nothing when the file's `infer` turns `centred_parts` off.
Centring CentreFloatingParts(const Assembly& assembly,
                             const std::vector<Subassembly>& subassemblies,
                             const std::vector<std::size_t>& subassembly_of,
                             std::vector<Pair>* pairs);

}  // namespace mechanist
