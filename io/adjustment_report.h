#pragma once

#include <ostream>
#include <string>

#include "kernel/assembly/assembly.h"
#include "reasoning/adjustment.h"

namespace mechanist {

/// `mechanist adjust` summary: the solver's status, one line per adjustment (its solved value
/// in the file's units, the bound it sits on, the parts it carries, or that no goal depends on
/// it) and one per goal (met or not, with its centre-distance, angle and axial errors before
/// and after, and, when it is missed, the adjustments held at a bound).
void WriteAdjustmentSummary(const Assembly& assembly, const AdjustmentSummary& summary,
                            std::ostream& out);

/// The adjustment JSON report: {"assembly", "all_met", "solver": {"status", "message",
/// "iterations", "initial_cost", "final_cost"}, "adjustments": [{"id", "moves", "kind",
/// "axis", "value", "unit", "used", "active_bound" (null, "lower", "upper"), "carried",
/// "tightened" (the loose threads locking it tightens)}],
/// "goals": [{"kind", "features", "met", "before", "after"}]}, errors as {"distance" (mm),
/// "angle" (degrees), "axial" (mm), "engaged", "met"}; values in the file's units
/// (rotations in its angle unit), 9 significant digits.
std::string AdjustmentJson(const Assembly& assembly, const AdjustmentSummary& summary);

}  // namespace mechanist
