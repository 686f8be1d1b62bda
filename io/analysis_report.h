#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "reasoning/analysis.h"
#include "reasoning/drag.h"
#include "reasoning/expectation_check.h"

namespace mechanist {

/// The readable `mechanist analyze` summary: subassemblies, pairs with their parameters,
/// mobility, what each driver moves and how, diagnostics. Deterministic.
void WriteAnalysisSummary(const Assembly& assembly, const Analysis& analysis, std::ostream& out);

/// The JSON report (format below), pretty-printed, byte-identical for the same input:
/// {"mechanist_report": 1, "assembly": name, "file": path,
///  "pairs": [{"id": "P1", "type", "a": "part/feature", "b", "source", "fastening",
///             "dof" (null for couplings), "ratio" ("p/q", gear and worm_gear),
///             "ratio_value", "travel_per_revolution" (mm, screw and rack_pinion),
///             "self_locking" (worm_gear), "via" (clamp, setscrew)}],
///  "subassemblies": [{"id": "S1", "parts": [...], "ground": bool}],
///  "mobility": {"dof", "redundant", "redundant_constraints": [{"pair": "P3", "count"}],
///               "free_motions": [{"part", "pair", "freedom", "parts"}],
///               "part_freedoms": [{"part", "freedoms"}] (parts that can move at all)},
///  "motion": [{"driver": id (null: all drivers at their rates), "possible", "reason",
///              "parts": [{"part", "kind": none|rotation|translation|screw, "axis" (world unit
///                         vector), "point" (on a rotation axis), "axis_feature", "ratio"
///                         ("p/q" or decimal: rev, or length for a translation, per unit
///                         driver rate), "ratio_value", "exact", "translation" and
///                         "translation_value" (screw)}]}],
///  "diagnostics": [{"severity", "code", "message", "parts", "features"}]}
std::string AnalysisJson(const Assembly& assembly, const Analysis& analysis);

/// The pair graph in Graphviz DOT: parts as nodes, subassemblies as clusters (the ground one
/// shaded), one edge per pair labelled with its type (fixed pairs dashed).
std::string AnalysisDot(const Assembly& assembly, const Analysis& analysis);

/// The `mechanist drag` report: the axis, the part's allowable motion, what moves and how,
/// and the pairs that absorb the motion, or why it is blocked and the pairs that hold the part.
void WriteDragReport(const Assembly& assembly, const Analysis& analysis, const DragResult& drag,
                     bool rotate, std::ostream& out);

/// `mechanist check` lines: "PASS|FAIL pointer: what (detail)" (or a line saying there are
/// none), then "N passed, M failed".
void WriteCheckResults(const std::vector<ExpectationResult>& results, std::ostream& out);

}  // namespace mechanist
