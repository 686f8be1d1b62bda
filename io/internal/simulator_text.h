#pragma once

#include <string>

#include "kernel/assembly/assembly.h"
#include "reasoning/analysis.h"
#include "reasoning/simulation_model.h"

namespace mechanist::internal {

/// "gear pair planet/teeth + ring/teeth, ratio 1/4" (with the pair's ratio or travel, when it
/// has one), for comments in the simulator files.
std::string PairLabel(const Assembly& assembly, const Analysis& analysis, std::size_t pair);

/// "parts bolt_a, housing (ground)": what a link is made of, for a comment.
std::string LinkLabel(const Assembly& assembly, const SimLink& link);

/// The parts that bound a joint's range, "stops on housing/lug at 90 deg"-style text: "lower
/// stop: arm meets base; upper stop: ..."; empty for a joint without limits.
std::string LimitLabel(const Assembly& assembly, const SimJoint& joint);

/// The first lines of a simulator file's comment: where it comes from and its units.
std::string Provenance(const Assembly& assembly);

}  // namespace mechanist::internal
