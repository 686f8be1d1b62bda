#pragma once

#include <string>
#include <vector>

#include "kernel/assembly.h"
#include "reasoning/analysis.h"

namespace mechanist {

/// The verdict on one `expect` entry.
struct ExpectationResult {
  bool passed = false;
  std::string pointer;  ///< the entry's JSON pointer ("/expect/3")
  std::string what;     ///< the expectation in words
  std::string detail;   ///< what was found
};

/// Evaluates the file's expectations against `analysis`, in file order. Evaluated: `pair`
/// (either feature order; with `type`, the pair of those features must have it),
/// `same_subassembly`, `diagnostic` (a diagnostic whose code equals the text or whose message
/// contains it, concerning every listed part). `ratio`, `moves`, `mobility` and `assemblable`
/// need analyses this build does not have: they fail and say so.
std::vector<ExpectationResult> CheckExpectations(const Assembly& assembly,
                                                 const Analysis& analysis);

}  // namespace mechanist
