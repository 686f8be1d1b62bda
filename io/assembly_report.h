#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "reasoning/analysis.h"
#include "reasoning/assembly_plan.h"
#include "reasoning/interference.h"
#include "reasoning/operation_check.h"

namespace mechanist {

/// Writes "  skipped, no geometry (features only): a, b" naming the features-only parts
/// (PartsWithoutGeometry) that the geometric checks leave out; nothing when there are none.
/// The JSON reports of interference, assemble, sweep and gaps list them as "skipped".
void WriteSkippedParts(const Assembly& assembly, std::ostream& out);

/// `mechanist interference` summary: one line per pair of parts that penetrate (clashes, then
/// designed fits), with depth (mm) and location (world), then a count of touching contacts.
void WriteInterferenceSummary(const Assembly& assembly, const Analysis& analysis,
                              const std::vector<PartContact>& contacts, std::ostream& out);

/// The interference JSON report: {"assembly", "skipped": [part ids], "clashes": n, "contacts":
/// [{"parts", "verdict", "depth", "depth_bound", "location", "contained", "pair"}]}; numbers to 9
/// significant digits.
std::string InterferenceJson(const Assembly& assembly, const Analysis& analysis,
                             const std::vector<PartContact>& contacts);

/// `mechanist assemble` summary: the verdict, the base, each insertion (clear, or its
/// obstacles with the travel at contact, the fit that holds it across its travel, or the
/// clash at rest that keeps it where it is; "sub-assembly A + B ..." for a sub-assembly moved
/// in as one, "apart, into the sub-assembly of step N: ..." for a step that puts it together),
/// the parts that could not be placed, the clashes.
void WriteAssemblySummary(const Assembly& assembly, const Analysis& analysis,
                          const AssemblyPlan& plan, std::ostream& out);

/// The assembly JSON report: {"assembly", "skipped", "assemblable", "source": "steps"|"search",
/// "base", "base_pins", "steps": [{"part", "carried", "feature", "into", "direction", "travel",
/// "clear", "blocked_by": [{"part", "pin", "travel", "short_by", "location", "held_by",
/// "clash_at_rest"}], "pair", "pins", "subassembly", "apart_for"}], "unplaced" (same shape),
/// "clashes": [...]}. An obstacle is a part ("part" its id, "pin" null) or a pin the file leaves
/// out ("part" null, "pin" the holes it goes through). "apart_for" is the index into "steps" of
/// the sub-assembly's insertion (InsertionStep::apart_for), else null.
std::string AssemblyPlanJson(const Assembly& assembly, const Analysis& analysis,
                             const AssemblyPlan& plan);

/// `mechanist sweep` summary: what ran and how far, the pairs swept, each clash with the
/// driver parameter at first contact.
void WriteOperationSummary(const Assembly& assembly, const OperationCheck& check,
                           std::ostream& out);

/// The sweep JSON report: {"assembly", "skipped", "driver" (id or null for all), "amount",
/// "possible", "reason", "pairs_swept", "clashes": [{"parts", "at", "distance", "location"}],
/// "undecided":
/// [...]}.
std::string OperationJson(const Assembly& assembly, const OperationCheck& check);

}  // namespace mechanist
