#pragma once

#include <string>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "reasoning/analysis.h"
#include "reasoning/assembly_plan.h"

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
/// contains it, concerning every listed part), `ratio` (exactly, or within a relative 1e-9
/// for a decimal; of the only driver at unit rate, or all drivers at their rates), `moves` (for
/// any driver alone), `mobility`, and `assemblable` against `plan` (PlanAssembly); without a
/// plan an `assemblable` entry fails with "not evaluated".
std::vector<ExpectationResult> CheckExpectations(const Assembly& assembly, const Analysis& analysis,
                                                 const AssemblyPlan* plan = nullptr);

/// Evaluates one expectation (as CheckExpectations does), for the C++ testing API.
ExpectationResult CheckExpectation(const Assembly& assembly, const Analysis& analysis,
                                   const Expectation& expectation,
                                   const AssemblyPlan* plan = nullptr);

}  // namespace mechanist
