#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "kernel/assembly.h"
#include "reasoning/analysis.h"
#include "reasoning/expectation_check.h"

namespace mechanist {

/// The readable `mechanist analyze` summary: subassemblies, pairs with their parameters,
/// diagnostics. Deterministic.
void WriteAnalysisSummary(const Assembly& assembly, const Analysis& analysis, std::ostream& out);

/// The JSON report (format below), pretty-printed, byte-identical for the same input:
/// {"mechanist_report": 1, "assembly": name, "file": path,
///  "pairs": [{"id": "P1", "type", "a": "part/feature", "b", "source", "fastening",
///             "dof" (null for couplings), "ratio" ("p/q", gear and worm_gear),
///             "ratio_value", "travel_per_revolution" (mm, screw and rack_pinion),
///             "self_locking" (worm_gear), "via" (clamp, setscrew)}],
///  "subassemblies": [{"id": "S1", "parts": [...], "ground": bool}],
///  "diagnostics": [{"severity", "code", "message", "parts", "features"}]}
std::string AnalysisJson(const Assembly& assembly, const Analysis& analysis);

/// The pair graph in Graphviz DOT: parts as nodes, subassemblies as clusters (the ground one
/// shaded), one edge per pair labelled with its type (fixed pairs dashed).
std::string AnalysisDot(const Assembly& assembly, const Analysis& analysis);

/// `mechanist check` lines: "PASS|FAIL pointer: what (detail)", then "N passed, M failed".
void WriteCheckResults(const std::vector<ExpectationResult>& results, std::ostream& out);

}  // namespace mechanist
